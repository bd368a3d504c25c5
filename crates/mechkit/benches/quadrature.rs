//! Quadrature of 10⁷ samples: the trapezoid rule at any spacing and at uniform spacing, Simpson
//! at any spacing and the running trapezoid integral, reported per sample
//! (`Throughput::Elements`). Two plain passes over the same `y` give the floor that memory
//! bandwidth sets: a vectorised integer reduction (reads 8 bytes per sample and does nothing
//! else; the same over `x` and `y` for 16 bytes) and `iter().sum()` (one dependent addition per
//! sample). A second group repeats the kernels on 10⁵ samples, which stay in cache.
//!
//! Run with `cargo bench -p mechkit --bench quadrature`.

use std::hint::black_box;
use std::time::Duration;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use mechkit::quad::{cumtrapz_into, simpson, trapz, trapz_uniform};

const N: usize = 10_000_000;

/// A non-uniform grid on [0, 1]: uniform spacing perturbed by up to ±40 % with a fixed-seed
/// linear congruential generator (Knuth's MMIX constants), and `y = sin(3x)`.
fn samples() -> (Vec<f64>, Vec<f64>) {
    let mut state: u64 = 0x5eed;
    let mut uniform = move || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let h = 1.0 / (N - 1) as f64;
    let x: Vec<f64> = (0..N)
        .map(|i| {
            let jitter = if i == 0 || i == N - 1 {
                0.0
            } else {
                0.8 * (uniform() - 0.5)
            };
            (i as f64 + jitter) * h
        })
        .collect();
    let y = x.iter().map(|x| (3.0 * x).sin()).collect();
    (x, y)
}

fn quadrature(c: &mut Criterion) {
    let (x, y) = samples();
    let h = 1.0 / (N - 1) as f64;
    let mut out = vec![0.0; N];
    let mut group = c.benchmark_group("quadrature of 10^7 samples");
    group
        .throughput(Throughput::Elements(N as u64))
        .sample_size(20)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(5));
    group.bench_function("trapz", |b| b.iter(|| trapz(black_box(&x), black_box(&y))));
    group.bench_function("trapz_uniform", |b| {
        b.iter(|| trapz_uniform(black_box(h), black_box(&y)));
    });
    group.bench_function("simpson", |b| {
        b.iter(|| simpson(black_box(&x), black_box(&y)));
    });
    group.bench_function("cumtrapz_into", |b| {
        b.iter(|| cumtrapz_into(black_box(&x), black_box(&y), black_box(&mut out)));
    });
    group.bench_function("floor: xor of the bits of y", |b| {
        b.iter(|| black_box(&y).iter().fold(0u64, |a, v| a ^ v.to_bits()));
    });
    group.bench_function("floor: xor of the bits of x and y", |b| {
        b.iter(|| {
            let xy = black_box(&x).iter().zip(black_box(&y));
            xy.fold(0u64, |a, (u, v)| a ^ u.to_bits() ^ v.to_bits())
        });
    });
    group.bench_function("floor: y.iter().sum()", |b| {
        b.iter(|| black_box(&y).iter().sum::<f64>());
    });
    group.finish();

    // The same kernels on the first 10^5 samples (1.6 MB, in cache): their arithmetic speed.
    let n = 100_000;
    let (x, y, out) = (&x[..n], &y[..n], &mut out[..n]);
    let mut group = c.benchmark_group("quadrature of 10^5 samples (in cache)");
    group.throughput(Throughput::Elements(n as u64));
    group.bench_function("trapz", |b| b.iter(|| trapz(black_box(x), black_box(y))));
    group.bench_function("trapz_uniform", |b| {
        b.iter(|| trapz_uniform(black_box(h), black_box(y)));
    });
    group.bench_function("simpson", |b| {
        b.iter(|| simpson(black_box(x), black_box(y)));
    });
    group.bench_function("cumtrapz_into", |b| {
        b.iter(|| cumtrapz_into(black_box(x), black_box(y), black_box(&mut *out)));
    });
    group.finish();
}

criterion_group!(benches, quadrature);
criterion_main!(benches);

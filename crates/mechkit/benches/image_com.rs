//! The image method on a photo-sized picture: selection and moments (`PixelBody::measure`)
//! of a 4000 × 3000 image, a dark ball of radius 600 px on a light, noisy background (a
//! fixed-seed generator), by the course's rule `R+G+B < 1.5`, on one colour channel, and with
//! the density from the shade. The issue asks for under 100 ms. A plain pass that adds up the
//! bytes gives the floor that reading 36 MB sets. Reported per pixel (`Throughput::Elements`).
//!
//! Run with `cargo bench -p mechkit --bench image_com`.

use std::hint::black_box;
use std::time::Duration;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use mechkit::mass::image::{Channel, Density, PixelBody, Raster, Selection};

const WIDTH: usize = 4000;
const HEIGHT: usize = 3000;

/// A dark ball (radius 600 px at (2500, 1200)) on a light grey sheet, every channel of every
/// pixel perturbed by up to ±10 % (Knuth's MMIX linear congruential generator, fixed seed).
fn photo() -> Raster {
    let mut state: u64 = 0x5eed;
    let mut noise = move || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        0.2 * ((state >> 11) as f64 / (1u64 << 53) as f64 - 0.5)
    };
    Raster::from_fn(WIDTH, HEIGHT, |x, y| {
        let (dx, dy) = (x as f64 - 2500.0, y as f64 - 1200.0);
        let base = if dx * dx + dy * dy < 600.0 * 600.0 {
            [0.55, 0.4, 0.1]
        } else {
            [0.85, 0.85, 0.8]
        };
        base.map(|c| c + noise())
    })
}

fn image_com(c: &mut Criterion) {
    let img = photo();
    let mut group = c.benchmark_group("image method, 4000 x 3000 pixels");
    group
        .throughput(Throughput::Elements((WIDTH * HEIGHT) as u64))
        .sample_size(20)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(5));
    let course = Selection::default();
    group.bench_function("measure, R+G+B < 1.5", |b| {
        b.iter(|| PixelBody::measure(black_box(&img), black_box(&course)).unwrap());
    });
    let blue = Selection::new(Channel::Blue).threshold(0.4);
    group.bench_function("measure, B < 0.4", |b| {
        b.iter(|| PixelBody::measure(black_box(&img), black_box(&blue)).unwrap());
    });
    let shade = course.density(Density::Darkness);
    group.bench_function("measure, R+G+B < 1.5, density from darkness", |b| {
        b.iter(|| PixelBody::measure(black_box(&img), black_box(&shade)).unwrap());
    });
    group.bench_function("floor: sum of the bytes", |b| {
        b.iter(|| {
            black_box(&img)
                .as_rgb8()
                .iter()
                .map(|&v| u64::from(v))
                .sum::<u64>()
        });
    });
    group.finish();
}

criterion_group!(benches, image_com);
criterion_main!(benches);

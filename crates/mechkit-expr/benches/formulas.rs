//! Compiled formulas against the hand-written Rust closure a user would otherwise write: the
//! course's feather drag `-m*g*Dmg*v*abs(v)` and a Lennard-Jones pair force
//! `24*eps/r*(2*(s/r)^12 - (s/r)^6)`, each through the interpreter and the native code.
//!
//! Run with `cargo bench -p mechkit-expr --bench formulas`.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use mechkit_expr::{Formula, MapScope, Program};

fn programs(src: &str, scope: &MapScope) -> (Program, Program) {
    let p = Formula::parse(src).unwrap().compile(scope).unwrap();
    let native = p.clone().native();
    assert!(native.is_native() || std::env::var("MECHKIT_JIT").as_deref() == Ok("0"));
    (p, native)
}

fn feather(c: &mut Criterion) {
    let (m, g, dmg) = (1e-3, 9.8, 4.0);
    let scope = MapScope::new()
        .constant("m", m)
        .constant("g", g)
        .constant("Dmg", dmg)
        .slot("v", 0);
    let (interp, native) = programs("-m*g*Dmg*v*abs(v)", &scope);
    let closure = move |v: f64| -m * g * dmg * v * v.abs();
    let boxed: Box<dyn Fn(f64) -> f64> = Box::new(closure);
    let mut group = c.benchmark_group("feather drag");
    group.bench_function("closure", |b| b.iter(|| closure(black_box(-0.3))));
    group.bench_function("closure behind dyn Fn", |b| {
        b.iter(|| boxed(black_box(-0.3)));
    });
    group.bench_function("native", |b| b.iter(|| native.eval(black_box(&[-0.3]))));
    group.bench_function("interpreter", |b| {
        b.iter(|| interp.eval(black_box(&[-0.3])));
    });
    group.finish();
}

fn lennard_jones(c: &mut Criterion) {
    let (eps, s) = (1.0, 1.0);
    let scope = MapScope::new()
        .constant("eps", eps)
        .constant("s", s)
        .slot("r", 0);
    let (interp, native) = programs("24*eps/r*(2*(s/r)^12 - (s/r)^6)", &scope);
    let closure = move |r: f64| {
        let q = s / r;
        let q6 = q.powi(6);
        24.0 * eps / r * (2.0 * q6 * q6 - q6)
    };
    let boxed: Box<dyn Fn(f64) -> f64> = Box::new(closure);
    let mut group = c.benchmark_group("lennard-jones force");
    group.bench_function("closure", |b| b.iter(|| closure(black_box(1.3))));
    group.bench_function("closure behind dyn Fn", |b| {
        b.iter(|| boxed(black_box(1.3)));
    });
    group.bench_function("native", |b| b.iter(|| native.eval(black_box(&[1.3]))));
    group.bench_function("interpreter", |b| b.iter(|| interp.eval(black_box(&[1.3]))));
    group.finish();
}

criterion_group!(benches, feather, lennard_jones);
criterion_main!(benches);

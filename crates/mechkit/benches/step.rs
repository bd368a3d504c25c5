//! One step of each integrator on a small state: the Kepler orbit (e = 0.5, state `[x, y, vx,
//! vy]`, four components), the cost of the stepper's own work around a cheap right-hand side.
//!
//! - The fixed-step methods (Euler, Euler-Cromer, velocity Verlet, RK4 and the symplectic
//!   compositions) take steps of `h = 2π/1000` through the [`Stepper`] trait object that
//!   [`Method::stepper`] returns, as `mechkit run` does; the state goes back to perihelion
//!   after each orbit.
//! - The adaptive pairs (dopri5, dop853) take one accepted step of [`AdaptiveRk::step`] at
//!   rtol = 1e-9, atol = 1e-12 (the settings of `bench/ode_compare`), along the orbit, with the
//!   step size their controller chooses.
//!
//! Run with `cargo bench -p mechkit --bench step`.

use std::f64::consts::TAU;
use std::hint::black_box;
use std::time::Duration;

use criterion::{Criterion, criterion_group, criterion_main};
use mechkit::ode::reference::Kepler;
use mechkit::ode::{AdaptiveConfig, AdaptiveRk, Method, State, Tolerance};

fn fixed_steps(c: &mut Criterion) {
    let kepler = Kepler { e: 0.5 };
    let y0 = kepler.initial();
    let h = TAU / 1000.0;
    let mut group = c.benchmark_group("one fixed step, Kepler (4 components)");
    group
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2));
    for m in Method::ALL {
        if m.is_adaptive() {
            continue;
        }
        let mut stepper = m.stepper::<Kepler>();
        let mut s = State::new(0.0, y0.to_vec());
        let mut evaluations = 0;
        group.bench_function(m.name(), |b| {
            b.iter(|| {
                if s.t >= TAU {
                    s.t = 0.0;
                    s.y.copy_from_slice(&y0);
                    stepper.reset();
                }
                let info = stepper
                    .step(&kepler, black_box(&mut s), black_box(h))
                    .expect("a finite step");
                evaluations = info.evaluations;
                info
            });
        });
        println!("{}: {evaluations} evaluations per step", m.name());
    }
    group.finish();
}

fn adaptive_steps(c: &mut Criterion) {
    let kepler = Kepler { e: 0.5 };
    let mut group = c.benchmark_group("one adaptive step, Kepler (4 components)");
    group
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2));
    for m in [Method::Dopri5, Method::Dop853] {
        let config = AdaptiveConfig {
            rtol: Tolerance::Scalar(1e-9),
            atol: Tolerance::Scalar(1e-12),
            ..AdaptiveConfig::default()
        };
        let tableau = m.tableau().expect("an adaptive pair");
        let mut rk = AdaptiveRk::new(tableau, config).expect("valid settings");
        let mut s = State::new(0.0, kepler.initial().to_vec());
        group.bench_function(m.name(), |b| {
            b.iter(|| {
                rk.step(&kepler, black_box(&mut s), f64::INFINITY)
                    .expect("a step")
            });
        });
        let st = rk.stats();
        println!(
            "{}: {:.2} evaluations per accepted step ({} rejected of {})",
            m.name(),
            st.evaluations as f64 / st.accepted as f64,
            st.rejected,
            st.accepted + st.rejected
        );
    }
    group.finish();
}

criterion_group!(benches, fixed_steps, adaptive_steps);
criterion_main!(benches);

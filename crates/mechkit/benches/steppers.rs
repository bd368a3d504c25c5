//! Time per step of the fixed-step methods, on the course's feather (1-D, gravity and
//! quadratic drag) and on a Kepler orbit (2-D, Newtonian gravity), through the same run loop
//! as `mechkit run` (energy ledger included, no observers).
//!
//! A plain harness (no criterion): each case runs 7 times after a warm-up and the median is
//! printed. Run with `cargo bench -p mechkit --bench steppers`.

use std::hint::black_box;
use std::time::Instant;

use mechkit::prelude::*;
use mechkit::scenario::Scenario;

fn median_ns_per_step(mut f: impl FnMut() -> u64) -> f64 {
    f(); // warm-up
    let mut samples: Vec<f64> = (0..7)
        .map(|_| {
            let t = Instant::now();
            let steps = f();
            t.elapsed().as_nanos() as f64 / steps as f64
        })
        .collect();
    samples.sort_by(f64::total_cmp);
    samples[3]
}

fn feather_builtin(method: Method, fuse: bool) -> u64 {
    let (g, m) = (9.8, 1e-3);
    let sys = ParticleSystem::builder(1)
        .body("feather", m)
        .force(UniformGravity::new("gravity", vec![0], g))
        .force(QuadraticDrag::new("air", vec![Target::new(0, m * g * 4.0)]))
        .build()
        .unwrap();
    let r = Simulation::new(&sys, method, 1e-5)
        .t_max(10.0)
        .fuse(fuse)
        .run(State::from_qv(0.0, &[2.4], &[0.0]), &mut [])
        .unwrap();
    black_box(r.final_state.y[0]);
    r.steps
}

fn kepler(method: Method) -> u64 {
    let gm = 4.0 * std::f64::consts::PI.powi(2);
    let sys = ParticleSystem::builder(2)
        .body("planet", 1.0)
        .force(NewtonianGravity::fixed_centre(
            "sun",
            vec![0],
            gm,
            vec![0.0, 0.0],
        ))
        .build()
        .unwrap();
    let vp = (gm * 3.0).sqrt();
    let r = Simulation::new(&sys, method, 1e-5)
        .t_max(10.0)
        .fuse(false)
        .run(State::from_qv(0.0, &[0.5, 0.0], &[0.0, vp]), &mut [])
        .unwrap();
    black_box(r.final_state.y[0]);
    r.steps
}

const FEATHER_FORMULA: &str = r#"
dimensions = 1
[constants]
g = "9.8 m/s^2"
Dmg = "4.0 s^2/m^2"
[[body]]
name = "feather"
mass = "1 g"
position = "2.4 m"
[[force]]
name = "gravity"
kind = "uniform-gravity"
g = "g"
[[force]]
name = "air"
kind = "expression"
F = "-m*g*Dmg*v*abs(v)"
[integrator]
method = "euler-cromer"
dt = "1e-5 s"
[stop]
t_max = "10 s"
[output]
plots = []
"#;

/// The course's loop written by hand: the floor under every other figure.
fn feather_hand_loop() -> u64 {
    let (g, dmg, dt) = (9.8, 4.0, 1e-5);
    let (mut x, mut v) = (2.4_f64, 0.0_f64);
    let n = 1_000_000;
    for _ in 0..n {
        let a = -g - g * dmg * v * v.abs();
        v += a * dt;
        x += v * dt;
    }
    black_box((x, v));
    n
}

fn main() {
    println!("{:<40} {:>10}", "case (1e6 steps each)", "ns/step");
    let ns = median_ns_per_step(feather_hand_loop);
    println!(
        "{:<40} {ns:>10.1}",
        "feather, hand-written Euler-Cromer loop"
    );
    if let Ok(only) = std::env::var("ONLY") {
        // for profiling one case: ONLY=euler perf record …
        let method = Method::from_name(&only).expect("a method name");
        for _ in 0..5 {
            feather_builtin(method, false);
        }
        return;
    }
    // symplectic methods refuse the feather's drag
    for method in Method::ALL
        .into_iter()
        .filter(|m| !m.needs_position_forces() && m.kind() != MethodKind::Implicit)
    {
        let ns = median_ns_per_step(|| feather_builtin(method, false));
        println!(
            "{:<40} {ns:>10.1}",
            format!("feather, built-in forces, {method}")
        );
    }
    for method in Method::ALL
        .into_iter()
        .filter(|m| m.kind() != MethodKind::Implicit)
    {
        let ns = median_ns_per_step(|| kepler(method));
        println!("{:<40} {ns:>10.1}", format!("kepler, {method}"));
    }
    let scenario = Scenario::from_str("feather.toml", FEATHER_FORMULA).unwrap();
    let ns = median_ns_per_step(|| scenario.run().unwrap().summary.steps);
    println!("{:<40} {ns:>10.1}", "feather, formula force, scenario run");
    // the steps no output looks at, in the compiled kernel (simulate::fused)
    for method in [Method::Euler, Method::EulerCromer] {
        let ns = median_ns_per_step(|| feather_builtin(method, true));
        println!(
            "{:<40} {ns:>10.1}",
            format!("feather, built-in forces, {method}, fused")
        );
    }
    let decimated = FEATHER_FORMULA.replace("plots = []", "plots = []\nevery = 100000");
    let scenario = Scenario::from_str("feather.toml", &decimated).unwrap();
    let ns = median_ns_per_step(|| {
        let s = scenario.run().unwrap().summary;
        assert!(s.step_control.fused_steps * 10 >= s.steps * 9);
        s.steps
    });
    println!("{:<40} {ns:>10.1}", "feather, formula, every 100000, fused");
}

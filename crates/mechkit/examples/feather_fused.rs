//! Times the feather workload of `bench/compare` (`bench/workloads/feather_1e7.toml`) in
//! memory, the way `mechkit run` runs it: `cargo run --release -p mechkit --example
//! feather_fused [ROUNDS]`. Prints ns per step for each round and the hand-written loop's.

use std::hint::black_box;
use std::time::Instant;

use mechkit::scenario::Scenario;

fn hand_loop(steps: u64) -> f64 {
    let (g, dmg, dt) = (9.8, 4.0, 1e-6);
    let (mut x, mut v) = (black_box(2.4_f64), black_box(0.0_f64));
    let start = Instant::now();
    for _ in 0..steps {
        let a = -g - g * dmg * v * v.abs();
        v += a * dt;
        x += v * dt;
    }
    black_box((x, v));
    start.elapsed().as_nanos() as f64 / steps as f64
}

fn main() {
    let rounds: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(5);
    let file = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../bench/workloads/feather_1e7.toml"
    );
    let scenario = Scenario::load(std::path::Path::new(file)).expect("the workload loads");
    for _ in 0..rounds {
        let start = Instant::now();
        let out = scenario.run().expect("the run succeeds");
        let ns = start.elapsed().as_nanos() as f64 / out.summary.steps as f64;
        println!(
            "scenario {ns:6.2} ns/step (fused {} of {})   hand-written loop {:6.2} ns/step",
            out.summary.step_control.fused_steps,
            out.summary.steps,
            hand_loop(out.summary.steps)
        );
    }
}

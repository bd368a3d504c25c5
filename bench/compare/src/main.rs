//! mechkit's side of `bench/compare`: each workload once, timed, printed as one line
//! `workload<TAB>tool<TAB>ns per unit<TAB>check value`. The driver (`bench/compare/run`)
//! alternates this program with the comparators and takes medians.
//!
//! Workloads:
//! - `feather`: the feather with quadratic drag typed as a formula in a scenario file
//!   (`bench/workloads/feather_1e7.toml`), Euler-Cromer, 10⁷ steps, every 100,000th step
//!   written; through `Scenario::run_to_dir`, exactly what `mechkit run` does (ns per step).
//!   Next to it the hand-written Rust loop of the same arithmetic (the floor).
//! - `trapz`: the trapezoid rule on 10⁷ samples, `mechkit::quad::trapz(x, y)` (ns per
//!   sample).

use std::hint::black_box;
use std::path::Path;
use std::time::Instant;

use mechkit::quad::trapz;
use mechkit::scenario::Scenario;

const STEPS: u64 = 10_000_000;

fn feather_scenario(root: &Path) -> (f64, f64) {
    let file = root.join("bench/workloads/feather_1e7.toml");
    let scenario = Scenario::load(&file).expect("the workload scenario loads");
    let out = std::env::temp_dir().join("mechkit_compare_feather");
    let start = Instant::now();
    let run = scenario.run_to_dir(&out).expect("the run succeeds");
    let ns = start.elapsed().as_nanos() as f64 / STEPS as f64;
    (ns, run.summary.bodies["feather"].velocity[0])
}

/// The course's loop, written by hand: v += a dt; x += v dt.
fn feather_loop() -> (f64, f64) {
    let (g, dmg, dt) = (9.8, 4.0, 1e-6);
    let (mut x, mut v) = (black_box(2.4_f64), black_box(0.0_f64));
    let start = Instant::now();
    for _ in 0..STEPS {
        let a = -g - g * dmg * v * v.abs();
        v += a * dt;
        x += v * dt;
    }
    let ns = start.elapsed().as_nanos() as f64 / STEPS as f64;
    black_box(x);
    (ns, v)
}

fn trapz_samples() -> (f64, f64) {
    let n = 10_000_000;
    let x: Vec<f64> = (0..n).map(|i| i as f64 / (n - 1) as f64).collect();
    let y: Vec<f64> = x.iter().map(|t| t * t).collect();
    let start = Instant::now();
    let value = trapz(black_box(&x), black_box(&y));
    let ns = start.elapsed().as_nanos() as f64 / n as f64;
    (ns, value)
}

fn main() {
    let root = std::env::args()
        .nth(1)
        .map_or_else(|| Path::new("../..").to_path_buf(), Into::into);
    let (ns, v) = feather_scenario(&root);
    println!("feather\tmechkit (scenario, formula force)\t{ns:.2}\t{v:.6}");
    let (ns, v) = feather_loop();
    println!("feather\thand-written Rust loop\t{ns:.2}\t{v:.6}");
    let (ns, value) = trapz_samples();
    println!("trapz\tmechkit::quad::trapz\t{ns:.3}\t{value:.9}");
}

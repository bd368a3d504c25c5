//! Kepler-orbit benchmark: mechkit's adaptive Runge-Kutta integrators (dopri5, dop853) against
//! the `ode_solvers` crate (Dopri5, Dop853) on the same problem, with the same right-hand side.
//!
//! Problem: GM = 1, semi-major axis 1, e = 0.5, from perihelion, t = 0 .. 100 · 2π (100
//! orbits), rtol = 1e-9, atol = 1e-12. The exact final state is the initial state.
//!
//! Run with
//! `CARGO_TARGET_DIR=/work/main/bench/ode_compare/target cargo run --release`.

use std::cell::Cell;
use std::hint::black_box;
use std::time::{Duration, Instant};

use mechkit::ode::reference::Kepler;
use mechkit::ode::{AdaptiveConfig, AdaptiveRk, Controller, OdeSystem, State, Tableau, Tolerance};
use ode_solvers::{Dop853, Dopri5, OutputType, System, Vector4};

const ECC: f64 = 0.5;
const ORBITS: f64 = 100.0;
const RTOL: f64 = 1e-9;
const ATOL: f64 = 1e-12;
/// Timed runs per method; the table reports the best (and the median).
const REPEATS: usize = 20;

/// The Kepler right-hand side shared by both wrappers: `[vx, vy, -x/r³, -y/r³]`, the same
/// arithmetic as `mechkit::ode::reference::Kepler`.
#[inline(always)]
fn kepler_rhs(x: f64, y: f64, vx: f64, vy: f64) -> [f64; 4] {
    let r2 = x * x + y * y;
    let s = -1.0 / (r2 * r2.sqrt());
    [vx, vy, s * x, s * y]
}

/// mechkit side: an `OdeSystem` counting its calls.
struct MkKepler<'a> {
    calls: &'a Cell<u64>,
}

impl OdeSystem for MkKepler<'_> {
    fn dim(&self) -> usize {
        4
    }

    fn rhs_into(&self, _t: f64, y: &[f64], dydt: &mut [f64]) {
        self.calls.set(self.calls.get() + 1);
        let d = kepler_rhs(y[0], y[1], y[2], y[3]);
        dydt[..4].copy_from_slice(&d);
    }
}

/// ode_solvers side: a `System` counting its calls.
struct OsKepler<'a> {
    calls: &'a Cell<u64>,
}

impl System<f64, Vector4<f64>> for OsKepler<'_> {
    fn system(&self, _t: f64, y: &Vector4<f64>, dy: &mut Vector4<f64>) {
        self.calls.set(self.calls.get() + 1);
        let d = kepler_rhs(y[0], y[1], y[2], y[3]);
        dy[0] = d[0];
        dy[1] = d[1];
        dy[2] = d[2];
        dy[3] = d[3];
    }
}

/// What one run produced.
struct Run {
    /// Calls of the right-hand side, counted by the wrapper.
    counted: u64,
    /// Evaluations as the library reports them.
    reported: u64,
    accepted: u64,
    rejected: u64,
    t_final: f64,
    y_final: [f64; 4],
}

struct Row {
    name: String,
    run: Run,
    best: Duration,
    median: Duration,
}

fn t_end() -> f64 {
    ORBITS * 2.0 * std::f64::consts::PI
}

fn mechkit_run(tableau: &Tableau, controller: Option<Controller>) -> Run {
    let k = Kepler { e: ECC };
    let calls = Cell::new(0);
    let sys = MkKepler { calls: &calls };
    let config = AdaptiveConfig {
        rtol: Tolerance::Scalar(RTOL),
        atol: Tolerance::Scalar(ATOL),
        controller,
        ..AdaptiveConfig::default()
    };
    let t_end = t_end();
    let mut rk = AdaptiveRk::new(tableau.clone(), config).expect("valid settings");
    let mut s = State::new(0.0, k.initial().to_vec());
    while s.t < t_end {
        rk.step(&sys, &mut s, t_end).expect("step");
    }
    let st = rk.stats();
    Run {
        counted: calls.get(),
        reported: st.evaluations,
        accepted: st.accepted,
        rejected: st.rejected,
        t_final: s.t,
        y_final: [s.y[0], s.y[1], s.y[2], s.y[3]],
    }
}

/// ode_solvers settings: the library's defaults from `new` (Hairer's automatic first step,
/// its default controller, h_max = t_end - t0, n_max = 100000) except the output type, which
/// is `Sparse` (the solution at every accepted step, no interpolation; `dx` is then unused
/// and passed as 0). The default `Dense` output would cost DOP853 three extra evaluations per
/// step for its interpolant.
fn ode_solvers_run(dop853: bool) -> Run {
    let k = Kepler { e: ECC };
    let calls = Cell::new(0);
    let sys = OsKepler { calls: &calls };
    let y0 = k.initial();
    let y0 = Vector4::new(y0[0], y0[1], y0[2], y0[3]);
    let (stats, t_final, y) = if dop853 {
        let mut st = Dop853::new(sys, 0.0, t_end(), 0.0, y0, RTOL, ATOL);
        st.set_output(OutputType::Sparse);
        let stats = st.integrate().expect("integrate");
        (stats, *st.x_out().last().unwrap(), *st.y_out().last().unwrap())
    } else {
        let mut st = Dopri5::new(sys, 0.0, t_end(), 0.0, y0, RTOL, ATOL);
        st.set_output(OutputType::Sparse);
        let stats = st.integrate().expect("integrate");
        (stats, *st.x_out().last().unwrap(), *st.y_out().last().unwrap())
    };
    Run {
        counted: calls.get(),
        reported: u64::from(stats.num_eval),
        accepted: u64::from(stats.accepted_steps),
        rejected: u64::from(stats.rejected_steps),
        t_final,
        y_final: [y[0], y[1], y[2], y[3]],
    }
}

fn time<F: FnMut() -> Run>(name: &str, mut f: F) -> Row {
    let run = f(); // warm-up, and the numbers reported
    let mut times = Vec::with_capacity(REPEATS);
    for _ in 0..REPEATS {
        let start = Instant::now();
        let r = black_box(f());
        times.push(start.elapsed());
        assert_eq!(r.counted, run.counted, "runs are deterministic");
    }
    times.sort();
    Row {
        name: name.to_string(),
        run,
        best: times[0],
        median: times[REPEATS / 2],
    }
}

/// Bare cost of one right-hand-side call through each wrapper (no integrator), ns.
fn bare_rhs_ns() -> (f64, f64) {
    const N: u64 = 20_000_000;
    let calls = Cell::new(0);
    let k = Kepler { e: ECC }.initial();
    let mk = MkKepler { calls: &calls };
    let mut y = k.to_vec();
    let mut d = vec![0.0; 4];
    let mut best_mk = f64::INFINITY;
    for _ in 0..5 {
        let start = Instant::now();
        for _ in 0..N {
            mk.rhs_into(0.0, black_box(&y), black_box(&mut d));
            y[0] = black_box(y[0]);
        }
        best_mk = best_mk.min(start.elapsed().as_secs_f64() * 1e9 / N as f64);
    }
    let os = OsKepler { calls: &calls };
    let yv = Vector4::new(k[0], k[1], k[2], k[3]);
    let mut dv = Vector4::zeros();
    let mut best_os = f64::INFINITY;
    for _ in 0..5 {
        let start = Instant::now();
        for _ in 0..N {
            os.system(0.0, black_box(&yv), black_box(&mut dv));
        }
        best_os = best_os.min(start.elapsed().as_secs_f64() * 1e9 / N as f64);
    }
    (best_mk, best_os)
}

fn main() {
    if let Ok(which) = std::env::var("PROFILE") {
        // for `perf record` / `valgrind`: one integrator, PROFILE_RUNS (200) runs
        let run: fn() -> Run = match which.as_str() {
            "mechkit-dopri5" => || mechkit_run(&Tableau::dopri5(), None),
            "mechkit-dop853" => || mechkit_run(&Tableau::dop853(), None),
            "ode_solvers-dopri5" => || ode_solvers_run(false),
            "ode_solvers-dop853" => || ode_solvers_run(true),
            _ => panic!(
                "PROFILE is one of mechkit-dopri5, mechkit-dop853, ode_solvers-dopri5, ode_solvers-dop853"
            ),
        };
        let runs: u64 = std::env::var("PROFILE_RUNS").map_or(200, |r| r.parse().expect("a count"));
        let mut evaluations = 0;
        for _ in 0..runs {
            evaluations += black_box(run()).counted;
        }
        println!("{which}: {evaluations} RHS evaluations in {runs} runs");
        return;
    }
    let k = Kepler { e: ECC };
    let t_end = t_end();
    // The exact final state is the initial state (period 2π); Kepler's equation at the
    // floating-point t_end agrees with it to round-off.
    let exact = k.initial();
    let via_kepler = k.exact(t_end);
    let kepler_gap = (0..4)
        .map(|i| (via_kepler[i] - exact[i]).powi(2))
        .sum::<f64>()
        .sqrt();

    let ode_solvers_dopri5_controller = Controller {
        safety: 0.9,
        beta: 0.04,
        min_factor: 0.2,
        max_factor: 10.0,
        predictive: false,
    };
    let ode_solvers_dop853_controller = Controller {
        safety: 0.9,
        beta: 0.0,
        min_factor: 0.333,
        max_factor: 6.0,
        predictive: false,
    };

    let main_rows = vec![
        time("mechkit dopri5", || mechkit_run(&Tableau::dopri5(), None)),
        time("mechkit dop853", || mechkit_run(&Tableau::dop853(), None)),
        time("ode_solvers Dopri5", || ode_solvers_run(false)),
        time("ode_solvers Dop853", || ode_solvers_run(true)),
    ];
    let matched_rows = vec![
        time("mechkit dopri5, ode_solvers' controller", || {
            mechkit_run(&Tableau::dopri5(), Some(ode_solvers_dopri5_controller))
        }),
        time("mechkit dop853, ode_solvers' controller", || {
            mechkit_run(&Tableau::dop853(), Some(ode_solvers_dop853_controller))
        }),
    ];

    println!(
        "Kepler e = {ECC}, {ORBITS} orbits (t_end = {t_end}), rtol = {RTOL:e}, atol = {ATOL:e}; \
         time: best (median) of {REPEATS} runs"
    );
    println!("(|exact(t_end) - initial| from Kepler's equation: {kepler_gap:.1e})\n");
    let header = "| method | RHS evals (counted) | evals reported by library | accepted | rejected | position error | rel. energy error | wall time / run, ms: best (median) | ns per RHS eval |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|";
    let print_rows = |rows: &[Row]| {
        println!("{header}");
        for r in rows {
            let y = r.run.y_final;
            assert!(
                (r.run.t_final - t_end).abs() <= 1e-12 * t_end,
                "{} stopped at t = {}",
                r.name,
                r.run.t_final
            );
            let pos_err = ((y[0] - exact[0]).powi(2) + (y[1] - exact[1]).powi(2)).sqrt();
            let energy_err = (k.energy(&y) + 0.5).abs() / 0.5;
            let best_ms = r.best.as_secs_f64() * 1e3;
            let median_ms = r.median.as_secs_f64() * 1e3;
            let ns_per_eval = r.best.as_secs_f64() * 1e9 / r.run.counted as f64;
            println!(
                "| {} | {} | {} | {} | {} | {:.2e} | {:.2e} | {:.3} ({:.3}) | {:.1} |",
                r.name,
                r.run.counted,
                r.run.reported,
                r.run.accepted,
                r.run.rejected,
                pos_err,
                energy_err,
                best_ms,
                median_ms,
                ns_per_eval
            );
        }
    };
    print_rows(&main_rows);
    println!("\nmechkit with the controller settings of ode_solvers' defaults (no predictive limit):\n");
    print_rows(&matched_rows);

    let (mk_ns, os_ns) = bare_rhs_ns();
    println!(
        "\nBare RHS call (no integrator), best of 5 x 2e7 calls: mechkit wrapper (slices) {mk_ns:.2} ns, ode_solvers wrapper (Vector4) {os_ns:.2} ns"
    );
}

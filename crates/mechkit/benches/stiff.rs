//! Work-precision of the implicit methods on the stiff test set (issue 28): for each problem
//! and tolerance, the error against the reference, steps, right-hand-side evaluations,
//! Jacobians and wall time, as tab-separated lines; `bench/stiff/run` runs SciPy's Radau,
//! BDF and LSODA on the same problems and tolerances and joins the two.
//!
//! Run with `cargo bench -p mechkit --bench stiff` (add `-- --quick` for one tolerance per
//! problem, `-- --only chain --solver radau5` for one problem and method). The chains also run with their Jacobian pattern hidden (`radau5-dense`,
//! `bdf-dense`): the dense LU they were solved with before the banded one. References:
//! published ones (Robertson, HIRES, Pleiades), else DOP853 at rtol = 1e-13, an independent
//! method; written to `$STIFF_REFERENCES` (default
//! `stiff_references.json` in the working directory) for the SciPy side.

use std::time::Instant;

use mechkit::ode::testset::{Hires, Pleiades, Robertson, SpringChain, VanDerPol};
use mechkit::ode::{
    AdaptiveConfig, AdaptiveRk, AdaptiveStats, Bdf, OdeSystem, Radau5, State, Tableau, Tolerance,
};

struct Problem {
    name: &'static str,
    sys: Box<dyn OdeSystem>,
    y0: Vec<f64>,
    t_end: f64,
    /// `atol = rtol · atol_factor`.
    atol_factor: f64,
    /// The components compared with the reference.
    compared: usize,
    reference: Option<Vec<f64>>,
    tolerances: &'static [f64],
}

fn problems() -> Vec<Problem> {
    vec![
        Problem {
            name: "vdp",
            sys: Box::new(VanDerPol { mu: 1000.0 }),
            y0: vec![2.0, 0.0],
            t_end: 2000.0,
            atol_factor: 1.0,
            compared: 1,
            reference: None,
            tolerances: &[1e-4, 1e-5, 1e-6, 1e-7, 1e-8],
        },
        Problem {
            name: "robertson",
            sys: Box::new(Robertson),
            y0: vec![1.0, 0.0, 0.0],
            t_end: 40.0,
            atol_factor: 1e-6,
            compared: 3,
            reference: Some(Robertson::REFERENCE_40.to_vec()),
            tolerances: &[1e-4, 1e-6, 1e-8],
        },
        Problem {
            name: "hires",
            sys: Box::new(Hires),
            y0: Hires::INITIAL.to_vec(),
            t_end: Hires::T_END,
            atol_factor: 1e-4,
            compared: 8,
            reference: Some(Hires::REFERENCE.to_vec()),
            tolerances: &[1e-4, 1e-6, 1e-8],
        },
        Problem {
            name: "pleiades",
            sys: Box::new(Pleiades),
            y0: Pleiades::initial(),
            t_end: 3.0,
            atol_factor: 1.0,
            compared: 14,
            reference: Some(Pleiades::REFERENCE.to_vec()),
            tolerances: &[1e-4, 1e-6, 1e-8],
        },
        chain("chain", 20, 0.1),
        chain("chain200", 200, 1.0),
    ]
}

/// A chain of `n` stiff damped springs pulled at its end, from rest to `t_end`.
fn chain(name: &'static str, n: usize, t_end: f64) -> Problem {
    Problem {
        name,
        sys: Box::new(SpringChain {
            n,
            k: 1e6,
            c: 2e4,
            pull: 1e3,
        }),
        y0: vec![0.0; 2 * n],
        t_end,
        atol_factor: 1e-3,
        compared: 20,
        reference: None,
        tolerances: &[1e-4, 1e-6, 1e-8],
    }
}

/// A system without its Jacobian pattern: the implicit methods factor it dense, as they all
/// did before the banded solver (the chains' "before").
struct Dense<'a>(&'a dyn OdeSystem);

impl OdeSystem for Dense<'_> {
    fn dim(&self) -> usize {
        self.0.dim()
    }
    fn rhs_into(&self, t: f64, y: &[f64], dydt: &mut [f64]) {
        self.0.rhs_into(t, y, dydt);
    }
    fn jacobian_into(&self, t: f64, y: &[f64], jac: &mut [f64]) -> bool {
        self.0.jacobian_into(t, y, jac)
    }
}

fn radau5_dense(
    sys: &dyn OdeSystem,
    y0: &[f64],
    t_end: f64,
    rtol: f64,
    atol: f64,
) -> (Vec<f64>, AdaptiveStats, u64) {
    radau5(&Dense(sys), y0, t_end, rtol, atol)
}

fn bdf_dense(
    sys: &dyn OdeSystem,
    y0: &[f64],
    t_end: f64,
    rtol: f64,
    atol: f64,
) -> (Vec<f64>, AdaptiveStats, u64) {
    bdf(&Dense(sys), y0, t_end, rtol, atol)
}

fn config(rtol: f64, atol: f64) -> AdaptiveConfig {
    AdaptiveConfig {
        rtol: Tolerance::Scalar(rtol),
        atol: Tolerance::Scalar(atol),
        ..AdaptiveConfig::default()
    }
}

/// One solve: the final state and the counters (steps, evaluations, Jacobians).
type Solve = fn(&dyn OdeSystem, &[f64], f64, f64, f64) -> (Vec<f64>, AdaptiveStats, u64);

fn radau5(
    sys: &dyn OdeSystem,
    y0: &[f64],
    t_end: f64,
    rtol: f64,
    atol: f64,
) -> (Vec<f64>, AdaptiveStats, u64) {
    let mut r = Radau5::new(config(rtol, atol));
    let mut s = State::new(0.0, y0.to_vec());
    while s.t < t_end {
        r.step(sys, &mut s, t_end).expect("radau5 step");
    }
    (s.y, r.stats(), r.implicit_stats().jacobians)
}

fn bdf(
    sys: &dyn OdeSystem,
    y0: &[f64],
    t_end: f64,
    rtol: f64,
    atol: f64,
) -> (Vec<f64>, AdaptiveStats, u64) {
    let mut r = Bdf::new(config(rtol, atol));
    let mut s = State::new(0.0, y0.to_vec());
    while s.t < t_end {
        r.step(sys, &mut s, t_end).expect("bdf step");
    }
    (s.y, r.stats(), r.implicit_stats().jacobians)
}

fn dop853(
    sys: &dyn OdeSystem,
    y0: &[f64],
    t_end: f64,
    rtol: f64,
    atol: f64,
) -> (Vec<f64>, AdaptiveStats, u64) {
    let mut r = AdaptiveRk::new(Tableau::dop853(), config(rtol, atol)).expect("adaptive");
    let mut s = State::new(0.0, y0.to_vec());
    while s.t < t_end {
        r.step(sys, &mut s, t_end).expect("dop853 step");
    }
    (s.y, r.stats(), 0)
}

fn error(y: &[f64], reference: &[f64]) -> f64 {
    y.iter()
        .zip(reference)
        .map(|(a, b)| (a - b).abs() / b.abs())
        .fold(0.0, f64::max)
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let quick = args.iter().any(|a| a == "--quick");
    // `--only NAME`: one problem (for profiling)
    let only = args
        .iter()
        .position(|a| a == "--only")
        .and_then(|i| args.get(i + 1).cloned());
    // `--solver NAME`: one method (for profiling)
    let solver = args
        .iter()
        .position(|a| a == "--solver")
        .and_then(|i| args.get(i + 1).cloned());
    let methods: &[(&str, Solve)] = &[
        ("radau5", radau5),
        ("bdf", bdf),
        ("dop853", dop853),
        ("radau5-dense", radau5_dense),
        ("bdf-dense", bdf_dense),
    ];
    let mut references = Vec::new();
    println!("problem\tsolver\ttol\terror\tsteps\tevaluations\tjacobians\twall_s");
    for p in problems() {
        if only.as_ref().is_some_and(|o| o != p.name) {
            continue;
        }
        let reference = p.reference.clone().unwrap_or_else(|| {
            let (y, _, _) = dop853(&*p.sys, &p.y0, p.t_end, 1e-13, 1e-13 * p.atol_factor);
            y[..p.compared].to_vec()
        });
        references.push(format!("\"{}\": {:?}", p.name, reference));
        let tolerances = if quick {
            &p.tolerances[2..3]
        } else {
            p.tolerances
        };
        for &tol in tolerances {
            for (name, solve) in methods {
                if solver.as_ref().is_some_and(|o| o != name) {
                    continue;
                }
                // DOP853 on the stiff problems only where it finishes in reasonable time
                if *name == "dop853" && p.name == "vdp" && tol < 1e-6 {
                    continue;
                }
                // the dense factorisations only where the banded one is used: the chains
                // (and not at 1e-8 on the long chain, where a dense solve takes seconds)
                if name.ends_with("-dense")
                    && (!p.name.starts_with("chain") || (p.name == "chain200" && tol < 1e-6))
                {
                    continue;
                }
                let atol = tol * p.atol_factor;
                let (y, stats, jacobians) = solve(&*p.sys, &p.y0, p.t_end, tol, atol);
                let start = Instant::now();
                let mut runs = 0u32;
                while runs < 3 || start.elapsed().as_secs_f64() < 0.3 {
                    std::hint::black_box(solve(&*p.sys, &p.y0, p.t_end, tol, atol));
                    runs += 1;
                }
                let wall = start.elapsed().as_secs_f64() / f64::from(runs);
                println!(
                    "{}\t{name}\t{tol:e}\t{:.3e}\t{}\t{}\t{jacobians}\t{wall:.3e}",
                    p.name,
                    error(&y[..p.compared], &reference),
                    stats.accepted,
                    stats.evaluations,
                );
            }
        }
    }
    let json = format!("{{{}}}\n", references.join(", "));
    let path = std::env::var("STIFF_REFERENCES").unwrap_or_else(|_| "stiff_references.json".into());
    std::fs::write(&path, json).expect("write the references");
}

//! Work-precision study of the adaptive step-size controllers: for each method, problem and
//! controller, the right-hand-side evaluations needed to reach a given final error, found by a
//! log-log fit over a sweep of tolerances (so single lucky tolerances do not decide).
//!
//! Run with `cargo bench -p mechkit --bench work_precision`.

use mechkit::ode::reference::{Arenstorf, Kepler};
use mechkit::ode::{AdaptiveConfig, AdaptiveRk, Controller, OdeSystem, State, Tableau, Tolerance};

struct Problem {
    name: &'static str,
    sys: Box<dyn OdeSystem>,
    y0: Vec<f64>,
    t_end: f64,
    exact: Vec<f64>,
}

fn problems() -> Vec<Problem> {
    let kepler = |e: f64, orbits: f64| {
        let k = Kepler { e };
        let t_end = orbits * 2.0 * std::f64::consts::PI;
        Problem {
            name: if e < 0.7 {
                "kepler e=0.5, 100 orbits"
            } else {
                "kepler e=0.9, 20 orbits"
            },
            sys: Box::new(k),
            y0: k.initial().to_vec(),
            t_end,
            exact: k.exact(t_end).to_vec(),
        }
    };
    vec![
        kepler(0.5, 100.0),
        kepler(0.9, 20.0),
        Problem {
            name: "arenstorf, 3 periods",
            sys: Box::new(Arenstorf),
            y0: Arenstorf.initial().to_vec(),
            t_end: 3.0 * Arenstorf::PERIOD,
            exact: Arenstorf.initial().to_vec(),
        },
    ]
}

fn solve(p: &Problem, tableau: &Tableau, rtol: f64, controller: Controller) -> (u64, f64) {
    let config = AdaptiveConfig {
        rtol: Tolerance::Scalar(rtol),
        atol: Tolerance::Scalar(rtol * 1e-3),
        controller: Some(controller),
        ..AdaptiveConfig::default()
    };
    let mut rk = AdaptiveRk::new(tableau.clone(), config).expect("valid settings");
    let mut s = State::new(0.0, p.y0.clone());
    while s.t < p.t_end {
        rk.step(&*p.sys, &mut s, p.t_end)
            .expect("the step size stays reasonable");
    }
    let err = s.y[..2]
        .iter()
        .zip(&p.exact)
        .map(|(a, b)| (a - b).powi(2))
        .sum::<f64>()
        .sqrt();
    (rk.stats().evaluations, err)
}

/// Evaluations at the error `target` from a log-log least-squares line through the five
/// points of the sweep nearest to it.
fn evaluations_at(points: &[(f64, f64)], target: f64) -> f64 {
    let mut points = points.to_vec();
    points.sort_by(|a, b| {
        (a.0 - target.ln())
            .abs()
            .total_cmp(&(b.0 - target.ln()).abs())
    });
    points.truncate(5);
    let n = points.len() as f64;
    let (mx, my) = (
        points.iter().map(|p| p.0).sum::<f64>() / n,
        points.iter().map(|p| p.1).sum::<f64>() / n,
    );
    let sxy: f64 = points.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let sxx: f64 = points.iter().map(|p| (p.0 - mx).powi(2)).sum();
    (my + sxy / sxx * (target.ln() - mx)).exp()
}

fn main() {
    let controllers = [
        (
            "I, safety 0.9 (scipy)",
            Controller {
                safety: 0.9,
                beta: 0.0,
                min_factor: 0.2,
                max_factor: 10.0,
                predictive: false,
            },
        ),
        (
            "PI 0.04, safety 0.9 (dopri5)",
            Controller {
                safety: 0.9,
                beta: 0.04,
                min_factor: 0.2,
                max_factor: 10.0,
                predictive: false,
            },
        ),
        (
            "I, safety 0.8",
            Controller {
                safety: 0.8,
                beta: 0.0,
                min_factor: 0.2,
                max_factor: 10.0,
                predictive: false,
            },
        ),
        (
            "PI 0.04, safety 0.8",
            Controller {
                safety: 0.8,
                beta: 0.04,
                min_factor: 0.2,
                max_factor: 10.0,
                predictive: false,
            },
        ),
        (
            "I + predictive, safety 0.9",
            Controller {
                safety: 0.9,
                beta: 0.0,
                min_factor: 0.2,
                max_factor: 10.0,
                predictive: true,
            },
        ),
        (
            "PI 0.04 + predictive, 0.9",
            Controller {
                safety: 0.9,
                beta: 0.04,
                min_factor: 0.2,
                max_factor: 10.0,
                predictive: true,
            },
        ),
        (
            "PI 0.02 + predictive, 0.9",
            Controller {
                safety: 0.9,
                beta: 0.02,
                min_factor: 0.2,
                max_factor: 10.0,
                predictive: true,
            },
        ),
    ];
    for tableau in [Tableau::dopri5(), Tableau::dop853()] {
        for p in problems() {
            println!(
                "\n{} on {}: evaluations to reach the final position error",
                tableau.name, p.name
            );
            let sweeps: Vec<Vec<(f64, f64)>> = controllers
                .iter()
                .map(|(_, c)| {
                    (0..15)
                        .map(|i| {
                            let rtol = 10f64.powf(-5.0 - 0.5 * f64::from(i));
                            let (ev, err) = solve(&p, &tableau, rtol, *c);
                            (err.max(1e-300).ln(), (ev as f64).ln())
                        })
                        .collect()
                })
                .collect();
            let targets: Vec<f64> = {
                let base = &sweeps[0];
                [base[4].0, base[8].0, base[12].0]
                    .iter()
                    .map(|x| x.exp())
                    .collect()
            };
            print!("{:32}", "controller");
            for t in &targets {
                print!("  err {t:9.2e}");
            }
            println!();
            for ((name, _), sweep) in controllers.iter().zip(&sweeps) {
                print!("{name:32}");
                for t in &targets {
                    print!("  {:>13.0}", evaluations_at(sweep, *t));
                }
                println!();
            }
        }
    }
}

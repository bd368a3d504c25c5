//! `mechkit rocket`: the rocket equation in free space and in gravity with the coast to the
//! apex (closed form and simulation agree), drag (the simulation falls below the drag-free
//! closed form), the text report and the plots, and bad input (m1 ≥ m0, a negative rate, a
//! wrong dimension).

use crate::util::{Dir, at, num};

const ROCKET: [&str; 9] = [
    "rocket",
    "--m0",
    "1000 kg",
    "--m1",
    "400 kg",
    "--mass-rate",
    "10 kg/s",
    "--exhaust-speed",
    "2 km/s",
];

fn json(dir: &Dir, extra: &[&str]) -> serde_json::Value {
    dir.json_with(&ROCKET, extra)
}

#[test]
fn free_space_is_tsiolkovsky() {
    let j = json(&Dir::new(), &["--no-plots"]);
    let dv = 2000.0 * 2.5f64.ln();
    assert!((num(&j, "/delta_v") - dv).abs() < 1e-12 * dv);
    assert_eq!(num(&j, "/burn_time"), 60.0);
    assert_eq!(num(&j, "/burnout/t"), 60.0);
    assert!((num(&j, "/burnout/v/simulated") - dv).abs() < 1e-8 * dv);
    assert!(num(&j, "/burnout/v/difference").abs() < 1e-8 * dv);
    assert_eq!(at(&j, "/apex"), &serde_json::Value::Null);
    assert_eq!(at(&j, "/plots"), &serde_json::Value::Null);
}

#[test]
fn gravity_and_coast_with_plots() {
    let dir = Dir::new();
    let j = json(&dir, &["--g", "9.81 m/s^2", "--coast", "--out", "plots"]);
    let (v1, x1) = (
        num(&j, "/burnout/v/closed_form"),
        num(&j, "/burnout/x/closed_form"),
    );
    assert!((v1 - (2000.0 * 2.5f64.ln() - 9.81 * 60.0)).abs() < 1e-9);
    assert!((num(&j, "/burnout/x/difference")).abs() < 1e-8 * x1);
    let apex = num(&j, "/apex/x/simulated");
    assert!((apex - (x1 + v1 * v1 / (2.0 * 9.81))).abs() < 1e-8 * apex);
    assert!((num(&j, "/apex/t/simulated") - (60.0 + v1 / 9.81)).abs() < 1e-8);
    assert_eq!(at(&j, "/lifts_off"), true);
    for name in ["v_t", "x_t", "m_t"] {
        assert!(
            dir.read(&format!("plots/{name}.svg")).starts_with("<svg"),
            "{name}"
        );
    }
    // the text report shows both columns and the differences
    let mut args = ROCKET.to_vec();
    args.extend_from_slice(&["--g", "9.81", "--coast", "--no-plots"]);
    let out = dir.run(&args);
    out.assert_code(0);
    for needle in [
        "Δv = u ln(m0/m1) = 1832.58146",
        "burn time T = (m0 - m1)/ṁ = 60 s",
        "closed form",
        "simulated",
        "burnout speed [m/s]",
        "apex height [m]",
        "dopri5",
    ] {
        assert!(out.stdout.contains(needle), "{needle}:\n{}", out.stdout);
    }
}

#[test]
fn drag_lowers_the_flight() {
    let j = json(
        &Dir::new(),
        &[
            "--g",
            "9.81 m/s^2",
            "--drag",
            "0.02 kg/m",
            "--coast",
            "--no-plots",
        ],
    );
    assert_eq!(num(&j, "/drag"), 0.02);
    assert!(num(&j, "/burnout/v/difference") < 0.0);
    assert!(num(&j, "/apex/x/simulated") < num(&j, "/apex/x/closed_form"));
}

#[test]
fn bad_input() {
    let dir = Dir::new();
    let run = |replace: (usize, &str), extra: &[&str]| {
        let mut args = ROCKET.to_vec();
        args[replace.0] = replace.1;
        args.extend_from_slice(extra);
        args.push("--no-plots");
        dir.run(&args)
    };
    run((4, "1000 kg"), &[]).assert_bad_input(&["--m1", "must be below the mass at ignition"]);
    run((4, "2000 kg"), &[]).assert_bad_input(&["--m1", "must be below"]);
    run((6, "-10 kg/s"), &[]).assert_bad_input(&["--mass-rate", "must be positive"]);
    run((6, "10 kg"), &[]).assert_bad_input(&["--mass-rate", "mass rate (kg/s"]);
    run((2, "1000 m"), &[]).assert_bad_input(&["--m0", "mass"]);
    run((8, "2 km"), &[]).assert_bad_input(&["--exhaust-speed", "velocity"]);
    run((0, "rocket"), &["--g", "-9.81"]).assert_bad_input(&["--g", "must be 0"]);
    run((0, "rocket"), &["--drag", "0.1 kg"]).assert_bad_input(&["--drag", "quadratic drag"]);
    run((0, "rocket"), &["--rtol", "0"]).assert_bad_input(&["--rtol"]);
}

//! `mechkit friction`: the incline report (normal force, static bound, marginal angle, sliding
//! acceleration) against the closed forms; the stick-slip mode (the earthquake model: first
//! stick at `μs N/(k w)`, every switch at its closed-form time, the energy ledger closed, the
//! CSV and the plots); the `μs < μd` warning; bad input (a negative coefficient, degrees
//! given as radians, a missing `--t-max`).

use crate::util::{Csv, Dir, at, num};

fn json(dir: &Dir, args: &[&str]) -> serde_json::Value {
    dir.json_with(&["friction"], args)
}

#[test]
fn incline_report_matches_the_closed_forms() {
    let dir = Dir::new();
    let base = ["--mass", "2 kg", "--mu-s", "0.5", "--mu-d", "0.3"];
    let mut args = base.to_vec();
    args.extend_from_slice(&["--angle", "20 deg"]);
    let j = json(&dir, &args);
    let a = 20f64.to_radians();
    assert!((num(&j, "/normal_force") - 2.0 * 9.81 * a.cos()).abs() < 1e-12);
    assert!((num(&j, "/max_static_friction") - 0.5 * 2.0 * 9.81 * a.cos()).abs() < 1e-12);
    assert!((num(&j, "/marginal_angle_deg") - 0.5f64.atan().to_degrees()).abs() < 1e-12);
    assert_eq!(at(&j, "/slides"), false);
    assert_eq!(num(&j, "/acceleration"), 0.0);
    let mut args = base.to_vec();
    args.extend_from_slice(&["--angle", "30 deg"]);
    let j = json(&dir, &args);
    let a = 30f64.to_radians();
    assert_eq!(at(&j, "/slides"), true);
    assert!((num(&j, "/acceleration") - 9.81 * (a.sin() - 0.3 * a.cos())).abs() < 1e-12);
    // the text report
    let mut args = vec!["friction"];
    args.extend_from_slice(&base);
    args.extend_from_slice(&["--angle", "30 deg"]);
    let out = dir.run(&args);
    out.assert_code(0);
    for needle in [
        "normal force N = m g cos α",
        "16.99142 N",
        "marginal angle",
        "26.56505",
        "slides",
        "2.356287 m/s²",
    ] {
        assert!(out.stdout.contains(needle), "{needle}:\n{}", out.stdout);
    }
}

#[test]
fn earthquake_model_switches_at_closed_form_times_with_csv_and_plots() {
    let dir = Dir::new();
    let j = json(
        &dir,
        &[
            "--mass",
            "1 kg",
            "--mu-s",
            "0.6",
            "--mu-d",
            "0.4",
            "--spring-k",
            "100 N/m",
            "--anchor-speed",
            "5 cm/s",
            "--t-max",
            "8 s",
            "--out",
            "quake",
        ],
    );
    let phases = at(&j, "/stick_slip/phases").as_array().unwrap();
    assert!(phases.len() >= 12, "{}", phases.len());
    assert!((num(&phases[0], "/t_end") - 0.6 * 9.81 / (100.0 * 0.05)).abs() < 1e-12);
    // every slip lasts (2π − 2 atan(Ω D/w))/Ω, D = (μs − μd) m g/k
    let d = 0.2 * 9.81 / 100.0;
    let slip = (2.0 * std::f64::consts::PI - 2.0 * (10.0 * d / 0.05f64).atan()) / 10.0;
    let mut slips = 0;
    for p in phases {
        if p["ended_by"] == "switch" {
            let diff = num(p, "/t_end") - num(p, "/t_end_closed_form");
            assert!(diff.abs() < 1e-11, "{p}");
        }
        if p["regime"] == "slip+" {
            slips += 1;
            assert!((num(p, "/t_end") - num(p, "/t_start") - slip).abs() < 1e-11);
        }
    }
    assert!(slips >= 6);
    assert_eq!(num(&j, "/stick_slip/slip_phases"), f64::from(slips));
    assert!(num(&j, "/stick_slip/energy/residual").abs() < 1e-10);
    assert!(num(&j, "/stick_slip/energy/heat") > 0.0);
    let csv = Csv::parse(&dir.read("quake/stick_slip.csv"));
    let (t, v, stuck) = (csv.column("t"), csv.column("v"), csv.column("stuck"));
    assert!(csv.rows.len() > 1000);
    for row in &csv.rows {
        if row[stuck] == 1.0 {
            assert_eq!(row[v], 0.0, "stuck on a fixed floor at t = {}", row[t]);
        }
    }
    assert_eq!(csv.rows.last().unwrap()[t], 8.0);
    for plot in ["x_t", "v_t", "forces_t"] {
        assert!(
            dir.read(&format!("quake/{plot}.svg")).starts_with("<svg"),
            "{plot}"
        );
    }
    // the text report lists the phases with their closed-form ends
    let out = dir.run(&[
        "friction",
        "--mass",
        "1 kg",
        "--mu-s",
        "0.6",
        "--mu-d",
        "0.4",
        "--spring-k",
        "100",
        "--belt-speed",
        "0.1 m/s",
        "--t-max",
        "3 s",
    ]);
    out.assert_code(0);
    for needle in [
        "stick-slip: k = 100 N/m",
        "closed form",
        "slip-",
        "(t_max)",
        "heat",
    ] {
        assert!(out.stdout.contains(needle), "{needle}:\n{}", out.stdout);
    }
}

#[test]
fn mu_static_below_mu_dynamic_warns() {
    let dir = Dir::new();
    let out = dir.run(&[
        "friction", "--mass", "1 kg", "--mu-s", "0.2", "--mu-d", "0.4", "--json",
    ]);
    out.assert_code(0);
    out.assert_stderr_contains("warning: μs = 0.2 is below μd = 0.4");
    let j: serde_json::Value = serde_json::from_str(&out.stdout).unwrap();
    assert_eq!(at(&j, "/warnings").as_array().unwrap().len(), 1);
    // μd bounds sticking: the marginal angle is atan 0.4
    assert!((num(&j, "/marginal_angle_deg") - 0.4f64.atan().to_degrees()).abs() < 1e-12);
}

#[test]
fn bad_input_names_the_flag() {
    let dir = Dir::new();
    dir.run(&["friction", "--mass", "1 kg", "--mu-s=-0.2", "--mu-d", "0.1"])
        .assert_bad_input(&["--mu-s", "-0.2", "zero or positive"]);
    dir.run(&["friction", "--mass", "1 kg", "--mu", "0.3", "--angle", "20"])
        .assert_bad_input(&["--angle", "radians", "20 deg"]);
    dir.run(&[
        "friction",
        "--mass",
        "1 kg",
        "--mu",
        "0.3",
        "--spring-k",
        "10 N/m",
    ])
    .assert_bad_input(&["--t-max"]);
    dir.run(&["friction", "--mass", "0 kg", "--mu", "0.3"])
        .assert_bad_input(&["--mass", "positive"]);
    dir.run(&["friction", "--mass", "1 m", "--mu", "0.3"])
        .assert_bad_input(&["--mass", "dimension"]);
    dir.run(&[
        "friction",
        "--mass",
        "1 kg",
        "--mu",
        "0.3",
        "--normal-load",
        "-20 N",
    ])
    .assert_bad_input(&["--normal-load", "off the surface"]);
}

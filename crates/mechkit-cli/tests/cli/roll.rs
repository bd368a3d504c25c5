//! `mechkit roll`: a sphere with spin on a slope (rolling starts at the closed-form time and
//! speed, to rounding; afterwards the friction is the rolling value), a ball with backspin on
//! a flat floor (it comes back at `(v0 + k R ω0)/(1 + k)`), the CSV and plots, the text
//! report, and bad input (no radius, a negative coefficient, an unknown body).

use crate::util::{Csv, Dir, at, num};

const SPHERE: [&str; 15] = [
    "roll", "--body", "sphere", "--radius", "11 cm", "--mass", "0.45 kg", "--slope", "20 deg",
    "--mu", "0.3", "--v0", "2 m/s", "--t-max", "3 s",
];

fn json(dir: &Dir, extra: &[&str]) -> serde_json::Value {
    dir.json_with(&SPHERE, extra)
}

#[test]
fn sphere_with_backspin_on_a_slope_rolls_at_the_closed_form() {
    let dir = Dir::new();
    let j = json(&dir, &["--omega0", "-30 rad/s", "--out", "ball"]);
    let (a, mu, k, r) = (20f64.to_radians(), 0.3, 0.4, 0.11);
    let vc0 = 2.0 + 30.0 * r;
    let rate = 9.81 * a.sin() - mu * 9.81 * a.cos() * (1.0 + k) / k;
    let t = -vc0 / rate;
    let v = 2.0 + 9.81 * (a.sin() - mu * a.cos()) * t;
    assert!((num(&j, "/roll_start/t/closed_form") - t).abs() < 1e-14 * t);
    assert!((num(&j, "/roll_start/t/simulated") - t).abs() < 1e-6 * t);
    assert!((num(&j, "/roll_start/v/simulated") - v).abs() < 1e-6 * v);
    assert!(num(&j, "/roll_start/t/difference").abs() < 1e-12);
    let f = -0.45 * 9.81 * a.sin() * k / (1.0 + k);
    assert!((num(&j, "/rolling_friction/simulated") - f).abs() < 1e-14);
    let phases = at(&j, "/phases").as_array().unwrap();
    assert_eq!(phases.len(), 2);
    assert_eq!(phases[0]["regime"], "slipping forward");
    assert_eq!(phases[1]["regime"], "rolling");
    assert!(num(&j, "/energy/residual").abs() < 1e-10);
    assert!(num(&j, "/energy/work_friction") < 0.0);
    // the CSV: v = ωR and the rolling friction after the start, friction −μd N before
    let csv = Csv::parse(&dir.read("ball/roll.csv"));
    let (ct, cv, cwr, cf, croll) = (
        csv.column("t"),
        csv.column("v"),
        csv.column("omega_R"),
        csv.column("friction"),
        csv.column("rolling"),
    );
    let n = 0.45 * 9.81 * a.cos();
    for row in &csv.rows {
        if row[croll] == 1.0 {
            assert!((row[cv] - row[cwr]).abs() < 1e-12, "t = {}", row[ct]);
            assert!((row[cf] - f).abs() < 1e-14);
        } else {
            assert!(row[ct] <= t + 1e-12);
            assert!((row[cf] + mu * n).abs() < 1e-14);
        }
    }
    for plot in ["v_t", "energy_t"] {
        assert!(
            dir.read(&format!("ball/{plot}.svg")).starts_with("<svg"),
            "{plot}"
        );
    }
}

#[test]
fn backspin_on_a_flat_floor_comes_back() {
    let dir = Dir::new();
    let out = dir.run(&[
        "roll",
        "--radius",
        "11 cm",
        "--mass",
        "0.45 kg",
        "--mu-s",
        "0.4",
        "--mu-d",
        "0.3",
        "--v0",
        "2 m/s",
        "--omega0",
        "-60 rad/s",
        "--t-max",
        "2 s",
    ]);
    out.assert_code(0);
    for needle in [
        "rolling starts",
        "closed form",
        "angular momentum about the contact point",
        "-0.4571429 m/s",
        "slipping forward",
        "rolling ",
    ] {
        assert!(out.stdout.contains(needle), "{needle}:\n{}", out.stdout);
    }
    let mut args = SPHERE.to_vec();
    args[8] = "0";
    args.extend_from_slice(&["--omega0", "-60 rad/s", "--json"]);
    let j: serde_json::Value = serde_json::from_str(&dir.run(&args).stdout).unwrap();
    let v_f = (2.0 - 0.4 * 0.11 * 60.0) / 1.4;
    assert!((num(&j, "/flat_floor_rolling_speed") - v_f).abs() < 1e-15);
    assert!((num(&j, "/roll_start/v/simulated") - v_f).abs() < 1e-12);
}

#[test]
fn bad_input_names_the_flag() {
    let dir = Dir::new();
    dir.run(&["roll", "--mass", "1 kg", "--mu", "0.3", "--t-max", "1 s"])
        .assert_bad_input(&["--radius", "v = ω R"]);
    dir.run(&[
        "roll", "--mass", "1 kg", "--radius", "0 m", "--mu", "0.3", "--t-max", "1 s",
    ])
    .assert_bad_input(&["--radius", "positive radius"]);
    dir.run(&[
        "roll",
        "--mass",
        "1 kg",
        "--radius",
        "0.1",
        "--mu=-0.3",
        "--t-max",
        "1 s",
    ])
    .assert_bad_input(&["--mu", "-0.3"]);
    dir.run(&[
        "roll", "--body", "cube", "--mass", "1", "--radius", "0.1", "--mu", "0.3", "--t-max", "1",
    ])
    .assert_bad_input(&["--body", "cube", "sphere"]);
    dir.run(&["roll", "--mass", "1", "--radius", "0.1", "--t-max", "1"])
        .assert_bad_input(&["--mu"]);
    dir.run(&[
        "roll", "--mass", "1", "--radius", "0.1", "--mu", "0.3", "--slope", "20", "--t-max", "1",
    ])
    .assert_bad_input(&["--slope", "20 deg"]);
    let out = dir.run(&[
        "roll", "--mass", "1", "--radius", "0.1", "--mu-s", "0.2", "--mu-d", "0.4", "--t-max", "1",
    ]);
    out.assert_code(0);
    out.assert_stderr_contains("warning: μs = 0.2 is below μd = 0.4");
}

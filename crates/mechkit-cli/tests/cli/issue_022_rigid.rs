//! Issue 22 for the rotation and rigid-body commands (`rotation`, `roll`, `bead`, `friction`,
//! `spin`, `rigid-collide`, `rocket`, `terminal`, `relative`): results are library values
//! printed by one front.
//!
//! What is checked:
//! - `rotation --radius R --centripetal a` gives ω = √(a/R) in rad/s and rpm, the period and
//!   v = ωR; every circle carries ω in rpm;
//! - `roll` reports the slipping phase's accelerations (a = g sin α − μ g cos α,
//!   α = μ m g cos α R/I) apart from the rolling phase's (g sin α/(1 + k), a/R), in the text
//!   and in the JSON, phase by phase;
//! - `bead` at rest (or nearly) on top of a circle says it sits at an unstable equilibrium,
//!   that a small `--speed` makes it slide off, and where: cos φ = 2/3;
//! - `rocket` and `bead` write nothing without `-o`; with it the CSV has its units sidecar,
//!   and plots are named `<y>_<x>` (`v_t.svg`), never `v(t).svg`;
//! - `-q` silences the text report, not `--json`;
//! - errors name the flag from the library's structured input (a tilt, a belt speed) and
//!   count components in the singular and the plural.

use crate::util::{Csv, Dir, at, num};

#[test]
fn rotation_from_the_centripetal_acceleration_and_the_radius() {
    let dir = Dir::new();
    let j = dir
        .run(&[
            "rotation",
            "--radius",
            "5 m",
            "--centripetal",
            "9.81 m/s^2",
            "--json",
        ])
        .json();
    let w = (9.81f64 / 5.0).sqrt();
    assert_eq!(at(&j, "/mode").as_str(), Some("circle"));
    assert!((num(&j, "/omega") - w).abs() < 1e-15);
    assert!((num(&j, "/omega_rpm") - w * 60.0 / std::f64::consts::TAU).abs() < 1e-12);
    assert!((num(&j, "/period") - std::f64::consts::TAU / w).abs() < 1e-14);
    assert!((num(&j, "/speed") - w * 5.0).abs() < 1e-14);
    assert!((num(&j, "/centripetal") - 9.81).abs() < 1e-13);
    // the text says it in rpm too
    let out = dir.run(&["rotation", "--radius", "5 m", "--centripetal", "9.81 m/s^2"]);
    out.assert_code(0);
    assert!(out.stdout.contains("rpm"), "{}", out.stdout);
    assert!(out.stdout.contains("13.37"), "{}", out.stdout);
    // the speed and the radius give the same in rpm
    let j = dir
        .run(&["rotation", "--speed", "10 m/s", "--radius", "5 m", "--json"])
        .json();
    assert!((num(&j, "/omega_rpm") - 2.0 * 60.0 / std::f64::consts::TAU).abs() < 1e-12);
    // three of them over-determine the circle; the acceleration alone is not enough
    dir.run(&[
        "rotation",
        "--radius",
        "5 m",
        "--speed",
        "1 m/s",
        "--centripetal",
        "1 m/s^2",
    ])
    .assert_bad_input(&["over-determine", "two"]);
    dir.run(&["rotation", "--centripetal", "1 m/s^2"])
        .assert_bad_input(&["--centripetal", "--radius", "--speed"]);
    dir.run(&["rotation", "--radius", "5 m", "--centripetal", "-1 m/s^2"])
        .assert_bad_input(&["--centripetal", "positive"]);
}

#[test]
fn roll_reports_the_slipping_phase_apart_from_rolling() {
    let dir = Dir::new();
    let args = [
        "roll",
        "--body",
        "sphere",
        "--radius",
        "11 cm",
        "--mass",
        "0.45 kg",
        "--slope",
        "20 deg",
        "--mu",
        "0.3",
        "--v0",
        "2 m/s",
        "--omega0",
        "-30 rad/s",
        "--t-max",
        "3 s",
    ];
    let mut with_json = args.to_vec();
    with_json.push("--json");
    let j = dir.run(&with_json).json();
    let (a, mu, m, r, g) = (20f64.to_radians(), 0.3, 0.45, 0.11, 9.81);
    let slip_a = g * (a.sin() - mu * a.cos());
    let slip_alpha = mu * m * g * a.cos() * r / (0.4 * m * r * r);
    let roll_a = g * a.sin() / 1.4;
    assert_eq!(
        at(&j, "/slipping/regime").as_str(),
        Some("slipping forward")
    );
    assert!((num(&j, "/slipping/acceleration") - slip_a).abs() < 1e-12);
    assert!((num(&j, "/slipping/angular_acceleration") - slip_alpha).abs() < 1e-9);
    assert!((num(&j, "/slipping/friction") + mu * m * g * a.cos()).abs() < 1e-12);
    assert!((num(&j, "/rolling/acceleration") - roll_a).abs() < 1e-12);
    assert!((num(&j, "/rolling/angular_acceleration") - roll_a / r).abs() < 1e-10);
    assert!((num(&j, "/rolling_acceleration") - roll_a).abs() < 1e-12);
    assert!((num(&j, "/phases/0/acceleration") - slip_a).abs() < 1e-12);
    assert!((num(&j, "/phases/1/acceleration") - roll_a).abs() < 1e-12);
    // the text gives the slipping phase its own accelerations, not only the rolling ones
    let out = dir.run(&args);
    out.assert_code(0);
    let text = &out.stdout;
    let line = text
        .lines()
        .find(|l| l.starts_with("slipping forward from the launch"))
        .unwrap_or_else(|| panic!("no slipping phase:\n{text}"));
    assert!(line.contains(&format!("{slip_a:.6}")[..7]), "{line}");
    assert!(
        text.contains("it can roll, with a = g sin α/(1+k) = 2.396"),
        "{text}"
    );
    // launched rolling, there is no slipping phase
    let j = dir
        .run(&[
            "roll", "--radius", "0.1", "--mass", "1", "--mu", "0.5", "--slope", "5 deg", "--v0",
            "1", "--omega0", "10", "--t-max", "1", "--json",
        ])
        .json();
    assert!(at(&j, "/slipping").is_null());
    assert_eq!(at(&j, "/phases/0/regime").as_str(), Some("rolling"));
}

#[test]
fn bead_at_an_unstable_top_says_where_a_push_takes_it_off() {
    let dir = Dir::new();
    let top = [
        "bead", "--circle", "1 m", "--side", "outside", "--start", "0", "--speed", "0", "--t-max",
        "1 s",
    ];
    let out = dir.run(&top);
    out.assert_code(0);
    for needle in [
        "stays on the curve",
        "unstable equilibrium",
        "--speed",
        "cos φ = 0.666666",
    ] {
        assert!(out.stdout.contains(needle), "{needle}:\n{}", out.stdout);
    }
    let mut json = top.to_vec();
    json.push("--json");
    let j = dir.run(&json).json();
    assert_eq!(at(&j, "/equilibrium/stability").as_str(), Some("unstable"));
    assert_eq!(at(&j, "/equilibrium/at_rest"), true);
    assert!((num(&j, "/equilibrium/leaves_at/cos_angle") - 2.0 / 3.0).abs() < 1e-12);
    // a tiny push: it has not left by t_max, and would leave just past 2/3
    let mut tiny = top.to_vec();
    tiny[8] = "1e-6 m/s";
    let out = dir.run(&tiny);
    out.assert_code(0);
    assert!(
        out.stdout.contains("too slowly") && out.stdout.contains("slides off"),
        "{}",
        out.stdout
    );
    // threaded, it never leaves
    let mut bead = top.to_vec();
    bead[4] = "bead";
    let out = dir.run(&bead);
    assert!(out.stdout.contains("never leaves"), "{}", out.stdout);
    // no file was written: there was no -o
    assert!(dir.files(".").is_empty(), "{:?}", dir.files("."));
}

#[test]
fn rocket_and_bead_write_only_into_the_directory_asked_for() {
    let dir = Dir::new();
    let rocket = [
        "rocket",
        "--m0",
        "1000 kg",
        "--m1",
        "400 kg",
        "--mass-rate",
        "10 kg/s",
        "--exhaust-speed",
        "2 km/s",
        "--g",
        "9.81",
        "--coast",
    ];
    let j = dir.run(&[&rocket[..], &["--json"]].concat()).json();
    assert!(at(&j, "/plots").is_null());
    dir.run(&["bead", "--circle", "1 m", "--speed", "1", "--t-max", "1"])
        .assert_code(0);
    assert!(dir.files(".").is_empty(), "{:?}", dir.files("."));
    // with -o: the CSV, its units and the plots named <y>_<x>
    let out = dir.run(&[&rocket[..], &["-o", "r"]].concat());
    out.assert_code(0)
        .assert_stderr_contains("wrote r/rocket.csv");
    assert_eq!(
        dir.files("r"),
        [
            "m_t.svg",
            "rocket.csv",
            "rocket.units.json",
            "v_t.svg",
            "x_t.svg"
        ]
    );
    assert_eq!(
        dir.read("r/rocket.units.json"),
        "{\"t\": \"s\", \"x\": \"m\", \"v\": \"m/s\", \"m\": \"kg\"}\n"
    );
    let csv = Csv::parse(&dir.read("r/rocket.csv"));
    let t = csv.column("t");
    assert_eq!(csv.rows[0][t], 0.0);
    // --no-plots: only the CSV
    dir.run(&[&rocket[..], &["-o", "n", "--no-plots"]].concat())
        .assert_code(0);
    assert_eq!(dir.files("n"), ["rocket.csv", "rocket.units.json"]);
    let j = dir
        .run(&[
            "bead", "--circle", "1 m", "--speed", "1", "--t-max", "1", "-o", "b", "--json",
        ])
        .json();
    assert_eq!(at(&j, "/files/csv").as_str(), Some("b/path.csv"));
    assert_eq!(at(&j, "/files/plot").as_str(), Some("b/path.svg"));
    assert!(
        dir.read("b/path.units.json")
            .contains("\"normal_force\": \"N\"")
    );
}

#[test]
fn plots_are_named_without_parentheses_and_every_csv_has_units() {
    let dir = Dir::new();
    dir.run(&[
        "roll", "--radius", "0.1", "--mass", "1", "--mu", "0.3", "--v0", "2", "--t-max", "1", "-o",
        "roll",
    ])
    .assert_code(0);
    dir.run(&[
        "friction",
        "--mass",
        "1",
        "--mu-s",
        "0.6",
        "--mu-d",
        "0.4",
        "--spring-k",
        "100",
        "--anchor-speed",
        "0.05",
        "--t-max",
        "2",
        "-o",
        "friction",
    ])
    .assert_code(0);
    dir.run(&[
        "spin",
        "--moments",
        "1, 2, 3",
        "--omega",
        "0.01, 1, 0.01",
        "--t-max",
        "10",
        "--samples",
        "50",
        "-o",
        "spin",
    ])
    .assert_code(0);
    let expected: [(&str, &[&str]); 3] = [
        (
            "roll",
            &["energy_t.svg", "roll.csv", "roll.units.json", "v_t.svg"],
        ),
        (
            "friction",
            &[
                "forces_t.svg",
                "stick_slip.csv",
                "stick_slip.units.json",
                "v_t.svg",
                "x_t.svg",
            ],
        ),
        ("spin", &["omega_t.svg", "spin.csv", "spin.units.json"]),
    ];
    for (sub, names) in expected {
        assert_eq!(dir.files(sub), names, "{sub}");
    }
    let units: serde_json::Value = serde_json::from_str(&dir.read("roll/roll.units.json")).unwrap();
    assert_eq!(units["omega"], "rad/s");
    assert_eq!(units["rolling"], "1");
    let units: serde_json::Value = serde_json::from_str(&dir.read("spin/spin.units.json")).unwrap();
    assert_eq!(units["L"], "kg*m^2/s");
    assert!(
        units
            .as_object()
            .unwrap()
            .values()
            .all(serde_json::Value::is_string),
        "{units}"
    );
}

#[test]
fn quiet_silences_the_report_but_not_the_json() {
    let dir = Dir::new();
    let args = [
        "relative",
        "--speed",
        "2 m/s",
        "--current",
        "1 m/s",
        "--track",
        "north",
    ];
    let out = dir.run(&[&args[..], &["-q"]].concat());
    out.assert_code(0);
    assert!(out.stdout.is_empty(), "{}", out.stdout);
    let j = dir.run(&[&args[..], &["-q", "--json"]].concat()).json();
    assert!((num(&j, "/ground_speed") - 3f64.sqrt()).abs() < 1e-12);
    let out = dir.run(&[
        "roll", "--radius", "0.1", "--mass", "1", "--mu", "0.3", "--t-max", "1", "-o", "q", "-q",
    ]);
    out.assert_code(0);
    assert!(out.stdout.is_empty() && out.stderr.is_empty(), "{out:?}");
    assert!(dir.path().join("q/roll.csv").exists());
}

#[test]
fn errors_name_the_flag_and_count_in_words() {
    let dir = Dir::new();
    dir.run(&[
        "rigid-collide",
        "--landing",
        "--rod",
        "--mass",
        "1 kg",
        "--length",
        "1 m",
        "--tilt",
        "120 deg",
        "--velocity",
        "0, -1 m/s",
        "-e",
        "0",
    ])
    .assert_bad_input(&["--tilt", "90°"]);
    dir.run(&[
        "rigid-collide",
        "--inertia",
        "1",
        "--mass",
        "1",
        "--cm-distance",
        "0",
        "--release-angle",
        "30 deg",
        "--hit-at",
        "1",
        "--block-mass",
        "1",
        "-e",
        "1",
    ])
    .assert_bad_input(&["--release-angle", "gravity"]);
    dir.run(&[
        "bead",
        "--circle",
        "1 m",
        "--drop-height=-1 m",
        "--t-max",
        "1",
    ])
    .assert_bad_input(&["--drop-height", "zero or positive"]);
    let out = dir.run(&[
        "relative",
        "--velocity",
        "2 m/s",
        "--frame-velocity",
        "1, 2 m/s",
    ]);
    out.assert_bad_input(&["--velocity has 1 component and --frame-velocity 2 components"]);
    assert!(!out.stderr.contains("1 components"), "{}", out.stderr);
}

//! `mechkit rotation`: ω and α from θ(t) and θ from ω(t) (symbolic, with the numerical
//! check), uniform angular acceleration in rpm, circular motion with latitude, v = ω × r in
//! 3-D, the text report, and bad input (no mode, a wrong dimension, a missing name, a bad
//! latitude).

use crate::util::{Dir, at, num};

fn json(args: &[&str]) -> serde_json::Value {
    Dir::new().json_with(&["rotation"], args)
}

#[test]
fn formulas_give_omega_and_alpha() {
    let j = json(&["--theta", "3*t^3 - t", "--at", "2 s, 0"]);
    assert_eq!(at(&j, "/omega").as_str(), Some("9*t^2 - 1"));
    assert_eq!(num(&j, "/at/0/omega"), 35.0);
    assert_eq!(num(&j, "/at/0/alpha"), 36.0);
    assert_eq!(num(&j, "/at/1/omega"), -1.0);
    assert_eq!(at(&j, "/at/0/agree"), &serde_json::Value::Bool(true));
    let j = json(&[
        "--omega",
        "a*t",
        "--set",
        "a=2 rad/s^2",
        "--theta0",
        "90 deg",
        "--at",
        "3",
    ]);
    assert!((num(&j, "/at/0/theta") - (std::f64::consts::FRAC_PI_2 + 9.0)).abs() < 1e-14);
    assert_eq!(num(&j, "/at/0/alpha"), 2.0);
}

#[test]
fn uniform_circle_and_vector_modes() {
    let j = json(&["--omega0", "0", "--omega1", "60 rpm", "--time", "2 s"]);
    assert!((num(&j, "/alpha") - std::f64::consts::PI).abs() < 1e-15);
    assert!((num(&j, "/revolutions") - 1.0).abs() < 1e-15);
    let j = json(&[
        "--angular-speed",
        "2 rad/s",
        "--radius",
        "3 m",
        "--alpha",
        "0.5 rad/s^2",
    ]);
    assert_eq!(num(&j, "/speed"), 6.0);
    assert_eq!(num(&j, "/centripetal"), 12.0);
    assert_eq!(num(&j, "/tangential"), 1.5);
    let j = json(&["--omega-vector", "0, 0, 3", "--point", "2 m, 0, 1 m"]);
    assert_eq!(num(&j, "/velocity/1"), 6.0);
    assert_eq!(num(&j, "/acceleration/centripetal/0"), -18.0);
    assert_eq!(num(&j, "/distance_from_axis"), 2.0);
    let text = Dir::new().run(&["rotation", "--period", "1 min", "--radius", "1 m"]);
    text.assert_code(0);
    assert!(text.stdout.contains("a_c = ω²R"), "{}", text.stdout);
}

#[test]
fn bad_rotation_input() {
    let dir = Dir::new();
    dir.run(&["rotation"])
        .assert_bad_input(&["--theta or --omega"]);
    dir.run(&["rotation", "--speed", "3 kg", "--radius", "1 m"])
        .assert_bad_input(&["--speed", "dimension"]);
    dir.run(&["rotation", "--theta", "a*t", "--at", "1"])
        .assert_bad_input(&["--theta", "--set a="]);
    dir.run(&[
        "rotation",
        "--period",
        "1 d",
        "--radius",
        "1 m",
        "--latitude",
        "100 deg",
    ])
    .assert_bad_input(&["--latitude", "between -90° and 90°"]);
    dir.run(&[
        "rotation", "--omega0", "1", "--omega1", "2", "--time", "0 s",
    ])
    .assert_bad_input(&["--time", "positive"]);
}

/// A speed and an acceleration limit give the smallest circle R = v²/a; turning through an
/// angle θ takes θ/ω along an arc θR. Without a radius or a limit, a speed is an error.
#[test]
fn acceleration_limit_and_turn() {
    let j = json(&[
        "--speed",
        "30 m/s",
        "--centripetal",
        "2 m/s^2",
        "--turn",
        "180 deg",
    ]);
    assert!((num(&j, "/radius") - 450.0).abs() < 1e-12);
    assert!((num(&j, "/centripetal") - 2.0).abs() < 1e-14);
    let half_turn = std::f64::consts::PI * 450.0 / 30.0;
    assert!((num(&j, "/turn/time") - half_turn).abs() < 1e-12);
    assert!((num(&j, "/turn/arc") - std::f64::consts::PI * 450.0).abs() < 1e-10);
    let out = Dir::new().run(&["rotation", "--speed", "30 m/s"]);
    out.assert_bad_input(&["--radius", "--centripetal"]);
    let out = Dir::new().run(&["rotation", "--speed", "30 m/s", "--centripetal", "0 m/s^2"]);
    out.assert_bad_input(&["--centripetal"]);
}

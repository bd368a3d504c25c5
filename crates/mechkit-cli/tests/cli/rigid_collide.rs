//! `mechkit rigid-collide`: the hinged rod struck by a block (c16-B6's numbers, angular
//! momentum about the hinge conserved, the energy ratio for e), a body given by its moment
//! of inertia, a body file about a pivot, the warnings for a pivot off the rod, and the errors
//! (zero moment of inertia, separating bodies, bad restitution).

use crate::util::{Dir, examples, num};

fn json(args: &[&str]) -> serde_json::Value {
    Dir::new().json_with(&["rigid-collide"], args)
}

#[test]
fn hinged_rod_and_block() {
    // ω0 = 2 rad/s, m = M: the plastic impact keeps ω0 L/(1 + 3m/M) = 0.5 m/s; K ratio
    // (I_O/(I_O + m L²)) = 1/4
    let j = json(&[
        "--rod",
        "--mass",
        "3 kg",
        "--length",
        "1 m",
        "--omega",
        "2 rad/s",
        "--block-mass",
        "3 kg",
        "-e",
        "0",
    ]);
    assert!((num(&j, "/block/velocity_after/0") - 0.5).abs() < 1e-15);
    assert!((num(&j, "/kinetic_energy/ratio") - 0.25).abs() < 1e-15);
    assert!(num(&j, "/angular_momentum_about_pivot/difference").abs() < 1e-12);
    let e = 0.6;
    let j = json(&[
        "--rod",
        "--mass",
        "3 kg",
        "--length",
        "1 m",
        "--omega",
        "2 rad/s",
        "--block-mass",
        "3 kg",
        "-e",
        "0.6",
    ]);
    let change = num(&j, "/kinetic_energy/change");
    assert!((change - num(&j, "/kinetic_energy/change_closed_form")).abs() < 1e-14);
    // m_eff = 1/(1/3 + 1/1) = 3/4 kg, u = 2 m/s: ΔK = −½(1 − e²)(3/4)(4)
    assert!((change + 0.5 * (1.0 - e * e) * 0.75 * 4.0).abs() < 1e-14);
}

#[test]
fn inertia_and_body_file() {
    let j = json(&[
        "--inertia",
        "2 kg*m^2",
        "--mass",
        "2 kg",
        "--cm-distance",
        "0.5 m",
        "--omega",
        "1",
        "--hit-at",
        "1 m",
        "--block-mass",
        "1 kg",
        "-e",
        "1",
    ]);
    assert!((num(&j, "/body/centre_of_percussion") - 2.0).abs() < 1e-15);
    let body = examples().join("bodies/rod_two_spheres.toml");
    let out = Dir::new().run(&[
        "rigid-collide",
        "--body",
        body.to_str().unwrap(),
        "--pivot",
        "0, 0, 0",
        "--omega",
        "1",
        "--hit-at",
        "0.5 m, 0",
        "--normal",
        "0, 1",
        "--block-mass",
        "0.1 kg",
        "-e",
        "1",
    ]);
    out.assert_code(0);
    assert!(out.stdout.contains("I_O = 0.337333"), "{}", out.stdout);
}

#[test]
fn warnings_and_errors() {
    let dir = Dir::new();
    let out = dir.run(&[
        "rigid-collide",
        "--rod",
        "--mass",
        "1",
        "--length",
        "1 m",
        "--pivot-at",
        "0.5 m",
        "--omega",
        "1",
        "--hit-at",
        "2 m",
        "--block-mass",
        "1",
        "-e",
        "1",
    ]);
    out.assert_code(0)
        .assert_stderr_contains("warning: the contact point is 2 m");
    dir.run(&[
        "rigid-collide",
        "--inertia",
        "0",
        "--mass",
        "1",
        "--omega",
        "1",
        "--hit-at",
        "1",
        "--block-mass",
        "1",
        "-e",
        "1",
    ])
    .assert_bad_input(&["--inertia", "moment of inertia", "zero"]);
    dir.run(&[
        "rigid-collide",
        "--rod",
        "--mass",
        "1",
        "--length",
        "1",
        "--omega",
        "-1",
        "--block-mass",
        "1",
        "-e",
        "1",
    ])
    .assert_bad_input(&["--block-velocity", "not approaching"]);
    dir.run(&[
        "rigid-collide",
        "--rod",
        "--mass",
        "1",
        "--length",
        "1",
        "--omega",
        "1",
        "--block-mass",
        "1",
        "-e",
        "2",
    ])
    .assert_bad_input(&["--restitution", "between 0"]);
    dir.run(&[
        "rigid-collide",
        "--rod",
        "--mass",
        "1",
        "--length",
        "1",
        "--block-mass",
        "1",
        "-e",
        "1",
    ])
    .assert_bad_input(&["--omega", "--release-angle"]);
}

/// A rod falling flat at v lands on one end with e = 0: ω = 3v/(2L) and the centre of mass
/// keeps 3v/4; tilted, with spin and e = 0.5, the end rebounds at e times its approach speed
/// and the angular momentum about the contact is unchanged.
#[test]
fn rod_landing_on_its_end() {
    let j = json(&[
        "--landing",
        "--rod",
        "--mass",
        "2 kg",
        "--length",
        "1 m",
        "--tilt",
        "0 deg",
        "--velocity",
        "0, -4 m/s",
        "-e",
        "0",
    ]);
    assert!((num(&j, "/after/omega") + 6.0).abs() < 1e-14);
    assert!((num(&j, "/after/velocity/1") + 3.0).abs() < 1e-14);
    assert!(num(&j, "/after/end_velocity/1").abs() < 1e-14);
    let j = json(&[
        "--landing",
        "--rod",
        "--mass",
        "1.5 kg",
        "--length",
        "0.8 m",
        "--tilt",
        "35 deg",
        "--velocity",
        "1 m/s, -3 m/s",
        "--omega",
        "2 rad/s",
        "-e",
        "0.5",
    ]);
    let u0 = num(&j, "/before/end_velocity/1");
    assert!((num(&j, "/after/end_velocity/1") + 0.5 * u0).abs() < 1e-13);
    let (l0, l1) = (
        num(&j, "/angular_momentum_contact/before"),
        num(&j, "/angular_momentum_contact/after"),
    );
    assert!((l0 - l1).abs() < 1e-14 * l0.abs().max(1.0));
    let lost = num(&j, "/kinetic_energy/change");
    assert!((lost - num(&j, "/kinetic_energy/change_closed_form")).abs() < 1e-13);
    // an end moving up cannot land
    let out = Dir::new().run(&[
        "rigid-collide",
        "--landing",
        "--rod",
        "--mass",
        "1 kg",
        "--length",
        "1 m",
        "--tilt",
        "10 deg",
        "--velocity",
        "0, 2 m/s",
        "-e",
        "0",
    ]);
    out.assert_bad_input(&["--velocity"]);
}

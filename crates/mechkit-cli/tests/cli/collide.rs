//! `mechkit collide` and `mechkit impulse`: textbook collisions in 1-D and 2-D, a wall, friction,
//! separating bodies (no collision), and bad input (e outside [0, 1], non-positive mass,
//! missing normal in 2-D, a force file whose time runs backwards).

use crate::util::{Dir, num};

#[test]
fn perfectly_inelastic_head_on() {
    let j = Dir::new().json(&[
        "collide",
        "--m1",
        "0.2 kg",
        "--v1",
        "15 m/s",
        "--m2",
        "1.5 kg",
        "--v2",
        "0",
        "--restitution",
        "0",
        "--json",
    ]);
    let v = 0.2 * 15.0 / 1.7;
    assert_eq!(num(&j, "/v1/0"), num(&j, "/v2/0"));
    assert!((num(&j, "/v1/0") - v).abs() < 1e-14);
    assert!((num(&j, "/kinetic_lost") - (0.5 * 0.2 * 225.0 - 0.5 * 1.7 * v * v)).abs() < 1e-12);
    assert!((num(&j, "/v_cm/0") - v).abs() < 1e-14);
}

#[test]
fn oblique_spheres_wall_and_friction() {
    let dir = Dir::new();
    // equal masses, elastic, the normal from the centres: the velocities end up perpendicular
    let j = dir.json(&[
        "collide", "--m1", "1", "--v1", "3, 0", "--m2", "1", "--v2", "0", "--r1", "0, 0", "--r2",
        "0.8, 0.6", "-e", "elastic", "--json",
    ]);
    let (a, b) = (
        [num(&j, "/v1/0"), num(&j, "/v1/1")],
        [num(&j, "/v2/0"), num(&j, "/v2/1")],
    );
    assert!((a[0] * b[0] + a[1] * b[1]).abs() < 1e-12);
    assert!((num(&j, "/kinetic_lost")).abs() < 1e-12);
    // a ball onto an immovable floor with friction: it slides, losing μ J_n of its 1 m/s
    let j = dir.json(&[
        "collide",
        "--m1",
        "1",
        "--v1",
        "1, -1",
        "--m2",
        "inf",
        "--v2",
        "0",
        "--normal",
        "0, -1",
        "-e",
        "0.5",
        "--friction",
        "0.2",
        "--json",
    ]);
    assert_eq!(j["sticks"], false);
    assert!((num(&j, "/v1/0") - 0.7).abs() < 1e-15 && (num(&j, "/v1/1") - 0.5).abs() < 1e-15);
    assert_eq!(j["m2"], "inf");
}

#[test]
fn separating_bodies_are_no_collision() {
    let dir = Dir::new();
    let out = dir.run(&[
        "collide", "--m1", "1", "--v1", "-1", "--m2", "1", "--v2", "1", "-e", "1",
    ]);
    out.assert_code(0);
    assert!(out.stdout.contains("no collision"), "{}", out.stdout);
    let j = dir.json(&[
        "collide", "--m1", "1", "--v1", "-1", "--m2", "1", "--v2", "1", "-e", "1", "--json",
    ]);
    assert_eq!(j["collided"], false);
}

#[test]
fn impulse_of_a_force_file() {
    let dir = Dir::new();
    dir.create("kick.d", "# t [s], F [N]\n0 0\n0.01 100\n0.02 0\n");
    let j = dir.json(&[
        "impulse", "kick.d", "--mass", "0.5 kg", "--v0", "-2 m/s", "--json",
    ]);
    assert!((num(&j, "/impulse") - 1.0).abs() < 1e-15);
    assert!((num(&j, "/delta_v") - 2.0).abs() < 1e-15);
    assert!((num(&j, "/v_end")).abs() < 1e-15);
    assert!((num(&j, "/mean_force") - 50.0).abs() < 1e-12);
}

#[test]
fn collide_and_impulse_bad_input() {
    let dir = Dir::new();
    let base = [
        "collide", "--m1", "1", "--v1", "1", "--m2", "1", "--v2", "0",
    ];
    let with = |extra: &[&'static str]| -> Vec<&'static str> { [&base[..], extra].concat() };
    dir.run(&with(&["-e", "1.5"]))
        .assert_bad_input(&["between 0", "and 1"]);
    dir.run(&with(&["-e", "-0.1"]))
        .assert_bad_input(&["between 0"]);
    dir.run(&with(&["-e", "inelastic"]))
        .assert_bad_input(&["needs its e"]);
    dir.run(&[
        "collide", "--m1", "0", "--v1", "1", "--m2", "1", "--v2", "0", "-e", "1",
    ])
    .assert_bad_input(&["--m1", "positive"]);
    dir.run(&[
        "collide", "--m1", "-2 kg", "--v1", "1", "--m2", "1", "--v2", "0", "-e", "1",
    ])
    .assert_bad_input(&["--m1", "positive"]);
    dir.run(&[
        "collide", "--m1", "1 m", "--v1", "1", "--m2", "1", "--v2", "0", "-e", "1",
    ])
    .assert_bad_input(&["--m1", "mass"]);
    dir.run(&[
        "collide", "--m1", "1", "--v1", "1, 0", "--m2", "1", "--v2", "0", "-e", "1",
    ])
    .assert_bad_input(&["--normal", "--r1"]);
    dir.run(&[
        "collide", "--m1", "1", "--v1", "1, 0", "--m2", "1", "--v2", "0", "-e", "1", "--normal",
        "0, 0",
    ])
    .assert_bad_input(&["zero length"]);
    dir.create("back.d", "0 1\n-0.1 2\n-0.2 3\n");
    dir.run(&["impulse", "back.d"])
        .assert_bad_input(&["negative time steps"]);
}

#[test]
fn centre_of_mass_of_point_masses() {
    let dir = Dir::new();
    let j = dir.json(&[
        "com",
        "--mass",
        "1 kg",
        "--at",
        "0, 0",
        "--mass",
        "3 kg",
        "--at",
        "1 m, 2 m",
        "--velocity",
        "2, -1",
        "--velocity",
        "0.5, 4",
        "--json",
    ]);
    assert_eq!(num(&j, "/total_mass"), 4.0);
    assert_eq!(
        (num(&j, "/centre_of_mass/0"), num(&j, "/centre_of_mass/1")),
        (0.75, 1.5)
    );
    assert_eq!(
        (num(&j, "/momentum/0"), num(&j, "/momentum/1")),
        (3.5, 11.0)
    );
    let k = num(&j, "/kinetic");
    assert!((k - num(&j, "/kinetic_cm") - num(&j, "/kinetic_internal")).abs() < 1e-14 * k);
    dir.run(&["com", "--mass", "1", "--at", "0", "--mass", "2"])
        .assert_bad_input(&["--mass is given twice but --at once"]);
    dir.run(&["com", "--mass", "-1", "--at", "0"])
        .assert_bad_input(&["--mass", "positive"]);
    dir.run(&[
        "com", "--mass", "1", "--at", "0", "--mass", "1", "--at", "1, 2",
    ])
    .assert_bad_input(&["same number of coordinates"]);
    dir.run(&["com", "--mass", "1 m", "--at", "0"])
        .assert_bad_input(&["--mass", "mass"]);
}

//! The work-energy commands: `potential` (equilibria, stability, turning points, motion, the
//! energy diagram, singular points, the gradient of a 2-D potential), `power` and
//! `work --field`, in text and JSON, and their bad input.

use crate::util::{Dir, at, num};

#[test]
fn lennard_jones_diagram_with_an_energy() {
    let dir = Dir::new();
    let j = dir.json(&[
        "potential",
        "U0*((a/r)^12-(b/r)^6)",
        "--var",
        "r",
        "--range",
        "0.8:3",
        "--set",
        "U0=1,a=1,b=1",
        "--energy=-0.1",
        "-o",
        "lj",
        "--json",
    ]);
    assert!((num(&j, "/equilibria/0/x") - 2f64.powf(1.0 / 6.0)).abs() < 1e-12);
    assert_eq!(at(&j, "/equilibria/0/stability"), "stable");
    assert_eq!(j["equilibria"].as_array().unwrap().len(), 1);
    assert_eq!(j["energy"]["turning_points"].as_array().unwrap().len(), 2);
    assert_eq!(at(&j, "/energy/regions/1/allowed"), true);
    let svg = dir.read("lj/U_r.svg");
    assert!(svg.starts_with("<svg") && svg.contains("stable equilibrium"));
    assert!(svg.contains("turning point") && svg.contains("forbidden"));
}

#[test]
fn force_given_energy_from_a_release() {
    let dir = Dir::new();
    let out = dir.run(&[
        "potential",
        "--force",
        "-F0*sin(2*pi*x/b)",
        "--range=-1:2",
        "--set",
        "F0=1,b=1",
        "--mass",
        "1",
        "--x0",
        "0",
        "--v0",
        "0.5",
        "-o",
        "d",
    ]);
    out.assert_code(0);
    for needle in [
        "U(x) = -F0*b*cos(2*pi*x/b)/(2*pi)",
        "unstable",
        "barrier 0.318310",
        "turns at",
    ] {
        assert!(out.stdout.contains(needle), "{needle}: {}", out.stdout);
    }
    // the diagram and the speed plot are written into the directory
    assert!(dir.read("d/U_x.svg").starts_with("<svg"));
    assert!(dir.read("d/v_x.svg").starts_with("<svg"));
}

#[test]
fn no_equilibrium_is_an_empty_list_and_a_pole_is_reported() {
    let dir = Dir::new();
    let j = dir.json(&["potential", "2*x", "--range=-1:2", "--json"]);
    assert_eq!(j["equilibria"], serde_json::json!([]));
    let out = dir.run(&["potential", "1/x", "--range", "-1:2"]);
    out.assert_code(0);
    assert!(out.stdout.contains("no equilibrium"), "{}", out.stdout);
    assert!(out.stdout.contains("singular near x = 0"), "{}", out.stdout);
}

#[test]
fn gradient_of_a_potential_field() {
    let j = Dir::new().json(&[
        "potential",
        "k*(x^2 + y^2)/2",
        "--var",
        "x,y",
        "--set",
        "k=2",
        "--at",
        "1,0; 0,3",
        "--json",
    ]);
    assert_eq!(at(&j, "/force/0"), "-k*x");
    assert_eq!(num(&j, "/at/1/force/1"), -6.0);
}

#[test]
fn potential_bad_input() {
    let dir = Dir::new();
    dir.run(&["potential", "k*x^2", "--range", "0:1"])
        .assert_bad_input(&["needs values for k", "--set k="]);
    dir.run(&["potential", "x^2", "--range", "0"])
        .assert_bad_input(&["interval A:B"]);
    dir.run(&["potential", "x^2", "--range", "1:1"])
        .assert_bad_input(&["empty"]);
    dir.run(&["potential", "x^2"])
        .assert_bad_input(&["--range"]);
    dir.run(&["potential", "x^2", "--range", "0:1", "--mass", "1"])
        .assert_bad_input(&["--x0"]);
    dir.run(&[
        "potential",
        "x^2",
        "--range",
        "0:1",
        "--mass",
        "1",
        "--x0",
        "5",
    ])
    .assert_bad_input(&["outside"]);
    dir.run(&["potential", "x^*2", "--range", "0:1"])
        .assert_bad_input(&["x^*2"]);
}

#[test]
fn constant_power_and_average_power() {
    let dir = Dir::new();
    let j = dir.json(&[
        "power",
        "--power",
        "20 kW",
        "--mass",
        "200 kg",
        "--at",
        "5 s",
        "--until-speed",
        "40 m/s",
        "--out",
        "p",
        "--json",
    ]);
    assert!((num(&j, "/at/0/v") - 1000f64.sqrt()).abs() < 1e-12);
    assert!((num(&j, "/until_speed/t") - 200.0 * 1600.0 / 40e3).abs() < 1e-12);
    assert!(dir.read("p/v_t.svg").starts_with("<svg"));
    let j = dir.json(&["power", "--work", "70.53 kJ", "--time", "24 h", "--json"]);
    assert!((num(&j, "/average_power") - 70530.0 / 86400.0).abs() < 1e-15);
    dir.run(&["power", "--power", "-1 W", "--mass", "1 kg"])
        .assert_bad_input(&["positive"]);
    dir.run(&["power", "--power", "1 kg", "--mass", "1 kg"])
        .assert_bad_input(&["--power"]);
}

#[test]
fn work_of_a_field_along_paths() {
    let dir = Dir::new();
    let swirl = dir.json(&[
        "work",
        "--field",
        "-y, x",
        "--path",
        "cos(s), sin(s)",
        "--param",
        "s=0:2*pi",
        "--json",
    ]);
    assert!((num(&swirl, "/work") - std::f64::consts::TAU).abs() < 1e-12);
    assert_eq!(at(&swirl, "/conservative"), false);
    assert_eq!(at(&swirl, "/closed"), true);
    let g = dir.json(&[
        "work",
        "--field",
        "0, -m*g",
        "--through",
        "0,0; 3,0; 3,2",
        "--set",
        "m=2,g=9.81",
        "--json",
    ]);
    assert!((num(&g, "/work") + 2.0 * 9.81 * 2.0).abs() < 1e-12);
    assert_eq!(at(&g, "/potential"), "g*m*y");
    dir.run(&["work", "--field", "x, y", "--through", "0,0; 1"])
        .assert_bad_input(&["2 coordinates"]);
    dir.run(&["work", "--field", "x, y", "--path", "s, s"])
        .assert_bad_input(&["--param"]);
    dir.run(&["work"]).assert_bad_input(&["data file"]);
}

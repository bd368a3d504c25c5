//! Issue 27, part 3: `solve` answers cubics and quartics without an interval (in closed form,
//! rational roots exactly, the casus irreducibilis through `cos` and `acos`), solves other
//! polynomials for every real root inside Cauchy's bound and says so, uses `--set` values for
//! a polynomial's symbolic coefficients, and keeps its JSON fields (adding `interval` and
//! `root_bound`). What is checked: the roots make the polynomial vanish, and the JSON.

use crate::util::{Dir, num};

/// `p(x)` for coefficients highest degree first.
fn horner(c: &[f64], x: f64) -> f64 {
    c.iter().fold(0.0, |acc, v| acc * x + v)
}

#[test]
fn a_cubic_without_an_interval() {
    let out = Dir::new().run(&["solve", "x^3 - 6*x^2 + 11*x - 6 = 0", "--for", "x"]);
    out.assert_code(0);
    assert_eq!(out.stdout, "x = 1\nx = 2\nx = 3\n");
    // the JSON fields stay, two are added
    let out = Dir::new().run(&["solve", "x^3 - 3*x + 1 = 0", "--json"]);
    out.assert_code(0);
    let j = out.json();
    for field in [
        "equation",
        "unknown",
        "symbolic",
        "no_real_root",
        "every_value",
        "assumptions",
        "numeric",
        "interval",
        "root_bound",
    ] {
        assert!(j.get(field).is_some(), "{field} missing: {j}");
    }
    assert_eq!(j["symbolic"].as_array().unwrap().len(), 3, "{j}");
    assert!(j["symbolic"][0].as_str().unwrap().contains("acos"), "{j}");
    assert!(j["root_bound"].is_null() && j["interval"].is_null(), "{j}");
    for k in 0..3 {
        let x = num(&j, &format!("/numeric/{k}"));
        assert!(horner(&[1.0, 0.0, -3.0, 1.0], x).abs() < 1e-14, "{x}");
    }
}

#[test]
fn quartics_with_four_two_and_no_real_roots() {
    for (eq, coefficients, count) in [
        ("x^4 - 4*x^2 + x + 1 = 0", [1.0, 0.0, -4.0, 1.0, 1.0], 4),
        ("x^4 = x + 1", [1.0, 0.0, 0.0, -1.0, -1.0], 2),
    ] {
        let out = Dir::new().run(&["solve", eq, "--json"]);
        out.assert_code(0);
        let j = out.json();
        let roots = j["numeric"].as_array().unwrap();
        assert_eq!(roots.len(), count, "{eq}: {j}");
        for r in roots {
            let x = r.as_f64().unwrap();
            assert!(horner(&coefficients, x).abs() < 1e-13, "{eq}: {x}");
        }
    }
    let out = Dir::new().run(&["solve", "x^4 + x^2 + 1 = 0"]);
    out.assert_code(1);
    assert!(out.stdout.contains("no real x"), "{}", out.stdout);
}

#[test]
fn a_quintic_has_every_real_root_inside_the_bound() {
    let out = Dir::new().run(&["solve", "x^5 = x + 1"]);
    out.assert_code(0);
    assert!(
        out.stdout.contains("[-2, 2], Cauchy's bound")
            && out.stdout.contains("x = 1.1673039782614"),
        "{}",
        out.stdout
    );
    let j = Dir::new().run(&["solve", "x^5 = x + 1", "--json"]).json();
    assert_eq!(j["root_bound"], 2.0);
    assert_eq!(j["interval"], serde_json::json!([-2.0, 2.0]));
    assert!(j["symbolic"].is_null(), "{j}");
    // no real root at all is a definite answer: exit 1
    let out = Dir::new().run(&["solve", "x^6 + x^2 + 1 = 0", "--json"]);
    out.assert_code(1);
    let j: serde_json::Value = serde_json::from_str(&out.stdout).unwrap();
    assert_eq!(j["no_real_root"], true, "{j}");
}

#[test]
fn set_gives_a_cubic_its_coefficients() {
    let out = Dir::new().run(&["solve", "a*x^3 + b = 0", "--set", "a=2,b=-16"]);
    out.assert_code(0);
    assert!(out.stdout.contains("x = -cbrt(b/a)"), "{}", out.stdout);
    assert!(out.stdout.contains("  x = 2\n"), "{}", out.stdout);
    let out = Dir::new().run(&[
        "solve",
        "k*x^3 - 6*x^2 + 11*x - 6 = 0",
        "--set",
        "k=1",
        "--json",
    ]);
    out.assert_code(0);
    assert_eq!(out.json()["numeric"], serde_json::json!([1.0, 2.0, 3.0]));
    // without the value: exit 2, the message names it
    let out = Dir::new().run(&["solve", "k*x^3 - 6*x^2 + 11*x - 6 = 0"]);
    out.assert_code(2);
    assert!(out.stderr.contains("`k` with --set"), "{}", out.stderr);
    // not a polynomial: the interval is still needed
    let out = Dir::new().run(&["solve", "x^3 = cos(x)"]);
    out.assert_code(2);
    assert!(out.stderr.contains("--in"), "{}", out.stderr);
}

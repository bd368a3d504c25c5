//! The calculus commands: `diff`, `integrate` (the acceptance integral and derivative of the
//! expression-engine issue), `solve` (symbolic, numeric on an interval, linear systems) and
//! `units`, in text and JSON, and their errors.

use crate::util::{Dir, at, num};

fn run(args: &[&str]) -> crate::util::Output {
    Dir::new().run(args)
}

#[test]
fn integrate_prints_the_antiderivative_with_its_assumption() {
    let out = run(&["integrate", "1/(a+x^2)", "--var", "x"]);
    out.assert_code(0);
    assert!(
        out.stdout.contains("atan(x/sqrt(a))/sqrt(a)"),
        "{}",
        out.stdout
    );
    assert!(out.stdout.contains("a > 0"), "{}", out.stdout);
}

/// An interval that leaves the integrand's domain is named by where it does, not by the
/// first quadrature node there ("NaN at x = -0.9957276855604063").
#[test]
fn an_interval_outside_the_domain_is_named() {
    for (f, from, to, says) in [
        ("1/sqrt(x)", "-1", "1", "NaN) for x from -1 to 0"),
        ("sqrt(1 - x^2)", "-2", "2", "NaN) for x from -2 to -1"),
    ] {
        let out = run(&["integrate", f, "--from", from, "--to", to]);
        out.assert_code(1);
        assert!(out.stdout.contains(says), "{f}: {}", out.stdout);
        assert!(
            out.stdout.contains("leaves its domain"),
            "{f}: {}",
            out.stdout
        );
    }
}

#[test]
fn definite_integral_by_closed_form_and_quadrature() {
    let out = run(&[
        "integrate",
        "1/(a+x^2)",
        "--var",
        "x",
        "--from",
        "0",
        "--to",
        "1",
        "--set",
        "a=1",
        "--json",
    ]);
    out.assert_code(0);
    let j: serde_json::Value = serde_json::from_str(&out.stdout).expect("JSON");
    assert!((num(&j, "/definite/closed_form") - std::f64::consts::FRAC_PI_4).abs() < 1e-12);
    assert!((num(&j, "/definite/quadrature/value") - std::f64::consts::FRAC_PI_4).abs() < 1e-9);
    assert_eq!(at(&j, "/definite/agree"), &serde_json::json!(true));
    assert_eq!(at(&j, "/assumptions/0"), &serde_json::json!("a > 0"));
}

#[test]
fn no_closed_form_falls_back_to_quadrature() {
    let out = run(&["integrate", "exp(-x^2)", "--from", "0", "--to", "1"]);
    out.assert_code(0);
    assert!(out.stdout.contains("no closed form"), "{}", out.stdout);
    assert!(out.stdout.contains("0.7468241328124"), "{}", out.stdout);
    // neither a closed form nor limits: nothing could be computed
    run(&["integrate", "exp(-x^2)"]).assert_code(1);
}

#[test]
fn derivative_of_the_periodic_force() {
    let out = run(&["diff", "-F0*sin(2*pi*x/b)", "--var", "x"]);
    out.assert_code(0);
    assert!(
        out.stdout.contains("-2*pi*F0*cos(2*pi*x/b)/b"),
        "{}",
        out.stdout
    );
    let out = run(&["diff", "k*(x^2 + y^2)/2", "--var", "y", "--json"]);
    let j: serde_json::Value = serde_json::from_str(&out.stdout).expect("JSON");
    assert_eq!(at(&j, "/derivative"), &serde_json::json!("k*y"));
}

/// At a corner there is no derivative: `abs(x)` at 0 printed "symbolic 0, numeric 0, the two
/// agree", exit 0. Nor at a vertical tangent, a cusp, or the edge of the domain.
#[test]
fn a_corner_has_no_derivative() {
    let out = run(&["diff", "abs(x)", "--at", "0"]);
    out.assert_code(1);
    assert!(
        out.stdout.contains(
            "at x = 0: abs(x) has a corner (slope -1 from the left, 1 from the right): it has no derivative there"
        ),
        "{}",
        out.stdout
    );
    let j = run(&["diff", "max(x, 0)", "--at", "0", "--json"]);
    j.assert_code(1);
    let j: serde_json::Value = serde_json::from_str(&j.stdout).expect("JSON");
    assert_eq!(at(&j, "/at/agree"), &serde_json::Value::Bool(false));
    assert!((num(&j, "/at/kink/0") - 0.0).abs() < 1e-6);
    assert!((num(&j, "/at/kink/1") - 1.0).abs() < 1e-6);
    assert_eq!(at(&j, "/at/jump"), &serde_json::Value::Null);
    run(&["diff", "abs(x)", "--at", "0.5"]).assert_code(0);
    // a corner whose derivative's formula is 0/0 there, a vertical tangent, a cusp, the edge
    // of a domain: each said in words, exit 1 (they gave the finiteness rule's generic "the
    // result at.symbolic is NaN")
    for (f, says) in [
        (
            "sqrt(x^2)",
            "sqrt(x^2) has a corner (slope -1 from the left, 1 from the right)",
        ),
        (
            "cbrt(x)",
            "cbrt(x) has a vertical tangent (its slopes grow without bound on both sides: 1.00e6 from the left and 1.00e6 from the right",
        ),
        ("sqrt(abs(x))", "sqrt(abs(x)) has a cusp"),
        (
            "sqrt(x)",
            "d/dx sqrt(x) is not a finite number (the point is at the edge of the formula's domain or at a singularity)",
        ),
        // x sin(1/x) is NaN at 0 itself, and even: central differences alone gave 0 ± 0
        ("x*sin(1/x)", "d/dx x*sin(1/x) is not a finite number"),
        // a derivative whose formula is 0/0 at the point, where the function has one
        (
            "sqrt(x^4)",
            "= 2*x^3/sqrt(x^4) has no value there (a removable singularity: 0/0 or the like), but the numerical derivative is sure: 0 ±",
        ),
    ] {
        let out = run(&["diff", f, "--at", "0"]);
        out.assert_code(1);
        assert!(out.stdout.contains(says), "{f}: {}", out.stdout);
        let j = run(&["diff", f, "--at", "0", "--json"]);
        j.assert_code(1);
        let j: serde_json::Value = serde_json::from_str(&j.stdout).expect("JSON");
        assert_eq!(at(&j, "/at/agree"), &serde_json::Value::Bool(false), "{f}");
        let estimate_only = f == "sqrt(x^4)";
        assert_eq!(
            at(&j, "/at/estimate_only"),
            &serde_json::Value::Bool(estimate_only),
            "{f}"
        );
    }
}

#[test]
fn equations_symbolic_numeric_and_systems() {
    let out = run(&["solve", "x^2 - 5*x + 6 = 0", "--for", "x", "--json"]);
    out.assert_code(0);
    let j: serde_json::Value = serde_json::from_str(&out.stdout).expect("JSON");
    assert_eq!(at(&j, "/numeric"), &serde_json::json!([2.0, 3.0]));

    let out = run(&["solve", "cos(x) = x", "--for", "x", "--in", "0:1"]);
    out.assert_code(0);
    assert!(out.stdout.contains("0.739085133215"), "{}", out.stdout);

    let out = run(&[
        "solve",
        "h = g*t^2/2",
        "--for",
        "t",
        "--set",
        "h=10 m,g=9.81",
    ]);
    assert!(out.stdout.contains("1.42784312"), "{}", out.stdout);

    let out = run(&[
        "solve",
        "N - m*g*cos(th) = 0; f = m*g*sin(th)",
        "--for",
        "N,f",
    ]);
    out.assert_code(0);
    assert!(
        out.stdout.contains("N = g*m*cos(th)") && out.stdout.contains("f = g*m*sin(th)"),
        "{}",
        out.stdout
    );

    let out = run(&["solve", "x^2 + 1 = 0"]);
    out.assert_code(1);
    assert!(out.stdout.contains("no real x"), "{}", out.stdout);

    // not polynomial and no interval: say what to do
    let out = run(&["solve", "sin(x) = x/2"]);
    out.assert_code(2);
    out.assert_stderr_contains("--in");
}

#[test]
fn unit_conversion() {
    let out = run(&["units", "60 km/h", "--to", "m/s"]);
    out.assert_code(0);
    assert!(
        out.stdout.contains("16.66666666666") && out.stdout.contains("velocity"),
        "{}",
        out.stdout
    );
    let out = run(&["units", "3000 rpm", "--json"]);
    let j: serde_json::Value = serde_json::from_str(&out.stdout).expect("JSON");
    assert!((num(&j, "/si") - 100.0 * std::f64::consts::PI).abs() < 1e-9);
    let out = run(&["units", "60 km/h", "--to", "kg"]);
    out.assert_code(2);
    out.assert_stderr_contains("dimensions differ");
    let out = run(&["units", "3 mps"]);
    out.assert_code(2);
    out.assert_stderr_contains("m/s");
}

#[test]
fn formula_errors_point_at_the_column() {
    let out = run(&["diff", "x + * 2"]);
    out.assert_code(2);
    out.assert_stderr_contains("column 5");
    out.assert_stderr_contains("x + * 2\n      ^");
    let out = run(&["integrate", "sinn(x)"]);
    out.assert_code(2);
    out.assert_stderr_contains("`sin`");
}

//! `mechkit dsolve`: differential equations in closed form. The JSON `solution` is a formula
//! in the variable that, evaluated, matches the exact solution; values given with `--set`
//! decide the damping case; an equation without a closed form exits 1 and points to
//! `mechkit run`; bad input exits 2 at its column.

use crate::util::{Dir, at};

fn run(args: &[&str]) -> crate::util::Output {
    Dir::new().run(args)
}

fn json(args: &[&str]) -> serde_json::Value {
    let mut all = args.to_vec();
    all.push("--json");
    let out = run(&all);
    out.assert_code(0);
    serde_json::from_str(&out.stdout).expect("JSON")
}

/// The JSON solution evaluated at `t` with mechkit's own formula language.
fn value(j: &serde_json::Value, t: f64) -> f64 {
    let text = at(j, "/solution").as_str().expect("a formula");
    let f = mechkit::expr::Sym::parse(text).expect("the solution parses");
    f.eval(&|n| (n == "t").then_some(t)).expect("a value")
}

#[test]
fn oscillator_with_initial_conditions_in_text_and_json() {
    let out = run(&["dsolve", "x'' + 4*x = 0", "--ic", "x(0)=1, x'(0)=0"]);
    out.assert_code(0);
    assert!(
        out.stdout.starts_with("x(t) = cos(2*t)\n"),
        "{}",
        out.stdout
    );
    assert!(out.stdout.contains("verified"), "{}", out.stdout);
    let j = json(&["dsolve", "x'' + 4*x = 0", "--ic", "x(0)=1, x'(0)=0"]);
    assert_eq!(at(&j, "/solution"), &serde_json::json!("cos(2*t)"));
    assert_eq!(at(&j, "/verified"), &serde_json::json!(true));
    assert_eq!(at(&j, "/constants"), &serde_json::json!([]));
}

#[test]
fn damped_and_driven_with_values() {
    let j = json(&[
        "dsolve",
        "m*x'' + c*x' + k*x = 0",
        "--ic",
        "x(0)=1, x'(0)=0",
        "--set",
        "m=1,c=0.4,k=4",
    ]);
    assert!(
        at(&j, "/method").as_str().unwrap().contains("under-damped"),
        "{j}"
    );
    let b = 3.96_f64.sqrt();
    for t in [0.5_f64, 1.0, 3.0] {
        let exact = (-0.2 * t).exp() * ((b * t).cos() + 0.2 / b * (b * t).sin());
        assert!((value(&j, t) - exact).abs() < 1e-12, "{j}");
    }
    // resonance
    let j = json(&[
        "dsolve",
        "x'' + w^2*x = cos(w*t)",
        "--ic",
        "x(0)=0, x'(0)=0",
        "--set",
        "w=2",
    ]);
    assert!(at(&j, "/method").as_str().unwrap().contains("resonance"));
    assert!(
        (value(&j, 1.3) - 1.3 * (2.6_f64).sin() / 4.0).abs() < 1e-12,
        "{j}"
    );
}

#[test]
fn free_constants_and_assumptions_without_values() {
    let j = json(&["dsolve", "m*x'' = -k*x"]);
    assert_eq!(at(&j, "/constants"), &serde_json::json!(["C1", "C2"]));
    assert_eq!(at(&j, "/assumptions"), &serde_json::json!(["k/m > 0"]));
    let j = json(&[
        "dsolve",
        "y' = -y/tau",
        "--func",
        "y",
        "--var",
        "s",
        "--ic",
        "y(0)=2",
    ]);
    assert_eq!(at(&j, "/solution"), &serde_json::json!("2*exp(-s/tau)"));
}

#[test]
fn no_closed_form_exits_1_and_points_to_a_scenario() {
    let out = run(&["dsolve", "x'' + sin(x) = 0"]);
    out.assert_code(1);
    assert!(out.stderr.contains("no closed form"), "{}", out.stderr);
    assert!(out.stderr.contains("mechkit run"), "{}", out.stderr);
}

#[test]
fn bad_input_is_located() {
    let out = run(&["dsolve", "x'' + * x = 0"]);
    out.assert_code(2);
    assert!(out.stderr.contains("column 7"), "{}", out.stderr);
    let out = run(&["dsolve", "x' = x", "--ic", "x'(0)=1"]);
    out.assert_code(2);
    assert!(out.stderr.contains("--ic"), "{}", out.stderr);
    run(&["dsolve", "x + 1 = 0"]).assert_code(2);
    run(&["dsolve", "x' = x", "--var", "x+y"]).assert_code(2);
}

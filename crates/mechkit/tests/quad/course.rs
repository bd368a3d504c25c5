//! The course's worked numbers: the work `W = ∫_0^{b/4} −F₀ sin(2πx/b) dx` of a sinusoidal
//! force over a quarter period (`F₀ = b = 1`, exact `−1/2π = −0.159155`) by the rules on
//! functions and on samples, and `∫_0^1 dx/(1 + x²) = π/4` by the trapezoid rule. The course
//! prints six decimals; each value must be reproduced to 1e-6.

use mechkit::quad::{Rule, SampleRule, Tolerance, integrate, integrate_rule, integrate_samples};

fn force(x: f64) -> f64 {
    -(2.0 * std::f64::consts::PI * x).sin()
}

#[test]
fn work_of_a_sinusoidal_force() {
    let exact = integrate(force, 0.0, 0.25, Tolerance::default())
        .unwrap()
        .value;
    assert!((exact - -0.159_155).abs() < 1e-6, "{exact}");
    assert!((exact + 0.5 / std::f64::consts::PI).abs() < 1e-14);
    let table = [
        (Rule::Left, 10, -0.146_328),
        (Rule::Midpoint, 10, -0.159_319),
        (Rule::Trapezoid, 10, -0.158_828),
        (Rule::Left, 100, -0.157_902),
        (Rule::Trapezoid, 100, -0.159_152),
    ];
    for (rule, n, course) in table {
        let w = integrate_rule(force, 0.0, 0.25, rule, n).unwrap();
        assert!(
            (w - course).abs() < 1e-6,
            "{rule}, n = {n}: {w} vs {course}"
        );
    }
}

#[test]
fn the_same_work_from_samples() {
    // the course samples F at n + 1 points and applies the rules to the table
    for (rule, n, course) in [
        (SampleRule::Left, 10, -0.146_328),
        (SampleRule::Trapezoid, 10, -0.158_828),
        (SampleRule::Trapezoid, 100, -0.159_152),
    ] {
        let x: Vec<f64> = (0..=n)
            .map(|i| 0.25 * f64::from(i) / f64::from(n))
            .collect();
        let f: Vec<f64> = x.iter().map(|&x| force(x)).collect();
        let w = integrate_samples(&x, &f, rule).unwrap();
        assert!(
            (w - course).abs() < 1e-6,
            "{rule}, n = {n}: {w} vs {course}"
        );
    }
}

#[test]
fn arctangent_by_the_trapezoid_rule() {
    let v = integrate_rule(|x| 1.0 / (1.0 + x * x), 0.0, 1.0, Rule::Trapezoid, 10).unwrap();
    assert!((v - 0.784_981).abs() < 1e-6, "{v}");
}

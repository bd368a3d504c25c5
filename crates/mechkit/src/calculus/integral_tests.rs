use std::f64::consts::PI;

use super::*;

/// The closed form of `text` on `[a, b]` with `set`, which must agree with the quadrature.
fn closed(text: &str, x: &str, (a, b): (Real, Real), set: &[(&str, Real)]) -> (Integral, Real) {
    let params: Vec<(String, Real)> = set.iter().map(|(k, v)| (k.to_string(), *v)).collect();
    let i = integral(text, x, Some((a, b)), &params).unwrap();
    let d = i.definite.clone().unwrap();
    assert_eq!(d.agree, Some(true), "{text}: {d:?}");
    (i, d.closed_form.unwrap())
}

#[test]
fn values_that_break_an_assumption_get_the_antiderivative_for_those_values() {
    // the ellipse (e < 1), where the symbolic search assumed the hyperbola's e - 1 > 0
    let (i, v) = closed("1/(1 + ecc*cos(th))^2", "th", (0.0, PI), &[("ecc", 0.5)]);
    assert!((v - 4.836_798_304_624_581).abs() < 1e-12, "{v}");
    assert!(i.assumptions.is_empty(), "{:?}", i.assumptions);
    assert!(!i.antiderivative.unwrap().to_string().contains("ecc"));
    // a < 0 breaks `a > 0` (the value was -0.18, flagged as a jump of ln|u|)
    let (_, v) = closed("sqrt(a^2 - x^2)", "x", (0.0, 1.0), &[("a", -2.0)]);
    assert!((v - 1.913_222_954_981_036_2).abs() < 1e-12, "{v}");
    // a = b makes the product-to-sum formula divide by a - b
    let (i, v) = closed(
        "sin(a*x)*sin(b*x)",
        "x",
        (0.0, 1.0),
        &[("a", 2.0), ("b", 2.0)],
    );
    assert!((v - (0.5 - (4.0_f64).sin() / 8.0)).abs() < 1e-12, "{v}");
    assert_eq!(i.input.to_string(), "sin(2*x)^2");
    // values the symbolic answer holds for keep it, with its assumption
    let (i, _) = closed("1/(a + x^2)", "x", (0.0, 1.0), &[("a", 4.0)]);
    assert_eq!(i.assumptions, vec!["a > 0"]);
    // and an integrand with no symbolic answer gets one for the values
    let (i, _) = closed(
        "1/(a + b*cos(x))",
        "x",
        (0.0, 1.0),
        &[("a", 1.0), ("b", 2.0)],
    );
    assert!(i.antiderivative.is_some());
}

#[test]
fn the_acceptance_integral() {
    let i = integral("1/(a+x^2)", "x", Some((0.0, 1.0)), &[("a".into(), 1.0)]).unwrap();
    assert_eq!(
        i.antiderivative.unwrap().to_string(),
        "atan(x/sqrt(a))/sqrt(a)"
    );
    assert_eq!(i.assumptions, vec!["a > 0"]);
    let d = i.definite.unwrap();
    assert!((d.closed_form.unwrap() - std::f64::consts::FRAC_PI_4).abs() < 1e-15);
    assert_eq!(d.agree, Some(true));
}

#[test]
fn rules_need_intervals_and_nothing_found_is_said() {
    let e = integration("x", "x", Some((0.0, 1.0)), &[], &[Rule::Left], &[0]).unwrap_err();
    assert!(matches!(
        e,
        CalculusError::Input(InputError {
            input: Input::Intervals,
            ..
        })
    ));
    let none = integration("exp(-x^2)", "x", None, &[], &[], &[]).unwrap();
    assert!(none.found_nothing() && none.rules.is_none());
}

#[cfg(feature = "serde")]
#[test]
fn the_json_shape_of_integrate() {
    let i = integration(
        "1/(a+x^2)",
        "x",
        Some((0.0, 1.0)),
        &[("a".into(), 1.0)],
        &[Rule::Trapezoid],
        &[10],
    )
    .unwrap();
    let j = serde_json::to_value(&i).unwrap();
    assert_eq!(j["antiderivative"], "atan(x/sqrt(a))/sqrt(a)");
    assert_eq!(j["parameters"], serde_json::json!({"a": 1.0}));
    assert_eq!(j["definite"]["quadrature_error"], serde_json::Value::Null);
    assert!(j["definite"]["quadrature"]["evaluations"].as_u64().unwrap() > 0);
    assert_eq!(j["rules"][0]["rule"], "trapezoid");
}

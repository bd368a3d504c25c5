//! Properties of the expression engine on random formulas (proptest):
//! - printing and parsing round-trip, for parse trees and for canonical forms;
//! - simplification never changes a value where both forms are defined;
//! - the interpreter agrees with the tree walker, and the native code with the interpreter bit
//!   for bit;
//! - an antiderivative differentiates back to the integrand at fresh points;
//! - no input string makes the parser, the compiler or the unit reader panic.

use mechkit_expr::units::Quantity;
use mechkit_expr::{Formula, MapScope, Sym, parse};
use proptest::prelude::*;

/// Formula text from a small grammar over x, y, z.
fn formula() -> impl Strategy<Value = String> {
    let leaf = prop_oneof![
        Just("x".to_string()),
        Just("y".to_string()),
        Just("z".to_string()),
        (1i32..9).prop_map(|n| n.to_string()),
        (1i32..40).prop_map(|n| format!("{}", f64::from(n) / 4.0)),
        Just("pi".to_string()),
    ];
    leaf.prop_recursive(4, 24, 3, |inner| {
        prop_oneof![
            (inner.clone(), inner.clone()).prop_map(|(a, b)| format!("({a} + {b})")),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| format!("({a} - {b})")),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| format!("({a} * {b})")),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| format!("({a} / {b})")),
            (inner.clone(), 0i32..4).prop_map(|(a, n)| format!("({a})^{n}")),
            inner.clone().prop_map(|a| format!("-({a})")),
            (
                prop_oneof![
                    Just("sin"),
                    Just("cos"),
                    Just("exp"),
                    Just("ln"),
                    Just("sqrt"),
                    Just("abs"),
                    Just("atan"),
                    Just("tanh")
                ],
                inner.clone()
            )
                .prop_map(|(f, a)| format!("{f}({a})")),
            (inner.clone(), inner.clone(), inner)
                .prop_map(|(c, a, b)| format!("if({c} > 1, {a}, {b})")),
        ]
    })
}

fn env(x: f64, y: f64, z: f64) -> impl Fn(&str) -> Option<f64> {
    move |n| match n {
        "x" => Some(x),
        "y" => Some(y),
        "z" => Some(z),
        other => mechkit_expr::builtin_constant(other),
    }
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-7 * a.abs().max(b.abs()).max(1.0)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    #[test]
    fn printing_round_trips(src in formula()) {
        let e = parse(&src).unwrap().expr;
        prop_assert_eq!(parse(&e.to_string()).unwrap().expr, e.clone());
        let s = Sym::from_expr(&e);
        let printed = s.to_string();
        prop_assert_eq!(Sym::parse(&printed).unwrap(), s, "{} printed as {}", src, printed);
    }

    #[test]
    fn simplify_keeps_values(src in formula(), x in -3.0f64..3.0, y in 0.1f64..3.0, z in -2.0f64..2.0) {
        let e = parse(&src).unwrap().expr;
        let s = Sym::from_expr(&e);
        let (a, b) = (e.eval_with(&env(x, y, z)).unwrap(), s.eval(&env(x, y, z)).unwrap());
        if a.is_finite() && b.is_finite() && a.abs() < 1e6 {
            prop_assert!(close(a, b), "{} = {} but simplified {} = {}", src, a, s, b);
        }
    }

    #[test]
    fn compiled_agrees(src in formula(), x in -3.0f64..3.0, y in 0.1f64..3.0, z in -2.0f64..2.0) {
        let f = Formula::parse(&src).unwrap();
        let scope = MapScope::new().slot("x", 0).slot("y", 1).slot("z", 2);
        let p = f.compile(&scope).unwrap();
        let native = p.clone().native();
        let vars = [x, y, z];
        let interpreted = p.eval_interpreted(&vars);
        // Bit for bit, except that a NaN is any NaN: Cranelift's optimizer may rewrite
        // (-a)*(-a) as a*a, which only changes the sign bit of a NaN.
        let n = native.eval(&vars);
        prop_assert!(n.to_bits() == interpreted.to_bits() || (n.is_nan() && interpreted.is_nan()),
            "{}: native {} differs from interpreted {}", src, n, interpreted);
        let tree = f.expr().eval_with(&env(x, y, z)).unwrap();
        prop_assert!(tree.to_bits() == interpreted.to_bits() || close(tree, interpreted) || (tree.is_nan() && interpreted.is_nan()),
            "{}: tree {} vs compiled {}", src, tree, interpreted);
    }

    #[test]
    fn antiderivatives_differentiate_back(src in formula(), x in 0.2f64..2.0) {
        let f = Sym::parse(&src.replace('y', "2").replace('z', "3")).unwrap();
        if let Some(a) = f.integrate("x") {
            let d = a.result.diff("x");
            let e = |v: f64| move |n: &str| (n == "x").then_some(v);
            let (fv, dv) = (f.eval(&e(x)).unwrap(), d.eval(&e(x)).unwrap());
            if fv.is_finite() && dv.is_finite() && fv.abs() < 1e6 {
                prop_assert!((fv - dv).abs() <= 1e-6 * fv.abs().max(1.0), "∫ {} = {}: derivative {} at {}", f, a.result, dv, x);
            }
        }
    }

    #[test]
    fn arbitrary_text_never_panics(text in "\\PC{0,40}") {
        if let Ok(f) = Formula::parse(&text) {
            let _ = f.compile(&MapScope::new().slot("x", 0));
            let _ = Sym::from_expr(f.expr()).to_string();
        }
        let _ = Quantity::parse(&text);
    }

    #[test]
    fn operator_soup_never_panics(text in "[-+*/^(),<>=!a-z0-9. ]{0,60}") {
        if let Ok(f) = Formula::parse(&text) {
            let s = Sym::from_expr(f.expr());
            let _ = s.diff("x");
            let _ = s.to_string();
        }
    }
}

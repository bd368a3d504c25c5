//! Tests of `solve`: one equation (by formula, in closed form, numerically) and linear systems.

use super::*;

#[test]
fn equations() {
    let s = solve("x^2 - 5*x + 6 = 0", "x", None, &[]).unwrap();
    assert_eq!(s.numeric, vec![2.0, 3.0]);
    let s = solve("cos(x) = x", "x", Some((0.0, 1.0)), &[]).unwrap();
    assert!((s.numeric[0] - 0.739_085_133_215_160_6).abs() < 1e-12);
    assert!(solve("cos(x) = x", "x", None, &[]).is_err());
    let sys = solve_system("N - m*g*cos(t) = 0; f = m*g*sin(t)", &["N", "f"]).unwrap();
    assert_eq!(sys[1].1.to_string(), "g*m*sin(t)");
}

/// Issue 22: `--set` gives values to a linear system's other names.
#[test]
fn a_system_uses_the_values_given() {
    let p = [("a".to_string(), 2.0)];
    let Solved::System(s) =
        solve_equations("a*x + y = 3; x - y = 1", &["x", "y"], None, &p).unwrap()
    else {
        panic!("a system")
    };
    let n = s.numeric.as_ref().unwrap();
    assert!((n[0].1 - 4.0 / 3.0).abs() < 1e-15 && (n[1].1 - 1.0 / 3.0).abs() < 1e-15);
    assert!(!s.singular_with_values() && s.missing().is_empty());
    // singular for a = -1
    let p = [("a".to_string(), -1.0)];
    let s = solve_equations("a*x + y = 3; x - y = 1", &["x", "y"], None, &p).unwrap();
    assert!(s.failed());
    // no values: the symbolic solution alone
    let Solved::System(s) =
        solve_equations("a*x + y = 3; x - y = 1", &["x", "y"], None, &[]).unwrap()
    else {
        panic!("a system")
    };
    assert!(s.numeric.is_none() && s.missing() == ["a"]);
}

/// Issue 27: cubics and quartics without an interval, in closed form; with `--set` values for
/// symbolic coefficients; other polynomials numerically inside Cauchy's bound.
#[test]
fn cubics_quartics_and_higher_degrees_without_an_interval() {
    let s = solve("x^3 - 6*x^2 + 11*x = 6", "x", None, &[]).unwrap();
    assert_eq!(s.numeric, vec![1.0, 2.0, 3.0]);
    assert_eq!(s.roots().unwrap()[2], Sym::int(3));
    assert!(s.interval.is_none() && s.root_bound.is_none());
    // casus irreducibilis: three real roots through cos and acos
    let s = solve("x^3 - 3*x + 1 = 0", "x", None, &[]).unwrap();
    assert_eq!(s.numeric.len(), 3);
    for v in &s.numeric {
        assert!((v * v * v - 3.0 * v + 1.0).abs() < 1e-14, "{v}");
    }
    // a quartic with no real root
    let s = solve("x^4 + x^2 + 1 = 0", "x", None, &[]).unwrap();
    assert_eq!(s.symbolic, Some(Solutions::NoRealRoot));
    assert!(s.is_empty());
    // symbolic coefficients with values: a = 1 gives the cubic above
    let p = [("a".to_string(), 1.0)];
    let s = solve("a*x^3 - 6*x^2 + 11*x - 6 = 0", "x", None, &p).unwrap();
    assert_eq!(s.numeric, vec![1.0, 2.0, 3.0]);
    // without values: the message names them
    let e = solve("a*x^3 - 6*x^2 + 11*x - 6 = 0", "x", None, &[]).unwrap_err();
    assert!(
        e.to_string().contains("give values for `a` with --set"),
        "{e}"
    );
    // degree five: every real root numerically, inside Cauchy's bound 1 + max|a_k/a_n| = 2
    let s = solve("x^5 = x + 1", "x", None, &[]).unwrap();
    assert!(s.symbolic.is_none());
    assert_eq!(s.root_bound, Some(2.0));
    assert_eq!(s.interval, Some((-2.0, 2.0)));
    assert_eq!(s.numeric.len(), 1);
    assert!((s.numeric[0] - 1.167_303_978_261_418_7).abs() < 1e-15);
    // none: x^6 + 1, a definite "no real root"
    let s = solve("x^6 + 1 = 0", "x", None, &[]).unwrap();
    assert_eq!(s.symbolic, Some(Solutions::NoRealRoot));
    // an interval keeps the roots in it
    let s = solve("x^5 - 5*x^3 + 4*x + 1 = 0", "x", Some((0.0, 3.0)), &[]).unwrap();
    assert_eq!(s.numeric.len(), 2, "{:?}", s.numeric);
    assert!(s.root_bound.is_none() && s.interval == Some((0.0, 3.0)));
    // not a polynomial: still an interval needed
    assert!(solve("x^3 = cos(x)", "x", None, &[]).is_err());
}

/// Coefficients whose discriminants overflow: no closed form and no bound, so an error that
/// asks for an interval rather than a root list missing the large roots.
#[test]
fn overflowing_coefficients_are_not_a_partial_answer() {
    // x (x² − 1e308): the quadratic is scaled before its discriminant is formed, so the
    // roots ±1e154 come out whole (review C-06)
    let s = solve("x^3 - 1e308*x = 0", "x", None, &[]).unwrap();
    assert_eq!(s.numeric, [-1e154, 0.0, 1e154]);
    // with an interval, the roots in it
    let s = solve("x^3 - 1e308*x = 0", "x", Some((-1.0, 1.0)), &[]).unwrap();
    assert!(
        s.numeric.len() == 1 && s.numeric[0].abs() < 1e-12,
        "{:?}",
        s.numeric
    );
}

/// Review C-06: the roots of a polynomial with float coefficients are computed without
/// cancellation, and a root beyond double precision is an error, never `x = inf`.
#[test]
fn a_root_that_overflows_is_refused_and_small_roots_keep_their_digits() {
    let s = solve("1e-200*x^2 + x - 1 = 0", "x", None, &[]).unwrap();
    assert_eq!(s.numeric, [-1e200, 1.0]);
    let e = solve("1e-300*x = 1e300", "x", None, &[]).unwrap_err();
    assert!(matches!(e, CalculusError::NotFinite { .. }), "{e}");
    assert!(e.to_string().contains("overflows double precision"), "{e}");
    let p = [("a".to_string(), 1e10)];
    let s = solve("x^2 + a*x - 1 = 0", "x", None, &p).unwrap();
    assert_eq!(s.numeric, [-1e10, 1e-10]);
}

/// Review C-14: values that break what the symbolic solution assumes are put in: `a*x = 1`
/// with a = 0 has no solution (not `x = 1/a`), `a*x^2 + x + 1 = 0` with a = 1 no real one.
#[test]
fn values_that_break_an_assumption_leave_no_solution() {
    let s = solve("a*x = 1", "x", None, &[("a".to_string(), 0.0)]).unwrap();
    assert_eq!(s.symbolic, Some(Solutions::NoRealRoot));
    assert!(s.values_put_in && s.is_empty() && s.assumptions.is_empty());
    let s = solve("a*x = 0", "x", None, &[("a".to_string(), 0.0)]).unwrap();
    assert_eq!(s.symbolic, Some(Solutions::Every));
    let s = solve("a*x^2 + x + 1 = 0", "x", None, &[("a".to_string(), 1.0)]).unwrap();
    assert!(s.is_empty(), "{s:?}");
    // values that keep the assumptions: the formula, and its value
    let s = solve("a*x = 1", "x", None, &[("a".to_string(), 2.0)]).unwrap();
    assert!(!s.values_put_in && s.numeric == [0.5]);
}

/// Review C-07: a sign change across a jump is no root.
#[test]
fn a_jump_across_zero_is_not_a_root() {
    let s = solve("floor(x) = 1.5", "x", Some((0.0, 3.0)), &[]).unwrap();
    assert!(s.is_empty(), "{s:?}");
    let s = solve("if(x > 1, 1, -1) = 0", "x", Some((0.0, 2.0)), &[]).unwrap();
    assert!(s.is_empty(), "{s:?}");
}

/// Review C-17: the unknown cannot be given a value.
#[test]
fn a_value_for_the_unknown_is_refused() {
    let e = solve("a*x = 1", "x", None, &[("x".to_string(), 2.0)]).unwrap_err();
    assert!(e.to_string().contains("`x` is the variable"), "{e}");
}

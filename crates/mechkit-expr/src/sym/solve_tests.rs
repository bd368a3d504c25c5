//! Tests of equation solving: linear, quadratic, cubic and quartic equations, and linear systems.

use super::*;
use crate::sym::poly::NumPoly;
use crate::sym::real_roots;

#[test]
fn linear_and_quadratic() {
    let s = Sym::parse("m*a - F").unwrap().solve("a").unwrap();
    assert_eq!(
        s.solutions,
        Solutions::Roots(vec![Sym::parse("F/m").unwrap()])
    );
    assert_eq!(s.assumptions, vec!["m ≠ 0"]);
    let s = Sym::parse("x^2 + 1").unwrap().solve("x").unwrap();
    assert_eq!(s.solutions, Solutions::NoRealRoot);
    let s = Sym::parse("h - g*t^2/2").unwrap().solve("t").unwrap();
    let Solutions::Roots(r) = s.solutions else {
        panic!()
    };
    assert_eq!(r.len(), 2);
    assert!(Sym::parse("sin(x) - 1/2").unwrap().solve("x").is_none());
}

#[test]
fn a_block_on_a_slope() {
    // N - m g cos(th) = 0, m g sin(th) - f = 0 for N, f
    let eqs = [
        Sym::parse("N - m*g*cos(th)").unwrap(),
        Sym::parse("m*g*sin(th) - f").unwrap(),
    ];
    let s = solve_linear(&eqs, &["N", "f"]).unwrap();
    assert_eq!(s[0].to_string(), "g*m*cos(th)");
    assert_eq!(s[1].to_string(), "g*m*sin(th)");
    assert!(
        solve_linear(
            &[Sym::parse("x*y - 1").unwrap(), Sym::parse("x").unwrap()],
            &["x", "y"]
        )
        .is_err()
    );
}

/// The real roots `Sym::solve` gives, as numbers (checked to be finite).
fn values(text: &str) -> Vec<f64> {
    let s = Sym::parse(text).unwrap().solve("x").unwrap();
    match s.solutions {
        Solutions::Roots(r) => r
            .iter()
            .map(|r| {
                let v = r.eval(&|_| None).unwrap();
                assert!(v.is_finite(), "{text}: {r}");
                v
            })
            .collect(),
        Solutions::NoRealRoot => Vec::new(),
        Solutions::Every => panic!("{text}: every value"),
    }
}

/// Cubics and quartics with known real roots (values from mpmath's `polyroots` at 30 digits,
/// or exact): rational roots exactly, a triple root once, the casus irreducibilis, quartics
/// with 0, 2 and 4 real roots.
#[test]
fn cubics_and_quartics_with_known_roots() {
    let table: &[(&str, &[f64])] = &[
        ("x^3 - 6*x^2 + 11*x - 6", &[1.0, 2.0, 3.0]),
        ("(x - 2)^3", &[2.0]),
        ("(x - 1)^2*(x + 2)", &[-2.0, 1.0]),
        ("2*x^3 - 4*x^2 - 22*x + 24", &[-3.0, 1.0, 4.0]),
        (
            "x^3 - 3*x + 1",
            &[
                -1.879_385_241_571_816_8,
                0.347_296_355_333_860_7,
                1.532_088_886_237_956,
            ],
        ),
        ("x^3 - 2", &[1.259_921_049_894_873_2]),
        ("x^3 + x - 1", &[0.682_327_803_828_019_3]),
        (
            "x^3 - 2*x",
            &[-std::f64::consts::SQRT_2, 0.0, std::f64::consts::SQRT_2],
        ),
        ("x^4 + x^2 + 1", &[]),
        ("x^4 + 1", &[]),
        ("(x - 1)^4", &[1.0]),
        ("x^4 - 2*x^2 + 1", &[-1.0, 1.0]),
        ("x^4 - 5*x^2 + 4", &[-2.0, -1.0, 1.0, 2.0]),
        (
            "x^4 - x - 1",
            &[-0.724_491_959_000_515_6, 1.220_744_084_605_759_5],
        ),
        (
            "x^4 + x^2 - 1",
            &[-0.786_151_377_757_423_3, 0.786_151_377_757_423_3],
        ),
        (
            "x^4 - 4*x^2 + x + 1",
            &[
                -2.061_498_850_684_642,
                -0.396_338_531_014_453_1,
                0.693_822_456_504_513,
                1.764_014_925_194_582_3,
            ],
        ),
        (
            "x^4 - 10*x^2 + 1",
            &[
                -3.146_264_369_941_972,
                -0.317_837_245_195_782_2,
                0.317_837_245_195_782_2,
                3.146_264_369_941_972,
            ],
        ),
        // (x^2 - 2)(x^2 - 3x + 1): not symmetric, so Ferrari's resolvent
        (
            "x^4 - 3*x^3 - x^2 + 6*x - 2",
            &[
                -std::f64::consts::SQRT_2,
                0.381_966_011_250_105_1,
                std::f64::consts::SQRT_2,
                2.618_033_988_749_895,
            ],
        ),
        // degree five, but x(x^4 - 1)
        ("x^5 - x", &[-1.0, 0.0, 1.0]),
    ];
    for (text, want) in table {
        let got = values(text);
        assert_eq!(got.len(), want.len(), "{text}: {got:?}");
        for (g, w) in got.iter().zip(*want) {
            assert!(
                (g - w).abs() <= 4e-15 * w.abs().max(1.0),
                "{text}: {g} vs {w}"
            );
        }
    }
    // rational roots are exact
    let s = Sym::parse("x^3 - 6*x^2 + 11*x - 6")
        .unwrap()
        .solve("x")
        .unwrap();
    assert_eq!(
        s.solutions,
        Solutions::Roots(vec![Sym::int(1), Sym::int(2), Sym::int(3)])
    );
    assert!(s.assumptions.is_empty());
    // the casus irreducibilis in cosines
    let s = Sym::parse("x^3 - 3*x + 1").unwrap().solve("x").unwrap();
    let Solutions::Roots(r) = s.solutions else {
        panic!()
    };
    assert!(r.iter().all(|r| r.to_string().contains("acos")), "{r:?}");
    // a factor of degree five is left: numerically
    assert!(Sym::parse("x^5 - x - 1").unwrap().solve("x").is_none());
}

/// Closed forms against the numerical search by the derivative's roots, two independent
/// methods, on every cubic and quartic with small integer coefficients of a pseudo-random
/// sample.
#[test]
fn closed_forms_agree_with_the_numerical_search() {
    let mut seed: u64 = 12345;
    let mut next = || {
        seed = seed
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        ((seed >> 33) % 19) as i64 - 9
    };
    let mut checked = 0;
    for i in 0..400 {
        let degree = 3 + i % 2;
        let mut c: Vec<i64> = (0..=degree).map(|_| next()).collect();
        if c[degree] == 0 {
            c[degree] = 1;
        }
        let p = NumPoly::new(c.iter().map(|v| crate::number::Number::int(*v)).collect());
        let closed: Vec<f64> = p
            .closed_form_roots()
            .unwrap_or_else(|| panic!("{c:?}"))
            .iter()
            .map(|r| r.eval(&|_| None).unwrap())
            .collect();
        let floats: Vec<f64> = c.iter().map(|v| *v as f64).collect();
        let numeric = real_roots(&floats).unwrap().roots;
        // a multiple root is found numerically only to about eps^(1/m)
        assert_eq!(
            closed.len(),
            numeric.len(),
            "{c:?}: {closed:?} vs {numeric:?}"
        );
        for (a, b) in closed.iter().zip(&numeric) {
            assert!((a - b).abs() < 1e-5 * a.abs().max(1.0), "{c:?}: {a} vs {b}");
        }
        checked += 1;
    }
    assert_eq!(checked, 400);
}

/// Symbolic coefficients: a factor x^k, and powers a x^3 + d, a x^4 + d.
#[test]
fn symbolic_cubics_and_quartics() {
    let s = Sym::parse("m*x^3 - k").unwrap().solve("x").unwrap();
    assert_eq!(
        s.solutions,
        Solutions::Roots(vec![Sym::parse("cbrt(k/m)").unwrap()])
    );
    assert_eq!(s.assumptions, vec!["m ≠ 0"]);
    let s = Sym::parse("a*x^4 - b").unwrap().solve("x").unwrap();
    let Solutions::Roots(r) = &s.solutions else {
        panic!()
    };
    assert_eq!(r.len(), 2);
    assert_eq!(s.assumptions, vec!["a ≠ 0", "b/a ≥ 0"]);
    let s = Sym::parse("a*x^3 + b*x^2 + c*x")
        .unwrap()
        .solve("x")
        .unwrap();
    let Solutions::Roots(r) = &s.solutions else {
        panic!()
    };
    assert_eq!(r.len(), 3);
    assert_eq!(r[0], Sym::zero());
    // no short answer: numerically with values
    assert!(Sym::parse("x^3 + a*x + 1").unwrap().solve("x").is_none());
}

/// The numerical search: all real roots inside Cauchy's bound, multiple ones included.
#[test]
fn real_roots_inside_the_bound() {
    // (x - 1)(x - 2)...(x - 8)
    let mut c = vec![1.0];
    for k in 1..=8 {
        let mut next = vec![0.0; c.len() + 1];
        for (i, v) in c.iter().enumerate() {
            next[i + 1] += v;
            next[i] -= v * f64::from(k);
        }
        c = next;
    }
    let r = real_roots(&c).unwrap();
    assert_eq!(r.roots.len(), 8);
    for (k, v) in r.roots.iter().enumerate() {
        assert!((v - (k + 1) as f64).abs() < 1e-9, "{v}");
    }
    // a double root, where the sign does not change: (x - 1)^2 (x + 3)
    let r = real_roots(&[3.0, -5.0, 1.0, 1.0]).unwrap();
    assert_eq!(r.roots.len(), 2, "{:?}", r.roots);
    assert!((r.roots[0] + 3.0).abs() < 1e-14 && (r.roots[1] - 1.0).abs() < 1e-7);
    assert_eq!(r.bound, 6.0);
    // none: x^6 + 1
    assert!(
        real_roots(&[1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0])
            .unwrap()
            .roots
            .is_empty()
    );
    // bad input
    assert!(real_roots(&[0.0, 0.0]).is_none());
    assert!(real_roots(&[1.0, f64::NAN]).is_none());
    assert!(real_roots(&[1.0; 102]).is_none());
    assert!(real_roots(&[1e300, 0.0, 0.0, 1e-300]).is_none());
}

/// Review C-06: float coefficients give float roots without the cancellation of the textbook
/// formula, and without the overflow of `b²`; exact ones that fold into floats likewise.
#[test]
fn quadratic_roots_are_found_without_cancellation_or_overflow() {
    let roots = |text: &str| match Sym::parse(text).unwrap().solve("x").unwrap().solutions {
        Solutions::Roots(r) => r
            .iter()
            .map(|r| r.eval(&|_| None).unwrap())
            .collect::<Vec<_>>(),
        other => panic!("{text}: {other:?}"),
    };
    assert_eq!(roots("1e-200*x^2 + x - 1"), [-1e200, 1.0]);
    let r = roots("1e300*x^2 + 1e300*x - 1e300");
    let golden = (5f64.sqrt() - 1.0) / 2.0;
    assert!(
        (r[0] + 1.0 + golden).abs() < 1e-15 && (r[1] - golden).abs() < 1e-15,
        "{r:?}"
    );
    assert_eq!(roots("x^2 + 10000000000*x - 1"), [-1e10, 1e-10]);
}

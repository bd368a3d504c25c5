use super::*;

fn int(src: &str) -> Option<String> {
    Sym::parse(src)
        .unwrap()
        .integrate("x")
        .map(|a| a.result.to_string())
}

#[test]
fn course_integrals() {
    assert_eq!(int("1/(a + x^2)").unwrap(), "atan(x/sqrt(a))/sqrt(a)");
    assert_eq!(int("k*x").unwrap(), "k*x^2/2");
    assert_eq!(int("C/x^2").unwrap(), "-C/x");
    assert_eq!(
        int("-F0*sin(2*pi*x/b)").unwrap(),
        "F0*b*cos(2*pi*x/b)/(2*pi)"
    );
    assert!(int("U0*((a/x)^12 - (b/x)^6)").is_some());
    assert_eq!(int("1/x").unwrap(), "ln(abs(x))");
    assert_eq!(int("x^3 - 2*x").unwrap(), "x^4/4 - x^2");
}

#[test]
fn substitutions_and_parts() {
    for f in [
        "exp(-3*x + 1)",
        "x/(a + x^2)",
        "x*exp(x^2)",
        "x*sin(x)",
        "x^2*exp(2*x)",
        "x*ln(x)",
        "1/(2 + 3*x)",
        "cos(x)^-2",
        "1/sqrt(4 - x^2)",
        "1/sqrt(x^2 + 1)",
        "1/(1 - x^2)",
        "1/((x - 1)*(x + 2))",
        "(x^2 + 1)/((x - 1)^2*(x + 3))",
        "1/(x^2 + 2*x + 5)",
        "x^3/(x^2 - 1)",
        "tan(x)",
        "sinh(2*x)*x",
    ] {
        assert!(int(f).is_some(), "no antiderivative for {f}");
    }
}

/// Squares of the circular and hyperbolic functions, by the double angle (the mean of
/// `sin^2` over a period is 1/2: the average power of an oscillator).
#[test]
fn squares_by_the_double_angle() {
    assert_eq!(int("sin(x)^2").unwrap(), "x/2 - sin(2*x)/4");
    assert_eq!(int("cos(x)^2").unwrap(), "x/2 + sin(2*x)/4");
    assert_eq!(int("tan(x)^2").unwrap(), "tan(x) - x");
    assert_eq!(int("sinh(x)^2").unwrap(), "sinh(2*x)/4 - x/2");
    assert_eq!(int("cosh(x)^2").unwrap(), "x/2 + sinh(2*x)/4");
    assert_eq!(int("tanh(x)^2").unwrap(), "x - tanh(x)");
    for f in [
        "A^2*w*sin(w*x + phi)^2",
        "cos(2*pi*x/T)^2",
        "3*sin(x)^2 - cos(x)^2",
    ] {
        assert!(int(f).is_some(), "no antiderivative for {f}");
    }
}

#[test]
fn no_answer_rather_than_a_wrong_one() {
    assert!(int("exp(x^2)").is_none());
    assert!(int("sin(x)/x").is_none());
}

/// Fuzz finding (expression): a tower of about 150 powers `a^b^c^…` made the substitution
/// search take the derivative of every level at every depth: 11 s and millions of clones. The
/// work budget stops it; the course's integrals stay far inside it.
#[test]
fn fuzz_a_power_tower_exhausts_the_budget_not_the_machine() {
    let tower =
        include_str!("../../../../../fuzz/regressions/calculus/power-tower-substitution-search");
    let run = |src: &str| {
        let f = Sym::parse(src).unwrap();
        let mut ctx = Ctx::new("x");
        let found = integrate(&f, &mut ctx).is_some();
        (found, FUEL - ctx.fuel)
    };
    let (found, used) = run(tower);
    assert!(!found && used >= FUEL - 1, "used {used} of {FUEL}");
    for f in [
        "x^2*exp(2*x)",
        "(x^2 + 1)/((x - 1)^2*(x + 3))",
        "1/(a + x^2)",
    ] {
        let (found, used) = run(f);
        assert!(found && used < FUEL / 100, "{f}: used {used}");
    }
}

/// Found by the `calculus` target (after 246 k inputs, 2026-12-05): a square root of a quadratic
/// whose coefficients are products of towers of powers took 7 s: completing the square
/// expanded products of those towers, and when the expansion was too large to carry out,
/// the linear term stayed and the square was completed again, down to the depth limit.
#[test]
fn fuzz_a_quadratic_with_towering_coefficients_is_not_completed_again_and_again() {
    let src = include_str!(
        "../../../../../fuzz/regressions/calculus/quadratic-with-towering-coefficients"
    );
    let f = Sym::parse(src).unwrap();
    let mut ctx = Ctx::new("x");
    assert!(integrate(&f, &mut ctx).is_none());
    // one completion tried, not one per level of the search until the budget ran out
    // (which it did: 10 substitutions and all 20,000 units, in 7 s)
    assert!(
        ctx.fuel > 0 && !ctx.completing,
        "{} substitutions, {} fuel",
        ctx.fresh,
        FUEL - ctx.fuel
    );
    // the completion still removes the linear term of an ordinary quadratic
    for f in ["1/sqrt(x^2 + 2*x + 5)", "sqrt(a*x^2 + b*x + c)"] {
        let f = Sym::parse(f).unwrap();
        assert!(f.integrate("x").is_some(), "{f}");
    }
}

/// Found by the `calculus` target (2026-12-05, fourth session): a product of seven factors,
/// one a power `(x - 2^m^…)^1.5` of towers, took 2.4 s in `mechkit integrate` (4 s in the fuzz
/// build): the square-root substitution and the reduction built an antiderivative of 147,150
/// nodes, and its verification differentiated it. A result is now charged its size at each
/// level of the search, so one that large is no answer: 0.1 s.
#[test]
fn fuzz_an_antiderivative_of_a_hundred_thousand_nodes_is_not_built() {
    let src = include_str!(
        "../../../../../fuzz/regressions/calculus/product-of-towers-147k-node-antiderivative"
    );
    let f = Sym::parse(src).unwrap();
    let mut ctx = Ctx::new("x");
    if let Some(r) = integrate(&f, &mut ctx) {
        panic!("an antiderivative of {} nodes", size(&r));
    }
    // what the same substitution gives on a small integrand still comes back
    for f in ["x*sqrt(x + 1)", "x^2*sqrt(a + b*x)", "(x - 2)^(3/2)*x^2"] {
        assert!(Sym::parse(f).unwrap().integrate("x").is_some(), "{f}");
    }
}

/// Found by the `calculus` target (2026-12-05): `1/(2*z^44 + x^2)^22` took 11 s (the
/// reduction's nested result rebuilt `2ⁿ` times by `Sym::product`, see
/// `build::tests::fuzz_a_deeply_nested_sum_is_rebuilt_once_per_level`); high powers of a
/// symbolic quadratic now reduce to a verified closed form.
#[test]
fn fuzz_a_high_power_of_a_symbolic_quadratic() {
    let src =
        include_str!("../../../../../fuzz/regressions/calculus/symbolic-quadratic-to-the-22nd");
    let f = Sym::parse(src).unwrap();
    let mut ctx = Ctx::new("x");
    let _ = integrate(&f, &mut ctx);
    assert!(ctx.fuel > 0, "the budget ran out");
    let r = Sym::parse("1/(a + x^2)^22")
        .unwrap()
        .integrate("x")
        .unwrap();
    assert!(
        r.result.to_string().contains("atan(x/sqrt(a))"),
        "{}",
        r.result
    );
}

/// Issue 27: the integrals the issue named, and the assumptions symbolic coefficients need.
#[test]
fn issue_27_list_and_assumptions() {
    let with = |src: &str| Sym::parse(src).unwrap().integrate("x").unwrap();
    assert_eq!(with("1/(c^2 - x^2)").assumptions, vec!["c > 0"]);
    assert_eq!(
        with("1/(c^2 - x^2)").result.to_string(),
        "ln(abs((c + x)/(c - x)))/(2*c)"
    );
    assert_eq!(with("sqrt(a^2 - x^2)").assumptions, vec!["a > 0"]);
    assert_eq!(
        with("exp(-a*x)*cos(w*x)").result.to_string(),
        "exp(-a*x)*(w*sin(w*x) - a*cos(w*x))/(a^2 + w^2)"
    );
    assert_eq!(int("sin(x)^3").unwrap(), "cos(x)^3/3 - cos(x)");
    assert_eq!(int("1/(1 + x^2)^2").unwrap(), "x/(2*(x^2 + 1)) + atan(x)/2");
    assert_eq!(int("1/(1 + exp(x))").unwrap(), "x - ln(abs(exp(x) + 1))");
    assert_eq!(int("ln(x)^2").unwrap(), "x*ln(x)^2 - 2*x*ln(x) + 2*x");
    assert_eq!(int("1/(x*sqrt(x^2 - 1))").unwrap(), "atan(sqrt(x^2 - 1))");
    for f in [
        "sqrt(1 - x^2)",
        "sqrt(4 + x^2)",
        "exp(-x)*sin(x)",
        "cos(x)^4",
        "1/cos(x)",
        "1/sin(x)",
        "x*atan(x)",
        "sqrt(x^2 - 1)",
        "tan(x)^5",
        "1/cosh(x)",
        "x^2*asin(x)",
        "exp(t)*sin(x)",
    ] {
        assert!(int(f).is_some(), "no antiderivative for {f}");
    }
}

/// Non-elementary integrals stay without a closed form, and quickly.
#[test]
fn non_elementary_integrals_give_up() {
    for f in [
        "exp(x^2)",
        "sin(x)/x",
        "exp(x)/x",
        "1/ln(x)",
        "sqrt(1 + x^3)",
        "sqrt(sin(x))",
        "sin(x^2)",
        "x^x",
        "exp(-x^2)*ln(x)",
        "1/sqrt(1 - x^4)",
        "sqrt(1 - x^2)*sqrt(1 + x^2)",
    ] {
        let mut ctx = Ctx::new("x");
        let found = integrate(&Sym::parse(f).unwrap(), &mut ctx);
        // a rule may find a form the check rejects; never one that passes
        let checked = Sym::parse(f).unwrap().integrate("x");
        assert!(checked.is_none(), "{f}: {:?}", found.map(|s| s.to_string()));
        assert!(FUEL - ctx.fuel < FUEL, "{f} exhausted the budget");
    }
}

#[test]
fn weierstrass_and_tangent_substitutions() {
    // continuous across x = ±π: (x - 2 atan(tan(x/2))) counts the poles of tan(x/2) passed
    assert_eq!(
        int("1/(2 + cos(x))").unwrap(),
        "2*atan(tan(x/2)/sqrt(3))/sqrt(3) + (x - 2*atan(tan(x/2)))/sqrt(3)"
    );
    assert_eq!(int("1/(1 + sin(x))").unwrap(), "-2/(tan(x/2) + 1)");
    let anti = Sym::parse("1/(a + b*cos(x))")
        .unwrap()
        .integrate("x")
        .unwrap();
    assert_eq!(anti.assumptions, vec!["a + b > 0", "a - b > 0"]);
    for f in ["1/(5 + 3*sin(x))", "cos(x)/(2 - cos(x))", "1/(3 + tan(x))"] {
        assert!(int(f).is_some(), "{f}");
    }
    // the antiderivatives are continuous across the poles of tan(x/2) (x = π) and of tan x
    // (x = π/2, where 1/(3 + tan x) is continuous)
    for (f, pole) in [
        ("1/(2 + cos(x))", std::f64::consts::PI),
        ("1/(5 + 4*sin(x))", std::f64::consts::PI),
        ("1/(3 + tan(x))", std::f64::consts::FRAC_PI_2),
    ] {
        let big_f = Sym::parse(f).unwrap().integrate("x").unwrap().result;
        let at = |v: f64| big_f.eval(&|n| (n == "x").then_some(v)).unwrap();
        let (left, right) = (at(pole - 1e-7), at(pole + 1e-7));
        assert!((left - right).abs() < 1e-6, "{f}: {left} against {right}");
    }
    // no trigonometric denominator: the substitution is not tried (and not needed)
    assert!(int("sin(x)^3").is_some());
}

#[test]
fn trigonometric_products_are_linearised() {
    assert_eq!(
        int("exp(-2*b*x)*cos(w*x)^2").unwrap(),
        "exp(-2*b*x)*(w*sin(2*w*x)/4 - b*cos(2*w*x)/4)/(b^2 + w^2) - exp(-2*b*x)/(4*b)"
    );
    for f in [
        "sin(x)^2*cos(2*x)",
        "exp(-g*x)*sin(w*x)^3",
        "sin(w*x)*cos(w*x)*exp(-b*x)",
        "x*exp(-x)*cos(x)^2",
    ] {
        assert!(int(f).is_some(), "{f}");
    }
}

#[test]
fn symbolic_powers_of_a_quadratic() {
    assert_eq!(
        int("1/(x^2 + a^2)^2").unwrap(),
        "(atan(x/a)/(2*a) + x/(2*(a^2 + x^2)))/a^2"
    );
    assert!(int("x^2/(x^2 + a^2)^2").is_some());
    assert!(int("1/(k - x^2)^3").is_some());
}

/// A rational function with symbols over linear factors (the table's `1/(x (a + b x))`), a
/// quotient over a symbolic quadratic, constant bases and functions of `ln x`: each answer
/// in the form a table gives, with no constant of integration left in the sum.
#[test]
fn symbolic_partial_fractions_constant_bases_and_functions_of_the_logarithm() {
    for (f, want) in [
        ("x/(a + x)", "x - a*ln(abs(a + x))"),
        ("1/(x*(a + b*x))", "ln(abs(x))/a - ln(abs(a + b*x))/a"),
        (
            "1/(x*(a + b*x)^2)",
            "1/(a*(a + b*x)) + ln(abs(x))/a^2 - ln(abs(a + b*x))/a^2",
        ),
        (
            "1/((x - a)*(x - b))",
            "ln(abs(a - x))/(a - b) - ln(abs(b - x))/(a - b)",
        ),
        ("x/(2 + 3*x)", "x/3 - 2*ln(abs(3*x + 2))/9"),
        ("x^3/(c^2 + x^2)", "x^2/2 - c^2*ln(abs(c^2 + x^2))/2"),
        ("x/(a + b*x^2)", "ln(abs(a + b*x^2))/(2*b)"),
        ("2^x", "2^x/ln(2)"),
        ("e^x", "exp(x)"),
        ("sin(ln(x))", "x*(sin(ln(x))/2 - cos(ln(x))/2)"),
        ("sec(x)*tan(x)", "1/cos(x)"),
    ] {
        assert_eq!(int(f).as_deref(), Some(want), "{f}");
    }
    let a = Sym::parse("a^x").unwrap().integrate("x").unwrap();
    assert_eq!(a.result.to_string(), "a^x/ln(a)");
    assert_eq!(a.assumptions, vec!["a > 0"]);
    // a factor written twice is one root of multiplicity two, not two roots
    assert_eq!(int("1/((x - a)*(x - a))").as_deref(), Some("1/(a - x)"));
    // a negative base has no real power: no answer
    assert_eq!(int("(-2)^x"), None);
}

/// `F(b) - F(a)` of the antiderivative of `f`.
fn definite(f: &str, a: f64, b: f64) -> f64 {
    let big_f = Sym::parse(f).unwrap().integrate("x").unwrap().result;
    let at = |v: f64| big_f.eval(&|n| (n == "x").then_some(v)).unwrap();
    at(b) - at(a)
}

#[test]
fn an_absolute_value_of_a_linear_argument_is_integrated_across_its_root() {
    assert_eq!(int("x*abs(x)").unwrap(), "abs(x)^3/3");
    assert_eq!(int("exp(-abs(x))").unwrap(), "sign(x)*(1 - exp(-abs(x)))");
    for (f, a, b, exact) in [
        ("x*abs(x)", -1.0, 2.0, 7.0 / 3.0),
        (
            "exp(-abs(x))",
            -1.0,
            2.0,
            2.0 - (-1.0_f64).exp() - (-2.0_f64).exp(),
        ),
        (
            "sqrt(abs(x))",
            -1.0,
            2.0,
            2.0 / 3.0 * (1.0 + 2.0_f64.powf(1.5)),
        ),
        ("x*abs(2*x - 1)", 0.0, 1.0, 0.25),
        ("ln(abs(x))", -2.0, -1.0, 2.0 * 2.0_f64.ln() - 1.0),
    ] {
        let v = definite(f, a, b);
        assert!((v - exact).abs() < 1e-12, "{f}: {v} against {exact}");
    }
}

#[test]
fn a_jump_of_the_integrand_gives_no_antiderivative_that_jumps() {
    // -exp(-x) heaviside(x - 1) differentiates to the integrand on either side of 1, and
    // jumps there: no answer (the product rule backwards found it)
    assert_eq!(int("heaviside(x - 1)*exp(-x)"), None);
    assert_eq!(int("floor(x)"), None);
    // continuous across the jump of its integrand
    assert_eq!(int("sign(x)").unwrap(), "abs(x)");
}

#[test]
fn rewrites_into_forms_the_rules_know() {
    for (f, want) in [
        ("log10(x)", "(x*ln(x) - x)/ln(10)"),
        ("sqrt(1 + sinh(x)^2)", "sinh(x)"),
        ("exp(2*x)*exp(3*x)", "exp(5*x)/5"),
        ("exp(x)*(1 + x*ln(x))/x", "exp(x)*ln(x)"),
        (
            "1/(sqrt(x + 1) + sqrt(x))",
            "2*(x + 1)^(3/2)/3 - 2*x^(3/2)/3",
        ),
        ("cos(x)^3/sqrt(sin(x))", "2*sqrt(sin(x)) - 2*sin(x)^(5/2)/5"),
        ("atan(1/x)", "x*atan(1/x) + ln(abs(x^2 + 1))/2"),
        (
            "1/(x^2 - 2)",
            "ln(abs((x - sqrt(2))/(sqrt(2) + x)))/(2*sqrt(2))",
        ),
    ] {
        assert_eq!(int(f).as_deref(), Some(want), "{f}");
    }
    // `1/x` by `t = 1/x`, with the sign of x
    assert!(int("1/(x*sqrt(x^2 + x + 1))").unwrap().contains("sign(x)"));
    // the symbolic u = tan x
    assert_eq!(
        int("1/(a^2*sin(x)^2 + b^2*cos(x)^2)").unwrap(),
        "atan(a*tan(x)/b)/(a*b) + (x - atan(tan(x)))/(a*b)"
    );
}

use super::*;

fn dims(n: &str) -> Dim {
    match n {
        "x" | "L" => Dim::Known(Dimension::LENGTH),
        "t" => Dim::Known(Dimension::TIME),
        "k" => Dim::Known(Dimension::STIFFNESS),
        "m" => Dim::Known(Dimension::MASS),
        "v" => Dim::Known(Dimension::VELOCITY),
        _ => Dim::Unknown,
    }
}

fn dim(src: &str) -> Result<Dim, ExprError> {
    Formula::parse(src).unwrap().dimension(&dims)
}

#[test]
fn products_sums_and_powers() {
    assert_eq!(dim("-k*(x - L)").unwrap(), Dim::Known(Dimension::FORCE));
    // A literal factor's unit is unknowable: no check, no false alarm.
    assert_eq!(dim("0.5*k*x^2").unwrap(), Dim::Unknown);
    assert_eq!(dim("-k*x - 0.5*v").unwrap(), Dim::Known(Dimension::FORCE));
    assert_eq!(dim("-0.5*x - 0.5*v").unwrap(), Dim::Unknown);
    assert_eq!(dim("k*x*x/2").unwrap(), Dim::Unknown);
    assert_eq!(dim("sin(2*t)").unwrap(), Dim::NONE);
    assert_eq!(dim("-k*x + q*v").unwrap(), Dim::Known(Dimension::FORCE));
    assert_eq!(dim("sqrt(k/m)").unwrap(), Dim::Known(Dimension::FREQUENCY));
    assert_eq!(dim("x - 1").unwrap(), Dim::Known(Dimension::LENGTH));
    assert_eq!(dim("max(0, -k*x)").unwrap(), Dim::Known(Dimension::FORCE));
    assert_eq!(dim("sin(2*pi*t/t)").unwrap(), Dim::NONE);
    assert_eq!(
        dim("x^(1/2)*x^(3/2)").unwrap(),
        Dim::Known(Dimension::LENGTH.powi(2))
    );
    assert_eq!(dim("q*x").unwrap(), Dim::Unknown);
    assert_eq!(
        dim("if(x > 0, -k*x, 0)").unwrap(),
        Dim::Known(Dimension::FORCE)
    );
}

#[test]
fn mismatches_are_explained() {
    let e = dim("x + t").unwrap_err();
    assert!(
        e.message()
            .contains("cannot add `x` (m (length)) and `t` (s (time))"),
        "{e}"
    );
    assert!(dim("sin(x)").is_err());
    assert_eq!(
        dim("sqrt(x)*sqrt(x)").unwrap(),
        Dim::Known(Dimension::LENGTH)
    );
    assert_eq!(
        dim("x^0.1").unwrap(),
        Dim::Known(Dimension::LENGTH.pow_ratio(1, 10).unwrap())
    );
    assert!(
        dim("x^pi")
            .unwrap_err()
            .message()
            .contains("no exact dimension")
    );
    assert!(dim("x^0.3333333").is_err());
    assert!(dim("x^t").is_err());
    let f = Formula::parse("x^n").unwrap();
    let with_n = f
        .dimension_with(&dims, &|name| (name == "n").then_some(3.0))
        .unwrap();
    assert_eq!(with_n, Dim::Known(Dimension::LENGTH.powi(3)));
    assert!(dim("x < t").is_err());
}

#[test]
fn rational_powers() {
    let m = |num, den| Dim::Known(Dimension::LENGTH.pow_ratio(num, den).unwrap());
    assert_eq!(dim("x^1.5").unwrap(), m(3, 2));
    assert_eq!(dim("x^(3/2)").unwrap(), m(3, 2));
    assert_eq!(dim("x^-1.5").unwrap(), m(-3, 2));
    assert_eq!(dim("sqrt(x^3)").unwrap(), m(3, 2));
    assert_eq!(dim("sqrt(sqrt(x))").unwrap(), m(1, 4));
    assert_eq!(dim("cbrt(x)").unwrap(), m(1, 3));
    assert_eq!(dim("cbrt(x)^3").unwrap(), m(1, 1));
    assert_eq!(dim("x^(1/3)*x^(2/3)").unwrap(), m(1, 1));
    // a Hertz contact: k in N/m^(3/2) times a length to the 3/2 is a force
    let hertz = Dim::Known(Dimension::FORCE / Dimension::LENGTH.pow_ratio(3, 2).unwrap());
    let names = |n: &str| if n == "kh" { hertz } else { dims(n) };
    let f = Formula::parse("kh*max(0, -x)^1.5").unwrap();
    assert_eq!(f.dimension(&names).unwrap(), Dim::Known(Dimension::FORCE));
    let wrong = Formula::parse("kh*max(0, -x)^2").unwrap();
    let e = wrong
        .expect_dimension(Dimension::FORCE, "a force", &names, &|_| None)
        .unwrap_err();
    assert!(e.message().contains("kg*m^(3/2)/s^2"), "{e}");
}

#[test]
fn huge_powers_are_exact_or_refused() {
    assert_eq!(
        dim("(((x^12)^12)^12)^12").unwrap(),
        Dim::Known(Dimension::LENGTH.checked_powi(20_736).unwrap())
    );
    // energy and force stay apart however large the powers
    assert_ne!(dim("k*x^2*x^5000"), dim("k*x*x^5000"));
    for src in [
        "(((((((((x^12)^12)^12)^12)^12)^12)^12)^12)^12)",
        "((x^2000)^2000)^2000",
        "x^1e12",
        "x^3000000000*x^3000000000",
    ] {
        let e = dim(src).unwrap_err();
        assert!(e.message().contains("exponent too large"), "{src}: {e}");
    }
    let mut deep = "x".to_string();
    for _ in 0..32 {
        deep = format!("sqrt({deep})");
    }
    assert!(
        dim(&deep)
            .unwrap_err()
            .message()
            .contains("exponent too large")
    );
}

#[test]
fn reduced_units_need_no_particular_dimension() {
    let f = Formula::parse("sin(t)").unwrap();
    let none = |_: &str| Dim::Unknown;
    assert!(
        f.expect_dimension(Dimension::FORCE, "a force", &none, &|_| None)
            .is_err()
    );
    assert!(
        f.expect_dimension_in(
            UnitSystem::Reduced,
            Dimension::FORCE,
            "a force",
            &none,
            &|_| None
        )
        .is_ok()
    );
    assert!(
        f.expect_dimension_in(UnitSystem::Si, Dimension::FORCE, "a force", &none, &|_| {
            None
        })
        .is_err()
    );
}

#[test]
fn expected_dimension() {
    let f = Formula::parse("-k*x*v").unwrap();
    assert!(
        Formula::parse("-k*x")
            .unwrap()
            .expect_dimension(Dimension::FORCE, "a force", &dims, &|_| None)
            .is_ok()
    );
    let e = f
        .expect_dimension(Dimension::FORCE, "a force", &dims, &|_| None)
        .unwrap_err();
    assert!(
        e.message()
            .starts_with("a force must have dimension kg*m/s^2 (force, N)"),
        "{e}"
    );
}

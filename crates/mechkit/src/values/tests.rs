//! Tests of the typed-value parser.

use super::*;

#[test]
fn values() {
    let p = vec![("b".to_string(), 2.0)];
    assert_eq!(value("3", "--x", &p).unwrap(), 3.0);
    assert!((value("60 km/h", "--v", &p).unwrap() - 16.666_666_666_666_668).abs() < 1e-12);
    assert_eq!(value("b/4", "--to", &p).unwrap(), 0.5);
    assert!((value("2*pi", "--to", &p).unwrap() - std::f64::consts::TAU).abs() < 1e-15);
    let e = value("c/4", "--to", &p).unwrap_err();
    assert!(e.message.contains("--set c="), "{e}");
    assert_eq!(e.input, "--to");
    assert_eq!(interval("-1:2", "--range", &p).unwrap(), (-1.0, 2.0));
    assert_eq!(value("-inf", "--from", &p).unwrap(), f64::NEG_INFINITY);
    assert_eq!(value("∞", "--to", &p).unwrap(), f64::INFINITY);
    assert!(interval("1", "--range", &p).is_err());
    assert_eq!(interval("2:1", "--param", &p).unwrap(), (2.0, 1.0));
    let e = increasing_interval("2:-1", "--range", &p).unwrap_err();
    assert!(
        e.message.contains("must be increasing") && e.message.contains("--range -1:2"),
        "{e}"
    );
    assert_eq!(e.input, "--range");
    assert_eq!(split_top_level("atan2(y, x), 0", ','), ["atan2(y, x)", "0"]);
}

#[test]
fn params_take_formulas_units_and_earlier_names() {
    let p = params("th=pi/6, m = 2 kg, w=m*3, f=atan2(1, 1)").unwrap();
    let get = |n: &str| p.iter().find(|(k, _)| k == n).unwrap().1;
    assert!((get("th") - std::f64::consts::FRAC_PI_6).abs() < 1e-15);
    assert_eq!(get("m"), 2.0);
    assert_eq!(get("w"), 6.0);
    assert!((get("f") - std::f64::consts::FRAC_PI_4).abs() < 1e-15);
    assert!((params("a=30 deg").unwrap()[0].1 - std::f64::consts::FRAC_PI_6).abs() < 1e-15);
    assert_eq!(params("a=1,a=2").unwrap(), [("a".to_string(), 2.0)]);
    let e = params("a").unwrap_err();
    assert!(e.message.contains("name=value"), "{e}");
    let e = params("2x=1").unwrap_err();
    assert!(e.message.contains("not a name"), "{e}");
    let e = params("a=b+1").unwrap_err();
    assert_eq!(e.input, "a");
    assert!(e.message.contains("`b`"), "{e}");
}

#[test]
fn vectors() {
    assert_eq!(
        vector("3 m/s, -1 m/s", "--v", Dimension::VELOCITY).unwrap(),
        [3.0, -1.0]
    );
    assert_eq!(
        vector("3, -1 km/s", "--v", Dimension::VELOCITY).unwrap(),
        [3000.0, -1000.0]
    );
    assert_eq!(vector("2", "--v", Dimension::VELOCITY).unwrap(), [2.0]);
    assert!(vector("1,2,3,4", "--v", Dimension::VELOCITY).is_err());
    assert!(vector("1,,2", "--v", Dimension::VELOCITY).is_err());
    let e = vector("1 kg", "--v", Dimension::VELOCITY).unwrap_err();
    assert!(e.message.contains("dimension"), "{e}");
}

/// Every input of dimension 1/s is an angular speed in rad/s: one written in Hz (cycles per
/// second) was taken 2π too small (`rotation --angular-speed "50 Hz"`: ω = 50 rad/s, a period
/// of 0.126 s for a rotation of 50 turns a second).
#[test]
fn an_angular_speed_in_hertz_is_refused() {
    use mechkit_expr::units::Dimension;
    for text in ["50 Hz", "0.05 kHz", "50 hertz"] {
        let e = quantity(text, "--angular-speed", Dimension::FREQUENCY).unwrap_err();
        assert!(e.message.contains("`rev/s`"), "{text}: {e}");
    }
    let w = quantity("50 rev/s", "--angular-speed", Dimension::FREQUENCY).unwrap();
    assert!((w - 100.0 * std::f64::consts::PI).abs() < 1e-9);
    assert!(quantity("3000 rpm", "--omega", Dimension::FREQUENCY).is_ok());
    // words that only contain the letters are not Hz
    assert!(!names_a_unit("50 Hzz", HERTZ) && names_a_unit("50 1/s*Hz", HERTZ));
}

//! Tests of the finiteness rule.

use super::*;
use std::collections::BTreeMap;

#[derive(serde::Serialize)]
enum Shape {
    Point(f64),
    Pair(f64, f64),
    Named { r: f64 },
    Empty,
}

#[derive(serde::Serialize)]
struct Report {
    title: String,
    n: u64,
    maybe: Option<f64>,
    shapes: Vec<Shape>,
    by_name: BTreeMap<String, [f64; 2]>,
}

fn report() -> Report {
    Report {
        title: "inf".into(),
        n: 3,
        maybe: None,
        shapes: vec![
            Shape::Point(1.0),
            Shape::Pair(1.0, 2.0),
            Shape::Named { r: 3.0 },
            Shape::Empty,
        ],
        by_name: BTreeMap::from([("ball".to_string(), [0.0, 1.0])]),
    }
}

#[test]
fn issue_026_finite_results_pass_and_each_non_finite_number_is_named_by_its_path() {
    assert_eq!(check_finite(&report()), Ok(()));
    let mut r = report();
    r.maybe = Some(f64::NAN);
    assert_eq!(check_finite(&r).unwrap_err().quantity, "maybe");
    let mut r = report();
    r.shapes[1] = Shape::Pair(1.0, f64::NEG_INFINITY);
    assert_eq!(check_finite(&r).unwrap_err().quantity, "shapes[1].Pair[1]");
    let mut r = report();
    r.shapes[2] = Shape::Named { r: f64::INFINITY };
    assert_eq!(check_finite(&r).unwrap_err().quantity, "shapes[2].Named.r");
    let mut r = report();
    r.by_name.insert("feather".into(), [f64::NAN, 0.0]);
    let e = check_finite(&r).unwrap_err();
    assert_eq!(e.quantity, "by_name.feather[0]");
    assert_eq!(
        e.to_string(),
        "the result by_name.feather[0] is NaN, not a finite number"
    );
    assert_eq!(
        check_finite(&f64::INFINITY).unwrap_err().to_string(),
        "the result is inf, not a finite number"
    );
}

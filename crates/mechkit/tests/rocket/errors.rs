//! Bad input is refused with the offending value: non-positive masses, a burnout mass not below
//! the mass at ignition, non-positive rate or exhaust speed, negative gravity or drag, and bad
//! tolerances.

use mechkit::rocket::{Rocket, RocketError};

use super::{config, rocket};

#[test]
fn bad_input() {
    let cases = [
        (Rocket::new(-1.0, 0.5, 1.0, 1.0), "m0 is -1 kg"),
        (Rocket::new(1.0, 0.0, 1.0, 1.0), "m1 is 0 kg"),
        (Rocket::new(1.0, 2.0, 1.0, 1.0), "m1 = 2 kg must be below"),
        (
            Rocket::new(1.0, 1.0, 1.0, 1.0),
            "must be below the mass at ignition",
        ),
        (Rocket::new(2.0, 1.0, -3.0, 1.0), "mass rate is -3 kg/s"),
        (Rocket::new(2.0, 1.0, 0.0, 1.0), "mass rate is 0 kg/s"),
        (Rocket::new(2.0, 1.0, 1.0, f64::NAN), "exhaust speed is NaN"),
        (rocket().with_gravity(-9.81), "g is -9.81"),
        (rocket().with_drag(-0.1), "drag coefficient D is -0.1"),
    ];
    for (result, needle) in cases {
        let e = result.unwrap_err();
        assert!(e.to_string().contains(needle), "{needle}: {e}");
    }
    assert!(matches!(
        Rocket::new(1.0, 2.0, 1.0, 1.0),
        Err(RocketError::Burnout { m0: 1.0, m1: 2.0 })
    ));
    // fields set by hand are checked again by the simulation, and so is the configuration
    let mut r = rocket();
    r.m1 = 2000.0;
    assert!(matches!(
        r.simulate(&config(1e-6), false),
        Err(RocketError::Burnout { .. })
    ));
    assert!(matches!(
        rocket().simulate(&config(-1.0), false),
        Err(RocketError::Config(_))
    ));
}

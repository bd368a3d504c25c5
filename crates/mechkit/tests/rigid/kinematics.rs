//! Angular kinematics: ω = dθ/dt and α = d²θ/dt² by symbolic differentiation, cross-checked
//! by Ridders' extrapolation; θ = θ₀ + ∫ω dt by the rule table (or quadrature); uniform angular
//! acceleration; circular motion (a_c = ω²R = v²/R, a_t = αR, radius R cos λ at latitude
//! λ); the rolling condition; v = ω × r and a = α × r + ω × (ω × r) in 3-D.

use std::f64::consts::{PI, TAU};

use mechkit::mass::Vec3;
use mechkit::rigid::kinematics::{
    AngularMotion, CircularMotion, Rolling, UniformAngularAcceleration, distance_from_axis,
    point_acceleration, point_velocity,
};

fn set(pairs: &[(&str, f64)]) -> Vec<(String, f64)> {
    pairs.iter().map(|(k, v)| ((*k).to_string(), *v)).collect()
}

/// c14-B4: θ = c1 t/t1 + c2 (t/t2)² → ω(1 s) = 2 rad/s, α = 1 rad/s² exactly; Ridders'
/// estimates agree to 1e-10.
#[test]
fn c14_b4_flywheel_from_theta() {
    let p = set(&[("c1", 1.0), ("t1", 1.0), ("c2", 2.0), ("t2", 2.0)]);
    let m = AngularMotion::from_angle("c1*t/t1 + c2*(t/t2)^2", &p).unwrap();
    let s = m.at(1.0);
    assert_eq!((s.theta, s.omega, s.alpha), (1.5, 2.0, 1.0));
    assert!(s.agree);
    assert!((s.omega_numeric.unwrap() - 2.0).abs() < 1e-10);
    assert!((s.alpha_numeric - 1.0).abs() < 1e-10);
}

/// c14-B5: ω = 2.5 cos(t/T) with T = 2 s: θ = 5 sin(t/2) symbolically (checked at 7 times
/// to 1e-14), ω(π s) = 0 and α(π s) = −1.25 rad/s² to 1e-15.
#[test]
fn c14_b5_unbalanced_wheel_from_omega() {
    let p = set(&[("w0", 2.5), ("T", 2.0)]);
    let m = AngularMotion::from_angular_velocity("w0*cos(t/T)", &p, 0.0).unwrap();
    assert!(m.theta_formula().is_some(), "the rule table integrates cos");
    for t in [0.0, 0.3, 1.0, 2.0, PI, 5.0, 10.0] {
        assert!(
            (m.theta(t) - 5.0 * (t / 2.0).sin()).abs() < 1e-14,
            "t = {t}"
        );
    }
    let s = m.at(PI);
    assert!(s.omega.abs() < 1e-15 && (s.alpha + 1.25).abs() < 1e-15);
    assert!(s.agree, "{s:?}");
}

/// Where the rule table has no antiderivative (ω = exp(−t²)), θ comes from adaptive
/// quadrature: θ(1) − θ₀ = (√π/2) erf(1) = 0.746824132812427 to 1e-13.
#[test]
fn theta_by_quadrature_when_no_closed_form() {
    let m = AngularMotion::from_angular_velocity("exp(-t^2)", &[], 0.5).unwrap();
    assert!(m.theta_formula().is_none());
    assert!((m.theta(1.0) - 0.5 - 0.746_824_132_812_427).abs() < 1e-13);
    let s = m.at(1.0);
    assert!(s.omega_numeric.is_none() && s.agree);
    assert!((s.alpha + 2.0 * (-1.0_f64).exp()).abs() < 1e-15);
}

/// c14-B7: 1000 → 2000 rpm in 15 s: α = 6.981 rad/s², 375 revolutions exactly.
#[test]
fn c14_b7_engine_spin_up() {
    let rpm = TAU / 60.0;
    let u = UniformAngularAcceleration::new(1000.0 * rpm, 2000.0 * rpm, 15.0).unwrap();
    assert!((u.alpha() - 200.0 * PI / 90.0).abs() < 1e-13);
    assert!((u.revolutions() - 375.0).abs() < 1e-12);
    assert!(UniformAngularAcceleration::new(1.0, 2.0, 0.0).is_err());
}

/// c14-B10 (v = 10 m/s on R = 50 m: ω = 0.2 rad/s, a = 2 m/s²), c14-B6 (Earth: T = 365.25 d
/// and 86400 s), c14-B11 (equator and 60° N: a_c halves).
#[test]
fn circular_motion_cases() {
    let run = CircularMotion::from_speed(10.0, 50.0).unwrap();
    assert!((run.omega - 0.2).abs() < 1e-16 && (run.centripetal() - 2.0).abs() < 1e-15);
    assert_eq!(run.tangential(), 0.0);
    let orbit = CircularMotion::from_period(365.25 * 86_400.0, 1.496e11).unwrap();
    assert!((orbit.omega / 1.99e-7 - 1.0).abs() < 3e-3);
    let earth = CircularMotion::from_period(86_400.0, 6.378e6).unwrap();
    assert!((earth.omega / 7.27e-5 - 1.0).abs() < 3e-3);
    assert!((earth.speed() - 463.8).abs() < 0.1);
    assert!((earth.centripetal() - 0.0337).abs() < 1e-4);
    let oslo = earth.at_latitude(60f64.to_radians()).unwrap();
    assert!((oslo.centripetal() / earth.centripetal() - 0.5).abs() < 1e-15);
    assert!(earth.at_latitude(2.0).is_err());
    let spin = CircularMotion::new(0.5, 4.0)
        .unwrap()
        .with_alpha(3.0)
        .unwrap();
    assert_eq!(spin.tangential(), 1.5);
    assert!((spin.acceleration() - (8.0_f64.hypot(1.5))).abs() < 1e-15);
}

/// Rolling: v = ωR, a = αR, zero slip when rolling.
#[test]
fn rolling_condition() {
    let w = Rolling::new(0.35).unwrap();
    assert_eq!(w.speed(10.0), 3.5);
    assert_eq!(w.omega(w.speed(10.0)), 10.0);
    assert_eq!(w.acceleration(2.0), 0.7);
    assert_eq!(w.slip(3.5, 10.0), 0.0);
    assert!(Rolling::new(0.0).is_err());
}

/// v = ω × r is perpendicular to ω and r with |v| = ω × (distance from the axis); the
/// centripetal part points to the axis with size ω² ρ (to 1e-14); compared with a finite
/// difference of the rotated point to 1e-8.
#[test]
fn angular_velocity_vector_in_3d() {
    let omega = Vec3::new(0.3, -1.2, 2.0);
    let r = Vec3::new(1.0, 0.5, -0.7);
    let v = point_velocity(&omega, &r);
    assert!(v.dot(&omega).abs() < 1e-15 && v.dot(&r).abs() < 1e-15);
    let rho = distance_from_axis(&omega, &r);
    assert!((v.norm() - omega.norm() * rho).abs() < 1e-14);
    let a = point_acceleration(&Vec3::zeros(), &omega, &r);
    assert!((a.centripetal.norm() - omega.norm_squared() * rho).abs() < 1e-14);
    // rotate r by a small angle about ω and compare (r(h) − r(−h))/2h with v
    let rot = |h: f64| nalgebra::Rotation3::new(omega * h) * r;
    let h = 1e-5;
    let fd = (rot(h) - rot(-h)) / (2.0 * h);
    assert!((fd - v).norm() < 1e-8);
    let fd2 = (rot(h) - 2.0 * r + rot(-h)) / (h * h);
    assert!((fd2 - a.total()).norm() < 1e-4);
    let alpha = Vec3::new(0.0, 0.0, 1.0);
    let with_alpha = point_acceleration(&alpha, &omega, &r);
    assert_eq!(with_alpha.tangential, alpha.cross(&r));
}

/// Review C-04: θ = ∫₀ᵗ ω dt across a pole of ω diverges: refused (neither the closed form's
/// F(t) − F(0) nor a quadrature is its value), as `integrate` refuses it; before the pole it
/// is the closed form.
#[test]
fn theta_across_a_pole_of_omega_is_refused() {
    for (omega, pole) in [("1/(t-1)^2", 1.0), ("tan(t)", PI / 2.0)] {
        let m = AngularMotion::from_angular_velocity(omega, &[], 0.0).unwrap();
        let e = m.report(&[2.0]).unwrap_err();
        assert!(
            matches!(e, mechkit::rigid::kinematics::KinematicsError::Diverges { pole: p, .. } if (p - pole).abs() < 1e-9),
            "{omega}: {e}"
        );
        assert!(m.report(&[0.5]).is_ok(), "{omega}");
    }
    // a value for t itself is refused
    assert!(AngularMotion::from_angle("c*t", &set(&[("t", 1.0)])).is_err());
}

//! Rolling and slipping on an incline.
//!
//! Physics checked:
//! - a sphere with spin placed on a slope (acceptance): rolling starts at
//!   `t* = −v_c0/v̇_c`, `v̇_c = g sin α − sign(v_c0) μd g cos α (1 + k)/k`, with the speed
//!   `v0 + (g sin α + f/m) t*`; the simulation matches both to better than 1e-6 relative,
//!   and afterwards the friction is the rolling value `m g sin α k/(1 + k)` (up the slope),
//!   the acceleration `g sin α/(1 + k)`, and `v = ω R`;
//! - a ball launched along a flat floor with backspin: the angular momentum about the contact
//!   point `m R (v + k R ω)` is conserved, so it rolls at `(v0 + k R ω0)/(1 + k)`, backwards
//!   when the backspin is strong;
//! - on a slope steeper than `atan(μs (1 + k)/k)` the body never rolls: the contact point
//!   stops sliding one way and breaks away the other;
//! - the energy balance `K_trans + K_rot + U − W_friction` is constant, with the work of friction
//!   `−μd N · v_c0²/(2 |v̇_c|)` over the slip and zero while rolling;
//! - shapes give their inertia factors; a body with no radius cannot roll.

use mechkit::mass::{Shape, Vec3};
use mechkit::ode::{AdaptiveConfig, Tolerance};
use mechkit::rigid::friction::Coulomb;
use mechkit::rigid::rolling::{Contact, RollingBody, RollingError, RollingMotion};

fn config(rtol: f64) -> AdaptiveConfig {
    AdaptiveConfig {
        rtol: Tolerance::Scalar(rtol),
        atol: Tolerance::Scalar(rtol * 1e-3),
        h_max: 0.01,
        ..AdaptiveConfig::default()
    }
}

/// Sphere, 0.45 kg, R = 11 cm, on a slope with μs = 0.35, μd = 0.3.
fn sphere_on_slope(degrees: f64, v0: f64, omega0: f64) -> RollingMotion {
    RollingMotion::new(
        RollingBody::sphere(0.45, 0.11).unwrap(),
        degrees.to_radians(),
        Coulomb::new(0.35, 0.3).unwrap(),
    )
    .launched(v0, omega0)
}

/// The closed form written out independently of the library: `(t*, v*)`.
fn hand_roll_start(m: &RollingMotion) -> (f64, f64) {
    let (g, a, k, r) = (m.g, m.angle, m.body.k, m.body.radius);
    let mu = m.friction.mu_dynamic;
    let vc0 = m.v0 - m.omega0 * r;
    let s = vc0.signum();
    let rate = g * a.sin() - s * mu * g * a.cos() * (1.0 + k) / k;
    let t = -vc0 / rate;
    (t, m.v0 + (g * a.sin() - s * mu * g * a.cos()) * t)
}

#[test]
fn sphere_with_spin_on_a_slope_rolls_at_the_closed_form_time_and_speed() {
    // backspin, forward overspin (v_c < 0), placed with spin and no speed, thrown uphill
    let cases = [
        (20.0, 2.0, -30.0),
        (20.0, 0.0, -30.0),
        (20.0, 1.0, 40.0),
        (10.0, 0.0, 25.0),
        (15.0, -3.0, 0.0),
        (5.0, -1.0, 20.0),
    ];
    let mut worst: f64 = 0.0;
    for (deg, v0, w0) in cases {
        let motion = sphere_on_slope(deg, v0, w0);
        let run = motion.simulate(3.0, &config(1e-12)).unwrap();
        let (t_c, v_c) = hand_roll_start(&motion);
        let (lib_t, lib_v) = motion.roll_start().unwrap();
        assert!(
            (lib_t - t_c).abs() <= 1e-14 * t_c && (lib_v - v_c).abs() <= 1e-13 * v_c.abs().max(1.0)
        );
        let (t, _, v, omega) = run.roll_start.expect("it rolls");
        let (et, ev) = ((t - t_c).abs() / t_c, (v - v_c).abs() / v_c.abs());
        worst = worst.max(et).max(ev);
        println!(
            "α = {deg}°, v0 = {v0}, ω0 = {w0}: t* = {t} (closed {t_c}, rel {et:.1e}), v* = {v} (closed {v_c}, rel {ev:.1e})"
        );
        assert!(et < 1e-6 && ev < 1e-6);
        assert_eq!(omega * motion.body.radius, v);
        // one slip, then rolling to the end
        assert_eq!(run.phases.len(), 2);
        assert_eq!(run.phases[1].contact, Contact::Rolling);
        // rolling: the friction is the rolling value, the acceleration g sin α/(1 + k), v = ωR
        let f_roll = 0.45 * 9.81 * deg.to_radians().sin() * 0.4 / 1.4;
        assert!((run.rolling_friction.unwrap() + f_roll).abs() < 1e-15);
        let rolling: Vec<_> = run.samples.iter().filter(|s| s.rolling).collect();
        let a = 9.81 * deg.to_radians().sin() / 1.4;
        for s in &rolling {
            assert_eq!(s.friction, -f_roll);
            assert!(s.slip_velocity.abs() < 1e-12);
            assert!((s.v - (v + a * (s.t - t))).abs() < 1e-12);
        }
        assert!(rolling.len() > 100);
    }
    println!("worst relative error of t* and v*: {worst:.1e}");
    assert!(worst < 1e-12);
}

#[test]
fn located_switch_does_not_depend_on_the_tolerance() {
    // with a loose tolerance the steps are large, the switch is still inside its step
    let motion = sphere_on_slope(20.0, 2.0, -30.0);
    let (t_c, v_c) = motion.roll_start().unwrap();
    for rtol in [1e-4, 1e-8] {
        let cfg = AdaptiveConfig {
            rtol: Tolerance::Scalar(rtol),
            ..AdaptiveConfig::default()
        };
        let run = motion.simulate(3.0, &cfg).unwrap();
        let (t, _, v, _) = run.roll_start.unwrap();
        println!(
            "rtol {rtol:e}: {} steps, t* rel {:.1e}",
            run.stats.accepted,
            (t - t_c).abs() / t_c
        );
        assert!((t - t_c).abs() < 1e-9 * t_c && (v - v_c).abs() < 1e-9 * v_c);
    }
}

#[test]
fn backspin_on_a_flat_floor_conserves_angular_momentum_about_the_contact() {
    let ball = RollingBody::sphere(0.45, 0.11).unwrap();
    let c = Coulomb::new(0.4, 0.3).unwrap();
    // mild backspin: slows down, rolls forward; strong backspin: comes back
    for (v0, w0) in [(2.0, -10.0), (2.0, -30.0), (2.0, -60.0), (-1.0, 50.0)] {
        let motion = RollingMotion::new(ball, 0.0, c).launched(v0, w0);
        let run = motion.simulate(5.0, &config(1e-12)).unwrap();
        let v_f = (v0 + 0.4 * 0.11 * w0) / 1.4;
        assert_eq!(motion.flat_floor_rolling_speed(), v_f);
        let (_, _, v, _) = run.roll_start.unwrap();
        let last = run.samples.last().unwrap();
        println!("v0 = {v0}, ω0 = {w0}: rolls at {v} (closed form {v_f})");
        assert!((v - v_f).abs() < 1e-13, "{v} {v_f}");
        assert!((last.v - v_f).abs() < 1e-13);
        let l0 = v0 + 0.4 * 0.11 * w0;
        for s in &run.samples {
            assert!((s.v + 0.4 * 0.11 * s.omega - l0).abs() < 1e-13);
        }
        if w0 == -60.0 {
            assert!(v_f < 0.0 && last.x < run.samples.iter().map(|s| s.x).fold(0.0, f64::max));
        }
    }
}

#[test]
fn too_steep_to_roll_the_contact_breaks_away() {
    // tan α > μs (1 + k)/k = 0.35 · 3.5 = 1.225 at α = 55° (tan 55° = 1.43); with overspin the
    // contact point first slides back (v_c < 0), stops, and then slides forward for good
    let motion = sphere_on_slope(55.0, 0.0, 50.0);
    assert!(!motion.can_roll());
    assert!(motion.steepest_rolling_angle().to_degrees() < 55.0);
    assert_eq!(motion.roll_start(), None);
    let run = motion.simulate(2.0, &config(1e-12)).unwrap();
    assert!(run.roll_start.is_none() && run.rolling_friction.is_none());
    let regimes: Vec<_> = run.phases.iter().map(|p| p.contact).collect();
    assert_eq!(
        regimes,
        [
            Contact::Slipping { direction: -1.0 },
            Contact::Slipping { direction: 1.0 }
        ]
    );
    // the switch is where v_c = 0: t = −v_c0/v̇_c with the backward-slip rate
    let a = 55f64.to_radians();
    let rate = 9.81 * a.sin() + 0.3 * 9.81 * a.cos() * 3.5;
    let t_switch = 50.0 * 0.11 / rate;
    assert!((run.phases[0].end.0 - t_switch).abs() < 1e-12 * t_switch);
    // then the contact point slides forward at the rate g sin α − μd g cos α (1 + k)/k
    let rate2 = 9.81 * a.sin() - 0.3 * 9.81 * a.cos() * 3.5;
    let last = run.samples.last().unwrap();
    assert!((last.slip_velocity - rate2 * (2.0 - t_switch)).abs() < 1e-12);
    assert_eq!(last.friction, -0.3 * 0.45 * 9.81 * a.cos());
}

#[test]
fn energy_ledger_closes_and_friction_works_only_while_slipping() {
    for (deg, v0, w0) in [(20.0, 2.0, -30.0), (0.0, 2.0, -60.0), (30.0, 0.0, 50.0)] {
        let motion = sphere_on_slope(deg, v0, w0);
        let run = motion.simulate(3.0, &config(1e-12)).unwrap();
        let b = &run.balance;
        let e0 = b.kinetic.start;
        let (kt, kr) = (b.kinetic.parts[0].start, b.kinetic.parts[1].start);
        assert_eq!((kt, kr), motion.kinetic(v0, w0));
        let work_friction = b.work_of("friction").unwrap();
        println!(
            "α = {deg}°: W_friction = {work_friction:.9} J, residual {:.1e} J",
            b.residual()
        );
        assert!(b.residual().abs() < 1e-12 * e0.max(1.0));
        // the slip's work in closed form: −μd N ∫|v_c| dt = −μd N v_c0²/(2|v̇_c|)
        let alpha = deg.to_radians();
        let n = 0.45 * 9.81 * alpha.cos();
        let vc0 = v0 - w0 * 0.11;
        let rate = 9.81 * alpha.sin() - vc0.signum() * 0.3 * 9.81 * alpha.cos() * 3.5;
        let w_exact = -0.3 * n * vc0 * vc0 / (2.0 * rate.abs());
        assert!(
            (work_friction - w_exact).abs() < 1e-12 * w_exact.abs(),
            "{work_friction} {w_exact}"
        );
        let t_roll = run.roll_start.unwrap().0;
        let at_roll = run
            .samples
            .iter()
            .find(|s| s.t == t_roll)
            .unwrap()
            .work_friction;
        let drift = run
            .samples
            .iter()
            .filter(|s| s.rolling)
            .map(|s| (s.work_friction - at_roll).abs())
            .fold(0.0, f64::max);
        println!("  drift of W_friction while rolling: {drift:.1e} J");
        // rounding only: v − ωR is zero to the last bits of v
        assert!(drift < 1e-12);
    }
}

#[test]
fn shapes_give_their_inertia_factors_and_need_a_radius() {
    let m = 2.0;
    let cases = [
        (
            Shape::Sphere {
                radius: 0.1,
                inner_radius: 0.0,
            },
            0.4,
        ),
        (Shape::SphericalShell { radius: 0.1 }, 2.0 / 3.0),
        (
            Shape::Cylinder {
                radius: 0.1,
                inner_radius: 0.0,
                height: 0.3,
            },
            0.5,
        ),
        (
            Shape::Disk {
                radius: 0.1,
                inner_radius: 0.0,
            },
            0.5,
        ),
        (Shape::Ring { radius: 0.1 }, 1.0),
        (
            Shape::Tube {
                radius: 0.1,
                height: 2.0,
            },
            1.0,
        ),
    ];
    for (shape, k) in cases {
        let body = RollingBody::from_shape(&shape, m).unwrap();
        assert!((body.k - k).abs() < 1e-14, "{}: {}", shape.name(), body.k);
        assert_eq!(body.radius, 0.1);
    }
    assert!(matches!(
        RollingBody::from_shape(
            &Shape::Cuboid {
                size: Vec3::new(1.0, 1.0, 1.0)
            },
            m
        ),
        Err(RollingError::ShapeCannotRoll { shape: "box" })
    ));
    assert!(matches!(
        RollingBody::sphere(1.0, 0.0),
        Err(RollingError::NoRadius { .. })
    ));
    assert!(matches!(
        RollingBody::new(1.0, -0.1, 0.4),
        Err(RollingError::NoRadius { .. })
    ));
    assert!(RollingBody::new(1.0, f64::NAN, 0.4).is_err());
    assert!(matches!(
        RollingBody::new(1.0, 0.1, 0.0),
        Err(RollingError::InertiaFactor { .. })
    ));
    assert!(matches!(
        RollingBody::preset("cube", 1.0, 0.1),
        Err(RollingError::UnknownBody { .. })
    ));
    let msg = RollingBody::sphere(1.0, 0.0).unwrap_err().to_string();
    assert!(msg.contains("positive radius"), "{msg}");
}

#[test]
fn bad_motion_input_is_refused() {
    let ball = RollingBody::sphere(1.0, 0.1).unwrap();
    let c = Coulomb::single(0.3).unwrap();
    let bad_mu = RollingMotion {
        friction: Coulomb {
            mu_static: -0.1,
            mu_dynamic: 0.3,
        },
        ..RollingMotion::new(ball, 0.0, c)
    };
    assert!(matches!(bad_mu.validate(), Err(RollingError::Friction(_))));
    assert!(matches!(
        RollingMotion::new(ball, 2.0, c).validate(),
        Err(RollingError::Angle { .. })
    ));
    assert!(
        RollingMotion::new(ball, 0.1, c)
            .launched(f64::INFINITY, 0.0)
            .validate()
            .is_err()
    );
    assert!(
        RollingMotion::new(ball, 0.1, c)
            .simulate(0.0, &config(1e-9))
            .is_err()
    );
}

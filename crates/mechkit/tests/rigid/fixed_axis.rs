//! Rotation about a fixed axis: the physical pendulum's period against `2π √(I/(m g d))` and the
//! elliptic-integral value, torques as `-dU/dθ`, the Atwood machine with a massive pulley and
//! a flywheel spun up by a constant torque against their closed forms, and the energy ledger.

use std::f64::consts::PI;

use mechkit::forces::Force;
use mechkit::mass::{MassProperties, Shape, Vec3};
use mechkit::ode::{AdaptiveConfig, Method, State, Tolerance};
use mechkit::particles::{Kinematics, ParticleSystem};
use mechkit::rigid::fixed_axis::pendulum::{elliptic_k, period, small_angle_period};
use mechkit::rigid::fixed_axis::torques::{
    AttachedSpring, ConstantTorque, FrictionLaw, FrictionTorque, TorsionSpring,
};
use mechkit::rigid::fixed_axis::{FixedAxisError, HingedBody, system};
use mechkit::simulate::{Direction, Event, Simulation, Stepping, StopReason};

const G: f64 = 9.81;

/// A uniform rod of length `l` and mass `m` along z, hinged at its top end about x; gravity -z.
fn rod_pendulum(l: f64, m: f64) -> (HingedBody, ParticleSystem) {
    let rod = Shape::Rod { length: l }.with_mass(m).unwrap();
    let body = HingedBody::new("rod", &rod, Vec3::new(0.0, 0.0, l / 2.0), Vec3::x()).unwrap();
    let gravity = body.gravity("gravity", 0, Vec3::new(0.0, 0.0, -G));
    let sys = system(std::slice::from_ref(&body), vec![Box::new(gravity)]).unwrap();
    (body, sys)
}

fn dop853(rtol: f64) -> Stepping {
    Stepping::Adaptive {
        method: Method::Dop853,
        config: AdaptiveConfig {
            rtol: Tolerance::Scalar(rtol),
            atol: Tolerance::Scalar(rtol * 1e-3),
            ..AdaptiveConfig::default()
        },
    }
}

/// The period from successive upward zero crossings of `θ`, located on the dense output.
fn measured_period(sys: &ParticleSystem, theta0: f64, stepping: Stepping) -> f64 {
    let up = Event::new("up", |s, _| s.q[0]).direction(Direction::Rising);
    let r = Simulation::with_stepping(sys, stepping)
        .t_max(1e3)
        .event(up.stop_at(3))
        .run(State::from_qv(0.0, &[theta0], &[0.0]), &mut [])
        .unwrap();
    assert_eq!(r.stop_reason, StopReason::Event);
    let t: Vec<f64> = r.events.iter().map(|e| e.t).collect();
    0.5 * (t[2] - t[0])
}

/// A rod hinged at its end: I = m L²/3 about the hinge, d = L/2, so T₀ = 2π √(2L/(3g)). At an
/// amplitude of 1e-3 rad the period exceeds T₀ by θ₀²/16 = 6.3e-8 (measured 6.25e-8), well
/// inside 1e-6.
#[test]
fn physical_pendulum_small_angle_period() {
    let (body, sys) = rod_pendulum(1.2, 0.7);
    assert!((body.moment() - 0.7 * 1.44 / 3.0).abs() < 1e-15);
    let t0 = small_angle_period(&body, G).unwrap();
    assert!((t0 - 2.0 * PI * (2.0 * 1.2 / (3.0 * G)).sqrt()).abs() < 1e-14);
    let t = measured_period(&sys, 1e-3, dop853(1e-12));
    let rel = (t - t0) / t0;
    assert!(rel.abs() < 1e-6, "relative difference {rel:e}");
    assert!((rel - 1e-6 / 16.0).abs() < 2e-9, "{rel:e}");
}

/// Large amplitudes (1 to 3 rad): the simulated period equals 4 √(I/(m g d)) K(sin(θ₀/2)) to
/// 1e-8 (measured ≤ 3e-11 with DOP853 at rtol 1e-12).
#[test]
fn physical_pendulum_large_angle_period_is_elliptic() {
    let (body, sys) = rod_pendulum(0.8, 2.0);
    for theta0 in [1.0, 2.0, 2.5, 3.0] {
        let exact = period(&body, G, theta0).unwrap();
        let t = measured_period(&sys, theta0, dop853(1e-12));
        let rel = ((t - exact) / exact).abs();
        assert!(rel < 1e-8, "θ0 = {theta0}: relative error {rel:e}");
    }
    assert_eq!(period(&body, G, PI), None);
    // K grows without bound towards the top: the period at 3 rad is 2.5 times T0
    let ratio = period(&body, G, 3.0).unwrap() / small_angle_period(&body, G).unwrap();
    assert!((ratio - 2.0 / PI * elliptic_k((1.5f64).sin()).unwrap()).abs() < 1e-15);
}

/// A disk hinged at its rim: I = 3/2 M R² (parallel-axis theorem through `MassProperties`);
/// the centre of mass turns with the body; zero moment and a bad axis are errors.
#[test]
fn hinged_disk_and_errors() {
    let disk = Shape::Disk {
        radius: 0.3,
        inner_radius: 0.0,
    }
    .with_mass(2.0)
    .unwrap();
    let body = HingedBody::new("disk", &disk, Vec3::new(0.3, 0.0, 0.0), Vec3::z()).unwrap();
    assert!((body.moment() - 1.5 * 2.0 * 0.09).abs() < 1e-15);
    assert!((body.lever() - 0.3).abs() < 1e-15);
    let turned = body.offset_at(PI / 2.0);
    assert!(
        (turned - Vec3::new(0.0, -0.3, 0.0)).norm() < 1e-15,
        "{turned}"
    );
    assert!(body.pivot_warning().is_none());
    let far = HingedBody::new("disk", &disk, Vec3::new(30.0, 0.0, 0.0), Vec3::z()).unwrap();
    assert!(far.pivot_warning().unwrap().contains("radius of gyration"));
    // a rod about its own length has no moment of inertia
    let rod = Shape::Rod { length: 1.0 }.with_mass(1.0).unwrap();
    let err = HingedBody::new("rod", &rod, Vec3::zeros(), Vec3::z()).unwrap_err();
    assert!(matches!(err, FixedAxisError::ZeroMoment { .. }), "{err}");
    let point = MassProperties::point(1.0, Vec3::zeros());
    let err = HingedBody::new("p", &point, Vec3::zeros(), Vec3::x()).unwrap_err();
    assert!(err.to_string().contains("no moment of inertia"), "{err}");
    let err = HingedBody::new("disk", &disk, Vec3::zeros(), Vec3::zeros()).unwrap_err();
    assert!(matches!(err, FixedAxisError::BadAxis(..)), "{err}");
}

/// Every conservative torque is `-dU/dθ` (central differences, to 1e-7 relative), at random-ish
/// angles, for gravity on an off-axis body, a torsion spring and a spring attached at a point.
#[test]
fn torques_are_minus_the_derivative_of_their_potential() {
    let props = MassProperties::new(
        1.3,
        Vec3::new(0.2, -0.4, 0.1),
        mechkit::mass::Mat3::identity() * 0.05,
    );
    let axis = Vec3::new(0.3, 0.2, 1.0).normalize();
    let body = HingedBody::new("b", &props, Vec3::zeros(), axis).unwrap();
    let torques: Vec<Box<dyn Force>> = vec![
        Box::new(body.gravity("g", 0, Vec3::new(0.0, -G, 0.0))),
        Box::new(TorsionSpring::new("torsion", 0, 2.5, 0.3)),
        Box::new(AttachedSpring::new(
            "spring",
            0,
            40.0,
            0.25,
            Vec3::new(0.5, 0.1, 0.0),
            Vec3::new(1.0, 0.4, 0.2),
            axis,
        )),
    ];
    for f in &torques {
        for theta in [-2.0, -0.7, 0.0, 0.4, 1.9, 3.0] {
            let at = |th: f64| {
                let (x, v, m) = ([th], [0.0], [1.0]);
                let k = Kinematics {
                    t: 0.0,
                    dim: 1,
                    x: &x,
                    v: &v,
                    mass: &m,
                };
                let mut out = [0.0];
                f.add_forces(&k, &mut out);
                (out[0], f.potential(&k).unwrap())
            };
            let h = 1e-5;
            let derivative = (at(theta + h).1 - at(theta - h).1) / (2.0 * h);
            let torque = at(theta).0;
            let scale = torque.abs().max(1.0);
            assert!(
                (torque + derivative).abs() < 1e-7 * scale,
                "{}: τ = {torque}, dU/dθ = {derivative}",
                f.name()
            );
        }
    }
}

/// The Atwood machine with a massive pulley (a disk of mass M, radius R) and weights m1 > m2:
/// α = (m1 - m2) g R / (I + (m1 + m2) R²) exactly; RK4 reproduces the constant acceleration to
/// rounding, and the weights' potential energy becomes the kinetic energy of all three.
#[test]
fn atwood_machine_with_massive_pulley() {
    let (big_m, r, m1, m2) = (2.0, 0.1, 3.0, 1.0);
    let pulley = Shape::Disk {
        radius: r,
        inner_radius: 0.0,
    }
    .with_mass(big_m)
    .unwrap();
    let mut body = HingedBody::new("pulley", &pulley, Vec3::zeros(), Vec3::z()).unwrap();
    let w1 = body.hang("m1", 0, m1, r, G).unwrap();
    let w2 = body.hang("m2", 0, m2, -r, G).unwrap();
    let i = 0.5 * big_m * r * r;
    assert!((body.effective_moment() - (i + (m1 + m2) * r * r)).abs() < 1e-15);
    let sys = system(&[body], vec![Box::new(w1), Box::new(w2)]).unwrap();
    let alpha = (m1 - m2) * G * r / (i + (m1 + m2) * r * r);
    let t_end = 1.5;
    let r = Simulation::new(&sys, Method::Rk4, 0.01)
        .t_max(t_end)
        .run(State::from_qv(0.0, &[0.0], &[0.0]), &mut [])
        .unwrap();
    let theta = r.final_state.y[0];
    let omega = r.final_state.y[1];
    assert!(
        (theta - 0.5 * alpha * t_end * t_end).abs() < 1e-12,
        "{theta}"
    );
    assert!((omega - alpha * t_end).abs() < 1e-12, "{omega}");
    // linear acceleration of the weights a = α R = (m1 - m2) g / (m1 + m2 + M/2)
    assert!((alpha * 0.1 - (m1 - m2) * G / (m1 + m2 + big_m / 2.0)).abs() < 1e-14);
    let ledger = &r.ledger;
    assert!(
        ledger.work_energy_residual().abs() < 1e-10,
        "{}",
        ledger.work_energy_residual()
    );
}

/// A flywheel spun up by a constant torque against viscous bearing friction reaches
/// ω(t) = τ/b (1 - e^{-b t/I}); the work of the engine minus the heat equals ½ I ω² (ledger).
#[test]
fn flywheel_spin_up_against_viscous_friction() {
    let wheel = Shape::Cylinder {
        radius: 0.25,
        inner_radius: 0.0,
        height: 0.05,
    }
    .with_mass(20.0)
    .unwrap();
    let body = HingedBody::new("flywheel", &wheel, Vec3::zeros(), Vec3::z()).unwrap();
    let i = body.moment();
    let (tau, b) = (15.0, 0.4);
    let sys = system(
        &[body],
        vec![
            Box::new(ConstantTorque::new("engine", 0, tau)),
            Box::new(FrictionTorque::new("bearing", 0, FrictionLaw::Viscous(b))),
        ],
    )
    .unwrap();
    let r = Simulation::with_stepping(&sys, dop853(1e-11))
        .t_max(5.0)
        .run(State::from_qv(0.0, &[0.0], &[0.0]), &mut [])
        .unwrap();
    let omega = r.final_state.y[1];
    let exact = tau / b * (1.0 - (-b * 5.0 / i).exp());
    assert!((omega - exact).abs() < 1e-9 * exact, "{omega} vs {exact}");
    let work = &r.ledger;
    assert!(
        work.work_energy_residual().abs() < 1e-8,
        "{}",
        work.work_energy_residual()
    );
}

/// Coulomb friction in the bearing stops a spinning wheel at t = I ω₀/τ₀ (event on ω = 0,
/// located to 1e-12 with fixed RK4 steps because ω is linear in t).
#[test]
fn coulomb_bearing_stops_the_wheel_at_the_closed_form_time() {
    let body = HingedBody::from_moment("wheel", 5.0, 0.4, Vec3::zeros(), Vec3::z()).unwrap();
    let sys = system(
        &[body],
        vec![Box::new(FrictionTorque::new(
            "bearing",
            0,
            FrictionLaw::Coulomb {
                torque: 0.3,
                direction: 1.0,
            },
        ))],
    )
    .unwrap();
    let stop = Event::new("stopped", |s, _| s.v[0])
        .direction(Direction::Falling)
        .stop();
    let r = Simulation::new(&sys, Method::Rk4, 0.01)
        .t_max(100.0)
        .event(stop)
        .run(State::from_qv(0.0, &[0.0], &[12.0]), &mut [])
        .unwrap();
    let t_stop = 0.4 * 12.0 / 0.3;
    assert!(
        (r.final_state.t - t_stop).abs() < 1e-12,
        "{}",
        r.final_state.t
    );
    // turned through ω₀ t/2
    assert!((r.final_state.y[0] - 6.0 * t_stop).abs() < 1e-10);
}

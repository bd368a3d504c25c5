//! The energy ledger: the work of each force, integrated as power along the computed path,
//! must satisfy the work-energy theorem `Σ W = ΔK` up to the discretisation error (which must
//! shrink with the step), equal `-ΔU` for conservative forces, and for drag equal the change
//! of mechanical energy `ΔE`.

use mechkit::prelude::*;

use crate::util::order;

fn spring_and_gravity() -> ParticleSystem {
    ParticleSystem::builder(1)
        .body("block", 0.5)
        .force(UniformGravity::new("gravity", vec![0], 9.81))
        .force(Spring::new(
            "spring",
            20.0,
            0.3,
            SpringEnds::Anchor {
                bodies: vec![0],
                anchor: vec![0.0],
            },
        ))
        .build()
        .unwrap()
}

fn residual(sys: &ParticleSystem, method: Method, dt: f64) -> f64 {
    let report = Simulation::new(sys, method, dt)
        .t_max(2.0)
        .run(State::from_qv(0.0, &[-0.3], &[0.0]), &mut [])
        .unwrap();
    report.ledger.work_energy_residual()
}

#[test]
fn residual_vanishes_as_the_step_shrinks() {
    let sys = spring_and_gravity();
    let hs = [4e-3, 2e-3, 1e-3, 5e-4];
    // energy scale: m g times the size of the motion
    let scale = 0.5 * 9.81 * 0.5;
    // trapezoids on the power are second order; Euler-Cromer's own first-order error shows
    for (method, p_min, rel) in [
        (Method::Rk4, 1.85, 1e-6),
        (Method::VelocityVerlet, 1.85, 1e-5),
        (Method::EulerCromer, 0.85, 1e-2),
    ] {
        let r: Vec<f64> = hs
            .iter()
            .map(|&h| residual(&sys, method, h).abs())
            .collect();
        let p = order(&hs, &r);
        assert!(p > p_min, "{method}: residual order {p}, residuals {r:?}");
        assert!(r[3] < rel * scale, "{method}: residual {} too large", r[3]);
    }
}

#[test]
fn conservative_work_equals_minus_delta_u() {
    let sys = spring_and_gravity();
    let report = Simulation::new(&sys, Method::Rk4, 1e-3)
        .t_max(0.7)
        .run(State::from_qv(0.0, &[-0.3], &[0.0]), &mut [])
        .unwrap();
    let l = &report.ledger;
    for (i, name) in l.names().iter().enumerate() {
        let w = l.work()[i];
        let du = l.potential_change(i).unwrap();
        // the path integral of the power has an O(h²) quadrature error
        assert!(
            (w + du).abs() < 1e-5 * w.abs(),
            "{name}: W = {w}, ΔU = {du}"
        );
    }
    // RK4 keeps E to ~1e-10 here
    assert!(l.energy_change().abs() < 1e-8);
}

#[test]
fn drag_work_is_negative_and_equals_the_energy_change() {
    let (m, d) = (0.145, 9.0e-4);
    let sys = ParticleSystem::builder(2)
        .body("ball", m)
        .force(UniformGravity::new("gravity", vec![0], 9.81))
        .force(QuadraticDrag::new("air", vec![Target::new(0, d)]))
        .build()
        .unwrap();
    let report = Simulation::new(&sys, Method::Rk4, 1e-3)
        .t_max(4.0)
        .run(State::from_qv(0.0, &[0.0, 0.0], &[30.0, 20.0]), &mut [])
        .unwrap();
    let l = &report.ledger;
    let w_air = l.work_of("air").unwrap();
    assert!(w_air < 0.0);
    let de = l.energy_change();
    assert!(
        (w_air - de).abs() < 1e-6 * w_air.abs(),
        "W_air = {w_air}, ΔE = {de}"
    );
    assert_eq!(l.non_conservative_work(), w_air);
}

#[test]
fn constant_force_work_is_force_times_distance() {
    let sys = ParticleSystem::builder(1)
        .body("cart", 10.0)
        .force(ConstantForce::new("pull", vec![0], &[90.0]))
        .force(ConstantForce::new("friction", vec![0], &[-30.0]))
        .build()
        .unwrap();
    let report = Simulation::new(&sys, Method::Rk4, 1e-3)
        .t_max(100.0)
        .stop_when(Condition::above(0, 0, 10.0))
        .run(State::from_qv(0.0, &[0.0], &[0.0]), &mut [])
        .unwrap();
    let l = &report.ledger;
    // the event is located to rounding, and power is linear in t, so trapezoids are exact
    assert!((l.work_of("pull").unwrap() - 900.0).abs() < 1e-9);
    assert!((l.work_of("friction").unwrap() + 300.0).abs() < 1e-9);
    assert!(l.work_energy_residual().abs() < 1e-9);
}

#[test]
fn energy_drift_per_method_on_a_kepler_orbit() {
    // GM = 4π² AU³/yr² in units of AU and years: e = 0.5, one orbit per year
    let gm = 4.0 * std::f64::consts::PI.powi(2);
    let sys = ParticleSystem::builder(2)
        .body("planet", 1.0)
        .force(NewtonianGravity::fixed_centre(
            "sun",
            vec![0],
            gm,
            vec![0.0, 0.0],
        ))
        .build()
        .unwrap();
    let vp = (gm * 1.5 / 0.5).sqrt();
    let drift = |method| {
        let r = Simulation::new(&sys, method, 1e-3)
            .t_max(10.0)
            .run(State::from_qv(0.0, &[0.5, 0.0], &[0.0, vp]), &mut [])
            .unwrap();
        let (e0, _) = r.ledger.energy();
        r.ledger.energy_change() / e0.abs()
    };
    let (euler, ec, vv, rk4) = (
        drift(Method::Euler),
        drift(Method::EulerCromer),
        drift(Method::VelocityVerlet),
        drift(Method::Rk4),
    );
    // Euler gains energy steadily; the symplectic methods and RK4 stay close
    assert!(euler > 0.1, "Euler relative drift {euler}");
    assert!(ec.abs() < 1e-2, "Euler-Cromer relative drift {ec}");
    assert!(vv.abs() < 1e-4, "Verlet relative drift {vv}");
    assert!(rk4.abs() < 1e-5, "RK4 relative drift {rk4}");
}

/// The ledger's balance: `Δ(K + U) = W_air` for a ball with drag, gravity listed as a
/// conservative force with its potential as a named part.
#[test]
fn the_balance_of_a_run_books_drag_as_non_conservative_work() {
    let (m, d) = (0.145, 9.0e-4);
    let sys = ParticleSystem::builder(2)
        .body("ball", m)
        .force(UniformGravity::new("gravity", vec![0], 9.81))
        .force(QuadraticDrag::new("air", vec![Target::new(0, d)]))
        .build()
        .unwrap();
    let report = Simulation::new(&sys, Method::Rk4, 1e-3)
        .t_max(4.0)
        .run(State::from_qv(0.0, &[0.0, 0.0], &[30.0, 20.0]), &mut [])
        .unwrap();
    let l = &report.ledger;
    let b = l.balance();
    assert_eq!(b.kinetic.start, l.kinetic_start());
    assert_eq!(b.kinetic.end, l.kinetic_end());
    let u = b.potential.as_ref().expect("gravity has a potential");
    assert_eq!(
        (Some(u.start), Some(u.end)),
        (l.potential_start(), l.potential_end())
    );
    assert_eq!(u.parts.len(), 1);
    assert_eq!(u.parts[0].name, "gravity");
    let names: Vec<(&str, bool)> = b
        .work
        .iter()
        .map(|w| (w.name.as_str(), w.conservative))
        .collect();
    assert_eq!(names, [("gravity", true), ("air", false)]);
    assert_eq!(b.work_of("air"), l.work_of("air"));
    assert_eq!(b.non_conservative_work(), l.work_of("air").unwrap());
    assert_eq!(b.events, 0.0);
    let w_air = l.work_of("air").unwrap();
    assert!(
        b.residual().abs() < 1e-6 * w_air.abs(),
        "residual {} of W_air = {w_air}",
        b.residual()
    );
}

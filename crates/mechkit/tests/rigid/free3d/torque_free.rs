//! Torque-free bodies: the racket's flip period, |L| and E over long runs, axisymmetric
//! precession, steady principal rotations, renormalisation, fixed-step orders.

use std::f64::consts::PI;
use std::time::Instant;

use mechkit::mass::Vec3;
use mechkit::ode::Tableau;
use mechkit::rigid::free3d::{
    Formulation, FreeBody, Poinsot, SpinIntegrator, SpinOptions, SpinningBody,
};
use nalgebra::UnitQuaternion;

use super::{adaptive, options, racket, start};

/// Acceptance: the flip period of a racket spun about its intermediate axis, from the zeros of
/// ω₂ located inside the DOP853 steps, against `4K(m)/λ` (m = 1 − 2.0e-4, T = 39.1057 s).
/// Measured relative differences 2.0e-5, 1.7e-6, 1.6e-7, 1.4e-8, 1.0e-9, 7.9e-11 at rtol 1e-8
/// … 1e-13: the error falls with the tolerance (the reference is right), amplified ~10³ by the
/// nearness of the separatrix (the period is ½ ln(1/(1 − m))-sensitive to E and L²). The
/// sampled ω(t) is within 1.3e-5 (rtol 1e-10) and 6.3e-9 rad/s (1e-13) of the elliptic ω(t).
#[test]
fn racket_flip_period_matches_the_elliptic_reference() {
    let body = racket();
    let a = start(&body, [0.01, 1.0, 0.01]);
    let reference = Poinsot::new([1.0, 2.0, 3.0], Vec3::new(0.01, 1.0, 0.01)).unwrap();
    let period = reference.period();
    println!(
        "T = 4K(m)/λ = {period} s, m = 1 − {:e}",
        reference.complementary_parameter()
    );
    for (rtol, bound, omega_bound) in [(1e-10, 1e-6, 1e-4), (1e-13, 1e-9, 1e-7)] {
        let opts = options(adaptive(Tableau::dop853(), rtol), Formulation::World, 2000);
        let run = body.simulate(&a, 4.0 * period, &opts).unwrap();
        assert_eq!(run.crossings.len(), 8);
        // the crossings alternate in direction
        assert!(run.crossings.windows(2).all(|w| w[0].rising != w[1].rising));
        let measured = run.crossing_period().unwrap();
        let rel = (measured - period).abs() / period;
        let omega_err = run
            .samples
            .iter()
            .map(|s| (s.omega_body - reference.omega(s.t)).norm())
            .fold(0.0, f64::max);
        println!(
            "rtol {rtol:e}: T = {measured}, relative difference {rel:e}; max |ω − ω_exact| = {omega_err:e}; {} steps",
            run.steps
        );
        assert!(rel < bound, "{rel:e}");
        assert!(omega_err < omega_bound, "{omega_err:e}");
    }
}

/// Acceptance: |L| over 10⁴ rotations (t = 10⁴ · 2π/|ω|) with the adaptive method. With `L` in
/// the world frame it is constant bit for bit (every stage adds `h · 0`), whatever the
/// tolerance; measured at rtol 1e-7 (119 050 steps, about 6 s in a debug build): |L| to
/// 2.9e-16 (the rounding of |L| itself), while the energy, which depends on the integrated
/// orientation, drifts by 3.1e-5.
#[test]
fn l_norm_is_kept_to_1e_10_over_ten_thousand_rotations() {
    let body = racket();
    let a = start(&body, [0.3, 0.2, 1.0]);
    let t_end = 1e4 * 2.0 * PI / body.omega_body(&a).norm();
    let clock = Instant::now();
    let opts = options(adaptive(Tableau::dop853(), 1e-7), Formulation::World, 100);
    let run = body.simulate(&a, t_end, &opts).unwrap();
    let c = run.conservation;
    println!(
        "10⁴ rotations, world frame, rtol 1e-7: |L| to {:e}, E to {:e}, |q| − 1 up to {:e} before renormalising; {} steps, {} evaluations, {:.2} s",
        c.l_norm,
        c.energy,
        c.quaternion_norm,
        run.steps,
        run.evaluations,
        clock.elapsed().as_secs_f64()
    );
    assert!(c.l_norm < 1e-10, "{:e}", c.l_norm);
    assert_eq!(run.end.l, a.l, "L_world is constant to the bit");
    assert!(c.energy < 1e-4, "{:e}", c.energy);
}

/// Euler's equations in the body frame keep |L| only as well as the integrator: over 10³
/// rotations DOP853 keeps |L| to 4.6e-14 and E to 3.2e-14 at rtol 1e-13 (measured), and the
/// world-frame formulation keeps E to 1.1e-12 at the same tolerance.
#[test]
fn eulers_equations_keep_l_and_energy_to_tight_tolerance() {
    let body = racket();
    let a = start(&body, [0.3, 0.2, 1.0]);
    let t_end = 1e3 * 2.0 * PI / body.omega_body(&a).norm();
    for (formulation, l_bound, e_bound) in [
        (Formulation::Body, 1e-11, 1e-11),
        (Formulation::World, 1e-15, 1e-10),
    ] {
        let opts = options(adaptive(Tableau::dop853(), 1e-13), formulation, 10);
        let run = body.simulate(&a, t_end, &opts).unwrap();
        let c = run.conservation;
        println!(
            "10³ rotations, {} frame, rtol 1e-13: |L| to {:e}, E to {:e}; {} steps",
            formulation.name(),
            c.l_norm,
            c.energy,
            run.steps
        );
        assert!(c.l_norm < l_bound, "{:e}", c.l_norm);
        assert!(c.energy < e_bound, "{:e}", c.energy);
    }
}

/// An axisymmetric body (I₁ = I₂): ω⊥ turns about the symmetry axis at
/// `Ω = (I₃ − I₁)ω₃/I₁` in the body frame, ω₃ constant. Measured: 1.6e-12 rad/s at rtol 1e-12.
#[test]
fn axisymmetric_body_precesses_in_the_body_frame_at_the_exact_rate() {
    let body = SpinningBody::free(FreeBody::new([2.0, 2.0, 3.0], 1.0).unwrap());
    let (a0, w3) = (0.1, 5.0);
    let a = start(&body, [a0, 0.0, w3]);
    let rate = (3.0 - 2.0) * w3 / 2.0;
    let opts = options(adaptive(Tableau::dop853(), 1e-12), Formulation::World, 500);
    let run = body.simulate(&a, 20.0, &opts).unwrap();
    let err = run
        .samples
        .iter()
        .map(|s| {
            let exact = Vec3::new(a0 * (rate * s.t).cos(), a0 * (rate * s.t).sin(), w3);
            (s.omega_body - exact).norm()
        })
        .fold(0.0, f64::max);
    println!("axisymmetric: max |ω − ω_exact| = {err:e}");
    assert!(err < 1e-10, "{err:e}");
}

/// Rotation about any principal axis (even the unstable intermediate one, started exactly)
/// stays steady: ω constant, the orientation a rotation by ωt about that axis, no flips.
#[test]
fn rotation_about_a_principal_axis_is_steady() {
    let body = racket();
    for axis in 0..3 {
        let mut w = [0.0; 3];
        w[axis] = 2.0;
        let run = body
            .simulate(&start(&body, w), 30.0, &SpinOptions::default())
            .unwrap();
        let drift = run
            .samples
            .iter()
            .map(|s| (s.omega_body - Vec3::from(w)).norm())
            .fold(0.0, f64::max);
        let exact = UnitQuaternion::from_scaled_axis(Vec3::from(w) * 30.0);
        let angle = run.end.q.angle_to(&exact);
        println!(
            "axis {}: |Δω| ≤ {drift:e}, orientation off by {angle:e} rad",
            axis + 1
        );
        assert!(drift < 1e-12, "{drift:e}");
        assert!(angle < 1e-8, "{angle:e}");
        assert!(run.crossings.is_empty());
    }
}

/// The zeros of ω₂ are proven in every step when ω₂ stays at or near zero: a sphere (three
/// equal moments, ω constant), a spin about the smallest or largest axis, and one a billionth
/// off it, with L in either frame, adaptive and fixed steps. ω₂ bounded through interval arithmetic
/// on the state's enclosures is as wide as the quaternion's swing over a piece of the step,
/// so the proof ran out of enclosures (2,000) in every step, silently sampling ω₂ instead:
/// `spin --moments "2, 2, 2" --omega "5.01, 0, 5.01" --t-max 80` took 12 s in a release
/// build (a fuzz finding). As one polynomial of the step it cancels to rounding (10 ms).
#[test]
fn a_steady_spin_is_proven_in_every_step() {
    let sphere = SpinningBody::free(FreeBody::new([2.0, 2.0, 2.0], 1.0).unwrap());
    let racket = racket();
    let integrators = [
        ("dop853", adaptive(Tableau::dop853(), 1e-10)),
        ("dopri5", adaptive(Tableau::dopri5(), 1e-8)),
        (
            "rk4",
            SpinIntegrator::Fixed {
                tableau: Tableau::rk4(),
                dt: 1e-2,
            },
        ),
    ];
    for (body, w, zeros) in [
        (&sphere, [5.01, 0.0, 5.01], false),
        (&sphere, [5.01, 0.0, 0.01], false),
        (&racket, [5.0, 0.0, 0.0], false),
        (&racket, [0.0, 0.0, 5.0], false),
        (&racket, [5.0, 1e-9, 0.0], true),
    ] {
        for (name, integrator) in &integrators {
            for formulation in [Formulation::World, Formulation::Body] {
                let opts = options(integrator.clone(), formulation, 100);
                let run = body.simulate(&start(body, w), 20.0, &opts).unwrap();
                let case = format!("{w:?} {name} {formulation:?}");
                assert_eq!(run.unproven_steps, 0, "{case}: {} steps", run.steps);
                if zeros {
                    // ω₂ oscillates a billionth about zero with the elliptic period
                    let moments = [1.0, 2.0, 3.0];
                    let period = Poinsot::new(moments, Vec3::from(w)).unwrap().period();
                    let expected = 2.0 * 20.0 / period;
                    let n = run.crossings.len() as f64;
                    assert!((n - expected).abs() <= 1.0, "{case}: {n} zeros, {expected}");
                } else {
                    assert!(run.crossings.is_empty(), "{case}: {:?}", run.crossings);
                }
            }
        }
    }
}

/// Renormalising the quaternion does not bias the energy: `dq/dt` is homogeneous of degree 1
/// in `q` and every observable depends on `q/|q|`, so a fixed-step Runge-Kutta step commutes
/// with scaling `q` and RK4 gives the same energy error with and without it (measured: 2.1e-9
/// both, differing by 1.4e-16, while |q| drifts by 3.0e-10 without). With DOP853 the energy
/// errors agree to 2e-4 of themselves (4.1e-9 at rtol 1e-8, 2.5e-12 at 1e-11).
#[test]
fn renormalising_the_quaternion_does_not_bias_the_energy() {
    let body = racket();
    let a = start(&body, [0.3, 0.2, 1.0]);
    for formulation in [Formulation::World, Formulation::Body] {
        let run = |integrator: SpinIntegrator, renormalise: bool| {
            let opts = SpinOptions {
                renormalise,
                ..options(integrator, formulation, 10)
            };
            body.simulate(&a, 100.0, &opts).unwrap().conservation
        };
        let rk4 = || SpinIntegrator::Fixed {
            tableau: Tableau::rk4(),
            dt: 0.02,
        };
        let (with, without) = (run(rk4(), true), run(rk4(), false));
        println!(
            "{} frame, RK4 dt = 0.02: energy error {:e} with, {:e} without renormalising (|q| − 1 up to {:e} without)",
            formulation.name(),
            with.energy,
            without.energy,
            without.quaternion_norm
        );
        assert!(without.quaternion_norm > 1e-11);
        assert!((with.energy - without.energy).abs() < 1e-6 * with.energy);
        let mut errors = Vec::new();
        for rtol in [1e-8, 1e-11] {
            let (w, wo) = (
                run(adaptive(Tableau::dop853(), rtol), true),
                run(adaptive(Tableau::dop853(), rtol), false),
            );
            println!(
                "{} frame, DOP853 rtol {rtol:e}: energy error {:e} with, {:e} without",
                formulation.name(),
                w.energy,
                wo.energy
            );
            assert!((w.energy / wo.energy).ln().abs() < 1.0, "{w:?} {wo:?}");
            errors.push(w.energy);
        }
        assert!(errors[1] < 1e-2 * errors[0], "{errors:?}");
    }
}

/// |q| stays 1: to rounding at every step end with renormalisation, and with the splitting
/// (a product of rotations) even without it.
#[test]
fn quaternion_norm_stays_one() {
    let body = racket();
    let a = start(&body, [0.3, 0.2, 1.0]);
    let run = body.simulate(&a, 200.0, &SpinOptions::default()).unwrap();
    let n = run.end.q.quaternion().norm();
    assert!((n - 1.0).abs() < 1e-15, "{n}");
    let opts = SpinOptions {
        renormalise: false,
        ..options(
            SpinIntegrator::Splitting { dt: 0.01 },
            Formulation::World,
            10,
        )
    };
    let split = body.simulate(&a, 200.0, &opts).unwrap();
    println!(
        "splitting, 20 000 steps: ||q| − 1| ≤ {:e}",
        split.conservation.quaternion_norm
    );
    assert!(split.conservation.quaternion_norm < 1e-13);
}

/// Fixed steps converge at their order against the elliptic ω(t) at t = 10: RK4 at 4
/// (observed orders 3.997, 3.999), the splitting at 2 (1.99994, 1.99999), which keeps |L| to
/// rounding (1.1e-14 after 4000 steps) and an energy error that stays bounded instead of
/// drifting (2.784263e-6 over 100 s and 2.784264e-6 over 1000 s at dt = 0.05).
#[test]
fn fixed_steps_converge_at_their_order() {
    let body = racket();
    let w0 = Vec3::new(0.3, 0.2, 1.0);
    let a = start(&body, w0.into());
    let exact = Poinsot::new([1.0, 2.0, 3.0], w0).unwrap().omega(10.0);
    for (name, order, dts) in [
        ("rk4", 4.0, [0.02, 0.01, 0.005]),
        ("splitting", 2.0, [0.01, 0.005, 0.0025]),
    ] {
        let errors: Vec<f64> = dts
            .iter()
            .map(|&dt| {
                let integrator = if name == "rk4" {
                    SpinIntegrator::Fixed {
                        tableau: Tableau::rk4(),
                        dt,
                    }
                } else {
                    SpinIntegrator::Splitting { dt }
                };
                let run = body
                    .simulate(&a, 10.0, &options(integrator, Formulation::World, 1))
                    .unwrap();
                if name == "splitting" {
                    assert!(
                        run.conservation.l_norm < 1e-13,
                        "{:e}",
                        run.conservation.l_norm
                    );
                }
                (run.samples.last().unwrap().omega_body - exact).norm()
            })
            .collect();
        let orders: Vec<f64> = errors.windows(2).map(|e| (e[0] / e[1]).log2()).collect();
        println!("{name}: errors {errors:?}, observed orders {orders:?}");
        for p in orders {
            assert!((p - order).abs() < 0.2, "{name}: {p}");
        }
    }
    // the splitting's energy error is bounded: the same over 100 and 1000 time units
    let energy = |t_end: f64| {
        body.simulate(
            &a,
            t_end,
            &options(
                SpinIntegrator::Splitting { dt: 0.05 },
                Formulation::World,
                1,
            ),
        )
        .unwrap()
        .conservation
        .energy
    };
    let (short, long) = (energy(100.0), energy(1000.0));
    println!("splitting dt = 0.05: energy error {short:e} over 100 s, {long:e} over 1000 s");
    assert!(long < 1.5 * short, "{short:e} {long:e}");
}

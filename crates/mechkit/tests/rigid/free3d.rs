//! Free rigid bodies in 3-D: a torque-free body keeps `L` (world frame) and its kinetic energy;
//! its body-frame ω(t) is the Euler-Poinsot solution in Jacobi's elliptic functions, whose
//! period `4K(m)/λ` is the tennis racket's flip period; an axisymmetric body's ω⊥ turns at
//! `Ω = (I₃ − I₁)ω₃/I₁` in the body; rotation about a principal axis is steady. A heavy
//! symmetric top keeps `E`, `L_z` and `L₃`, precesses steadily at the root of
//! `J₁ cos θ Ω² − J₃ ω₃ Ω + m g ℓ = 0`, and a fast top at about `m g ℓ/(J₃ ω₃)`.

use std::f64::consts::PI;
use std::time::Instant;

use mechkit::mass::{MassProperties, Mat3, Vec3};
use mechkit::ode::{AdaptiveConfig, Tableau, Tolerance};
use mechkit::rigid::free3d::{
    Attitude, Formulation, Free3dError, FreeBody, Poinsot, SpinIntegrator, SpinOptions,
    SpinningBody, complete_k, incomplete_f, jacobi,
};
use nalgebra::{UnitQuaternion, Vector3};

fn racket() -> SpinningBody {
    SpinningBody::free(FreeBody::new([1.0, 2.0, 3.0], 1.0).unwrap())
}

fn start(body: &SpinningBody, omega: [f64; 3]) -> Attitude {
    body.attitude(UnitQuaternion::identity(), Vec3::from(omega))
        .unwrap()
}

fn options(integrator: SpinIntegrator, formulation: Formulation, samples: usize) -> SpinOptions {
    SpinOptions {
        integrator,
        formulation,
        renormalise: true,
        samples,
    }
}

fn adaptive(tableau: Tableau, rtol: f64) -> SpinIntegrator {
    SpinIntegrator::Adaptive {
        tableau,
        config: AdaptiveConfig {
            rtol: Tolerance::Scalar(rtol),
            atol: Tolerance::Scalar(rtol * 1e-3),
            ..AdaptiveConfig::default()
        },
    }
}

#[test]
#[allow(clippy::excessive_precision)] // the digits mpmath printed
fn complete_k_by_agm_matches_mpmath_to_2e_16() {
    // mpmath.ellipk at 25 digits
    let cases = [
        (0.0, std::f64::consts::FRAC_PI_2),
        (0.1, 1.612_441_348_720_219_4),
        (0.5, 1.854_074_677_301_371_9),
        (0.9, 2.578_092_113_348_173_3),
        (0.99, 3.695_637_362_989_874_2),
        (0.999_999, 8.294_051_463_601_062),
    ];
    for (m, k) in cases {
        let rel = (complete_k(m) - k).abs() / k;
        assert!(rel < 4e-16, "K({m}): {} vs {k}, {rel:e}", complete_k(m));
    }
    // near m = 1 through the complement: K ≈ ln(4/√m₁)
    let k = mechkit::rigid::free3d::complete_k_complement(1e-12);
    assert!((k - 15.201_804_919_087_715).abs() < 1e-13, "{k}");
}

#[test]
#[allow(clippy::excessive_precision)] // the digits mpmath printed
fn jacobi_functions_and_their_inverse_match_mpmath() {
    let cases = [
        (0.7, 0.8, 0.612_365_484_117_245_3, 0.790_574_799_662_784_5),
        (3.0, 0.3, 0.411_422_660_634_000_65, -0.911_444_674_303_843_8),
        (
            10.0,
            0.999,
            -0.307_462_292_454_822_26,
            -0.951_560_265_415_924_9,
        ),
        (
            -1.3,
            0.5,
            -0.920_446_474_210_017_8,
            0.390_868_632_809_473_46,
        ),
    ];
    for (u, m, sn, cn) in cases {
        let (s, c, d) = jacobi(u, m);
        assert!(
            (s - sn).abs() < 1e-14 && (c - cn).abs() < 1e-14,
            "{u} {m}: {s} {c}"
        );
        assert!((d * d - (1.0 - m * sn * sn)).abs() < 1e-14);
    }
    for (phi, m, f) in [
        (1.2, 0.6, 1.381_322_687_881_858_2),
        (0.3, 0.99, 0.304_556_009_344_368_2),
        (2.5, 0.5, 3.044_408_477_487_261_3),
        (-4.0, 0.7, -5.088_975_077_596_994),
    ] {
        assert!((incomplete_f(phi, m) - f).abs() < 2e-14, "F({phi}|{m})");
    }
}

/// Euler's equations `I₁ω̇₁ = (I₂ − I₃)ω₂ω₃` (and cyclic), by central differences of the
/// elliptic solution.
fn euler_residual(moments: [f64; 3], p: &Poinsot, t: f64) -> f64 {
    let h = 1e-5;
    let dw = (p.omega(t + h) - p.omega(t - h)) / (2.0 * h);
    let w = p.omega(t);
    let i = moments;
    (0..3)
        .map(|k| {
            let (a, b) = ((k + 1) % 3, (k + 2) % 3);
            (i[k] * dw[k] - (i[a] - i[b]) * w[a] * w[b]).abs()
        })
        .fold(0.0, f64::max)
}

#[test]
fn poinsot_solution_solves_eulers_equations_in_both_regimes_and_any_axis_order() {
    for moments in [
        [1.0, 2.0, 3.0],
        [3.0, 1.0, 2.0],
        [2.0, 3.0, 1.0],
        [2.0, 1.0, 3.0],
    ] {
        for omega in [[0.3, 1.0, 0.2], [1.0, 0.4, 0.1], [0.1, 0.4, 1.0]] {
            let p = Poinsot::new(moments, Vec3::from(omega)).unwrap();
            assert!((p.omega(0.0) - Vec3::from(omega)).norm() < 1e-13);
            for t in [0.3, 1.7, 5.0, 23.0] {
                let r = euler_residual(moments, &p, t);
                assert!(r < 1e-8, "{moments:?} {omega:?} t = {t}: residual {r:e}");
            }
            let back = p.omega(p.period());
            assert!((back - Vec3::from(omega)).norm() < 1e-11, "periodic");
        }
    }
    // steady rotations and the separatrix have no period
    assert!(Poinsot::new([1.0, 2.0, 3.0], Vec3::new(0.0, 0.0, 1.0)).is_none());
    assert!(Poinsot::new([1.0, 2.0, 3.0], Vec3::new(0.0, 1.0, 0.0)).is_none());
    assert!(Poinsot::new([2.0, 2.0, 2.0], Vec3::new(0.3, 1.0, 0.0)).is_none());
}

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
/// tolerance; measured at rtol 1e-7 (about 7 s in a debug build): the energy, which depends
/// on the integrated orientation, drifts by 2.8e-5.
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
/// rotations DOP853 keeps |L| to 1.5e-13 and E to 3.5e-13 at rtol 1e-13 (measured), and the
/// world-frame formulation keeps E to 1.9e-12 at the same tolerance.
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
/// `Ω = (I₃ − I₁)ω₃/I₁` in the body frame, ω₃ constant. Measured: 4.6e-12 rad/s at rtol 1e-12.
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

/// Renormalising the quaternion does not bias the energy: `dq/dt` is homogeneous of degree 1
/// in `q` and every observable depends on `q/|q|`, so a fixed-step Runge-Kutta step commutes
/// with scaling `q` and RK4 gives the same energy error with and without it (measured: the two
/// differ by 2e-16 while the error is 1.0e-8 and |q| drifts by 1e-9 without). With DOP853 the
/// energy errors agree within a factor 1.1, and both scale with the tolerance.
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
/// (measured error ratios 16.0 per halving), the splitting at 2 (4.0), which keeps |L| to
/// rounding (2e-16) and an energy error that stays bounded instead of drifting.
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

/// A symmetric top: m = 0.5 kg, I₁ = I₂ = 3e-3, I₃ = 4e-3 kg·m² about the CM, ℓ = 5 cm.
fn top() -> SpinningBody {
    let body = FreeBody::new([3e-3, 3e-3, 4e-3], 0.5).unwrap();
    SpinningBody::on_pivot(body, Vec3::new(0.0, 0.0, 0.05), 9.81).unwrap()
}

/// Released tilted and spinning, the heavy top nutates; E, L_z and L₃ are conserved
/// (measured 1.4e-12, 4.9e-13, 1.1e-13 relative at rtol 1e-12) while |L| is not.
#[test]
fn heavy_top_keeps_energy_lz_and_l3() {
    let top = top();
    let a = top.tilted(0.5, 50.0, 0.0);
    let opts = options(adaptive(Tableau::dop853(), 1e-12), Formulation::World, 400);
    let run = top.simulate(&a, 10.0, &opts).unwrap();
    let c = run.conservation;
    println!(
        "heavy top: E to {:e}, L_z to {:e}, L_3 to {:e}; |L| changes by {:e}",
        c.energy, c.l_z, c.l_3, c.l_norm
    );
    assert!(c.energy < 1e-10 && c.l_z < 1e-10 && c.l_3 < 1e-10, "{c:?}");
    assert!(c.l_norm > 1e-4, "gravity's torque changes |L|");
    // the body-frame formulation agrees
    let body = top
        .simulate(
            &a,
            10.0,
            &options(adaptive(Tableau::dop853(), 1e-12), Formulation::Body, 400),
        )
        .unwrap();
    let diff = (body.end.l - run.end.l).norm() / a.l.norm();
    assert!(diff < 1e-8, "{diff:e}");
}

/// Started at the slow root of `J₁ cos θ Ω² − J₃ ω₃ Ω + m g ℓ = 0`, the top precesses steadily:
/// θ stays at 30° (measured within 2.6e-11 rad) and the mean precession rate is Ω (measured
/// 2.3e-11 relative).
#[test]
fn heavy_top_precesses_steadily_at_the_root_of_the_quadratic() {
    let top = top();
    let (theta, spin) = (PI / 6.0, 50.0);
    let (slow, fast) = top.steady_precession(theta, spin).unwrap();
    let a = top.tilted(theta, spin, slow);
    let t_end = 2.0 * 2.0 * PI / slow;
    let opts = options(adaptive(Tableau::dop853(), 1e-12), Formulation::World, 1000);
    let run = top.simulate(&a, t_end, &opts).unwrap();
    let nutation = run
        .samples
        .iter()
        .map(|s| (s.attitude.euler_angles().1 - theta).abs())
        .fold(0.0, f64::max);
    let (first, last) = (run.samples[0], run.samples[run.samples.len() - 1]);
    let rate = (last.precession - first.precession) / (last.t - first.t);
    let rel = (rate - slow).abs() / slow;
    println!(
        "steady precession Ω = {slow} rad/s (fast root {fast}): |θ − 30°| ≤ {nutation:e} rad, mean rate {rate} ({rel:e})"
    );
    assert!(nutation < 1e-9, "{nutation:e}");
    assert!(rel < 1e-9, "{rel:e}");
    // the fast root is a steady precession too
    let a = top.tilted(theta, spin, fast);
    let run = top.simulate(&a, 0.5, &opts).unwrap();
    let nutation = run
        .samples
        .iter()
        .map(|s| (s.attitude.euler_angles().1 - theta).abs())
        .fold(0.0, f64::max);
    assert!(nutation < 1e-9, "fast: {nutation:e}");
}

/// A fast top released without precession nutates a little and precesses on average at
/// about `m g ℓ/(J₃ ω₃)`: measured 1.4e-4 relative at ω₃ = 500 rad/s (the correction is of
/// order `J₁ Ω/(J₃ ω₃)` ≈ 2.6e-4); θ swings by `2 J₁ m g ℓ sin θ/(J₃ω₃)²` = 3.7e-4 rad.
#[test]
fn fast_top_precesses_at_mgl_over_l3() {
    let top = top();
    let (theta, spin) = (PI / 4.0, 500.0);
    let approx = top.fast_top_precession(spin).unwrap();
    let a = top.tilted(theta, spin, 0.0);
    let t_end = 2.0 * PI / approx;
    let opts = options(adaptive(Tableau::dop853(), 1e-10), Formulation::World, 2000);
    let run = top.simulate(&a, t_end, &opts).unwrap();
    let (first, last) = (run.samples[0], run.samples[run.samples.len() - 1]);
    let rate = (last.precession - first.precession) / (last.t - first.t);
    let rel = (rate - approx).abs() / approx;
    let nutation = run
        .samples
        .iter()
        .map(|s| (s.attitude.euler_angles().1 - theta).abs())
        .fold(0.0, f64::max);
    // the nutation of a fast top released at rest: θ swings by 2 J₁ m g ℓ sin θ/(J₃ω₃)²
    let (j1, j3) = (top.inertia()[(0, 0)], top.inertia()[(2, 2)]);
    let swing = 2.0 * j1 * 0.5 * 9.81 * 0.05 * theta.sin() / (j3 * spin).powi(2);
    println!(
        "fast top: mean precession {rate} rad/s vs m g ℓ/(J₃ω₃) = {approx} ({rel:e}), nutation ≤ {nutation:e} rad (2J₁mgℓ sinθ/(J₃ω₃)² = {swing:e})"
    );
    assert!(rel < 1e-3, "{rel:e}");
    assert!(
        (nutation / swing - 1.0).abs() < 0.02,
        "{nutation:e} vs {swing:e}"
    );
}

#[test]
fn a_body_from_mass_properties_has_its_principal_moments() {
    let i = Mat3::from_diagonal(&Vec3::new(13.0, 10.0, 5.0));
    let props = MassProperties::new(12.0, Vec3::zeros(), i).rotated(
        &nalgebra::Rotation3::from_axis_angle(&Vector3::z_axis(), 0.5),
    );
    let (body, axes) = FreeBody::from_mass_properties(&props).unwrap();
    let m = body.moments();
    assert!(
        (m[0] - 5.0).abs() < 1e-12 && (m[2] - 13.0).abs() < 1e-12,
        "{m:?}"
    );
    assert_eq!(body.mass(), 12.0);
    // the body-frame tensor rotated by the axes is the given one
    let back = axes.to_rotation_matrix().matrix()
        * Mat3::from_diagonal(&Vec3::from(m))
        * axes.to_rotation_matrix().matrix().transpose();
    assert!((back - props.inertia).norm() < 1e-12);
    // a point mass has no rotational inertia
    let point = MassProperties::point(1.0, Vec3::zeros());
    assert!(matches!(
        FreeBody::from_mass_properties(&point),
        Err(Free3dError::Moment { .. })
    ));
}

#[test]
fn bad_input_is_refused_with_the_offending_value() {
    let err = |r: Result<FreeBody, Free3dError>| r.unwrap_err().to_string();
    assert!(err(FreeBody::new([1.0, -2.0, 3.0], 1.0)).contains("I2 = -2"));
    assert!(err(FreeBody::new([1.0, 2.0, f64::NAN], 1.0)).contains("I3"));
    let e = err(FreeBody::new([1.0, 1.0, 2.5], 1.0));
    assert!(e.contains("triangle inequality") && e.contains("I3"), "{e}");
    assert!(err(FreeBody::new([1.0, 2.0, 3.0], 0.0)).contains("mass"));
    let body = FreeBody::new([1.0, 2.0, 3.0], 1.0).unwrap();
    assert!(matches!(
        SpinningBody::on_pivot(body, Vec3::new(0.0, 0.0, 1.0), -9.81),
        Err(Free3dError::Gravity { .. })
    ));
    assert!(matches!(
        SpinningBody::on_pivot(body, Vec3::new(f64::INFINITY, 0.0, 1.0), 9.81),
        Err(Free3dError::NonFinite { .. })
    ));
    let free = SpinningBody::free(body);
    let a = start(&free, [0.0, 1.0, 0.0]);
    assert!(matches!(
        free.simulate(&a, 0.0, &SpinOptions::default()),
        Err(Free3dError::Duration { .. })
    ));
    let fixed = |dt| options(SpinIntegrator::Splitting { dt }, Formulation::World, 1);
    assert!(matches!(
        free.simulate(&a, 1.0, &fixed(-1.0)),
        Err(Free3dError::Step { .. })
    ));
    assert!(matches!(
        free.simulate(&a, 1e6, &fixed(1e-6)),
        Err(Free3dError::TooManySteps { .. })
    ));
    let tilted = SpinningBody::on_pivot(body, Vec3::new(0.1, 0.0, 1.0), 9.81).unwrap();
    assert!(matches!(
        tilted.simulate(&a, 1.0, &fixed(0.01)),
        Err(Free3dError::SplittingOffAxis { .. })
    ));
    assert!(
        free.attitude(UnitQuaternion::identity(), Vec3::new(f64::NAN, 0.0, 0.0))
            .is_err()
    );
}

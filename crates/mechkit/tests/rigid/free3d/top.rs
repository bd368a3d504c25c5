//! The heavy symmetric top: conservation of E, L_z and L₃, steady precession, the fast top.

use std::f64::consts::PI;

use mechkit::mass::Vec3;
use mechkit::ode::Tableau;
use mechkit::rigid::free3d::{Formulation, FreeBody, SpinningBody};

use super::{adaptive, options};

/// A symmetric top: m = 0.5 kg, I₁ = I₂ = 3e-3, I₃ = 4e-3 kg·m² about the CM, ℓ = 5 cm.
fn top() -> SpinningBody {
    let body = FreeBody::new([3e-3, 3e-3, 4e-3], 0.5).unwrap();
    SpinningBody::on_pivot(body, Vec3::new(0.0, 0.0, 0.05), 9.81).unwrap()
}

/// Released tilted and spinning, the heavy top nutates; E, L_z and L₃ are conserved
/// (measured 8.2e-15, 0, 9.2e-15 relative at rtol 1e-12) while |L| is not (3.4e-4).
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
/// θ stays at 30° (measured within 1.9e-13 rad) and the mean precession rate is Ω (measured
/// 1.1e-14 relative).
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
    assert!(nutation < 1e-11, "{nutation:e}");
    assert!(rel < 1e-11, "{rel:e}");
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

/// The nutation angle of a top tilted by a hair: read from `acos(cos θ)` it had a floor of
/// about 1.5e-8 rad (a tilt of 1e-8 rad read as 0 or 1.5e-8); from both its sine and cosine it
/// is exact to rounding at any tilt.
#[test]
fn the_nutation_angle_is_exact_near_upright() {
    let top = top();
    for theta in [1e-12, 1e-8, 1e-4, 0.5, 3.0] {
        let a = top.tilted(theta, 50.0, 0.0);
        let got = a.euler_angles().1;
        assert!(
            (got - theta).abs() <= 1e-15 * theta.max(1e-3),
            "{theta}: {got}"
        );
    }
}

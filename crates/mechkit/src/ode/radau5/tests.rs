//! Radau IIA(5) against exact solutions, an explicit method on a stiff system, and its
//! order.

use crate::Real;
use crate::ode::*;

struct Decay;
impl OdeSystem for Decay {
    fn dim(&self) -> usize {
        1
    }
    fn rhs_into(&self, _t: Real, y: &[Real], dydt: &mut [Real]) {
        dydt[0] = -y[0];
    }
}

/// Robertson's chemical kinetics: three species, rates 0.04, 3·10⁷ and 10⁴.
struct Robertson {
    exact_jacobian: bool,
}
impl OdeSystem for Robertson {
    fn dim(&self) -> usize {
        3
    }
    fn rhs_into(&self, _t: Real, y: &[Real], d: &mut [Real]) {
        d[0] = -0.04 * y[0] + 1e4 * y[1] * y[2];
        d[2] = 3e7 * y[1] * y[1];
        d[1] = -d[0] - d[2];
    }
    fn jacobian_into(&self, _t: Real, y: &[Real], j: &mut [Real]) -> bool {
        if !self.exact_jacobian {
            return false;
        }
        j.copy_from_slice(&[
            -0.04,
            1e4 * y[2],
            1e4 * y[1],
            0.04,
            -1e4 * y[2] - 6e7 * y[1],
            -1e4 * y[1],
            0.0,
            6e7 * y[1],
            0.0,
        ]);
        true
    }
}

/// Van der Pol's oscillator `x'' = μ (1 − x²) x' − x` as a second-order system.
struct VanDerPol {
    mu: Real,
}
impl SecondOrderSystem for VanDerPol {
    fn dof(&self) -> usize {
        1
    }
    fn accel_into(&self, _t: Real, q: &[Real], v: &[Real], a: &mut [Real]) {
        a[0] = self.mu * (1.0 - q[0] * q[0]) * v[0] - q[0];
    }
    fn accel_jacobian_into(
        &self,
        _t: Real,
        q: &[Real],
        v: &[Real],
        da_dq: &mut [Real],
        da_dv: &mut [Real],
    ) -> bool {
        da_dq[0] = -2.0 * self.mu * q[0] * v[0] - 1.0;
        da_dv[0] = self.mu * (1.0 - q[0] * q[0]);
        true
    }
}

fn config(rtol: Real, atol: Real) -> AdaptiveConfig {
    AdaptiveConfig {
        rtol: Tolerance::Scalar(rtol),
        atol: Tolerance::Scalar(atol),
        ..AdaptiveConfig::default()
    }
}

fn integrate<S: OdeSystem + ?Sized>(r: &mut Radau5, sys: &S, y0: &[Real], t_end: Real) -> State {
    let mut state = State::new(0.0, y0.to_vec());
    while state.t < t_end {
        r.step(sys, &mut state, t_end).unwrap();
    }
    state
}

#[test]
fn decay_meets_its_tolerance_and_the_error_falls_with_it() {
    let mut errors = Vec::new();
    for rtol in [1e-4, 1e-6, 1e-8, 1e-10] {
        let mut r = Radau5::new(config(rtol, rtol));
        let s = integrate(&mut r, &Decay, &[1.0], 5.0);
        let e = (s.y[0] - (-5.0_f64).exp()).abs();
        assert!(e < 10.0 * rtol, "rtol {rtol}: error {e}");
        errors.push((rtol, e, r.stats()));
    }
    // the error follows the tolerance, and the steps grow as tol^(-1/4) (the estimate is of
    // order 4): 10^6 in tolerance is 31.6 times the steps
    let (_, e_loose, s_loose) = errors[0];
    let (_, e_tight, s_tight) = errors[3];
    assert!(e_tight < e_loose * 1e-5, "{errors:?}");
    let ratio = s_tight.accepted as Real / s_loose.accepted as Real;
    assert!((15.0..60.0).contains(&ratio), "{ratio}: {errors:?}");
}

#[test]
fn robertson_matches_dop853_and_the_exact_jacobian_saves_evaluations() {
    let y0 = [1.0, 0.0, 0.0];
    let t_end = 40.0;
    // the reference: DOP853 at a tight tolerance (explicit: many small steps on this system)
    let mut rk = AdaptiveRk::new(Tableau::dop853(), config(1e-12, 1e-16)).unwrap();
    let mut reference = State::new(0.0, y0.to_vec());
    while reference.t < t_end {
        rk.step(
            &Robertson {
                exact_jacobian: false,
            },
            &mut reference,
            t_end,
        )
        .unwrap();
    }
    let mut counts = Vec::new();
    for exact_jacobian in [false, true] {
        let mut r = Radau5::new(config(1e-8, 1e-12));
        let s = integrate(&mut r, &Robertson { exact_jacobian }, &y0, t_end);
        for i in 0..3 {
            let e = (s.y[i] - reference.y[i]).abs();
            assert!(
                e < 1e-7 * reference.y[i].abs() + 1e-11,
                "y{i}: {} vs {}",
                s.y[i],
                reference.y[i]
            );
        }
        assert!(r.stats().accepted < 500, "{:?}", r.stats());
        counts.push((r.stats(), r.implicit_stats()));
    }
    assert!(
        rk.stats().accepted > 20 * counts[1].0.accepted,
        "{:?} {counts:?}",
        rk.stats()
    );
    assert_eq!(counts[1].1.jacobians_by_differences, 0);
    assert!(
        counts[1].0.evaluations < counts[0].0.evaluations,
        "{counts:?}"
    );
}

#[test]
fn van_der_pol_with_mu_1000_takes_few_steps() {
    let sys = VanDerPol { mu: 1000.0 };
    let mut r = Radau5::new(config(1e-6, 1e-6));
    let s = integrate(&mut r, &sys, &[2.0, 0.0], 3000.0);
    // one relaxation period is about (3 − 2 ln 2) μ = 1614 s: x has come round past −2 to
    // climb back; a tight run agrees
    let mut tight = Radau5::new(config(1e-10, 1e-10));
    let reference = integrate(&mut tight, &sys, &[2.0, 0.0], 3000.0);
    assert!(
        (s.y[0] - reference.y[0]).abs() < 1e-3,
        "{} vs {}",
        s.y[0],
        reference.y[0]
    );
    assert!(
        r.stats().accepted < 1000,
        "{:?} {:?}",
        r.stats(),
        r.implicit_stats()
    );
}

#[test]
fn the_dense_output_is_the_collocation_polynomial() {
    let mut r = Radau5::new(config(1e-9, 1e-12));
    let mut state = State::new(0.0, vec![1.0]);
    r.step(&Decay, &mut state, 10.0).unwrap();
    r.step(&Decay, &mut state, 10.0).unwrap();
    let (t0, h) = (r.last_t0, r.last_h);
    let mut out = [0.0];
    let mut poly = StepPolynomial::default();
    r.dense_polynomial_into(&mut poly);
    for s in [0.0, 0.25, 0.5, 0.9, 1.0] {
        let t = t0 + s * h;
        r.dense_into(t, &mut out);
        assert!((out[0] - (-t).exp()).abs() < 1e-7, "{s}: {}", out[0]);
        assert!((poly.value(0, s) - out[0]).abs() < 1e-15);
    }
    assert_eq!(out[0], state.y[0]);
}

/// A 0.1 kg ball of radius 1 cm dropped from 1 mm onto a Hertz floor (k = 10¹⁰ N/m^1.5,
/// Hunt-Crossley α = 2 s/m), `y = (x, v)`, with its exact Jacobian: a right-hand side whose
/// Jacobian jumps at the contact's start.
struct HertzDrop;
impl HertzDrop {
    const M: Real = 0.1;
    const R: Real = 0.01;
    const K: Real = 1e10;
    const ALPHA: Real = 2.0;
    fn energy(y: &[Real]) -> Real {
        let d = (Self::R - y[0]).max(0.0);
        0.5 * Self::M * y[1] * y[1] + Self::M * 9.81 * y[0] + 0.4 * Self::K * d * d * d.sqrt()
    }
}
impl OdeSystem for HertzDrop {
    fn dim(&self) -> usize {
        2
    }
    fn rhs_into(&self, _t: Real, y: &[Real], d: &mut [Real]) {
        let delta = Self::R - y[0];
        let f = if delta > 0.0 {
            (Self::K * delta * delta.sqrt() * (1.0 - Self::ALPHA * y[1])).max(0.0)
        } else {
            0.0
        };
        d[0] = y[1];
        d[1] = -9.81 + f / Self::M;
    }
    fn jacobian_into(&self, _t: Real, y: &[Real], j: &mut [Real]) -> bool {
        j.copy_from_slice(&[0.0, 1.0, 0.0, 0.0]);
        let delta = Self::R - y[0];
        let damp = 1.0 - Self::ALPHA * y[1];
        if delta > 0.0 && damp > 0.0 {
            j[2] = -1.5 * Self::K * delta.sqrt() * damp / Self::M;
            j[3] = -Self::ALPHA * Self::K * delta * delta.sqrt() / Self::M;
        }
        true
    }
}

/// Issue 28: the first step into the floor converged in one Newton pass on the contraction
/// rate remembered from free flight, with the stages never evaluated where they ended, 48 µm
/// deep (the true bounce reaches 9 µm): the ball left with seven times the energy it fell
/// with. The energy can only fall, through the first bounce and back up.
#[test]
fn a_ball_landing_on_a_stiff_floor_gains_no_energy() {
    for rtol in [1e-6, 1e-8] {
        let mut r = Radau5::new(config(rtol, 1e-12));
        let mut state = State::new(0.0, vec![0.011, 0.0]);
        let e0 = HertzDrop::energy(&state.y);
        let mut bounced = false;
        while state.t < 0.03 {
            r.step(&HertzDrop, &mut state, 0.03).unwrap();
            let e = HertzDrop::energy(&state.y);
            assert!(
                e <= e0 * (1.0 + 1e-6),
                "rtol {rtol}, t = {}: E = {e} > {e0}",
                state.t
            );
            bounced |= state.y[1] > 0.0;
        }
        assert!(bounced, "rtol {rtol}: the ball bounced");
    }
}

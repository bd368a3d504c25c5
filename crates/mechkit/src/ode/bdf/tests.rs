//! The BDF/NDF integrator: its difference array, exact solutions, its order when the order
//! is capped, stiff problems (van der Pol at μ = 1000, Robertson) and events on its dense
//! output.

use std::ops::ControlFlow;

use mechkit_expr::interval::Jet;

use super::diff::{MAX_ORDER, change_spacing, newton_basis};
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

/// `y' = y cos t`: `y = exp(sin t)`, smooth, growing and decaying in turn.
struct Wave;
impl OdeSystem for Wave {
    fn dim(&self) -> usize {
        1
    }
    fn rhs_into(&self, t: Real, y: &[Real], dydt: &mut [Real]) {
        dydt[0] = y[0] * t.cos();
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

fn integrate<S: OdeSystem + ?Sized>(b: &mut Bdf, sys: &S, y0: &[Real], t_end: Real) -> State {
    let mut state = State::new(0.0, y0.to_vec());
    while state.t < t_end {
        b.step(sys, &mut state, t_end).unwrap();
    }
    state
}

/// The differences of `y(t) = t³ − 2t + 1` on the grid `t = 1, 1 − h, …` (`D⁰ = y(1)`,
/// `Dʲ⁺¹ = ∇Dʲ`).
fn differences(h: Real, order: usize) -> Vec<Real> {
    let y = |t: Real| t * t * t - 2.0 * t + 1.0;
    let mut rows: Vec<Vec<Real>> = vec![(0..=order).map(|m| y(1.0 - m as Real * h)).collect()];
    for j in 1..=order {
        let prev = &rows[j - 1];
        rows.push((0..=order - j).map(|m| prev[m] - prev[m + 1]).collect());
    }
    rows.iter().map(|r| r[0]).collect()
}

#[test]
fn changing_the_spacing_matches_the_differences_on_the_new_grid() {
    for order in 3..=MAX_ORDER {
        let mut d = differences(0.1, order);
        change_spacing(&mut d, 1, order, 0.37);
        let want = differences(0.037, order);
        for j in 0..=order {
            assert!(
                (d[j] - want[j]).abs() < 1e-13,
                "{order} {j}: {d:?} {want:?}"
            );
        }
    }
}

#[test]
fn the_basis_interpolates_the_back_values() {
    let order = 4;
    let h = 0.2;
    let d = differences(h, order);
    let phi = newton_basis(order);
    for m in 0..=order {
        // s = 1 − m is the back value at t = 1 − m h
        let s = 1.0 - m as Real;
        let p: Real = (0..=order)
            .map(|j| d[j] * (0..=order).rev().fold(0.0, |acc, q| acc * s + phi[j][q]))
            .sum();
        let t = 1.0 - m as Real * h;
        let want = t * t * t - 2.0 * t + 1.0;
        assert!((p - want).abs() < 1e-13, "{m}: {p} vs {want}");
    }
}

#[test]
fn decay_meets_its_tolerance_and_the_error_falls_with_it() {
    let mut errors = Vec::new();
    for rtol in [1e-4, 1e-6, 1e-8, 1e-10] {
        let mut b = Bdf::new(config(rtol, rtol));
        let s = integrate(&mut b, &Decay, &[1.0], 5.0);
        let e = (s.y[0] - (-5.0_f64).exp()).abs();
        assert!(e < 10.0 * rtol, "rtol {rtol}: error {e}");
        errors.push((rtol, e, b.stats().accepted));
    }
    assert!(errors[3].1 < errors[0].1 * 1e-4, "{errors:?}");
}

/// The order of each formula, measured: steps of one size `h` and one order `k` from exact
/// back values (the differences of `exp(sin t)` at `0, −h, …, −k h`); the error at t = 4
/// falls by `2ᵏ` when `h` halves.
#[test]
fn each_order_converges_at_its_order() {
    let t_end: Real = 4.0;
    let exact = |t: Real| t.sin().exp();
    for k in 1..=MAX_ORDER {
        let errors: Vec<Real> = [40.0, 80.0, 160.0]
            .iter()
            .map(|&steps| {
                let h: Real = t_end / steps;
                let mut b = Bdf::with_max_order(config(1e-12, 1e-12), k);
                b.resize(1);
                b.held = true;
                // the differences of the back values: Dʲ⁺¹ = ∇Dʲ
                let mut back: Vec<Real> = (0..=k).map(|m| exact(-(m as Real) * h)).collect();
                for j in 0..=k {
                    b.d[j] = back[0];
                    back = back.windows(2).map(|w| w[0] - w[1]).collect();
                }
                b.h = h;
                b.order = k;
                b.t = Some(0.0);
                let mut state = State::new(0.0, vec![1.0]);
                while state.t < t_end - 0.5 * h {
                    b.step(&Wave, &mut state, Real::INFINITY).unwrap();
                    assert_eq!((b.order(), b.h), (k, h));
                }
                assert!((state.t - t_end).abs() < 1e-12);
                (state.y[0] - exact(state.t)).abs()
            })
            .collect();
        let rates: Vec<Real> = errors.windows(2).map(|e| (e[0] / e[1]).log2()).collect();
        eprintln!("order {k}: errors {errors:?}, observed orders {rates:.2?}");
        for r in &rates {
            assert!((r - k as Real).abs() < 0.3, "order {k}: {rates:?}");
        }
    }
}

/// With the order capped, the run never goes above it, and a higher cap takes fewer steps
/// for the same tolerance on a smooth problem.
#[test]
fn a_capped_order_is_kept_and_higher_orders_save_steps() {
    let mut steps = Vec::new();
    for k in 1..=MAX_ORDER {
        let mut b = Bdf::with_max_order(config(1e-6, 1e-6), k);
        let mut state = State::new(0.0, vec![1.0]);
        let mut highest = 0;
        while state.t < 20.0 {
            b.step(&Wave, &mut state, 20.0).unwrap();
            highest = highest.max(b.order());
        }
        assert_eq!(highest, k);
        // backward Euler's global error is far above its local one
        let error = (state.y[0] - 20.0_f64.sin().exp()).abs();
        assert!(error < if k == 1 { 2e-2 } else { 1e-3 }, "{k}: {error}");
        steps.push(b.stats().accepted);
    }
    assert!(steps.windows(2).all(|w| w[1] < w[0]), "{steps:?}");
}

/// Van der Pol at μ = 1000 to t = 2000 s against x(2000) = 1.7061677 (Radau5 at 1e-10,
/// tests/scenario/stiff.rs). SciPy's BDF (the same method) at rtol = atol = 1e-6: 847 steps,
/// 2,620 evaluations, error 1.1e-4; at 1e-7: 1,278 steps, error 1.5e-5.
#[test]
fn van_der_pol_with_mu_1000_is_accurate_in_few_steps() {
    let sys = VanDerPol { mu: 1000.0 };
    let mut runs = Vec::new();
    for tol in [1e-6, 1e-7] {
        let mut b = Bdf::new(config(tol, tol));
        let s = integrate(&mut b, &sys, &[2.0, 0.0], 2000.0);
        let error = s.y[0] - 1.706_167_7;
        eprintln!(
            "van der Pol at {tol}: x(2000) = {} (error {error:.2e}), {:?} {:?}",
            s.y[0],
            b.stats(),
            b.implicit_stats()
        );
        runs.push((error.abs(), b.stats()));
    }
    assert!(runs[0].0 < 2e-4 && runs[0].1.accepted < 900, "{runs:?}");
    assert!(runs[1].0 < 3e-5 && runs[1].1.accepted < 1350, "{runs:?}");
}

/// The reference: Radau5 at a tight tolerance (itself checked against DOP853 to t = 40).
fn robertson_reference(t_end: Real) -> State {
    let sys = Robertson {
        exact_jacobian: true,
    };
    let mut r = Radau5::new(config(1e-11, 1e-15));
    let mut state = State::new(0.0, vec![1.0, 0.0, 0.0]);
    while state.t < t_end {
        r.step(&sys, &mut state, t_end).unwrap();
    }
    state
}

#[test]
fn robertson_matches_radau5_and_the_exact_jacobian_saves_evaluations() {
    let y0 = [1.0, 0.0, 0.0];
    for t_end in [40.0, 4e5] {
        let reference = robertson_reference(t_end);
        let mut counts = Vec::new();
        for exact_jacobian in [false, true] {
            let mut b = Bdf::new(config(1e-8, 1e-12));
            let s = integrate(&mut b, &Robertson { exact_jacobian }, &y0, t_end);
            for i in 0..3 {
                let e = (s.y[i] - reference.y[i]).abs();
                assert!(
                    e < 1e-6 * reference.y[i].abs() + 1e-11,
                    "t {t_end}, y{i}: {} vs {}",
                    s.y[i],
                    reference.y[i]
                );
            }
            eprintln!(
                "Robertson to {t_end} (exact J {exact_jacobian}): {:?} {:?} {:?}",
                s.y,
                b.stats(),
                b.implicit_stats()
            );
            assert!(b.stats().accepted < 1500, "{:?}", b.stats());
            counts.push((b.stats(), b.implicit_stats()));
        }
        assert_eq!(counts[1].1.jacobians_by_differences, 0);
        assert!(
            counts[1].0.evaluations < counts[0].0.evaluations,
            "{counts:?}"
        );
    }
}

#[test]
fn the_dense_output_interpolates_both_ends_of_the_step() {
    let mut b = Bdf::new(config(1e-9, 1e-12));
    let mut state = State::new(0.0, vec![1.0]);
    let mut poly = StepPolynomial::default();
    let mut out = [0.0];
    for _ in 0..40 {
        let before = state.clone();
        b.step(&Decay, &mut state, 10.0).unwrap();
        b.dense_polynomial_into(&mut poly);
        assert_eq!((poly.t0(), poly.t0() + poly.h()), (before.t, state.t));
        assert!((poly.value(0, 0.0) - before.y[0]).abs() < 1e-15);
        assert!((poly.value(0, 1.0) - state.y[0]).abs() < 1e-15);
        for s in [0.0, 0.25, 0.5, 0.9, 1.0] {
            let t = before.t + s * (state.t - before.t);
            b.dense_into(t, &mut out);
            assert!((out[0] - (-t).exp()).abs() < 1e-8, "{s}: {}", out[0]);
            assert!((poly.value(0, s) - out[0]).abs() < 1e-15);
        }
    }
    assert!(b.order() >= 3, "order {}", b.order());
}

/// `x' = v, v' = −x`.
struct Oscillator;
impl OdeSystem for Oscillator {
    fn dim(&self) -> usize {
        2
    }
    fn rhs_into(&self, _t: Real, y: &[Real], dydt: &mut [Real]) {
        dydt[0] = y[1];
        dydt[1] = -y[0];
    }
}

/// A ball falling under gravity, `y = [x, v]`.
struct Fall;
impl OdeSystem for Fall {
    fn dim(&self) -> usize {
        2
    }
    fn rhs_into(&self, _t: Real, y: &[Real], dydt: &mut [Real]) {
        dydt[0] = y[1];
        dydt[1] = -9.81;
    }
}

#[test]
fn events_are_located_on_the_dense_output() {
    // x = cos t: zeros at π/2 and 3π/2 (proven on the polynomial), x = 0.5 rising at 5π/3
    let mut b = Bdf::new(config(1e-10, 1e-12));
    let mut state = State::new(0.0, vec![1.0, 0.0]);
    let events = [
        OdeEvent::new(|_, y| y[0]).bounded_by(|_, y: &[Jet]| Some(y[0])),
        OdeEvent::new(|_, y| y[0] - 0.5).rising(),
    ];
    let mut hits = Vec::new();
    let end = run_events(
        Integrator::Bdf(&mut b),
        &Oscillator,
        &mut state,
        6.0,
        &events,
        &mut |p| {
            if let Progress::Event(h) = p {
                hits.push((h.event, h.t));
            }
            ControlFlow::Continue(())
        },
    )
    .unwrap();
    assert_eq!(end, EventEnd::TimeLimit);
    let pi = std::f64::consts::PI;
    let want = [(0, pi / 2.0), (0, 1.5 * pi), (1, 5.0 * pi / 3.0)];
    assert_eq!(hits.len(), want.len(), "{hits:?}");
    for ((e, t), (we, wt)) in hits.iter().zip(want) {
        assert_eq!(*e, we);
        assert!((t - wt).abs() < 1e-7, "{e}: {t} vs {wt}");
    }
    assert_eq!(state.t, 6.0);
    assert!((state.y[0] - 6.0_f64.cos()).abs() < 1e-7, "{:?}", state.y);
}

#[test]
fn a_bouncing_ball_restarts_after_each_bounce() {
    // restitution 0.8 from 1 m: bounces at t₁ = √(2/g), then every 2 · 0.8ⁱ v₁ / g
    let mut b = Bdf::new(config(1e-10, 1e-12));
    let mut state = State::new(0.0, vec![1.0, 0.0]);
    let floor = OdeEvent::new(|_, y| y[0])
        .bounded_by(|_, y: &[Jet]| Some(y[0]))
        .falling()
        .action(|_, y| y[1] *= -0.8);
    let mut hits = Vec::new();
    run_events(
        Integrator::Bdf(&mut b),
        &Fall,
        &mut state,
        3.0,
        &[floor],
        &mut |p| {
            if let Progress::Event(h) = p {
                hits.push(h.t);
            }
            ControlFlow::Continue(())
        },
    )
    .unwrap();
    let g = 9.81;
    let t1 = (2.0 / g as Real).sqrt();
    let v1 = g * t1;
    let mut want = vec![t1];
    while want.len() < 4 {
        let i = want.len() as i32;
        want.push(want[want.len() - 1] + 2.0 * 0.8_f64.powi(i) * v1 / g);
    }
    assert!(hits.len() >= 4, "{hits:?}");
    for (t, w) in hits.iter().zip(&want) {
        assert!((t - w).abs() < 1e-8, "{t} vs {w}");
    }
}

#[test]
fn a_step_to_where_it_stands_changes_nothing() {
    let mut b = Bdf::new(config(1e-6, 1e-9));
    let mut state = State::new(1.0, vec![2.0]);
    assert_eq!(b.step(&Decay, &mut state, 1.0), Ok(0.0));
    assert_eq!(state.y, vec![2.0]);
    let mut out = [0.0];
    b.dense_into(1.0, &mut out);
    assert_eq!(out, [2.0]);
}

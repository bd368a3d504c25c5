//! A derivative handed to a stepper (`provide_derivative`) replaces the evaluation at the start
//! of the next step: the step is the same as with its own evaluation, costs one evaluation
//! less, and a derivative for another time is ignored.

use mechkit::ode::reference::Oscillator;
use mechkit::ode::{Euler, EulerCromer, Rk4, SecondOrderSystem, State, Stepper, VelocityVerlet};

fn check<S: Stepper<Oscillator>>(mut plain: S, mut fed: S, saved: usize) {
    let osc = Oscillator { omega: 3.0 };
    let (mut a, mut b) = (
        State::from_qv(0.0, &[1.0], &[0.5]),
        State::from_qv(0.0, &[1.0], &[0.5]),
    );
    for _ in 0..5 {
        let ea = plain.step(&osc, &mut a, 0.01).unwrap().evaluations;
        let mut acc = [0.0];
        osc.accel_into(b.t, &b.y[..1], &b.y[1..], &mut acc);
        fed.provide_derivative(b.t, &[b.y[1], acc[0]]);
        let eb = fed.step(&osc, &mut b, 0.01).unwrap().evaluations;
        assert_eq!(a, b, "{}", plain.name());
        assert!(
            eb + saved <= ea,
            "{}: {eb} vs {ea} evaluations",
            plain.name()
        );
    }
    // a derivative for another time is not used
    fed.provide_derivative(b.t + 1.0, &[1e9, 1e9]);
    plain.step(&osc, &mut a, 0.01).unwrap();
    fed.step(&osc, &mut b, 0.01).unwrap();
    assert_eq!(a, b, "{}: stale derivative used", plain.name());
}

#[test]
fn provided_derivatives_change_cost_not_results() {
    check(Euler::new(), Euler::new(), 1);
    check(EulerCromer::new(), EulerCromer::new(), 1);
    check(Rk4::new(), Rk4::new(), 1);
    check(VelocityVerlet::new(), VelocityVerlet::new(), 0);
}

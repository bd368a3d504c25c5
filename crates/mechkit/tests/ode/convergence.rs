//! Measured order of convergence of the fixed-step methods on problems with exact solutions:
//! halving the step should divide the global error by 2^p, with p = 1 for Euler and
//! Euler-Cromer, 2 for velocity Verlet and 4 for RK4. The order is the least-squares slope of
//! log(error) against log(h) over four step sizes, and must be within ±0.15 of p.

use mechkit::ode::reference::{Decay, Oscillator};
use mechkit::ode::{Euler, EulerCromer, Rk4, State, Stepper, VelocityVerlet};

use crate::util::order;

const T: f64 = 2.0;
const HS: [f64; 4] = [0.02, 0.01, 0.005, 0.0025];

fn oscillator_error<S: Stepper<Oscillator>>(mut stepper: S, h: f64) -> f64 {
    let osc = Oscillator { omega: 2.0 };
    let mut s = State::from_qv(0.0, &[1.0], &[0.0]);
    stepper.integrate(&osc, &mut s, T, h).unwrap();
    let (x, v) = osc.exact(T);
    // error in phase space, scaled so both components count alike
    ((s.y[0] - x).powi(2) + ((s.y[1] - v) / osc.omega).powi(2)).sqrt()
}

fn measured<S: Stepper<Oscillator>>(make: impl Fn() -> S) -> f64 {
    let errs: Vec<f64> = HS.iter().map(|&h| oscillator_error(make(), h)).collect();
    let p = order(&HS, &errs);
    let shown: Vec<String> = errs.iter().map(|e| format!("{e:.3e}")).collect();
    println!(
        "{}: errors {shown:?} at h = {HS:?}: order {p:.3}",
        make().name()
    );
    p
}

#[test]
fn euler_is_first_order() {
    let p = measured(Euler::new);
    assert!((p - 1.0).abs() < 0.15, "Euler order {p}");
}

#[test]
fn euler_cromer_is_first_order() {
    let p = measured(EulerCromer::new);
    assert!((p - 1.0).abs() < 0.15, "Euler-Cromer order {p}");
}

#[test]
fn velocity_verlet_is_second_order() {
    let p = measured(VelocityVerlet::new);
    assert!((p - 2.0).abs() < 0.15, "Verlet order {p}");
}

#[test]
fn rk4_is_fourth_order() {
    let p = measured(Rk4::new);
    assert!((p - 4.0).abs() < 0.15, "RK4 order {p}");
}

#[test]
fn first_order_systems_converge_too() {
    let decay = Decay { lambda: 1.5 };
    let err = |mut st: Box<dyn Stepper<Decay>>, h: f64| {
        let mut s = State::new(0.0, vec![1.0]);
        st.integrate(&decay, &mut s, T, h).unwrap();
        (s.y[0] - decay.exact(T)).abs()
    };
    let euler: Vec<f64> = HS.iter().map(|&h| err(Box::new(Euler::new()), h)).collect();
    let rk4: Vec<f64> = HS.iter().map(|&h| err(Box::new(Rk4::new()), h)).collect();
    assert!((order(&HS, &euler) - 1.0).abs() < 0.15);
    assert!((order(&HS, &rk4) - 4.0).abs() < 0.15);
}

#[test]
fn integrate_lands_exactly_on_t_end() {
    let osc = Oscillator { omega: 1.0 };
    let mut s = State::from_qv(0.0, &[1.0], &[0.0]);
    let n = Rk4::new().integrate(&osc, &mut s, 1.0, 0.3).unwrap();
    assert_eq!(n, 4);
    assert_eq!(s.t, 1.0);
}

#[test]
fn verlet_reuses_its_end_acceleration() {
    // position-only forces: one evaluation per step after the first
    let osc = Oscillator { omega: 1.0 };
    let mut st = VelocityVerlet::new();
    let mut s = State::from_qv(0.0, &[1.0], &[0.0]);
    assert_eq!(st.step(&osc, &mut s, 0.1).unwrap().evaluations, 2);
    assert_eq!(st.step(&osc, &mut s, 0.1).unwrap().evaluations, 1);
    Stepper::<Oscillator>::reset(&mut st);
    assert_eq!(st.step(&osc, &mut s, 0.1).unwrap().evaluations, 2);
}

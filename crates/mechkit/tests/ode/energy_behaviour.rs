//! Energy over long runs of a harmonic oscillator: forward Euler gains energy without bound
//! (each step multiplies it by 1 + ω²h²), while the symplectic Euler-Cromer and velocity
//! Verlet keep the error bounded and oscillating.

use mechkit::ode::reference::Oscillator;
use mechkit::ode::{Euler, EulerCromer, State, Stepper, VelocityVerlet};

fn max_energy_error<S: Stepper<Oscillator>>(mut st: S, h: f64, steps: usize) -> (f64, f64) {
    let osc = Oscillator { omega: 1.0 };
    let mut s = State::from_qv(0.0, &[1.0], &[0.0]);
    let e0 = osc.energy(1.0, 0.0);
    let mut max_err: f64 = 0.0;
    for _ in 0..steps {
        st.step(&osc, &mut s, h).unwrap();
        max_err = max_err.max((osc.energy(s.y[0], s.y[1]) - e0).abs() / e0);
    }
    (max_err, (osc.energy(s.y[0], s.y[1]) - e0) / e0)
}

#[test]
fn euler_energy_grows_as_predicted() {
    let (h, n) = (0.01, 10_000);
    let (_, end) = max_energy_error(Euler::new(), h, n);
    let predicted = (1.0 + h * h).powi(n as i32) - 1.0;
    assert!(
        (end - predicted).abs() < 1e-9 * predicted.max(1.0),
        "{end} vs {predicted}"
    );
}

#[test]
fn symplectic_methods_keep_energy_bounded() {
    let (h, n) = (0.05, 200_000); // about 1600 periods
    let (ec, _) = max_energy_error(EulerCromer::new(), h, n);
    let (vv, _) = max_energy_error(VelocityVerlet::new(), h, n);
    // Euler-Cromer: O(h) oscillation; Verlet: O(h²)
    assert!(ec < 0.03, "Euler-Cromer energy error {ec}");
    assert!(vv < 1e-3, "Verlet energy error {vv}");
}

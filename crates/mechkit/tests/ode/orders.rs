//! Measured convergence orders of the tableau and splitting methods on two problems with exact
//! solutions: the harmonic oscillator (ω = 2 over t = 2) and the Kepler orbit with e = 0.5 over
//! one period (see [`Mesh`] for how the steps are spread). The order is the least-squares slope of log(error) against log(h) over four
//! step sizes chosen in each method's asymptotic range (above round-off), and must be within
//! ±0.15 of the theoretical order.

use mechkit::ode::reference::{Kepler, Oscillator};
use mechkit::ode::{Composition, ExplicitRk, State, Stepper, Symplectic, Tableau};

use crate::util::order;

/// How the `n` steps of one Kepler orbit are spread.
#[derive(Clone, Copy, Debug)]
enum Mesh {
    /// Uniform in time.
    Uniform,
    /// Uniform in the eccentric anomaly `E` (the orbit's natural clock, `t = E − e sin E`), so
    /// that each step carries a similar local error. With uniform steps the short perihelion
    /// passage dominates and DOP853 reaches its asymptotic range (local order 7.5 at n = 113,
    /// 7.7 at 160, 7.9 at 226) only where round-off (1e-13) takes over; on this mesh the
    /// same happens at n = 57-160, errors 1e-9 to 1e-13.
    Graded,
}

/// Global error (whole state) after one orbit of the Kepler problem in `n` steps.
fn kepler_error(stepper: &mut dyn Stepper<Kepler>, n: usize, mesh: Mesh) -> f64 {
    let k = Kepler { e: 0.5 };
    let mut s = State::new(0.0, k.initial().to_vec());
    stepper.reset();
    for i in 1..=n {
        let angle = 2.0 * std::f64::consts::PI * i as f64 / n as f64;
        let t = match mesh {
            Mesh::Uniform => angle,
            Mesh::Graded => angle - k.e * angle.sin(),
        };
        let h = t - s.t;
        stepper.step(&k, &mut s, h).unwrap();
        s.t = t;
    }
    let exact = k.exact(s.t);
    (0..4)
        .map(|i| (s.y[i] - exact[i]).powi(2))
        .sum::<f64>()
        .sqrt()
}

fn oscillator_error(stepper: &mut dyn Stepper<Oscillator>, h: f64) -> f64 {
    let osc = Oscillator { omega: 2.0 };
    let mut s = State::from_qv(0.0, &[1.0], &[0.0]);
    stepper.reset();
    stepper.integrate(&osc, &mut s, 2.0, h).unwrap();
    let (x, v) = osc.exact(2.0);
    ((s.y[0] - x).powi(2) + ((s.y[1] - v) / osc.omega).powi(2)).sqrt()
}

/// Measures the order on both problems; `osc_h` and `kepler_n` are the coarsest step and the
/// fewest steps per orbit, refined three times by `ratio` (2, or √2 for high orders whose
/// error would otherwise fall to round-off).
fn check<M>(
    make: impl Fn() -> M,
    want: f64,
    osc_h: f64,
    (kepler_n, mesh): (usize, Mesh),
    ratio: f64,
) where
    M: Stepper<Oscillator> + Stepper<Kepler>,
{
    let hs: Vec<f64> = (0..4).map(|i| osc_h / ratio.powi(i)).collect();
    let errs: Vec<f64> = hs
        .iter()
        .map(|&h| oscillator_error(&mut make(), h))
        .collect();
    let p_osc = order(&hs, &errs);
    let ns: Vec<usize> = (0..4)
        .map(|i| (kepler_n as f64 * ratio.powi(i)).round() as usize)
        .collect();
    let hk: Vec<f64> = ns.iter().map(|&n| 1.0 / n as f64).collect();
    let errk: Vec<f64> = ns
        .iter()
        .map(|&n| kepler_error(&mut make(), n, mesh))
        .collect();
    let p_kep = order(&hk, &errk);
    let name = Stepper::<Kepler>::name(&make());
    println!(
        "{name}: oscillator order {p_osc:.3} (errors {:.2e} .. {:.2e}), Kepler order {p_kep:.3} ({mesh:?} mesh, errors {:.2e} .. {:.2e})",
        errs[0], errs[3], errk[0], errk[3]
    );
    assert!(
        (p_osc - want).abs() < 0.15,
        "{name} on the oscillator: order {p_osc}"
    );
    assert!(
        (p_kep - want).abs() < 0.15,
        "{name} on Kepler: order {p_kep}"
    );
}

#[test]
fn heun_is_second_order() {
    check(
        || ExplicitRk::new(Tableau::heun()),
        2.0,
        0.02,
        (2000, Mesh::Uniform),
        2.0,
    );
}

#[test]
fn bogacki_shampine_is_third_order() {
    check(
        || ExplicitRk::new(Tableau::bogacki_shampine()),
        3.0,
        0.02,
        (1000, Mesh::Uniform),
        2.0,
    );
}

#[test]
fn tableau_rk4_is_fourth_order() {
    check(
        || ExplicitRk::new(Tableau::rk4()),
        4.0,
        0.04,
        (400, Mesh::Uniform),
        2.0,
    );
}

#[test]
fn dormand_prince_is_fifth_order() {
    check(
        || ExplicitRk::new(Tableau::dopri5()),
        5.0,
        0.1,
        (905, Mesh::Uniform),
        std::f64::consts::SQRT_2,
    );
}

#[test]
fn dop853_is_eighth_order() {
    check(
        || ExplicitRk::new(Tableau::dop853()),
        8.0,
        0.2,
        (57, Mesh::Graded),
        std::f64::consts::SQRT_2,
    );
}

#[test]
fn leapfrog_is_second_order() {
    check(
        || Symplectic::new(Composition::leapfrog()),
        2.0,
        0.02,
        (2000, Mesh::Uniform),
        2.0,
    );
}

#[test]
fn yoshida4_is_fourth_order() {
    check(
        || Symplectic::new(Composition::yoshida4()),
        4.0,
        0.04,
        (400, Mesh::Uniform),
        2.0,
    );
}

#[test]
fn forest_ruth_is_fourth_order() {
    check(
        || Symplectic::new(Composition::forest_ruth()),
        4.0,
        0.04,
        (400, Mesh::Uniform),
        2.0,
    );
}

#[test]
fn pefrl_is_fourth_order() {
    check(
        || Symplectic::new(Composition::pefrl()),
        4.0,
        0.1,
        (200, Mesh::Uniform),
        2.0,
    );
}

#[test]
fn yoshida6_is_sixth_order() {
    check(
        || Symplectic::new(Composition::yoshida6()),
        6.0,
        0.1,
        (200, Mesh::Uniform),
        2.0,
    );
}

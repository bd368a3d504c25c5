//! The standard ODE test set (issue 28): each problem against its published reference, with
//! radau5 (and DOP853 where the problem is not stiff, or to show that it is).

use mechkit::Real;
use mechkit::ode::reference::Arenstorf;
use mechkit::ode::testset::{Hires, Pleiades, Robertson, SpringChain, VanDerPol};
use mechkit::ode::{
    AdaptiveConfig, AdaptiveRk, AdaptiveStats, OdeSystem, Radau5, State, Tableau, Tolerance,
};

fn config(rtol: Real, atol: Real) -> AdaptiveConfig {
    AdaptiveConfig {
        rtol: Tolerance::Scalar(rtol),
        atol: Tolerance::Scalar(atol),
        ..AdaptiveConfig::default()
    }
}

/// `y(t_end)` by radau5, and its counters.
fn radau5<S: OdeSystem>(
    sys: &S,
    y0: &[Real],
    t_end: Real,
    rtol: Real,
    atol: Real,
) -> (Vec<Real>, AdaptiveStats) {
    let mut r = Radau5::new(config(rtol, atol));
    let mut s = State::new(0.0, y0.to_vec());
    while s.t < t_end {
        r.step(sys, &mut s, t_end).unwrap();
    }
    (s.y, r.stats())
}

/// `y(t_end)` by DOP853, its counters, and when its stiffness test fired.
fn dop853<S: OdeSystem>(
    sys: &S,
    y0: &[Real],
    t_end: Real,
    rtol: Real,
    atol: Real,
) -> (Vec<Real>, AdaptiveStats, Option<Real>) {
    let mut r = AdaptiveRk::new(Tableau::dop853(), config(rtol, atol)).unwrap();
    let mut s = State::new(0.0, y0.to_vec());
    while s.t < t_end {
        r.step(sys, &mut s, t_end).unwrap();
    }
    (s.y, r.stats(), r.stiff_from())
}

fn assert_close(got: &[Real], want: &[Real], rel: Real, abs: Real, what: &str) {
    for (i, (g, w)) in got.iter().zip(want).enumerate() {
        assert!(
            (g - w).abs() <= rel * w.abs() + abs,
            "{what}: component {i}: {g} vs {w} (error {:e})",
            (g - w).abs()
        );
    }
}

/// The acceptance case: fewer steps and evaluations than SciPy's Radau (617 and 5,167 at
/// rtol = atol = 1e-6) and the reference to 1e-4.
#[test]
fn van_der_pol_mu_1000() {
    let sys = VanDerPol { mu: 1000.0 };
    let (y, stats) = radau5(&sys, &[2.0, 0.0], 2000.0, 1e-6, 1e-6);
    assert!((y[0] - 1.706_167_7).abs() < 1e-4, "{}", y[0]);
    assert!(
        stats.accepted < 617 && stats.evaluations < 5167,
        "{stats:?}"
    );
}

#[test]
fn robertson_to_40_against_the_published_reference() {
    let (y, stats) = radau5(&Robertson, &[1.0, 0.0, 0.0], 40.0, 1e-10, 1e-14);
    assert_close(&y, &Robertson::REFERENCE_40, 1e-8, 1e-16, "Robertson");
    assert!(stats.accepted < 1000, "{stats:?}");
}

#[test]
fn hires_against_the_published_reference() {
    let (y, stats) = radau5(&Hires, &Hires::INITIAL, Hires::T_END, 1e-10, 1e-14);
    assert_close(&y, &Hires::REFERENCE, 1e-6, 1e-14, "HIRES radau5");
    // an explicit pair gets there too, in many more steps, and says the problem is stiff
    let (y, explicit, stiff) = dop853(&Hires, &Hires::INITIAL, Hires::T_END, 1e-10, 1e-14);
    assert_close(&y, &Hires::REFERENCE, 1e-6, 1e-14, "HIRES dop853");
    assert!(stiff.is_some(), "{explicit:?}");
    assert!(
        explicit.evaluations > 5 * stats.evaluations,
        "{explicit:?} vs {stats:?}"
    );
}

#[test]
fn pleiades_against_the_published_reference() {
    let y0 = Pleiades::initial();
    let (y, _, stiff) = dop853(&Pleiades, &y0, 3.0, 1e-12, 1e-12);
    assert_close(
        &y[..14],
        &Pleiades::REFERENCE,
        1e-9,
        1e-9,
        "Pleiades dop853",
    );
    assert!(stiff.is_none());
    let (y, _) = radau5(&Pleiades, &y0, 3.0, 1e-11, 1e-11);
    assert_close(
        &y[..14],
        &Pleiades::REFERENCE,
        1e-7,
        1e-7,
        "Pleiades radau5",
    );
}

#[test]
fn arenstorf_closes_its_orbit() {
    let y0 = Arenstorf.initial();
    let (y, _, stiff) = dop853(&Arenstorf, &y0, Arenstorf::PERIOD, 1e-12, 1e-12);
    assert_close(&y, &y0, 0.0, 1e-7, "Arenstorf dop853");
    assert!(stiff.is_none());
    let (y, _) = radau5(&Arenstorf, &y0, Arenstorf::PERIOD, 1e-11, 1e-11);
    assert_close(&y, &y0, 0.0, 1e-5, "Arenstorf radau5");
}

/// Twenty masses on stiff damped springs (k = 10⁶ N/m, c = 2·10⁴ N·s/m: modes to −8·10⁴ s⁻¹),
/// pulled at the end: radau5 against a tight DOP853 run at t = 0.1 s, and the static
/// equilibrium `q_i = (i + 1) F/k` by t = 1 s.
#[test]
fn a_chain_of_stiff_springs() {
    let sys = SpringChain {
        n: 20,
        k: 1e6,
        c: 2e4,
        pull: 1e3,
    };
    let y0 = vec![0.0; 40];
    let (y, stats) = radau5(&sys, &y0, 0.1, 1e-8, 1e-12);
    let (reference, _, _) = dop853(&sys, &y0, 0.1, 1e-11, 1e-15);
    assert_close(&y[..20], &reference[..20], 1e-6, 1e-12, "chain at 0.1 s");
    // at the same tolerance DOP853's steps are held by stability (|h λ| ≤ 6.4)
    let (_, explicit, stiff) = dop853(&sys, &y0, 0.1, 1e-8, 1e-12);
    assert!(stiff.is_some());
    assert!(
        stats.evaluations * 5 < explicit.evaluations,
        "{stats:?} vs {explicit:?}"
    );
    let (y, _) = radau5(&sys, &y0, 1.0, 1e-8, 1e-12);
    let equilibrium: Vec<Real> = (1..=20).map(|i| Real::from(i) * 1e3 / 1e6).collect();
    assert_close(&y[..20], &equilibrium, 1e-8, 1e-12, "chain at rest");
}

/// `J`'s column `j` by central differences of `f`.
fn difference_column(sys: &dyn OdeSystem, y: &[Real], j: usize) -> Vec<Real> {
    let n = y.len();
    let h = 1e-6 * y[j].abs().max(1e-3);
    let (mut up, mut down) = (y.to_vec(), y.to_vec());
    up[j] += h;
    down[j] -= h;
    let (mut fu, mut fd) = (vec![0.0; n], vec![0.0; n]);
    sys.rhs_into(0.0, &up, &mut fu);
    sys.rhs_into(0.0, &down, &mut fd);
    fu.iter()
        .zip(&fd)
        .map(|(a, b)| (a - b) / (2.0 * h))
        .collect()
}

/// Every problem's exact Jacobian against central differences, at its start and at a state
/// nearby (the comparison the work-precision benchmark relies on: both sides get it).
#[test]
fn the_exact_jacobians_match_central_differences() {
    let chain = SpringChain {
        n: 4,
        k: 1e6,
        c: 2e4,
        pull: 1e3,
    };
    let robertson = [1.0, 3e-5, 0.2];
    let hires = [1.0, 0.1, 0.2, 0.3, 0.4, 0.1, 0.2, 0.3];
    let problems: [(&dyn OdeSystem, Vec<Real>); 5] = [
        (&VanDerPol { mu: 1000.0 }, vec![2.0, -0.5]),
        (&Robertson, robertson.to_vec()),
        (&Hires, hires.to_vec()),
        (&Pleiades, Pleiades::initial()),
        (&chain, (0..8).map(|i| 1e-3 * Real::from(i)).collect()),
    ];
    for (k, (sys, y0)) in problems.iter().enumerate() {
        let n = y0.len();
        for shift in [0.0, 0.01] {
            let y: Vec<Real> = y0
                .iter()
                .enumerate()
                .map(|(i, v)| v + shift * (i as Real).sin())
                .collect();
            let mut jac = vec![0.0; n * n];
            assert!(
                sys.jacobian_into(0.0, &y, &mut jac),
                "problem {k}: no Jacobian"
            );
            let scale = jac.iter().fold(1.0, |m: Real, v| m.max(v.abs()));
            for j in 0..n {
                let column = difference_column(*sys, &y, j);
                for i in 0..n {
                    assert!(
                        (jac[i * n + j] - column[i]).abs() < 1e-6 * scale,
                        "problem {k}, entry ({i}, {j}): {} vs {}",
                        jac[i * n + j],
                        column[i]
                    );
                }
            }
        }
    }
}

//! The banded Newton solver of the implicit methods (issue 28): a chain of stiff springs,
//! whose Jacobian `[[0, I], [A, B]]` is tridiagonal in each block, is solved with its unknowns
//! reordered (`qᵢ`, `vᵢ` neighbours) and banded LU; the same run with the pattern hidden is
//! factored dense. Only the linear algebra differs, so the solutions agree to rounding and
//! the steps and evaluations are the same or nearly so.

use mechkit::Real;
use mechkit::ode::testset::SpringChain;
use mechkit::ode::{AdaptiveConfig, AdaptiveStats, Bdf, OdeSystem, Radau5, State, Tolerance};

/// `sys` without its Jacobian pattern: the implicit methods factor it dense.
struct Dense<'a, S>(&'a S);

impl<S: OdeSystem> OdeSystem for Dense<'_, S> {
    fn dim(&self) -> usize {
        self.0.dim()
    }
    fn rhs_into(&self, t: Real, y: &[Real], dydt: &mut [Real]) {
        self.0.rhs_into(t, y, dydt);
    }
    fn jacobian_into(&self, t: Real, y: &[Real], jac: &mut [Real]) -> bool {
        self.0.jacobian_into(t, y, jac)
    }
}

fn config(rtol: Real, atol: Real) -> AdaptiveConfig {
    AdaptiveConfig {
        rtol: Tolerance::Scalar(rtol),
        atol: Tolerance::Scalar(atol),
        ..AdaptiveConfig::default()
    }
}

/// The final state, the counters and the band of a radau5 (or, with `bdf`, a BDF) run.
fn solve(
    sys: &dyn OdeSystem,
    bdf: bool,
    t_end: Real,
    tol: Real,
) -> (Vec<Real>, AdaptiveStats, Option<(usize, usize)>) {
    let mut s = State::new(0.0, vec![0.0; sys.dim()]);
    let c = config(tol, 1e-3 * tol);
    if bdf {
        let mut r = Bdf::new(c);
        while s.t < t_end {
            r.step(sys, &mut s, t_end).unwrap();
        }
        (s.y, r.stats(), r.band())
    } else {
        let mut r = Radau5::new(c);
        while s.t < t_end {
            r.step(sys, &mut s, t_end).unwrap();
        }
        (s.y, r.stats(), r.band())
    }
}

fn chain(n: usize) -> SpringChain {
    SpringChain {
        n,
        k: 1e6,
        c: 2e4,
        pull: 1e3,
    }
}

fn compare(bdf: bool, tol: Real) {
    let sys = chain(20);
    let (yb, banded, band) = solve(&sys, bdf, 0.1, tol);
    let (yd, dense, none) = solve(&Dense(&sys), bdf, 0.1, tol);
    let (kl, ku) = band.expect("the chain is factored banded");
    assert!(kl + ku < 7, "band {kl} + {ku} + 1");
    assert_eq!(none, None);
    for (i, (b, d)) in yb.iter().zip(&yd).enumerate() {
        assert!(
            (b - d).abs() <= 1e-9 * d.abs().max(1e-3),
            "component {i}: banded {b} vs dense {d}"
        );
    }
    eprintln!("tol {tol}: banded {banded:?} vs dense {dense:?}");
    let near = |a: u64, b: u64| a.abs_diff(b) * 50 <= b;
    assert!(
        near(banded.accepted, dense.accepted) && near(banded.evaluations, dense.evaluations),
        "banded {banded:?} vs dense {dense:?}"
    );
}

#[test]
fn radau5_on_a_chain_banded_matches_dense() {
    compare(false, 1e-4);
    compare(false, 1e-8);
}

#[test]
fn bdf_on_a_chain_banded_matches_dense() {
    compare(true, 1e-6);
}

/// Two hundred masses (400 unknowns: a dense LU would cost 400³/3 multiply-adds per
/// factorisation): radau5 and bdf at 1e-6 against radau5 at 1e-10, all banded, at t = 0.1 s,
/// while the pull has travelled a quarter of the chain.
#[test]
fn a_long_chain_banded() {
    let sys = chain(200);
    let (reference, _, band) = solve(&sys, false, 0.1, 1e-10);
    assert!(band.is_some_and(|(kl, ku)| kl + ku < 8), "{band:?}");
    let scale = reference[..200]
        .iter()
        .fold(0.0, |m: Real, q| m.max(q.abs()));
    assert!(scale > 1e-3, "the pull moved the chain: {scale}");
    for bdf in [false, true] {
        let (y, _, band) = solve(&sys, bdf, 0.1, 1e-6);
        assert!(band.is_some());
        for (i, (q, want)) in y[..200].iter().zip(&reference).enumerate() {
            assert!(
                (q - want).abs() < 1e-4 * scale,
                "bdf {bdf}: q{i} = {q} vs {want}"
            );
        }
    }
}

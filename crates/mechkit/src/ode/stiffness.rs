//! Detecting stiffness in an explicit pair (Hairer's test, as in DOPRI5 and DOP853: Hairer &
//! Wanner, *Solving ODEs II*, Sec. IV.2).
//!
//! Two stages of an accepted step evaluated at the same time `t + h` but at different states
//! estimate the dominant eigenvalue of the Jacobian along the step:
//! `h λ ≈ h ‖f(y_new) − f(y_l)‖ / ‖y_new − y_l‖`. When `|h λ|` sits at the edge of the
//! method's stability region on the negative real axis for many steps in a row, stability,
//! not accuracy, is choosing the step: the problem is stiff there, and an implicit method
//! takes far fewer steps.

use super::stages::{Sparse, Stages, sparse};
use super::tableau::Tableau;
use crate::Real;

/// Stiff steps in a row before the test reports (Hairer's 15).
const STIFF_STEPS: u32 = 15;
/// Non-stiff steps in a row that clear the count (Hairer's 6).
const CALM_STEPS: u32 = 6;

/// The running test of one integrator.
#[derive(Debug, Clone)]
pub(super) struct StiffnessTest {
    /// The stage at `c = 1` compared with the new state's derivative, and its row of `a`.
    stage: usize,
    row: Sparse,
    /// `|h λ|` beyond which a step counts as limited by stability (just inside the
    /// stability boundary on the negative real axis).
    limit: Real,
    stiff: u32,
    calm: u32,
    /// When the test first fired.
    pub from: Option<Real>,
}

impl StiffnessTest {
    /// The test for `tab`, when it has a stage at `c = 1` whose state differs from the new
    /// solution (DOPRI5's sixth, DOP853's twelfth) and a stability interval on the negative
    /// real axis.
    pub fn for_tableau(tab: &Tableau) -> Option<StiffnessTest> {
        let s = tab.stages();
        let stage = (1..s)
            .rev()
            .find(|&l| tab.c[l] == 1.0 && tab.a[l][..] != tab.b[..l] && tab.a[l].len() == l)?;
        let limit = 0.98 * real_stability_boundary(tab)?;
        Some(StiffnessTest {
            stage,
            row: sparse(&tab.a[stage]),
            limit,
            stiff: 0,
            calm: 0,
            from: None,
        })
    }

    /// Counts the accepted step `h` that ended at `t_new` with `y_new`: stage `s` holds
    /// `f(t_new, y_new)` and the stages hold the step's (`scratch` is overwritten).
    pub fn check(
        &mut self,
        stages: &mut Stages,
        s: usize,
        h: Real,
        y_new: &[Real],
        scratch: &mut [Real],
        t_new: Real,
    ) {
        if self.from.is_some() {
            return;
        }
        stages.advance_into(&self.row, h, scratch);
        let (kl, ks) = (stages.k(self.stage), stages.k(s));
        let (mut num, mut den) = (0.0, 0.0);
        for i in 0..y_new.len() {
            num += (ks[i] - kl[i]).powi(2);
            den += (y_new[i] - scratch[i]).powi(2);
        }
        if den > 0.0 && h * h * num > self.limit * self.limit * den {
            self.calm = 0;
            self.stiff += 1;
            if self.stiff >= STIFF_STEPS {
                self.from = Some(t_new);
            }
        } else {
            self.calm += 1;
            if self.calm >= CALM_STEPS {
                self.stiff = 0;
            }
        }
    }
}

/// The largest `r` with `|R(−x)| ≤ 1` for all `0 ≤ x ≤ r`, `R` the method's stability
/// function `R(z) = 1 + z bᵀ (I − z A)⁻¹ 1`, found on a grid of 1/1000 up to 50.
pub(super) fn real_stability_boundary(tab: &Tableau) -> Option<Real> {
    let s = tab.stages();
    let r = |z: Real| {
        let mut g = vec![0.0; s];
        for i in 0..s {
            let sum: Real = tab.a[i].iter().zip(&g).map(|(a, gj)| a * gj).sum();
            g[i] = 1.0 + z * sum;
        }
        1.0 + z * tab.b.iter().zip(&g).map(|(b, gi)| b * gi).sum::<Real>()
    };
    let mut last = None;
    for k in 1..=50_000 {
        let x = Real::from(k) * 1e-3;
        if r(-x).abs() > 1.0 + 1e-12 {
            return last;
        }
        last = Some(x);
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stability_boundaries_are_the_known_ones() {
        // Hairer's codes use 3.25 (DOPRI5) and 6.1 (DOP853), inside these
        let dp5 = real_stability_boundary(&Tableau::dopri5()).unwrap();
        assert!((dp5 - 3.307).abs() < 0.01, "{dp5}");
        let dop853 = real_stability_boundary(&Tableau::dop853()).unwrap();
        assert!((dop853 - 6.39).abs() < 0.01, "{dop853}");
        let rk4 = real_stability_boundary(&Tableau::rk4()).unwrap();
        assert!((rk4 - 2.785).abs() < 0.01, "{rk4}");
    }

    #[test]
    fn the_pairs_with_a_second_stage_at_the_end_have_a_test() {
        assert_eq!(
            StiffnessTest::for_tableau(&Tableau::dopri5()).map(|t| t.stage),
            Some(5)
        );
        assert_eq!(
            StiffnessTest::for_tableau(&Tableau::dop853()).map(|t| t.stage),
            Some(11)
        );
    }
}

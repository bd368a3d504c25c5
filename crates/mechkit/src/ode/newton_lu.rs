//! The factorisation of an implicit method's Newton matrix: dense ([`Lu`]), or banded
//! ([`BandedLu`]) in the order of a [`BandPlan`] when the system's Jacobian pattern makes
//! that cheaper. Callers fill and solve in the system's own order of the unknowns; the
//! reordering stays inside.

use super::band_plan::BandPlan;
use super::banded::BandedLu;
use super::linalg::{Lu, Scalar, Singular};

/// A Newton matrix's LU factorisation, dense or banded.
#[derive(Debug, Clone, Default)]
pub(crate) struct NewtonLu<T> {
    dense: Lu<T>,
    banded: BandedLu<T>,
    plan: Option<BandPlan>,
    /// Whether `plan` was set for the current system (dense or banded).
    planned: bool,
    /// The right-hand side in the plan's order.
    work: Vec<T>,
}

impl<T: Scalar + Default> NewtonLu<T> {
    /// Factors banded with `plan` from now on, or dense with `None`.
    pub fn set_plan(&mut self, plan: Option<BandPlan>) {
        self.plan = plan;
        self.planned = true;
    }

    /// Whether [`NewtonLu::set_plan`] was called since [`NewtonLu::forget_plan`].
    pub fn is_planned(&self) -> bool {
        self.planned
    }

    /// Factors dense until told otherwise (for a new system or size).
    pub fn forget_plan(&mut self) {
        self.plan = None;
        self.planned = false;
    }

    /// `(kl, ku)` of the banded factorisation, `None` when dense.
    pub fn band(&self) -> Option<(usize, usize)> {
        self.plan.as_ref().map(|p| (p.kl, p.ku))
    }

    /// Factors the matrix `fill(r, c)` of size `n` (banded: only the entries inside the
    /// plan's band are asked for; a plan made for another size is dropped).
    pub fn factor(&mut self, n: usize, fill: impl Fn(usize, usize) -> T) -> Result<(), Singular> {
        if self.plan.as_ref().is_some_and(|p| p.order.len() != n) {
            self.plan = None;
        }
        match &self.plan {
            Some(p) => {
                let o = &p.order;
                self.banded
                    .factor(n, p.kl, p.ku, |r, c| fill(o[r], o[c]))
                    .map_err(|Singular { col }| Singular { col: o[col] })
            }
            None => self.dense.factor(n, fill),
        }
    }

    /// Solves `A x = b` in place.
    pub fn solve(&mut self, b: &mut [T]) {
        match &self.plan {
            Some(p) => {
                self.work.clear();
                self.work.extend(p.order.iter().map(|&i| b[i]));
                self.banded.solve(&mut self.work);
                for (&i, &x) in p.order.iter().zip(&self.work) {
                    b[i] = x;
                }
            }
            None => self.dense.solve(b),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Real;
    use crate::ode::pattern::JacobianPattern;

    #[test]
    fn a_reordered_band_solves_like_the_dense_lu() {
        // the Newton matrix 3 I − J of a chain of 12 masses in [q, v] order
        let n = 12;
        let mut a = JacobianPattern::new(n);
        for i in 0..n {
            for j in i.saturating_sub(1)..(i + 2).min(n) {
                a.insert(i, j);
            }
        }
        let p = a.second_order(0);
        let m = 2 * n;
        let entry = |r: usize, c: usize| -> Real {
            let j = if p.contains(r, c) {
                ((r * 7 + c * 3) % 5) as Real - 2.0
            } else {
                0.0
            };
            if r == c { 3.0 - j } else { -j }
        };
        let x: Vec<Real> = (0..m).map(|i| (i as Real).sin()).collect();
        let b: Vec<Real> = (0..m)
            .map(|r| (0..m).map(|c| entry(r, c) * x[c]).sum())
            .collect();
        let mut banded = NewtonLu::default();
        banded.set_plan(BandPlan::choose(&p));
        assert!(banded.band().is_some());
        banded.factor(m, entry).unwrap();
        let mut xb = b.clone();
        banded.solve(&mut xb);
        let mut dense = NewtonLu::default();
        dense.factor(m, entry).unwrap();
        let mut xd = b;
        dense.solve(&mut xd);
        for i in 0..m {
            assert!((xb[i] - x[i]).abs() < 1e-10, "{xb:?}");
            assert!((xd[i] - x[i]).abs() < 1e-10);
        }
    }
}

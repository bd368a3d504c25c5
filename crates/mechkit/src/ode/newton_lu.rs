//! The factorisation of an implicit method's Newton matrix `μ I − ν J`: dense ([`Lu`]), or
//! banded ([`BandedLu`]) in the order of a [`BandPlan`] when the system's Jacobian pattern
//! makes that cheaper; for a second-order system, of the matrix reduced to its positions
//! ([`Reduction`]). Callers fill and solve in the system's own order of the unknowns; the
//! reduction and the reordering stay inside.

use super::band_plan::BandPlan;
use super::banded::BandedLu;
use super::linalg::{Lu, Scalar, Singular};
use super::reduction::Reduction;
use super::system::OdeSystem;
use crate::Real;

/// A Newton matrix's LU factorisation, dense or banded, whole or reduced.
#[derive(Debug, Clone, Default)]
pub(crate) struct NewtonLu<T> {
    dense: Lu<T>,
    banded: BandedLu<T>,
    /// The band plan of the matrix factored (the reduced one when reducing).
    plan: Option<BandPlan>,
    reduction: Option<Reduction<T>>,
    /// Whether a plan was made for the current system (dense or banded).
    planned: bool,
    /// The right-hand side in the plan's order.
    work: Vec<T>,
}

impl<T: Scalar + Default> NewtonLu<T> {
    /// Plans the factorisations of `sys`'s Newton matrices of size `n`: reduced to the
    /// positions when it is a second-order system ([`OdeSystem::second_order_dof`]), banded
    /// when its [`OdeSystem::jacobian_pattern`] makes that cheaper, else dense.
    pub fn plan<S: OdeSystem + ?Sized>(&mut self, sys: &S, n: usize) {
        let pattern = sys.jacobian_pattern().filter(|p| p.dim() == n);
        if let Some(d) = sys.second_order_dof().filter(|&d| d > 0 && 2 * d <= n) {
            let (reduction, reduced) = Reduction::new(d, n, pattern);
            self.plan = reduced.and_then(|p| BandPlan::choose(&p));
            self.reduction = Some(reduction);
        } else {
            self.plan = pattern.and_then(|p| BandPlan::choose(&p));
            self.reduction = None;
        }
        self.planned = true;
    }

    /// Factors the whole matrix, banded with `plan` from now on, or dense with `None`.
    #[cfg(test)]
    pub fn set_plan(&mut self, plan: Option<BandPlan>) {
        self.plan = plan;
        self.reduction = None;
        self.planned = true;
    }

    /// Whether a plan was made since [`NewtonLu::forget_plan`].
    pub fn is_planned(&self) -> bool {
        self.planned
    }

    /// Factors dense until told otherwise (for a new system or size).
    pub fn forget_plan(&mut self) {
        self.plan = None;
        self.reduction = None;
        self.planned = false;
    }

    /// `(kl, ku)` of the banded factorisation, `None` when dense.
    pub fn band(&self) -> Option<(usize, usize)> {
        self.plan.as_ref().map(|p| (p.kl, p.ku))
    }

    /// The size of the matrix factored when it is reduced to a second-order system's
    /// positions; `None` when the whole matrix is.
    pub fn reduced_to(&self) -> Option<usize> {
        self.reduction.as_ref().map(Reduction::dof)
    }

    /// Factors `μ I − ν J` of size `n` (`jac` row-major `n × n`).
    pub fn factor(&mut self, n: usize, mu: T, nu: Real, jac: &[Real]) -> Result<(), Singular> {
        if self.reduction.as_ref().is_some_and(|r| r.size() != n) {
            self.forget_plan();
        }
        match &mut self.reduction {
            Some(r) => {
                r.prepare(mu, nu, jac)?;
                let r = &*r;
                let (d, plan) = (r.dof(), &mut self.plan);
                let (dense, banded) = (&mut self.dense, &mut self.banded);
                factor_in(plan, dense, banded, d, |i, j| r.entry(i, j, nu, jac))
            }
            None => factor_in(
                &mut self.plan,
                &mut self.dense,
                &mut self.banded,
                n,
                |r, c| {
                    let m = T::from_real(-nu * jac[r * n + c]);
                    if r == c { mu + m } else { m }
                },
            ),
        }
    }

    /// Solves `A x = b` in place.
    pub fn solve(&mut self, b: &mut [T]) {
        match &mut self.reduction {
            Some(r) => {
                r.reduce(b);
                let mut x = std::mem::take(&mut r.work);
                solve_in(
                    self.plan.as_ref(),
                    &self.dense,
                    &self.banded,
                    &mut self.work,
                    &mut x,
                );
                r.work = x;
                r.expand(b);
            }
            None => solve_in(
                self.plan.as_ref(),
                &self.dense,
                &self.banded,
                &mut self.work,
                b,
            ),
        }
    }
}

/// Factors the matrix `fill(r, c)` of size `n`, banded with `plan` (a plan made for another
/// size is dropped: only the entries inside its band are asked for) or dense.
fn factor_in<T: Scalar + Default>(
    plan: &mut Option<BandPlan>,
    dense: &mut Lu<T>,
    banded: &mut BandedLu<T>,
    n: usize,
    fill: impl Fn(usize, usize) -> T,
) -> Result<(), Singular> {
    if plan.as_ref().is_some_and(|p| p.order.len() != n) {
        *plan = None;
    }
    match plan {
        Some(p) => {
            let o = &p.order;
            banded
                .factor(n, p.kl, p.ku, |r, c| fill(o[r], o[c]))
                .map_err(|Singular { col }| Singular { col: o[col] })
        }
        None => dense.factor(n, fill),
    }
}

/// Solves with the factorisation [`factor_in`] made, in place (`work`: scratch).
fn solve_in<T: Scalar + Default>(
    plan: Option<&BandPlan>,
    dense: &Lu<T>,
    banded: &BandedLu<T>,
    work: &mut Vec<T>,
    b: &mut [T],
) {
    match plan {
        Some(p) => {
            work.clear();
            work.extend(p.order.iter().map(|&i| b[i]));
            banded.solve(work);
            for (&i, &x) in p.order.iter().zip(work.iter()) {
                b[i] = x;
            }
        }
        None => dense.solve(b),
    }
}

#[cfg(test)]
mod tests {
    use nalgebra::Complex;

    use super::*;
    use crate::ode::pattern::JacobianPattern;

    /// A made-up entry in `[-2, 2]`.
    fn entry(r: usize, c: usize) -> Real {
        ((r * 7 + c * 3) % 5) as Real - 2.0 + 0.1 * (r as Real - c as Real).sin()
    }

    /// A chain of 12 masses' pattern `[[0, I], [A, A]]`.
    fn chain_pattern(n: usize) -> JacobianPattern {
        let mut a = JacobianPattern::new(n);
        for i in 0..n {
            for j in i.saturating_sub(1)..(i + 2).min(n) {
                a.insert(i, j);
            }
        }
        a.second_order(0)
    }

    #[test]
    fn a_reordered_band_solves_like_the_dense_lu() {
        let p = chain_pattern(12);
        let m = p.dim();
        let jac: Vec<Real> = (0..m * m)
            .map(|k| {
                let (r, c) = (k / m, k % m);
                if p.contains(r, c) { entry(r, c) } else { 0.0 }
            })
            .collect();
        let x: Vec<Real> = (0..m).map(|i| (i as Real).sin()).collect();
        // M = 3 I − J
        let b: Vec<Real> = (0..m)
            .map(|r| {
                let jx: Real = (0..m).map(|c| jac[r * m + c] * x[c]).sum();
                3.0 * x[r] - jx
            })
            .collect();
        let mut banded = NewtonLu::default();
        banded.set_plan(BandPlan::choose(&p));
        assert!(banded.band().is_some());
        banded.factor(m, 3.0, 1.0, &jac).unwrap();
        let mut xb = b.clone();
        banded.solve(&mut xb);
        let mut dense = NewtonLu::default();
        dense.factor(m, 3.0, 1.0, &jac).unwrap();
        let mut xd = b;
        dense.solve(&mut xd);
        for i in 0..m {
            assert!((xb[i] - x[i]).abs() < 1e-10, "{xb:?}");
            assert!((xd[i] - x[i]).abs() < 1e-10);
        }
    }

    /// A second-order system of `dof` coordinates and `extra` components carried along, with
    /// a pattern or without.
    struct Structured {
        dof: usize,
        extra: usize,
        pattern: Option<JacobianPattern>,
    }

    impl OdeSystem for Structured {
        fn dim(&self) -> usize {
            2 * self.dof + self.extra
        }
        fn rhs_into(&self, _t: Real, _y: &[Real], _dydt: &mut [Real]) {}
        fn jacobian_pattern(&self) -> Option<JacobianPattern> {
            self.pattern.clone()
        }
        fn second_order_dof(&self) -> Option<usize> {
            Some(self.dof)
        }
    }

    impl Structured {
        /// A Jacobian `[[0, I, 0], [A_q, A_v, 0], [E_q, E_v, E_e]]` with this structure.
        fn jacobian(&self) -> Vec<Real> {
            let (d, n) = (self.dof, self.dim());
            let mut jac = vec![0.0; n * n];
            for r in 0..n {
                for c in 0..n {
                    let may = match &self.pattern {
                        Some(p) => p.contains(r, c),
                        None => true,
                    };
                    jac[r * n + c] = if r < d {
                        if c == d + r { 1.0 } else { 0.0 }
                    } else if (c < 2 * d || c == r) && may {
                        entry(r, c)
                    } else {
                        0.0
                    };
                }
            }
            jac
        }
    }

    /// `(μ I − ν J) x = b` solved reduced and whole: the same `x`.
    fn reduced_matches_whole<T>(sys: &Structured, mu: T, nu: Real, banded: bool)
    where
        T: Scalar + Default + std::fmt::Debug + Into<Complex<Real>>,
    {
        let n = sys.dim();
        let jac = sys.jacobian();
        let mut reduced = NewtonLu::<T>::default();
        reduced.plan(sys, n);
        assert_eq!(reduced.reduced_to(), Some(sys.dof));
        assert_eq!(reduced.band().is_some(), banded);
        reduced.factor(n, mu, nu, &jac).unwrap();
        let mut whole = NewtonLu::<T>::default();
        whole.set_plan(None);
        whole.factor(n, mu, nu, &jac).unwrap();
        let b: Vec<T> = (0..n)
            .map(|i| T::from_real((i as Real + 0.5).cos()))
            .collect();
        let (mut xr, mut xw) = (b.clone(), b);
        reduced.solve(&mut xr);
        whole.solve(&mut xw);
        for i in 0..n {
            let (r, w): (Complex<Real>, Complex<Real>) = (xr[i].into(), xw[i].into());
            assert!(
                (r - w).norm() < 1e-11 * (1.0 + w.norm()),
                "{i}: {xr:?} vs {xw:?}"
            );
        }
    }

    #[test]
    fn a_second_order_system_is_solved_in_its_positions() {
        // dense, with two components carried along; radau5's real and complex matrices and
        // BDF's `I − c J`
        let dense = Structured {
            dof: 5,
            extra: 2,
            pattern: None,
        };
        reduced_matches_whole(&dense, 3.3, 1.0, false);
        reduced_matches_whole(&dense, Complex::new(2.7, 3.05), 1.0, false);
        reduced_matches_whole(&dense, 1.0, 0.37, false);
        // a chain of 12: the reduced matrix is tridiagonal
        let chain = Structured {
            dof: 12,
            extra: 0,
            pattern: Some(chain_pattern(12)),
        };
        reduced_matches_whole(&chain, 3.3, 1.0, true);
        reduced_matches_whole(&chain, Complex::new(2.7, 3.05), 1.0, true);
        let mut lu = NewtonLu::<Real>::default();
        lu.plan(&chain, 24);
        assert_eq!(lu.band(), Some((1, 1)));
    }
}

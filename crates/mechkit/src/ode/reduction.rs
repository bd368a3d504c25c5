//! The Newton matrix `M = μ I − ν J` of a second-order system, solved in its positions alone.
//!
//! With the state `y = [q, v, e]`, `q' = v` exactly, and no derivative depending on `e`
//! (quantities carried along, like the works of forces: [`OdeSystem::second_order_dof`]), the
//! Jacobian is `[[0, I, 0], [A_q, A_v, 0], [E_q, E_v, E_e]]` with `E_e` diagonal, and `M x = r`
//! reads
//!
//! ```text
//!           μ x_q −           ν x_v          = r_q
//!     −ν A_q x_q + (μ I − ν A_v) x_v          = r_v
//!     −ν E_q x_q −        ν E_v x_v + M_ee x_e = r_e
//! ```
//!
//! The first row gives `x_v = (μ x_q − r_q) / ν`; put into the second,
//! `(μ² I − μ ν A_v − ν² A_q) x_q = ν r_v + (μ I − ν A_v) r_q`: `dof` unknowns instead of
//! `2 dof + e` (a dense factorisation costs an eighth, a chain's band is a third as wide), and
//! the last row gives `x_e` directly. Hairer's RADAU5 does the same for such systems
//! (`M1 = M2` in its `IWORK(9)`; Hairer & Wanner, *Solving ODEs II*, Sec. IV.8).
//!
//! [`OdeSystem::second_order_dof`]: super::OdeSystem::second_order_dof

use super::linalg::{Scalar, Singular};
use super::pattern::JacobianPattern;
use crate::Real;

/// The reduction of a Newton matrix of size `n` to its `dof` positions: the places of the
/// entries it needs, and their values at the last factorisation.
#[derive(Debug, Clone)]
pub(crate) struct Reduction<T> {
    /// The number of positions (and of velocities, after them).
    dof: usize,
    /// The size of the whole matrix.
    n: usize,
    /// The Jacobian's pattern, when the system gave one (else every entry may be non-zero).
    pattern: Option<JacobianPattern>,
    /// At the last factorisation, row by row from row `dof` on (velocities, then the rest):
    /// the non-zero entries of `M` that the solve uses (`μ I − ν A_v` in the velocity rows,
    /// with its column less `dof`; `−ν E_q`, `−ν E_v` in the rest), compressed by rows.
    start: Vec<usize>,
    cols: Vec<usize>,
    vals: Vec<T>,
    /// `μ`, `1 / ν` and `1 / M_ee` of the last factorisation.
    mu: T,
    inv_nu: Real,
    inv_rest: Vec<T>,
    /// The reduced right-hand side.
    pub work: Vec<T>,
}

impl<T: Scalar + Default> Reduction<T> {
    /// The reduction of matrices of size `n` with `dof` positions (`2 dof ≤ n`), and the
    /// pattern of its reduced matrix `μ² I − μ ν A_v − ν² A_q` when `pattern` is known.
    pub fn new(
        dof: usize,
        n: usize,
        pattern: Option<JacobianPattern>,
    ) -> (Self, Option<JacobianPattern>) {
        debug_assert!(dof > 0 && 2 * dof <= n);
        let reduced = pattern.as_ref().map(|p| {
            let mut s = JacobianPattern::new(dof);
            for i in 0..dof {
                s.insert(i, i);
                for &c in p.row(dof + i).iter().filter(|&&c| c < 2 * dof) {
                    s.insert(i, c % dof);
                }
            }
            s
        });
        let reduction = Self {
            dof,
            n,
            pattern,
            start: Vec::new(),
            cols: Vec::new(),
            vals: Vec::new(),
            mu: T::default(),
            inv_nu: 0.0,
            inv_rest: Vec::new(),
            work: vec![T::default(); dof],
        };
        (reduction, reduced)
    }

    /// The number of positions: the size of the reduced matrix.
    pub fn dof(&self) -> usize {
        self.dof
    }

    /// The size of the whole matrix.
    pub fn size(&self) -> usize {
        self.n
    }

    /// Keeps what [`Reduction::solve`] needs of `M = μ I − ν J` (`jac` row-major `n × n`);
    /// `Singular` when `ν` or a diagonal entry of the rest is zero.
    pub fn prepare(&mut self, mu: T, nu: Real, jac: &[Real]) -> Result<(), Singular> {
        let (d, n) = (self.dof, self.n);
        if !(nu != 0.0 && nu.is_finite()) {
            return Err(Singular { col: 0 });
        }
        (self.mu, self.inv_nu) = (mu, 1.0 / nu);
        self.start.clear();
        self.cols.clear();
        self.vals.clear();
        self.inv_rest.clear();
        self.start.push(0);
        for r in d..n {
            let row = &jac[r * n..(r + 1) * n];
            // velocity rows: the velocity columns; the rest: the position and velocity columns
            let (lo, hi) = if r < 2 * d { (d, 2 * d) } else { (0, 2 * d) };
            let mut keep = |c: usize| {
                let m = if c == r {
                    mu - T::from_real(nu * row[c])
                } else {
                    T::from_real(-nu * row[c])
                };
                if m.size() != 0.0 {
                    self.cols.push(if r < 2 * d { c - d } else { c });
                    self.vals.push(m);
                }
            };
            match &self.pattern {
                Some(p) => p
                    .row(r)
                    .iter()
                    .filter(|&&c| (lo..hi).contains(&c) && c != r)
                    .for_each(|&c| keep(c)),
                None => (lo..hi).filter(|&c| c != r).for_each(&mut keep),
            }
            if r < 2 * d {
                keep(r);
            } else {
                let diagonal = mu - T::from_real(nu * row[r]);
                if !(diagonal.size() > 0.0 && diagonal.size().is_finite()) {
                    return Err(Singular { col: r });
                }
                self.inv_rest.push(diagonal.recip());
            }
            self.start.push(self.cols.len());
        }
        Ok(())
    }

    /// The entry `(i, j)` of the reduced matrix `μ² I − μ ν A_v − ν² A_q`.
    pub fn entry(&self, i: usize, j: usize, nu: Real, jac: &[Real]) -> T {
        let (d, n, mu) = (self.dof, self.n, self.mu);
        let row = (d + i) * n;
        let s = mu * T::from_real(-nu * jac[row + d + j]) - T::from_real(nu * nu * jac[row + j]);
        if i == j { s + mu * mu } else { s }
    }

    /// Puts the reduced right-hand side `ν r_v + (μ I − ν A_v) r_q` of `b = r` into
    /// [`Reduction::work`].
    pub fn reduce(&mut self, b: &[T]) {
        let d = self.dof;
        let nu = T::from_real(self.inv_nu.recip());
        for i in 0..d {
            let mut s = nu * b[d + i];
            for e in self.start[i]..self.start[i + 1] {
                s = s + self.vals[e] * b[self.cols[e]];
            }
            self.work[i] = s;
        }
    }

    /// Given the positions' solution in [`Reduction::work`], writes the whole solution `x`
    /// over `b = r`.
    pub fn expand(&self, b: &mut [T]) {
        let (d, n) = (self.dof, self.n);
        let inv_nu = T::from_real(self.inv_nu);
        for i in 0..d {
            let xq = self.work[i];
            b[d + i] = (self.mu * xq - b[i]) * inv_nu;
            b[i] = xq;
        }
        for (k, r) in (2 * d..n).enumerate() {
            let mut s = b[r];
            for e in self.start[r - d]..self.start[r - d + 1] {
                s = s - self.vals[e] * b[self.cols[e]];
            }
            b[r] = s * self.inv_rest[k];
        }
    }
}

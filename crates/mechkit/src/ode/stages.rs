//! The stage vectors of an explicit Runge-Kutta step and the fused loops that combine them.
//!
//! Stage `l` is stored in blocks of [`LANES`] components (`k_l = k[l nb .. (l + 1) nb]`, the
//! last block padded with zeros), so that every combination `y + h Σ_j a_ij k_j` is one pass
//! over the blocks with the tableau row's non-zero coefficients in the inner loop: the
//! accumulator stays in registers, the block loop has no remainder, and the compiler unrolls
//! and vectorises it whatever the length of the state. The arithmetic per component is that of
//! the plain loops (`c₀ k₀ + c₁ k₁ + …` from the left, then `y + h ·`), so the results are the
//! same bit for bit.

use super::blocks::{Block, LANES, block_sum, blocks, store, store_block, sum_by_rows};
use super::fixed::FixedTableau;
use super::stepper::Provided;
use super::system::OdeSystem;
use super::tableau::Tableau;
use crate::Real;

/// The non-zero entries of a row of coefficients: `(stage, coefficient)`.
pub(crate) type Sparse = Vec<(usize, Real)>;

/// The non-zero entries of `row`.
pub(crate) fn sparse(row: &[Real]) -> Sparse {
    row.iter()
        .copied()
        .enumerate()
        .filter(|(_, c)| *c != 0.0)
        .collect()
}

/// Stage buffers for a tableau, stored in blocks (see the module docs), with the tableau's
/// rows as lists of non-zero coefficients.
#[derive(Debug, Clone)]
pub(crate) struct Stages {
    /// Components.
    n: usize,
    /// Blocks per stage.
    nb: usize,
    k: Vec<Block>,
    /// The state the stages start from, in blocks.
    y: Vec<Block>,
    /// The argument of the stage being evaluated.
    tmp: Vec<Block>,
    /// Sums of stages ([`sum_by_rows`]).
    acc: Vec<Block>,
    rows: Vec<Sparse>,
    weights: Sparse,
    pub provided: Provided,
}

impl Stages {
    /// Buffers for `tab`'s stages (sized by [`Stages::resize`]).
    pub fn new(tab: &Tableau) -> Self {
        Self {
            n: 0,
            nb: 0,
            k: Vec::new(),
            y: Vec::new(),
            tmp: Vec::new(),
            acc: Vec::new(),
            rows: tab.a.iter().map(|r| sparse(r)).collect(),
            weights: sparse(&tab.b),
            provided: Provided::default(),
        }
    }

    /// Room for `count` stage vectors of length `n`.
    #[inline]
    pub fn resize(&mut self, count: usize, n: usize) {
        if self.n != n {
            self.n = n;
            self.nb = n.div_ceil(LANES);
            // the padding must stay zero: start afresh
            self.k.clear();
            self.y.clear();
            self.tmp.clear();
            self.acc.clear();
            self.y.resize(self.nb, [0.0; LANES]);
            self.tmp.resize(self.nb, [0.0; LANES]);
            self.acc.resize(self.nb, [0.0; LANES]);
        }
        if self.k.len() < count * self.nb {
            self.k.resize(count * self.nb, [0.0; LANES]);
        }
    }

    /// Stage `l`.
    pub fn k(&self, l: usize) -> &[Real] {
        &self.k[l * self.nb..(l + 1) * self.nb].as_flattened()[..self.n]
    }

    /// Stage `l`, to write.
    pub fn k_mut(&mut self, l: usize) -> &mut [Real] {
        let n = self.n;
        &mut self.k[l * self.nb..(l + 1) * self.nb].as_flattened_mut()[..n]
    }

    /// Component `i` of stage `l`.
    #[inline]
    pub fn at(&self, l: usize, i: usize) -> Real {
        self.k[l * self.nb + i / LANES][i % LANES]
    }

    /// Copies stage `from` into stage `to`.
    #[inline]
    pub fn copy_stage(&mut self, from: usize, to: usize) {
        let nb = self.nb;
        for b in 0..nb {
            self.k[to * nb + b] = self.k[from * nb + b];
        }
    }

    /// `out = Σ_{(l, c) in row} c k_l` for the stages held.
    #[inline]
    pub fn combine_into(&self, row: &[(usize, Real)], out: &mut [Real]) {
        if self.nb == 1 {
            self.combine_nb::<1>(row, out);
        } else {
            sum_by_rows(&self.k, self.nb, row, out);
        }
    }

    #[allow(clippy::inline_always)] // as `block_sum`
    #[inline(always)]
    fn combine_nb<const NB: usize>(&self, row: &[(usize, Real)], out: &mut [Real]) {
        let (k, nb) = (&self.k, blocks::<NB>(self.nb));
        for (b, o) in out.chunks_mut(LANES).enumerate().take(nb) {
            store(block_sum(k, nb, row, b), o);
        }
    }

    /// `out = y + h Σ_{(l, c) in row} c k_l`, with `y` the state loaded by the last
    /// [`Stages::compute`] or [`Stages::stage_from`].
    #[inline]
    pub fn advance_into(&mut self, row: &[(usize, Real)], h: Real, out: &mut [Real]) {
        if self.nb == 1 {
            self.advance_nb::<1>(row, h, out);
        } else {
            sum_by_rows(&self.k, self.nb, row, self.acc.as_flattened_mut());
            let m = out.len();
            let (acc, y) = (&self.acc.as_flattened()[..m], &self.y.as_flattened()[..m]);
            for i in 0..m {
                out[i] = y[i] + h * acc[i];
            }
        }
    }

    #[allow(clippy::inline_always)] // as `block_sum`
    #[inline(always)]
    fn advance_nb<const NB: usize>(&self, row: &[(usize, Real)], h: Real, out: &mut [Real]) {
        let (k, nb, y) = (&self.k, blocks::<NB>(self.nb), &self.y);
        for (b, (o, yb)) in out.chunks_mut(LANES).zip(&y[..nb]).enumerate() {
            let acc = block_sum(k, nb, row, b);
            let mut v = [0.0; LANES];
            for j in 0..LANES {
                v[j] = yb[j] + h * acc[j];
            }
            store(v, o);
        }
    }

    /// `y + h Σ b_i k_i`, the solution at the end of the step computed by
    /// [`Stages::compute`].
    #[inline]
    pub fn solution_into(&mut self, h: Real, out: &mut [Real]) {
        let weights = std::mem::take(&mut self.weights);
        self.advance_into(&weights, h, out);
        self.weights = weights;
    }

    /// Copies `y` into the blocks the stages start from.
    #[inline]
    fn load(&mut self, y: &[Real]) {
        if self.nb == 1 {
            store_block(y, &mut self.y[0]);
        } else {
            self.y.as_flattened_mut()[..y.len()].copy_from_slice(y);
        }
    }

    /// Evaluates stage `into` at `t` from `y + h Σ_{(l, c) in row} c k_l`, `y` loaded. The
    /// small terms are summed before they are added to `y`, which keeps round-off at the level
    /// of `y`'s last bit.
    #[allow(clippy::inline_always)] // as `block_sum`
    #[inline(always)]
    fn stage<const NB: usize, S: OdeSystem + ?Sized>(
        &mut self,
        sys: &S,
        row: &[(usize, Real)],
        t: Real,
        h: Real,
        into: usize,
    ) {
        let (n, nb) = (self.n, blocks::<NB>(self.nb));
        for (b, (yb, tb)) in self.y[..nb].iter().zip(&mut self.tmp[..nb]).enumerate() {
            let acc = block_sum(&self.k, nb, row, b);
            let mut o = [0.0; LANES];
            for j in 0..LANES {
                o[j] = yb[j] + h * acc[j];
            }
            *tb = o;
        }
        let arg = &self.tmp.as_flattened()[..n];
        let out = &mut self.k[into * nb..(into + 1) * nb].as_flattened_mut()[..n];
        sys.rhs_into(t, arg, out);
    }

    /// [`Stages::stage`] for a row given as data.
    #[inline]
    fn stage_general<S: OdeSystem + ?Sized>(
        &mut self,
        sys: &S,
        row: &[(usize, Real)],
        t: Real,
        h: Real,
        into: usize,
    ) {
        if self.nb == 1 {
            self.stage::<1, S>(sys, row, t, h, into);
            return;
        }
        let (n, nb) = (self.n, self.nb);
        sum_by_rows(&self.k, nb, row, self.acc.as_flattened_mut());
        let (tmp, acc, y) = (
            self.tmp.as_flattened_mut(),
            self.acc.as_flattened(),
            self.y.as_flattened(),
        );
        let m = tmp.len();
        let (acc, y) = (&acc[..m], &y[..m]);
        for i in 0..m {
            tmp[i] = y[i] + h * acc[i];
        }
        let arg = &self.tmp.as_flattened()[..n];
        let out = &mut self.k[into * nb..(into + 1) * nb].as_flattened_mut()[..n];
        sys.rhs_into(t, arg, out);
    }

    /// Evaluates stage `into` at `t` from `y + h Σ_{(l, c) in row} c k_l`.
    pub fn stage_from<S: OdeSystem + ?Sized>(
        &mut self,
        sys: &S,
        row: &[(usize, Real)],
        t: Real,
        y: &[Real],
        h: Real,
        into: usize,
    ) {
        self.load(y);
        self.stage_general(sys, row, t, h, into);
    }

    /// Evaluates `f(t, y)` into stage `l`.
    #[inline]
    pub fn eval_into<S: OdeSystem + ?Sized>(&mut self, sys: &S, t: Real, y: &[Real], l: usize) {
        sys.rhs_into(t, y, self.k_mut(l));
    }

    /// Computes the stages of `tab` from `(t, y)` with step `h` and returns the evaluations
    /// made; [`Stages::solution_into`] then gives the new state. Stage 0 must already hold
    /// `f(t, y)` when `k0_known`.
    #[inline]
    pub fn compute<S: OdeSystem + ?Sized>(
        &mut self,
        tab: &Tableau,
        sys: &S,
        t: Real,
        y: &[Real],
        h: Real,
        k0_known: bool,
    ) -> usize {
        let s = tab.stages();
        let mut evaluations = 0;
        if !k0_known {
            self.eval_into(sys, t, y, 0);
            evaluations += 1;
        }
        self.load(y);
        let rows = std::mem::take(&mut self.rows);
        for (i, (row, c)) in rows[1..s].iter().zip(&tab.c[1..s]).enumerate() {
            self.stage_general(sys, row, t + c * h, h, i + 1);
        }
        self.rows = rows;
        evaluations + s - 1
    }

    /// [`Stages::compute`] for a tableau whose coefficients are constants: every stage is
    /// written out with its row, so that the loops over the rows are unrolled with the
    /// coefficients in the code. Stage 0 must hold `f(t, y)`.
    #[allow(clippy::inline_always)] // one copy per tableau, each with its constants
    #[inline(always)]
    pub fn compute_fixed<T: FixedTableau, S: OdeSystem + ?Sized>(
        &mut self,
        sys: &S,
        t: Real,
        y: &[Real],
        h: Real,
    ) -> usize {
        self.load(y);
        if self.nb == 1 {
            self.fixed_stages::<T, 1, S>(sys, t, h);
        } else {
            self.fixed_stages::<T, 0, S>(sys, t, h);
        }
        T::A.len() - 1
    }

    #[allow(clippy::inline_always)] // as `compute_fixed`
    #[inline(always)]
    fn fixed_stages<T: FixedTableau, const NB: usize, S: OdeSystem + ?Sized>(
        &mut self,
        sys: &S,
        t: Real,
        h: Real,
    ) {
        macro_rules! stages {
            ($($i:literal)*) => {$(
                if $i < T::A.len() {
                    self.stage::<NB, S>(sys, T::A[$i], t + T::C[$i] * h, h, $i);
                }
            )*};
        }
        stages!(1 2 3 4 5 6 7 8 9 10 11 12 13 14 15);
        debug_assert!(T::A.len() <= 16, "more stages than written out");
    }

    /// [`Stages::combine_into`] for a row of constants (inlined, its loop unrolled).
    #[allow(clippy::inline_always)] // as `compute_fixed`
    #[inline(always)]
    pub fn combine_fixed(&self, row: &'static [(usize, Real)], out: &mut [Real]) {
        if self.nb == 1 {
            self.combine_nb::<1>(row, out);
        } else {
            self.combine_nb::<0>(row, out);
        }
    }

    /// [`Stages::advance_into`] for a row of constants (inlined, its loop unrolled).
    #[allow(clippy::inline_always)] // as `compute_fixed`
    #[inline(always)]
    pub fn advance_fixed(&self, row: &'static [(usize, Real)], h: Real, out: &mut [Real]) {
        if self.nb == 1 {
            self.advance_nb::<1>(row, h, out);
        } else {
            self.advance_nb::<0>(row, h, out);
        }
    }

    /// Puts the derivative handed in for time `t` (if any) into stage 0; whether there was one.
    pub fn take_provided(&mut self, t: Real) -> bool {
        if !self.provided.take(t) {
            return false;
        }
        let (n, nb) = (self.n, self.nb);
        self.k[..nb].as_flattened_mut()[..n].copy_from_slice(&self.provided.dydt);
        true
    }

    /// `Σ b_i k_i` (the increment of the solution divided by `h`) into `slope`.
    pub fn slope_into(&self, slope: &mut [Real]) {
        self.combine_into(&self.weights, slope);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `y' = (1, 2, …, n)`: every stage is the same vector.
    struct Ramp(usize);

    impl OdeSystem for Ramp {
        fn dim(&self) -> usize {
            self.0
        }

        fn rhs_into(&self, _t: Real, y: &[Real], dydt: &mut [Real]) {
            assert_eq!(y.len(), self.0, "the stage argument has the state's length");
            for (i, d) in dydt.iter_mut().enumerate() {
                *d = (i + 1) as Real;
            }
        }
    }

    #[test]
    fn blocks_hold_states_of_any_length() {
        let tab = Tableau::rk4();
        for n in [1, 3, 4, 5, 8, 9, 13] {
            let mut st = Stages::new(&tab);
            st.resize(tab.stages(), n);
            let y: Vec<Real> = (0..n).map(|i| 10.0 * i as Real).collect();
            assert_eq!(st.compute(&tab, &Ramp(n), 0.0, &y, 0.5, false), 4);
            let mut out = vec![0.0; n];
            st.solution_into(0.5, &mut out);
            for i in 0..n {
                let want = y[i] + 0.5 * (i + 1) as Real;
                assert!(
                    (out[i] - want).abs() <= 1e-12 * want.max(1.0),
                    "n = {n}, i = {i}"
                );
                assert_eq!(st.at(3, i), (i + 1) as Real);
            }
            assert_eq!(st.k(2).len(), n);
            // a change of length starts afresh
            st.resize(tab.stages(), n + 1);
            assert!(st.k(0).iter().all(|v| *v == 0.0));
        }
    }
}

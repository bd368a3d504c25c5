//! Pair forces written into a kernel ([`ForceEmitter`]): the compiled `F(r)` inlined, the
//! cut-off and the undefined line of centres (`r = 0`) as selects, in the operations and
//! order of [`PairForce`]'s `add_forces`, so the fused step and the compiled Jacobian of the
//! implicit methods ([`crate::particles::CompiledJacobian`]) see pair potentials too.

use mechkit_expr::{BinOp, Val};

use super::{PairForce, RadialPotential};
use crate::forces::ForceEmitter;

impl RadialPotential {
    /// `F(r)/r` as a kernel value: NaN at `r = 0`, zero beyond the cut-off.
    fn emit_force_over_r(&self, e: &mut ForceEmitter<'_>, r: Val) -> Val {
        let f = e.b().inline(&self.force, &[r]);
        let f = match self.cutoff {
            Some(rc) => {
                let rc = e.constant(rc);
                let cut = e.b().compare(BinOp::Ge, r, rc);
                let zero = e.constant(0.0);
                e.b().select(cut, zero, f)
            }
            None => f,
        };
        let per_r = e.b().div(f, r);
        let zero = e.constant(0.0);
        let coincident = e.b().compare(BinOp::Eq, r, zero);
        let nan = e.constant(f64::NAN);
        e.b().select(coincident, nan, per_r)
    }
}

impl PairForce {
    /// Every pair `(a, b)`: `d = x_a - x_b`, `s = F(r)/r`, `out_a += s d`, `out_b -= s d`.
    pub(super) fn emit_pairs(&self, e: &mut ForceEmitter<'_>) -> bool {
        let dim = e.dim();
        for &(a, b) in &self.pairs {
            let xa: Vec<Val> = (0..dim).map(|i| e.x(a, i)).collect();
            let xb: Vec<Val> = (0..dim).map(|i| e.x(b, i)).collect();
            let (d, r) = e.separation(&xa, &xb);
            let s = self.law.emit_force_over_r(e, r);
            for (i, di) in d.into_iter().enumerate() {
                let f = e.b().mul(s, di);
                e.add(a * dim + i, f);
                e.sub(b * dim + i, f);
            }
        }
        true
    }
}

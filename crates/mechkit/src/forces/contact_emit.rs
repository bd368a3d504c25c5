//! Contact forces written into a kernel ([`ForceEmitter`]): the elastic part
//! ([`ContactForce`]) and the damper ([`super::ContactDamper`]) as the same IEEE operations,
//! in the same order, as their `add_forces`, so the fused step and the compiled Jacobian of
//! the implicit methods ([`crate::particles::CompiledJacobian`]) see the contact laws too.
//!
//! A contact that does not touch adds nothing in the general loop; in a kernel, which has no
//! branches, every contact is computed and its force selected to zero where it does not
//! touch (`if(apart, 0, F n̂)`). Adding that zero changes nothing but the sign of an exact
//! zero, and a select's derivative is that of the branch it takes, so the Jacobian of a
//! contact that does not touch is exactly zero (the NaN of `sqrt(δ)` for `δ < 0` in the branch
//! not taken never reaches it).

use mechkit_expr::{BinOp, Func, Val};

use super::contact::ContactForce;
use super::contact_law::{ContactDamping, ContactLaw};
use super::emit::ForceEmitter;

/// One contact as kernel values: `b` is pushed along `n` (and `a`, if a body, against it)
/// unless `apart` (1 where the general loop skips the contact).
pub(super) struct TouchVals {
    apart: Val,
    a: Option<usize>,
    b: usize,
    n: Vec<Val>,
    /// The overlap `δ` (meaningful where not apart).
    pub(super) delta: Val,
    /// Its rate `δ̇`.
    pub(super) rate: Val,
}

impl ContactForce {
    /// Emits `magnitude(δ, δ̇) n̂` for every contact, pairs first then walls (the order of
    /// `for_each_touch`), each selected to zero where the contact is apart.
    pub(super) fn emit_touches(
        &self,
        e: &mut ForceEmitter<'_>,
        mut magnitude: impl FnMut(&mut ForceEmitter<'_>, &TouchVals) -> Val,
    ) -> bool {
        if e.dim() != self.dim {
            return false;
        }
        let touches = self.touch_vals(e);
        let dim = self.dim;
        for t in &touches {
            let m = magnitude(e, t);
            let zero = e.constant(0.0);
            for i in 0..dim {
                let f = e.b().mul(m, t.n[i]);
                let f = e.b().select(t.apart, zero, f);
                e.add(t.b * dim + i, f);
                if let Some(a) = t.a {
                    e.sub(a * dim + i, f);
                }
            }
        }
        true
    }

    /// The contacts' geometry, as `for_each_touch` computes it.
    fn touch_vals(&self, e: &mut ForceEmitter<'_>) -> Vec<TouchVals> {
        let dim = self.dim;
        let mut out = Vec::with_capacity(self.pairs.len() + self.walls.len());
        let zero = e.constant(0.0);
        for p in &self.pairs {
            // n = x_b - x_a, r2 = 0 + Σ n², apart where r2 ≥ reach²
            let raw: Vec<Val> = (0..dim)
                .map(|i| {
                    let (xb, xa) = (e.x(p.b, i), e.x(p.a, i));
                    e.b().sub(xb, xa)
                })
                .collect();
            let r2 = sum(e, raw.iter().map(|c| (*c, *c)));
            let reach2 = e.constant(p.reach * p.reach);
            let apart = e.b().compare(BinOp::Ge, r2, reach2);
            let r = e.b().call(Func::Sqrt, r2);
            // n /= r where r > 0, else +x
            let positive = e.b().compare(BinOp::Gt, r, zero);
            let n: Vec<Val> = raw
                .iter()
                .enumerate()
                .map(|(i, c)| {
                    let unit = e.constant(if i == 0 { 1.0 } else { 0.0 });
                    let q = e.b().div(*c, r);
                    e.b().select(positive, q, unit)
                })
                .collect();
            // δ̇ = Σ (v_a - v_b)·n
            let dv: Vec<Val> = (0..dim)
                .map(|i| {
                    let (va, vb) = (e.v(p.a, i), e.v(p.b, i));
                    e.b().sub(va, vb)
                })
                .collect();
            let rate = sum(e, dv.into_iter().zip(n.iter().copied()));
            let reach = e.constant(p.reach);
            let delta = e.b().sub(reach, r);
            out.push(TouchVals {
                apart,
                a: Some(p.a),
                b: p.b,
                n,
                delta,
                rate,
            });
        }
        for w in &self.walls {
            // d = Σ (x - p)·n, δ = R - d, apart where δ ≤ 0
            let offsets: Vec<(Val, Val)> = (0..dim)
                .map(|i| {
                    let x = e.x(w.body, i);
                    let p = e.constant(w.point[i]);
                    let c = e.b().sub(x, p);
                    (c, e.constant(w.normal[i]))
                })
                .collect();
            let d = sum(e, offsets.into_iter());
            let radius = e.constant(w.radius);
            let delta = e.b().sub(radius, d);
            let apart = e.b().compare(BinOp::Le, delta, zero);
            let n: Vec<Val> = w.normal.iter().map(|c| e.constant(*c)).collect();
            let vn: Vec<(Val, Val)> = (0..dim).map(|i| (e.v(w.body, i), n[i])).collect();
            let s = sum(e, vn.into_iter());
            let rate = e.b().neg(s);
            out.push(TouchVals {
                apart,
                a: None,
                b: w.body,
                n,
                delta,
                rate,
            });
        }
        out
    }
}

/// `Σ a_i b_i` as `Iterator::sum` and the laws' `0.0 +=` loops compute it: both add nothing
/// to the first product.
fn sum(e: &mut ForceEmitter<'_>, terms: impl Iterator<Item = (Val, Val)>) -> Val {
    let mut acc: Option<Val> = None;
    for (a, b) in terms {
        let p = e.b().mul(a, b);
        acc = Some(match acc {
            None => p,
            Some(s) => e.b().add(s, p),
        });
    }
    acc.unwrap_or_else(|| e.constant(0.0))
}

/// [`ContactLaw::force`]: `k δ` or `k δ √δ` for `δ > 0`, zero otherwise.
pub(super) fn emit_law_force(e: &mut ForceEmitter<'_>, law: ContactLaw, delta: Val) -> Val {
    let zero = e.constant(0.0);
    let not_positive = e.b().compare(BinOp::Le, delta, zero);
    let k = e.constant(law.k());
    let kd = e.b().mul(k, delta);
    let f = match law {
        ContactLaw::Linear { .. } => kd,
        ContactLaw::Hertz { .. } => {
            let root = e.b().call(Func::Sqrt, delta);
            e.b().mul(kd, root)
        }
    };
    e.b().select(not_positive, zero, f)
}

/// [`ContactForce::normal_force`] minus the elastic force `fe` (the damper's magnitude):
/// `F_e + F_d`, clamped at zero unless attraction is allowed, zero for `δ ≤ 0`.
pub(super) fn emit_damping(e: &mut ForceEmitter<'_>, contact: &ContactForce, t: &TouchVals) -> Val {
    let law = contact.law();
    let fe = emit_law_force(e, law, t.delta);
    let zero = e.constant(0.0);
    let not_positive = e.b().compare(BinOp::Le, t.delta, zero);
    let damping = match contact.damping() {
        ContactDamping::None => zero,
        ContactDamping::Linear { c } => {
            let c = e.constant(c);
            e.b().mul(c, t.rate)
        }
        ContactDamping::HuntCrossley { alpha } => {
            let alpha = e.constant(alpha);
            let af = e.b().mul(alpha, fe);
            e.b().mul(af, t.rate)
        }
    };
    let total = e.b().add(fe, damping);
    let total = if contact.allows_attraction() {
        total
    } else {
        // f.max(0.0): f where f > 0, else 0 (NaN included)
        let pushes = e.b().compare(BinOp::Gt, total, zero);
        e.b().select(pushes, total, zero)
    };
    let normal = e.b().select(not_positive, zero, total);
    e.b().sub(normal, fe)
}

#[cfg(test)]
#[path = "law_emit_tests.rs"]
mod tests;

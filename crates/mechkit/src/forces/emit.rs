//! Forces written into a fused step kernel ([`mechkit_expr::KernelBuilder`]): the same IEEE
//! operations, in the same order, as each force's [`Force::add_forces`](super::Force), so a
//! fixed-step run gives the same numbers in the compiled kernel as in the general loop.
//!
//! One deliberate difference: the general loop sums into buffers that start at `0.0`, and
//! `0.0 + x` is `x` for every `x` except `-0.0` (it gives `+0.0`). The emitter starts a
//! component at its first contribution instead, which saves an addition on the critical path
//! of every step; results can differ only in the sign of an exact zero.

use mechkit_expr::{Func, KernelBuilder, Val};

use crate::Real;

/// One force's contributions to the force buffer of a kernel's step, and the kinematics it
/// may read (all as kernel values, masses as numbers).
pub struct ForceEmitter<'a> {
    builder: &'a mut KernelBuilder,
    dim: usize,
    t: Val,
    x: &'a [Val],
    v: &'a [Val],
    mass: &'a [Real],
    out: Vec<Option<Val>>,
}

impl<'a> ForceEmitter<'a> {
    /// An emitter over a state of `x.len() / dim` bodies; every component starts at zero.
    pub fn new(
        builder: &'a mut KernelBuilder,
        dim: usize,
        t: Val,
        x: &'a [Val],
        v: &'a [Val],
        mass: &'a [Real],
    ) -> Self {
        Self {
            builder,
            dim,
            t,
            x,
            v,
            mass,
            out: vec![None; x.len()],
        }
    }

    /// The kernel being built, for arithmetic.
    pub fn b(&mut self) -> &mut KernelBuilder {
        self.builder
    }

    /// Dimensions.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// Time.
    pub fn t(&self) -> Val {
        self.t
    }

    /// Position component `i` of body `body`.
    pub fn x(&self, body: usize, i: usize) -> Val {
        self.x[body * self.dim + i]
    }

    /// Velocity component `i` of body `body`.
    pub fn v(&self, body: usize, i: usize) -> Val {
        self.v[body * self.dim + i]
    }

    /// Mass of body `body`.
    pub fn mass(&self, body: usize) -> Real {
        self.mass[body]
    }

    /// A constant.
    pub fn constant(&mut self, c: Real) -> Val {
        self.builder.constant(c)
    }

    /// `out[index] += f`.
    pub fn add(&mut self, index: usize, f: Val) {
        self.out[index] = Some(match self.out[index] {
            None => f,
            Some(o) => self.builder.add(o, f),
        });
    }

    /// `out[index] -= f`.
    pub fn sub(&mut self, index: usize, f: Val) {
        let o = match self.out[index] {
            None => self.builder.constant(0.0),
            Some(o) => o,
        };
        self.out[index] = Some(self.builder.sub(o, f));
    }

    /// `sqrt(Σ a_i²)`, the norm of `crate::particles::norm` and of the force laws' own
    /// loops (`Iterator::sum` starts from `-0.0` and the laws' loops from `0.0`; both add
    /// nothing to the first square).
    pub fn norm(&mut self, a: &[Val]) -> Val {
        let s = sum_of_squares(self.builder, a);
        self.builder.call(Func::Sqrt, s)
    }

    /// `d = a - b` component by component and `|d|`: the force laws' `separation`.
    pub fn separation(&mut self, a: &[Val], b: &[Val]) -> (Vec<Val>, Val) {
        let d: Vec<Val> = a
            .iter()
            .zip(b)
            .map(|(p, q)| self.builder.sub(*p, *q))
            .collect();
        let r = self.norm(&d);
        (d, r)
    }

    /// The force buffer: `None` where nothing was added (exactly zero).
    pub fn into_forces(self) -> Vec<Option<Val>> {
        self.out
    }
}

/// `r2 = 0.0; r2 += d_i²` as the force laws write it: the first `0.0 + d²` is exact (a
/// square is never `-0.0`), so it starts at the first square.
fn sum_of_squares(b: &mut KernelBuilder, d: &[Val]) -> Val {
    let mut r2: Option<Val> = None;
    for &c in d {
        let sq = b.mul(c, c);
        r2 = Some(match r2 {
            None => sq,
            Some(s) => b.add(s, sq),
        });
    }
    r2.unwrap_or_else(|| b.constant(0.0))
}

//! The exact Jacobian of a particle system's accelerations, compiled: every force written
//! into a kernel ([`Force::emit`](crate::forces::Force::emit), the same expressions the fused
//! step uses), differentiated there by forward mode
//! ([`mechkit_expr::KernelBuilder::derivatives`]), and compiled to native code with the
//! accelerations' sub-expressions shared. The implicit methods call it through
//! [`SecondOrderSystem::accel_jacobian_into`](crate::ode::SecondOrderSystem).
//!
//! A system gets one when its forces can all be emitted (formulas and the built-in laws that
//! write themselves into kernels), its coordinates are Cartesian positions with constant
//! masses, and it is not too large ([`MAX_DOF`] coordinates, [`MAX_ENTRIES`] entries that
//! are not structurally zero); otherwise the implicit methods take the Jacobian by finite
//! differences, as before. Only the entries that are not structurally zero are outputs of
//! the kernel, so a chain of a few hundred bodies costs what its few thousand entries cost,
//! and their positions are the pattern the banded solver is planned from.

use mechkit_expr::{Kernel, KernelBuilder, Val};

use super::ParticleSystem;
use crate::Real;
use crate::forces::ForceEmitter;
use crate::ode::JacobianPattern;
use crate::particles::Coordinates;

/// The largest number of coordinates given a compiled Jacobian (each of its `2 n` columns
/// is one pass of forward differentiation over the accelerations' body).
pub const MAX_DOF: usize = 2048;

/// The largest number of entries of `∂a/∂q` and `∂a/∂v` together that are not structurally
/// zero (each is an output of the compiled kernel): two dense blocks of 96 coordinates.
pub const MAX_ENTRIES: usize = 2 * 96 * 96;

/// The largest amount of differentiation work, `2 n ×` the accelerations' instructions,
/// spent to find the entries (a few tenths of a second).
const MAX_WORK: usize = 50_000_000;

/// `∂a/∂q` and `∂a/∂v` of a system as one compiled kernel over the slots
/// `[t, q (n), v (n), entries]`: the entries that are not structurally zero, in the order
/// of `at`.
#[derive(Debug, Clone)]
pub struct CompiledJacobian {
    kernel: Kernel,
    n: usize,
    /// `(i, j)` where `∂aᵢ/∂qⱼ` or `∂aᵢ/∂vⱼ` is not structurally zero.
    pattern: JacobianPattern,
    /// Where each output entry goes: `(block, i · n + j)`, block 0 for `∂a/∂q`, 1 for
    /// `∂a/∂v`.
    at: Vec<(u8, usize)>,
}

/// The accelerations of `sys` emitted into `b` over the slots `[t, q, v, …]`, with `q` and
/// `v`'s values; `None` when a force cannot be emitted.
fn accelerations(sys: &ParticleSystem, b: &mut KernelBuilder) -> Option<(Vec<Val>, [Vec<Val>; 2])> {
    let n = sys.dim * sys.bodies.len();
    let t = b.get(0);
    let x: Vec<Val> = (0..n).map(|i| b.get(1 + i)).collect();
    let v: Vec<Val> = (0..n).map(|i| b.get(1 + n + i)).collect();
    let mut total: Vec<Option<Val>> = vec![None; n];
    for f in sys.forces.iter() {
        let mut e = ForceEmitter::new(b, sys.dim, t, &x, &v, &sys.mass);
        if !f.emit(&mut e) {
            return None;
        }
        for (o, s) in total.iter_mut().zip(e.into_forces()) {
            *o = match (*o, s) {
                (o, None) => o,
                (None, s) => s,
                (Some(o), Some(s)) => Some(b.add(o, s)),
            };
        }
    }
    let accel = total
        .iter()
        .zip(&sys.inv_mass)
        .map(|(f, w)| {
            let f = f.unwrap_or_else(|| b.constant(0.0));
            let w = b.constant(*w);
            b.mul(f, w)
        })
        .collect();
    Some((accel, [x, v]))
}

/// The entries of `∂a/∂q` (block 0) and `∂a/∂v` (block 1) that are not structurally zero,
/// column by column: `(block, i, j, value)`.
fn entries(
    b: &mut KernelBuilder,
    accel: &[Val],
    wrt: &[Vec<Val>; 2],
) -> Option<Vec<(u8, usize, usize, Val)>> {
    let mut out = Vec::new();
    for (block, wrt) in (0u8..).zip(wrt) {
        for (j, &xj) in wrt.iter().enumerate() {
            for (i, d) in b.derivatives(accel, xj)?.into_iter().enumerate() {
                if let Some(d) = d {
                    out.push((block, i, j, d));
                }
            }
            if out.len() > MAX_ENTRIES {
                return None;
            }
        }
    }
    Some(out)
}

impl CompiledJacobian {
    /// The Jacobian of `sys`'s accelerations, or `None` when it cannot be compiled (see the
    /// module's documentation).
    pub fn build(sys: &ParticleSystem) -> Option<CompiledJacobian> {
        let n = sys.dim * sys.bodies.len();
        if n == 0
            || n > MAX_DOF
            || !sys.extras.is_empty()
            || sys.coordinates != Coordinates::Cartesian
            || !sys.spinners.is_empty()
            || sys.has_variable_mass()
            || sys.forces.has_constraints()
        {
            return None;
        }
        // first the entries' positions, then a kernel with one slot for each
        let mut probe = KernelBuilder::new(1 + 2 * n);
        let (accel, wrt) = accelerations(sys, &mut probe)?;
        if 2 * n * probe.len() > MAX_WORK {
            return None;
        }
        let count = entries(&mut probe, &accel, &wrt)?.len();
        let mut b = KernelBuilder::new(1 + 2 * n + count);
        let (accel, wrt) = accelerations(sys, &mut b)?;
        let found = entries(&mut b, &accel, &wrt)?;
        let mut pattern = JacobianPattern::new(n);
        let mut at = Vec::with_capacity(found.len());
        for (k, (block, i, j, d)) in found.into_iter().enumerate() {
            pattern.insert(i, j);
            at.push((block, i * n + j));
            b.set(1 + 2 * n + k, d);
        }
        Some(CompiledJacobian {
            kernel: b.finish().native(),
            n,
            pattern,
            at,
        })
    }

    /// Which coordinates each acceleration depends on: `(i, j)` where `∂aᵢ/∂qⱼ` or
    /// `∂aᵢ/∂vⱼ` is not structurally zero (the kernel's derivative of `aᵢ` is not the
    /// constant zero), as [`SecondOrderSystem::accel_pattern`](crate::ode::SecondOrderSystem)
    /// reports it.
    pub fn pattern(&self) -> &JacobianPattern {
        &self.pattern
    }

    /// Writes `∂a/∂q` and `∂a/∂v` at `(t, q, v)` (row-major, `n × n`); `false` when an entry
    /// is not finite (the caller then takes differences).
    pub fn eval_into(
        &self,
        t: Real,
        q: &[Real],
        v: &[Real],
        da_dq: &mut [Real],
        da_dv: &mut [Real],
    ) -> bool {
        let n = self.n;
        let mut slots = vec![0.0; self.kernel.slots()];
        slots[0] = t;
        slots[1..=n].copy_from_slice(q);
        slots[(1 + n)..=(2 * n)].copy_from_slice(v);
        self.kernel.run(&mut slots, 1);
        da_dq.fill(0.0);
        da_dv.fill(0.0);
        for (&(block, k), &d) in self.at.iter().zip(&slots[1 + 2 * n..]) {
            if block == 0 {
                da_dq[k] = d;
            } else {
                da_dv[k] = d;
            }
        }
        slots[1 + 2 * n..].iter().all(|j| j.is_finite())
    }
}

#[cfg(test)]
#[path = "jacobian_tests.rs"]
mod tests;

//! The exact Jacobian of a particle system's accelerations, compiled: every force written
//! into a kernel ([`Force::emit`](crate::forces::Force::emit), the same expressions the fused
//! step uses), differentiated there by forward mode
//! ([`mechkit_expr::KernelBuilder::derivatives`]), and compiled to native code with the
//! accelerations' sub-expressions shared. The implicit methods call it through
//! [`SecondOrderSystem::accel_jacobian_into`](crate::ode::SecondOrderSystem).
//!
//! A system gets one when its forces can all be emitted (formulas and the built-in laws that
//! write themselves into kernels), its coordinates are Cartesian positions with constant
//! masses, and it is small enough for a dense Jacobian ([`MAX_DOF`]); otherwise the implicit
//! methods take the Jacobian by finite differences, as before.

use mechkit_expr::{Kernel, KernelBuilder, Val};

use super::ParticleSystem;
use crate::Real;
use crate::forces::ForceEmitter;
use crate::ode::JacobianPattern;
use crate::particles::Coordinates;

/// The largest number of coordinates given a compiled Jacobian (its `2 n²` entries are a
/// kernel's outputs).
pub const MAX_DOF: usize = 96;

/// `∂a/∂q` and `∂a/∂v` of a system as one compiled kernel over the slots
/// `[t, q (n), v (n), ∂a/∂q (n²), ∂a/∂v (n²)]`.
#[derive(Debug, Clone)]
pub struct CompiledJacobian {
    kernel: Kernel,
    n: usize,
    /// `(i, j)` where `∂aᵢ/∂qⱼ` or `∂aᵢ/∂vⱼ` is not structurally zero.
    pattern: JacobianPattern,
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
        let mut b = KernelBuilder::new(1 + 2 * n + 2 * n * n);
        let t = b.get(0);
        let x: Vec<Val> = (0..n).map(|i| b.get(1 + i)).collect();
        let v: Vec<Val> = (0..n).map(|i| b.get(1 + n + i)).collect();
        let mut total: Vec<Option<Val>> = vec![None; n];
        for f in sys.forces.iter() {
            let mut e = ForceEmitter::new(&mut b, sys.dim, t, &x, &v, &sys.mass);
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
        let accel: Vec<Val> = total
            .iter()
            .zip(&sys.inv_mass)
            .map(|(f, w)| {
                let f = f.unwrap_or_else(|| b.constant(0.0));
                let w = b.constant(*w);
                b.mul(f, w)
            })
            .collect();
        let zero = b.constant(0.0);
        let mut pattern = JacobianPattern::new(n);
        for (block, wrt) in [(0, &x), (1, &v)] {
            for (j, &xj) in wrt.iter().enumerate() {
                let column = b.derivatives(&accel, xj)?;
                for (i, d) in column.into_iter().enumerate() {
                    if d.is_some() {
                        pattern.insert(i, j);
                    }
                    b.set(1 + 2 * n + block * n * n + i * n + j, d.unwrap_or(zero));
                }
            }
        }
        Some(CompiledJacobian {
            kernel: b.finish().native(),
            n,
            pattern,
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
        let out = &slots[1 + 2 * n..];
        da_dq.copy_from_slice(&out[..n * n]);
        da_dv.copy_from_slice(&out[n * n..]);
        out.iter().all(|j| j.is_finite())
    }
}

#[cfg(test)]
#[path = "jacobian_tests.rs"]
mod tests;

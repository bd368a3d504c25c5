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

use std::sync::OnceLock;
use std::sync::atomic::{AtomicU64, Ordering};

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
/// spent to find the entries (about a second at most).
const MAX_WORK: usize = 200_000_000;

/// Kernels up to this many instructions are compiled to native code at once. Native
/// compilation of a larger one costs seconds (register allocation over thousands of live
/// entries), far more than interpreting it for the few Jacobians most runs take; it is
/// compiled once it has been interpreted for [`NATIVE_AFTER`] instructions in all.
const NATIVE_AT_ONCE: usize = 4096;

/// Instructions interpreted (evaluations × the kernel's length) after which a large kernel
/// is compiled to native code (about a third of a second of interpretation).
const NATIVE_AFTER: u64 = 100_000_000;

/// `∂a/∂q` and `∂a/∂v` of a system as one compiled kernel over the slots
/// `[t, q (n), v (n), entries]`: the entries that are not structurally zero, in the order
/// of `at`.
#[derive(Debug)]
pub struct CompiledJacobian {
    /// Native when it is small ([`NATIVE_AT_ONCE`]), else interpreted.
    kernel: Kernel,
    /// The large kernel compiled, once it has been used enough ([`NATIVE_AFTER`]).
    native: OnceLock<Kernel>,
    /// Instructions interpreted so far.
    interpreted: AtomicU64,
    /// [`NATIVE_AFTER`] (smaller in tests).
    native_after: u64,
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

impl Clone for CompiledJacobian {
    fn clone(&self) -> Self {
        Self {
            kernel: self.kernel.clone(),
            native: self.native.clone(),
            interpreted: AtomicU64::new(self.interpreted.load(Ordering::Relaxed)),
            native_after: self.native_after,
            n: self.n,
            pattern: self.pattern.clone(),
            at: self.at.clone(),
        }
    }
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
        // the entries that are not zero by structure, then one output slot for each
        let mut b = KernelBuilder::new(1 + 2 * n);
        let (accel, wrt) = accelerations(sys, &mut b)?;
        if 2 * n * b.len() > MAX_WORK {
            return None;
        }
        let found = entries(&mut b, &accel, &wrt)?;
        let first = b.add_slots(found.len());
        let mut pattern = JacobianPattern::new(n);
        let mut at = Vec::with_capacity(found.len());
        for (k, (block, i, j, d)) in found.into_iter().enumerate() {
            pattern.insert(i, j);
            at.push((block, i * n + j));
            b.set(first + k, d);
        }
        let kernel = b.finish();
        let kernel = if kernel.len() <= NATIVE_AT_ONCE {
            kernel.native()
        } else {
            kernel
        };
        Some(CompiledJacobian {
            kernel,
            native: OnceLock::new(),
            interpreted: AtomicU64::new(0),
            native_after: NATIVE_AFTER,
            n,
            pattern,
            at,
        })
    }

    /// The kernel to run: the native one once there is one, compiling a large kernel when
    /// it has been interpreted long enough.
    fn kernel(&self) -> &Kernel {
        if self.kernel.is_native() {
            return &self.kernel;
        }
        if let Some(k) = self.native.get() {
            return k;
        }
        let len = self.kernel.len() as u64;
        if self.interpreted.fetch_add(len, Ordering::Relaxed) + len >= self.native_after {
            return self.native.get_or_init(|| self.kernel.clone().native());
        }
        &self.kernel
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
        self.kernel().run(&mut slots, 1);
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

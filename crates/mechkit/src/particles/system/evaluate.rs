//! Evaluating a particle system at a state: the accelerations (with the variable masses and
//! the rigid bodies' turning), each force's power, potential and net force, the energies,
//! for observers; and the system as a [`SecondOrderSystem`] for the steppers.

use super::{Kinematics, ParticleSystem, dot};
use crate::Real;
use crate::ode::SecondOrderSystem;
use crate::particles::sample::Evaluation;

impl ParticleSystem {
    /// Evaluates accelerations, the power and potential of each force, and the energies at a
    /// state, into `out` (buffers are resized once and reused).
    pub fn evaluate(
        &self,
        t: Real,
        q: &[Real],
        v: &[Real],
        out: &mut Evaluation,
        scratch: &mut Vec<Real>,
    ) {
        let n = q.len();
        let nf = self.forces.len();
        out.a.resize(n, 0.0);
        out.power.resize(nf, 0.0);
        out.potential.resize(nf, Real::NAN);
        out.net.resize(nf * self.dim, 0.0);
        scratch.resize(n, 0.0);
        let mut current = Vec::new();
        let k = self.kinematics_with(t, q, v, &mut current);
        let report = if self.forces.has_constraints() {
            out.constraint
                .resize(nf * crate::rigid::mechanism::REPORT_LEN, Real::NAN);
            Some(&mut out.constraint[..])
        } else {
            out.constraint.clear();
            None
        };
        self.forces.total_power_report(
            &k,
            &mut out.a,
            &mut out.power,
            &mut out.net,
            scratch,
            report,
        );
        self.turn(q, v, &mut out.a);
        for (a, w) in out.a.iter_mut().zip(&self.inv_mass) {
            *a *= w;
        }
        self.rescale_variable(k.mass, &mut out.a);
        let mut total = None;
        for (i, f) in self.forces.iter().enumerate() {
            let u = f.potential(&k);
            out.potential[i] = u.unwrap_or(Real::NAN);
            if let Some(u) = u {
                total = Some(total.unwrap_or(0.0) + u);
            }
        }
        out.potential_total = total;
        out.kinetic_rotation = self.rotational_kinetic_energy(q, v);
        out.kinetic = out.kinetic_rotation
            + k.mass
                .iter()
                .enumerate()
                .map(|(i, m)| {
                    let vi = &v[i * self.dim..(i + 1) * self.dim];
                    0.5 * m * dot(vi, vi)
                })
                .sum::<Real>();
        out.momentum.clear();
        out.momentum.resize(self.dim, 0.0);
        for (m, body) in k.mass.iter().zip(v.chunks_exact(self.dim)) {
            for (p, vk) in out.momentum.iter_mut().zip(body) {
                *p += m * vk;
            }
        }
    }
}

impl ParticleSystem {
    /// The force view of a state with the current masses (read from `q` into `current` when
    /// some mass varies; `current` stays empty, unallocated, otherwise).
    fn kinematics_with<'a>(
        &'a self,
        t: Real,
        q: &'a [Real],
        v: &'a [Real],
        current: &'a mut Vec<Real>,
    ) -> Kinematics<'a> {
        if !self.has_variable_mass() {
            return self.kinematics(t, q, v);
        }
        self.masses_at(q, current);
        Kinematics {
            t,
            dim: self.dim,
            x: q,
            v,
            mass: current,
        }
    }

    /// `a` was divided by the starting masses: divide the variable bodies' by their current
    /// masses instead.
    fn rescale_variable(&self, current: &[Real], a: &mut [Real]) {
        for &(b, _) in &self.variable {
            let f = self.mass[b] / current[b];
            for ak in &mut a[b * self.dim..(b + 1) * self.dim] {
                *ak *= f;
            }
        }
    }
}

impl SecondOrderSystem for ParticleSystem {
    fn dof(&self) -> usize {
        self.dim * self.bodies.len() + self.extras.len()
    }

    #[inline]
    fn accel_into(&self, t: Real, q: &[Real], v: &[Real], a: &mut [Real]) {
        let mut current = Vec::new();
        let k = self.kinematics_with(t, q, v, &mut current);
        self.forces.total_into(&k, a);
        self.turn(q, v, a);
        for (ai, w) in a.iter_mut().zip(&self.inv_mass) {
            *ai *= w;
        }
        self.rescale_variable(k.mass, a);
    }

    fn velocity_dependent(&self) -> bool {
        self.velocity_dependent
    }

    /// From the compiled Jacobian ([`super::CompiledJacobian`]) when the system has one.
    fn accel_jacobian_into(
        &self,
        t: Real,
        q: &[Real],
        v: &[Real],
        da_dq: &mut [Real],
        da_dv: &mut [Real],
    ) -> bool {
        self.jacobian
            .get_or_init(|| super::CompiledJacobian::build(self))
            .as_ref()
            .is_some_and(|j| j.eval_into(t, q, v, da_dq, da_dv))
    }

    /// The structural zeros of the compiled Jacobian, when the system has one.
    fn accel_pattern(&self) -> Option<crate::ode::JacobianPattern> {
        self.jacobian
            .get_or_init(|| super::CompiledJacobian::build(self))
            .as_ref()
            .map(|j| j.pattern().clone())
    }
}

//! A set of named forces, evaluated together or one by one for the energy ledger.

use super::force::Force;
use crate::Real;
use crate::particles::Kinematics;
use crate::particles::dot;

/// The forces of a system.
#[derive(Debug, Default)]
pub struct ForceSet {
    forces: Vec<Box<dyn Force>>,
}

impl ForceSet {
    /// No forces.
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds a force.
    pub fn push(&mut self, force: Box<dyn Force>) {
        self.forces.push(force);
    }

    /// Number of forces.
    pub fn len(&self) -> usize {
        self.forces.len()
    }

    /// Whether there are no forces.
    pub fn is_empty(&self) -> bool {
        self.forces.is_empty()
    }

    /// The forces, in the order added.
    pub fn iter(&self) -> impl Iterator<Item = &dyn Force> {
        self.forces.iter().map(AsRef::as_ref)
    }

    /// Force `i`.
    pub fn get(&self, i: usize) -> &dyn Force {
        self.forces[i].as_ref()
    }

    /// Index of the force named `name`.
    pub fn index_of(&self, name: &str) -> Option<usize> {
        self.forces.iter().position(|f| f.name() == name)
    }

    /// Sets `out` to the total force.
    pub fn total_into(&self, k: &Kinematics<'_>, out: &mut [Real]) {
        out.fill(0.0);
        for f in &self.forces {
            f.add_forces(k, out);
        }
    }

    /// Sets `out` to the total force, `power[i]` to the power `F_i·v` of force `i` and
    /// `net[i*dim..]` to its net force summed over the bodies; `scratch` holds one force at a
    /// time.
    pub fn total_and_power_into(
        &self,
        k: &Kinematics<'_>,
        out: &mut [Real],
        power: &mut [Real],
        net: &mut [Real],
        scratch: &mut [Real],
    ) {
        out.fill(0.0);
        let d = k.dim;
        for (i, (f, p)) in self.forces.iter().zip(power.iter_mut()).enumerate() {
            scratch.fill(0.0);
            f.add_forces(k, scratch);
            *p = dot(scratch, k.v);
            for (o, s) in out.iter_mut().zip(scratch.iter()) {
                *o += s;
            }
            let n = &mut net[i * d..(i + 1) * d];
            n.fill(0.0);
            for body in scratch.chunks_exact(d) {
                for (nk, fk) in n.iter_mut().zip(body) {
                    *nk += fk;
                }
            }
        }
    }

    /// Whether any force depends on velocity.
    pub fn velocity_dependent(&self) -> bool {
        self.forces.iter().any(|f| f.velocity_dependent())
    }
}

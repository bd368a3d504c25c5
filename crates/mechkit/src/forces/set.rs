//! A set of named forces, evaluated together or one by one for the energy ledger.

use super::force::Force;
use crate::Real;
use crate::particles::Kinematics;
use crate::particles::dot;
use crate::rigid::mechanism::REPORT_LEN as LEN;

/// The forces of a system.
#[derive(Debug, Default)]
pub struct ForceSet {
    forces: Vec<Box<dyn Force>>,
    /// For each force that is [`Force::local`], its bodies, sorted and without repeats: the
    /// energy ledger visits only their coordinates.
    reach: Vec<Option<Vec<usize>>>,
}

impl ForceSet {
    /// No forces.
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds a force.
    pub fn push(&mut self, force: Box<dyn Force>) {
        self.reach.push(force.local().then(|| {
            let mut bodies = force.bodies();
            bodies.sort_unstable();
            bodies.dedup();
            bodies
        }));
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
        for f in self.forces.iter().filter(|f| !f.constraint()) {
            f.add_forces(k, out);
        }
        if self.has_constraints() {
            let applied = out.to_vec();
            for f in self.forces.iter().filter(|f| f.constraint()) {
                f.add_constraint_forces(k, &applied, out);
            }
        }
    }

    /// Sets `out` to the sum of the forces that are not constraints.
    pub fn applied_into(&self, k: &Kinematics<'_>, out: &mut [Real]) {
        out.fill(0.0);
        for f in self.forces.iter().filter(|f| !f.constraint()) {
            f.add_forces(k, out);
        }
    }

    /// Whether some force is a constraint (a joint).
    pub fn has_constraints(&self) -> bool {
        self.forces.iter().any(|f| f.constraint())
    }

    /// Sets `out` to the total force, `power[i]` to the power `F_i·v` of force `i` and
    /// `net[i*dim..]` to its net force summed over the bodies; `scratch` holds one force at a
    /// time. Constraint forces come after the others, from their sum; `report` gets each
    /// constraint's report (5 values per force, NaN for the others) when given.
    pub fn total_and_power_into(
        &self,
        k: &Kinematics<'_>,
        out: &mut [Real],
        power: &mut [Real],
        net: &mut [Real],
        scratch: &mut [Real],
    ) {
        self.total_power_report(k, out, power, net, scratch, None);
    }

    /// [`ForceSet::total_and_power_into`] with the constraints' reports.
    pub(crate) fn total_power_report(
        &self,
        k: &Kinematics<'_>,
        out: &mut [Real],
        power: &mut [Real],
        net: &mut [Real],
        scratch: &mut [Real],
        mut report: Option<&mut [Real]>,
    ) {
        out.fill(0.0);
        let d = k.dim;
        let n_pos = d * k.n_bodies();
        let mut applied: Option<Vec<Real>> = None;
        // `scratch` is all zero at the start of a local force (which clears what it wrote)
        let mut dirty = true;
        for pass in [false, true] {
            for (i, (f, p)) in self.forces.iter().zip(power.iter_mut()).enumerate() {
                if f.constraint() != pass {
                    continue;
                }
                let n = &mut net[i * d..(i + 1) * d];
                if let (false, Some(bodies)) = (pass, &self.reach[i]) {
                    if dirty {
                        scratch.fill(0.0);
                        dirty = false;
                    }
                    if let Some(r) = report.as_deref_mut() {
                        r[i * LEN..(i + 1) * LEN].fill(Real::NAN);
                    }
                    f.add_forces(k, scratch);
                    *p = local_ledger(bodies, d, scratch, k.v, out, n) + f.extra_power(k);
                    f.extra_momentum_rate(k, n);
                    continue;
                }
                dirty = true;
                scratch.fill(0.0);
                if pass {
                    let applied = applied.get_or_insert_with(|| out.to_vec());
                    f.add_constraint_forces(k, applied, scratch);
                    if let Some(r) = report.as_deref_mut() {
                        r[i * LEN..(i + 1) * LEN].copy_from_slice(&f.constraint_report(k, applied));
                    }
                } else if let Some(r) = report.as_deref_mut() {
                    r[i * LEN..(i + 1) * LEN].fill(Real::NAN);
                }
                if !pass {
                    f.add_forces(k, scratch);
                }
                *p = dot(scratch, k.v) + f.extra_power(k);
                for (o, s) in out.iter_mut().zip(scratch.iter()) {
                    *o += s;
                }
                n.fill(0.0);
                for body in scratch[..n_pos].chunks_exact(d) {
                    for (nk, fk) in n.iter_mut().zip(body) {
                        *nk += fk;
                    }
                }
                f.extra_momentum_rate(k, n);
            }
        }
    }

    /// Sets `each[i*n..(i+1)*n]` to force `i`'s own generalized force (`n = out.len()`
    /// coordinates; constraint forces from the sum of the others, as in a step) and `out` to
    /// their sum.
    pub fn each_into(&self, k: &Kinematics<'_>, out: &mut [Real], each: &mut [Real]) {
        let n = out.len();
        out.fill(0.0);
        each.fill(0.0);
        for (i, f) in self.forces.iter().enumerate() {
            if !f.constraint() {
                f.add_forces(k, &mut each[i * n..(i + 1) * n]);
            }
        }
        for chunk in each.chunks_exact(n) {
            for (o, x) in out.iter_mut().zip(chunk) {
                *o += x;
            }
        }
        if self.has_constraints() {
            let applied = out.to_vec();
            for (i, f) in self.forces.iter().enumerate() {
                if f.constraint() {
                    let own = &mut each[i * n..(i + 1) * n];
                    f.add_constraint_forces(k, &applied, own);
                    for (o, x) in out.iter_mut().zip(own.iter()) {
                        *o += x;
                    }
                }
            }
        }
    }

    /// Whether any force depends on velocity.
    pub fn velocity_dependent(&self) -> bool {
        self.forces.iter().any(|f| f.velocity_dependent())
    }
}

/// The ledger of one [`Force::local`] force whose forces are in `scratch` at the
/// coordinates of `bodies` (sorted, without repeats) and zero elsewhere: adds them to `out`,
/// sets `net` to their sum over the bodies, clears them from `scratch`, and returns their
/// power `F·v`. The same sums in the same order as over every coordinate, without the zeros.
fn local_ledger(
    bodies: &[usize],
    d: usize,
    scratch: &mut [Real],
    v: &[Real],
    out: &mut [Real],
    net: &mut [Real],
) -> Real {
    let mut power = -0.0;
    net.fill(0.0);
    for &b in bodies {
        for (c, nk) in (b * d..(b + 1) * d).zip(net.iter_mut()) {
            let f = std::mem::take(&mut scratch[c]);
            if let Some(vc) = v.get(c) {
                power += f * vc;
            }
            out[c] += f;
            *nk += f;
        }
    }
    power
}

#[cfg(test)]
#[path = "set_tests.rs"]
mod tests;

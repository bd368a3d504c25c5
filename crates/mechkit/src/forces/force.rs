//! The force trait.

use std::fmt::Debug;

use super::emit::ForceEmitter;
use crate::Real;
use crate::particles::Kinematics;

/// A force law acting on some bodies of a particle system.
pub trait Force: Debug + Send + Sync {
    /// The force's name, as in the energy ledger (`gravity`, `air`).
    fn name(&self) -> &str;

    /// Adds this force, `dim` components per body, into `out` (one slot per coordinate of the
    /// system).
    fn add_forces(&self, k: &Kinematics<'_>, out: &mut [Real]);

    /// Potential energy, for conservative forces; `None` otherwise.
    fn potential(&self, _k: &Kinematics<'_>) -> Option<Real> {
        None
    }

    /// Whether the force depends on velocities.
    fn velocity_dependent(&self) -> bool {
        false
    }

    /// Writes this force into a fused step kernel: the same operations, in the same order, as
    /// [`Force::add_forces`] (see [`ForceEmitter`]). Returns `false`, the default, when the
    /// force cannot be written as straight-line arithmetic; fixed-step runs then take the
    /// general loop.
    fn emit(&self, _e: &mut ForceEmitter<'_>) -> bool {
        false
    }

    /// Indices of the bodies it acts on (for diagnostics).
    fn bodies(&self) -> Vec<usize>;

    /// Whether [`Force::add_forces`] writes only the coordinates of [`Force::bodies`]
    /// (`b·dim .. (b + 1)·dim` for each `b`): the energy ledger then reads and clears only
    /// those, so its cost grows with the force's bodies, not the system's. `false`, the
    /// default, makes no such promise.
    fn local(&self) -> bool {
        false
    }

    /// What it looks like in an animation: a spring's coil, a joint's rod or string, a
    /// pulley. Nothing, the default, for a force that is not a thing (gravity, drag).
    fn sketch(&self) -> Vec<crate::animation::SceneItem> {
        Vec::new()
    }

    /// Whether the force acts only between bodies of the system, in action-reaction pairs: it
    /// moves no momentum, and its potential energy is internal.
    fn internal(&self) -> bool {
        false
    }

    /// Power that is not `F·v` of its force (the kinetic energy an ejected mass carries
    /// away); 0 for ordinary forces.
    fn extra_power(&self, _k: &Kinematics<'_>) -> Real {
        0.0
    }

    /// Momentum per second that is not its force (the momentum an ejected mass carries away),
    /// added to `net` (one component per dimension); nothing for ordinary forces.
    fn extra_momentum_rate(&self, _k: &Kinematics<'_>, _net: &mut [Real]) {}

    /// Whether it is a constraint force (a joint): it is then evaluated after every other
    /// force, from their sum, by [`Force::add_constraint_forces`].
    fn constraint(&self) -> bool {
        false
    }

    /// For a constraint force: adds its force into `out`, given the sum `applied` of the
    /// forces that are not constraints.
    fn add_constraint_forces(&self, k: &Kinematics<'_>, _applied: &[Real], out: &mut [Real]) {
        self.add_forces(k, out);
    }

    /// For a constraint force: what it reports (force components, normal force or tension,
    /// friction, violation: [`crate::rigid::mechanism::REPORT_FIELDS`]); NaN for other forces.
    fn constraint_report(
        &self,
        _k: &Kinematics<'_>,
        _applied: &[Real],
    ) -> [Real; crate::rigid::mechanism::REPORT_LEN] {
        [Real::NAN; crate::rigid::mechanism::REPORT_LEN]
    }
}

/// A body a single-body force acts on, with the force's coefficient for that body (a drag
/// coefficient may depend on the body's own mass).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Target {
    /// Body index.
    pub body: usize,
    /// The force's coefficient for this body.
    pub coefficient: Real,
}

impl Target {
    /// Body `body` with coefficient `coefficient`.
    pub fn new(body: usize, coefficient: Real) -> Self {
        Self { body, coefficient }
    }

    /// The same coefficient for each of `bodies`.
    pub fn all(bodies: &[usize], coefficient: Real) -> Vec<Target> {
        bodies
            .iter()
            .map(|&b| Target::new(b, coefficient))
            .collect()
    }
}

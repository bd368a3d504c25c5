//! The momentum and the centre of mass of a run, at its start and end.

use serde::Serialize;

use super::BodyState;
use crate::Real;
use crate::mass::PointMasses;
use crate::particles::ParticleSystem;

/// Position and velocity of the centre of mass at the start and end of a run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CentreOfMass {
    /// Total mass (kg).
    pub total_mass: Real,
    /// At the start.
    pub start: BodyState,
    /// At the end.
    pub end: BodyState,
    /// Kinetic energy relative to the centre of mass at the end (J): `K - ½ M V²`.
    pub internal_kinetic_end: Real,
    /// The same at the start (J).
    pub internal_kinetic_start: Real,
    /// Change of the potential energy of the internal forces (springs and gravity between
    /// bodies, contacts between spheres) (J); null when none has a potential.
    pub internal_potential_change: Option<Real>,
    /// Change of the potential energy of the external forces (J); null when none has one.
    pub external_potential_change: Option<Real>,
}

pub(super) fn centre_of_mass(sys: &ParticleSystem, q: &[Real], v: &[Real]) -> (BodyState, Real) {
    let n = sys.extras_start();
    let p = PointMasses::new(
        sys.dim(),
        sys.masses().to_vec(),
        q[..n].to_vec(),
        Some(v[..n].to_vec()),
    )
    .expect("a built system has positive masses and matching coordinates")
    .summary();
    (
        BodyState {
            position: p.centre_of_mass,
            velocity: p.cm_velocity.unwrap_or_default(),
        },
        p.kinetic_internal.unwrap_or(0.0),
    )
}

/// Total momentum at the start and end of a run, and where its change came from.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MomentumSummary {
    /// At the start.
    pub start: Vec<Real>,
    /// At the end.
    pub end: Vec<Real>,
    /// The impulse of all forces, `Σ ∫F dt` (internal forces contribute nothing).
    pub external_impulse: Vec<Real>,
    /// Changed by events (impacts on walls).
    pub events_change: Vec<Real>,
    /// `end - start - external_impulse - events_change`: zero for an exact trajectory.
    pub residual: Vec<Real>,
}

//! What the summary says of each body at the end of a run: its centre of mass, and how a
//! rigid body turns (in a plane: angle and angular velocity; in space: orientation, angular
//! velocity and angular momentum).

use std::collections::BTreeMap;

use serde::Serialize;

use crate::Real;
use crate::particles::ParticleSystem;
use crate::particles::spin::{self, Mat3};

/// A body at the end of the run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BodySummary {
    /// Mass (kg).
    pub mass: Real,
    /// Final position (m).
    pub position: Vec<Real>,
    /// Final velocity (m/s).
    pub velocity: Vec<Real>,
    /// Final speed (m/s).
    pub speed: Real,
    /// A rigid body's final angle (rad) and angular velocity (rad/s), and its moment of
    /// inertia about the centre of mass (kg m²).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rotation: Option<Rotation>,
    /// A rigid body in space: its final orientation, angular velocity and angular momentum.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub spin: Option<SpinSummary>,
}

/// A rigid body's turning at the end of the run.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Rotation {
    /// Angle (rad).
    pub theta: Real,
    /// Angular velocity (rad/s).
    pub omega: Real,
    /// Moment of inertia about the centre of mass (kg m²).
    pub inertia: Real,
}

/// A rigid body turning in space, at the end of the run.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SpinSummary {
    /// Orientation, a unit quaternion `[w, x, y, z]` (body → world).
    pub orientation: [Real; 4],
    /// Angular velocity, world frame (rad/s).
    pub omega: [Real; 3],
    /// Angular momentum about the centre of mass, world frame (kg m²/s).
    pub angular_momentum: [Real; 3],
    /// Inertia tensor about the centre of mass, body frame (kg m²).
    pub inertia: Mat3,
}

/// Each body's summary at the state `(q, v)`, by name.
pub(super) fn bodies(
    sys: &ParticleSystem,
    q: &[Real],
    v: &[Real],
) -> BTreeMap<String, BodySummary> {
    let d = sys.dim();
    let start = sys.extras_start();
    sys.bodies()
        .iter()
        .enumerate()
        .map(|(i, b)| {
            let vel = v[i * d..(i + 1) * d].to_vec();
            let speed = vel.iter().map(|x| x * x).sum::<Real>().sqrt();
            let rotation = sys
                .extras()
                .iter()
                .position(|e| e.body == Some(i))
                .map(|k| Rotation {
                    theta: q[start + k],
                    omega: v[start + k],
                    inertia: sys.extras()[k].inertia,
                });
            let spin = sys.spinners().iter().find(|s| s.body == i).map(|s| {
                let (qq, qd) = s.of(q, v);
                let n = spin::norm2(qq).sqrt();
                SpinSummary {
                    orientation: qq.map(|x| x / n),
                    omega: spin::omega_world(qq, qd),
                    angular_momentum: s.momentum(qq, qd),
                    inertia: s.inertia,
                }
            });
            (
                b.name.clone(),
                BodySummary {
                    // a body that ejects mass ends with what is left
                    mass: sys
                        .extras()
                        .iter()
                        .position(|e| e.mass_of == Some(i))
                        .map_or(b.mass, |k| q[start + k]),
                    position: q[i * d..(i + 1) * d].to_vec(),
                    velocity: vel,
                    speed,
                    rotation,
                    spin,
                },
            )
        })
        .collect()
}

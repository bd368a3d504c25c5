//! Torques on hinged bodies, as [`Force`]s on the angle coordinate: each adds its torque about
//! the axis to the body's generalised force, and the conservative ones give their potential
//! energy (so `τ = -dU/dθ` and the energy ledger splits `U` from the work of the others).

use super::hinge::rotate;
use crate::Real;
use crate::forces::Force;
use crate::mass::Vec3;
use crate::particles::Kinematics;

/// Uniform gravity on a hinged body: `τ = n · (r(θ) × m g)`, `U = -m g · r(θ)`, with `r(θ)` the
/// centre of mass relative to the pivot.
#[derive(Debug, Clone, PartialEq)]
pub struct GravityTorque {
    name: String,
    body: usize,
    weight: Vec3,
    offset: Vec3,
    axis: Vec3,
}

impl GravityTorque {
    /// Gravity `g` (a vector) on a body of mass `mass` whose centre of mass is at `offset` from
    /// the pivot at `θ = 0`, turning about the unit `axis`.
    pub fn new(
        name: impl Into<String>,
        body: usize,
        mass: Real,
        g: Vec3,
        offset: Vec3,
        axis: Vec3,
    ) -> Self {
        GravityTorque {
            name: name.into(),
            body,
            weight: g * mass,
            offset,
            axis,
        }
    }

    fn arm(&self, k: &Kinematics<'_>) -> Vec3 {
        rotate(&self.offset, &self.axis, k.x[self.body])
    }
}

impl Force for GravityTorque {
    fn name(&self) -> &str {
        &self.name
    }

    fn add_forces(&self, k: &Kinematics<'_>, out: &mut [Real]) {
        out[self.body] += self.axis.dot(&self.arm(k).cross(&self.weight));
    }

    fn potential(&self, k: &Kinematics<'_>) -> Option<Real> {
        Some(-self.weight.dot(&self.arm(k)))
    }

    fn bodies(&self) -> Vec<usize> {
        vec![self.body]
    }
}

/// A torsion spring: `τ = -κ (θ - θ₀)`, `U = ½ κ (θ - θ₀)²`.
#[derive(Debug, Clone, PartialEq)]
pub struct TorsionSpring {
    name: String,
    body: usize,
    kappa: Real,
    rest: Real,
}

impl TorsionSpring {
    /// Stiffness `kappa` (N m/rad), rest angle `rest`.
    pub fn new(name: impl Into<String>, body: usize, kappa: Real, rest: Real) -> Self {
        TorsionSpring {
            name: name.into(),
            body,
            kappa,
            rest,
        }
    }
}

impl Force for TorsionSpring {
    fn name(&self) -> &str {
        &self.name
    }

    fn add_forces(&self, k: &Kinematics<'_>, out: &mut [Real]) {
        out[self.body] -= self.kappa * (k.x[self.body] - self.rest);
    }

    fn potential(&self, k: &Kinematics<'_>) -> Option<Real> {
        let d = k.x[self.body] - self.rest;
        Some(0.5 * self.kappa * d * d)
    }

    fn bodies(&self) -> Vec<usize> {
        vec![self.body]
    }
}

/// A linear spring from a point of the body to a fixed anchor: the force
/// `F = -k (L - L₀) d/L` at the point, with `d` from the anchor to the point, gives the torque
/// `n · (p × F)` about the pivot; `U = ½ k (L - L₀)²`.
#[derive(Debug, Clone, PartialEq)]
pub struct AttachedSpring {
    name: String,
    body: usize,
    k: Real,
    rest_length: Real,
    point: Vec3,
    anchor: Vec3,
    axis: Vec3,
}

impl AttachedSpring {
    /// Stiffness `k`, rest length `rest_length`, attached at `point` of the body (relative to
    /// the pivot at `θ = 0`) and at the fixed `anchor` (relative to the pivot); unit `axis`.
    pub fn new(
        name: impl Into<String>,
        body: usize,
        k: Real,
        rest_length: Real,
        point: Vec3,
        anchor: Vec3,
        axis: Vec3,
    ) -> Self {
        AttachedSpring {
            name: name.into(),
            body,
            k,
            rest_length,
            point,
            anchor,
            axis,
        }
    }

    /// The attachment point and the spring vector (anchor to point) at angle `theta`.
    fn geometry(&self, theta: Real) -> (Vec3, Vec3) {
        let p = rotate(&self.point, &self.axis, theta);
        (p, p - self.anchor)
    }
}

impl Force for AttachedSpring {
    fn name(&self) -> &str {
        &self.name
    }

    fn add_forces(&self, k: &Kinematics<'_>, out: &mut [Real]) {
        let (p, d) = self.geometry(k.x[self.body]);
        let length = d.norm();
        if length > 0.0 {
            let f = d * (-self.k * (length - self.rest_length) / length);
            out[self.body] += self.axis.dot(&p.cross(&f));
        }
    }

    fn potential(&self, k: &Kinematics<'_>) -> Option<Real> {
        let stretch = self.geometry(k.x[self.body]).1.norm() - self.rest_length;
        Some(0.5 * self.k * stretch * stretch)
    }

    fn bodies(&self) -> Vec<usize> {
        vec![self.body]
    }
}

/// How a friction torque depends on the angular velocity.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FrictionLaw {
    /// Dry friction in the bearing, `τ = -τ₀ s` while the body turns in the direction
    /// `s = ±1` (the sign of `ω`). The torque is constant while the body turns, so `ω`
    /// reaches zero at a definite time, where an event on `ω` ends the regime (the bearing
    /// then holds the body if the other torques do not exceed `τ₀`). Writing `sign(ω)` instead
    /// would let every step that straddles `ω = 0` chatter around it without ever crossing.
    Coulomb {
        /// Magnitude `τ₀` (N m).
        torque: Real,
        /// The direction of turning `s` (+1 or -1).
        direction: Real,
    },
    /// `τ = -b ω` (viscous friction).
    Viscous(Real),
}

/// Friction in the bearing; its work is the energy lost to heat.
#[derive(Debug, Clone, PartialEq)]
pub struct FrictionTorque {
    name: String,
    body: usize,
    law: FrictionLaw,
}

impl FrictionTorque {
    /// Friction on `body` by `law`.
    pub fn new(name: impl Into<String>, body: usize, law: FrictionLaw) -> Self {
        FrictionTorque {
            name: name.into(),
            body,
            law,
        }
    }
}

impl Force for FrictionTorque {
    fn name(&self) -> &str {
        &self.name
    }

    fn add_forces(&self, k: &Kinematics<'_>, out: &mut [Real]) {
        let w = k.v[self.body];
        out[self.body] += match self.law {
            FrictionLaw::Coulomb { torque, direction } => -torque * direction.signum(),
            FrictionLaw::Viscous(b) => -b * w,
        };
    }

    fn velocity_dependent(&self) -> bool {
        matches!(self.law, FrictionLaw::Viscous(_))
    }

    fn bodies(&self) -> Vec<usize> {
        vec![self.body]
    }
}

/// A constant applied torque (an engine, a hand): its work is energy put in.
#[derive(Debug, Clone, PartialEq)]
pub struct ConstantTorque {
    name: String,
    body: usize,
    torque: Real,
}

impl ConstantTorque {
    /// Torque `torque` (N m) on `body`.
    pub fn new(name: impl Into<String>, body: usize, torque: Real) -> Self {
        ConstantTorque {
            name: name.into(),
            body,
            torque,
        }
    }
}

impl Force for ConstantTorque {
    fn name(&self) -> &str {
        &self.name
    }

    fn add_forces(&self, _k: &Kinematics<'_>, out: &mut [Real]) {
        out[self.body] += self.torque;
    }

    fn bodies(&self) -> Vec<usize> {
        vec![self.body]
    }
}

/// A weight of mass `m` hanging from a string wound on a drum of radius `r` on the axle (the
/// Atwood machine with a massive pulley, a flywheel driven by a falling weight): the torque is
/// `m g r` and `U = -m g r θ` (it descends by `r θ`); its `m r²` belongs to the body's moment
/// of inertia ([`super::HingedBody::hang`]).
#[derive(Debug, Clone, PartialEq)]
pub struct HangingWeight {
    name: String,
    body: usize,
    torque: Real,
}

impl HangingWeight {
    pub(crate) fn new(
        name: impl Into<String>,
        body: usize,
        mass: Real,
        radius: Real,
        g: Real,
    ) -> Self {
        HangingWeight {
            name: name.into(),
            body,
            torque: mass * g * radius,
        }
    }
}

impl Force for HangingWeight {
    fn name(&self) -> &str {
        &self.name
    }

    fn add_forces(&self, _k: &Kinematics<'_>, out: &mut [Real]) {
        out[self.body] += self.torque;
    }

    fn potential(&self, k: &Kinematics<'_>) -> Option<Real> {
        Some(-self.torque * k.x[self.body])
    }

    fn bodies(&self) -> Vec<usize> {
        vec![self.body]
    }
}

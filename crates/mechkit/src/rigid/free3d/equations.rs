//! The equations of motion as a first-order system for [`crate::ode`]: the state is
//! `y = [w, x, y, z, L₁, L₂, L₃]`, a quaternion (body → world) and the angular momentum about
//! the rotation point, in the world frame or in the body frame ([`Formulation`]).
//!
//! - `ω = J⁻¹ L_body` with `L_body = Rᵀ L_world`;
//! - `dq/dt = ½ q ⊗ (0, ω)`;
//! - world frame: `dL/dt = τ_world`, so a torque-free `L` is constant step by step (bit for
//!   bit: every stage of a Runge-Kutta step adds `h · 0`);
//! - body frame (Euler's equations): `dL_body/dt = L_body × ω + Rᵀ τ_world`, whose `|L|` is
//!   conserved only as well as the integrator keeps it.
//!
//! The rotation `R` is computed from `q/|q|`, so `dq/dt` is homogeneous of degree 1 in `q`
//! and every observable depends on the direction of `q` only.

use nalgebra::{Quaternion, UnitQuaternion};

use super::body::{Attitude, SpinningBody, torque};
use crate::Real;
use crate::mass::{Mat3, Vec3};
use crate::ode::OdeSystem;

/// Which angular momentum the state carries.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Formulation {
    /// `L` in the world frame: `dL/dt = τ` (torque-free: constant by construction).
    #[default]
    World,
    /// `L` in the body frame: Euler's equations `dL/dt = L × ω + τ_body`.
    Body,
}

impl Formulation {
    /// The name (`world`, `body`).
    pub fn name(self) -> &'static str {
        match self {
            Formulation::World => "world",
            Formulation::Body => "body",
        }
    }

    /// The state vector of an attitude.
    pub fn to_state(self, a: &Attitude) -> Vec<Real> {
        let q = a.q.quaternion();
        let l = match self {
            Formulation::World => a.l,
            Formulation::Body => a.l_body(),
        };
        vec![q.w, q.i, q.j, q.k, l.x, l.y, l.z]
    }

    /// The attitude of a state vector (the quaternion normalised).
    pub fn attitude(self, y: &[Real]) -> Attitude {
        let q = UnitQuaternion::from_quaternion(Quaternion::new(y[0], y[1], y[2], y[3]));
        let l = Vec3::new(y[4], y[5], y[6]);
        let l = match self {
            Formulation::World => l,
            Formulation::Body => q * l,
        };
        Attitude { q, l }
    }
}

/// `R(q/|q|)` of a quaternion `(w, x, y, z)`.
pub(super) fn rotation(y: &[Real]) -> Mat3 {
    let (w, x, yy, z) = (y[0], y[1], y[2], y[3]);
    let s = 2.0 / (w * w + x * x + yy * yy + z * z);
    Mat3::new(
        1.0 - s * (yy * yy + z * z),
        s * (x * yy - w * z),
        s * (x * z + w * yy),
        s * (x * yy + w * z),
        1.0 - s * (x * x + z * z),
        s * (yy * z - w * x),
        s * (x * z - w * yy),
        s * (yy * z + w * x),
        1.0 - s * (x * x + yy * yy),
    )
}

/// The ODE of a [`SpinningBody`] in a [`Formulation`].
#[derive(Debug, Clone, Copy)]
pub struct SpinEquations<'a> {
    /// The body.
    pub body: &'a SpinningBody,
    /// The frame of `L` in the state.
    pub formulation: Formulation,
}

impl SpinEquations<'_> {
    /// `ω` in the body frame at the state `y`.
    pub fn omega_body(&self, y: &[Real]) -> Vec3 {
        let l = Vec3::new(y[4], y[5], y[6]);
        let lb = match self.formulation {
            Formulation::World => rotation(y).transpose() * l,
            Formulation::Body => l,
        };
        self.body.inverse_inertia() * lb
    }
}

impl OdeSystem for SpinEquations<'_> {
    fn dim(&self) -> usize {
        7
    }

    fn rhs_into(&self, _t: Real, y: &[Real], dydt: &mut [Real]) {
        let r = rotation(y);
        let l = Vec3::new(y[4], y[5], y[6]);
        let lb = match self.formulation {
            Formulation::World => r.transpose() * l,
            Formulation::Body => l,
        };
        let w = self.body.inverse_inertia() * lb;
        let (qw, qv) = (y[0], Vec3::new(y[1], y[2], y[3]));
        // q ⊗ (0, ω) = (−v·ω, w ω + v × ω)
        let dv = 0.5 * (qw * w + qv.cross(&w));
        dydt[0] = -0.5 * qv.dot(&w);
        dydt[1] = dv.x;
        dydt[2] = dv.y;
        dydt[3] = dv.z;
        let tau = self
            .body
            .pivot()
            .map_or_else(Vec3::zeros, |(d, g)| torque(&(r * d), self.body.body().mass() * g));
        let dl = match self.formulation {
            Formulation::World => tau,
            Formulation::Body => lb.cross(&w) + r.transpose() * tau,
        };
        dydt[4] = dl.x;
        dydt[5] = dl.y;
        dydt[6] = dl.z;
    }
}

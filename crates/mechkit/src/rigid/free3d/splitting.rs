//! A structure-preserving fixed step: the splitting of the rigid body's kinetic energy
//! `T = Σ L_i²/(2 J_i)` into three rotations about the body axes, each solved exactly
//! (Dullweber, Leimkuhler & McLachlan, J. Chem. Phys. 107, 5840 (1997); Touma & Wisdom, AJ
//! 107, 1189 (1994)), with gravity's torque as half kicks around it (Strang):
//!
//! `kick(h/2) · R₁(h/2) · R₂(h/2) · R₃(h) · R₂(h/2) · R₁(h/2) · kick(h/2)`.
//!
//! The flow of `L_i²/(2J_i)` turns the body about its axis `i` by `θ = L_i τ / J_i` with `L`
//! fixed in space: `q ← q ⊗ rot(e_i, θ)`, `L_body ← rot(e_i, −θ) L_body`. Each piece is a
//! rotation, so `|L|` and `|q|` are kept to rounding; the method is symplectic and symmetric
//! (second order), so the energy error stays bounded instead of drifting. The kick changes
//! `L_world` by `τ(q) h/2` with the orientation fixed: exact for a torque of orientation.
//! Needs the inertia about the rotation point diagonal in the body frame.

use nalgebra::{Unit, UnitQuaternion};

use super::body::SpinningBody;
use crate::Real;
use crate::mass::Vec3;

/// One step `h` of the splitting on `(q, L_body)`.
pub(super) fn split_step(
    body: &SpinningBody,
    q: &mut UnitQuaternion<Real>,
    lb: &mut Vec3,
    h: Real,
) {
    let j = body.inertia();
    let kick = |q: &UnitQuaternion<Real>, lb: &mut Vec3, tau: Real| {
        let torque = body.torque_world(q);
        if torque != Vec3::zeros() {
            *lb += q.inverse_transform_vector(&(torque * tau));
        }
    };
    let turn = |q: &mut UnitQuaternion<Real>, lb: &mut Vec3, axis: usize, tau: Real| {
        let theta = lb[axis] / j[(axis, axis)] * tau;
        let e = Unit::new_unchecked(Vec3::ith(axis, 1.0));
        let r = UnitQuaternion::from_axis_angle(&e, theta);
        *q *= r;
        *lb = r.inverse_transform_vector(lb);
    };
    kick(q, lb, 0.5 * h);
    turn(q, lb, 0, 0.5 * h);
    turn(q, lb, 1, 0.5 * h);
    turn(q, lb, 2, h);
    turn(q, lb, 1, 0.5 * h);
    turn(q, lb, 0, 0.5 * h);
    kick(q, lb, 0.5 * h);
}

//! References from a state quantity into a rigid body: a body turning in space (its
//! orientation coordinates and inertia) and a point of a rigid body, each evaluated on the
//! state vector.

use super::kinematics::{dot, norm};
use super::spin::{self, Mat3, Quat};
use crate::Real;

/// What of a rigid body turning in space ([`StateVar::Spin`](super::StateVar::Spin)).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SpinField {
    /// Angular velocity component, world frame (`wx`, `wy`, `wz`).
    Omega(usize),
    /// Angular velocity component along a body axis (`w1`, `w2`, `w3`).
    OmegaBody(usize),
    /// Angular speed `|ω|` (`omega`).
    Speed,
    /// Component of the unit orientation quaternion, body → world (`q0` … `q3`).
    Quaternion(usize),
    /// Angular acceleration component, world frame (`alphax`, …).
    Alpha(usize),
    /// Angular momentum about the centre of mass, world frame (`Lx`, …).
    Momentum(usize),
    /// Its magnitude (`L`).
    MomentumMagnitude,
    /// Kinetic energy of the body, `½ m v² + ½ ω·Iω` (`K`).
    Kinetic,
}

/// A rigid body turning in space: body `body`, its orientation coordinates from `first` in
/// `q`, its inertia tensor about the centre of mass in the body frame (stored as bits so the
/// type is `Eq`: `xx, yy, zz, xy, xz, yz`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SpinRef {
    /// Body index.
    pub body: usize,
    /// Index of `q₀` in `q`.
    pub first: usize,
    inertia: [u64; 6],
}

impl SpinRef {
    /// Body `body` with orientation coordinates from `first` and inertia tensor `inertia`.
    pub fn new(body: usize, first: usize, inertia: &Mat3) -> Self {
        let i = inertia;
        Self {
            body,
            first,
            inertia: [i[0][0], i[1][1], i[2][2], i[0][1], i[0][2], i[1][2]].map(Real::to_bits),
        }
    }

    /// The inertia tensor.
    pub fn inertia(self) -> Mat3 {
        let [xx, yy, zz, xy, xz, yz] = self.inertia.map(Real::from_bits);
        [[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]]
    }

    fn quat(self, x: &[Real]) -> Quat {
        let f = self.first;
        [x[f], x[f + 1], x[f + 2], x[f + 3]]
    }

    /// The value of `field` at a state (`a` the accelerations, for [`SpinField::Alpha`]).
    pub fn value(
        self,
        field: SpinField,
        x: &[Real],
        v: &[Real],
        a: &[Real],
        mass: Real,
        dim: usize,
    ) -> Real {
        let (q, qd) = (self.quat(x), self.quat(v));
        match field {
            SpinField::Omega(i) => spin::omega_world(q, qd)[i],
            SpinField::OmegaBody(i) => spin::omega_body(q, qd)[i],
            SpinField::Speed => norm(&spin::omega_body(q, qd)),
            SpinField::Quaternion(i) => q[i] / spin::norm2(q).sqrt(),
            SpinField::Alpha(i) => {
                let n = spin::norm2(q);
                let p = spin::mul(spin::conj(q), self.quat(a));
                let w = spin::omega_body(q, qd);
                let nd = 2.0 * q.iter().zip(qd).map(|(a, b)| a * b).sum::<Real>();
                let wd = [0, 1, 2].map(|k| 2.0 * p[k + 1] / n - w[k] * nd / n);
                spin::rotate(q, wd)[i]
            }
            SpinField::Momentum(i) => {
                spin::rotate(q, spin::mat_vec(&self.inertia(), spin::omega_body(q, qd)))[i]
            }
            SpinField::MomentumMagnitude => {
                norm(&spin::mat_vec(&self.inertia(), spin::omega_body(q, qd)))
            }
            SpinField::Kinetic => {
                let w = spin::omega_body(q, qd);
                let vc = &v[self.body * dim..(self.body + 1) * dim];
                0.5 * mass * dot(vc, vc) + 0.5 * spin::dot3(w, spin::mat_vec(&self.inertia(), w))
            }
        }
    }
}

/// A point of a rigid body: body `body`, turned by the angle coordinate `angle` (in a plane)
/// or by the quaternion from coordinate `angle` on (in space), at `r` from its centre of mass
/// in the body frame (stored as bits so the type is `Eq`); `r` holds the moment of inertia
/// in its first component for [`StateVar::RigidKinetic`](super::StateVar::RigidKinetic).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PointRef {
    /// Body index.
    pub body: usize,
    /// Index of the body's angle (or first quaternion component) in `q`.
    pub angle: usize,
    r: [u64; 3],
    spatial: bool,
}

impl PointRef {
    /// The point `r` (body frame) of body `body` with angle coordinate `angle`.
    pub fn new(body: usize, angle: usize, r: [Real; 2]) -> Self {
        Self {
            body,
            angle,
            r: [r[0].to_bits(), r[1].to_bits(), 0],
            spatial: false,
        }
    }

    /// The point `r` (body frame) of body `body` turning in space, its quaternion from
    /// coordinate `first`.
    pub fn spatial(body: usize, first: usize, r: [Real; 3]) -> Self {
        Self {
            body,
            angle: first,
            r: r.map(Real::to_bits),
            spatial: true,
        }
    }

    /// The offset from the centre of mass, body frame (in a plane).
    pub fn r(self) -> [Real; 2] {
        [Real::from_bits(self.r[0]), Real::from_bits(self.r[1])]
    }

    /// World position (`rate` false) or velocity (true) component `i` at a state.
    pub fn value(self, x: &[Real], v: &[Real], dim: usize, i: usize, rate: bool) -> Real {
        if self.spatial {
            let f = self.angle;
            let q = [x[f], x[f + 1], x[f + 2], x[f + 3]];
            let w = spin::rotate(q, self.r.map(Real::from_bits));
            let b = self.body * dim + i;
            return if rate {
                let omega = spin::omega_world(q, [v[f], v[f + 1], v[f + 2], v[f + 3]]);
                v[b] + spin::cross(omega, w)[i]
            } else {
                x[b] + w[i]
            };
        }
        let r = self.r();
        let (s, c) = x[self.angle].sin_cos();
        let w = [c * r[0] - s * r[1], s * r[0] + c * r[1]];
        let b = self.body * dim + i;
        if rate {
            let omega = v[self.angle];
            v[b] + omega * [-w[1], w[0]][i]
        } else {
            x[b] + w[i]
        }
    }
}

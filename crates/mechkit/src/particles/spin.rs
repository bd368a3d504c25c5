//! The orientation of a rigid body in space as four coordinates of a particle system: a
//! quaternion `q` (body → world), its rate `q̇`, and the generalized force a torque puts on
//! them.
//!
//! - the angular velocity in the body frame is `ω_b = 2 vec(q* ⊗ q̇) / |q|²`;
//! - a world torque `τ` is the generalized force `Q = 2 (0, τ) ⊗ q / |q|²`, so that
//!   `Q · q̇ = τ · ω`: a force's power over these coordinates is its torque's power, and the
//!   ledger books it like any other;
//! - Euler's equations `I ω̇_b = τ_b − ω_b × I ω_b` give `q̈ = q̇ ⊗ p + ½ q ⊗ (0, ω̇_b) − p₀² q`
//!   with `p = q* ⊗ q̇ / |q|²`, which keeps `d²|q|/dt² = 0` exactly.
//!
//! Everything observable depends on the direction of `q` only: the integrator may let `|q|`
//! drift, nothing reads it.

use crate::Real;

/// A quaternion `[w, x, y, z]`.
pub type Quat = [Real; 4];

/// A 3×3 matrix, row by row.
pub type Mat3 = [[Real; 3]; 3];

/// `a ⊗ b`.
#[inline]
pub fn mul(a: Quat, b: Quat) -> Quat {
    [
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
        a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
        a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
        a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
    ]
}

/// `q*`.
#[inline]
pub fn conj(q: Quat) -> Quat {
    [q[0], -q[1], -q[2], -q[3]]
}

/// `|q|²`.
#[inline]
pub fn norm2(q: Quat) -> Real {
    q.iter().map(|x| x * x).sum()
}

/// The pure quaternion `(0, v)`.
#[inline]
pub fn pure(v: [Real; 3]) -> Quat {
    [0.0, v[0], v[1], v[2]]
}

/// The vector part.
#[inline]
pub fn vec3(q: Quat) -> [Real; 3] {
    [q[1], q[2], q[3]]
}

/// `m v`.
#[inline]
pub fn mat_vec(m: &Mat3, v: [Real; 3]) -> [Real; 3] {
    [
        m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2],
        m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
        m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2],
    ]
}

/// `a × b`.
#[inline]
pub fn cross(a: [Real; 3], b: [Real; 3]) -> [Real; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `a · b`.
#[inline]
pub fn dot3(a: [Real; 3], b: [Real; 3]) -> Real {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `v` turned by `q` (body → world): `q ⊗ (0, v) ⊗ q* / |q|²`.
#[inline]
pub fn rotate(q: Quat, v: [Real; 3]) -> [Real; 3] {
    let n = norm2(q);
    let r = vec3(mul(mul(q, pure(v)), conj(q)));
    [r[0] / n, r[1] / n, r[2] / n]
}

/// `v` turned back by `q` (world → body).
#[inline]
pub fn unrotate(q: Quat, v: [Real; 3]) -> [Real; 3] {
    rotate(conj(q), v)
}

/// The angular velocity in the body frame at `(q, q̇)`.
#[inline]
pub fn omega_body(q: Quat, qd: Quat) -> [Real; 3] {
    let p = mul(conj(q), qd);
    let s = 2.0 / norm2(q);
    [s * p[1], s * p[2], s * p[3]]
}

/// The angular velocity in the world frame at `(q, q̇)`.
#[inline]
pub fn omega_world(q: Quat, qd: Quat) -> [Real; 3] {
    rotate(q, omega_body(q, qd))
}

/// The rate `q̇` that turns `q` at the world angular velocity `omega`.
pub fn rate_for(q: Quat, omega: [Real; 3]) -> Quat {
    mul(pure(omega), q).map(|x| 0.5 * x)
}

/// The generalized force of the world torque `tau` on the coordinates `q`.
#[inline]
pub fn torque_force(q: Quat, tau: [Real; 3]) -> Quat {
    let s = 2.0 / norm2(q);
    mul(pure(tau), q).map(|x| s * x)
}

/// The world torque of the generalized force `f` on the coordinates `q`.
#[inline]
pub fn force_torque(q: Quat, f: Quat) -> [Real; 3] {
    let t = mul(f, conj(q));
    [0.5 * t[1], 0.5 * t[2], 0.5 * t[3]]
}

/// The inverse of a symmetric positive definite matrix; `None` if it is not one.
pub fn invert_spd(m: &Mat3) -> Option<Mat3> {
    let c = |i: usize, j: usize| {
        let (a, b) = ((i + 1) % 3, (i + 2) % 3);
        let (d, e) = ((j + 1) % 3, (j + 2) % 3);
        m[a][d] * m[b][e] - m[a][e] * m[b][d]
    };
    let det = m[0][0] * c(0, 0) + m[0][1] * c(0, 1) + m[0][2] * c(0, 2);
    let symmetric = (0..3).all(|i| {
        (0..3).all(|j| (m[i][j] - m[j][i]).abs() <= 1e-12 * m[i][i].abs().max(m[j][j].abs()))
    });
    let minors = m[0][0] > 0.0 && m[0][0] * m[1][1] - m[0][1] * m[1][0] > 0.0 && det > 0.0;
    if !(symmetric && minors && det.is_finite()) {
        return None;
    }
    let mut inv = [[0.0; 3]; 3];
    for (i, row) in inv.iter_mut().enumerate() {
        for (j, x) in row.iter_mut().enumerate() {
            *x = c(j, i) / det;
        }
    }
    Some(inv)
}

/// A rigid body turning in space: its orientation is coordinates `first..first + 4` of the
/// system, its inertia tensor about the centre of mass is given in the body frame.
#[derive(Debug, Clone, PartialEq)]
pub struct Spinner {
    /// The body (index among the system's bodies).
    pub body: usize,
    /// Index of `q₀` in the system's coordinates.
    pub first: usize,
    /// Inertia tensor about the centre of mass, body frame (kg m²).
    pub inertia: Mat3,
    inv_inertia: Mat3,
}

impl Spinner {
    /// A body with inertia tensor `inertia` (body frame, about the centre of mass); `None`
    /// if the tensor is not symmetric positive definite.
    pub fn new(body: usize, first: usize, inertia: Mat3) -> Option<Self> {
        Some(Self {
            body,
            first,
            inertia,
            inv_inertia: invert_spd(&inertia)?,
        })
    }

    /// Its quaternion and rate in a state.
    #[inline]
    pub fn of(&self, q: &[Real], v: &[Real]) -> (Quat, Quat) {
        let f = self.first;
        (
            [q[f], q[f + 1], q[f + 2], q[f + 3]],
            [v[f], v[f + 1], v[f + 2], v[f + 3]],
        )
    }

    /// `q̈` from the generalized force `f` on its coordinates.
    pub fn accel(&self, q: Quat, qd: Quat, f: Quat) -> Quat {
        let n = norm2(q);
        let w = omega_body(q, qd);
        let tau = unrotate(q, force_torque(q, f));
        let iw = mat_vec(&self.inertia, w);
        let g = cross(w, iw);
        let wd = mat_vec(
            &self.inv_inertia,
            [tau[0] - g[0], tau[1] - g[1], tau[2] - g[2]],
        );
        let p = mul(conj(q), qd).map(|x| x / n);
        let a = mul(qd, p);
        let b = mul(q, pure(wd));
        let mut out = [0.0; 4];
        for k in 0..4 {
            out[k] = a[k] + 0.5 * b[k] - p[0] * p[0] * q[k];
        }
        out
    }

    /// The part of `q̈` that the generalized force `f` adds (linear in `f`): the response a
    /// constraint solver needs.
    pub fn response(&self, q: Quat, f: Quat) -> Quat {
        let tau = unrotate(q, force_torque(q, f));
        let wd = mat_vec(&self.inv_inertia, tau);
        mul(q, pure(wd)).map(|x| 0.5 * x)
    }

    /// Rotational kinetic energy `½ ω·Iω`.
    pub fn kinetic(&self, q: Quat, qd: Quat) -> Real {
        let w = omega_body(q, qd);
        0.5 * dot3(w, mat_vec(&self.inertia, w))
    }

    /// Angular momentum about the centre of mass, world frame.
    pub fn momentum(&self, q: Quat, qd: Quat) -> [Real; 3] {
        rotate(q, mat_vec(&self.inertia, omega_body(q, qd)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: [Real; 3], b: [Real; 3], tol: Real) {
        for k in 0..3 {
            assert!((a[k] - b[k]).abs() < tol, "{a:?} vs {b:?}");
        }
    }

    #[test]
    fn rotation_and_rates() {
        // a quarter turn about z, scaled: x goes to y
        let h = (0.5 as Real).sqrt();
        let q = [2.0 * h, 0.0, 0.0, 2.0 * h];
        close(rotate(q, [1.0, 0.0, 0.0]), [0.0, 1.0, 0.0], 1e-15);
        close(unrotate(q, [0.0, 1.0, 0.0]), [1.0, 0.0, 0.0], 1e-15);
        let w = [0.3, -1.0, 2.0];
        let qd = rate_for(q, w);
        close(omega_world(q, qd), w, 1e-14);
        let tau = [1.0, 2.0, -0.5];
        let f = torque_force(q, tau);
        close(force_torque(q, f), tau, 1e-14);
        // Q·q̇ = τ·ω
        let power: Real = f.iter().zip(qd).map(|(a, b)| a * b).sum();
        assert!((power - dot3(tau, w)).abs() < 1e-14);
    }

    #[test]
    fn torque_free_symmetric_body_keeps_its_spin() {
        // about a principal axis: no acceleration, and |q| has no second derivative
        let s = Spinner::new(0, 0, [[1.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 3.0]]).unwrap();
        let q = [1.0, 0.0, 0.0, 0.0];
        let qd = rate_for(q, [0.0, 0.0, 5.0]);
        let a = s.accel(q, qd, [0.0; 4]);
        // q̈ = -¼ ω² q for a steady spin
        assert!((a[0] + 0.25 * 25.0).abs() < 1e-12, "{a:?}");
        assert!((s.kinetic(q, qd) - 0.5 * 3.0 * 25.0).abs() < 1e-12);
        assert!(Spinner::new(0, 0, [[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, 1.0]]).is_none());
        assert!(Spinner::new(0, 0, [[1.0, 0.5, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]).is_none());
    }
}

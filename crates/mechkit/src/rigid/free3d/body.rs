//! The body (principal moments and mass), how it is held (free, or on a pivot in uniform
//! gravity), its attitude (orientation and angular momentum) and what is observed of it.

use nalgebra::UnitQuaternion;

use super::error::Free3dError;
use crate::Real;
use crate::mass::{MassProperties, Mat3, Vec3, parallel_axis};
use crate::rigid::Input;

/// An orientation: the rotation from the body frame to the world frame.
pub type Orientation = UnitQuaternion<Real>;

/// A rigid body as rotation sees it: its principal moments of inertia about the centre of
/// mass (kg·m², the body frame is the principal axes) and its mass (kg).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FreeBody {
    moments: [Real; 3],
    mass: Real,
}

impl FreeBody {
    /// A body with principal moments `[I1, I2, I3]` about its centre of mass and mass `m`:
    /// each moment positive and finite, none above the sum of the other two (the triangle
    /// inequality every distribution of positive mass obeys), `m` positive and finite.
    ///
    /// ```
    /// use mechkit::rigid::free3d::{Free3dError, FreeBody};
    /// assert!(FreeBody::new([1.0, 2.0, 3.0], 1.0).is_ok());
    /// assert!(matches!(
    ///     FreeBody::new([1.0, 1.0, 3.0], 1.0),
    ///     Err(Free3dError::Triangle { largest: 3, .. })
    /// ));
    /// ```
    pub fn new(moments: [Real; 3], mass: Real) -> Result<Self, Free3dError> {
        for (k, &value) in moments.iter().enumerate() {
            if !crate::invertible(value) {
                return Err(Free3dError::Moment {
                    index: k + 1,
                    value,
                });
            }
        }
        for k in 0..3 {
            let others = moments[(k + 1) % 3] + moments[(k + 2) % 3];
            // a flat body has equality; allow rounding of the sum
            if moments[k] > others * (1.0 + 8.0 * Real::EPSILON) {
                return Err(Free3dError::Triangle {
                    moments,
                    largest: k + 1,
                });
            }
        }
        if !crate::invertible(mass) {
            return Err(Free3dError::Mass { value: mass });
        }
        Ok(Self { moments, mass })
    }

    /// The body of `properties` (a shape or a body file): its principal moments about the
    /// centre of mass, and the rotation whose columns are the principal axes in the
    /// properties' frame (body frame → that frame).
    pub fn from_mass_properties(
        properties: &MassProperties,
    ) -> Result<(Self, UnitQuaternion<Real>), Free3dError> {
        let principal = properties.principal();
        let body = Self::new(principal.moments, properties.mass)?;
        let axes = nalgebra::Rotation3::from_matrix_unchecked(principal.axes);
        Ok((body, UnitQuaternion::from_rotation_matrix(&axes)))
    }

    /// `[I1, I2, I3]` (kg·m²).
    pub fn moments(&self) -> [Real; 3] {
        self.moments
    }

    /// The mass (kg).
    pub fn mass(&self) -> Real {
        self.mass
    }

    /// The index (0, 1 or 2) of the intermediate moment.
    pub fn intermediate_axis(&self) -> usize {
        let i = self.moments;
        let mut order = [0, 1, 2];
        order.sort_by(|&a, &b| i[a].total_cmp(&i[b]));
        order[1]
    }
}

/// A body free of torques (rotating about its centre of mass), or held at a pivot in uniform
/// gravity `g` along −z (the heavy top). The body frame is the principal frame about the
/// centre of mass; the pivot is the origin of the world frame.
#[derive(Debug, Clone, PartialEq)]
pub struct SpinningBody {
    body: FreeBody,
    /// The vector from the pivot to the centre of mass, body frame (m), and `g`.
    pivot: Option<(Vec3, Real)>,
    /// The inertia tensor about the rotation point (CM or pivot), body frame, and its inverse.
    inertia: Mat3,
    inverse: Mat3,
}

impl SpinningBody {
    /// A torque-free body rotating about its centre of mass.
    pub fn free(body: FreeBody) -> Self {
        let inertia = Mat3::from_diagonal(&Vec3::from(body.moments));
        let inverse = Mat3::from_diagonal(&Vec3::from(body.moments.map(|i| 1.0 / i)));
        Self {
            body,
            pivot: None,
            inertia,
            inverse,
        }
    }

    /// The body held at a fixed point: `cm_offset` is the vector from the pivot to the centre
    /// of mass in the body frame (m), `g ≥ 0` the gravity along −z (m/s²). The inertia about
    /// the pivot follows from the parallel-axis theorem.
    pub fn on_pivot(body: FreeBody, cm_offset: Vec3, g: Real) -> Result<Self, Free3dError> {
        if !cm_offset.iter().all(|x| x.is_finite()) {
            return Err(Free3dError::NonFinite {
                input: Input::Pivot,
                what: "the pivot offset",
                value: cm_offset.into(),
            });
        }
        if !(g >= 0.0 && g.is_finite()) {
            return Err(Free3dError::Gravity { value: g });
        }
        let inertia = parallel_axis(
            &Mat3::from_diagonal(&Vec3::from(body.moments)),
            body.mass,
            &cm_offset,
        );
        let inverse = inertia
            .try_inverse()
            .expect("a positive-definite inertia tensor is invertible");
        Ok(Self {
            body,
            pivot: Some((cm_offset, g)),
            inertia,
            inverse,
        })
    }

    /// The body.
    pub fn body(&self) -> &FreeBody {
        &self.body
    }

    /// The vector from the pivot to the centre of mass (body frame) and `g`, if held.
    pub fn pivot(&self) -> Option<(Vec3, Real)> {
        self.pivot
    }

    /// The inertia tensor about the rotation point (the centre of mass, or the pivot), body
    /// frame (kg·m²).
    pub fn inertia(&self) -> &Mat3 {
        &self.inertia
    }

    /// The inverse of [`SpinningBody::inertia`].
    pub fn inverse_inertia(&self) -> &Mat3 {
        &self.inverse
    }

    /// The attitude with orientation `q` (body → world) and angular velocity `omega_body`
    /// (rad/s, body frame): `L = R J ω`.
    pub fn attitude(
        &self,
        q: UnitQuaternion<Real>,
        omega_body: Vec3,
    ) -> Result<Attitude, Free3dError> {
        if !omega_body.iter().all(|x| x.is_finite()) {
            return Err(Free3dError::NonFinite {
                input: Input::AngularVelocity,
                what: "the angular velocity",
                value: omega_body.into(),
            });
        }
        let norm = q.quaternion().norm();
        if !(norm.is_finite() && (norm - 1.0).abs() < 1e-6) {
            return Err(Free3dError::Quaternion { norm });
        }
        Ok(Attitude {
            q,
            l: q * (self.inertia * omega_body),
        })
    }

    /// `ω` in the body frame: `J⁻¹ Rᵀ L`.
    pub fn omega_body(&self, a: &Attitude) -> Vec3 {
        self.inverse * a.l_body()
    }

    /// `ω` in the world frame.
    pub fn omega_world(&self, a: &Attitude) -> Vec3 {
        a.q * self.omega_body(a)
    }

    /// The rotational kinetic energy `½ ω·Jω = ½ ω·L` (J).
    pub fn kinetic_energy(&self, a: &Attitude) -> Real {
        let lb = a.l_body();
        0.5 * lb.dot(&(self.inverse * lb))
    }

    /// The potential energy `m g z_cm` with the pivot at `z = 0` (0 for a free body) (J).
    pub fn potential_energy(&self, q: &UnitQuaternion<Real>) -> Real {
        self.pivot
            .map_or(0.0, |(d, g)| self.body.mass * g * (q * d).z)
    }

    /// `T + U` (J).
    pub fn energy(&self, a: &Attitude) -> Real {
        self.kinetic_energy(a) + self.potential_energy(&a.q)
    }

    /// The torque of gravity about the pivot, world frame: `(R d) × (0, 0, −m g)` (N·m).
    pub fn torque_world(&self, q: &UnitQuaternion<Real>) -> Vec3 {
        self.pivot
            .map_or_else(Vec3::zeros, |(d, g)| torque(&(q * d), self.body.mass * g))
    }
}

/// `r × (0, 0, −w)`.
pub(super) fn torque(r: &Vec3, weight: Real) -> Vec3 {
    Vec3::new(-r.y * weight, r.x * weight, 0.0)
}

/// Orientation and angular momentum: the state of a rotating body.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Attitude {
    /// The rotation from the body frame to the world frame.
    pub q: UnitQuaternion<Real>,
    /// The angular momentum about the rotation point, world frame (kg·m²/s).
    pub l: Vec3,
}

impl Attitude {
    /// The angular momentum in the body frame, `Rᵀ L`.
    pub fn l_body(&self) -> Vec3 {
        self.q.inverse_transform_vector(&self.l)
    }

    /// The z-x-z Euler angles `(φ, θ, ψ)` of the orientation (Goldstein): precession `φ`
    /// about the world z axis, nutation `θ` (the angle between the body's third axis and
    /// the world z axis), spin `ψ` about the body's third axis (rad).
    pub fn euler_angles(&self) -> (Real, Real, Real) {
        let r = self.q.to_rotation_matrix();
        let r = r.matrix();
        // θ from both its sine and cosine: acos(cos θ) alone loses half the digits near
        // upright (a tilt of 1e-8 rad read as 0 to 1.5e-8)
        let theta = r[(0, 2)].hypot(r[(1, 2)]).atan2(r[(2, 2)]);
        let phi = r[(0, 2)].atan2(-r[(1, 2)]);
        let psi = r[(2, 0)].atan2(r[(2, 1)]);
        (phi, theta, psi)
    }
}

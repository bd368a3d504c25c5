//! Mass properties of a rigid body: mass, centre of mass and inertia tensor about the centre
//! of mass, with the parallel-axis theorem (Steiner), inertia about any point and any axis,
//! principal moments and axes, placing a body in space and adding bodies (holes as negative
//! mass).

use nalgebra::{Matrix3, Rotation3, SymmetricEigen, Vector3};

use super::MassError;
use crate::Real;

/// A vector in space (m).
pub type Vec3 = Vector3<Real>;
/// A 3×3 tensor (kg·m² for inertia tensors).
pub type Mat3 = Matrix3<Real>;

/// Mass, centre of mass and the inertia tensor about the centre of mass (world axes).
///
/// ```
/// use mechkit::mass::{MassProperties, Vec3};
/// // two 1 kg points 2 m apart: I = 2 kg m² about the perpendicular axes through the CM
/// let a = MassProperties::point(1.0, Vec3::new(-1.0, 0.0, 0.0));
/// let b = MassProperties::point(1.0, Vec3::new(1.0, 0.0, 0.0));
/// let both = MassProperties::sum(&[a, b]).unwrap();
/// assert_eq!(both.inertia[(2, 2)], 2.0);
/// // about one of the points (Steiner): 2 + 2·1² = 4
/// let end = both.inertia_about(&Vec3::new(-1.0, 0.0, 0.0));
/// assert_eq!(end[(2, 2)], 4.0);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MassProperties {
    /// Mass (kg); negative for a hole.
    pub mass: Real,
    /// Centre of mass (m).
    pub centre_of_mass: Vec3,
    /// Inertia tensor about the centre of mass (kg·m²), world axes.
    pub inertia: Mat3,
}

/// Principal moments (ascending) and axes (columns of a right-handed rotation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Principal {
    /// `I₁ ≤ I₂ ≤ I₃`.
    pub moments: [Real; 3],
    /// Column `k` is the axis of `moments[k]`; `axes` is a proper rotation (det +1).
    pub axes: Mat3,
}

/// `I_P = I_cm + m (|d|² 𝟙 − d dᵀ)`: the inertia tensor about a point `P` from the one about
/// the centre of mass, with `d` the vector from `P` to the centre of mass (Steiner's theorem).
///
/// ```
/// use mechkit::mass::{Mat3, Vec3, parallel_axis};
/// // a thin rod (m = 3 kg, L = 2 m) about its end: mL²/12 + m(L/2)² = mL²/3
/// let i_cm = Mat3::from_diagonal(&Vec3::new(1.0, 1.0, 0.0));
/// let i_end = parallel_axis(&i_cm, 3.0, &Vec3::new(0.0, 0.0, 1.0));
/// assert_eq!(i_end[(0, 0)], 4.0);
/// ```
pub fn parallel_axis(inertia_cm: &Mat3, mass: Real, offset: &Vec3) -> Mat3 {
    inertia_cm + mass * (Mat3::identity() * offset.norm_squared() - offset * offset.transpose())
}

/// The inertia tensor `tr(C) 𝟙 − C` of a second-moment tensor `C = ∫ r rᵀ dm`.
pub fn inertia_from_second_moment(c: &Mat3) -> Mat3 {
    Mat3::identity() * c.trace() - c
}

/// The second-moment tensor `C = ∫ r rᵀ dm = ½ tr(I) 𝟙 − I` of an inertia tensor.
pub fn second_moment_from_inertia(inertia: &Mat3) -> Mat3 {
    Mat3::identity() * (0.5 * inertia.trace()) - inertia
}

impl MassProperties {
    /// From the parts; the inertia tensor is symmetrised.
    pub fn new(mass: Real, centre_of_mass: Vec3, inertia: Mat3) -> Self {
        Self {
            mass,
            centre_of_mass,
            inertia: 0.5 * (inertia + inertia.transpose()),
        }
    }

    /// A point mass.
    pub fn point(mass: Real, at: Vec3) -> Self {
        Self::new(mass, at, Mat3::zeros())
    }

    /// From the moments about the origin: mass `m`, first moment `∫ r dm` and second moment
    /// `∫ r rᵀ dm`.
    pub fn from_moments(mass: Real, first: &Vec3, second: &Mat3) -> Self {
        let cm = first / mass;
        let c_cm = second - mass * cm * cm.transpose();
        Self::new(mass, cm, inertia_from_second_moment(&c_cm))
    }

    /// The same body with its mass (and inertia) multiplied by `factor`.
    #[must_use]
    pub fn scaled(&self, factor: Real) -> Self {
        Self::new(
            self.mass * factor,
            self.centre_of_mass,
            self.inertia * factor,
        )
    }

    /// The same shape as a hole: negative mass.
    #[must_use]
    pub fn hole(&self) -> Self {
        self.scaled(-1.0)
    }

    /// The body moved by `offset`.
    #[must_use]
    pub fn translated(&self, offset: &Vec3) -> Self {
        Self::new(self.mass, self.centre_of_mass + offset, self.inertia)
    }

    /// The body rotated about the origin: `r → R r`, `I → R I Rᵀ`.
    #[must_use]
    pub fn rotated(&self, rotation: &Rotation3<Real>) -> Self {
        let r = rotation.matrix();
        Self::new(
            self.mass,
            r * self.centre_of_mass,
            r * self.inertia * r.transpose(),
        )
    }

    /// The inertia tensor about `point` (parallel-axis theorem).
    pub fn inertia_about(&self, point: &Vec3) -> Mat3 {
        parallel_axis(&self.inertia, self.mass, &(self.centre_of_mass - point))
    }

    /// The moment of inertia about the axis through `point` along `direction` (any length).
    pub fn moment_about_axis(&self, point: &Vec3, direction: &Vec3) -> Result<Real, MassError> {
        let n = direction.norm();
        if !(n.is_finite() && n > 0.0) {
            return Err(MassError::ZeroAxis {
                direction: [direction.x, direction.y, direction.z],
            });
        }
        let u = direction / n;
        Ok((u.transpose() * self.inertia_about(point) * u)[(0, 0)])
    }

    /// The radius of gyration `k = √(I/m)` about the axis through `point` along `direction`.
    pub fn radius_of_gyration(&self, point: &Vec3, direction: &Vec3) -> Result<Real, MassError> {
        Ok((self.moment_about_axis(point, direction)? / self.mass).sqrt())
    }

    /// The principal moments about the centre of mass and their axes.
    pub fn principal(&self) -> Principal {
        principal(&self.inertia)
    }

    /// The sum of several bodies (holes have negative mass). Fails when the total mass is
    /// not positive, as when holes cancel the body.
    pub fn sum(parts: &[MassProperties]) -> Result<Self, MassError> {
        let mass: Real = parts.iter().map(|p| p.mass).sum();
        let gross: Real = parts.iter().map(|p| p.mass.abs()).sum();
        if parts.is_empty() || mass.is_nan() || mass <= 1e-12 * gross || !mass.is_finite() {
            return Err(MassError::ZeroMass { total: mass, gross });
        }
        let first: Vec3 = parts.iter().map(|p| p.mass * p.centre_of_mass).sum();
        let cm = first / mass;
        let inertia: Mat3 = parts.iter().map(|p| p.inertia_about(&cm)).sum();
        Ok(Self::new(mass, cm, inertia))
    }
}

/// Principal moments (ascending) and right-handed axes of a symmetric tensor. Each of the
/// first two axes points to where its largest component is positive, so the result does not
/// depend on the eigen-solver's signs.
pub fn principal(tensor: &Mat3) -> Principal {
    let eig = SymmetricEigen::new(0.5 * (tensor + tensor.transpose()));
    let mut order = [0usize, 1, 2];
    order.sort_by(|&a, &b| eig.eigenvalues[a].total_cmp(&eig.eigenvalues[b]));
    let mut cols = order.map(|k| eig.eigenvectors.column(k).into_owned());
    for c in cols.iter_mut().take(2) {
        let big = c.iamax();
        if c[big] < 0.0 {
            *c = -*c;
        }
    }
    cols[2] = cols[0].cross(&cols[1]);
    Principal {
        moments: order.map(|k| eig.eigenvalues[k]),
        axes: Mat3::from_columns(&cols),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn principal_axes_are_sorted_and_right_handed() {
        // a box 1 × 2 × 3 (m = 12) rotated 30° about z
        let i = Mat3::from_diagonal(&Vec3::new(13.0, 10.0, 5.0));
        let body = MassProperties::new(12.0, Vec3::zeros(), i)
            .rotated(&Rotation3::from_axis_angle(&Vector3::z_axis(), 0.5));
        let p = body.principal();
        assert!((p.moments[0] - 5.0).abs() < 1e-12);
        assert!((p.moments[2] - 13.0).abs() < 1e-12);
        assert!((p.axes.determinant() - 1.0).abs() < 1e-12);
        let back = p.axes * Mat3::from_diagonal(&Vec3::from(p.moments)) * p.axes.transpose();
        assert!((back - body.inertia).norm() < 1e-12);
        // the smallest moment is the z axis
        assert!((p.axes.column(0).z.abs() - 1.0).abs() < 1e-12);
    }

    #[test]
    fn holes_that_cancel_the_body_are_an_error() {
        let b = MassProperties::point(2.0, Vec3::zeros());
        assert!(matches!(
            MassProperties::sum(&[b, b.hole()]),
            Err(MassError::ZeroMass { .. })
        ));
        assert!(b.moment_about_axis(&Vec3::zeros(), &Vec3::zeros()).is_err());
    }
}

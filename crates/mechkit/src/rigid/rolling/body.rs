//! The rolling body: mass, radius of the contact circle, and the inertia factor
//! `k = I/(m R²)` of its moment about the centre of mass.

use super::error::RollingError;
use crate::Real;
use crate::mass::{Shape, Vec3};

/// A rigid body with a circular contact profile: a sphere, cylinder, hoop… of mass `m` and
/// radius `R`, with moment of inertia `I = k m R²` about the axis through its centre of mass
/// perpendicular to the plane of motion.
///
/// # Example
/// ```
/// use approx::assert_relative_eq;
/// use mechkit::mass::Shape;
/// use mechkit::rigid::rolling::RollingBody;
/// let ball = RollingBody::sphere(0.45, 0.11)?;
/// assert_relative_eq!(ball.moment_of_inertia(), 0.4 * 0.45 * 0.11 * 0.11);
/// // the same from the mass module's shape: k about the rolling axis
/// let shape = Shape::Cylinder { radius: 0.2, inner_radius: 0.1, height: 0.5 };
/// let pipe = RollingBody::from_shape(&shape, 3.0)?;
/// assert_relative_eq!(pipe.k, (0.2f64.powi(2) + 0.1f64.powi(2)) / 2.0 / 0.04, max_relative = 1e-12);
/// assert!(RollingBody::from_shape(&Shape::Rod { length: 1.0 }, 1.0).is_err());
/// # Ok::<(), mechkit::rigid::rolling::RollingError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollingBody {
    /// Mass (kg).
    pub mass: Real,
    /// Radius of the contact circle (m).
    pub radius: Real,
    /// Inertia factor `k = I/(m R²)` (2/5 solid sphere, 2/3 hollow sphere, 1/2 cylinder,
    /// 1 hoop).
    pub k: Real,
}

impl RollingBody {
    /// A body of `mass` (kg), `radius` (m) and inertia factor `k`. Checked.
    pub fn new(mass: Real, radius: Real, k: Real) -> Result<Self, RollingError> {
        let body = Self { mass, radius, k };
        body.validate()?;
        Ok(body)
    }

    /// A solid sphere, `k = 2/5`.
    pub fn sphere(mass: Real, radius: Real) -> Result<Self, RollingError> {
        Self::new(mass, radius, 0.4)
    }

    /// A thin spherical shell, `k = 2/3`.
    pub fn hollow_sphere(mass: Real, radius: Real) -> Result<Self, RollingError> {
        Self::new(mass, radius, 2.0 / 3.0)
    }

    /// A solid cylinder or disk, `k = 1/2`.
    pub fn cylinder(mass: Real, radius: Real) -> Result<Self, RollingError> {
        Self::new(mass, radius, 0.5)
    }

    /// A thin hoop or ring, `k = 1`.
    pub fn hoop(mass: Real, radius: Real) -> Result<Self, RollingError> {
        Self::new(mass, radius, 1.0)
    }

    /// A preset by name: `sphere`, `hollow-sphere` (or `shell`), `cylinder` (or `disk`),
    /// `hoop` (or `ring`).
    pub fn preset(name: &str, mass: Real, radius: Real) -> Result<Self, RollingError> {
        let k = Self::preset_factor(name).ok_or_else(|| RollingError::UnknownBody {
            name: name.to_string(),
        })?;
        Self::new(mass, radius, k)
    }

    /// The inertia factor of a preset name, `None` if unknown.
    pub fn preset_factor(name: &str) -> Option<Real> {
        match name.to_ascii_lowercase().as_str() {
            "sphere" | "ball" | "solid-sphere" => Some(0.4),
            "hollow-sphere" | "shell" | "spherical-shell" => Some(2.0 / 3.0),
            "cylinder" | "disk" | "disc" | "solid-cylinder" => Some(0.5),
            "hoop" | "ring" | "thin-hoop" => Some(1.0),
            _ => None,
        }
    }

    /// The body of a [`Shape`] of `mass`: the radius of its circular profile and `k` from its
    /// moment about the rolling axis through the centre of mass (a sphere's any axis; the
    /// symmetry axis z of a cylinder, tube, disk or ring, which rolls on its rim). Other
    /// shapes have no radius to roll on: [`RollingError::ShapeCannotRoll`].
    pub fn from_shape(shape: &Shape, mass: Real) -> Result<Self, RollingError> {
        let radius = match shape {
            Shape::Sphere { radius, .. }
            | Shape::SphericalShell { radius }
            | Shape::Cylinder { radius, .. }
            | Shape::Tube { radius, .. }
            | Shape::Disk { radius, .. }
            | Shape::Ring { radius } => *radius,
            other => {
                return Err(RollingError::ShapeCannotRoll {
                    shape: other.name(),
                });
            }
        };
        if !(mass.is_finite() && mass > 0.0) {
            return Err(RollingError::Mass { value: mass });
        }
        if !(radius.is_finite() && radius > 0.0) {
            return Err(RollingError::NoRadius { radius });
        }
        let props = shape.with_mass(mass)?;
        let moment = props.moment_about_axis(&props.centre_of_mass, &Vec3::z())?;
        Self::new(mass, radius, moment / (mass * radius * radius))
    }

    /// Checks every field.
    pub fn validate(&self) -> Result<(), RollingError> {
        if !(self.mass.is_finite() && self.mass > 0.0) {
            return Err(RollingError::Mass { value: self.mass });
        }
        if !(self.radius.is_finite() && self.radius > 0.0) {
            return Err(RollingError::NoRadius {
                radius: self.radius,
            });
        }
        if !(self.k.is_finite() && self.k > 0.0) {
            return Err(RollingError::InertiaFactor { value: self.k });
        }
        Ok(())
    }

    /// The moment of inertia about the centre of mass, `I = k m R²` (kg m²).
    pub fn moment_of_inertia(&self) -> Real {
        self.k * self.mass * self.radius * self.radius
    }
}

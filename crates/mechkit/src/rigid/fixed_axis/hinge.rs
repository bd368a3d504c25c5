//! A rigid body hinged to the world: its moment of inertia about the axis, the position of
//! its centre of mass as it turns, and the weights hanging from its axle.

use thiserror::Error;

use super::torques::{GravityTorque, HangingWeight};
use crate::Real;
use crate::mass::{MassError, MassProperties, Vec3};

/// Why a hinged body cannot be built.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum FixedAxisError {
    /// The axis direction is zero or not finite.
    #[error(
        "the axis direction ({}, {}, {}) must be a non-zero vector",
        crate::error::short(*.0),
        crate::error::short(*.1),
        crate::error::short(*.2)
    )]
    BadAxis(Real, Real, Real),
    /// The body's mass is not positive.
    #[error("the mass of `{name}` must be positive and finite, not {} kg", crate::error::short(*mass))]
    BadMass {
        /// Body.
        name: String,
        /// Mass given.
        mass: Real,
    },
    /// The moment of inertia about the axis vanishes (or is negative): the body cannot turn.
    #[error(
        "the moment of inertia of `{name}` about the axis is {} kg m²: a body with no moment of inertia about its axis cannot be given an angular acceleration",
        crate::error::short(*moment)
    )]
    ZeroMoment {
        /// Body.
        name: String,
        /// Moment about the axis.
        moment: Real,
    },
    /// A weight hanging from the axle with a non-positive mass or a non-finite radius.
    #[error(
        "a weight of {} kg on a drum of radius {} m: the mass must be positive",
        crate::error::short(*mass),
        crate::error::short(*radius)
    )]
    BadWeight {
        /// Mass.
        mass: Real,
        /// Radius (signed).
        radius: Real,
    },
    /// The mass properties could not be used.
    #[error(transparent)]
    Mass(#[from] MassError),
}

/// A rigid body turning about a fixed axis through a pivot.
///
/// Positions are relative to the pivot in the configuration `θ = 0` (the frame the body was
/// described in, shifted to the pivot); at angle `θ` every point is turned by `θ` about the
/// axis through the pivot (Rodrigues' formula).
#[derive(Debug, Clone, PartialEq)]
pub struct HingedBody {
    name: String,
    mass: Real,
    moment: Real,
    offset: Vec3,
    axis: Vec3,
    inertia_cm_size: Real,
    weights: Real,
}

impl HingedBody {
    /// A body with mass properties `props` (in its own frame) hinged at `pivot` (same frame)
    /// about `axis`.
    pub fn new(
        name: impl Into<String>,
        props: &MassProperties,
        pivot: Vec3,
        axis: Vec3,
    ) -> Result<HingedBody, FixedAxisError> {
        let name = name.into();
        let axis = unit_axis(axis)?;
        if !crate::invertible(props.mass) {
            return Err(FixedAxisError::BadMass {
                name,
                mass: props.mass,
            });
        }
        let moment = props.moment_about_axis(&pivot, &axis)?;
        // the size of the body: its radius of gyration about the centre of mass
        let size = (props.inertia.trace() / (2.0 * props.mass)).max(0.0).sqrt();
        HingedBody::build(
            name,
            props.mass,
            moment,
            props.centre_of_mass - pivot,
            axis,
            size,
        )
    }

    /// A body given by its mass, moment of inertia about the axis through the pivot, and the
    /// position of its centre of mass relative to the pivot.
    pub fn from_moment(
        name: impl Into<String>,
        mass: Real,
        moment: Real,
        centre_of_mass: Vec3,
        axis: Vec3,
    ) -> Result<HingedBody, FixedAxisError> {
        let name = name.into();
        let axis = unit_axis(axis)?;
        if !crate::invertible(mass) {
            return Err(FixedAxisError::BadMass { name, mass });
        }
        HingedBody::build(name, mass, moment, centre_of_mass, axis, 0.0)
    }

    fn build(
        name: String,
        mass: Real,
        moment: Real,
        offset: Vec3,
        axis: Vec3,
        inertia_cm_size: Real,
    ) -> Result<HingedBody, FixedAxisError> {
        // rounding of a parallel-axis sum leaves ~1e-16 of the terms
        let scale = mass * offset.norm_squared() + mass * inertia_cm_size * inertia_cm_size;
        if !(moment > 1e-12 * scale && moment.is_finite()) {
            return Err(FixedAxisError::ZeroMoment { name, moment });
        }
        Ok(HingedBody {
            name,
            mass,
            moment,
            offset,
            axis,
            inertia_cm_size,
            weights: 0.0,
        })
    }

    /// Hangs a weight of mass `mass` from a string wound on a drum of radius `|radius|` on the
    /// axle: it adds `m r²` to the moment of inertia, and its torque (from
    /// [`HangingWeight`]) is `m g r`. A positive `radius` pulls `θ` forwards (the weight
    /// descends as `θ` grows); a negative one backwards.
    pub fn hang(
        &mut self,
        name: impl Into<String>,
        body: usize,
        mass: Real,
        radius: Real,
        g: Real,
    ) -> Result<HangingWeight, FixedAxisError> {
        if !(mass > 0.0 && mass.is_finite() && radius.is_finite()) {
            return Err(FixedAxisError::BadWeight { mass, radius });
        }
        self.weights += mass * radius * radius;
        Ok(HangingWeight::new(name, body, mass, radius, g))
    }

    /// Its name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// Its mass (without hanging weights).
    pub fn mass(&self) -> Real {
        self.mass
    }

    /// Its moment of inertia about the axis (without hanging weights).
    pub fn moment(&self) -> Real {
        self.moment
    }

    /// The moment of inertia the angle's equation of motion uses: the body's plus `m r²` of
    /// every hanging weight.
    pub fn effective_moment(&self) -> Real {
        self.moment + self.weights
    }

    /// The unit axis.
    pub fn axis(&self) -> Vec3 {
        self.axis
    }

    /// The centre of mass relative to the pivot at `θ = 0`.
    pub fn offset(&self) -> Vec3 {
        self.offset
    }

    /// The distance of the centre of mass from the axis.
    pub fn lever(&self) -> Real {
        (self.offset - self.axis * self.axis.dot(&self.offset)).norm()
    }

    /// The centre of mass relative to the pivot at angle `theta`.
    pub fn offset_at(&self, theta: Real) -> Vec3 {
        rotate(&self.offset, &self.axis, theta)
    }

    /// The angular momentum about the axis at angular velocity `omega` (weights included).
    pub fn angular_momentum(&self, omega: Real) -> Real {
        self.effective_moment() * omega
    }

    /// The torque of uniform gravity `g` (a vector, e.g. `(0, -9.81, 0)`) on the body.
    pub fn gravity(&self, name: impl Into<String>, body: usize, g: Vec3) -> GravityTorque {
        GravityTorque::new(name, body, self.mass, g, self.offset, self.axis)
    }

    /// A warning when the pivot is far outside the body: more than ten radii of gyration
    /// from its centre of mass (a body with extent only; a point mass on a massless rod may
    /// hang at any distance).
    pub fn pivot_warning(&self) -> Option<String> {
        let d = self.offset.norm();
        (self.inertia_cm_size > 0.0 && d > 10.0 * self.inertia_cm_size).then(|| {
            format!(
                "the pivot of `{}` is {} m from its centre of mass, {} times the body's radius of gyration ({} m): is the pivot in the body's own coordinates?",
                self.name,
                mechkit_expr::short_fixed(d, 4),
                mechkit_expr::short_fixed(d / self.inertia_cm_size, 0),
                mechkit_expr::short_fixed(self.inertia_cm_size, 4)
            )
        })
    }
}

fn unit_axis(axis: Vec3) -> Result<Vec3, FixedAxisError> {
    let n = axis.norm();
    if n > 0.0 && n.is_finite() {
        Ok(axis / n)
    } else {
        Err(FixedAxisError::BadAxis(axis.x, axis.y, axis.z))
    }
}

/// `v` turned by `theta` about the unit `axis` (Rodrigues' formula).
pub(crate) fn rotate(v: &Vec3, axis: &Vec3, theta: Real) -> Vec3 {
    let (s, c) = theta.sin_cos();
    v * c + axis.cross(v) * s + axis * (axis.dot(v) * (1.0 - c))
}

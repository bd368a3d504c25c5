//! Composite bodies: shapes placed and turned in space, added by superposition, holes as
//! negative mass; each part's inertia carried to the common centre of mass by the
//! parallel-axis theorem.

use nalgebra::{Rotation3, Unit};

use super::{MassError, MassProperties, Shape, Vec3};
use crate::Real;

/// How much matter a part has: a density (per length, area or volume as the shape's
/// [`Extent`](super::Extent) says) or a total mass.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Amount {
    /// kg/m, kg/m² or kg/m³.
    Density(Real),
    /// kg. For a hole, the mass the removed material had.
    Mass(Real),
}

/// One part of a composite body.
#[derive(Debug, Clone, PartialEq)]
pub struct Part {
    /// Name for reports.
    pub name: String,
    /// The shape in its own frame.
    pub shape: Shape,
    /// Density or mass.
    pub amount: Amount,
    /// Turns the shape's frame (applied first, about the shape's local origin).
    pub rotation: Rotation3<Real>,
    /// Where the shape's local origin goes.
    pub position: Vec3,
    /// Removed material: counts with negative mass.
    pub hole: bool,
}

impl Part {
    /// A part at the origin, not turned.
    pub fn new(name: impl Into<String>, shape: Shape, amount: Amount) -> Self {
        Self {
            name: name.into(),
            shape,
            amount,
            rotation: Rotation3::identity(),
            position: Vec3::zeros(),
            hole: false,
        }
    }

    /// Moved so its local origin is at `position`.
    #[must_use]
    pub fn at(mut self, position: Vec3) -> Self {
        self.position = position;
        self
    }

    /// Turned by `rotation` (after any earlier turn).
    #[must_use]
    pub fn rotated(mut self, rotation: Rotation3<Real>) -> Self {
        self.rotation = rotation * self.rotation;
        self
    }

    /// Turned so the shape's local z axis (the axis of a rod, cylinder or cone; the normal of
    /// a flat shape) points along `direction`. A zero direction leaves it unchanged.
    #[must_use]
    pub fn along(self, direction: Vec3) -> Self {
        let Some(to) = Unit::try_new(direction, 0.0) else {
            return self;
        };
        let turn = Rotation3::rotation_between(&Vec3::z(), &to).unwrap_or_else(|| {
            // exactly opposite: half a turn about x
            Rotation3::from_axis_angle(&Vec3::x_axis(), std::f64::consts::PI)
        });
        self.rotated(turn)
    }

    /// Marked as a hole.
    #[must_use]
    pub fn hole(mut self) -> Self {
        self.hole = true;
        self
    }

    /// The part's mass properties in the body frame (negative mass for a hole).
    pub fn properties(&self) -> Result<MassProperties, MassError> {
        let local = match self.amount {
            Amount::Mass(m) if m.is_finite() && m > 0.0 => self.shape.with_mass(m)?,
            Amount::Density(rho) if rho.is_finite() && rho > 0.0 => self.shape.with_density(rho)?,
            Amount::Mass(x) | Amount::Density(x) => {
                let what = if matches!(self.amount, Amount::Mass(_)) {
                    "mass"
                } else {
                    "density"
                };
                return Err(MassError::Invalid(format!(
                    "part `{}`: the {what} is {}; it must be positive (use `hole = true` to remove material)",
                    self.name,
                    crate::error::short(x)
                )));
            }
        };
        let placed = local.rotated(&self.rotation).translated(&self.position);
        Ok(if self.hole { placed.hole() } else { placed })
    }
}

/// A rigid body made of parts.
///
/// ```
/// use mechkit::mass::{Amount, Body, Part, Shape, Vec3};
/// // a cube of side 2 with a cubic hole of side 1 in one corner (density 1)
/// let cube = Part::new("cube", Shape::Cuboid { size: Vec3::new(2.0, 2.0, 2.0) }, Amount::Density(1.0));
/// let hole = Part::new("hole", Shape::Cuboid { size: Vec3::new(1.0, 1.0, 1.0) }, Amount::Density(1.0))
///     .at(Vec3::new(0.5, 0.5, 0.5))
///     .hole();
/// let p = Body::new(vec![cube, hole]).properties().unwrap();
/// assert!((p.mass - 7.0).abs() < 1e-12);
/// assert!((p.centre_of_mass.x + 0.5 / 7.0).abs() < 1e-12); // moved away from the hole
/// ```
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Body {
    parts: Vec<Part>,
}

impl Body {
    /// A body of these parts.
    pub fn new(parts: Vec<Part>) -> Self {
        Self { parts }
    }

    /// The parts.
    pub fn parts(&self) -> &[Part] {
        &self.parts
    }

    /// Each part's mass properties in the body frame; holes that are not inside the solid
    /// parts are refused ([`Body::check_holes`]).
    pub fn part_properties(&self) -> Result<Vec<MassProperties>, MassError> {
        self.check_holes()?;
        self.parts.iter().map(Part::properties).collect()
    }

    /// The whole body: total mass, centre of mass, inertia about the centre of mass. Fails
    /// when the holes cancel the mass.
    pub fn properties(&self) -> Result<MassProperties, MassError> {
        MassProperties::sum(&self.part_properties()?)
    }
}

//! What a body's mass properties report: [`BodySummary`] (the whole and each part, rescaled
//! to a total mass if asked), its centre of mass ([`BodyCentreOfMass`], `mechkit com
//! BODYFILE`) and its inertia ([`InertiaReport`], `mechkit inertia BODYFILE`): the tensor
//! about the centre of mass and about a point (Steiner), the principal moments and axes, the
//! moment and radius of gyration `k = √(I/m)` about an axis.

use super::{Body, MassError, MassProperties, Mat3, Vec3};
use crate::Real;

/// A vector as a report writes it (`-0` as `0`).
fn arr(v: &Vec3) -> [Real; 3] {
    [v.x + 0.0, v.y + 0.0, v.z + 0.0]
}

/// A tensor as rows, divided by `scale` (a unit's size).
fn rows(m: &Mat3, scale: Real) -> [[Real; 3]; 3] {
    std::array::from_fn(|r| std::array::from_fn(|c| m[(r, c)] / scale + 0.0))
}

/// One part of a body as reports list it.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct PartSummary {
    /// Its name.
    pub name: String,
    /// Its shape's name (`sphere`, `rod`, …).
    pub shape: &'static str,
    /// Whether it is removed material.
    pub hole: bool,
    /// Its mass (kg; negative for a hole).
    pub mass: Real,
    /// Its centre of mass in the body frame (m).
    pub centre_of_mass: [Real; 3],
}

/// A body's mass properties, the whole and each part in the body frame.
#[derive(Debug, Clone, PartialEq)]
pub struct BodySummary {
    /// The body's title.
    pub title: String,
    /// The whole body.
    pub whole: MassProperties,
    /// Each part's mass properties (negative mass for a hole) and how it is listed.
    pub parts: Vec<(PartSummary, MassProperties)>,
}

/// The distance of the centre of mass from a point.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct PointDistance {
    /// The point (m).
    pub point: [Real; 3],
    /// Its distance from the centre of mass (m).
    pub distance: Real,
}

/// The centre of mass of a body (`mechkit com BODYFILE`).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct BodyCentreOfMass {
    /// Always `body` (an image reports `image`).
    pub source: &'static str,
    /// The body's title.
    pub title: String,
    /// Its mass (kg).
    pub total_mass: Real,
    /// Its centre of mass (m).
    pub centre_of_mass: [Real; 3],
    /// The centre of mass in `unit`.
    pub centre_of_mass_in_unit: [Real; 3],
    /// The length unit of `centre_of_mass_in_unit` (`m` when none was chosen).
    pub unit: String,
    /// The distance from a point, when one was given.
    pub about: Option<PointDistance>,
    /// The parts.
    pub parts: Vec<PartSummary>,
}

/// The moment of inertia about an axis.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct AxisMoment {
    /// The axis's unit direction.
    pub direction: [Real; 3],
    /// The point it goes through (m).
    pub through: [Real; 3],
    /// The moment `I = uᵀ I_P u`, in the report's unit.
    pub moment: Real,
    /// The radius of gyration `k = √(I/m)` (m).
    pub radius_of_gyration: Real,
}

/// The inertia of a body (`mechkit inertia BODYFILE`): tensors in the report's unit.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct InertiaReport {
    /// The body's title.
    pub title: String,
    /// Its mass (kg).
    pub mass: Real,
    /// Its centre of mass (m).
    pub centre_of_mass: [Real; 3],
    /// The unit of the moments (`kg*m^2` when none was chosen).
    pub unit: String,
    /// The inertia tensor about the centre of mass, rows.
    pub inertia_cm: [[Real; 3]; 3],
    /// The point of `inertia_about` (m).
    pub about: [Real; 3],
    /// The inertia tensor about that point (parallel-axis theorem), rows.
    pub inertia_about: [[Real; 3]; 3],
    /// The principal moments about the centre of mass, ascending.
    pub principal_moments: [Real; 3],
    /// Their axes, one unit vector per moment (a right-handed set).
    pub principal_axes: [[Real; 3]; 3],
    /// The moment about an axis through `about`, when one was given.
    pub axis: Option<AxisMoment>,
    /// The parts.
    pub parts: Vec<PartSummary>,
}

impl Body {
    /// The whole body and its parts, titled `title`, rescaled so that the body's mass is
    /// `total_mass` when it is given (every part in proportion).
    ///
    /// ```
    /// use mechkit::mass::{Amount, Body, Part, Shape, Vec3};
    /// let ball = |x: f64| Part::new("ball", Shape::Sphere { radius: 0.1, inner_radius: 0.0 }, Amount::Mass(1.0))
    ///     .at(Vec3::new(x, 0.0, 0.0));
    /// let s = Body::new(vec![ball(-0.5), ball(0.5)]).summary("dumbbell", Some(4.0)).unwrap();
    /// assert_eq!(s.whole.mass, 4.0);
    /// assert_eq!(s.parts[1].0.mass, 2.0);
    /// assert!(Body::new(vec![ball(0.0)]).summary("x", Some(0.0)).is_err());
    /// ```
    pub fn summary(&self, title: &str, total_mass: Option<Real>) -> Result<BodySummary, MassError> {
        let mut props = self.part_properties()?;
        let mut whole = MassProperties::sum(&props)?;
        if let Some(m) = total_mass {
            if !(m.is_finite() && m > 0.0) {
                return Err(MassError::TotalMass { mass: m });
            }
            let factor = m / whole.mass;
            whole = whole.scaled(factor);
            props = props.iter().map(|p| p.scaled(factor)).collect();
        }
        let parts = self
            .parts()
            .iter()
            .zip(props)
            .map(|(part, p)| {
                let summary = PartSummary {
                    name: part.name.clone(),
                    shape: part.shape.name(),
                    hole: part.hole,
                    mass: p.mass,
                    centre_of_mass: arr(&p.centre_of_mass),
                };
                (summary, p)
            })
            .collect();
        Ok(BodySummary {
            title: title.to_string(),
            whole,
            parts,
        })
    }
}

impl BodySummary {
    /// The parts as reports list them.
    pub fn part_list(&self) -> Vec<PartSummary> {
        self.parts.iter().map(|(s, _)| s.clone()).collect()
    }

    /// The centre of mass, also in a length unit of `size` metres named `unit`, and its
    /// distance from `about` when given.
    pub fn centre_of_mass(&self, unit: &str, size: Real, about: Option<Vec3>) -> BodyCentreOfMass {
        let cm = self.whole.centre_of_mass;
        BodyCentreOfMass {
            source: "body",
            title: self.title.clone(),
            total_mass: self.whole.mass,
            centre_of_mass: arr(&cm),
            centre_of_mass_in_unit: arr(&(cm / size)),
            unit: unit.to_string(),
            about: about.map(|a| PointDistance {
                point: arr(&a),
                distance: (cm - a).norm(),
            }),
            parts: self.part_list(),
        }
    }

    /// The inertia about the centre of mass and about `about`, the principal moments and
    /// axes, and with `axis` the moment and radius of gyration about the axis through
    /// `about` along it; moments in a unit of `size` kg·m² named `unit`. Fails for an axis of
    /// zero length.
    ///
    /// ```
    /// use mechkit::mass::{Amount, Body, Part, Shape, Vec3};
    /// // a thin rod (1 kg, 1 m along x) about its end, across: m L²/3, k = L/√3
    /// let rod = Part::new("rod", Shape::Rod { length: 1.0 }, Amount::Mass(1.0)).along(Vec3::x());
    /// let s = Body::new(vec![rod]).summary("rod", None).unwrap();
    /// let r = s.inertia("kg*m^2", 1.0, Vec3::new(-0.5, 0.0, 0.0), Some(Vec3::z())).unwrap();
    /// let axis = r.axis.unwrap();
    /// assert!((axis.moment - 1.0 / 3.0).abs() < 1e-15);
    /// assert!((axis.radius_of_gyration - 3f64.sqrt().recip()).abs() < 1e-15);
    /// ```
    pub fn inertia(
        &self,
        unit: &str,
        size: Real,
        about: Vec3,
        axis: Option<Vec3>,
    ) -> Result<InertiaReport, MassError> {
        let p = &self.whole;
        let principal = p.principal();
        let axis = match axis {
            Some(d) => Some(AxisMoment {
                moment: p.moment_about_axis(&about, &d)? / size,
                radius_of_gyration: p.radius_of_gyration(&about, &d)?,
                direction: arr(&d.normalize()),
                through: arr(&about),
            }),
            None => None,
        };
        Ok(InertiaReport {
            title: self.title.clone(),
            mass: p.mass,
            centre_of_mass: arr(&p.centre_of_mass),
            unit: unit.to_string(),
            inertia_cm: rows(&p.inertia, size),
            about: arr(&about),
            inertia_about: rows(&p.inertia_about(&about), size),
            principal_moments: principal.moments.map(|m| m / size + 0.0),
            principal_axes: std::array::from_fn(|k| arr(&principal.axes.column(k).into_owned())),
            axis,
            parts: self.part_list(),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mass::{Amount, MassInput, Part, Shape};

    fn dumbbell() -> BodySummary {
        let ball = |x: f64| {
            Part::new(
                "ball",
                Shape::Sphere {
                    radius: 0.1,
                    inner_radius: 0.0,
                },
                Amount::Mass(1.0),
            )
            .at(Vec3::new(x, 0.0, 0.0))
        };
        Body::new(vec![ball(-0.5), ball(0.5)])
            .summary("dumbbell", None)
            .unwrap()
    }

    #[test]
    fn the_centre_of_mass_in_a_unit_and_from_a_point() {
        let r = dumbbell().centre_of_mass("cm", 0.01, Some(Vec3::new(3.0, 4.0, 0.0)));
        assert_eq!(r.total_mass, 2.0);
        assert_eq!(r.centre_of_mass, [0.0; 3]);
        assert_eq!(r.about.unwrap().distance, 5.0);
        assert_eq!(r.parts.len(), 2);
        assert_eq!(r.parts[0].centre_of_mass, [-0.5, 0.0, 0.0]);
    }

    #[test]
    fn inertia_in_a_unit_with_the_library_radius_of_gyration() {
        let s = dumbbell();
        // two spheres (2/5 m r² each) half a metre from the axis: 2 (0.004 + 0.25)
        let r = s
            .inertia(
                "g*cm^2",
                1e-7,
                Vec3::zeros(),
                Some(Vec3::new(0.0, 0.0, 2.0)),
            )
            .unwrap();
        let axis = r.axis.unwrap();
        let i = 2.0 * (0.4 * 0.01 + 0.25);
        assert!((axis.moment - i * 1e7).abs() < 1e-6);
        assert_eq!(axis.direction, [0.0, 0.0, 1.0]);
        assert_eq!(
            axis.radius_of_gyration,
            s.whole
                .radius_of_gyration(&Vec3::zeros(), &Vec3::z())
                .unwrap()
        );
        assert!((r.inertia_cm[2][2] - i * 1e7).abs() < 1e-6);
        // the principal axes are unit vectors, the smallest moment along the bar (x)
        assert!((r.principal_axes[0][0].abs() - 1.0).abs() < 1e-12);
        let e = s
            .inertia("kg*m^2", 1.0, Vec3::zeros(), Some(Vec3::zeros()))
            .unwrap_err();
        assert_eq!(e.input(), Some(MassInput::Axis));
        let e = Body::new(vec![]).summary("x", Some(-1.0)).unwrap_err();
        assert_eq!(e.input(), None, "no parts: the body's own error first");
    }
}

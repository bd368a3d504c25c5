//! A hole removes material the body has: it must lie inside the solid parts. A hole placed
//! outside (or larger than what it is cut from) adds negative mass where there is none, and
//! the moments of inertia come out too small or negative. Two checks, both cheap and shape
//! independent: each hole's outline ([`Shape::outline_points`](super::Shape::outline_points))
//! lies inside the box that bounds the solid parts' outlines, and the second moments of the
//! whole about its centre of mass (`Σ m r rᵀ`, positive semi-definite for any real matter)
//! have no negative principal value.

use super::{Body, MassError, MassProperties, Vec3, principal, second_moment_from_inertia};
use crate::Real;

/// Placed outline points of a part, in the body frame.
fn placed(part: &super::Part) -> Vec<Vec3> {
    part.shape
        .outline_points()
        .into_iter()
        .map(|v| part.rotation * v + part.position)
        .collect()
}

impl Body {
    /// Refuses holes that do not lie inside the solid parts ([`MassError::Hole`], naming the
    /// first such hole by its index among the parts).
    ///
    /// # Errors
    /// [`MassError::Hole`].
    pub fn check_holes(&self) -> Result<(), MassError> {
        let parts = self.parts();
        if !parts.iter().any(|p| p.hole) {
            return Ok(());
        }
        let (mut lo, mut hi) = (
            Vec3::repeat(Real::INFINITY),
            Vec3::repeat(Real::NEG_INFINITY),
        );
        for p in parts.iter().filter(|p| !p.hole) {
            for v in placed(p) {
                lo = lo.inf(&v);
                hi = hi.sup(&v);
            }
        }
        let size = (hi - lo).amax();
        let tol = 1e-9 * if size.is_finite() { size } else { 1.0 };
        for (index, p) in parts.iter().enumerate().filter(|(_, p)| p.hole) {
            let outside = placed(p)
                .into_iter()
                .find(|v| (0..3).any(|k| !(v[k] >= lo[k] - tol && v[k] <= hi[k] + tol)));
            if let Some(v) = outside {
                return Err(MassError::Hole {
                    index,
                    name: p.name.clone(),
                    reason: format!(
                        "its point ({}, {}, {}) m is outside the solid parts, which span ({}, {}, {}) m to ({}, {}, {}) m",
                        short(v.x),
                        short(v.y),
                        short(v.z),
                        short(lo.x),
                        short(lo.y),
                        short(lo.z),
                        short(hi.x),
                        short(hi.y),
                        short(hi.z)
                    ),
                });
            }
        }
        // more removed than there is (holes overlapping each other, or larger than the part
        // they are cut from): the second moments of what is left are not those of any matter
        let props = parts
            .iter()
            .map(super::Part::properties)
            .collect::<Result<Vec<_>, _>>()?;
        let whole = MassProperties::sum(&props)?;
        let second = second_moment_from_inertia(&whole.inertia);
        let smallest = principal(&second).moments[0];
        let scale = second.trace().abs()
            + props
                .iter()
                .map(|p| second_moment_from_inertia(&p.inertia).trace().abs())
                .sum::<Real>();
        if smallest < -1e-9 * scale {
            let (index, hole) = parts
                .iter()
                .enumerate()
                .find(|(_, p)| p.hole)
                .map(|(i, p)| (i, p.name.clone()))
                .unwrap_or_default();
            return Err(MassError::Hole {
                index,
                name: hole,
                reason: format!(
                    "the holes remove more than the parts hold: what is left has a negative second moment ({} kg m²) about its centre of mass",
                    short(smallest)
                ),
            });
        }
        Ok(())
    }
}

fn short(x: Real) -> String {
    crate::error::short(x + 0.0)
}

#[cfg(test)]
mod tests {
    use super::super::{Amount, Part, Shape};
    use super::*;

    fn cube_with_hole_at(at: Real) -> Body {
        let cube = Part::new(
            "cube",
            Shape::Cuboid {
                size: Vec3::repeat(0.1),
            },
            Amount::Density(7850.0),
        );
        let hole = Part::new(
            "hole",
            Shape::Cuboid {
                size: Vec3::repeat(0.05),
            },
            Amount::Density(7850.0),
        )
        .at(Vec3::repeat(at))
        .hole();
        Body::new(vec![cube, hole])
    }

    #[test]
    fn a_hole_outside_its_body_is_refused_where_it_would_give_negative_moments() {
        // in the corner: fine
        let p = cube_with_hole_at(0.025).properties().unwrap();
        assert!(p.principal().moments.iter().all(|&m| m > 0.0));
        // 20 cm off: the moments would be -0.12 kg m²
        assert!(matches!(
            cube_with_hole_at(0.2).properties(),
            Err(MassError::Hole { index: 1, .. })
        ));
        // partly outside
        assert!(cube_with_hole_at(0.04).check_holes().is_err());
    }

    #[test]
    fn holes_removing_more_than_there_is_are_refused() {
        // the top slab of a cube removed twice: 0.4 kg left, its centre of mass below the cube
        let cube = Part::new(
            "cube",
            Shape::Cuboid {
                size: Vec3::repeat(1.0),
            },
            Amount::Density(1.0),
        );
        let slab = Part::new(
            "slab",
            Shape::Cuboid {
                size: Vec3::new(1.0, 1.0, 0.3),
            },
            Amount::Density(1.0),
        )
        .at(Vec3::new(0.0, 0.0, 0.35))
        .hole();
        let body = Body::new(vec![cube, slab.clone(), slab]);
        assert!(matches!(body.check_holes(), Err(MassError::Hole { .. })));
    }
}

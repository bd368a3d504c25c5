//! The work-energy theorem as a tool: `½mv² = ½mv0² + ∫_{x0}^x F dx'`, i.e. the speed
//! `v(x) = sqrt(2(E - U(x))/m)` of a body of mass `m` released at `x0` with speed `v0`, and the
//! turning points where `v²` reaches zero.

use super::diagram::{Diagram, Region};
use super::potential::Potential;
use crate::Real;

/// What ends the motion on one side of the start: a turning point, the end of the range
/// analysed (the body leaves it), or a singular point of the potential.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(tag = "kind", rename_all = "snake_case"))]
#[non_exhaustive]
pub enum Bound {
    /// `U = E` here: the body stops and turns back.
    TurningPoint {
        /// Where.
        x: Real,
    },
    /// The body reaches the end of the range with speed left: it leaves the range.
    RangeEnd {
        /// The end of the range.
        x: Real,
    },
    /// The body reaches a point where `U` or `F` is infinite or undefined.
    SingularPoint {
        /// Where.
        x: Real,
    },
}

impl Bound {
    /// Where the bound is.
    pub fn x(self) -> Real {
        match self {
            Bound::TurningPoint { x } | Bound::RangeEnd { x } | Bound::SingularPoint { x } => x,
        }
    }
}

/// Where a body can go, and how fast, with the energy it starts with.
///
/// Serialized as `{mass, x0, v0, energy, left_turn, right_turn, left, right}`, each bound as
/// `{kind: "turning_point" | "range_end" | "singular_point", x}`.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Motion {
    /// Mass.
    pub mass: Real,
    /// Start position.
    pub x0: Real,
    /// Start speed.
    pub v0: Real,
    /// `E = ½mv0² + U(x0)`.
    pub energy: Real,
    /// The diagram with this energy (its `energy` field is set).
    #[cfg_attr(feature = "serde", serde(skip))]
    pub diagram: Diagram,
    /// `v(x)` at the diagram's grid points, NaN where forbidden.
    #[cfg_attr(feature = "serde", serde(skip))]
    pub speed: Vec<Real>,
    /// The turning point below `x0`, if the motion is bounded on that side inside the range.
    pub left_turn: Option<Real>,
    /// The turning point above `x0`.
    pub right_turn: Option<Real>,
    /// What bounds the motion below `x0`.
    pub left: Bound,
    /// What bounds the motion above `x0`.
    pub right: Bound,
}

impl Motion {
    /// Whether the body first moves towards larger `x`: the direction of `v0`, or at rest the
    /// direction of the force at `x0` (`false` when there is none: it stays).
    pub fn moves_right_first(&self, p: &Potential) -> bool {
        match self.v0.partial_cmp(&0.0) {
            Some(std::cmp::Ordering::Greater) => true,
            Some(std::cmp::Ordering::Less) => false,
            _ => p.force(self.x0) > 0.0,
        }
    }

    /// `v(x) = sqrt(2(E - U(x))/m)`, NaN where `U(x) > E`.
    pub fn speed_at(&self, p: &Potential, x: Real) -> Real {
        let u = p.potential_between(self.x0, x, p.potential(self.x0));
        let k = self.energy - u;
        if k < 0.0 {
            Real::NAN
        } else {
            (2.0 * k / self.mass).sqrt()
        }
    }
}

impl Potential {
    /// The motion of a body of mass `mass` starting at `x0` with speed `v0`, on `[from, to]`.
    ///
    /// ```
    /// use mechkit::energy::Potential;
    /// // an ion approaching a repulsive centre, U = C/x, from x = 1 at 2.5
    /// let p = Potential::from_potential("1/x", "x", &[]).unwrap();
    /// let m = p.motion(1.0, 1.0, 2.5, 0.01, 1e6, 4000);
    /// assert!((m.left_turn.unwrap() - 1.0 / (2.5f64.powi(2) / 2.0 + 1.0)).abs() < 1e-12);
    /// assert!(m.right_turn.is_none()); // it escapes
    /// ```
    pub fn motion(
        &self,
        mass: Real,
        x0: Real,
        v0: Real,
        from: Real,
        to: Real,
        samples: usize,
    ) -> Motion {
        let energy = 0.5 * mass * v0 * v0 + self.potential(x0);
        let diagram = self.diagram(from, to, Some(energy), samples);
        let speed = diagram
            .potential
            .iter()
            .map(|&u| {
                let k = energy - u;
                if k >= 0.0 {
                    (2.0 * k / mass).sqrt()
                } else {
                    Real::NAN
                }
            })
            .collect();
        let (lo, hi) = (from.min(to), from.max(to));
        let (mut left, mut right) = (Bound::RangeEnd { x: lo }, Bound::RangeEnd { x: hi });
        if let Some(cut) = &diagram.energy {
            // the allowed region the body is in; at a boundary between two (released at rest
            // on a turning point), the one it moves into: the way v0 points, at rest the way
            // the force pushes
            let right_first = match v0.partial_cmp(&0.0) {
                Some(std::cmp::Ordering::Greater) => true,
                Some(std::cmp::Ordering::Less) => false,
                _ => self.force(x0) > 0.0,
            };
            // a turning point found by root finding may be an ulp or so off x0
            let tol = 1e-9 * (hi - lo);
            let contains = |r: &&Region| (r.from - tol..=r.to + tol).contains(&x0);
            let ahead = |r: &&Region| if right_first { r.to > x0 } else { r.from < x0 };
            let here: Option<&Region> = cut
                .regions
                .iter()
                .filter(contains)
                .filter(|r| r.allowed)
                .find(ahead)
                .or_else(|| cut.regions.iter().filter(contains).find(|r| r.allowed))
                .or_else(|| cut.regions.iter().find(contains));
            if let Some(r) = here {
                let bound = |x: Real| {
                    if cut.turning_points.contains(&x) {
                        Bound::TurningPoint { x }
                    } else if diagram.singularities.contains(&x) {
                        Bound::SingularPoint { x }
                    } else {
                        Bound::RangeEnd { x }
                    }
                };
                (left, right) = (bound(r.from), bound(r.to));
            }
        }
        let turn = |b: Bound| matches!(b, Bound::TurningPoint { .. }).then(|| b.x());
        let (left_turn, right_turn) = (turn(left), turn(right));
        Motion {
            mass,
            x0,
            v0,
            energy,
            diagram,
            speed,
            left_turn,
            right_turn,
            left,
            right,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn released_at_rest_it_goes_the_way_the_force_pushes() {
        // F = 1 (U = -x) from rest at -0.5: the start is a turning point, and it leaves at 1
        let p = Potential::from_potential("-x", "x", &[]).unwrap();
        let m = p.motion(1.0, -0.5, 0.0, -1.0, 1.0, 4000);
        assert!(matches!(m.left, Bound::TurningPoint { x } if (x + 0.5).abs() < 1e-12));
        assert_eq!(m.right, Bound::RangeEnd { x: 1.0 });
        assert!(m.moves_right_first(&p));
        // F = -1 (U = x) from rest at 0.5: it leaves at -1
        let p = Potential::from_potential("x", "x", &[]).unwrap();
        let m = p.motion(1.0, 0.5, 0.0, -1.0, 1.0, 4000);
        assert_eq!(m.left, Bound::RangeEnd { x: -1.0 });
        assert!(matches!(m.right, Bound::TurningPoint { x } if (x - 0.5).abs() < 1e-12));
        // moving against the force: it turns, then leaves the other way
        let m = p.motion(1.0, 0.0, 1.0, -1.0, 1.0, 4000);
        assert!(matches!(m.right, Bound::TurningPoint { x } if (x - 0.5).abs() < 1e-9));
        assert_eq!(m.left, Bound::RangeEnd { x: -1.0 });
    }
}

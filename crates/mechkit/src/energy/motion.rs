//! The work-energy theorem as a tool: `½mv² = ½mv0² + ∫_{x0}^x F dx'`, i.e. the speed
//! `v(x) = sqrt(2(E - U(x))/m)` of a body of mass `m` released at `x0` with speed `v0`, and the
//! turning points where `v²` reaches zero.

use super::diagram::{Diagram, Region};
use super::potential::Potential;
use crate::Real;

/// Where a body can go, and how fast, with the energy it starts with.
#[derive(Debug, Clone, PartialEq)]
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
    pub diagram: Diagram,
    /// `v(x)` at the diagram's grid points, NaN where forbidden.
    pub speed: Vec<Real>,
    /// The turning point below `x0`, if the motion is bounded on that side inside the range.
    pub left_turn: Option<Real>,
    /// The turning point above `x0`.
    pub right_turn: Option<Real>,
}

impl Motion {
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
        let (mut left_turn, mut right_turn) = (None, None);
        if let Some(cut) = &diagram.energy {
            let here: Option<&Region> = cut.regions.iter().find(|r| (r.from..=r.to).contains(&x0));
            if let Some(r) = here {
                let is_turn = |x: Real| cut.turning_points.contains(&x);
                left_turn = is_turn(r.from).then_some(r.from);
                right_turn = is_turn(r.to).then_some(r.to);
            }
        }
        Motion {
            mass,
            x0,
            v0,
            energy,
            diagram,
            speed,
            left_turn,
            right_turn,
        }
    }
}

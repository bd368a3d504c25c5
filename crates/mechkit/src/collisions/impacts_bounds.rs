//! How the contact gaps are searched inside a step: their enclosures over a piece of a step
//! (for the event proof, [`crate::ode::StepProof`]), the gap of two spheres or of a sphere and
//! a wall from the enclosures of the positions, with the rounding-level band that
//! [`snapped`](super::snapped) sets to zero; and the evenly spaced samples a gap asks for when
//! it cannot be proven.

use super::{Impacts, ROUNDING};
use crate::Real;
use crate::interval::{Interval, Jet};
use crate::particles::StateJets;

/// The enclosure of [`snapped`] over a piece of a step, from the enclosure of the raw `gap`
/// and an upper bound of `scale`: the raw gap where it is clear of the snapping band, else
/// its hull with zero. The slope stays the raw gap's: snapping keeps a monotone gap monotone
/// (non-strictly, with a flat zero), which is what the event proof asks of a slope, a sign
/// change of the snapped gap at most once over a piece where the raw gap is monotone.
fn snapped_jet(gap: Jet, scale: Real) -> Jet {
    let band = (ROUNDING * scale).next_up();
    if gap.v.lo() > band || gap.v.hi() < -band {
        gap
    } else {
        Jet::new(gap.v.hull(Interval::point(0.0)), gap.d)
    }
}

/// The largest magnitude in an enclosure.
fn magnitude(x: Interval) -> Real {
    x.lo().abs().max(x.hi().abs())
}

/// Sample spacing inside a step: a relative displacement of at most this fraction of the radii
/// between two samples. Two spheres passing through each other overlap for at least the time
/// the chord takes; with this spacing only grazes shallower than 0.2 % of the radii (impact
/// parameter above 0.998 of the sum of the radii) could fit between two samples.
pub(super) const SPACING: Real = 1.0 / 16.0;

/// Interior samples a step of length `h` needs for a gap that closes at speed up to `u`.
pub(super) fn samples_for(u: Real, h: Real, reach: Real) -> usize {
    if reach > 0.0 && u.is_finite() {
        ((u * h / (SPACING * reach)).ceil() as usize).saturating_sub(1)
    } else {
        0
    }
}

/// Interior samples a step of length `h` needs for a signed gap (a wall's, or two bodies' on
/// a line), whose rate is `u0` at the step's start and `u1` at its end. A signed gap shows a
/// body that ends the step past the plane (or past the other body) at the step's end, however
/// fast it went. Only a body that goes in and comes out again inside one step could be missed,
/// and for that its normal velocity must turn from approach (`u0 < 0`) to retreat (`u1 > 0`);
/// then the samples follow the spacing rule. (A normal velocity that turns twice inside one
/// step, more than half an oscillation per step, is not looked for.) Without this, a body
/// sliding along a wall would ask for samples in proportion to its step, and the steps of a
/// smooth motion grow without bound.
pub(super) fn signed_gap_samples(u0: Real, u1: Real, h: Real, reach: Real) -> usize {
    if u0 < 0.0 && u1 > 0.0 {
        samples_for(u0.abs().max(u1), h, reach)
    } else {
        0
    }
}

impl Impacts {
    /// The enclosure of the (snapped) gap of bodies `a` and `b` over a piece of a step.
    pub(super) fn pair_gap_jet(&self, j: &StateJets<'_>, a: usize, b: usize, reach: Real) -> Jet {
        let d = self.dim;
        let (xa, xb) = (j.position(a, 0), j.position(b, 0));
        let scale = reach + magnitude(xa.v) + magnitude(xb.v);
        let raw = if d == 1 {
            let apart = xb - xa;
            match self.side(a, b) {
                Some(side) => Jet::constant(side) * apart - Jet::constant(reach),
                None => apart.abs() - Jet::constant(reach),
            }
        } else {
            let d2 = (0..d)
                .map(|k| (j.position(b, k) - j.position(a, k)).sqr())
                .reduce(|x, y| x + y)
                .expect("at least one dimension");
            d2.sqrt() - Jet::constant(reach)
        };
        snapped_jet(raw, scale)
    }

    /// The enclosure of the (snapped) gap of body `i` to wall `w` over a piece of a step.
    pub(super) fn wall_gap_jet(&self, j: &StateJets<'_>, i: usize, w: usize, r: Real) -> Jet {
        let wall = &self.walls[w];
        let mut distance = Jet::constant(0.0);
        let mut scale = r + wall.point.iter().map(|x| x.abs()).sum::<Real>();
        for (k, (p, n)) in wall.point.iter().zip(&wall.normal).enumerate() {
            let x = j.position(i, k);
            scale += magnitude(x.v);
            distance = distance + (x - Jet::constant(*p)) * Jet::constant(*n);
        }
        snapped_jet(distance - Jet::constant(r), scale.next_up())
    }
}

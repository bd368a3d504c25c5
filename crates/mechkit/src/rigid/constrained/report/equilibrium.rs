//! The start at an equilibrium of the curve (a horizontal tangent): its stability, whether
//! the body stayed there, and, at an unstable top of a curve it rests on, where the slightest
//! push would make it leave ([`Equilibrium`], [`LeavingPoint`]).
//!
//! Leaving from near the top. With the energy per unit mass `E = ½v₀² + g y₀` the speed
//! along the curve is `v² = 2(E − g y)` and the normal force per unit mass is
//! `(r''·n) q̇² + g n_y`; on a circle of radius R started at the top this vanishes at
//! cos φ = (2 + v₀²/(gR))/3, cos φ = 2/3 from rest (φ ≈ 48.19°).

use super::wrapped_degrees;
use crate::Real;
use crate::rigid::constrained::{BeadOnCurve, BeadRun, Side, Start};

/// Where the body would leave the curve.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct LeavingPoint {
    /// The curve coordinate (x, or φ on a circle).
    pub coordinate: Real,
    /// Position (m).
    pub position: [Real; 2],
    /// On a circle: the angle from the top (degrees).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub angle_from_top_deg: Option<Real>,
    /// On a circle: cos φ.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub cos_angle: Option<Real>,
}

/// The start is an equilibrium of the curve: its tangent is horizontal.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Equilibrium {
    /// `unstable` (a top) or `stable` (a bottom).
    pub stability: &'static str,
    /// Whether it starts at rest there (then it stays: nothing pushes it).
    pub at_rest: bool,
    /// Whether it stayed near the start for the whole run (within 1% of the curve's length
    /// scale).
    pub stayed: bool,
    /// At an unstable top of a curve it rests on (not threaded): where it leaves the curve
    /// after the slightest push in the direction of its start speed (or of increasing
    /// coordinate from rest), with the energy of the start; `None` where it never leaves.
    pub leaves_at: Option<LeavingPoint>,
}

impl BeadOnCurve {
    /// The equilibrium at the start, if the curve's tangent is horizontal there.
    pub(super) fn equilibrium(&self, start: Start, run: &BeadRun) -> Option<Equilibrium> {
        let geo = self.curve.geometry(start.coordinate);
        let level = geo.d1[1].abs() <= 1e-9 * geo.speed_factor();
        if !level || geo.d2[1] == 0.0 {
            return None;
        }
        let unstable = geo.d2[1] < 0.0;
        let p0 = geo.r;
        let reach = 0.01 * self.curve.scale();
        let stayed = run
            .samples
            .iter()
            .all(|s| (s.position[0] - p0[0]).hypot(s.position[1] - p0[1]) <= reach);
        let leaves_at = if unstable && self.side == Side::Outer {
            let direction = if start.speed < 0.0 { -1.0 } else { 1.0 };
            self.leaving_point(start, direction)
        } else {
            None
        };
        Some(Equilibrium {
            stability: if unstable { "unstable" } else { "stable" },
            at_rest: start.speed == 0.0,
            stayed,
            leaves_at,
        })
    }

    /// Where the body, sliding from `start` in `direction` (±1) with the start's energy, first
    /// reaches N = 0: a scan in steps of 1/1000 of the length scale (up to 100 scales), then
    /// Brent's method.
    fn leaving_point(&self, start: Start, direction: Real) -> Option<LeavingPoint> {
        let geo0 = self.curve.geometry(start.coordinate);
        let energy = 0.5 * start.speed * start.speed + self.g * geo0.r[1];
        let normal = |q: Real| {
            let geo = self.curve.geometry(q);
            let v2 = 2.0 * (energy - self.g * geo.r[1]);
            let s = geo.speed_factor();
            let qd = v2.max(0.0).sqrt() / s;
            (v2 >= 0.0).then(|| self.side.sign() * geo.normal_force(qd, self.g))
        };
        // steps of about a thousandth of the length scale along the curve
        let h = 1e-3 * self.curve.scale() / geo0.speed_factor();
        let mut a = start.coordinate;
        for _ in 0..100_000 {
            let b = a + direction * h;
            let n = normal(b).filter(|n| n.is_finite())?;
            if n < 0.0 {
                let q = crate::roots::brent(|q| normal(q).unwrap_or(Real::NAN), a, b, 1e-15)?;
                let position = self.curve.point(q);
                let circle = self.curve.radius().is_some();
                return Some(LeavingPoint {
                    coordinate: q,
                    position,
                    angle_from_top_deg: circle.then(|| wrapped_degrees(q)),
                    cos_angle: circle.then(|| q.cos()),
                });
            }
            a = b;
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rigid::constrained::{BeadReport, Curve};

    /// 1 kg on `curve` on `side` in g = 9.81 m/s², from `coordinate` at `speed`, for `t_max`.
    fn report(
        curve: Curve,
        side: Side,
        (coordinate, speed): (Real, Real),
        t_max: Real,
    ) -> BeadReport {
        BeadOnCurve::new(curve, side, 1.0, 9.81)
            .unwrap()
            .report(Start { coordinate, speed }, t_max, 1e-10)
            .unwrap()
    }

    /// From the top of a circle of radius 2 m, for 1 s.
    fn top(side: Side, speed: Real) -> BeadReport {
        report(Curve::circle(2.0).unwrap(), side, (0.0, speed), 1.0)
    }

    /// At rest (or nearly) on top of a cylinder: no departure within the run, an unstable
    /// equilibrium, and the point it would leave at is the textbook's cos φ = 2/3 + v₀²/3gR,
    /// which a longer run with a small push reaches.
    #[test]
    fn an_unstable_top_says_where_a_push_would_take_it_off() {
        let rest = top(Side::Outer, 0.0);
        assert!(rest.departure.is_none());
        let eq = rest.equilibrium.unwrap();
        assert_eq!(
            (eq.stability, eq.at_rest, eq.stayed),
            ("unstable", true, true)
        );
        let at = eq.leaves_at.unwrap();
        assert!((at.cos_angle.unwrap() - 2.0 / 3.0).abs() < 1e-12);
        assert!((at.angle_from_top_deg.unwrap() - (2.0f64 / 3.0).acos().to_degrees()).abs() < 1e-9);
        let v0: Real = 1e-6;
        let nudged = top(Side::Outer, v0).equilibrium.unwrap();
        assert!(!nudged.at_rest && nudged.stayed);
        let want = 2.0 / 3.0 + v0 * v0 / (3.0 * 9.81 * 2.0);
        assert!((nudged.leaves_at.unwrap().cos_angle.unwrap() - want).abs() < 1e-12);
        // the same push, followed long enough, leaves there
        let long = report(Curve::circle(2.0).unwrap(), Side::Outer, (0.0, 1e-3), 10.0);
        let d = long.departure.expect("it leaves");
        let want = 2.0 / 3.0 + 1e-6 / (3.0 * 9.81 * 2.0);
        assert!((d.cos_angle.unwrap() - want).abs() < 1e-8);
        // threaded, it never leaves; at the bottom it is stable
        let bead = top(Side::Bead, 0.0).equilibrium.unwrap();
        assert!(bead.leaves_at.is_none());
        let bottom = report(
            Curve::circle(1.0).unwrap(),
            Side::Inner,
            (std::f64::consts::PI, 0.0),
            1.0,
        );
        assert_eq!(bottom.equilibrium.unwrap().stability, "stable");
    }

    #[test]
    fn a_hill_top_is_left_where_the_normal_force_vanishes() {
        // the upper half of the unit circle as a graph: left from rest where cos φ = 2/3,
        // x = √5/3, as on the circle
        let hill = Curve::graph("sqrt(1 - x^2)", &[]).unwrap();
        let r = report(hill, Side::Outer, (0.0, 0.0), 1.0);
        let at = r.equilibrium.unwrap().leaves_at.unwrap();
        assert!((at.coordinate - 5f64.sqrt() / 3.0).abs() < 1e-9, "{at:?}");
        assert!(at.cos_angle.is_none());
        assert_eq!(r.table().columns().len(), 7);
        assert_eq!(r.plot().file_stem, "path");
        // y = −x²/2 bends less than the free fall from its top: it is never left
        let parabola = Curve::graph("-x^2/2", &[]).unwrap();
        let r = report(parabola, Side::Outer, (0.0, 0.0), 1.0);
        assert!(r.equilibrium.unwrap().leaves_at.is_none());
    }
}

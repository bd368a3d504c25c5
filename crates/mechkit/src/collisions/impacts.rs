//! Event-driven collisions in a simulation: spheres (disks in 2-D, points with a size in 1-D)
//! against each other and against fixed planes (walls). Every pair and every (body, wall)
//! has an event on its gap, `|r_b - r_a| - (R_a + R_b)` or `(r - p)·n - R`, fired when the
//! gap falls through zero (on a line, with the start given, the pair's gap is signed by the
//! bodies' order: `±(x_b - x_a) - (R_a + R_b)`); the run's event machinery locates the instant
//! of impact on the step's interpolant, and the event's state change resolves the contact with
//! [`Collision`].
//!
//! **Simultaneous contacts.** At an impact every pair that touches (gap within `1e-9` of the
//! radii) and still approaches is resolved, pair by pair in a fixed order (body pairs by index,
//! then walls), and the sweep repeats until no touching pair approaches. A 3-ball Newton's
//! cradle with `e = 1` therefore hands the velocity down the line: the first sweep stops ball 1
//! and starts ball 2, which meets ball 3 in the same sweep, and the second sweep finds nothing
//! left to resolve. A pair approaching by less than `1e-12` of the bodies' speeds has settled
//! (a perfectly inelastic chain reaches its common velocity only to rounding). The sweeps stop
//! after 10,000 rounds (a jammed pile), leaving the last velocities.

use std::sync::Arc;

use super::resolve::{Collision, Resolution, Restitution};
use crate::Real;
use crate::simulate::{Condition, Direction, Event};

/// Relative gap within which two surfaces count as touching.
const TOUCH: Real = 1e-9;
/// Gap, relative to the size of the positions, within which a point (radius 0) touches a wall
/// or another point.
const POINT_TOUCH: Real = 1e-12;
/// Gaps within this many rounding units of the positions are zero: two balls resting in
/// contact must not flicker across zero on the step's interpolant (a cubic through equal
/// values can miss them by an ulp), which would fire their event at every step.
const ROUNDING: Real = 8.0 * Real::EPSILON;

/// A gap, with rounding-level values snapped to zero (`scale`: the size of the numbers it was
/// computed from).
fn snapped(gap: Real, scale: Real) -> Real {
    if gap.abs() <= ROUNDING * scale {
        0.0
    } else {
        gap
    }
}

/// Most resolution sweeps at one impact.
const MAX_SWEEPS: usize = 10_000;

/// Approach speeds at or below this fraction of the bodies' speeds are rounding, not approach:
/// a perfectly inelastic chain converges to a common velocity only to within a few ulps, and
/// resolving the ulps again and again would run every impact to [`MAX_SWEEPS`].
const SETTLED: Real = 1e-12;

/// Whether bodies with velocities `va` and `vb` approach along `normal` (from `a` to `b`) by
/// more than rounding.
fn approaching(va: &[Real], vb: &[Real], normal: &[Real]) -> bool {
    let norm = normal.iter().map(|x| x * x).sum::<Real>().sqrt();
    let approach: Real = va
        .iter()
        .zip(vb)
        .zip(normal)
        .map(|((a, b), n)| (a - b) * n)
        .sum::<Real>()
        / norm;
    let scale = va.iter().chain(vb).fold(0.0, |m: Real, x| m.max(x.abs()));
    approach > SETTLED * scale
}

/// A fixed plane that bodies bounce off.
#[derive(Debug, Clone, PartialEq)]
pub struct Wall {
    /// Its name (in event names: `ball hits floor`).
    pub name: String,
    /// A point of the plane.
    pub point: Vec<Real>,
    /// The unit normal, pointing to the side where the bodies are.
    pub normal: Vec<Real>,
    /// Coefficient of restitution of impacts on it.
    pub restitution: Restitution,
    /// Coulomb friction coefficient along it.
    pub friction: Real,
}

impl Wall {
    /// A wall through `point` with normal `normal` (normalised here; `None` if it has zero
    /// length or the lengths differ).
    pub fn new(
        name: impl Into<String>,
        point: Vec<Real>,
        normal: &[Real],
        restitution: Restitution,
        friction: Real,
    ) -> Option<Self> {
        let len = normal.iter().map(|x| x * x).sum::<Real>().sqrt();
        (len > 0.0 && len.is_finite() && point.len() == normal.len()).then(|| Self {
            name: name.into(),
            point,
            normal: normal.iter().map(|x| x / len).collect(),
            restitution,
            friction,
        })
    }

    /// Signed distance of a point from the plane (positive on the bodies' side).
    pub fn distance(&self, r: &[Real]) -> Real {
        r.iter()
            .zip(&self.point)
            .zip(&self.normal)
            .map(|((x, p), n)| (x - p) * n)
            .sum()
    }
}

/// Restitution and friction of one pair of bodies.
#[derive(Debug, Clone, Copy, PartialEq)]
struct PairRule {
    a: usize,
    b: usize,
    restitution: Restitution,
    friction: Real,
}

/// Two things overlapping at the start.
#[derive(Debug, Clone, PartialEq)]
pub struct Overlap {
    /// The first body.
    pub body: usize,
    /// The other body, or `None` for a wall.
    pub other: Option<usize>,
    /// The wall's index, for a wall.
    pub wall: Option<usize>,
    /// How deep they overlap (m).
    pub depth: Real,
}

/// The spheres and walls of a system, and how they collide.
#[derive(Debug, Clone, PartialEq)]
pub struct Impacts {
    dim: usize,
    radius: Vec<Option<Real>>,
    mass: Vec<Real>,
    names: Vec<String>,
    restitution: Restitution,
    friction: Real,
    rules: Vec<PairRule>,
    walls: Vec<Wall>,
    /// In 1-D, the positions at the start, which fix the order of the bodies on the line.
    start: Option<Vec<Real>>,
}

impl Impacts {
    /// Bodies with their names, masses and radii (`None`: the body takes no part in
    /// collisions), in `dim` dimensions; elastic and frictionless unless set otherwise.
    pub fn new(dim: usize, names: Vec<String>, mass: Vec<Real>, radius: Vec<Option<Real>>) -> Self {
        assert!(
            names.len() == mass.len() && mass.len() == radius.len(),
            "one name, mass and radius per body"
        );
        Self {
            dim,
            radius,
            mass,
            names,
            restitution: Restitution::ELASTIC,
            friction: 0.0,
            rules: Vec::new(),
            walls: Vec::new(),
            start: None,
        }
    }

    /// The positions at the start of the run. In 1-D bodies on a line cannot pass each other,
    /// so they fix each pair's order: the gap between two bodies is then signed, like a
    /// wall's, and a step that carries one through the other shows it at the step's end,
    /// whatever their radii (without them the gap is `|x_b - x_a| - (R_a + R_b)`, and a pass
    /// between two samples of a step could be missed). In 2-D and 3-D they change nothing.
    #[must_use]
    pub fn with_start(mut self, q: &[Real]) -> Self {
        if self.dim == 1 {
            self.start = Some(q.to_vec());
        }
        self
    }

    /// In 1-D with the start known, the side `b` is on of `a`: +1 or -1 (+1 when they start
    /// at the same place).
    fn side(&self, a: usize, b: usize) -> Option<Real> {
        let q = self.start.as_ref()?;
        Some(if q[b] < q[a] { -1.0 } else { 1.0 })
    }

    /// The default restitution and friction of body pairs (walls carry their own).
    #[must_use]
    pub fn with_default(mut self, restitution: Restitution, friction: Real) -> Self {
        self.restitution = restitution;
        self.friction = friction;
        self
    }

    /// Restitution and friction of the pair `a`, `b`.
    #[must_use]
    pub fn with_pair(
        mut self,
        a: usize,
        b: usize,
        restitution: Restitution,
        friction: Real,
    ) -> Self {
        let (a, b) = (a.min(b), a.max(b));
        self.rules.retain(|r| (r.a, r.b) != (a, b));
        self.rules.push(PairRule {
            a,
            b,
            restitution,
            friction,
        });
        self
    }

    /// Adds a wall.
    #[must_use]
    pub fn with_wall(mut self, wall: Wall) -> Self {
        assert_eq!(
            wall.point.len(),
            self.dim,
            "a wall of the system's dimension"
        );
        self.walls.push(wall);
        self
    }

    /// The walls.
    pub fn walls(&self) -> &[Wall] {
        &self.walls
    }

    fn rule(&self, a: usize, b: usize) -> (Restitution, Real) {
        self.rules
            .iter()
            .find(|r| (r.a, r.b) == (a.min(b), a.max(b)))
            .map_or((self.restitution, self.friction), |r| {
                (r.restitution, r.friction)
            })
    }

    fn pos<'q>(&self, q: &'q [Real], i: usize) -> &'q [Real] {
        &q[i * self.dim..(i + 1) * self.dim]
    }

    fn pairs(&self) -> impl Iterator<Item = (usize, usize, Real)> + '_ {
        let n = self.radius.len();
        (0..n).flat_map(move |a| {
            (a + 1..n).filter_map(move |b| Some((a, b, self.radius[a]? + self.radius[b]?)))
        })
    }

    fn wall_contacts(&self) -> impl Iterator<Item = (usize, usize, Real)> + '_ {
        (0..self.radius.len()).flat_map(move |i| {
            (0..self.walls.len()).filter_map(move |w| Some((i, w, self.radius[i]?)))
        })
    }

    fn pair_gap(&self, q: &[Real], a: usize, b: usize, reach: Real) -> Real {
        let (ra, rb) = (self.pos(q, a), self.pos(q, b));
        let d2: Real = ra.iter().zip(rb).map(|(x, y)| (y - x) * (y - x)).sum();
        if self.dim == 1 {
            // in 1-D bodies keep their order: b is on the side it started
            match self.side(a, b) {
                Some(side) => side * (rb[0] - ra[0]) - reach,
                None => (rb[0] - ra[0]).abs() - reach,
            }
        } else {
            d2.sqrt() - reach
        }
    }

    /// The first overlap at the start, if any (touching is allowed).
    pub fn overlap(&self, q: &[Real]) -> Option<Overlap> {
        for (a, b, reach) in self.pairs() {
            let gap = self.pair_gap(q, a, b, reach);
            if gap < -TOUCH * reach {
                return Some(Overlap {
                    body: a,
                    other: Some(b),
                    wall: None,
                    depth: -gap,
                });
            }
        }
        for (i, w, r) in self.wall_contacts() {
            let gap = self.walls[w].distance(self.pos(q, i)) - r;
            if gap < -TOUCH * r.max(Real::MIN_POSITIVE) {
                return Some(Overlap {
                    body: i,
                    other: None,
                    wall: Some(w),
                    depth: -gap,
                });
            }
        }
        None
    }

    /// Resolves every touching, approaching contact in `y = [q, v]` (see the module doc);
    /// returns the number of impulses applied.
    pub fn resolve_contacts(&self, y: &mut [Real]) -> usize {
        let (q, v) = y.split_at_mut(y.len() / 2);
        let d = self.dim;
        let mut applied = 0;
        for _ in 0..MAX_SWEEPS {
            let mut any = false;
            for (a, b, reach) in self.pairs() {
                let gap = self.pair_gap(q, a, b, reach);
                // touching: within TOUCH of the radii, or of the positions' size for two
                // points, which the located crossing leaves a few ulps apart (or past)
                let scale = reach
                    + (0..d)
                        .map(|k| q[a * d + k].abs() + q[b * d + k].abs())
                        .sum::<Real>();
                if gap > TOUCH * reach + POINT_TOUCH * scale {
                    continue;
                }
                let normal = if d == 1 {
                    vec![self.side(a, b).unwrap_or_else(|| (q[b] - q[a]).signum())]
                } else {
                    (0..d).map(|k| q[b * d + k] - q[a * d + k]).collect()
                };
                if !approaching(&v[a * d..(a + 1) * d], &v[b * d..(b + 1) * d], &normal) {
                    continue;
                }
                let (restitution, friction) = self.rule(a, b);
                let c = Collision {
                    m1: self.mass[a],
                    m2: self.mass[b],
                    v1: v[a * d..(a + 1) * d].to_vec(),
                    v2: v[b * d..(b + 1) * d].to_vec(),
                    normal,
                    restitution,
                    friction,
                };
                if let Ok(Resolution::Collided(o)) = c.resolve() {
                    v[a * d..(a + 1) * d].copy_from_slice(&o.v1);
                    v[b * d..(b + 1) * d].copy_from_slice(&o.v2);
                    any = true;
                    applied += 1;
                }
            }
            for (i, w, r) in self.wall_contacts() {
                let wall = &self.walls[w];
                let at = &q[i * d..(i + 1) * d];
                let gap = wall.distance(at) - r;
                // touching: within TOUCH of the radius, or of the positions' size for a point
                // (radius 0), which the located crossing leaves a few ulps off the wall
                let scale = r + at.iter().chain(&wall.point).map(|x| x.abs()).sum::<Real>();
                if gap > TOUCH * r + POINT_TOUCH * scale {
                    continue;
                }
                let inward: Vec<Real> = wall.normal.iter().map(|x| -x).collect();
                let at_rest = [0.0; 3];
                if !approaching(&v[i * d..(i + 1) * d], &at_rest[..d], &inward) {
                    continue;
                }
                let c = Collision {
                    m1: self.mass[i],
                    m2: Real::INFINITY,
                    v1: v[i * d..(i + 1) * d].to_vec(),
                    v2: vec![0.0; d],
                    normal: inward,
                    restitution: wall.restitution,
                    friction: wall.friction,
                };
                if let Ok(Resolution::Collided(o)) = c.resolve() {
                    v[i * d..(i + 1) * d].copy_from_slice(&o.v1);
                    any = true;
                    applied += 1;
                }
            }
            if !any {
                break;
            }
        }
        applied
    }

    /// Relative speed of bodies `a` and `b` in `y = [q, v]`.
    fn relative_speed(&self, y: &[Real], a: usize, b: usize) -> Real {
        let d = self.dim;
        let v = &y[y.len() / 2..];
        (0..d)
            .map(|k| (v[b * d + k] - v[a * d + k]).powi(2))
            .sum::<Real>()
            .sqrt()
    }

    /// Velocity of body `i` in `y = [q, v]` along a wall's `normal` (positive away from it).
    fn normal_velocity(&self, y: &[Real], i: usize, normal: &[Real]) -> Real {
        let d = self.dim;
        let v = &y[y.len() / 2 + i * d..y.len() / 2 + (i + 1) * d];
        v.iter().zip(normal).map(|(a, b)| a * b).sum()
    }

    /// One event per pair of spheres and per (sphere, wall), each resolving the contacts when
    /// its gap falls through zero, and each asking for samples dense enough inside a step that
    /// the bodies cannot pass through each other between two of them, whatever their speed
    /// (see the spacing rule above).
    pub fn events(self) -> Vec<Event> {
        let this = Arc::new(self);
        let mut events = Vec::new();
        for (a, b, reach) in this.pairs() {
            let (g, s, p) = (Arc::clone(&this), Arc::clone(&this), Arc::clone(&this));
            let name = format!("{} hits {}", this.names[a], this.names[b]);
            let bound = Arc::clone(&this);
            let gap = Condition::from_fn(name, false, false, move |smp, _| {
                let scale = reach + g.pos(smp.q, a)[0].abs() + g.pos(smp.q, b)[0].abs();
                snapped(g.pair_gap(smp.q, a, b, reach), scale)
            })
            .with_enclosure(move |j, _| Some(bound.pair_gap_jet(j, a, b, reach)));
            events.push(
                Event::from_function(gap)
                    .direction(Direction::Falling)
                    .set(move |_, _, y| {
                        s.resolve_contacts(y);
                    })
                    .set_description("impulse with restitution")
                    .sampling(move |y0, y1, h| {
                        if let Some(side) = p.side(a, b) {
                            // on a line the gap is signed, as a wall's
                            let rate =
                                |y: &[Real]| side * (y[y.len() / 2 + b] - y[y.len() / 2 + a]);
                            signed_gap_samples(rate(y0), rate(y1), h, reach)
                        } else {
                            let u = p.relative_speed(y0, a, b).max(p.relative_speed(y1, a, b));
                            samples_for(u, h, reach)
                        }
                    }),
            );
        }
        for (i, w, r) in this.wall_contacts() {
            let (g, s, p) = (Arc::clone(&this), Arc::clone(&this), Arc::clone(&this));
            let name = format!("{} hits {}", this.names[i], this.walls[w].name);
            let bound = Arc::clone(&this);
            let gap = Condition::from_fn(name, false, false, move |smp, _| {
                let wall = &g.walls[w];
                let r_i = g.pos(smp.q, i);
                let scale = r + r_i.iter().chain(&wall.point).map(|x| x.abs()).sum::<Real>();
                snapped(wall.distance(r_i) - r, scale)
            })
            .with_enclosure(move |j, _| Some(bound.wall_gap_jet(j, i, w, r)));
            events.push(
                Event::from_function(gap)
                    .direction(Direction::Falling)
                    .set(move |_, _, y| {
                        s.resolve_contacts(y);
                    })
                    .set_description("impulse with restitution")
                    .sampling(move |y0, y1, h| {
                        let n = p.walls[w].normal.as_slice();
                        let (u0, u1) = (p.normal_velocity(y0, i, n), p.normal_velocity(y1, i, n));
                        signed_gap_samples(u0, u1, h, r)
                    }),
            );
        }
        events
    }
}

#[path = "impacts_bounds.rs"]
mod bounds;

#[cfg(test)]
use bounds::SPACING;
use bounds::{samples_for, signed_gap_samples};

#[cfg(test)]
#[path = "impacts_tests.rs"]
mod tests;

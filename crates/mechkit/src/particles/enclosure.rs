//! Enclosures of the state over a range of times inside a step: each quantity a formula may
//! read (`x`, `vy`, `r`, `speed`, `K`, `work.F`, …) as an interval holding all its values
//! there, with an interval holding its time derivative ([`Jet`]), read off the step's
//! interpolant ([`StepPolynomial`]). Event functions are bounded with them
//! ([`crate::simulate::Condition::enclose`]) to prove where they cannot change sign.

use mechkit_expr::interval::{Interval, Jet};

use super::vars::{BodyRef, StateVar};
use crate::Real;
use crate::ode::StepPolynomial;

/// The state over the times `t₀ + s h`, `s ∈ S`, of one step.
#[derive(Debug, Clone, Copy)]
pub struct StateJets<'a> {
    poly: &'a StepPolynomial,
    s: Interval,
    dim: usize,
    /// Number of coordinates (velocities follow them in the polynomial).
    n: usize,
    mass: &'a [Real],
    /// Whether the work of each force follows the velocities in the polynomial.
    work: bool,
}

impl<'a> StateJets<'a> {
    /// The state of a system in `dim` dimensions with body masses `mass`, over the fractions
    /// `s` of the step whose interpolant is `poly` (`[q, v]` with `dof` coordinates, then the
    /// work of each force when `work`).
    pub fn new(
        poly: &'a StepPolynomial,
        s: Interval,
        dim: usize,
        mass: &'a [Real],
        dof: usize,
        work: bool,
    ) -> Self {
        Self {
            poly,
            s,
            dim,
            n: dof,
            mass,
            work,
        }
    }

    /// Time.
    pub fn time(&self) -> Jet {
        let t0 = Interval::point(self.poly.t0());
        let h = Interval::point(self.poly.h());
        Jet {
            v: t0 + h * self.s,
            d: Interval::point(1.0),
        }
    }

    /// Position component `i` of body `b`.
    pub fn position(&self, b: usize, i: usize) -> Jet {
        self.poly.enclose(b * self.dim + i, self.s)
    }

    /// Coordinate `i` of `q` (an angle, a mode).
    pub fn coordinate(&self, i: usize) -> Jet {
        self.poly.enclose(i, self.s)
    }

    /// Rate of coordinate `i`.
    pub fn coordinate_rate(&self, i: usize) -> Jet {
        self.poly.enclose(self.n + i, self.s)
    }

    /// Velocity component `i` of body `b`.
    pub fn velocity(&self, b: usize, i: usize) -> Jet {
        self.poly.enclose(self.n + b * self.dim + i, self.s)
    }

    /// Work done by force `k` so far, when the interpolant carries it (adaptive runs).
    pub fn work(&self, k: usize) -> Option<Jet> {
        let i = 2 * self.n + k;
        (self.work && i < self.poly.len()).then(|| self.poly.enclose(i, self.s))
    }

    /// Mass of body `b`.
    pub fn mass(&self, b: usize) -> Real {
        self.mass[b]
    }

    /// Number of bodies.
    pub fn bodies(&self) -> usize {
        self.mass.len()
    }

    /// `|(c_0, …)|` of body `b`'s positions or velocities.
    fn norm(&self, b: usize, component: impl Fn(usize, usize) -> Jet) -> Jet {
        if self.dim == 1 {
            return component(b, 0).abs();
        }
        let sum = (0..self.dim)
            .map(|i| component(b, i).sqr())
            .reduce(|a, c| a + c)
            .expect("at least one dimension");
        sum.sqrt()
    }

    /// `½ m |v|²` of body `b`.
    fn kinetic(&self, b: usize) -> Jet {
        let v2 = (0..self.dim)
            .map(|i| self.velocity(b, i).sqr())
            .reduce(|a, c| a + c)
            .expect("at least one dimension");
        Jet::constant(0.5 * self.mass[b]) * v2
    }
}

impl StateVar {
    /// The enclosure of this quantity over the times of `j`, bare names meaning body `local`;
    /// `None` for quantities that depend on the forces (accelerations, potential energy,
    /// power) or on the work where the interpolant does not carry it.
    pub fn enclose(self, j: &StateJets<'_>, local: Option<usize>) -> Option<Jet> {
        let body = |r: BodyRef| match r {
            BodyRef::Index(i) => Some(i),
            BodyRef::Local => local,
        };
        Some(match self {
            StateVar::Time => j.time(),
            StateVar::Position(r, i) => j.position(body(r)?, i),
            StateVar::Velocity(r, i) => j.velocity(body(r)?, i),
            StateVar::Speed(r) => j.norm(body(r)?, |b, i| j.velocity(b, i)),
            StateVar::Distance(r) => j.norm(body(r)?, |b, i| j.position(b, i)),
            StateVar::Mass(r) => Jet::constant(j.mass(body(r)?)),
            StateVar::BodyKinetic(r) => j.kinetic(body(r)?),
            StateVar::Coordinate(i) | StateVar::VariableMass(i) => j.coordinate(i),
            StateVar::CoordinateRate(i) => j.coordinate_rate(i),
            StateVar::Kinetic if j.n != j.dim * j.bodies() => return None,
            StateVar::Kinetic => (0..j.bodies())
                .map(|b| j.kinetic(b))
                .reduce(|a, c| a + c)
                .unwrap_or(Jet::constant(0.0)),
            StateVar::Work(k) => j.work(k)?,
            _ => return None,
        })
    }
}

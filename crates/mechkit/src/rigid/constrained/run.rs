//! The motion on the curve by the one event driver ([`run_to_event`]): the turning points, and
//! the departure where the normal force reaches zero (then the free flight, `flight.rs`).

use std::ops::ControlFlow;

use super::curve::{Curve, Geometry, Side};
use super::error::ConstrainedError;
use crate::Real;
use crate::interval::Jet;
use crate::ode::{
    AdaptiveConfig, AdaptiveRk, AdaptiveStats, EventEnd, OdeEvent, OdeSystem, Progress, State,
    Tableau, run_to_event,
};
use crate::rigid::Input;

/// A body on a curve: the curve, the side it is on, its mass and gravity.
#[derive(Debug, Clone, PartialEq)]
pub struct BeadOnCurve {
    /// The curve.
    pub curve: Curve,
    /// Which side of it the body is on.
    pub side: Side,
    /// Mass (kg): only the normal force depends on it.
    pub mass: Real,
    /// Gravitational acceleration (m/s², pointing in −y).
    pub g: Real,
}

/// Where the body starts: the coordinate (x for a graph, the angle φ from the top, clockwise,
/// for a circle) and the speed along the curve, positive in the direction of increasing
/// coordinate.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Start {
    /// x (m) or φ (rad).
    pub coordinate: Real,
    /// Signed speed along the curve (m/s).
    pub speed: Real,
}

/// One sample of the motion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BeadSample {
    /// Time (s).
    pub t: Real,
    /// Position (m).
    pub position: [Real; 2],
    /// Velocity (m/s).
    pub velocity: [Real; 2],
    /// The normal force (N) along the allowed direction (for a threaded bead: along n) while
    /// on the curve; `None` in free flight.
    pub normal_force: Option<Real>,
}

/// The body leaves the curve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Departure {
    /// Time (s).
    pub t: Real,
    /// The curve coordinate there (x or φ).
    pub coordinate: Real,
    /// Position (m).
    pub position: [Real; 2],
    /// Velocity (m/s).
    pub velocity: [Real; 2],
    /// The normal force there (N): zero to the integration's accuracy.
    pub normal_force: Real,
}

/// The free body meets the curve again.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Landing {
    /// Time (s).
    pub t: Real,
    /// The curve coordinate there.
    pub coordinate: Real,
    /// Position (m).
    pub position: [Real; 2],
    /// Velocity (m/s).
    pub velocity: [Real; 2],
    /// The velocity component along the curve's tangent (m/s).
    pub tangential_speed: Real,
    /// The velocity component into the curve (m/s, positive).
    pub normal_speed: Real,
}

/// Why the run ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum StopReason {
    /// `t_max` reached.
    TimeLimit,
    /// The body left the curve and landed on it again.
    Landed,
}

/// A run ([`BeadOnCurve::simulate`]).
#[derive(Debug, Clone, PartialEq)]
pub struct BeadRun {
    /// Samples: the start, the end of every accepted step on the curve, the departure, then
    /// the flight.
    pub samples: Vec<BeadSample>,
    /// Where the body left the curve, if it did.
    pub departure: Option<Departure>,
    /// Where it met the curve again, if it did before `t_max`.
    pub landing: Option<Landing>,
    /// Times at which the speed along the curve changes sign (turning points): events of
    /// [`run_to_event`], located by Brent's method on the interpolant.
    pub turning_times: Vec<Real>,
    /// The energy per unit mass at the start, ½v² + g y (J/kg).
    pub energy: Real,
    /// The largest |E − E₀| per unit mass on the curve (J/kg).
    pub energy_drift: Real,
    /// Why it ended.
    pub stop: StopReason,
    /// The integrator's counters.
    pub stats: AdaptiveStats,
}

struct System<'a> {
    curve: &'a Curve,
    g: Real,
}

impl OdeSystem for System<'_> {
    fn dim(&self) -> usize {
        2
    }

    fn rhs_into(&self, _t: Real, y: &[Real], dydt: &mut [Real]) {
        dydt[0] = y[1];
        dydt[1] = self.curve.geometry(y[0]).accel(y[1], self.g);
    }
}

pub(super) fn positive(
    (input, what): (Input, &'static str),
    value: Real,
    zero_ok: bool,
) -> Result<Real, ConstrainedError> {
    if value.is_finite() && (value > 0.0 || (zero_ok && value == 0.0)) {
        Ok(value)
    } else {
        Err(ConstrainedError::Value {
            input,
            what,
            value,
            must_be: if zero_ok {
                "zero or positive, and finite"
            } else {
                "positive and finite"
            },
        })
    }
}

impl BeadOnCurve {
    /// A checked model: `mass` > 0, `g` ≥ 0.
    pub fn new(curve: Curve, side: Side, mass: Real, g: Real) -> Result<Self, ConstrainedError> {
        Ok(Self {
            curve,
            side,
            mass: positive((Input::Mass, "the mass"), mass, false)?,
            g: positive((Input::Gravity, "g"), g, true)?,
        })
    }

    /// The normal force (N) along the allowed direction at `(q, q̇)` (along n for a bead).
    pub fn normal_force(&self, q: Real, qd: Real) -> Real {
        let n = self.curve.geometry(q).normal_force(qd, self.g) * self.mass;
        match self.side {
            Side::Bead => n,
            side => side.sign() * n,
        }
    }

    fn sample(&self, t: Real, y: &[Real]) -> BeadSample {
        let geo = self.curve.geometry(y[0]);
        BeadSample {
            t,
            position: geo.r,
            velocity: [geo.d1[0] * y[1], geo.d1[1] * y[1]],
            normal_force: Some(self.normal_force(y[0], y[1])),
        }
    }

    fn energy(&self, geo: &Geometry, qd: Real) -> Real {
        let v2 = (geo.d1[0] * geo.d1[0] + geo.d1[1] * geo.d1[1]) * qd * qd;
        0.5 * v2 + self.g * geo.r[1]
    }

    /// Integrates from `start` to `t_max` (s) with Dormand-Prince 5(4) at the tolerances of
    /// `config`, by the one event driver ([`run_to_event`]). The turning points are events
    /// where `q̇` changes sign. A body on one side of the curve leaves it where the normal force
    /// reaches zero (a terminal event, enclosed on a circle and on a graph whose formulas
    /// compile, so a dip of N below zero narrower than a step is not missed; the step redone to
    /// end there), and flies freely, integrated by the same driver, until it meets the curve
    /// again or `t_max` (the landing is an enclosed event on its gap from the curve). A body at
    /// rest where the curve is level (an equilibrium, stable or not) stays there: the run is its
    /// start and its state at `t_max`, without steps.
    pub fn simulate(
        &self,
        start: Start,
        t_max: Real,
        config: &AdaptiveConfig,
    ) -> Result<BeadRun, ConstrainedError> {
        positive((Input::Duration, "t_max"), t_max, false)?;
        if !(start.coordinate.is_finite() && start.speed.is_finite()) {
            return Err(ConstrainedError::Start(format!(
                "the start ({}, {}) must be finite",
                crate::error::short(start.coordinate),
                crate::error::short(start.speed)
            )));
        }
        config.validate(2)?;
        let sys = System {
            curve: &self.curve,
            g: self.g,
        };
        let geo0 = self.curve.check_at(start.coordinate)?;
        let qd0 = start.speed / geo0.speed_factor();
        let energy = self.energy(&geo0, qd0);
        let mut rk = AdaptiveRk::new(Tableau::dopri5(), config.clone())?;
        let mut state = State::new(0.0, vec![start.coordinate, qd0]);
        let mut samples = vec![self.sample(0.0, &state.y)];
        let (mut turning_times, mut drift) = (Vec::new(), 0.0_f64);
        let leaves = self.side != Side::Bead;
        let mut departure = None;
        if qd0 == 0.0
            && geo0.accel(0.0, self.g) == 0.0
            && !(leaves && self.normal_force(state.y[0], 0.0) < 0.0)
        {
            // at rest where the curve is level: the solution is constant (an equilibrium; the
            // turning-point event would be identically zero all along)
            samples.push(self.sample(t_max, &state.y));
            return Ok(BeadRun {
                samples,
                departure: None,
                landing: None,
                turning_times,
                energy,
                energy_drift: drift,
                stop: StopReason::TimeLimit,
                stats: rk.stats(),
            });
        }
        if leaves && self.normal_force(state.y[0], state.y[1]) < 0.0 {
            departure = Some(self.departure(&state));
        } else {
            let turning = OdeEvent::new(|_, y| y[1]).bounded_by(|_, y: &[Jet]| Some(y[1]));
            let mut events = vec![turning];
            if leaves {
                events.push(self.leaving());
            }
            let mut undefined = None;
            let mut last_q = start.coordinate;
            let end = run_to_event(&mut rk, &sys, &mut state, t_max, &events, &mut |p| {
                match p {
                    Progress::Event(hit) => turning_times.push(hit.t),
                    Progress::Step(s) => {
                        let geo = match self.curve.check_at(s.y[0]) {
                            Ok(geo) => geo,
                            Err(e) => {
                                undefined = Some(e);
                                return ControlFlow::Break(());
                            }
                        };
                        // a step or a kink crossed in this step: no equation of motion there
                        if let Some((x, what)) = self.curve.break_between(last_q, s.y[0]) {
                            undefined = Some(ConstrainedError::NotSmooth { x, what });
                            return ControlFlow::Break(());
                        }
                        last_q = s.y[0];
                        drift = drift.max((self.energy(&geo, s.y[1]) - energy).abs());
                        samples.push(self.sample(s.t, &s.y));
                    }
                }
                ControlFlow::Continue(())
            })?;
            if let Some(e) = undefined {
                return Err(e);
            }
            if end == (EventEnd::Terminal { event: 1 }) {
                departure = Some(self.departure(&state));
            }
        }
        let landing = match &departure {
            Some(d) => self.fly(&mut rk, d, t_max, &mut samples)?,
            None => None,
        };
        Ok(BeadRun {
            samples,
            departure,
            landing,
            turning_times,
            energy,
            energy_drift: drift,
            stop: if landing.is_some() {
                StopReason::Landed
            } else {
                StopReason::TimeLimit
            },
            stats: rk.stats(),
        })
    }

    /// Leaving the curve as a terminal event: the normal force along the allowed direction
    /// falls through zero. Enclosed from the jets of `q` and `q̇`
    /// ([`Curve::enclose_normal_force`]); sampled where a graph's formulas do not compile.
    fn leaving(&self) -> OdeEvent<'_> {
        let scale = Jet::constant(self.side.sign() * self.mass);
        OdeEvent::new(|_, y| self.normal_force(y[0], y[1]))
            .bounded_by(move |_, y| {
                Some(scale * self.curve.enclose_normal_force(y[0], y[1], self.g)?)
            })
            .falling()
            .terminal()
    }

    fn departure(&self, s: &State) -> Departure {
        let sample = self.sample(s.t, &s.y);
        Departure {
            t: s.t,
            coordinate: s.y[0],
            position: sample.position,
            velocity: sample.velocity,
            normal_force: self.normal_force(s.y[0], s.y[1]),
        }
    }
}

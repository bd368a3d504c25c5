//! The simulated motion of a [`RollingMotion`]: slipping and rolling integrated with DOP853 by
//! the one event driver ([`run_to_event`]), the start of rolling a terminal event where the
//! contact point's velocity reaches zero (enclosed, so never missed inside a step; the step
//! redone to end exactly there), and the energy balance with the work of friction integrated
//! along.

use std::ops::ControlFlow;

use super::error::RollingError;
use super::motion::RollingMotion;
use crate::Real;
use crate::energy::{EnergyBalance, EnergyTerm};
use crate::interval::Jet;
use crate::ode::{
    AdaptiveConfig, AdaptiveRk, AdaptiveStats, EventEnd, OdeEvent, OdeSystem, Progress, State,
    Tableau, run_to_event,
};
use crate::rigid::Input;

/// The regime of the contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Contact {
    /// Rolling without slipping, `v = ω R`; static friction.
    Rolling,
    /// Slipping; `direction` is the sign of the contact point's velocity `v − ω R` (±1).
    Slipping {
        /// +1 sliding down the slope (forward), −1 up (backward).
        direction: Real,
    },
}

/// One interval of rolling or slipping.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollPhase {
    /// The regime.
    pub contact: Contact,
    /// `(t, x, v, ω)` at the start.
    pub start: (Real, Real, Real, Real),
    /// `(t, x, v, ω)` at the end.
    pub end: (Real, Real, Real, Real),
    /// Whether it ended at a switch (true) or at the end time (false).
    pub switched: bool,
}

/// One output point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollSample {
    /// Time (s).
    pub t: Real,
    /// Position along the incline, down positive (m).
    pub x: Real,
    /// Velocity (m/s).
    pub v: Real,
    /// Angle turned (rad), forward positive.
    pub theta: Real,
    /// Angular velocity (rad/s), forward positive.
    pub omega: Real,
    /// Slip velocity of the contact point `v − ω R` (m/s).
    pub slip_velocity: Real,
    /// Friction on the body along the incline, down positive (N).
    pub friction: Real,
    /// Whether the body rolls without slipping.
    pub rolling: bool,
    /// Work of friction so far (J).
    pub work_friction: Real,
}

/// A simulated motion ([`RollingMotion::simulate`]).
#[derive(Debug, Clone, PartialEq)]
pub struct RollingRun {
    /// The state at the end of every accepted step and at both sides of every switch.
    pub samples: Vec<RollSample>,
    /// The phases in order.
    pub phases: Vec<RollPhase>,
    /// `(t, x, v, ω)` when rolling first begins, if it does.
    pub roll_start: Option<(Real, Real, Real, Real)>,
    /// The friction force while rolling (N), as the simulation applied it, if it rolls.
    pub rolling_friction: Option<Real>,
    /// The energy balance `K_trans + K_rot + U = E0 + W_friction`: `K` in the parts
    /// `"translational"` (`½ m v²`) and `"rotational"` (`½ I ω²`), `U = −m g x sin α` (part
    /// `"gravity"`), and the work of `"friction"` `∫ f (v − ω R) dt`, negative while slipping,
    /// zero while rolling.
    pub balance: EnergyBalance,
    /// The integrator's counters.
    pub stats: AdaptiveStats,
}

/// `y = [x, v, θ, ω, W_f]` in one regime.
struct Dynamics<'a> {
    motion: &'a RollingMotion,
    contact: Contact,
}

impl Dynamics<'_> {
    fn friction(&self) -> Real {
        match self.contact {
            Contact::Rolling => self.motion.rolling_friction(),
            Contact::Slipping { direction } => self.motion.slip_friction(direction),
        }
    }
}

impl OdeSystem for Dynamics<'_> {
    fn dim(&self) -> usize {
        5
    }

    fn rhs_into(&self, _t: Real, y: &[Real], dydt: &mut [Real]) {
        let m = self.motion;
        let b = &m.body;
        let f = self.friction();
        dydt[0] = y[1];
        dydt[1] = m.g * m.angle.sin() + f / b.mass;
        dydt[2] = y[3];
        dydt[3] = -f * b.radius / b.moment_of_inertia();
        dydt[4] = f * (y[1] - y[3] * b.radius);
    }
}

impl RollingMotion {
    /// The regime from a state with `v_c = 0`: rolling if it can last, else slipping down.
    fn contact_at_rest(&self) -> Contact {
        if self.can_roll() {
            Contact::Rolling
        } else {
            Contact::Slipping {
                direction: self.breakaway_direction(),
            }
        }
    }

    /// Simulates from `t = 0` to `t_max` with DOP853 at the tolerances of `config` (the
    /// error control looks at `x, v, θ, ω`; the work of friction rides along). A slip ends
    /// when the contact point's velocity `v − ω R` reaches zero, a terminal event of
    /// [`run_to_event`] located inside the step by Brent's method on the interpolant; the step
    /// is redone to exactly then, `ω` is set to
    /// `v/R`, and the body rolls if the friction rolling needs is within `μs N`
    /// ([`RollingMotion::can_roll`]), otherwise it slips on the other way.
    ///
    /// # Example
    /// ```
    /// use approx::assert_relative_eq;
    /// use mechkit::ode::{AdaptiveConfig, Tolerance};
    /// use mechkit::rigid::friction::Coulomb;
    /// use mechkit::rigid::rolling::{RollingBody, RollingMotion};
    /// // a sphere placed on a 20° slope spinning backwards
    /// let ball = RollingBody::sphere(0.45, 0.11)?;
    /// let motion = RollingMotion::new(ball, 20f64.to_radians(), Coulomb::single(0.3)?)
    ///     .launched(0.0, -30.0);
    /// let config = AdaptiveConfig { rtol: Tolerance::Scalar(1e-12), ..Default::default() };
    /// let run = motion.simulate(3.0, &config)?;
    /// let (t, _, v, _) = run.roll_start.unwrap();
    /// let (t_c, v_c) = motion.roll_start().unwrap();
    /// assert_relative_eq!(t, t_c, max_relative = 1e-10);
    /// assert_relative_eq!(v, v_c, max_relative = 1e-10);
    /// assert_relative_eq!(run.rolling_friction.unwrap(), motion.rolling_friction());
    /// # Ok::<(), mechkit::rigid::rolling::RollingError>(())
    /// ```
    pub fn simulate(
        &self,
        t_max: Real,
        config: &AdaptiveConfig,
    ) -> Result<RollingRun, RollingError> {
        self.validate()?;
        if !(t_max.is_finite() && t_max > 0.0) {
            return Err(RollingError::Invalid {
                input: Input::Duration,
                what: "the end time t_max (s)",
                value: t_max,
                expected: "positive and finite",
            });
        }
        let config = AdaptiveConfig {
            error_components: Some(4),
            ..config.clone()
        };
        config.validate(5)?;
        let mut rk = AdaptiveRk::new(Tableau::dop853(), config)?;
        let radius = self.body.radius;
        let mut state = State::new(0.0, vec![self.x0, self.v0, 0.0, self.omega0, 0.0]);
        let vc0 = self.slip_velocity(self.v0, self.omega0);
        let mut contact = if vc0 == 0.0 {
            self.contact_at_rest()
        } else {
            Contact::Slipping {
                direction: vc0.signum(),
            }
        };
        let (mut samples, mut phases) = (Vec::new(), Vec::new());
        let (mut roll_start, mut rolling_friction) = (None, None);
        let quad = |s: &State| (s.t, s.y[0], s.y[1], s.y[3]);
        loop {
            let dynamics = Dynamics {
                motion: self,
                contact,
            };
            if contact == Contact::Rolling {
                roll_start.get_or_insert(quad(&state));
                rolling_friction = Some(dynamics.friction());
            }
            let start = quad(&state);
            samples.push(self.sample(&dynamics, &state));
            let event = self.switch(&dynamics);
            rk.reset();
            let end = run_to_event(&mut rk, &dynamics, &mut state, t_max, &[event], &mut |p| {
                if let Progress::Step(s) = p {
                    samples.push(self.sample(&dynamics, s));
                }
                ControlFlow::Continue(())
            })?;
            let switched = matches!(end, EventEnd::Terminal { .. });
            if switched && matches!(contact, Contact::Slipping { .. }) {
                // the contact point is at rest at the located time
                state.y[3] = state.y[1] / radius;
            }
            phases.push(RollPhase {
                contact,
                start,
                end: quad(&state),
                switched,
            });
            if !switched {
                break;
            }
            contact = match contact {
                Contact::Slipping { .. } => self.contact_at_rest(),
                // rolling can no longer last: the contact point breaks away down the slope
                Contact::Rolling => Contact::Slipping {
                    direction: self.breakaway_direction(),
                },
            };
        }
        let balance = self.balance(&state);
        Ok(RollingRun {
            samples,
            phases,
            roll_start,
            rolling_friction,
            balance,
            stats: rk.stats(),
        })
    }

    /// The end of a regime as a terminal event, positive while it lasts: rolling lasts while
    /// the friction it needs is within `μs N` (on a plane that is constant: a rolling body
    /// keeps rolling), slipping while the contact point slides the same way. Both enclosed.
    fn switch(&self, d: &Dynamics<'_>) -> OdeEvent<'_> {
        let radius = self.body.radius;
        let c = Jet::constant;
        match d.contact {
            Contact::Rolling => {
                let margin = self.friction.max_static(self.normal()) - d.friction().abs();
                OdeEvent::new(move |_, _| margin).bounded_by(move |_, _| Some(c(margin)))
            }
            Contact::Slipping { direction } => {
                OdeEvent::new(move |_, y| direction * (y[1] - y[3] * radius))
                    .bounded_by(move |_, y| Some(c(direction) * (y[1] - y[3] * c(radius))))
            }
        }
        .falling()
        .terminal()
    }

    fn sample(&self, d: &Dynamics<'_>, s: &State) -> RollSample {
        RollSample {
            t: s.t,
            x: s.y[0],
            v: s.y[1],
            theta: s.y[2],
            omega: s.y[3],
            slip_velocity: self.slip_velocity(s.y[1], s.y[3]),
            friction: d.friction(),
            rolling: d.contact == Contact::Rolling,
            work_friction: s.y[4],
        }
    }

    fn balance(&self, end: &State) -> EnergyBalance {
        let (kt0, kr0) = self.kinetic(self.v0, self.omega0);
        let (kt1, kr1) = self.kinetic(end.y[1], end.y[3]);
        let (u0, u1) = (self.potential(self.x0), self.potential(end.y[0]));
        EnergyBalance::new(EnergyTerm::from_parts([
            ("translational", kt0, kt1),
            ("rotational", kr0, kr1),
        ]))
        .with_potential(EnergyTerm::from_parts([("gravity", u0, u1)]))
        .with_work("friction", end.y[4])
    }
}

//! The stick-slip simulation of a [`SpringBlock`]: each regime integrated with DOP853 by the
//! one event driver ([`run_to_event`]), its end a terminal event with an enclosure (so a switch
//! is never missed inside a step, and the step is redone to end exactly there), the phases
//! listed, and the energy balance kept by integrating the heat and the work of the belt and of
//! the anchor with the motion.

use std::ops::ControlFlow;

use super::error::FrictionError;
use super::spring_block::SpringBlock;
use crate::Real;
use crate::energy::{EnergyBalance, EnergyTerm};
use crate::interval::Jet;
use crate::ode::{
    AdaptiveConfig, AdaptiveRk, AdaptiveStats, EventEnd, OdeEvent, OdeSystem, Progress, State,
    Tableau, run_to_event,
};
use crate::rigid::Input;

/// The regime of the block relative to the surface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Regime {
    /// Moving with the surface; static friction balances the spring.
    Stick,
    /// Sliding; `direction` is the sign of `v − u` (±1).
    Slip {
        /// +1 faster than the surface, −1 slower.
        direction: Real,
    },
}

/// How a phase ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PhaseEnd {
    /// A stick ended because `|F_s|` reached `μs N`, a slip because `v − u` reached 0.
    Switch,
    /// The simulation reached its end time.
    TimeLimit,
}

/// One stick or slip interval.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Phase {
    /// The regime.
    pub regime: Regime,
    /// `(t, x, v)` at the start.
    pub start: (Real, Real, Real),
    /// `(t, x, v)` at the end.
    pub end: (Real, Real, Real),
    /// Why it ended.
    pub ended: PhaseEnd,
    /// The distance slid relative to the surface, `Δx − u Δt` (m); 0 for a stick.
    pub slip_distance: Real,
}

/// One output point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StickSlipSample {
    /// Time (s).
    pub t: Real,
    /// Position (m).
    pub x: Real,
    /// Velocity (m/s).
    pub v: Real,
    /// The spring's force on the block (N).
    pub spring_force: Real,
    /// The friction on the block (N).
    pub friction: Real,
    /// Whether the block sticks.
    pub stuck: bool,
    /// Heat generated so far (J).
    pub heat: Real,
    /// Work done so far by the belt through friction (J).
    pub work_belt: Real,
    /// Work done so far by the anchor through the spring (J).
    pub work_anchor: Real,
}

/// A simulated stick-slip motion ([`SpringBlock::simulate`]).
#[derive(Debug, Clone, PartialEq)]
pub struct StickSlipRun {
    /// The state at the end of every accepted step, and at both sides of every switch.
    pub samples: Vec<StickSlipSample>,
    /// The stick and slip intervals in order.
    pub phases: Vec<Phase>,
    /// The energy balance: `K`, the spring's `U` (part `"spring"`), and the work of
    /// `"friction"` (relative to the surface, `∫ f (v − u) dt = −Q`: the heat is its negative),
    /// of the `"belt"` (`∫ f u dt`, 0 on a fixed floor) and of the `"anchor"` (`∫ F_s w dt`, 0
    /// for a fixed wall); the first two add up to the work of friction on the block.
    pub balance: EnergyBalance,
    /// The integrator's counters over the run.
    pub stats: AdaptiveStats,
}

/// `y = [x, v, Q, W_belt, W_anchor]` in one regime.
struct Motion<'a> {
    block: &'a SpringBlock,
    regime: Regime,
}

impl Motion<'_> {
    /// The friction on the block at `(t, x, v)` in this regime.
    fn friction(&self, t: Real, x: Real) -> Real {
        match self.regime {
            // the surface moves steadily: no acceleration relative to it, f balances F_s
            Regime::Stick => -self.block.spring_force(t, x),
            Regime::Slip { direction } => {
                -direction * self.block.friction.dynamic(self.block.normal())
            }
        }
    }
}

impl OdeSystem for Motion<'_> {
    fn dim(&self) -> usize {
        5
    }

    fn rhs_into(&self, t: Real, y: &[Real], dydt: &mut [Real]) {
        let b = self.block;
        let (x, v) = (y[0], y[1]);
        let fs = b.spring_force(t, x);
        let f = self.friction(t, x);
        let u = b.belt_speed;
        match self.regime {
            Regime::Stick => {
                dydt[0] = u;
                dydt[1] = 0.0;
            }
            Regime::Slip { .. } => {
                dydt[0] = v;
                dydt[1] = (fs + f) / b.mass;
            }
        }
        dydt[2] = -f * (v - u);
        dydt[3] = f * u;
        dydt[4] = fs * b.anchor_speed;
    }
}

impl SpringBlock {
    /// The regime at `(t, x)` with the block moving with the surface: stick if the spring
    /// force is within the static bound (or on it and about to fall back inside), else slip
    /// in the direction of the spring force.
    fn regime_at_rest(&self, t: Real, x: Real) -> Regime {
        let fs = self.spring_force(t, x);
        let bound = self.stick_bound();
        // sticking, F_s changes at the rate −k (u − w)
        let rate = -self.k * (self.belt_speed - self.anchor_speed);
        if fs.abs() < bound || (fs.abs() == bound && fs * rate <= 0.0) {
            Regime::Stick
        } else {
            Regime::Slip {
                direction: fs.signum(),
            }
        }
    }

    /// Simulates from `t = 0` to `t_max` with DOP853 at the tolerances of `config` (its
    /// error control looks at `x` and `v`; the heat and works ride along). The switches
    /// are events: a stick ends when `|F_s|` reaches `μs N`, a slip when `v − u` reaches 0;
    /// both are terminal events of [`run_to_event`], found inside the step with a guarantee
    /// and located by Brent's method on the interpolant, and the step is redone to exactly
    /// that time. At the end of a slip the block sticks if the spring
    /// force is within `μs N`, otherwise it slips again the other way.
    ///
    /// # Example
    /// ```
    /// use approx::assert_relative_eq;
    /// use mechkit::ode::{AdaptiveConfig, Tolerance};
    /// use mechkit::rigid::friction::{Coulomb, Regime, SpringBlock};
    /// // a block moving with a belt at 0.1 m/s, tied to a wall: stick-slip cycles
    /// let block = SpringBlock::new(1.0, 100.0, Coulomb::new(0.6, 0.4)?)?
    ///     .on_belt(0.1)
    ///     .starting_at(0.0, 0.1);
    /// let config = AdaptiveConfig { rtol: Tolerance::Scalar(1e-12), atol: Tolerance::Scalar(1e-14), ..Default::default() };
    /// let run = block.simulate(5.0, &config)?;
    /// assert_eq!(run.phases[0].regime, Regime::Stick);
    /// // the first stick ends when k x = μs m g, after x/u
    /// let (t1, x1, _) = run.phases[0].end;
    /// assert_relative_eq!(x1, 0.6 * 9.81 / 100.0, max_relative = 1e-12);
    /// assert_relative_eq!(t1, x1 / 0.1, max_relative = 1e-12);
    /// assert!(run.balance.residual().abs() < 1e-10);
    /// # Ok::<(), mechkit::rigid::friction::FrictionError>(())
    /// ```
    pub fn simulate(
        &self,
        t_max: Real,
        config: &AdaptiveConfig,
    ) -> Result<StickSlipRun, FrictionError> {
        self.validate()?;
        if !(t_max.is_finite() && t_max > 0.0) {
            return Err(FrictionError::NotPositive {
                input: Input::Duration,
                what: "the end time t_max (s)",
                value: t_max,
            });
        }
        let config = AdaptiveConfig {
            error_components: Some(2),
            ..config.clone()
        };
        config.validate(5)?;
        let mut rk = AdaptiveRk::new(Tableau::dop853(), config)?;
        let u = self.belt_speed;
        let mut state = State::new(0.0, vec![self.x0, self.v0, 0.0, 0.0, 0.0]);
        let mut regime = if self.v0 == u {
            self.regime_at_rest(0.0, self.x0)
        } else {
            Regime::Slip {
                direction: (self.v0 - u).signum(),
            }
        };
        let mut samples = Vec::new();
        let mut phases = Vec::new();
        loop {
            if phases.len() >= self.max_phases {
                return Err(FrictionError::TooManyPhases {
                    max: self.max_phases,
                    t: state.t,
                });
            }
            let motion = Motion {
                block: self,
                regime,
            };
            let start = (state.t, state.y[0], state.y[1]);
            samples.push(self.sample(&motion, &state));
            let event = self.switch(regime);
            rk.reset();
            let end = run_to_event(&mut rk, &motion, &mut state, t_max, &[event], &mut |p| {
                if let Progress::Step(s) = p {
                    samples.push(self.sample(&motion, s));
                }
                ControlFlow::Continue(())
            })?;
            let switched = matches!(end, EventEnd::Terminal { .. });
            if switched && matches!(regime, Regime::Slip { .. }) {
                // the relative velocity is zero at the located time
                state.y[1] = u;
            }
            let (t1, x1, v1) = (state.t, state.y[0], state.y[1]);
            phases.push(Phase {
                regime,
                start,
                end: (t1, x1, v1),
                ended: if switched {
                    PhaseEnd::Switch
                } else {
                    PhaseEnd::TimeLimit
                },
                slip_distance: match regime {
                    Regime::Stick => 0.0,
                    Regime::Slip { .. } => (x1 - start.1) - u * (t1 - start.0),
                },
            });
            if !switched {
                break;
            }
            regime = match regime {
                Regime::Stick => Regime::Slip {
                    direction: self.spring_force(t1, x1).signum(),
                },
                Regime::Slip { .. } => self.regime_at_rest(t1, x1),
            };
        }
        let balance = self.balance(&state);
        Ok(StickSlipRun {
            samples,
            phases,
            balance,
            stats: rk.stats(),
        })
    }

    /// The end of a regime as a terminal event, positive while it lasts: a stick ends when
    /// `|F_s|` reaches `μs N`, a slip when `v − u` reaches 0. Both are enclosed from the jets
    /// of `t`, `x` and `v`.
    fn switch(&self, regime: Regime) -> OdeEvent<'_> {
        let (bound, k, w, u) = (
            self.stick_bound(),
            self.k,
            self.anchor_speed,
            self.belt_speed,
        );
        let c = Jet::constant;
        match regime {
            Regime::Stick => OdeEvent::new(move |t, y| bound - self.spring_force(t, y[0]).abs())
                .bounded_by(move |t, y| {
                    let fs = c(-k) * (y[0] - c(w) * t);
                    Some(c(bound) - fs.abs())
                }),
            Regime::Slip { direction } => OdeEvent::new(move |_, y| direction * (y[1] - u))
                .bounded_by(move |_, y| Some(c(direction) * (y[1] - c(u)))),
        }
        .falling()
        .terminal()
    }

    fn sample(&self, motion: &Motion<'_>, s: &State) -> StickSlipSample {
        let (t, x) = (s.t, s.y[0]);
        StickSlipSample {
            t,
            x,
            v: s.y[1],
            spring_force: self.spring_force(t, x),
            friction: motion.friction(t, x),
            stuck: motion.regime == Regime::Stick,
            heat: s.y[2],
            work_belt: s.y[3],
            work_anchor: s.y[4],
        }
    }

    fn balance(&self, end: &State) -> EnergyBalance {
        let kinetic = |v: Real| 0.5 * self.mass * v * v;
        let spring = (
            self.spring_energy(0.0, self.x0),
            self.spring_energy(end.t, end.y[0]),
        );
        let (heat, work_belt, work_anchor) = (end.y[2], end.y[3], end.y[4]);
        EnergyBalance::new(EnergyTerm::new(kinetic(self.v0), kinetic(end.y[1])))
            .with_potential(EnergyTerm::from_parts([("spring", spring.0, spring.1)]))
            .with_work("friction", -heat)
            .with_work("belt", work_belt)
            .with_work("anchor", work_anchor)
    }
}

impl StickSlipRun {
    /// The heat `Q = ∫ μd N |v − u| dt` generated while slipping (J, ≥ 0): the negative work
    /// of friction relative to the surface.
    pub fn heat(&self) -> Real {
        -self.work("friction")
    }

    /// The work of friction on the block in the ground frame, `∫ f v dt = W_belt − Q` (J).
    pub fn work_friction(&self) -> Real {
        self.work("belt") - self.heat()
    }

    /// The work of the moving surface through friction, `∫ f u dt` (J); 0 on a fixed floor.
    pub fn work_belt(&self) -> Real {
        self.work("belt")
    }

    /// The work of the moving anchor through the spring, `∫ F_s w dt` (J); 0 for a fixed wall.
    pub fn work_anchor(&self) -> Real {
        self.work("anchor")
    }

    fn work(&self, name: &str) -> Real {
        self.balance
            .work_of(name)
            .expect("a stick-slip balance books friction, belt and anchor")
    }
}

//! The simulated flight: the state `(x, v, m)` integrated with Dormand-Prince 5(4) by the one
//! event driver ([`run_to_event`]): the burn to exactly `t = T`, then the coast to the apex, a
//! terminal event where `v` falls through zero (enclosed, so never missed inside a step),
//! reached by integration and refined by one Newton step.

use std::ops::ControlFlow;

use super::error::RocketError;
use super::vehicle::Rocket;
use crate::Real;
use crate::interval::Jet;
use crate::ode::{
    AdaptiveConfig, AdaptiveRk, AdaptiveStats, EventEnd, OdeEvent, OdeSystem, Progress, State,
    Tableau, run_to_event,
};

/// A simulated flight ([`Rocket::simulate`]).
#[derive(Debug, Clone, PartialEq)]
pub struct RocketRun {
    /// `(t, x, v, m)` at the start and at the end of every accepted step; the burn ends on a
    /// sample at `t = T`, the coast (if any) on the apex.
    pub samples: Vec<(Real, Real, Real, Real)>,
    /// `(t, x, v)` at burnout, `t = T` exactly.
    pub burnout: (Real, Real, Real),
    /// `(t, x)` at the highest point of the coast (the burnout point if the rocket is not
    /// rising then); `None` without a coast or in free space.
    pub apex: Option<(Real, Real)>,
    /// The integrator's counters over the whole flight.
    pub stats: AdaptiveStats,
}

/// The right-hand side `x' = v`, `v' = (thrust − D v|v|)/m − g`, `m' = −ṁ` while burning
/// (thrust `u ṁ`), `m' = 0` and no thrust on the coast.
struct Flight<'a> {
    rocket: &'a Rocket,
    burning: bool,
}

impl OdeSystem for Flight<'_> {
    fn dim(&self) -> usize {
        3
    }

    fn rhs_into(&self, _t: Real, y: &[Real], dydt: &mut [Real]) {
        let r = self.rocket;
        let (v, m) = (y[1], y[2]);
        let (thrust, rate) = if self.burning {
            (r.thrust(), r.mass_rate)
        } else {
            (0.0, 0.0)
        };
        dydt[0] = v;
        dydt[1] = (thrust - r.drag_coefficient() * v * v.abs()) / m - r.g;
        dydt[2] = -rate;
    }
}

impl Rocket {
    /// Integrates the flight from rest at `x = 0` with Dormand-Prince 5(4) at the tolerances of
    /// `config`: the burn up to exactly `t = T`, then, if `coast` and `g > 0`, the coast with
    /// the mass `m1` until the speed reaches 0 (the apex: a terminal event of [`run_to_event`],
    /// located inside the step on the interpolant, then integrated to and refined by a Newton
    /// step). Without drag it agrees with the closed forms
    /// ([`Rocket::burnout`], [`Rocket::apex`]) to about the tolerance; with drag it is the
    /// only answer.
    ///
    /// # Example
    /// ```
    /// use approx::assert_relative_eq;
    /// use mechkit::ode::{AdaptiveConfig, Tolerance};
    /// use mechkit::rocket::Rocket;
    /// let rocket = Rocket::new(1000.0, 400.0, 10.0, 2000.0)?.with_gravity(9.81)?;
    /// let config = AdaptiveConfig { rtol: Tolerance::Scalar(1e-10), ..Default::default() };
    /// let run = rocket.simulate(&config, true)?;
    /// let (t1, x1, v1) = run.burnout;
    /// assert_eq!(t1, 60.0);
    /// assert_relative_eq!(v1, rocket.burnout().2, max_relative = 1e-8);
    /// assert_relative_eq!(x1, rocket.burnout().1, max_relative = 1e-8);
    /// let (_, apex) = run.apex.unwrap();
    /// assert_relative_eq!(apex, rocket.apex().unwrap().1, max_relative = 1e-8);
    /// // with drag the rocket goes less high
    /// let draggy = rocket.with_drag(0.01)?.simulate(&config, true)?;
    /// assert!(draggy.apex.unwrap().1 < apex);
    /// # Ok::<(), mechkit::rocket::RocketError>(())
    /// ```
    pub fn simulate(&self, config: &AdaptiveConfig, coast: bool) -> Result<RocketRun, RocketError> {
        self.validate()?;
        config.validate(3)?;
        let mut rk = AdaptiveRk::new(Tableau::dopri5(), config.clone())?;
        let t_burn = self.burn_time();
        let burn = Flight {
            rocket: self,
            burning: true,
        };
        let mut state = State::new(0.0, vec![0.0, 0.0, self.m0]);
        let mut samples = vec![sample(&state)];
        run_to_event(&mut rk, &burn, &mut state, t_burn, &[], &mut |p| {
            if let Progress::Step(s) = p {
                samples.push(sample(s));
            }
            ControlFlow::Continue(())
        })?;
        let burnout = (state.t, state.y[0], state.y[1]);
        let apex = if coast && self.g > 0.0 {
            // the mass m0 − ṁ t is integrated exactly up to rounding; the coast starts at m1
            state.y[2] = self.m1;
            rk.reset();
            Some(self.coast(&mut rk, state, &mut samples)?)
        } else {
            None
        };
        Ok(RocketRun {
            samples,
            burnout,
            apex,
            stats: rk.stats(),
        })
    }

    /// The coast from burnout `state` to the apex, appending samples; returns `(t, x)` there.
    fn coast(
        &self,
        rk: &mut AdaptiveRk,
        mut state: State,
        samples: &mut Vec<(Real, Real, Real, Real)>,
    ) -> Result<(Real, Real), RocketError> {
        let glide = Flight {
            rocket: self,
            burning: false,
        };
        let (t1, x1, v1) = (state.t, state.y[0], state.y[1]);
        if v1 <= 0.0 {
            return Ok((t1, x1));
        }
        // drag and gravity both slow the climb, so the apex comes before the drag-free one
        let t_bound = t1 + 2.0 * v1 / self.g;
        let apex = OdeEvent::new(|_, y| y[1])
            .bounded_by(|_, y: &[Jet]| Some(y[1]))
            .falling()
            .terminal();
        let end = run_to_event(rk, &glide, &mut state, t_bound, &[apex], &mut |p| {
            if let Progress::Step(s) = p {
                samples.push(sample(s));
            }
            ControlFlow::Continue(())
        })?;
        assert!(
            matches!(end, EventEnd::Terminal { .. }),
            "the coast turns before t1 + 2 v1/g"
        );
        // the state reached the interpolant's zero of v; one Newton step on v = 0 with v' = −g
        // there (no drag at zero speed) takes it to the integrator's own
        samples.pop();
        let dt = state.y[1] / self.g;
        let top = State::new(
            state.t + dt,
            vec![state.y[0] + 0.5 * state.y[1] * dt, 0.0, state.y[2]],
        );
        samples.push(sample(&top));
        Ok((top.t, top.y[0]))
    }
}

fn sample(s: &State) -> (Real, Real, Real, Real) {
    (s.t, s.y[0], s.y[1], s.y[2])
}

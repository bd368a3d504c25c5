//! Events: a function `g` of time and state whose zeros mark something happening (a bounce, an
//! apex, a crossing), with a direction, an action (record and continue, change the state, or
//! stop) and limits on how often it fires.
//!
//! Inside every step each event function is bounded over pieces of the step's interpolant
//! ([`super::prove`]), so no sign change inside a step is missed, however short; each crossing
//! is then located by Brent's method on the interpolant to near machine precision, and the
//! firings of all events are handled in time order.
//!
//! The rules at exact zeros (the cases SciPy's `solve_ivp` gets wrong, issues #9228, #17066,
//! #19418): arriving at zero is a crossing, at that exact time (a root on a step boundary fires
//! once, in the step that ends there); leaving zero afterwards is not. A zero at the start of
//! the run counts when the function leaves it in the event's direction.

use std::fmt;
use std::sync::Arc;

use super::condition::Condition;
use crate::Real;
use crate::ode::events::find::Side;
use crate::particles::{ParticleSystem, Sample};

pub use crate::ode::events::Direction;

/// What an event does when it fires (besides being recorded).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum EventAction {
    /// Record it and continue.
    #[default]
    Record,
    /// End the run at the `n`-th occurrence (earlier ones are recorded).
    StopAt(u32),
}

type SetFn = dyn Fn(&Sample<'_>, &ParticleSystem, &mut [Real]) + Send + Sync;
type SamplingFn = dyn Fn(&[Real], &[Real], Real) -> usize + Send + Sync;

/// When an event fires.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Trigger {
    /// A zero crossing in a direction.
    Crossing(Direction),
    /// The condition starts to hold (`[stop] when`): `g > 0`, or `g ≥ 0` when inclusive.
    Holds { inclusive: bool },
}

/// An event of a run.
///
/// # Example
/// ```
/// use mechkit::simulate::{Direction, Event};
/// // a ball bouncing on the floor y = 0 with restitution 0.9 (state [x, y, vx, vy])
/// let bounce = Event::new("bounce", |s, _| s.q[1])
///     .direction(Direction::Falling)
///     .set(|_, _, y| y[3] *= -0.9);
/// assert_eq!(bounce.name(), "bounce");
/// ```
#[derive(Clone)]
pub struct Event {
    condition: Condition,
    pub(crate) trigger: Trigger,
    pub(crate) action: EventAction,
    pub(crate) max_count: Option<u32>,
    set: Option<Arc<SetFn>>,
    set_description: Option<String>,
    sampling: Option<Arc<SamplingFn>>,
}

impl fmt::Debug for Event {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Event")
            .field("name", &self.condition.description())
            .field("trigger", &self.trigger)
            .field("action", &self.action)
            .field("max_count", &self.max_count)
            .field("set", &self.set_description)
            .field("sampling", &self.sampling.is_some())
            .finish()
    }
}

impl Event {
    /// An event at the zeros of `g` (of time, positions and velocities), recorded in both
    /// directions; refine it with the builder methods.
    pub fn new(
        name: impl Into<String>,
        g: impl Fn(&Sample<'_>, &ParticleSystem) -> Real + Send + Sync + 'static,
    ) -> Self {
        Self::from_function(Condition::from_fn(name, false, false, g))
    }

    /// An event at the zeros of a condition's event function (its `needs_forces` flag says
    /// whether `g` reads accelerations, energies, work or power).
    pub fn from_function(condition: Condition) -> Self {
        Self {
            condition,
            trigger: Trigger::Crossing(Direction::Both),
            action: EventAction::Record,
            max_count: None,
            set: None,
            set_description: None,
            sampling: None,
        }
    }

    /// The stop condition of `[stop] when`: fires when the condition starts to hold, ends the
    /// run there.
    pub fn stop_condition(condition: Condition) -> Self {
        let inclusive = condition.inclusive();
        Self {
            condition,
            trigger: Trigger::Holds { inclusive },
            action: EventAction::StopAt(1),
            max_count: None,
            set: None,
            set_description: None,
            sampling: None,
        }
    }

    /// Which crossings count.
    #[must_use]
    pub fn direction(mut self, direction: Direction) -> Self {
        self.trigger = Trigger::Crossing(direction);
        self
    }

    /// Ends the run at the first occurrence.
    #[must_use]
    pub fn stop(self) -> Self {
        self.stop_at(1)
    }

    /// Ends the run at the `n`-th occurrence (`n ≥ 1`).
    #[must_use]
    pub fn stop_at(mut self, n: u32) -> Self {
        self.action = EventAction::StopAt(n.max(1));
        self
    }

    /// Fires at most `n` times; later crossings are ignored.
    #[must_use]
    pub fn max_count(mut self, n: u32) -> Self {
        self.max_count = Some(n);
        self
    }

    /// Changes the state when the event fires: `f` gets the state at the event and writes the
    /// new `[positions, velocities]` into the slice (which starts as a copy of the old). The run
    /// continues from the changed state.
    #[must_use]
    pub fn set(
        mut self,
        f: impl Fn(&Sample<'_>, &ParticleSystem, &mut [Real]) + Send + Sync + 'static,
    ) -> Self {
        self.set = Some(Arc::new(f));
        self.set_description
            .get_or_insert_with(|| "state change".into());
        self
    }

    /// How densely the event function must be sampled inside a step: `f(y_start, y_end, h)`
    /// returns the number of interior sample points a step of length `h` from state `y_start`
    /// (`[q, v]`) to `y_end` needs so that no zero crossing of this event can fall between
    /// two samples (a contact gap asks for spacing below a fraction of the radii divided by the
    /// relative speed). The run uses the most any event asks for, at least its default.
    #[must_use]
    pub fn sampling(
        mut self,
        f: impl Fn(&[Real], &[Real], Real) -> usize + Send + Sync + 'static,
    ) -> Self {
        self.sampling = Some(Arc::new(f));
        self
    }

    /// The interior samples this event asks for in a step (0 when it has no demand).
    pub(crate) fn samples_needed(&self, y0: &[Real], y1: &[Real], h: Real) -> usize {
        self.sampling.as_ref().map_or(0, |f| f(y0, y1, h))
    }

    /// Describes the state change for reports (`vy = -e*vy`).
    #[must_use]
    pub fn set_description(mut self, description: impl Into<String>) -> Self {
        self.set_description = Some(description.into());
        self
    }

    /// Its name.
    pub fn name(&self) -> &str {
        self.condition.description()
    }

    /// The event function and its description.
    pub fn condition(&self) -> &Condition {
        &self.condition
    }

    /// Whether evaluating `g` needs the forces.
    pub fn needs_forces(&self) -> bool {
        self.condition.needs_forces()
    }

    /// Tests the event only at step ends, unlocated ([`Condition::at_step_ends`]): it fires at
    /// the end of the first step over which its function crossed, not at the crossing.
    #[must_use]
    pub fn at_step_ends(mut self) -> Self {
        self.condition = self.condition.at_step_ends();
        self
    }

    /// Whether it is tested only at step ends.
    pub fn is_checked_at_step_ends(&self) -> bool {
        self.condition.is_checked_at_step_ends()
    }

    /// Whether it is the stop condition of `[stop] when`.
    pub fn is_stop_condition(&self) -> bool {
        matches!(self.trigger, Trigger::Holds { .. })
    }

    /// The state change, if any.
    pub(crate) fn state_change(&self) -> Option<&SetFn> {
        self.set.as_deref()
    }

    /// The description of the state change.
    pub fn state_change_description(&self) -> Option<&str> {
        self.set_description.as_deref()
    }

    /// The side at the start of the run for the value `g` there.
    pub(crate) fn initial_side(&self, g: Real) -> Side {
        match Side::of(g) {
            Some(Side::Zero) if matches!(self.trigger, Trigger::Crossing(_)) => Side::StartZero,
            Some(s) => s,
            None => Side::Unknown,
        }
    }

    /// Whether going from `from` to `to` fires the event.
    pub(crate) fn fires(&self, from: Side, to: Side) -> bool {
        match self.trigger {
            Trigger::Holds { inclusive } => {
                let holds = |s: Side| match s {
                    Side::Pos => true,
                    Side::Zero | Side::StartZero => inclusive,
                    Side::Neg | Side::Unknown => false,
                };
                !holds(from) && holds(to) && from != Side::Unknown
            }
            Trigger::Crossing(d) => d.fires(from, to),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crossings_follow_the_direction() {
        use Side::*;
        let ev = |d| Event::new("g", |_, _| 0.0).direction(d);
        assert!(ev(Direction::Rising).fires(Neg, Pos) && !ev(Direction::Rising).fires(Zero, Pos));
        assert!(ev(Direction::Falling).fires(StartZero, Neg));
        assert!(ev(Direction::Both).initial_side(0.0) == StartZero);
    }

    #[test]
    fn stop_condition_rules() {
        use Side::*;
        let strict = Event::stop_condition(Condition::from_fn("x < 0", false, false, |_, _| 0.0));
        assert!(strict.fires(Neg, Pos) && strict.fires(Zero, Pos));
        assert!(!strict.fires(Neg, Zero));
        let incl = Event::stop_condition(Condition::from_fn("x <= 0", true, false, |_, _| 0.0));
        assert!(incl.fires(Neg, Zero) && !incl.fires(Zero, Pos));
    }
}

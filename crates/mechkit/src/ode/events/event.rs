//! An event of an ODE: a function `g(t, y)` whose zeros mark something happening (a switch of
//! regime, an apex, a turning point), with an optional enclosure of it over a range of times,
//! a direction, and whether it ends the integration.
//!
//! The crossing rules (as for the particles' events, [`crate::simulate::Event`]): the side of an
//! event is the sign of the last non-zero value of `g` seen. A [`Direction::Falling`] event
//! fires when `g` goes from positive to zero or negative, a [`Direction::Rising`] one from
//! negative to zero or positive. Arriving at zero is a crossing, at that exact time; leaving
//! zero afterwards is not, and neither is leaving a zero at the start of the integration.

use std::fmt;

use mechkit_expr::interval::Jet;

use super::find::Side;

use crate::Real;

/// Which zero crossings of an event function count.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Direction {
    /// From negative to zero or positive.
    Rising,
    /// From positive to zero or negative.
    Falling,
    /// Either way.
    #[default]
    Both,
}

impl Direction {
    /// Name as in scenario files.
    pub fn name(self) -> &'static str {
        match self {
            Direction::Rising => "rising",
            Direction::Falling => "falling",
            Direction::Both => "both",
        }
    }

    /// Whether a function going from side `from` to side `to` is a crossing in this
    /// direction: arriving at zero counts, leaving a zero counted already does not, and
    /// leaving a zero at the start counts only where the start's side says so
    /// ([`Side::StartZero`]).
    pub(crate) fn fires(self, from: Side, to: Side) -> bool {
        let rising = matches!(
            (from, to),
            (Side::Neg, Side::Zero | Side::Pos) | (Side::StartZero, Side::Pos)
        );
        let falling = matches!(
            (from, to),
            (Side::Pos, Side::Zero | Side::Neg) | (Side::StartZero, Side::Neg)
        );
        match self {
            Direction::Rising => rising,
            Direction::Falling => falling,
            Direction::Both => rising || falling,
        }
    }

    /// The side an event that fired comes from: positive for a falling one, negative for a
    /// rising one, and for both the side it was on before (`before`).
    pub(crate) fn origin(self, before: Side) -> Side {
        match self {
            Direction::Falling => Side::Pos,
            Direction::Rising => Side::Neg,
            Direction::Both => before,
        }
    }

    /// Looks a direction up by name (`rising`/`up`/`increasing`, `falling`/`down`/`decreasing`,
    /// `both`/`any`).
    pub fn from_name(name: &str) -> Option<Direction> {
        Some(match name.trim().to_ascii_lowercase().as_str() {
            "rising" | "up" | "increasing" | "+" => Direction::Rising,
            "falling" | "down" | "decreasing" | "-" => Direction::Falling,
            "both" | "any" | "either" => Direction::Both,
            _ => return None,
        })
    }
}

type EventFn<'a> = dyn Fn(Real, &[Real]) -> Real + 'a;
type BoundFn<'a> = dyn Fn(Jet, &[Jet]) -> Option<Jet> + 'a;
type ActionFn<'a> = dyn Fn(Real, &mut [Real]) + 'a;

/// An event of an [`OdeSystem`](crate::ode::OdeSystem), found by
/// [`run_to_event`](super::run_to_event).
///
/// The enclosure ([`OdeEvent::bounded_by`]) receives the time and every state component over a
/// range of times inside a step, each as a [`Jet`] (value and time-derivative bounds, from the
/// step's [`StepPolynomial`](crate::ode::StepPolynomial)), and returns a jet of `g` over that
/// range (`None`: it cannot bound it). With it, every sign change of `g` along the step's
/// interpolant is found, however short; without it `g` is sampled at
/// [`SAMPLES`](super::SAMPLES) evenly spaced points per step.
///
/// # Example
/// ```
/// use mechkit::interval::Jet;
/// use mechkit::ode::{Direction, OdeEvent};
/// // the apex of a vertical throw, y = [x, v]: v falls through zero, and the run ends there
/// let apex = OdeEvent::new(|_t, y| y[1])
///     .bounded_by(|_t, y: &[Jet]| Some(y[1]))
///     .direction(Direction::Falling)
///     .terminal();
/// assert!(apex.is_terminal() && apex.is_bounded());
/// assert_eq!(apex.value(0.0, &[0.0, 2.5]), 2.5);
/// ```
pub struct OdeEvent<'a> {
    g: Box<EventFn<'a>>,
    bound: Option<Box<BoundFn<'a>>>,
    action: Option<Box<ActionFn<'a>>>,
    direction: Direction,
    terminal: bool,
}

impl fmt::Debug for OdeEvent<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("OdeEvent")
            .field("bounded", &self.bound.is_some())
            .field("action", &self.action.is_some())
            .field("direction", &self.direction)
            .field("terminal", &self.terminal)
            .finish()
    }
}

impl<'a> OdeEvent<'a> {
    /// An event at the zeros of `g(t, y)`, in both directions, recorded without ending the
    /// integration; refine it with the builder methods.
    pub fn new(g: impl Fn(Real, &[Real]) -> Real + 'a) -> Self {
        Self {
            g: Box::new(g),
            bound: None,
            action: None,
            direction: Direction::Both,
            terminal: false,
        }
    }

    /// An enclosure of `g` from jets of the time and of the state components.
    #[must_use]
    pub fn bounded_by(mut self, bound: impl Fn(Jet, &[Jet]) -> Option<Jet> + 'a) -> Self {
        self.bound = Some(Box::new(bound));
        self
    }

    /// Which crossings count.
    #[must_use]
    pub fn direction(mut self, direction: Direction) -> Self {
        self.direction = direction;
        self
    }

    /// Only crossings from positive to zero or negative count.
    #[must_use]
    pub fn falling(self) -> Self {
        self.direction(Direction::Falling)
    }

    /// Only crossings from negative to zero or positive count.
    #[must_use]
    pub fn rising(self) -> Self {
        self.direction(Direction::Rising)
    }

    /// A change of the state where it fires, `action(t, y)` (a bounce: `y[1] *= -0.8`): the
    /// step is cut there and the integration starts afresh from the changed state
    /// ([`run_events`](super::run_events)).
    #[must_use]
    pub fn action(mut self, action: impl Fn(Real, &mut [Real]) + 'a) -> Self {
        self.action = Some(Box::new(action));
        self
    }

    /// Whether it changes the state where it fires.
    pub fn has_action(&self) -> bool {
        self.action.is_some()
    }

    /// Applies its action, if any, to the state `y` at time `t`.
    pub fn apply(&self, t: Real, y: &mut [Real]) {
        if let Some(action) = &self.action {
            action(t, y);
        }
    }

    /// The integration ends at the first crossing, exactly there.
    #[must_use]
    pub fn terminal(mut self) -> Self {
        self.terminal = true;
        self
    }

    /// Whether it ends the integration.
    pub fn is_terminal(&self) -> bool {
        self.terminal
    }

    /// Whether it has an enclosure.
    pub fn is_bounded(&self) -> bool {
        self.bound.is_some()
    }

    /// Which crossings count.
    pub fn crossing_direction(&self) -> Direction {
        self.direction
    }

    /// `g(t, y)`.
    pub fn value(&self, t: Real, y: &[Real]) -> Real {
        (self.g)(t, y)
    }

    /// The enclosure of `g` from jets of the time and the state, if it has one.
    pub fn enclose(&self, t: Jet, y: &[Jet]) -> Option<Jet> {
        self.bound.as_ref().and_then(|b| b(t, y))
    }

    /// The side of the function's value `g` at the start of an integration: a zero there
    /// is one already counted (leaving it is no crossing).
    pub(super) fn initial_side(g: Real) -> Side {
        Side::of(g).unwrap_or(Side::Unknown)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crossing_rules() {
        let (both, falling, rising) = (Direction::Both, Direction::Falling, Direction::Rising);
        let from_start = |g: Real| OdeEvent::initial_side(g);
        // arriving at zero counts
        assert!(falling.fires(Side::Pos, Side::Zero) && both.fires(Side::Pos, Side::Zero));
        assert!(rising.fires(Side::Neg, Side::Zero) && both.fires(Side::Neg, Side::Zero));
        // only in the direction asked for
        assert!(!falling.fires(Side::Neg, Side::Pos) && !rising.fires(Side::Pos, Side::Neg));
        // leaving zero (at the start, or after firing there) does not
        for d in [both, falling, rising] {
            assert!(!d.fires(from_start(0.0), Side::Pos) && !d.fires(from_start(0.0), Side::Neg));
        }
        assert_eq!(from_start(Real::NAN), Side::Unknown);
        assert!(!both.fires(Side::Unknown, Side::Pos));
    }
}

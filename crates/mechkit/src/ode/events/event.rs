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

/// The side of zero an event function was last seen on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Side {
    Pos,
    Neg,
    /// At zero since the start, or since it fired there.
    Unknown,
}

impl Side {
    /// The side of a value at the start of an integration.
    pub fn of(g: Real) -> Side {
        if g > 0.0 {
            Side::Pos
        } else if g < 0.0 {
            Side::Neg
        } else {
            Side::Unknown
        }
    }

    /// The side after a value `g` that did not fire: a zero (or NaN) keeps the old one.
    pub fn after(self, g: Real) -> Side {
        match Side::of(g) {
            Side::Unknown => self,
            side => side,
        }
    }
}

type EventFn<'a> = dyn Fn(Real, &[Real]) -> Real + 'a;
type BoundFn<'a> = dyn Fn(Jet, &[Jet]) -> Option<Jet> + 'a;

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
    direction: Direction,
    terminal: bool,
}

impl fmt::Debug for OdeEvent<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("OdeEvent")
            .field("bounded", &self.bound.is_some())
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

    /// Whether the value `g` fires the event from `side`.
    pub(super) fn fires(&self, side: Side, g: Real) -> bool {
        let falling = side == Side::Pos && g <= 0.0;
        let rising = side == Side::Neg && g >= 0.0;
        match self.direction {
            Direction::Falling => falling,
            Direction::Rising => rising,
            Direction::Both => falling || rising,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crossing_rules() {
        let both = OdeEvent::new(|_, _| 0.0);
        let falling = OdeEvent::new(|_, _| 0.0).falling();
        let rising = OdeEvent::new(|_, _| 0.0).rising();
        // arriving at zero counts
        assert!(falling.fires(Side::Pos, 0.0) && both.fires(Side::Pos, 0.0));
        assert!(rising.fires(Side::Neg, 0.0) && both.fires(Side::Neg, 0.0));
        // only in the direction asked for
        assert!(!falling.fires(Side::Neg, 1.0) && !rising.fires(Side::Pos, -1.0));
        // leaving zero (at the start, or after firing there) does not
        for e in [&both, &falling, &rising] {
            assert!(!e.fires(Side::Unknown, 1.0) && !e.fires(Side::Unknown, -1.0));
        }
        assert!(!both.fires(Side::Pos, Real::NAN));
        assert_eq!(Side::Pos.after(0.0), Side::Pos);
        assert_eq!(Side::Unknown.after(-2.0), Side::Neg);
    }
}

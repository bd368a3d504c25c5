//! Stop conditions as event functions.

use std::fmt;
use std::sync::Arc;

use crate::Real;
use mechkit_expr::interval::Jet;

use crate::particles::{ParticleSystem, Sample, StateJets};

type EventFn = dyn Fn(&Sample<'_>, &ParticleSystem) -> Real + Send + Sync;
type EncloseFn = dyn Fn(&StateJets<'_>, &ParticleSystem) -> Option<Jet> + Send + Sync;

/// A condition on the state: it holds where its event function `g` is positive (or
/// non-negative, when inclusive). `g` should be continuous where possible (`x < 0` has
/// `g = -x`), so the crossing can be located precisely.
///
/// A condition is located inside steps unless it is marked [`Condition::at_step_ends`]: it is
/// then tested only where a step ends, as a textbook `while` loop tests it.
#[derive(Clone)]
pub struct Condition {
    description: String,
    g: Arc<EventFn>,
    enclosure: Option<Arc<EncloseFn>>,
    inclusive: bool,
    needs_forces: bool,
    step_end: bool,
}

impl fmt::Debug for Condition {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Condition")
            .field("description", &self.description)
            .field("inclusive", &self.inclusive)
            .field("provable", &self.enclosure.is_some())
            .finish_non_exhaustive()
    }
}

impl Condition {
    /// A condition from an event function. `needs_forces` says whether `g` reads
    /// accelerations, energies, work or power (which must then be evaluated at interpolated
    /// states too).
    pub fn from_fn(
        description: impl Into<String>,
        inclusive: bool,
        needs_forces: bool,
        g: impl Fn(&Sample<'_>, &ParticleSystem) -> Real + Send + Sync + 'static,
    ) -> Self {
        Self {
            description: description.into(),
            g: Arc::new(g),
            enclosure: None,
            inclusive,
            needs_forces,
            step_end: false,
        }
    }

    /// The same condition tested only at the ends of steps, unlocated: an event on it fires at
    /// the end of the first step where its function has crossed (a stop condition: the first
    /// step end where it holds), as a textbook `while` loop checks its condition, and may
    /// overshoot the crossing by up to a step. A step cut short by another event's state
    /// change or stop is not a step end for it.
    #[must_use]
    pub fn at_step_ends(mut self) -> Self {
        self.step_end = true;
        self
    }

    /// Whether it is tested only at step ends ([`Condition::at_step_ends`]).
    pub fn is_checked_at_step_ends(&self) -> bool {
        self.step_end
    }

    /// The same condition with an enclosure of its event function: `enclose(j, sys)` bounds
    /// `g` and its time derivative over the times of `j` (or `None` where it cannot), so
    /// that the run can prove where `g` keeps its sign or is monotone inside a step and
    /// never miss a sign change ([`crate::simulate`]'s event guarantee). Without one, `g` is
    /// sampled.
    #[must_use]
    pub fn with_enclosure(
        mut self,
        enclose: impl Fn(&StateJets<'_>, &ParticleSystem) -> Option<Jet> + Send + Sync + 'static,
    ) -> Self {
        self.enclosure = Some(Arc::new(enclose));
        self
    }

    /// Coordinate `axis` of body `body` below `level`.
    pub fn below(body: usize, axis: usize, level: Real) -> Self {
        Self::from_fn(
            format!("body {body} axis {axis} < {level}"),
            false,
            false,
            move |s, sys| level - s.q[body * sys.dim() + axis],
        )
        .with_enclosure(move |j, _| Some(Jet::constant(level) - j.position(body, axis)))
    }

    /// Coordinate `axis` of body `body` above `level`.
    pub fn above(body: usize, axis: usize, level: Real) -> Self {
        Self::from_fn(
            format!("body {body} axis {axis} > {level}"),
            false,
            false,
            move |s, sys| s.q[body * sys.dim() + axis] - level,
        )
        .with_enclosure(move |j, _| Some(j.position(body, axis) - Jet::constant(level)))
    }

    /// Encloses the event function and its time derivative over the times of `j`, when the
    /// condition can.
    pub fn enclose(&self, j: &StateJets<'_>, sys: &ParticleSystem) -> Option<Jet> {
        self.enclosure.as_ref().and_then(|f| f(j, sys))
    }

    /// Whether the event function can be enclosed.
    pub fn is_provable(&self) -> bool {
        self.enclosure.is_some()
    }

    /// What it tests, for reports.
    pub fn description(&self) -> &str {
        &self.description
    }

    /// The event function.
    pub fn value(&self, s: &Sample<'_>, sys: &ParticleSystem) -> Real {
        (self.g)(s, sys)
    }

    /// Whether the condition holds for the function value `g`.
    pub fn holds_for(&self, g: Real) -> bool {
        if self.inclusive { g >= 0.0 } else { g > 0.0 }
    }

    /// Whether the condition also holds where `g = 0` (`<=`, `>=`).
    pub fn inclusive(&self) -> bool {
        self.inclusive
    }

    /// Whether `g` depends on force evaluations.
    pub fn needs_forces(&self) -> bool {
        self.needs_forces
    }
}

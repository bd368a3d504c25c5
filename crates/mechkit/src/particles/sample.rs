//! Everything known about the system at one instant: the state and what follows from it
//! (accelerations, energies, power and accumulated work of each force).

use crate::Real;

/// Quantities derived from a state by evaluating the forces; reused buffers.
#[derive(Debug, Clone, Default)]
pub struct Evaluation {
    /// Acceleration of every coordinate.
    pub a: Vec<Real>,
    /// Power `F·v` of each force (summed over the bodies it acts on).
    pub power: Vec<Real>,
    /// Potential energy of each force; `NaN` for forces without one.
    pub potential: Vec<Real>,
    /// Total kinetic energy.
    pub kinetic: Real,
    /// Sum of the potentials of the conservative forces; `None` if no force has one.
    pub potential_total: Option<Real>,
    /// Net force of each force summed over the bodies it acts on, `dim` components per force
    /// (zero for an internal force between bodies, which obeys Newton's third law).
    pub net: Vec<Real>,
    /// Total momentum `Σ m v`, `dim` components.
    pub momentum: Vec<Real>,
    /// What each constraint force (joint) reports, 5 values per force
    /// ([`crate::rigid::mechanism::REPORT_FIELDS`]); NaN for the other forces. Empty when the
    /// system has no constraints.
    pub constraint: Vec<Real>,
    /// Rotational kinetic energy `Σ ½ I ω²` of the rigid bodies (0 without any).
    pub kinetic_rotation: Real,
}

/// The state at one instant with its derived quantities, as passed to observers.
#[derive(Debug, Clone, Copy)]
pub struct Sample<'a> {
    /// Index of the step that produced this sample (0 for the initial state).
    pub step: u64,
    /// Time.
    pub t: Real,
    /// Positions.
    pub q: &'a [Real],
    /// Velocities.
    pub v: &'a [Real],
    /// Accelerations, power and energies here.
    pub eval: &'a Evaluation,
    /// Work done by each force from the start until now.
    pub work: &'a [Real],
    /// What kind of instant this is.
    pub kind: SampleKind,
}

/// Where a sample comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SampleKind {
    /// The state at the end of a step (or the initial state, step 0).
    Step,
    /// A located event: a state interpolated inside a step (or a step's end, when the event is
    /// exactly there), before or after the event's state change.
    Event,
    /// A requested output time (`[output] interval`), interpolated inside a step.
    Grid,
}

impl SampleKind {
    /// Whether it is the end of a step.
    pub fn is_step(self) -> bool {
        self == SampleKind::Step
    }
}

impl Sample<'_> {
    /// Total mechanical energy `K + U` (just `K` without potentials).
    pub fn energy(&self) -> Real {
        self.eval.kinetic + self.eval.potential_total.unwrap_or(0.0)
    }
}

//! The particles' events for the one event finder ([`crate::ode::events::find`]): how an
//! [`Event`] is enclosed over a range of a step ([`Condition::enclose`], on the state's jets
//! read off the step's interpolant) and evaluated inside it (on the engine's interpolant, with
//! the forces evaluated there when a function reads them), and which changes of side fire it.
//!
//! With an enclosure, every sign change of odd multiplicity of an event function along the
//! interpolant is found, in time order, however short the excursion and however many per
//! step; a zero of even multiplicity (a touch) does not fire. Functions that read the forces
//! (accelerations, potential energy, power, and the work in fixed-step runs) cannot be
//! enclosed: they are sampled at evenly spaced points, as is a step that would need more than
//! [`MAX_BOUNDS`](crate::ode::MAX_BOUNDS) enclosures for one event (with a warning).
//!
//! [`Condition::enclose`]: super::Condition::enclose

use mechkit_expr::interval::{Interval, Jet};

use super::event::Event;
use super::probe::{Probe, Step, event_values};
use super::run::sample_of;
use crate::Real;
use crate::ode::events::find::{Bounds, FALLBACK_SAMPLES, Rules, Side};
use crate::ode::{MAX_BOUNDS, StepPolynomial};
use crate::particles::{ParticleSystem, SampleKind, StateJets};

/// The warning for an event whose proof ran out of enclosures in the step from `t0`.
pub(crate) fn ran_out_warning(event: &Event, t0: Real) -> String {
    format!(
        "the event `{}` could not be bounded in the step at t = {} s (it needed more than {MAX_BOUNDS} bounds, or its value is not a number there); there it is sampled at {FALLBACK_SAMPLES} points, so a sign change between two samples may be missed; smaller steps (dt, or h_max) make the bounds tighter",
        event.name(),
        crate::error::short(t0)
    )
}

/// What the proofs need of the run.
pub(crate) struct Proving<'a> {
    pub events: &'a [Event],
    pub enabled: &'a [bool],
    pub sys: &'a ParticleSystem,
    /// Whether the interpolant carries the work of each force (adaptive runs).
    pub work: bool,
    /// The states `[q, v]` at the step's start and end, and its length (for the samples an
    /// unproven event asks for: [`Event::samples_needed`]).
    pub ends: (&'a [Real], &'a [Real], Real),
}

impl Bounds for Proving<'_> {
    fn count(&self) -> usize {
        self.events.len()
    }

    fn enabled(&self, i: usize) -> bool {
        self.enabled[i]
    }

    fn provable(&self, i: usize) -> bool {
        self.events[i].condition().is_provable()
    }

    fn enclose(&mut self, i: usize, poly: &StepPolynomial, s: Interval) -> Option<Jet> {
        let (dim, mass) = (self.sys.dim(), self.sys.masses());
        let dof = crate::ode::SecondOrderSystem::dof(self.sys);
        self.events[i].condition().enclose(
            &StateJets::new(poly, s, dim, mass, dof, self.work),
            self.sys,
        )
    }

    fn samples_asked(&self, i: usize) -> usize {
        let (y0, y1, h) = self.ends;
        self.events[i].samples_needed(y0, y1, h)
    }
}

/// The events inside the step just taken, evaluated on the engine's interpolant.
pub(crate) struct Sampling<'s, 'r, 'a> {
    pub events: &'a [Event],
    pub enabled: &'s [bool],
    pub step: Step<'r, 'a>,
    pub probe: &'s mut Probe,
    pub evaluations: &'s mut u64,
    /// Whether an event function reads the forces (each sample then costs an evaluation).
    pub forces: bool,
    /// The run's step count, for the samples.
    pub steps: u64,
}

impl Rules for Sampling<'_, '_, '_> {
    fn count(&self) -> usize {
        self.events.len()
    }

    fn enabled(&self, i: usize) -> bool {
        self.enabled[i]
    }

    fn fires(&self, i: usize, from: Side, to: Side) -> bool {
        self.events[i].fires(from, to)
    }

    fn values(&mut self, _: &StepPolynomial, t: Real, out: &mut [Real]) {
        let probe = &mut *self.probe;
        self.step.probe(probe, t, self.forces, self.evaluations);
        let s = sample_of(
            self.steps,
            &probe.state,
            &probe.eval,
            &probe.work,
            SampleKind::Event,
        );
        event_values(self.events, &s, self.step.sys, out);
    }
}

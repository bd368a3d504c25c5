//! The events of one step, in time order: the points at which the scan must look (proven by
//! `simulate/prove.rs`, or as densely as contacts ask), the scan from the last firing to the
//! step's end, and each firing in turn until one cuts the step or none is left.

use crate::Real;
use crate::particles::SampleKind;
use crate::simulate::observe::Observer;
use crate::simulate::probe::{Step, event_values};
use crate::simulate::prove::Proving;
use crate::simulate::report::SimulateError;
use crate::simulate::run::sample_of;
use crate::simulate::scan::{Fired, scan};
use crate::simulate::stepping::Engine;

use super::fire::AfterFiring;
use super::run::Run;

/// How the events of a step leave it.
pub(super) enum StepEnd {
    /// A firing cut the step short: the run goes on from the event (or ends there).
    Cut,
    /// The step goes on to its end, whose sample is of this kind (an event recorded exactly
    /// at the end makes it an event sample).
    Finish(SampleKind),
}

impl Run<'_> {
    /// Finds and handles the events of the step just taken, in time order.
    pub fn events_in_step(
        &mut self,
        observers: &mut [&mut dyn Observer],
    ) -> Result<StepEnd, SimulateError> {
        if self.any_enabled() {
            self.prove_points();
        }
        let mut t_scan = self.ends.t0;
        self.g_scan.clone_from(&self.g_a);
        self.sides_scan.clone_from(&self.sides);
        // (no events: nothing to scan)
        while self.any_enabled() {
            let Some(fired) = self.scan_from(t_scan) else {
                // the sides at the step's end (`sides_scan` is set afresh for the next step)
                std::mem::swap(&mut self.sides, &mut self.sides_scan);
                break;
            };
            match self.fire(observers, fired)? {
                AfterFiring::Cut => return Ok(StepEnd::Cut),
                AfterFiring::AtStepEnd => return Ok(StepEnd::Finish(SampleKind::Event)),
                AfterFiring::ScanFrom(t) => t_scan = t,
            }
        }
        Ok(StepEnd::Finish(SampleKind::Step))
    }

    /// Whether any event can still fire.
    fn any_enabled(&self) -> bool {
        self.book.enabled.iter().any(|e| *e)
    }

    /// The times inside the step at which the event functions are sampled: those that prove
    /// no sign change is missed, and, for events that cannot be proven, evenly spaced ones
    /// (as many as contacts ask for).
    fn prove_points(&mut self) {
        let (t_a, t_b) = (self.ends.t0, self.ends.t1);
        if self.any_provable {
            self.engine
                .step_polynomial(&self.ws, &self.ends, &mut self.prover.poly);
        } else {
            self.prover.poly.reset(t_a, t_b - t_a, 0, 1);
        }
        let proving = Proving {
            events: self.events,
            enabled: &self.book.enabled,
            sys: self.sys,
            work: matches!(self.engine, Engine::Adaptive { .. }),
            default_interior: self.interior,
            ends: (&self.ends.y0, &self.state.y),
        };
        self.prover
            .points(&proving, &mut self.scan_points, &mut self.warnings);
    }

    /// The first firing in the step after `t_scan` (where the event functions are `g_scan`
    /// and the sides `sides_scan`), if any.
    fn scan_from(&mut self, t_scan: Real) -> Option<Fired> {
        let mut step = Step {
            sys: self.sys,
            ws: &self.ws,
            engine: &mut self.engine,
            ends: &self.ends,
            ledger: &self.ledger,
        };
        let (events, sys, steps) = (self.events, self.sys, self.steps);
        let (probe, evaluations) = (&mut self.probe, &mut self.evaluations);
        let forces = self.forces_for_events;
        let mut values = |t: Real, out: &mut [Real]| {
            step.probe(probe, t, forces, evaluations);
            let s = sample_of(
                steps,
                &probe.state,
                &probe.eval,
                &probe.work,
                SampleKind::Event,
            );
            event_values(events, &s, sys, out);
        };
        scan(
            events,
            &self.book.enabled,
            &mut self.sides_scan,
            (t_scan, &self.g_scan),
            (self.ends.t1, &self.g_b),
            &self.scan_points,
            &mut values,
            &mut self.scan_buffers,
        )
    }
}

//! The events of one step, in time order, through the one event finder
//! ([`crate::ode::events::find`], with the particles' events as `simulate/prove.rs` gives
//! them): the points at which the scan must look, the scan from the last firing to the step's
//! end, and each firing in turn until one cuts the step or none is left.

use crate::Real;
use crate::ode::events::find::Fired;
use crate::particles::SampleKind;
use crate::simulate::observe::Observer;
use crate::simulate::probe::Step;
use crate::simulate::prove::{Proving, Sampling, ran_out_warning};
use crate::simulate::report::SimulateError;
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
                .step_polynomial(&self.ws, &self.ends, &mut self.finder.poly);
        } else {
            self.finder.poly.reset(t_a, t_b - t_a, 0, 1);
        }
        let mut proving = Proving {
            events: self.events,
            enabled: &self.book.enabled,
            sys: self.sys,
            work: matches!(self.engine, Engine::Adaptive { .. }),
            ends: (&self.ends.y0, &self.state.y, t_b - t_a),
        };
        let (events, warned, warnings) = (self.events, &mut self.warned, &mut self.warnings);
        self.finder
            .plan(&mut proving, t_b, self.interior, &mut |i| {
                if !warned[i] {
                    warned[i] = true;
                    warnings.push(ran_out_warning(&events[i], t_a));
                }
            });
    }

    /// The first firing in the step after `t_scan` (where the event functions are `g_scan`
    /// and the sides `sides_scan`), if any.
    fn scan_from(&mut self, t_scan: Real) -> Option<Fired> {
        let mut sampling = Sampling {
            events: self.events,
            enabled: &self.book.enabled,
            step: Step {
                sys: self.sys,
                ws: &self.ws,
                engine: &mut self.engine,
                ends: &self.ends,
                ledger: &self.ledger,
            },
            probe: &mut self.probe,
            evaluations: &mut self.evaluations,
            forces: self.forces_for_events,
            steps: self.steps,
        };
        self.finder.first_firing(
            &mut sampling,
            &mut self.sides_scan,
            (t_scan, &self.g_scan),
            (self.ends.t1, &self.g_b),
        )
    }
}

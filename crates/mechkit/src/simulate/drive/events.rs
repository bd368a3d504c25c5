//! The particles' run on the one event-aware loop ([`crate::ode::events::drive`]): the
//! [`Model`] that hands the loop's turns to the `Run`, and the events of one step through the
//! one event finder ([`crate::ode::events::find`], with the particles' events as
//! `simulate/prove.rs` gives them): the points at which the scan must look, and the scan from
//! the last firing to the step's end.
//!
//! Events checked at step ends only ([`Event::at_step_ends`](crate::simulate::Event::at_step_ends))
//! are hidden from the finder: they are neither proven nor sampled inside a step. When the scan
//! reaches the step's end, each fires if going from its side at the last step end to its side
//! at this one fires it, together with any located event firing there.

use crate::Real;
use crate::ode::events::drive::{AfterFiring, Model};
use crate::ode::events::find::{Fired, Firing};
use crate::particles::SampleKind;
use crate::simulate::observe::Observer;
use crate::simulate::probe::Step;
use crate::simulate::prove::{Proving, Sampling, ran_out_warning};
use crate::simulate::report::SimulateError;
use crate::simulate::stepping::Engine;

use super::run::Run;

/// A particles' run with its observers, on the one event-aware loop.
pub(super) struct Particles<'m, 'r, 'o> {
    pub run: &'m mut Run<'r>,
    pub observers: &'m mut [&'o mut dyn Observer],
}

impl Model for Particles<'_, '_, '_> {
    type Error = SimulateError;

    fn ended(&self) -> bool {
        self.run.stop_reason.is_some()
    }

    fn stops_before_step(&mut self) -> bool {
        self.run.stops_before_step(self.observers)
    }

    fn fast_forward(&mut self) -> bool {
        self.run.fused_chunk(self.observers)
    }

    fn advance(&mut self) -> Result<bool, SimulateError> {
        self.run.advance()
    }

    fn any_enabled(&self) -> bool {
        self.run.book.enabled.iter().any(|e| *e)
    }

    fn plan(&mut self) {
        self.run.prove_points();
    }

    fn begin_scan(&mut self) -> Real {
        let run = &mut *self.run;
        run.g_scan.clone_from(&run.g_a);
        run.sides_scan.clone_from(&run.sides);
        run.ends.t0
    }

    fn scan_from(&mut self, t_scan: Real) -> Option<Fired> {
        self.run.scan_from(t_scan)
    }

    fn end_scan(&mut self) {
        // the sides at the step's end (`sides_scan` is set afresh for the next step)
        std::mem::swap(&mut self.run.sides, &mut self.run.sides_scan);
    }

    fn fire(&mut self, fired: Fired) -> Result<AfterFiring, SimulateError> {
        self.run.fire(self.observers, fired)
    }

    fn finish_step(&mut self, event_at_end: bool) -> Result<(), SimulateError> {
        let kind = if event_at_end {
            SampleKind::Event
        } else {
            SampleKind::Step
        };
        self.run.finish_step(self.observers, kind)
    }
}

impl Run<'_> {
    /// The times inside the step at which the event functions are sampled: those that prove
    /// no sign change is missed, and, for events that cannot be proven, evenly spaced ones
    /// (as many as contacts ask for).
    pub fn prove_points(&mut self) {
        self.refresh_located();
        let (t_a, t_b) = (self.ends.t0, self.ends.t1);
        if self.any_provable {
            self.engine
                .step_polynomial(&self.ws, &self.ends, &mut self.finder.poly);
        } else {
            self.finder.poly.reset(t_a, t_b - t_a, 0, 1);
        }
        let mut proving = Proving {
            events: self.events,
            enabled: &self.located,
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
    /// and the sides `sides_scan`), if any: of the located events, and at the step's end of
    /// the events checked there.
    pub fn scan_from(&mut self, t_scan: Real) -> Option<Fired> {
        self.refresh_located();
        let located = self.locate_from(t_scan);
        if self.step_end_events.is_empty() {
            return located;
        }
        let t_b = self.ends.t1;
        match located {
            Some(fired) if fired.firing.t < t_b => Some(fired),
            Some(mut fired) => {
                let list = &mut fired.firing.events;
                list.extend(self.at_step_end());
                list.sort_unstable();
                list.dedup();
                Some(fired)
            }
            None => {
                let events = self.at_step_end();
                (!events.is_empty()).then(|| Fired {
                    firing: Firing { t: t_b, events },
                    values: self.g_b.clone(),
                })
            }
        }
    }

    /// The events checked at step ends that fire at the end of this step: from their sides at
    /// the last step end (`sides`) to their values here (`g_b`).
    fn at_step_end(&self) -> Vec<usize> {
        self.step_end_events
            .iter()
            .copied()
            .filter(|&i| {
                self.book.enabled[i]
                    && self.events[i].fires(self.sides[i], self.sides[i].after(self.g_b[i]))
            })
            .collect()
    }

    /// The first firing of a located event in the step after `t_scan`.
    fn locate_from(&mut self, t_scan: Real) -> Option<Fired> {
        let mut sampling = Sampling {
            events: self.events,
            enabled: &self.located,
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

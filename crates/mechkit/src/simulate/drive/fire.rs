//! One firing inside a step: the output times before it, the state at it, its entry in the
//! book, and what it does to the run: end it there, apply the state changes and go on from the
//! new state (with the events re-armed and the engine restarted), or only record it and scan
//! on.

use crate::Real;
use crate::ode::events::drive::AfterFiring;
use crate::ode::events::find::{Fired, Side};
use crate::particles::SampleKind;
use crate::simulate::book::EventBook;
use crate::simulate::observe::Observer;
use crate::simulate::probe::{Step, emit, event_values};
use crate::simulate::rearm::{sides_after_change, values_ahead};
use crate::simulate::report::{SimulateError, StopReason};
use crate::simulate::run::sample_of;
use crate::simulate::stepping::Engine;

use super::run::Run;

impl Run<'_> {
    /// Handles the events that fire together at `fired.firing.t`.
    pub fn fire(
        &mut self,
        observers: &mut [&mut dyn Observer],
        fired: Fired,
    ) -> Result<AfterFiring, SimulateError> {
        let Fired { firing, values } = fired;
        let te = firing.t;
        self.state_at(observers, te)?;
        let outcome = self.book.fire(
            self.events,
            &firing.events,
            te,
            &self.probe.state.y,
            (self.ends.t0, &self.ends.y0),
            (self.ends.t1, &self.state.y),
            self.step_scale,
            self.steps,
            &mut self.warnings,
        );
        if outcome.failure.is_some() {
            self.failure = outcome.failure;
        }
        let stop_here = outcome.stop.is_some();
        if stop_here {
            self.stop_reason = outcome.stop;
        }
        if stop_here || !outcome.setters.is_empty() {
            // the run continues from (or ends at) the event: the rest of the step is dropped
            self.cut_at(observers, te)?;
            if !stop_here {
                self.change_state(observers, te, (&firing.events, &outcome.setters), &values)?;
            }
            return Ok(AfterFiring::Cut);
        }
        // recorded only: show it and look further in the same step
        self.record(observers, te, &firing.events, &values)
    }

    /// Passes the observers the output times before `te`, and puts the state at `te` in the
    /// probe.
    fn state_at(
        &mut self,
        observers: &mut [&mut dyn Observer],
        te: Real,
    ) -> Result<(), SimulateError> {
        let mut step = Step {
            sys: self.sys,
            ws: &self.ws,
            engine: &mut self.engine,
            ends: &self.ends,
            ledger: &self.ledger,
        };
        if let Some(grid) = &mut self.grid {
            grid.emit_until(
                &mut step,
                &mut self.probe,
                te,
                false,
                self.steps,
                &mut self.evaluations,
                observers,
            )?;
        }
        let probe = &mut self.probe;
        if te == self.ends.t1 {
            probe.state.t = self.ends.t1;
            probe.state.y.clone_from(&self.state.y);
            probe.eval.clone_from(&self.eval_b);
            probe.work.clone_from(&self.work_b);
        } else if te == self.ends.t0 {
            // the ledger has not moved since the step's start: its work is the work there
            probe.state.t = self.ends.t0;
            probe.state.y.clone_from(&self.ends.y0);
            probe.eval.clone_from(&self.eval_a);
            probe.work.clear();
            probe.work.extend_from_slice(self.ledger.work());
        } else {
            step.probe(probe, te, true, &mut self.evaluations);
        }
        Ok(())
    }

    /// Ends the step at `te` (the state in the probe): the ledger up to it, the sample there,
    /// and the run's state at it.
    fn cut_at(
        &mut self,
        observers: &mut [&mut dyn Observer],
        te: Real,
    ) -> Result<(), SimulateError> {
        let probe = &self.probe;
        match &self.engine {
            Engine::Fixed { .. } => self.ledger.advance(te, &probe.eval),
            Engine::Adaptive { .. } => self.ledger.set(te, &probe.eval, &probe.work),
        }
        if te != self.ends.t0 {
            let work = self.ledger.work();
            let at = sample_of(
                self.steps,
                &probe.state,
                &probe.eval,
                work,
                SampleKind::Event,
            );
            emit(observers, &at)?;
        }
        self.state.t = te;
        self.state.y.clone_from(&probe.state.y);
        self.eval_a.clone_from(&probe.eval);
        Ok(())
    }

    /// Applies the state changes of `setters` (of the `fired` events, whose functions were
    /// `at_values` at the event) to the state at `te`, in declaration order, each seeing the
    /// state at the event; then the run goes on from the new state. A change that makes the
    /// state non-finite ends the run there instead.
    fn change_state(
        &mut self,
        observers: &mut [&mut dyn Observer],
        te: Real,
        (fired, setters): (&[usize], &[usize]),
        at_values: &[Real],
    ) -> Result<(), SimulateError> {
        let kind = SampleKind::Event;
        let probe = &self.probe;
        let pre = sample_of(
            self.steps,
            &probe.state,
            &probe.eval,
            self.ledger.work(),
            kind,
        );
        if let Err(d) = EventBook::apply(self.events, setters, &pre, self.sys, &mut self.state.y) {
            self.failure = Some(d);
            self.state.y.clone_from(&probe.state.y);
            self.stop_reason = Some(StopReason::Diverged);
            return Ok(());
        }
        self.evaluate_here();
        self.evaluations += 1;
        self.ledger.jump(&self.eval_a);
        self.book.changed(self.events, setters, te, &self.state.y);
        let post = sample_of(
            self.steps,
            &self.state,
            &self.eval_a,
            self.ledger.work(),
            kind,
        );
        emit(observers, &post)?;
        event_values(self.events, &post, self.sys, &mut self.g_a);
        // a stop condition that the change itself makes true (a joint letting go, a mode
        // switched) ends the run at the change, as it would have at a crossing
        let stop = (0..self.events.len()).find(|&i| {
            let c = self.events[i].condition();
            self.events[i].is_stop_condition()
                && self.book.enabled[i]
                && !c.holds_for(at_values[i])
                && c.holds_for(self.g_a[i])
        });
        if let Some(i) = stop {
            let outcome = self.book.fire(
                self.events,
                &[i],
                te,
                &self.state.y,
                (self.ends.t0, &self.ends.y0),
                (te, &self.state.y),
                self.step_scale,
                self.steps,
                &mut self.warnings,
            );
            self.stop_reason = outcome.stop.or(Some(StopReason::Event));
            return Ok(());
        }
        self.rearm(te, fired, at_values);
        Ok(())
    }

    /// After a state change at `te`: the sides of the events from the new state (`fired`
    /// re-armed when the change turned their function back), and the engine restarted there.
    fn rearm(&mut self, te: Real, fired: &[usize], at_values: &[Real]) {
        let last_step_end = (!self.step_end_events.is_empty()).then(|| self.sides.clone());
        values_ahead(
            (self.events, fired),
            self.sys,
            (&self.state, &self.eval_a, self.ledger.work()),
            self.step_scale,
            self.steps,
            &mut self.probe,
            &mut self.evaluations,
            &mut self.g_b,
        );
        sides_after_change(
            self.events,
            fired,
            &self.sides_scan,
            (at_values, &self.g_a, &self.g_b),
            &mut self.sides,
        );
        if let Some(before) = last_step_end {
            // events checked at step ends: a change at the step's end is seen from the new
            // state; a step cut short inside is no step end, so they keep their last sides
            let at_end = te == self.ends.t1;
            for &i in &self.step_end_events {
                self.sides[i] = if at_end {
                    before[i].after(self.g_a[i])
                } else {
                    before[i]
                };
            }
        }
        self.engine.restart(&self.state, self.ledger.work());
        self.hand_over();
        self.fixed_origin = te;
        self.fixed_k = 0;
        self.planned = self.planned_from(te);
    }

    /// Records a firing that changes nothing (the `fired` events, whose functions are
    /// `at_values` at `te`): at the step's end the step finishes as usual; inside it, its
    /// sample goes to the observers and the scan goes on from it.
    fn record(
        &mut self,
        observers: &mut [&mut dyn Observer],
        te: Real,
        fired: &[usize],
        at_values: &[Real],
    ) -> Result<AfterFiring, SimulateError> {
        if te == self.ends.t1 {
            let before = self.sides_scan.iter().zip(&self.g_b);
            for (i, (side, (scanned, g))) in self.sides.iter_mut().zip(before).enumerate() {
                // an event checked at step ends keeps the side it fired to: it fires again only
                // after a step end on the other side
                *side = if fired.contains(&i) && !self.events[i].is_checked_at_step_ends() {
                    Side::Zero
                } else {
                    scanned.after(*g)
                };
            }
            return Ok(AfterFiring::AtStepEnd);
        }
        if te != self.ends.t0 {
            let probe = &self.probe;
            let at = sample_of(
                self.steps,
                &probe.state,
                &probe.eval,
                &probe.work,
                SampleKind::Event,
            );
            emit(observers, &at)?;
        }
        for (i, (side, g)) in self.sides_scan.iter_mut().zip(at_values).enumerate() {
            *side = if fired.contains(&i) {
                Side::Zero
            } else {
                side.after(*g)
            };
        }
        self.g_scan.copy_from_slice(at_values);
        Ok(AfterFiring::ScanFrom(te))
    }
}

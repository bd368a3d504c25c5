//! Advancing the run: a chunk of silent steps in the fused kernel, one step of the engine
//! (fixed or adaptive, with the diagnosis of a step that fails), and the end of a step that no
//! event cut short (the output times in it, the ledger, the step's sample).

use crate::Real;
use crate::ode::AdaptiveError;
use crate::particles::SampleKind;
use crate::simulate::diagnose::{diagnose_state, step_failure};
use crate::simulate::fused::{MIN_CHUNK, chunk_len};
use crate::simulate::observe::Observer;
use crate::simulate::probe::{Step, emit, event_values};
use crate::simulate::report::{SimulateError, StopReason};
use crate::simulate::run::sample_of;
use crate::simulate::stepping::{Engine, fixed_next};

use super::run::Run;

impl Run<'_> {
    /// Runs the next silent steps (those no observer looks at) in the fused kernel, when the
    /// run has one and there are enough of them; returns whether it did. A chunk that went
    /// non-finite is dropped, and its steps are left to the general loop.
    pub fn fused_chunk(&mut self, observers: &[&mut dyn Observer]) -> bool {
        let Some(kernel) = &mut self.fused else {
            return false;
        };
        if self.steps == 0 || self.steps < self.fuse_resumes_at {
            return false;
        }
        let chunk = chunk_len(
            observers,
            self.steps,
            self.limit,
            self.planned,
            self.fixed_k,
        );
        if chunk < MIN_CHUNK {
            return false;
        }
        let a = std::mem::take(&mut self.eval_a.a);
        let finite = kernel.advance(
            &mut self.state,
            &mut self.fixed_k,
            &a,
            &mut self.ledger,
            &mut self.step_range,
            chunk,
        );
        self.eval_a.a = a;
        if !finite {
            self.fuse_resumes_at = self.steps + chunk + 1;
            return false;
        }
        self.steps += chunk;
        self.evaluations += chunk;
        self.fused_steps += chunk;
        self.evaluate_here();
        self.ledger.end_at(&self.eval_a);
        self.hand_over();
        self.check_evaluation();
        true
    }

    /// Takes one step from the current state and evaluates its end (`ends`, `eval_b`,
    /// `work_b`, `g_b`). Returns whether it failed: the run then stops with a diagnosis, at
    /// the step's start.
    pub fn advance(&mut self) -> Result<bool, SimulateError> {
        let t_a = self.state.t;
        self.ends.t0 = t_a;
        self.ends.y0.clone_from(&self.state.y);
        if self.interpolates {
            self.ends.a0.clone_from(&self.eval_a.a);
        }
        if let Engine::Fixed { .. } = self.engine {
            self.fixed_step(t_a)?;
        } else if !self.adaptive_step(t_a) {
            return Ok(true);
        }
        self.steps += 1;
        let h_taken = self.state.t - t_a;
        self.step_range = (
            self.step_range.0.min(h_taken),
            self.step_range.1.max(h_taken),
        );
        if self.step_scale.is_nan() {
            self.step_scale = h_taken;
        }
        if !self.state.is_finite() {
            let d = diagnose_state(self.sys, &self.ends.y0, &self.state, t_a, self.steps - 1);
            self.failure = Some(d);
            self.state.y.copy_from_slice(&self.ends.y0);
            self.state.t = t_a;
            self.stop_reason = Some(StopReason::Diverged);
            return Ok(true);
        }
        self.evaluate_end();
        Ok(false)
    }

    /// One fixed step from `t_a`, on the grid of fixed steps (landing on `t_max`).
    fn fixed_step(&mut self, t_a: Real) -> Result<(), SimulateError> {
        let Engine::Fixed { stepper, dt } = &mut self.engine else {
            unreachable!("a fixed step of an adaptive engine")
        };
        let t_next = fixed_next(
            self.fixed_origin,
            self.fixed_k,
            *dt,
            self.planned,
            self.sim.t_max,
        );
        let info = stepper.step(self.sys, &mut self.state, t_next - t_a)?;
        self.evaluations += info.evaluations as u64;
        self.state.t = t_next;
        self.fixed_k += 1;
        Ok(())
    }

    /// One adaptive step from `t_a` (the work of the forces in `work_b`, the evaluation at its
    /// end in `eval_b`). Returns whether it was taken: a step that became too small stops the
    /// run with a diagnosis, at `t_a`.
    fn adaptive_step(&mut self, t_a: Real) -> bool {
        let t_bound = self.sim.t_max.unwrap_or(Real::INFINITY);
        let before = self.engine.adaptive_stats().map_or(0, |s| s.evaluations);
        let result =
            self.engine
                .adaptive_step(&self.ws, &mut self.state, &mut self.work_b, t_bound);
        self.evaluations += self.engine.adaptive_stats().map_or(0, |s| s.evaluations) - before;
        if let Err(AdaptiveError::StepTooSmall {
            t,
            h,
            h_min,
            component,
            non_finite,
        }) = result
        {
            self.state.t = t_a;
            self.state.y.copy_from_slice(&self.ends.y0);
            let bad = self.ws.bad.borrow_mut().take();
            let (reason, d) = step_failure(
                self.sys,
                bad.as_ref(),
                (t, h, h_min, component, non_finite),
                self.steps,
                &mut self.scratch,
            );
            self.failure = Some(d);
            self.stop_reason = Some(reason);
            return false;
        }
        self.ws.take_last(&mut self.eval_b);
        true
    }

    /// The end of the step just taken: the evaluation there (for a fixed step; an adaptive
    /// step brought its own), the step's ends for the interpolant, and the event functions.
    fn evaluate_end(&mut self) {
        let t_b = self.state.t;
        if let Engine::Fixed { .. } = self.engine {
            let (q, v) = self.state.qv();
            self.sys
                .evaluate(t_b, q, v, &mut self.eval_b, &mut self.scratch);
            self.evaluations += 1;
            if !self.events.is_empty() {
                self.ledger
                    .preview_into(t_b, &self.eval_b.power, &mut self.work_b);
            }
        }
        self.ends.t1 = t_b;
        if self.interpolates {
            self.ends.y1.clone_from(&self.state.y);
            self.ends.a1.clone_from(&self.eval_b.a);
        }
        if !self.events.is_empty() {
            let at_b = sample_of(
                self.steps,
                &self.state,
                &self.eval_b,
                &self.work_b,
                SampleKind::Step,
            );
            event_values(self.events, &at_b, self.sys, &mut self.g_b);
        }
    }

    /// Finishes a step no event cut short: the output times up to its end, the ledger, and
    /// the sample at its end (of `kind`: an event recorded at the end makes it an event
    /// sample); its end becomes the start of the next.
    pub fn finish_step(
        &mut self,
        observers: &mut [&mut dyn Observer],
        kind: SampleKind,
    ) -> Result<(), SimulateError> {
        let t_b = self.ends.t1;
        if let Some(grid) = &mut self.grid {
            let mut step = Step {
                sys: self.sys,
                ws: &self.ws,
                engine: &mut self.engine,
                ends: &self.ends,
                ledger: &self.ledger,
            };
            grid.emit_until(
                &mut step,
                &mut self.probe,
                t_b,
                true,
                self.steps,
                &mut self.evaluations,
                observers,
            )?;
        }
        match &self.engine {
            Engine::Fixed { .. } => self.ledger.advance(t_b, &self.eval_b),
            Engine::Adaptive { .. } => self.ledger.set(t_b, &self.eval_b, &self.work_b),
        }
        let end = sample_of(
            self.steps,
            &self.state,
            &self.eval_b,
            self.ledger.work(),
            kind,
        );
        emit(observers, &end)?;
        std::mem::swap(&mut self.eval_a, &mut self.eval_b);
        std::mem::swap(&mut self.g_a, &mut self.g_b);
        self.hand_over();
        self.check_evaluation();
        Ok(())
    }
}

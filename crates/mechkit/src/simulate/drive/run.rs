//! The run loop and the state it carries from step to step (`Run`): how a run starts (the
//! first sample, a stop condition that already holds, the output times, the fused kernel),
//! the loop itself, and the report it ends with.

use crate::Real;
use crate::energy::EnergyLedger;
use crate::ode::events::find::{Finder, Side};
use crate::ode::{State, steps_to_cover};
use crate::particles::{Evaluation, ParticleSystem, SampleKind};
use crate::simulate::book::EventBook;
use crate::simulate::diagnose::diagnose_evaluation;
use crate::simulate::event::Event;
use crate::simulate::fused::Fused;
use crate::simulate::halt::stop_before_step;
use crate::simulate::observe::Observer;
use crate::simulate::probe::{Grid, Probe, emit, event_values};
use crate::simulate::report::{Divergence, RunReport, SimulateError, StopReason};
use crate::simulate::run::{Simulation, sample_of};
use crate::simulate::stepping::{Engine, StepEnds, Stepping, WorkSystem, step_budget};

use super::events::Particles;

/// Runs `sim` from `initial`, passing every sample to `observers`.
pub(in crate::simulate) fn drive(
    sim: &Simulation<'_>,
    initial: State,
    observers: &mut [&mut dyn Observer],
) -> Result<RunReport, SimulateError> {
    let mut run = Run::start(sim, initial, observers)?;
    crate::ode::events::drive::drive(&mut Particles {
        run: &mut run,
        observers,
    })?;
    run.report(observers)
}

/// A run under way: what it steps with, the state and what was evaluated at both ends of the
/// current step, the ledger, the events' book and sides, the output times, the counters, and
/// the buffers reused from step to step.
pub(super) struct Run<'r> {
    pub sim: &'r Simulation<'r>,
    pub sys: &'r ParticleSystem,
    pub events: &'r [Event],
    /// The run's stepping, with the error components of an adaptive run filled in.
    pub stepping: Stepping,
    pub ws: WorkSystem<'r>,
    pub engine: Engine,
    /// The step budget.
    pub limit: u64,
    pub warnings: Vec<String>,
    pub initial: State,
    pub state: State,
    pub scratch: Vec<Real>,
    /// The evaluation at the start of the step (at `state` between steps).
    pub eval_a: Evaluation,
    /// The evaluation at the end of the step.
    pub eval_b: Evaluation,
    /// The work of each force at the end of the step.
    pub work_b: Vec<Real>,
    pub ledger: EnergyLedger,
    pub evaluations: u64,
    pub steps: u64,
    pub stop_reason: Option<StopReason>,
    pub failure: Option<Divergence>,
    /// The event functions at the start and at the end of the step.
    pub g_a: Vec<Real>,
    pub g_b: Vec<Real>,
    /// The events' sides at the start of the step.
    pub sides: Vec<Side>,
    pub book: EventBook,
    /// The events the finder locates inside the steps: those still enabled that are not
    /// checked at step ends only ([`Event::at_step_ends`]); refreshed before each use.
    pub located: Vec<bool>,
    /// The events checked at step ends only, in declaration order.
    pub step_end_events: Vec<usize>,
    /// Whether an event function reads the forces (each interior sample costs an evaluation).
    pub forces_for_events: bool,
    /// Interior sample points per step of an event function that cannot be enclosed.
    pub interior: usize,
    /// Whether any event function can be enclosed (the step's polynomial is then built).
    pub any_provable: bool,
    /// The derivative handed to a fixed-step stepper at the start of a step.
    pub dydt: Vec<Real>,
    pub grid: Option<Grid>,
    pub probe: Probe,
    pub ends: StepEnds,
    /// The fixed steps are counted from `fixed_origin` (the start, or the last state change):
    /// `fixed_k` of them so far, `planned` to reach `t_max`.
    pub fixed_origin: Real,
    pub fixed_k: u64,
    pub planned: Option<u64>,
    /// The smallest and largest step.
    pub step_range: (Real, Real),
    /// Whether the step's interpolant is needed (for events and output times only).
    pub interpolates: bool,
    /// The scan's progress through the step: the event functions and sides at its last point.
    pub g_scan: Vec<Real>,
    pub sides_scan: Vec<Side>,
    /// The one event finder: the step's interpolant, its sample points, the scan's buffers.
    pub finder: Finder,
    /// The events already warned of a step whose proof ran out of enclosures.
    pub warned: Vec<bool>,
    /// The first step taken, a typical step for the Zeno watch.
    pub step_scale: Real,
    pub fused: Option<Fused>,
    pub fused_steps: u64,
    /// A chunk that went non-finite is rerun by the general loop up to this step.
    pub fuse_resumes_at: u64,
}

impl<'r> Run<'r> {
    /// Evaluates the system at the start, passes the first sample to the observers, and sets
    /// up the events, the output times and the fused kernel. A start that already diverged, or
    /// at which a stop condition holds, sets the stop reason.
    pub fn start(
        sim: &'r Simulation<'r>,
        initial: State,
        observers: &mut [&mut dyn Observer],
    ) -> Result<Self, SimulateError> {
        let mut run = Run::new(sim, initial)?;
        let t0 = run.state.t;
        let s0 = sample_of(
            0,
            &run.state,
            &run.eval_a,
            run.ledger.work(),
            SampleKind::Step,
        );
        emit(observers, &s0)?;
        event_values(run.events, &s0, run.sys, &mut run.g_a);
        run.sides = run
            .events
            .iter()
            .zip(&run.g_a)
            .map(|(e, g)| e.initial_side(*g))
            .collect();
        run.check_start();
        run.engine.restart(&run.state, run.ledger.work());
        run.hand_over();
        run.grid = Grid::of(sim, t0, &mut run.warnings);
        run.planned = run.planned_from(t0);
        let expected = run.planned.unwrap_or(run.limit);
        run.fused = Fused::for_run(sim, &run.stepping, t0, expected, run.grid.is_some());
        Ok(run)
    }

    /// The run before its first sample: the engine, the step budget, the evaluation at the
    /// start and the ledger from it, and empty buffers.
    fn new(sim: &'r Simulation<'r>, initial: State) -> Result<Self, SimulateError> {
        let sys = sim.system;
        let events = &sim.events[..];
        let (m, n2, nf, t0) = (events.len(), initial.y.len(), sys.forces().len(), initial.t);
        let stepping = match &sim.stepping {
            Stepping::Adaptive { method, config } => {
                let mut config = config.clone();
                config.error_components.get_or_insert(n2);
                Stepping::Adaptive {
                    method: *method,
                    config,
                }
            }
            fixed @ Stepping::Fixed { .. } => fixed.clone(),
        };
        let engine = Engine::new(&stepping)?;
        let mut warnings = Vec::new();
        let limit = step_budget(sim, &stepping, t0, &mut warnings);
        let state = initial.clone();
        let (mut scratch, mut eval_a) = (Vec::new(), Evaluation::default());
        let (q, v) = state.qv();
        sys.evaluate(t0, q, v, &mut eval_a, &mut scratch);
        let names: Vec<String> = sys.forces().iter().map(|f| f.name().to_string()).collect();
        let ledger = EnergyLedger::start(names, t0, &eval_a);
        // events checked at step ends only are never sampled inside a step: they need neither
        // the step's polynomial nor forces at interior points
        let located = |e: &&Event| !e.is_checked_at_step_ends();
        let forces_for_events = events.iter().filter(located).any(Event::needs_forces);
        Ok(Run {
            sim,
            sys,
            events,
            stepping,
            ws: WorkSystem::new(sys),
            engine,
            limit,
            warnings,
            initial,
            state,
            scratch,
            eval_a,
            eval_b: Evaluation::default(),
            work_b: vec![0.0; nf],
            ledger,
            evaluations: 1,
            steps: 0,
            stop_reason: None,
            failure: None,
            g_a: vec![Real::NAN; m],
            g_b: vec![Real::NAN; m],
            sides: Vec::new(),
            book: EventBook::new(m),
            located: vec![false; m],
            step_end_events: (0..m)
                .filter(|&i| events[i].is_checked_at_step_ends())
                .collect(),
            forces_for_events,
            interior: if forces_for_events { 1 } else { 7 },
            any_provable: events
                .iter()
                .filter(located)
                .any(|e| e.condition().is_provable()),
            dydt: vec![0.0; n2],
            grid: None,
            probe: Probe::new(t0, n2, nf),
            ends: StepEnds::default(),
            fixed_origin: t0,
            fixed_k: 0,
            planned: None,
            step_range: (Real::INFINITY, 0.0),
            interpolates: m > 0 || sim.interval.is_some() || sim.times.is_some(),
            g_scan: Vec::with_capacity(m),
            sides_scan: Vec::with_capacity(m),
            finder: Finder::default(),
            warned: vec![false; m],
            step_scale: Real::NAN,
            fused: None,
            fused_steps: 0,
            fuse_resumes_at: 0,
        })
    }

    /// Stops a run whose start is not finite, or at which a stop condition already holds.
    fn check_start(&mut self) {
        if self.check_evaluation() {
            return;
        }
        let holds = |(i, e): &(usize, &Event)| {
            e.is_stop_condition() && e.condition().holds_for(self.g_a[*i])
        };
        if let Some((i, e)) = self.events.iter().enumerate().find(holds) {
            let t0 = self.state.t;
            self.warnings.push(format!(
                "the stop condition `{}` already holds at the start (t = {} s); nothing was simulated",
                e.name(),
                crate::error::short(t0)
            ));
            self.book.at_start(e, i, t0, &self.state.y);
            self.stop_reason = Some(StopReason::Event);
        }
    }

    /// Sets [`Run::located`] from the events still enabled.
    pub fn refresh_located(&mut self) {
        let enabled = self.book.enabled.iter().zip(self.events);
        for (l, (on, e)) in self.located.iter_mut().zip(enabled) {
            *l = *on && !e.is_checked_at_step_ends();
        }
    }

    /// Whether the run stops before its next step (setting the reason).
    pub fn stops_before_step(&mut self, observers: &[&mut dyn Observer]) -> bool {
        self.stop_reason = stop_before_step(
            self.sim,
            observers,
            self.events,
            self.state.t,
            self.steps,
            self.limit,
            &mut self.warnings,
        );
        self.stop_reason.is_some()
    }

    /// The fixed steps it takes to reach `t_max` from `origin` (`None`: adaptive, or no
    /// `t_max`).
    pub fn planned_from(&self, origin: Real) -> Option<u64> {
        match (&self.stepping, self.sim.t_max) {
            (Stepping::Fixed { dt, .. }, Some(tm)) => Some(steps_to_cover(tm - origin, *dt) as u64),
            _ => None,
        }
    }

    /// Hands a fixed-step stepper the derivative at the current state (from `eval_a`).
    pub fn hand_over(&mut self) {
        if let Engine::Fixed { stepper, .. } = &mut self.engine {
            let n = self.state.y.len() / 2;
            self.dydt[..n].copy_from_slice(&self.state.y[n..]);
            self.dydt[n..].copy_from_slice(&self.eval_a.a);
            stepper.provide_derivative(self.state.t, &self.dydt);
        }
    }

    /// Evaluates the system at the current state, into `eval_a`.
    pub fn evaluate_here(&mut self) {
        let (q, v) = self.state.qv();
        self.sys
            .evaluate(self.state.t, q, v, &mut self.eval_a, &mut self.scratch);
    }

    /// Whether the evaluation at the current state is not finite (the run then stops,
    /// diverged, with a diagnosis).
    pub fn check_evaluation(&mut self) -> bool {
        let d = diagnose_evaluation(self.sys, &self.state, &self.eval_a, self.steps);
        let diverged = d.is_some();
        if diverged {
            self.failure = d;
            self.stop_reason = Some(StopReason::Diverged);
        }
        diverged
    }

    /// Passes the last sample to the observers and reports the run.
    fn report(self, observers: &mut [&mut dyn Observer]) -> Result<RunReport, SimulateError> {
        let steps = self.steps;
        let last_kind = if self.book.terminal.is_some() && steps > 0 {
            SampleKind::Event
        } else {
            SampleKind::Step
        };
        let last = sample_of(
            steps,
            &self.state,
            &self.eval_a,
            self.ledger.work(),
            last_kind,
        );
        for o in observers.iter_mut() {
            o.finish(&last)?;
        }
        let span = self.state.t - self.initial.t;
        let mut warnings = self.warnings;
        if let Some(t) = self.engine.stiff_from() {
            warnings.push(stiffness_warning(self.stepping.method(), t));
        }
        if let Some(t) = self.engine.switched_at() {
            warnings.push(format!(
                "method = \"auto\" switched from dop853 to radau5 at t = {} s, where the problem turned stiff (Hairer's test)",
                crate::error::short(t)
            ));
        }
        Ok(RunReport {
            method: self.stepping.method(),
            dt: self.stepping.dt().unwrap_or(if steps > 0 {
                span / steps as Real
            } else {
                Real::NAN
            }),
            stepping: self.sim.stepping.clone(),
            adaptive: self.engine.adaptive_stats(),
            step_range: if steps > 0 {
                self.step_range
            } else {
                (Real::NAN, Real::NAN)
            },
            steps,
            evaluations: self.evaluations,
            fused_steps: self.fused_steps,
            stop_reason: self.stop_reason.expect("the loop sets a reason"),
            initial: self.initial,
            final_state: self.state,
            event: self.book.terminal,
            events: self.book.records,
            divergence: self.failure,
            ledger: self.ledger,
            warnings,
        })
    }
}

/// What the stiffness test of an explicit pair says, and what to do about it.
fn stiffness_warning(method: crate::ode::Method, t: Real) -> String {
    format!(
        "the problem is stiff from t = {} s: {method}'s steps were limited by stability, not accuracy, for 15 steps in a row (Hairer's test); method = \"radau5\" or \"bdf\" takes far fewer steps",
        crate::error::short(t)
    )
}

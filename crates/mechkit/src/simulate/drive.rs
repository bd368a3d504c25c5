//! The simulation loop: advance, keep the energy ledger, find and handle events in time order,
//! sample the requested output times, hand every sample to the observers, and stop with a
//! diagnosis when the numbers stop being numbers.

use super::diagnose::{coordinate_name, diagnose_evaluation, diagnose_state};
use super::event::{Event, EventAction, Side};
use super::observe::Observer;
use super::report::{Divergence, EventRecord, RunReport, SimulateError, Snapshot, StopReason};
use super::run::{DEFAULT_MAX_STEPS, Simulation, sample_of};
use super::scan::{ScanResult, scan};
use super::stepping::{Engine, StepEnds, Stepping, WorkSystem};
use crate::Real;
use crate::energy::EnergyLedger;
use crate::ode::{AdaptiveError, State, steps_to_cover};
use crate::particles::{Evaluation, ParticleSystem, Sample, SampleKind};

/// An event firing this many times in a row, each within a relative 1e-9 of the time since the
/// last, is Zeno behaviour: the run stops with a diagnosis.
pub const ZENO_LIMIT: u32 = 50;

/// At most this many event occurrences are kept in the report (all are counted).
const MAX_RECORDS: usize = 100_000;

/// A state between steps with what follows from it.
struct Probe {
    state: State,
    eval: Evaluation,
    work: Vec<Real>,
    scratch: Vec<Real>,
}

/// Everything the loop needs to interpolate inside the current step.
struct Step<'r, 'a> {
    sys: &'a ParticleSystem,
    ws: &'r WorkSystem<'a>,
    engine: &'r mut Engine,
    ends: &'r StepEnds,
    ledger: &'r EnergyLedger,
}

impl Step<'_, '_> {
    /// Fills `p` with the state at `t` (and the forces there when `forces`).
    fn probe(&mut self, p: &mut Probe, t: Real, forces: bool, evaluations: &mut u64) {
        p.state.t = t;
        let have_work = self
            .engine
            .interpolate(self.ws, self.ends, t, &mut p.state.y, &mut p.work);
        if forces {
            let (q, v) = p.state.qv();
            self.sys.evaluate(t, q, v, &mut p.eval, &mut p.scratch);
            *evaluations += 1;
            if !have_work {
                self.ledger.preview_into(t, &p.eval.power, &mut p.work);
            }
        } else if !have_work {
            p.work.clear();
            p.work.extend_from_slice(self.ledger.work());
        }
    }
}

fn event_values(events: &[Event], s: &Sample<'_>, sys: &ParticleSystem, out: &mut [Real]) {
    for (o, e) in out.iter_mut().zip(events) {
        *o = e.condition().value(s, sys);
    }
}

fn emit(observers: &mut [&mut dyn Observer], s: &Sample<'_>) -> Result<(), SimulateError> {
    for o in observers.iter_mut() {
        o.observe(s)?;
    }
    Ok(())
}

/// The output times still to come: every `dt` from `t0`, or a list.
struct Grid {
    t0: Real,
    dt: Real,
    list: Option<Vec<Real>>,
    k: u64,
    t_max: Option<Real>,
}

impl Grid {
    fn next(&self) -> Option<Real> {
        let t = match &self.list {
            Some(list) => *list.get(usize::try_from(self.k).ok()?)?,
            None => self.t0 + self.k as Real * self.dt,
        };
        match self.t_max {
            Some(tm) if t > tm * (1.0 + 1e-12) + 1e-300 => None,
            _ => Some(t),
        }
    }
}

/// The end of fixed step number `k + 1` of a grid started at `origin` (landing on `t_max`).
fn fixed_next(origin: Real, k: u64, dt: Real, planned: Option<u64>, t_max: Option<Real>) -> Real {
    match (planned, t_max) {
        (Some(n), Some(tm)) if k + 1 >= n => tm,
        _ => origin + (k + 1) as Real * dt,
    }
}

#[allow(clippy::too_many_lines)]
pub(super) fn drive(
    sim: &Simulation<'_>,
    initial: State,
    observers: &mut [&mut dyn Observer],
) -> Result<RunReport, SimulateError> {
    let sys = sim.system;
    let events = &sim.events;
    let m = events.len();
    let n2 = initial.y.len();
    let nf = sys.forces().len();
    let t0 = initial.t;
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
    let ws = WorkSystem::new(sys);
    let mut engine = Engine::new(&stepping)?;
    let mut warnings = Vec::new();
    let limit = match (sim.max_steps, sim.t_max) {
        (Some(n), _) => n,
        (None, Some(_)) => u64::MAX,
        (None, None) => {
            warnings.push(format!(
                "no t_max was given: the run is bounded by {DEFAULT_MAX_STEPS} steps{}; set t_max to choose the end",
                stepping
                    .dt()
                    .map(|dt| format!(" (t = {} s with dt = {dt} s)", t0 + DEFAULT_MAX_STEPS as Real * dt))
                    .unwrap_or_default()
            ));
            DEFAULT_MAX_STEPS
        }
    };

    let mut state = initial.clone();
    let mut scratch = Vec::new();
    let mut eval_a = Evaluation::default();
    {
        let (q, v) = state.qv();
        sys.evaluate(t0, q, v, &mut eval_a, &mut scratch);
    }
    let names: Vec<String> = sys.forces().iter().map(|f| f.name().to_string()).collect();
    let mut ledger = EnergyLedger::start(names, t0, &eval_a);
    let mut evaluations: u64 = 1;
    let mut steps: u64 = 0;
    let mut stop_reason = None;
    let mut failure: Option<Divergence> = None;
    let mut records: Vec<EventRecord> = Vec::new();
    let mut terminal: Option<EventRecord> = None;

    let s0 = sample_of(0, &state, &eval_a, ledger.work(), SampleKind::Step);
    emit(observers, &s0)?;
    let mut g_a = vec![Real::NAN; m];
    event_values(events, &s0, sys, &mut g_a);
    let mut sides: Vec<Side> = events
        .iter()
        .zip(&g_a)
        .map(|(e, g)| e.initial_side(*g))
        .collect();
    let mut enabled = vec![true; m];
    let mut counts = vec![0u32; m];
    let mut zeno: Vec<(u32, Real)> = vec![(0, Real::NAN); m];
    let interior = if events.iter().any(Event::needs_forces) {
        1
    } else {
        7
    };
    let forces_for_events = events.iter().any(Event::needs_forces);

    if let Some(d) = diagnose_evaluation(sys, &state, &eval_a, 0) {
        failure = Some(d);
        stop_reason = Some(StopReason::Diverged);
    } else if let Some((i, e)) = events
        .iter()
        .enumerate()
        .find(|(i, e)| e.is_stop_condition() && e.condition().holds_for(g_a[*i]))
    {
        warnings.push(format!(
            "the stop condition `{}` already holds at the start (t = {t0} s); nothing was simulated",
            e.name()
        ));
        let snap = Snapshot::of(t0, &state.y);
        let rec = EventRecord {
            name: e.name().to_string(),
            occurrence: 1,
            t: t0,
            state: snap.clone(),
            last_step: snap.clone(),
            crossing_step: snap,
            after: None,
            terminal: true,
        };
        counts[i] = 1;
        records.push(rec.clone());
        terminal = Some(rec);
        stop_reason = Some(StopReason::Event);
    }

    engine.restart(&state, ledger.work());
    let n = n2 / 2;
    let mut dydt = vec![0.0; n2];
    let hand_over = |engine: &mut Engine, t: Real, y: &[Real], a: &[Real], dydt: &mut Vec<Real>| {
        if let Engine::Fixed { stepper, .. } = engine {
            dydt[..n].copy_from_slice(&y[n..]);
            dydt[n..].copy_from_slice(a);
            stepper.provide_derivative(t, dydt);
        }
    };
    hand_over(&mut engine, t0, &state.y, &eval_a.a, &mut dydt);

    let mut grid = match (&sim.times, sim.interval) {
        (Some(list), _) => {
            let list: Vec<Real> = list.iter().copied().filter(|t| *t > t0).collect();
            Some(Grid {
                t0,
                dt: Real::NAN,
                list: Some(list),
                k: 0,
                t_max: sim.t_max,
            })
        }
        (None, Some(dt)) => Some(Grid {
            t0,
            dt,
            list: None,
            k: 1,
            t_max: sim.t_max,
        }),
        (None, None) => None,
    };
    let mut probe = Probe {
        state: State::new(t0, vec![0.0; n2]),
        eval: Evaluation::default(),
        work: vec![0.0; nf],
        scratch: Vec::new(),
    };
    let mut ends = StepEnds::default();
    let mut eval_b = Evaluation::default();
    let mut work_b = vec![0.0; nf];
    let mut g_b = vec![Real::NAN; m];
    let mut fixed_origin = t0;
    let mut fixed_k: u64 = 0;
    let planned_from = |origin: Real| match (&stepping, sim.t_max) {
        (Stepping::Fixed { dt, .. }, Some(tm)) => Some(steps_to_cover(tm - origin, *dt) as u64),
        _ => None,
    };
    let mut planned = planned_from(t0);
    let mut step_range: (Real, Real) = (Real::INFINITY, 0.0);
    // the step's interpolant is needed for events and output times only
    let interpolates = m > 0 || sim.interval.is_some() || sim.times.is_some();
    let mut work_a = Vec::with_capacity(nf);
    let mut g_scan = Vec::with_capacity(m);
    let mut sides_scan = Vec::with_capacity(m);
    let mut step_scale = Real::NAN;

    while stop_reason.is_none() {
        if let Some(tm) = sim.t_max
            && state.t >= tm
        {
            stop_reason = Some(StopReason::TMax);
            break;
        }
        if steps >= limit {
            stop_reason = Some(StopReason::MaxSteps);
            if sim.max_steps.is_none() {
                let why = if events.iter().any(Event::is_stop_condition) {
                    "the stop condition never became true"
                } else {
                    "nothing else ends this run"
                };
                warnings.push(format!(
                    "stopped after the default budget of {DEFAULT_MAX_STEPS} steps at t = {} s: {why}; set [stop] t_max",
                    state.t
                ));
            }
            break;
        }
        let t_a = state.t;
        ends.t0 = t_a;
        ends.y0.clone_from(&state.y);
        if interpolates {
            ends.a0.clone_from(&eval_a.a);
            work_a.clear();
            work_a.extend_from_slice(ledger.work());
        }

        // advance
        if let Engine::Fixed { stepper, dt } = &mut engine {
            let t_next = fixed_next(fixed_origin, fixed_k, *dt, planned, sim.t_max);
            let info = stepper.step(sys, &mut state, t_next - t_a)?;
            evaluations += info.evaluations as u64;
            state.t = t_next;
            fixed_k += 1;
        } else {
            {
                let t_bound = sim.t_max.unwrap_or(Real::INFINITY);
                let before = engine.adaptive_stats().map_or(0, |s| s.evaluations);
                let result = engine.adaptive_step(&ws, &mut state, &mut work_b, t_bound);
                evaluations += engine.adaptive_stats().map_or(0, |s| s.evaluations) - before;
                if let Err(AdaptiveError::StepTooSmall {
                    t,
                    h,
                    h_min,
                    component,
                    non_finite,
                }) = result
                {
                    state.t = t_a;
                    state.y.copy_from_slice(&ends.y0);
                    let bad = ws.bad.borrow_mut().take();
                    let named = bad.as_ref().and_then(|b| {
                        let mut e = Evaluation::default();
                        let (q, v) = b.qv();
                        sys.evaluate(b.t, q, v, &mut e, &mut scratch);
                        diagnose_evaluation(sys, b, &e, steps)
                    });
                    let (reason, d) = match named {
                        Some(d) if non_finite => (
                            StopReason::Diverged,
                            Divergence {
                                t,
                                message: format!(
                                    "the run cannot continue past t = {t} s: every step tried from there (down to {h:e} s) reaches states where a force is not finite; the first: {}",
                                    d.message
                                ),
                                ..d
                            },
                        ),
                        _ => {
                            let quantity = coordinate_name(sys, component.min(n2 - 1));
                            (
                                StopReason::StepTooSmall,
                                Divergence {
                                    t,
                                    step: steps,
                                    quantity: quantity.clone(),
                                    value: h,
                                    message: format!(
                                        "the step size fell to {h:e} s at t = {t} s (minimum {h_min:e} s) without meeting the tolerance; the error is dominated by {quantity}: the solution is not smooth there (a discontinuous force, a collision, a singularity), or the tolerance is below what double precision allows; loosen rtol/atol, or model the discontinuity as an event"
                                    ),
                                },
                            )
                        }
                    };
                    failure = Some(d);
                    stop_reason = Some(reason);
                    break;
                }
                ws.take_last(&mut eval_b);
            }
        }
        steps += 1;
        let h_taken = state.t - t_a;
        step_range = (step_range.0.min(h_taken), step_range.1.max(h_taken));
        if step_scale.is_nan() {
            step_scale = h_taken;
        }
        if !state.is_finite() {
            failure = Some(diagnose_state(sys, &ends.y0, &state, t_a, steps - 1));
            state.y.copy_from_slice(&ends.y0);
            state.t = t_a;
            stop_reason = Some(StopReason::Diverged);
            break;
        }
        let t_b = state.t;
        if let Engine::Fixed { .. } = engine {
            let (q, v) = state.qv();
            sys.evaluate(t_b, q, v, &mut eval_b, &mut scratch);
            evaluations += 1;
            if m > 0 {
                ledger.preview_into(t_b, &eval_b.power, &mut work_b);
            }
        }
        ends.t1 = t_b;
        if interpolates {
            ends.y1.clone_from(&state.y);
            ends.a1.clone_from(&eval_b.a);
        }
        if m > 0 {
            let at_b = sample_of(steps, &state, &eval_b, &work_b, SampleKind::Step);
            event_values(events, &at_b, sys, &mut g_b);
        }

        // events, in time order
        let mut t_scan = t_a;
        g_scan.clone_from(&g_a);
        sides_scan.clone_from(&sides);
        let mut cut = false;
        let mut event_at_end = false;
        // (no events: nothing to scan)
        while enabled.iter().any(|e| *e) {
            let mut step = Step {
                sys,
                ws: &ws,
                engine: &mut engine,
                ends: &ends,
                ledger: &ledger,
            };
            let result = {
                let mut values = |t: Real, out: &mut [Real]| {
                    step.probe(&mut probe, t, forces_for_events, &mut evaluations);
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
                    &enabled,
                    &sides_scan,
                    (t_scan, &g_scan),
                    (t_b, &g_b),
                    interior,
                    &mut values,
                )
            };
            let (firing, at_values) = match result {
                ScanResult::Quiet(s) => {
                    sides = s;
                    break;
                }
                ScanResult::Fired { firing, values } => (firing, values),
            };
            let te = firing.t;
            // output times before the event
            if let Some(gr) = &mut grid {
                while let Some(tg) = gr.next().filter(|tg| *tg < te) {
                    step.probe(&mut probe, tg, true, &mut evaluations);
                    emit(
                        observers,
                        &sample_of(
                            steps,
                            &probe.state,
                            &probe.eval,
                            &probe.work,
                            SampleKind::Grid,
                        ),
                    )?;
                    gr.k += 1;
                }
            }
            // the state at the event
            if te == t_b {
                probe.state.t = t_b;
                probe.state.y.clone_from(&state.y);
                probe.eval.clone_from(&eval_b);
                probe.work.clone_from(&work_b);
            } else if te == t_a {
                probe.state.t = t_a;
                probe.state.y.clone_from(&ends.y0);
                probe.eval.clone_from(&eval_a);
                probe.work.clone_from(&work_a);
            } else {
                step.probe(&mut probe, te, true, &mut evaluations);
            }
            let mut stop_here = false;
            let mut setters = Vec::new();
            for &i in &firing.events {
                let e = &events[i];
                counts[i] += 1;
                // Zeno: firing again and again within a relative 1e-9 of the time
                let (run, last) = zeno[i];
                let close = te - last <= 1e-9 * te.abs().max(step_scale.abs());
                zeno[i] = (if close { run + 1 } else { 0 }, te);
                if zeno[i].0 >= ZENO_LIMIT {
                    failure = Some(Divergence {
                        t: te,
                        step: steps,
                        quantity: e.name().to_string(),
                        value: Real::from(counts[i]),
                        message: format!(
                            "the event `{}` fired {} times in a row, each within {:.1e} s of the last, up to t = {te} s (occurrence {}): its occurrences accumulate at one instant (Zeno behaviour, like a ball bouncing infinitely often before coming to rest); end the run before that instant (t_max), or add an event that stops or changes the model there (e.g. when the rebound speed falls below a threshold)",
                            e.name(),
                            ZENO_LIMIT,
                            1e-9 * te.abs().max(step_scale.abs()),
                            counts[i]
                        ),
                    });
                    stop_reason = Some(StopReason::Zeno);
                    stop_here = true;
                }
                if e.max_count.is_some_and(|mc| counts[i] >= mc) {
                    enabled[i] = false;
                }
                let ends_run = matches!(e.action, EventAction::StopAt(k) if counts[i] >= k);
                if ends_run {
                    stop_here = true;
                    if stop_reason.is_none() {
                        stop_reason = Some(StopReason::Event);
                    }
                }
                if e.state_change().is_some() && !ends_run {
                    setters.push(i);
                }
                let rec = EventRecord {
                    name: e.name().to_string(),
                    occurrence: counts[i],
                    t: te,
                    state: Snapshot::of(te, &probe.state.y),
                    last_step: Snapshot::of(t_a, &ends.y0),
                    crossing_step: Snapshot::of(t_b, &state.y),
                    after: None,
                    terminal: ends_run,
                };
                if ends_run && terminal.is_none() {
                    terminal = Some(rec.clone());
                }
                if records.len() < MAX_RECORDS {
                    records.push(rec);
                } else if records.len() == MAX_RECORDS {
                    warnings.push(format!(
                        "more than {MAX_RECORDS} event occurrences: only the first are reported"
                    ));
                }
            }
            if stop_here || !setters.is_empty() {
                // the run continues from (or ends at) the event: the rest of the step is dropped
                match &engine {
                    Engine::Fixed { .. } => ledger.advance(te, &probe.eval),
                    Engine::Adaptive { .. } => ledger.set(te, &probe.eval, &probe.work),
                }
                let kind = SampleKind::Event;
                if te != t_a {
                    emit(
                        observers,
                        &sample_of(steps, &probe.state, &probe.eval, ledger.work(), kind),
                    )?;
                }
                state.t = te;
                state.y.clone_from(&probe.state.y);
                eval_a.clone_from(&probe.eval);
                cut = true;
                if stop_here {
                    break;
                }
                // state changes, in declaration order, each seeing the state at the event
                let pre = sample_of(steps, &probe.state, &probe.eval, ledger.work(), kind);
                let mut y_new = probe.state.y.clone();
                for &i in &setters {
                    (events[i].state_change().expect("a setter"))(&pre, sys, &mut y_new);
                }
                state.y.copy_from_slice(&y_new);
                if !state.is_finite() {
                    let i = state
                        .y
                        .iter()
                        .position(|x| !x.is_finite())
                        .expect("non-finite");
                    failure = Some(Divergence {
                        t: te,
                        step: steps,
                        quantity: coordinate_name(sys, i),
                        value: state.y[i],
                        message: format!(
                            "the state change of the event `{}` at t = {te} s made {} = {}",
                            events[setters[0]].name(),
                            coordinate_name(sys, i),
                            state.y[i]
                        ),
                    });
                    state.y.clone_from(&probe.state.y);
                    stop_reason = Some(StopReason::Diverged);
                    break;
                }
                {
                    let (q, v) = state.qv();
                    sys.evaluate(te, q, v, &mut eval_a, &mut scratch);
                }
                evaluations += 1;
                ledger.jump(&eval_a);
                for &i in &setters {
                    if let Some(r) = records
                        .iter_mut()
                        .rev()
                        .find(|r| r.name == events[i].name() && r.t == te)
                    {
                        r.after = Some(Snapshot::of(te, &state.y));
                    }
                }
                let post = sample_of(steps, &state, &eval_a, ledger.work(), kind);
                emit(observers, &post)?;
                event_values(events, &post, sys, &mut g_a);
                for i in 0..m {
                    sides[i] = if firing.events.contains(&i) || g_a[i] == 0.0 {
                        Side::Zero
                    } else {
                        sides_scan[i].after(g_a[i])
                    };
                }
                engine.restart(&state, ledger.work());
                hand_over(&mut engine, te, &state.y, &eval_a.a, &mut dydt);
                fixed_origin = te;
                fixed_k = 0;
                planned = planned_from(te);
                break;
            }
            // recorded only: show it and look further in the same step
            if te == t_b {
                event_at_end = true;
                for i in 0..m {
                    sides[i] = if firing.events.contains(&i) {
                        Side::Zero
                    } else {
                        sides_scan[i].after(g_b[i])
                    };
                }
                break;
            }
            if te != t_a {
                emit(
                    observers,
                    &sample_of(
                        steps,
                        &probe.state,
                        &probe.eval,
                        &probe.work,
                        SampleKind::Event,
                    ),
                )?;
            }
            for i in 0..m {
                sides_scan[i] = if firing.events.contains(&i) {
                    Side::Zero
                } else {
                    sides_scan[i].after(at_values[i])
                };
            }
            g_scan.copy_from_slice(&at_values);
            t_scan = te;
        }
        if cut {
            continue;
        }

        // output times up to the step's end
        if let Some(gr) = &mut grid {
            let mut step = Step {
                sys,
                ws: &ws,
                engine: &mut engine,
                ends: &ends,
                ledger: &ledger,
            };
            while let Some(tg) = gr.next().filter(|tg| *tg <= t_b) {
                step.probe(&mut probe, tg, true, &mut evaluations);
                emit(
                    observers,
                    &sample_of(
                        steps,
                        &probe.state,
                        &probe.eval,
                        &probe.work,
                        SampleKind::Grid,
                    ),
                )?;
                gr.k += 1;
            }
        }
        match &engine {
            Engine::Fixed { .. } => ledger.advance(t_b, &eval_b),
            Engine::Adaptive { .. } => ledger.set(t_b, &eval_b, &work_b),
        }
        let kind = if event_at_end {
            SampleKind::Event
        } else {
            SampleKind::Step
        };
        emit(
            observers,
            &sample_of(steps, &state, &eval_b, ledger.work(), kind),
        )?;
        std::mem::swap(&mut eval_a, &mut eval_b);
        std::mem::swap(&mut g_a, &mut g_b);
        hand_over(&mut engine, t_b, &state.y, &eval_a.a, &mut dydt);
        if let Some(d) = diagnose_evaluation(sys, &state, &eval_a, steps) {
            failure = Some(d);
            stop_reason = Some(StopReason::Diverged);
        }
    }

    let last_kind = if terminal.is_some() && steps > 0 {
        SampleKind::Event
    } else {
        SampleKind::Step
    };
    let last = sample_of(steps, &state, &eval_a, ledger.work(), last_kind);
    for o in observers.iter_mut() {
        o.finish(&last)?;
    }
    let adaptive = engine.adaptive_stats();
    let span = state.t - t0;
    Ok(RunReport {
        method: stepping.method(),
        dt: stepping.dt().unwrap_or(if steps > 0 {
            span / steps as Real
        } else {
            Real::NAN
        }),
        stepping: sim.stepping.clone(),
        adaptive,
        step_range: if steps > 0 {
            step_range
        } else {
            (Real::NAN, Real::NAN)
        },
        steps,
        evaluations,
        stop_reason: stop_reason.expect("the loop sets a reason"),
        initial,
        final_state: state,
        event: terminal,
        events: records,
        divergence: failure,
        ledger,
        warnings,
    })
}

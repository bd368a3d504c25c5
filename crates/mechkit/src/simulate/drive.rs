//! The simulation loop: advance, keep the energy ledger, find and handle events in time order,
//! sample the requested output times, hand every sample to the observers, and stop with a
//! diagnosis when the numbers stop being numbers.

use super::book::EventBook;
use super::diagnose::{diagnose_evaluation, diagnose_state, step_failure};
use super::event::{Event, Side};
use super::fused::{Fused, MIN_CHUNK, chunk_len};
use super::halt::stop_before_step;
use super::observe::Observer;
use super::probe::{Grid, Probe, Step, emit, event_values};
use super::prove::{Prover, Proving};
use super::rearm::{sides_after_change, values_ahead};
use super::report::{Divergence, RunReport, SimulateError, StopReason};
use super::run::{Simulation, sample_of};
use super::scan::{Fired, ScanBuffers, scan};
use super::stepping::{Engine, StepEnds, Stepping, WorkSystem, fixed_next, step_budget};
use crate::Real;
use crate::energy::EnergyLedger;
use crate::ode::{AdaptiveError, State, steps_to_cover};
use crate::particles::{Evaluation, SampleKind};

/// Most interior samples an event may ask for in one step.
const MAX_INTERIOR: usize = 100_000;

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
    let limit = step_budget(sim, &stepping, t0, &mut warnings);

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

    let s0 = sample_of(0, &state, &eval_a, ledger.work(), SampleKind::Step);
    emit(observers, &s0)?;
    let mut g_a = vec![Real::NAN; m];
    event_values(events, &s0, sys, &mut g_a);
    let mut sides: Vec<Side> = events
        .iter()
        .zip(&g_a)
        .map(|(e, g)| e.initial_side(*g))
        .collect();
    let mut book = EventBook::new(m);
    // interior sample points per step for the event functions (each costs an evaluation of
    // the forces when a function needs them)
    let forces_for_events = events.iter().any(Event::needs_forces);
    let interior = if forces_for_events { 1 } else { 7 };

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
        book.at_start(e, i, t0, &state.y);
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

    let mut grid = Grid::of(sim, t0, &mut warnings);
    let mut probe = Probe::new(t0, n2, nf);
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
    let mut scan_buffers = ScanBuffers::default();
    let mut prover = Prover::default();
    let mut scan_points: Vec<Real> = Vec::new();
    let mut step_scale = Real::NAN;
    let mut fused = Fused::for_run(sim, &stepping, t0, planned.unwrap_or(limit), grid.is_some());
    let mut fused_steps: u64 = 0;
    // a chunk that went non-finite is rerun by the general loop up to this step
    let mut fuse_resumes_at: u64 = 0;

    while stop_reason.is_none() {
        stop_reason =
            stop_before_step(sim, observers, events, state.t, steps, limit, &mut warnings);
        if stop_reason.is_some() {
            break;
        }
        // the steps no observer looks at, in the compiled kernel
        if let Some(kernel) = &mut fused
            && steps > 0
            && steps >= fuse_resumes_at
        {
            let chunk = chunk_len(observers, steps, limit, planned, fixed_k);
            if chunk >= MIN_CHUNK {
                let a = std::mem::take(&mut eval_a.a);
                let finite = kernel.advance(
                    &mut state,
                    &mut fixed_k,
                    &a,
                    &mut ledger,
                    &mut step_range,
                    chunk,
                );
                eval_a.a = a;
                if finite {
                    steps += chunk;
                    evaluations += chunk;
                    fused_steps += chunk;
                    {
                        let (q, v) = state.qv();
                        sys.evaluate(state.t, q, v, &mut eval_a, &mut scratch);
                    }
                    ledger.end_at(&eval_a);
                    hand_over(&mut engine, state.t, &state.y, &eval_a.a, &mut dydt);
                    if let Some(d) = diagnose_evaluation(sys, &state, &eval_a, steps) {
                        failure = Some(d);
                        stop_reason = Some(StopReason::Diverged);
                    }
                    continue;
                }
                fuse_resumes_at = steps + chunk + 1;
            }
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
                let (reason, d) = step_failure(
                    sys,
                    bad.as_ref(),
                    (t, h, h_min, component, non_finite),
                    steps,
                    &mut scratch,
                );
                failure = Some(d);
                stop_reason = Some(reason);
                break;
            }
            ws.take_last(&mut eval_b);
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

        // events, in time order, at the points that prove no sign change is missed (and as
        // densely as contacts ask)
        if book.enabled.iter().any(|e| *e) {
            let extra = events.iter().fold(0, |n, e| {
                n.max(
                    e.samples_needed(&ends.y0, &state.y, t_b - t_a)
                        .min(MAX_INTERIOR),
                )
            });
            if events.iter().any(|e| e.condition().is_provable()) {
                engine.step_polynomial(&ws, &ends, &mut prover.poly);
            } else {
                prover.poly.reset(t_a, t_b - t_a, 0, 1);
            }
            let proving = Proving {
                events,
                enabled: &book.enabled,
                sys,
                work: matches!(engine, Engine::Adaptive { .. }),
                default_interior: interior,
            };
            prover.points(&proving, extra, &mut scan_points, &mut warnings);
        }
        let mut t_scan = t_a;
        g_scan.clone_from(&g_a);
        sides_scan.clone_from(&sides);
        let mut cut = false;
        let mut event_at_end = false;
        // (no events: nothing to scan)
        while book.enabled.iter().any(|e| *e) {
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
                    &book.enabled,
                    &mut sides_scan,
                    (t_scan, &g_scan),
                    (t_b, &g_b),
                    &scan_points,
                    &mut values,
                    &mut scan_buffers,
                )
            };
            let Some(Fired {
                firing,
                values: at_values,
            }) = result
            else {
                sides.clone_from(&sides_scan);
                break;
            };
            let te = firing.t;
            // output times before the event
            if let Some(gr) = &mut grid {
                gr.emit_until(
                    &mut step,
                    &mut probe,
                    te,
                    false,
                    steps,
                    &mut evaluations,
                    observers,
                )?;
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
            let outcome = book.fire(
                events,
                &firing.events,
                te,
                &probe.state.y,
                (t_a, &ends.y0),
                (t_b, &state.y),
                step_scale,
                steps,
                &mut warnings,
            );
            if outcome.failure.is_some() {
                failure = outcome.failure;
            }
            let stop_here = outcome.stop.is_some();
            if stop_here {
                stop_reason = outcome.stop;
            }
            let setters = outcome.setters;
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
                if let Err(d) = EventBook::apply(events, &setters, &pre, sys, &mut state.y) {
                    failure = Some(d);
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
                book.changed(events, &setters, te, &state.y);
                let post = sample_of(steps, &state, &eval_a, ledger.work(), kind);
                emit(observers, &post)?;
                event_values(events, &post, sys, &mut g_a);
                values_ahead(
                    (events, &firing.events),
                    sys,
                    (&state, &eval_a, ledger.work()),
                    step_scale,
                    steps,
                    &mut probe,
                    &mut evaluations,
                    &mut g_b,
                );
                sides_after_change(
                    events,
                    &firing.events,
                    &sides_scan,
                    (&at_values, &g_a, &g_b),
                    &mut sides,
                );
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
            gr.emit_until(
                &mut step,
                &mut probe,
                t_b,
                true,
                steps,
                &mut evaluations,
                observers,
            )?;
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

    let last_kind = if book.terminal.is_some() && steps > 0 {
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
        fused_steps,
        stop_reason: stop_reason.expect("the loop sets a reason"),
        initial,
        final_state: state,
        event: book.terminal,
        events: book.records,
        divergence: failure,
        ledger,
        warnings,
    })
}

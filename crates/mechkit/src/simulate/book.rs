//! The bookkeeping of event occurrences: counts, limits, the Zeno watch, the records.

use super::diagnose::coordinate_name;
use super::event::{Event, EventAction};
use super::report::{Divergence, EventRecord, Snapshot, StopReason};
use crate::Real;
use crate::particles::{ParticleSystem, Sample};

/// An event firing this many times in a row, each within a relative 1e-9 of the time since the
/// last, is Zeno behaviour: the run stops with a diagnosis.
pub const ZENO_LIMIT: u32 = 50;

/// Occurrences of an event with a state change this close together, in units in the last
/// place of the time, are Zeno behaviour at once.
const ZENO_ULPS: Real = 64.0;

/// The spacing of floating-point numbers at `x` (`x ≥ 0`).
fn ulp(x: Real) -> Real {
    x.next_up() - x
}

/// What to do about Zeno behaviour, at the end of its diagnosis.
const ZENO_ADVICE: &str = "end the run before that instant (t_max), or add an event that stops or changes the model there (e.g. when the rebound speed falls below a threshold)";

/// At most this many event occurrences are kept in the report (all are counted).
const MAX_RECORDS: usize = 100_000;

/// What the occurrences at one instant ask of the run.
#[derive(Debug, Default)]
pub(super) struct Outcome {
    /// The run ends here, for this reason.
    pub stop: Option<StopReason>,
    /// Set when the run fails (Zeno).
    pub failure: Option<Divergence>,
    /// Events whose state change applies, in declaration order.
    pub setters: Vec<usize>,
}

/// The occurrences of the events of a run.
pub(super) struct EventBook {
    /// Events still firing (`max_count` not reached).
    pub enabled: Vec<bool>,
    counts: Vec<u32>,
    /// Per event: occurrences in a row close to the previous, and the time of the last.
    zeno: Vec<(u32, Real)>,
    /// Every occurrence (up to `MAX_RECORDS`).
    pub records: Vec<EventRecord>,
    /// The one that ended the run.
    pub terminal: Option<EventRecord>,
    overflow: bool,
}

impl EventBook {
    pub fn new(m: usize) -> Self {
        Self {
            enabled: vec![true; m],
            counts: vec![0; m],
            zeno: vec![(0, Real::NAN); m],
            records: Vec::new(),
            terminal: None,
            overflow: false,
        }
    }

    /// A stop condition that holds at the start: the run ends before any step.
    pub fn at_start(&mut self, event: &Event, i: usize, t0: Real, y: &[Real]) {
        let snap = Snapshot::of(t0, y);
        let rec = EventRecord {
            name: event.name().to_string(),
            occurrence: 1,
            t: t0,
            state: snap.clone(),
            last_step: snap.clone(),
            crossing_step: snap,
            after: None,
            terminal: true,
        };
        self.counts[i] = 1;
        self.records.push(rec.clone());
        self.terminal = Some(rec);
    }

    /// Books the occurrences of `fired` at `te` (state `y`), inside the step from `last` to
    /// `crossing`; `scale` is a typical step, for the Zeno watch.
    #[allow(clippy::too_many_arguments)]
    pub fn fire(
        &mut self,
        events: &[Event],
        fired: &[usize],
        te: Real,
        y: &[Real],
        last: (Real, &[Real]),
        crossing: (Real, &[Real]),
        scale: Real,
        step: u64,
        warnings: &mut Vec<String>,
    ) -> Outcome {
        let mut out = Outcome::default();
        for &i in fired {
            let e = &events[i];
            self.counts[i] += 1;
            let count = self.counts[i];
            // Zeno: firing again and again within a relative 1e-9 of the time
            let (run, previous) = self.zeno[i];
            let gap = 1e-9 * te.abs().max(scale.abs());
            // firing again within a few units in the last place of the time of its own last
            // occurrence: the state change there could not carry the function off zero for
            // any time the run resolves (an adaptive step is at least 10 ulps of t)
            let at_once = e.state_change().is_some()
                && te <= previous + ZENO_ULPS * ulp(previous.abs().max(te.abs()));
            let run = if te - previous <= gap { run + 1 } else { 0 };
            self.zeno[i] = (run, te);
            let why = if at_once {
                Some(format!(
                    "the event `{}` fired again at t = {} s right after its own state change there, within {ZENO_ULPS} units in the last place of t (occurrence {count}): its next occurrence came sooner than the run can resolve in time, so its occurrences accumulate at this instant (Zeno behaviour, like a ball bouncing infinitely often before it comes to rest); {ZENO_ADVICE}",
                    e.name(),
                    crate::error::short(te)
                ))
            } else if run >= ZENO_LIMIT {
                Some(format!(
                    "the event `{}` fired {ZENO_LIMIT} times in a row, each within {gap:.1e} s of the last, up to t = {} s (occurrence {count}): its occurrences accumulate at one instant (Zeno behaviour, like a ball bouncing infinitely often before coming to rest); {ZENO_ADVICE}",
                    e.name(),
                    crate::error::short(te)
                ))
            } else {
                None
            };
            if let Some(message) = why {
                out.failure = Some(Divergence {
                    t: te,
                    step,
                    quantity: e.name().to_string(),
                    value: Real::from(count),
                    message,
                });
                out.stop = Some(StopReason::Zeno);
            }
            if e.max_count.is_some_and(|mc| count >= mc) {
                self.enabled[i] = false;
            }
            let ends_run = matches!(e.action, EventAction::StopAt(k) if count >= k);
            if ends_run {
                out.stop.get_or_insert(StopReason::Event);
            } else if e.state_change().is_some() {
                out.setters.push(i);
            }
            let rec = EventRecord {
                name: e.name().to_string(),
                occurrence: count,
                t: te,
                state: Snapshot::of(te, y),
                last_step: Snapshot::of(last.0, last.1),
                crossing_step: Snapshot::of(crossing.0, crossing.1),
                after: None,
                terminal: ends_run,
            };
            if ends_run && self.terminal.is_none() {
                self.terminal = Some(rec.clone());
            }
            if self.records.len() < MAX_RECORDS {
                self.records.push(rec);
            } else if !self.overflow {
                self.overflow = true;
                warnings.push(format!(
                    "more than {MAX_RECORDS} event occurrences: only the first are reported"
                ));
            }
        }
        out
    }

    /// Applies the state changes of `setters` to `y` (each seeing the state at the event,
    /// `pre`, in declaration order); a change that makes the state non-finite is refused.
    pub fn apply(
        events: &[Event],
        setters: &[usize],
        pre: &Sample<'_>,
        sys: &ParticleSystem,
        y: &mut [Real],
    ) -> Result<(), Divergence> {
        let mut y_new = y.to_vec();
        for &i in setters {
            (events[i].state_change().expect("a setter"))(pre, sys, &mut y_new);
        }
        if let Some(i) = y_new.iter().position(|x| !x.is_finite()) {
            let name = coordinate_name(sys, i);
            return Err(Divergence {
                t: pre.t,
                step: pre.step,
                quantity: name.clone(),
                value: y_new[i],
                message: format!(
                    "the state change of the event `{}` at t = {} s made {name} = {}",
                    events[setters[0]].name(),
                    crate::error::short(pre.t),
                    y_new[i]
                ),
            });
        }
        y.copy_from_slice(&y_new);
        Ok(())
    }

    /// Notes the state after the state changes of `setters` at `te`.
    pub fn changed(&mut self, events: &[Event], setters: &[usize], te: Real, y: &[Real]) {
        for &i in setters {
            if let Some(r) = self
                .records
                .iter_mut()
                .rev()
                .find(|r| r.name == events[i].name() && r.t == te)
            {
                r.after = Some(Snapshot::of(te, y));
            }
        }
    }
}

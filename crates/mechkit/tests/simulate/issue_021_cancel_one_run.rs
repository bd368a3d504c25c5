//! Issue 21 (cancellation per run): stopping a run was one process-wide flag, so a caller
//! running several runs at once (a Python package, a browser app) could only stop them all.
//! Each run now holds its own [`Cancel`] handle. Checked here:
//! - two runs in parallel threads, each with its own handle: the one whose observer raises its
//!   own handle after N samples ends with `Interrupted` after N − 1 steps, while the other,
//!   which waits at its own N-th sample until the first was cancelled, still runs to `t_max`;
//! - a scenario whose handle is raised stops (`interrupted`) while another scenario, given
//!   none, runs to its `t_max`;
//! - a sweep cancelled after some of its runs starts no more runs: on one thread it holds
//!   exactly the rows finished before the cancel; on two threads a run in flight ends
//!   `interrupted`, no other run starts, and the call returns promptly.

use std::sync::atomic::{AtomicUsize, Ordering};
use std::thread;
use std::time::{Duration, Instant};

use mechkit::particles::Sample;
use mechkit::prelude::*;
use mechkit::scenario::Scenario;
use mechkit::scenario::sweep::{Parameter, Sampling, SweepGrid, SweepOptions, run_sweep};
use mechkit::simulate::{Cancel, Observer, ObserverError, RunReport};

/// Raises its run's own handle when it has seen `n` samples.
struct CancelAfter {
    n: usize,
    seen: usize,
    cancel: Cancel,
}

impl Observer for CancelAfter {
    fn observe(&mut self, _: &Sample<'_>) -> Result<(), ObserverError> {
        self.seen += 1;
        if self.seen == self.n {
            self.cancel.cancel();
        }
        Ok(())
    }
}

/// Holds its run at the `n`-th sample until `other` (another run's handle) is raised, so the
/// run is certainly in flight when the other one is cancelled.
struct WaitFor {
    n: usize,
    seen: usize,
    other: Cancel,
}

impl Observer for WaitFor {
    fn observe(&mut self, _: &Sample<'_>) -> Result<(), ObserverError> {
        self.seen += 1;
        if self.seen == self.n {
            let start = Instant::now();
            while !self.other.is_cancelled() {
                assert!(
                    start.elapsed() < Duration::from_mins(1),
                    "the other run was never cancelled"
                );
                thread::sleep(Duration::from_millis(1));
            }
        }
        Ok(())
    }
}

fn ball() -> ParticleSystem {
    ParticleSystem::builder(1)
        .body("ball", 1.0)
        .force(UniformGravity::new("gravity", vec![0], 9.81))
        .build()
        .unwrap()
}

#[test]
fn cancelling_one_of_two_parallel_runs_leaves_the_other_to_its_end() {
    const N: usize = 1000;
    let sys = ball();
    let start = State::from_qv(0.0, &[0.0], &[0.0]);
    let (a, b) = (Cancel::new(), Cancel::new());
    // a would take 10^12 steps (the step budget is only a safety net); b takes 20,000
    let long = Simulation::new(&sys, Method::EulerCromer, 1e-3)
        .t_max(1e9)
        .max_steps(50_000_000)
        .cancel_on(a.clone());
    let short = Simulation::new(&sys, Method::EulerCromer, 1e-3)
        .t_max(20.0)
        .cancel_on(b.clone());
    let (ra, rb): (RunReport, RunReport) = thread::scope(|s| {
        let ta = s.spawn(|| {
            let mut stop = CancelAfter {
                n: N,
                seen: 0,
                cancel: a.clone(),
            };
            long.run(start.clone(), &mut [&mut stop]).unwrap()
        });
        let tb = s.spawn(|| {
            let mut wait = WaitFor {
                n: N,
                seen: 0,
                other: a.clone(),
            };
            short.run(start.clone(), &mut [&mut wait]).unwrap()
        });
        (ta.join().unwrap(), tb.join().unwrap())
    });
    assert_eq!(ra.stop_reason, StopReason::Interrupted);
    // samples are step 0 and every step after it: the N-th sample is step N − 1
    assert_eq!(ra.steps, N as u64 - 1);
    assert!(
        ra.warnings
            .iter()
            .any(|w| w.starts_with("interrupted at t =")),
        "{:?}",
        ra.warnings
    );
    assert!(a.is_cancelled() && !b.is_cancelled());
    assert_eq!(rb.stop_reason, StopReason::TMax);
    assert_eq!(rb.final_state.t, 20.0);
    assert!(rb.steps >= 19_999, "{}", rb.steps);
}

/// A feather that would fall for a very long time, `T` seconds (1 µs steps).
const FALL: &str = r#"
[constants]
T = "1e7 s"
[[body]]
name = "feather"
mass = "1 g"
position = "2.4 m"
[[force]]
kind = "uniform-gravity"
[[force]]
name = "air"
kind = "expression"
F = "-0.04*v*abs(v)"
[integrator]
method = "euler-cromer"
dt = "1 us"
[stop]
t_max = "T"
max_steps = 100000000
"#;

#[test]
fn a_scenario_stops_when_its_own_handle_is_raised() {
    let endless = Scenario::from_str("endless.toml", FALL).unwrap();
    let short = Scenario::from_str("short.toml", &FALL.replace("1e7 s", "0.01 s")).unwrap();
    let cancel = endless.cancel.clone();
    let (a, b) = thread::scope(|s| {
        let a = s.spawn(|| endless.run().unwrap());
        let b = s.spawn(|| short.run().unwrap()).join().unwrap();
        // only once the short run has ended is the endless one cancelled
        cancel.cancel();
        (a.join().unwrap(), b)
    });
    assert_eq!(b.summary.stop_reason, "t_max");
    assert!(
        (b.summary.t_end - 0.01).abs() < 1e-12,
        "{}",
        b.summary.t_end
    );
    assert_eq!(a.summary.stop_reason, "interrupted");
    assert!(a.summary.t_end < 1e7, "{}", a.summary.t_end);

    // a handle raised before the run: nothing is simulated
    let mut raised = Scenario::from_str("raised.toml", FALL).unwrap();
    raised.cancel = Cancel::new();
    raised.cancel.cancel();
    let out = raised.run().unwrap();
    assert_eq!(out.summary.stop_reason, "interrupted");
    assert_eq!(out.summary.steps, 0);
}

/// A sweep of `FALL` over the list of durations `times` (seconds), on `threads` threads,
/// whose `on_done` calls `done` with the number of runs finished so far.
fn fall_sweep(
    times: &str,
    threads: usize,
    options: &SweepOptions,
    done: &(dyn Fn(usize) + Sync),
) -> mechkit::scenario::sweep::SweepTable {
    let grid = SweepGrid::new(
        vec![Parameter::parse(&format!("T={times}")).unwrap()],
        Sampling::Grid,
    );
    let finished = AtomicUsize::new(0);
    let on_done = || done(finished.fetch_add(1, Ordering::SeqCst) + 1);
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap()
        .install(|| run_sweep("fall.toml", FALL, &grid, options, &on_done))
        .unwrap()
}

#[test]
fn a_sweep_cancelled_after_five_runs_starts_no_more_on_one_thread() {
    let options = SweepOptions::default();
    let times = vec!["0.001"; 40].join(",");
    let table = fall_sweep(&times, 1, &options, &|n| {
        if n == 5 {
            options.cancel.cancel();
        }
    });
    assert_eq!(table.runs, 40);
    assert_eq!(table.rows.len(), 5);
    assert!(table.rows.iter().all(|r| r.stop_reason == "t_max"));
}

#[test]
fn a_sweep_cancelled_in_flight_interrupts_its_runs_and_returns_promptly() {
    // run 0 is short; every other run would take 10^13 steps
    let times = std::iter::once("0.001")
        .chain(std::iter::repeat_n("1e7", 19))
        .collect::<Vec<_>>()
        .join(",");
    let options = SweepOptions::default();
    let cancelled_at = std::sync::Mutex::new(None);
    let table = fall_sweep(&times, 2, &options, &|n| {
        if n == 1 {
            // the other thread has most likely taken run 10 (rayon splits the runs in
            // halves): give it a moment inside it
            thread::sleep(Duration::from_millis(100));
            *cancelled_at.lock().unwrap() = Some(Instant::now());
            options.cancel.cancel();
        }
    });
    let took = cancelled_at.lock().unwrap().expect("run 0 ended").elapsed();
    assert!(took < Duration::from_secs(10), "{took:?}");
    assert_eq!(table.runs, 20);
    // run 0 ended before the cancel; of the others at most the one in flight has a row
    assert_eq!(table.rows[0].index, 0);
    assert_eq!(table.rows[0].stop_reason, "t_max");
    assert!(table.rows.len() <= 2, "{} rows", table.rows.len());
    for r in &table.rows[1..] {
        assert_eq!(r.stop_reason, "interrupted", "run {}", r.index);
        assert!(r.t_end < 1e7);
    }
}

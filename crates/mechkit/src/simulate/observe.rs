//! Observers receive every sample of a run: writers of trajectory files, recorders, reductions.

use thiserror::Error;

use crate::Real;
use crate::particles::Sample;
use crate::simulate::StopReason;

/// An observer could not take a sample (typically an output file could not be written).
#[derive(Debug, Clone, PartialEq, Error)]
#[error("{0}")]
pub struct ObserverError(pub String);

/// Receives the samples of a run.
pub trait Observer {
    /// Called with the initial state (step 0), after every step, and with a located event
    /// (which replaces the step that crossed it).
    fn observe(&mut self, sample: &Sample<'_>) -> Result<(), ObserverError>;

    /// The first step after `step` whose [`SampleKind::Step`](crate::particles::SampleKind)
    /// sample this observer needs, or `None` when it needs none before the end (it still gets
    /// events, output times and [`Observer::finish`]). The default, every step, is always
    /// right; an observer that keeps every n-th step says so, and a fixed-step run may then
    /// run the steps in between in a compiled kernel without building their samples.
    fn next_step(&self, step: u64) -> Option<u64> {
        Some(step + 1)
    }

    /// Why the run must stop now, if it must: an output file reached its size limit
    /// ([`StopReason::OutputLimit`]) or could not be written ([`StopReason::OutputError`]).
    /// Checked before every step; the run then ends with that reason and this message among
    /// its warnings.
    fn halt(&self) -> Option<(StopReason, String)> {
        None
    }

    /// Called once at the end with the final sample (already passed to `observe`).
    fn finish(&mut self, _last: &Sample<'_>) -> Result<(), ObserverError> {
        Ok(())
    }
}

/// Keeps `t`, positions and velocities of every `every`-th sample (and the last) in memory.
#[derive(Debug, Clone, Default)]
pub struct Recorder {
    every: u64,
    /// Times.
    pub t: Vec<Real>,
    /// Positions per kept sample.
    pub q: Vec<Vec<Real>>,
    /// Velocities per kept sample.
    pub v: Vec<Vec<Real>>,
    last_step: Option<u64>,
}

impl Recorder {
    /// Keeps every `every`-th step.
    pub fn new(every: u64) -> Self {
        Self {
            every: every.max(1),
            ..Self::default()
        }
    }

    fn push(&mut self, s: &Sample<'_>) {
        self.t.push(s.t);
        self.q.push(s.q.to_vec());
        self.v.push(s.v.to_vec());
        self.last_step = Some(s.step);
    }
}

impl Observer for Recorder {
    fn observe(&mut self, s: &Sample<'_>) -> Result<(), ObserverError> {
        if s.step.is_multiple_of(self.every) {
            self.push(s);
        }
        Ok(())
    }

    fn next_step(&self, step: u64) -> Option<u64> {
        Some((step / self.every + 1) * self.every)
    }

    fn finish(&mut self, s: &Sample<'_>) -> Result<(), ObserverError> {
        if self.t.last() != Some(&s.t) {
            self.push(s);
        }
        Ok(())
    }
}

//! Stopping a run from outside: a [`Cancel`] handle, one per run (or per sweep, or per
//! process for the command line), that another thread or a signal handler raises. A run
//! given one ([`Simulation::cancel_on`](super::Simulation::cancel_on)) looks at it before
//! every step and stops cleanly with [`StopReason::Interrupted`](super::StopReason::Interrupted):
//! the samples so far have reached the observers, the report is complete up to the last step,
//! and output files are finished as for any other stop. Raising one handle stops only the runs
//! that hold it (or a clone of it).

use std::fmt;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

/// A request to stop, shared by its clones: raising any clone raises them all.
///
/// # Example
/// ```
/// use mechkit::prelude::*;
/// use mechkit::simulate::Cancel;
/// # let system = ParticleSystem::builder(1)
/// #     .body("ball", 1.0)
/// #     .force(UniformGravity::new("gravity", vec![0], 9.81))
/// #     .build()
/// #     .unwrap();
/// let cancel = Cancel::new();
/// let run = Simulation::new(&system, Method::EulerCromer, 1e-3)
///     .t_max(10.0)
///     .cancel_on(cancel.clone());
/// // another thread (or a Ctrl-C handler) raises its clone
/// let other = cancel.clone();
/// std::thread::spawn(move || other.cancel()).join().unwrap();
/// assert!(cancel.is_cancelled());
/// let report = run.run(State::from_qv(0.0, &[0.0], &[0.0]), &mut []).unwrap();
/// assert_eq!(report.stop_reason, StopReason::Interrupted);
/// assert_eq!(report.steps, 0);
/// // a run without the handle goes to its end
/// let free = Simulation::new(&system, Method::EulerCromer, 1e-3).t_max(10.0);
/// let report = free.run(State::from_qv(0.0, &[0.0], &[0.0]), &mut []).unwrap();
/// assert_eq!(report.stop_reason, StopReason::TMax);
/// ```
#[derive(Clone, Default)]
pub struct Cancel {
    stop: Arc<AtomicBool>,
    urgent: Arc<AtomicBool>,
}

impl Cancel {
    /// A handle not yet raised.
    pub fn new() -> Self {
        Self::default()
    }

    /// Asks the runs holding this handle to stop after their current step.
    pub fn cancel(&self) {
        self.stop.store(true, Ordering::Relaxed);
    }

    /// Whether a stop was asked for.
    #[inline]
    pub fn is_cancelled(&self) -> bool {
        self.stop.load(Ordering::Relaxed) || self.is_urgent()
    }

    /// Asks for a stop in a hurry (a second Ctrl-C, SIGTERM): the runs stop after their
    /// current step as for [`Cancel::cancel`], and whoever finishes the outputs keeps to
    /// what cannot be lost (the streamed files, the summary) and skips what takes time
    /// (plots, animations).
    pub fn cancel_urgently(&self) {
        self.urgent.store(true, Ordering::Relaxed);
        self.cancel();
    }

    /// Whether a stop in a hurry was asked for ([`Cancel::cancel_urgently`]).
    #[inline]
    pub fn is_urgent(&self) -> bool {
        self.urgent.load(Ordering::Relaxed)
    }

    /// The flag itself, for a signal handler to raise (`signal_hook::flag::register`).
    pub fn flag(&self) -> Arc<AtomicBool> {
        Arc::clone(&self.stop)
    }
}

impl fmt::Debug for Cancel {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Cancel")
            .field("cancelled", &self.is_cancelled())
            .finish()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clones_share_the_request_and_others_do_not() {
        let a = Cancel::new();
        let b = a.clone();
        let other = Cancel::new();
        assert!(!b.is_cancelled());
        a.cancel();
        assert!(b.is_cancelled());
        assert!(!other.is_cancelled());
        // what a signal handler stores through the flag is seen by the handle
        other.flag().store(true, Ordering::Relaxed);
        assert!(other.is_cancelled());
        assert_eq!(format!("{a:?}"), "Cancel { cancelled: true }");
        assert!(!a.is_urgent());
        let hurry = Cancel::new();
        hurry.clone().cancel_urgently();
        assert!(hurry.is_urgent() && hurry.is_cancelled());
    }
}

/// How far a run has come: the time of its latest sample, shared with whoever shows it (a
/// progress bar, a browser page). A run holding a clone updates it every few thousand steps
/// and at every output sample; reading it never slows the run.
///
/// ```
/// let p = mechkit::simulate::Progress::new();
/// assert!(p.time().is_nan());
/// ```
#[derive(Clone)]
pub struct Progress(Arc<std::sync::atomic::AtomicU64>);

impl Default for Progress {
    fn default() -> Self {
        Self(Arc::new(std::sync::atomic::AtomicU64::new(
            crate::Real::NAN.to_bits(),
        )))
    }
}

impl Progress {
    /// A handle that has seen no sample yet ([`Progress::time`] is NaN).
    pub fn new() -> Self {
        Self::default()
    }

    /// Records the time of the latest sample.
    #[inline]
    pub fn set(&self, t: crate::Real) {
        self.0.store(t.to_bits(), Ordering::Relaxed);
    }

    /// The time of the latest sample, NaN before the first.
    pub fn time(&self) -> crate::Real {
        crate::Real::from_bits(self.0.load(Ordering::Relaxed))
    }
}

impl fmt::Debug for Progress {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Progress").field("t", &self.time()).finish()
    }
}

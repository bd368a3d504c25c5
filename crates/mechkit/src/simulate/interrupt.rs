//! Stopping a run from outside: one process-wide flag that a signal handler (the command
//! line's Ctrl-C) or another thread raises. Runs look at it before every step and stop
//! cleanly with [`StopReason::Interrupted`](super::StopReason::Interrupted): the samples so
//! far have reached the observers, the report is complete up to the last step, and output
//! files are finished as for any other stop.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, LazyLock};

static FLAG: LazyLock<Arc<AtomicBool>> = LazyLock::new(|| Arc::new(AtomicBool::new(false)));

/// The flag itself, for a signal handler to raise (`signal_hook::flag::register`).
pub fn flag() -> Arc<AtomicBool> {
    Arc::clone(&FLAG)
}

/// Asks every run in this process to stop after its current step.
pub fn request() {
    FLAG.store(true, Ordering::Relaxed);
}

/// Lowers the flag (runs started afterwards go to their end).
pub fn clear() {
    FLAG.store(false, Ordering::Relaxed);
}

/// Whether a stop was asked for.
#[inline]
pub fn requested() -> bool {
    FLAG.load(Ordering::Relaxed)
}

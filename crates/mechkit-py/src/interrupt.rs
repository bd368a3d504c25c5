//! Long computations that Ctrl-C stops: the work runs on a worker thread while the calling
//! thread, with the GIL released, wakes every [`POLL`] to let Python run its signal handlers.
//! A handler's exception (KeyboardInterrupt) raises the work's [`Cancel`], so the run stops
//! after its current step; once it has, the exception is raised in Python.

use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

use mechkit::simulate::Cancel;
use pyo3::prelude::*;

/// How often the calling thread looks for signals while the work runs.
pub const POLL: Duration = Duration::from_millis(50);

/// Runs `work` with the GIL released; on an exception from a signal handler, raises `cancel`
/// (which `work`'s run must hold), waits for `work` to return and gives the exception.
///
/// Signal handlers run only on Python's main thread: called from another, this waits for the
/// work to end.
pub fn run<T, F>(py: Python<'_>, cancel: &Cancel, work: F) -> PyResult<T>
where
    T: Send,
    F: FnOnce() -> T + Send,
{
    let caller = std::thread::current();
    let done = AtomicBool::new(false);
    std::thread::scope(|scope| {
        let (caller, done_flag) = (&caller, &done);
        let worker = scope.spawn(move || {
            let out = work();
            done_flag.store(true, Ordering::Release);
            caller.unpark();
            out
        });
        let mut interrupted: Option<PyErr> = None;
        while !done.load(Ordering::Acquire) {
            py.detach(|| std::thread::park_timeout(POLL));
            // a second Ctrl-C while the run finishes its step is the same request
            if let Err(e) = py.check_signals()
                && interrupted.is_none()
            {
                cancel.cancel();
                interrupted = Some(e);
            }
        }
        let out = py.detach(move || worker.join());
        let out = out.unwrap_or_else(|panic| std::panic::resume_unwind(panic));
        match interrupted {
            Some(e) => Err(e),
            None => Ok(out),
        }
    })
}

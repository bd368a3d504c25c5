//! The runs: those going on (at most `--max-runs`) and the last [`KEPT_RUNS`] finished, each
//! with its directory under the server's scratch folder.

use std::collections::VecDeque;
use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard};
use std::time::Instant;

use mechkit::simulate::{Cancel, Progress};
use serde::Serialize;

use super::error::ApiError;

/// How many finished runs are kept (with their files); the oldest goes first.
pub const KEPT_RUNS: usize = 16;

/// A run's outcome, once it has ended.
#[derive(Debug, Clone, Default)]
pub struct Finished {
    /// Whether it ran to its end (else `error` says why not).
    pub ok: bool,
    /// `summary.json`, if the run got that far.
    pub summary: Option<serde_json::Value>,
    /// What went wrong.
    pub error: Option<String>,
    /// The plot files, in the scenario's order.
    pub plots: Vec<String>,
    /// The HTML player, if drawn.
    pub animation: Option<String>,
    /// Every file of the run's directory, with its size.
    pub files: Vec<(String, u64)>,
}

/// One run.
#[derive(Debug)]
pub struct Run {
    /// Its number.
    pub id: u64,
    /// Where its files go.
    pub dir: PathBuf,
    /// Stops it (the time limit, a stop asked for, the server's end).
    pub cancel: Cancel,
    /// The time it has reached.
    pub progress: Progress,
    /// Its end time, if it has one.
    pub t_max: Option<f64>,
    /// When it started.
    pub started: Instant,
    /// Its outcome, once it has ended.
    pub finished: Option<Finished>,
    /// Files still being drawn after the end.
    pub pending: Vec<String>,
    /// Whether its thread is still at work (running, or drawing the GIF after the end): it
    /// holds its place among `--max-runs` until then.
    pub working: bool,
}

/// A file of a run, as the API lists it.
#[derive(Debug, Serialize)]
pub struct FileLink {
    /// Its name in the run's directory.
    pub name: String,
    /// Where to get it.
    pub url: String,
    /// Its size in bytes (0 for a plot listed before its file is read).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bytes: Option<u64>,
}

/// `GET /api/run/{id}`.
#[derive(Debug, Serialize)]
pub struct RunView {
    /// The run's number.
    pub id: u64,
    /// `running`, `done` or `failed`.
    pub state: &'static str,
    /// The fraction of `t_max` reached, 0 to 1 (1 once ended).
    pub progress: f64,
    /// The time reached (s).
    pub t: Option<f64>,
    /// The end time (s), if the scenario has one.
    pub t_max: Option<f64>,
    /// Wall-clock seconds since it started.
    pub seconds: f64,
    /// `summary.json`.
    pub summary: Option<serde_json::Value>,
    /// What went wrong.
    pub error: Option<String>,
    /// The plots.
    pub plots: Vec<FileLink>,
    /// The HTML player.
    pub animation: Option<String>,
    /// Every file of the run.
    pub files: Vec<FileLink>,
    /// Files still being drawn after the end (`animation.gif`), listed once written.
    pub pending: Vec<String>,
}

/// The runs, behind one lock held only to read or change the list.
#[derive(Debug)]
pub struct Registry {
    root: PathBuf,
    max_running: usize,
    inner: Mutex<Inner>,
}

#[derive(Debug, Default)]
struct Inner {
    next: u64,
    runs: VecDeque<Run>,
}

impl Registry {
    /// Runs go in folders under `root` (created), at most `max_running` at once.
    pub fn new(root: PathBuf, max_running: usize) -> std::io::Result<Self> {
        create_private_dir(&root)?;
        Ok(Self {
            root,
            max_running,
            inner: Mutex::new(Inner::default()),
        })
    }

    fn lock(&self) -> MutexGuard<'_, Inner> {
        // a handler that panicked holding the lock left the list whole: go on with it
        self.inner
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
    }

    /// Registers a new run with its own empty folder: 429 when `max_running` are going on.
    /// Drops the oldest finished runs (and their files) beyond [`KEPT_RUNS`].
    pub fn start(
        &self,
        cancel: Cancel,
        progress: Progress,
        t_max: Option<f64>,
    ) -> Result<(u64, PathBuf), ApiError> {
        let mut inner = self.lock();
        let running = inner.runs.iter().filter(|r| r.working).count();
        if running >= self.max_running {
            return Err(ApiError::new(
                axum::http::StatusCode::TOO_MANY_REQUESTS,
                format!(
                    "{running} runs are going on, as many as the server allows (--max-runs): try again when one has ended"
                ),
            ));
        }
        while inner.runs.iter().filter(|r| !r.working).count() >= KEPT_RUNS {
            let Some(oldest) = inner.runs.iter().position(|r| !r.working) else {
                break;
            };
            if let Some(run) = inner.runs.remove(oldest) {
                let _ = std::fs::remove_dir_all(&run.dir);
            }
        }
        inner.next += 1;
        let id = inner.next;
        let dir = self.root.join(format!("run-{id}"));
        create_private_dir(&dir)
            .map_err(|e| ApiError::internal(format!("cannot create the run's folder: {e}")))?;
        inner.runs.push_back(Run {
            id,
            dir: dir.clone(),
            cancel,
            progress,
            t_max,
            started: Instant::now(),
            finished: None,
            pending: Vec::new(),
            working: true,
        });
        Ok((id, dir))
    }

    /// Records the end of run `id`; `pending` files are still to be drawn.
    pub fn finish(&self, id: u64, finished: Finished, pending: &[String]) {
        if let Some(run) = self.lock().runs.iter_mut().find(|r| r.id == id) {
            run.pending = pending.to_vec();
            run.finished = Some(finished);
        }
    }

    /// Records that run `id`'s thread is done: its files are `files` now, and `problem` (if
    /// any) went wrong after the end. A run that never finished failed with `problem`.
    pub fn settle(&self, id: u64, files: Vec<(String, u64)>, problem: Option<String>) {
        if let Some(run) = self.lock().runs.iter_mut().find(|r| r.id == id) {
            run.working = false;
            run.pending.clear();
            let finished = run.finished.get_or_insert_with(Finished::default);
            finished.files = files;
            if let Some(p) = problem {
                finished.ok = false;
                finished.error = Some(match finished.error.take() {
                    Some(e) => format!("{e}\n{p}"),
                    None => p,
                });
            }
        }
    }

    /// Run `id` as the API shows it.
    pub fn view(&self, id: u64) -> Option<RunView> {
        let inner = self.lock();
        let run = inner.runs.iter().find(|r| r.id == id)?;
        let link = |name: &str, bytes: Option<u64>| FileLink {
            name: name.to_string(),
            url: format!("/api/run/{id}/file/{name}"),
            bytes,
        };
        let t = run.progress.time();
        let t = t.is_finite().then_some(t);
        let mut view = RunView {
            id,
            state: "running",
            progress: match (t, run.t_max) {
                (Some(t), Some(t_max)) if t_max > 0.0 => (t / t_max).clamp(0.0, 1.0),
                _ => 0.0,
            },
            t,
            t_max: run.t_max,
            seconds: run.started.elapsed().as_secs_f64(),
            summary: None,
            error: None,
            plots: Vec::new(),
            animation: None,
            files: Vec::new(),
            pending: Vec::new(),
        };
        if let Some(f) = &run.finished {
            view.state = if f.ok { "done" } else { "failed" };
            view.progress = 1.0;
            view.summary.clone_from(&f.summary);
            view.error.clone_from(&f.error);
            view.plots = f.plots.iter().map(|p| link(p, None)).collect();
            view.animation = f.animation.as_deref().map(|a| link(a, None).url);
            view.files = f.files.iter().map(|(n, b)| link(n, Some(*b))).collect();
            view.pending.clone_from(&run.pending);
        }
        Some(view)
    }

    /// The file `name` of finished run `id`, if it is one of the run's own.
    pub fn file(&self, id: u64, name: &str) -> Option<PathBuf> {
        let inner = self.lock();
        let run = inner.runs.iter().find(|r| r.id == id)?;
        let finished = run.finished.as_ref()?;
        finished
            .files
            .iter()
            .any(|(n, _)| n == name)
            .then(|| run.dir.join(name))
    }

    /// Asks run `id` to stop; false if there is no such run going on.
    pub fn stop(&self, id: u64) -> bool {
        let inner = self.lock();
        let run = inner
            .runs
            .iter()
            .find(|r| r.id == id && r.finished.is_none());
        run.inspect(|r| r.cancel.cancel()).is_some()
    }

    /// Asks every run to stop (the server is ending).
    pub fn stop_all(&self) {
        for run in &self.lock().runs {
            run.cancel.cancel();
        }
    }
}

impl Drop for Registry {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.root);
    }
}

/// A folder only this user may read (the runs' outputs are theirs).
fn create_private_dir(dir: &Path) -> std::io::Result<()> {
    let mut builder = std::fs::DirBuilder::new();
    builder.recursive(true);
    #[cfg(unix)]
    std::os::unix::fs::DirBuilderExt::mode(&mut builder, 0o700);
    builder.create(dir)
}

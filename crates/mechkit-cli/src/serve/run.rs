//! `POST /api/run` (start a run: 202 with its id, 429 when `--max-runs` are going on),
//! `GET /api/run/{id}` (its state, progress and files), `GET /api/run/{id}/file/{name}` (one
//! of its files) and `POST /api/run/{id}/stop`.
//!
//! A run is `mechkit run -o DIR` into a folder of the server's: `trajectory.csv` and
//! `summary.json` (`Scenario::run_to_dir`), the plots as the command draws them, and the
//! animation as `animation.html` (shown in the app); the run is then done, and its thread
//! draws `animation.gif` (listed as pending until written: a debug build takes seconds).

use std::path::Path;
use std::sync::{Arc, Weak};
use std::time::{Duration, Instant};

use axum::Json;
use axum::extract::rejection::{JsonRejection, PathRejection};
use axum::extract::{Path as UrlPath, State};
use axum::http::{StatusCode, header};
use axum::response::{IntoResponse, Response};
use mechkit::animation::{Animation, AnimationFormat, AnimationOptions};
use mechkit::scenario::{RunOutput, Scenario, format_size};
use mechkit::simulate::Cancel;
use serde::Serialize;

use super::app::{App, ScenarioRequest};
use super::error::ApiError;
use super::registry::{Finished, RunView};
use crate::animate::Canvas;
use crate::args::PlotFormat;

/// `POST /api/run`'s answer.
#[derive(Debug, Serialize)]
pub struct Started {
    /// The run's number, for `GET /api/run/{id}`.
    pub id: u64,
}

/// `POST /api/run`: checks the scenario (400 with its error when invalid), and starts it on a
/// blocking thread, stopped after the time limit.
pub async fn start(
    State(app): State<Arc<App>>,
    body: Result<Json<ScenarioRequest>, JsonRejection>,
) -> Result<(StatusCode, Json<Started>), ApiError> {
    let Json(req) = body?;
    let shared = Arc::clone(&app);
    let built = tokio::task::spawn_blocking(move || shared.scenario(&req))
        .await
        .map_err(|e| ApiError::internal(format!("reading the scenario failed: {e}")))??;
    let mut scenario = built.map_err(|e| {
        let at = e.location.as_ref().map_or_else(String::new, |l| {
            format!("line {}, column {}: ", l.line, l.column)
        });
        ApiError::bad_request(format!("the scenario is not valid: {at}{}", e.message))
    })?;
    scenario.max_output = scenario.max_output.min(app.limits.output);
    let cancel = Cancel::new();
    scenario.cancel = cancel.clone();
    let (id, dir) =
        app.registry
            .start(cancel.clone(), scenario.progress.clone(), scenario.t_max)?;
    let limit = app.limits.run_time;
    let watchdog = tokio::spawn(async move {
        tokio::time::sleep(limit).await;
        cancel.cancel();
    });
    tokio::spawn(async move {
        // a weak handle: a GIF still being drawn when the server ends does not keep its
        // state (and folders) alive
        let shared = Arc::downgrade(&app);
        let folder = dir.clone();
        let job =
            tokio::task::spawn_blocking(move || work(&shared, id, &scenario, &dir, limit)).await;
        watchdog.abort();
        if let Err(e) = job {
            let problem = format!("the run failed: {e}");
            app.registry.settle(id, listing(&folder), Some(problem));
        }
    });
    Ok((StatusCode::ACCEPTED, Json(Started { id })))
}

/// Run `id`'s thread: the run, its plots and HTML player ([`execute`]), recorded as its end;
/// then the GIF, recorded as the thread's end. Nothing is recorded once the server has gone.
fn work(app: &Weak<App>, id: u64, scenario: &Scenario, dir: &Path, limit: Duration) {
    let (finished, animation) = execute(scenario, dir, limit);
    let gif = AnimationFormat::Gif.file_name();
    let pending = animation.iter().map(|_| gif.clone()).collect::<Vec<_>>();
    match app.upgrade() {
        Some(app) => app.registry.finish(id, finished, &pending),
        None => return,
    }
    // the GIF last: the app shows the HTML player, the GIF is a download
    let problem = animation.and_then(|a| {
        crate::commands::animate::write(&a, &[AnimationFormat::Gif], Canvas::default(), dir)
            .err()
            .map(|e| format!("{gif}: {}", crate::failure::message(&e)))
    });
    if let Some(app) = app.upgrade() {
        app.registry.settle(id, listing(dir), problem);
    }
}

/// `GET /api/run/{id}`.
pub async fn view(
    State(app): State<Arc<App>>,
    id: Result<UrlPath<u64>, PathRejection>,
) -> Result<Json<RunView>, ApiError> {
    let UrlPath(id) = id?;
    app.registry.view(id).map(Json).ok_or_else(|| no_run(id))
}

/// `POST /api/run/{id}/stop`: the run stops after its current step, keeping its outputs.
pub async fn stop(
    State(app): State<Arc<App>>,
    id: Result<UrlPath<u64>, PathRejection>,
) -> Result<Json<Started>, ApiError> {
    let UrlPath(id) = id?;
    if app.registry.stop(id) {
        Ok(Json(Started { id }))
    } else {
        Err(ApiError::not_found(format!("no run {id} is going on")))
    }
}

/// `GET /api/run/{id}/file/{name}`: a file the run's listing names, nothing else.
pub async fn file(
    State(app): State<Arc<App>>,
    path: Result<UrlPath<(u64, String)>, PathRejection>,
) -> Result<Response, ApiError> {
    let UrlPath((id, name)) = path?;
    let path = app
        .registry
        .file(id, &name)
        .ok_or_else(|| ApiError::not_found(format!("run {id} has no file `{name}`")))?;
    let bytes = tokio::task::spawn_blocking(move || {
        mechkit::csv::read_bounded(&path, mechkit::csv::MAX_DATA_BYTES)
    })
    .await
    .map_err(|e| ApiError::internal(format!("reading the file failed: {e}")))?
    .map_err(|e| ApiError::not_found(format!("cannot read `{name}`: {e}")))?;
    Ok((
        [
            (header::CONTENT_TYPE, content_type(&name)),
            (header::X_CONTENT_TYPE_OPTIONS, "nosniff"),
            (header::CACHE_CONTROL, "no-store"),
            (header::CONTENT_SECURITY_POLICY, RUN_FILE_POLICY),
        ],
        bytes,
    )
        .into_response())
}

/// What a run's file may do when opened: the player runs its own inline script and styles,
/// and loads nothing; only the app may frame it.
const RUN_FILE_POLICY: &str = "default-src 'none'; script-src 'unsafe-inline'; \
     style-src 'unsafe-inline'; img-src 'self' data:; frame-ancestors 'self'";

fn no_run(id: u64) -> ApiError {
    ApiError::not_found(format!(
        "no run {id}: it never was, or it was dropped (the server keeps the last {})",
        super::registry::KEPT_RUNS
    ))
}

/// The media type of a run's file, by its extension.
fn content_type(name: &str) -> &'static str {
    match name.rsplit('.').next().unwrap_or("") {
        "svg" => "image/svg+xml",
        "png" => "image/png",
        "gif" => "image/gif",
        "html" => "text/html; charset=utf-8",
        "json" => "application/json",
        "csv" => "text/csv; charset=utf-8",
        "xyz" | "txt" => "text/plain; charset=utf-8",
        _ => "application/octet-stream",
    }
}

/// Runs `scenario` into `dir` as `mechkit run -o DIR` does, then draws its plots and its
/// HTML player; returns the outcome and the animation (for the GIF). A run stopped by its
/// handle after `limit` ran out of time.
fn execute(scenario: &Scenario, dir: &Path, limit: Duration) -> (Finished, Option<Animation>) {
    let started = Instant::now();
    let mut finished = Finished::default();
    let mut out = match scenario.run_to_dir(dir) {
        Ok(out) => out,
        Err(e) => {
            finished.error = Some(e.to_string());
            finished.files = listing(dir);
            return (finished, None);
        }
    };
    let ran_for = started.elapsed();
    let mut problems = Vec::new();
    problems.extend(stopped_early(scenario, &out, ran_for, limit));
    if let Err(e) = crate::plot::render_run(scenario, &mut out, dir, PlotFormat::default()) {
        problems.push(format!("the plots: {}", crate::failure::message(&e)));
    }
    let animation = match animate(scenario, dir) {
        Ok(animation) => {
            finished.animation = Some(AnimationFormat::Html.file_name());
            Some(animation)
        }
        Err(e) => {
            problems.push(format!("the animation: {}", crate::failure::message(&e)));
            None
        }
    };
    finished.plots.clone_from(&out.summary.files.plots);
    finished.summary = serde_json::to_value(&out.summary).ok();
    finished.ok = problems.is_empty();
    finished.error = (!problems.is_empty()).then(|| problems.join("\n"));
    finished.files = listing(dir);
    (finished, animation)
}

/// Why the run ended before its end, in words: the time limit, a stop asked for, its output
/// limit, or a failed computation.
fn stopped_early(
    scenario: &Scenario,
    out: &RunOutput,
    ran_for: Duration,
    limit: Duration,
) -> Option<String> {
    let s = &out.summary;
    let held = "the outputs hold the run up to there";
    match s.stop_reason.as_str() {
        "interrupted" if ran_for >= limit.mul_f64(0.99) => Some(format!(
            "the run reached the server's time limit of {} s (--max-run-seconds) at t = {} s: {held}",
            mechkit::expr::short_number(limit.as_secs_f64()),
            mechkit::expr::short_number(s.t_end)
        )),
        "interrupted" => Some(format!(
            "the run was stopped at t = {} s: {held}",
            mechkit::expr::short_number(s.t_end)
        )),
        "output_limit" => Some(format!(
            "the run stopped at t = {} s because its output reached the limit ({}): {held}",
            mechkit::expr::short_number(s.t_end),
            format_size(scenario.max_output)
        )),
        "output_error" => Some(format!(
            "the run stopped at t = {} s because its output could not be written",
            mechkit::expr::short_number(s.t_end)
        )),
        _ if out.failed() => {
            let what = match s.stop_reason.as_str() {
                "diverged" => "the simulation diverged",
                "step_too_small" => "the adaptive step size underflowed",
                "zeno" => "an event fired endlessly",
                _ => "the simulation failed",
            };
            Some(match &s.divergence {
                Some(d) => format!("{what}: {}", d.message),
                None => what.to_string(),
            })
        }
        _ => None,
    }
}

/// The run's animation, written as the HTML player that the app shows.
fn animate(scenario: &Scenario, dir: &Path) -> anyhow::Result<Animation> {
    let path = dir.join("trajectory.csv");
    let table = mechkit::data::Table::read(&path)?;
    let animation =
        crate::commands::animate::build(scenario, &table, &AnimationOptions::default())?;
    crate::commands::animate::write(&animation, &[AnimationFormat::Html], Canvas::default(), dir)?;
    Ok(animation)
}

/// The regular files of the run's folder, by name, with their sizes.
fn listing(dir: &Path) -> Vec<(String, u64)> {
    let mut files: Vec<(String, u64)> = std::fs::read_dir(dir)
        .map(|entries| {
            entries
                .flatten()
                .filter(|e| e.file_type().is_ok_and(|t| t.is_file()))
                .map(|e| {
                    let bytes = e.metadata().map_or(0, |m| m.len());
                    (e.file_name().to_string_lossy().into_owned(), bytes)
                })
                .collect()
        })
        .unwrap_or_default();
    files.sort();
    files
}

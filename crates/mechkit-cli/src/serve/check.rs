//! `POST /api/check {name, text, set?}`: the scenario read and checked as `mechkit check`
//! does, its error at its line and column.

use std::sync::Arc;

use axum::Json;
use axum::extract::State;
use axum::extract::rejection::JsonRejection;
use mechkit::scenario::{CheckReport, ScenarioError};
use serde::Serialize;

use super::app::{App, ScenarioRequest};
use super::error::ApiError;

/// An error of a scenario, where the CLI prints it (`file.toml:LINE:COLUMN`).
#[derive(Debug, Serialize)]
pub struct Located {
    /// 1-based line, if the error is at a place in the text.
    pub line: Option<usize>,
    /// 1-based column, in characters.
    pub column: Option<usize>,
    /// How many characters the error spans.
    pub width: Option<usize>,
    /// What is wrong.
    pub message: String,
    /// What would fix it.
    pub hint: Option<String>,
}

impl From<&ScenarioError> for Located {
    fn from(e: &ScenarioError) -> Self {
        let loc = e.location.as_deref();
        Self {
            line: loc.map(|l| l.line),
            column: loc.map(|l| l.column),
            width: loc.map(|l| l.width.max(1)),
            message: e.message.clone(),
            hint: e.hint.clone(),
        }
    }
}

/// The answer: `ok` with the setup and its warnings, or the errors.
#[derive(Debug, Serialize)]
pub struct Checked {
    /// Whether the scenario is valid.
    pub ok: bool,
    /// Its errors (the first the library finds).
    pub errors: Vec<Located>,
    /// Warnings about its setup.
    pub warnings: Vec<String>,
    /// What it sets up (`mechkit check --json`), when valid.
    pub report: Option<CheckReport>,
}

/// `POST /api/check`.
pub async fn check(
    State(app): State<Arc<App>>,
    body: Result<Json<ScenarioRequest>, JsonRejection>,
) -> Result<Json<Checked>, ApiError> {
    let Json(req) = body?;
    let checked = tokio::task::spawn_blocking(move || {
        app.scenario(&req).map(|scenario| match scenario {
            Ok(s) => {
                let report = s.check_report();
                Checked {
                    ok: true,
                    errors: Vec::new(),
                    warnings: report.warnings.clone(),
                    report: Some(report),
                }
            }
            Err(e) => Checked {
                ok: false,
                errors: vec![Located::from(&e)],
                warnings: Vec::new(),
                report: None,
            },
        })
    })
    .await
    .map_err(|e| ApiError::internal(format!("the check failed: {e}")))??;
    Ok(Json(checked))
}

//! `GET /api/files` (the workspace's scenario files and the gallery's cases) and
//! `GET /api/file?path=REL` (one file's text).

use std::sync::Arc;

use axum::Json;
use axum::extract::rejection::QueryRejection;
use axum::extract::{Query, State};
use axum::http::StatusCode;
use mechkit::scenario::{MAX_SCENARIO_BYTES, format_size};
use serde::{Deserialize, Serialize};

use super::app::{App, GALLERY};
use super::error::ApiError;
use super::workspace::{Listed, MAX_LISTED};
use crate::commands::gallery_run::BOOK;

/// A case of the gallery.
#[derive(Debug, Serialize)]
pub struct GalleryCase {
    /// Its id.
    pub id: String,
    /// Its chapter of the course.
    pub chapter: u32,
    /// What it is about.
    pub topic: String,
    /// The question asked.
    pub asked: String,
    /// Its scenarios, to open (`gallery:STEM.toml`); a case answered by a script alone has
    /// none (`mechkit gallery ID` runs it).
    pub scenarios: Vec<String>,
}

/// `GET /api/files`.
#[derive(Debug, Serialize)]
pub struct FileList {
    /// The workspace's canonical path.
    pub workspace: String,
    /// Its scenario files.
    pub files: Vec<Listed>,
    /// Whether the list stopped at its limit.
    pub truncated: bool,
    /// The gallery's cases.
    pub gallery: Vec<GalleryCase>,
}

/// `GET /api/files`.
pub async fn list(State(app): State<Arc<App>>) -> Result<Json<FileList>, ApiError> {
    tokio::task::spawn_blocking(move || {
        let files = app.workspace.scenario_files();
        let gallery = app.gallery.as_ref().map_or_else(Vec::new, |g| {
            g.cases
                .iter()
                .map(|case| GalleryCase {
                    id: case.id.clone(),
                    chapter: case.chapter,
                    topic: case.topic.clone(),
                    asked: case.asked.clone(),
                    scenarios: g
                        .files
                        .iter()
                        .filter(|(stem, ext)| *ext == "toml" && case.expected_of(stem).is_some())
                        .map(|(stem, _)| format!("{GALLERY}{stem}.toml"))
                        .collect(),
                })
                .collect()
        });
        Json(FileList {
            workspace: app.workspace.root().display().to_string(),
            truncated: files.len() >= MAX_LISTED,
            files,
            gallery,
        })
    })
    .await
    .map_err(|e| ApiError::internal(format!("the listing failed: {e}")))
}

/// `?path=REL`: a path relative to the workspace, or `gallery:STEM.toml`.
#[derive(Debug, Deserialize)]
pub struct FileQuery {
    path: String,
}

/// `GET /api/file?path=REL`.
#[derive(Debug, Serialize)]
pub struct FileText {
    /// The path asked for.
    pub path: String,
    /// The file's text.
    pub text: String,
}

/// `GET /api/file?path=REL`: 403 outside the workspace, 404 for no file, 413 over
/// [`MAX_SCENARIO_BYTES`], 415 for a file that is not text.
pub async fn read(
    State(app): State<Arc<App>>,
    query: Result<Query<FileQuery>, QueryRejection>,
) -> Result<Json<FileText>, ApiError> {
    let Query(FileQuery { path }) = query?;
    tokio::task::spawn_blocking(move || {
        let file = match path.strip_prefix(GALLERY) {
            Some(name) => {
                let gallery = app
                    .gallery
                    .as_ref()
                    .ok_or_else(|| ApiError::not_found("the gallery is not available"))?;
                if name.contains('/') || name.contains('\\') {
                    return Err(ApiError::forbidden(format!(
                        "`{path}`: a gallery case is named by its file alone"
                    )));
                }
                gallery.workspace.file(&format!("{BOOK}/{name}"))?
            }
            None => app.workspace.file(&path)?,
        };
        let size = std::fs::metadata(&file).map_or(0, |m| m.len());
        if size > MAX_SCENARIO_BYTES {
            return Err(ApiError::new(
                StatusCode::PAYLOAD_TOO_LARGE,
                format!(
                    "`{path}` is {}, more than a scenario file can be ({})",
                    format_size(size),
                    format_size(MAX_SCENARIO_BYTES)
                ),
            ));
        }
        let bytes = mechkit::csv::read_bounded(&file, MAX_SCENARIO_BYTES)
            .map_err(|e| ApiError::internal(format!("cannot read `{path}`: {e}")))?;
        let text = String::from_utf8(bytes).map_err(|_| {
            ApiError::new(
                StatusCode::UNSUPPORTED_MEDIA_TYPE,
                format!("`{path}` is not a text file (UTF-8)"),
            )
        })?;
        Ok(Json(FileText { path, text }))
    })
    .await
    .map_err(|e| ApiError::internal(format!("the read failed: {e}")))?
}

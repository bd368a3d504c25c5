//! The server's state ([`App`]): the workspace, the gallery, the runs and the limits; and how
//! a request's scenario (`{name, text, set?}`) becomes a [`Scenario`].

use std::path::PathBuf;
use std::time::Duration;

use mechkit::scenario::{ConstantOverride, Scenario, ScenarioError};
use serde::Deserialize;

use super::error::ApiError;
use super::registry::Registry;
use super::workspace::Workspace;
use crate::commands::gallery_run::{BOOK, Bundle};
use crate::gallery::Case;

/// The largest request body: 1 MB (scenarios are a few kilobytes).
pub const MAX_BODY: usize = 1_000_000;

/// The prefix of a bundled gallery case's name (`gallery:c04-….toml`).
pub const GALLERY: &str = "gallery:";

/// What limits the runs.
#[derive(Debug, Clone, Copy)]
pub struct Limits {
    /// The longest a run may take (wall clock).
    pub run_time: Duration,
    /// The most bytes a run's trajectory may hold.
    pub output: u64,
    /// How many runs may go on at once.
    pub runs: usize,
}

/// The bundled gallery: its files extracted under a scratch folder for the server's life.
pub struct Gallery {
    /// The extracted files, held for the server's life (removed when dropped).
    _bundle: Bundle,
    /// The folder holding `examples/`, as the scenarios' sandbox.
    pub workspace: Workspace,
    /// The cases.
    pub cases: Vec<Case>,
    /// The case files: (stem, extension).
    pub files: Vec<(String, &'static str)>,
}

/// Everything the handlers share.
pub struct App {
    /// The user's workspace.
    pub workspace: Workspace,
    /// The gallery, if its bundle could be extracted.
    pub gallery: Option<Gallery>,
    /// The runs, going on and finished.
    pub registry: Registry,
    /// The limits of a run.
    pub limits: Limits,
}

/// A scenario in a request: `name` is its path in the workspace (which need not exist; its
/// body files are found beside it) or `gallery:STEM.toml`; `set` gives constants other
/// values, as `mechkit run --set` does.
#[derive(Debug, Deserialize)]
pub struct ScenarioRequest {
    /// Where the scenario is (relative paths inside it resolve from there).
    #[serde(default)]
    pub name: String,
    /// The TOML text.
    pub text: String,
    /// Constant overrides, e.g. `"v0=12 m/s, th=pi/6"`.
    #[serde(default)]
    pub set: Option<String>,
}

impl App {
    /// The scenario of a request: `Err` (403, 400) when its name is not allowed, `Ok(Err)`
    /// when the text is not a valid scenario (the library's error, at its line and column).
    /// Reads body files of the workspace: call it on a blocking thread.
    pub fn scenario(
        &self,
        req: &ScenarioRequest,
    ) -> Result<Result<Scenario, ScenarioError>, ApiError> {
        let (path, workspace) = self.place(&req.name)?;
        let name = path.display().to_string();
        let dir = path
            .parent()
            .map_or_else(|| workspace.root().into(), PathBuf::from);
        if let Some(e) = super::references::outside(&name, &req.text, &dir, workspace) {
            return Ok(Err(e));
        }
        let overrides = match req.set.as_deref().map(str::trim) {
            Some(text) if !text.is_empty() => ConstantOverride::parse_list(text)
                .map_err(|e| ApiError::bad_request(format!("set: {e}")))?,
            _ => Vec::new(),
        };
        Ok(Scenario::from_str_with(&name, &req.text, &overrides))
    }

    /// Where a scenario named `name` lives, and the directory it may read in.
    fn place(&self, name: &str) -> Result<(PathBuf, &Workspace), ApiError> {
        if let Some(file) = name.strip_prefix(GALLERY) {
            let gallery = self
                .gallery
                .as_ref()
                .ok_or_else(|| ApiError::not_found("the gallery's files could not be extracted"))?;
            if file.contains('/') || file.contains('\\') {
                return Err(ApiError::forbidden(format!(
                    "`{name}`: a gallery case is named by its file alone"
                )));
            }
            let path = gallery.workspace.join(&format!("{BOOK}/{file}"))?;
            return Ok((path, &gallery.workspace));
        }
        let name = if name.trim().is_empty() {
            "untitled.toml"
        } else {
            name
        };
        Ok((self.workspace.join(name)?, &self.workspace))
    }
}

impl Gallery {
    /// The bundled gallery, extracted to a scratch folder.
    pub fn extract() -> anyhow::Result<Self> {
        let bundle = Bundle::extract()?;
        let workspace = Workspace::open(bundle.root())?;
        let cases = bundle.cases()?;
        let files = bundle.files()?;
        Ok(Self {
            _bundle: bundle,
            workspace,
            cases,
            files,
        })
    }
}

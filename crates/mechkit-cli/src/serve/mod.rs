//! `mechkit serve`: the browser app, a small HTTP server on a loopback address whose pages
//! and scripts are compiled into the binary (`assets/`).
//!
//! The app lists the workspace's scenario files and the bundled gallery, checks the scenario
//! being edited as the user types (the errors of [`mechkit::scenario::Scenario::from_str_with`]
//! at their line and column), runs it on a blocking thread into a directory of the server's
//! own, and shows the plots, the animation and the files that `mechkit run` would write.
//!
//! Safe by construction:
//! - it listens on a loopback address unless `--allow-remote` is given, and answers only
//!   requests addressed to that host (`guard.rs`: no DNS rebinding, no cross-site posts);
//! - it reads files of the workspace only: relative paths without `..`, resolved through
//!   their symlinks inside the canonical workspace (`workspace.rs`), and a scenario's own
//!   references to body and mesh files likewise (`references.rs`); it never writes there;
//! - request bodies are at most 1 MB, a run at most `--max-run-seconds` and `--max-output`,
//!   at most `--max-runs` at once, and the last [`registry::KEPT_RUNS`] finished runs are kept.
//!
//! Every answer of the API is JSON, errors as `{"error": "…"}` (`error.rs`).

mod app;
mod assets;
mod check;
mod error;
mod files;
mod guard;
mod references;
mod registry;
mod run;
mod server;
mod workspace;

pub use server::{routes, serve};

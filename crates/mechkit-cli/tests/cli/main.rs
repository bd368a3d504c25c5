//! Command-line tests of the `mechkit` binary, run as a separate process in a temporary
//! directory.
//!
//! What is checked:
//! - `mechkit run examples/feather.toml --out DIR` exits 0 and writes `trajectory.csv` (header,
//!   landing row), `summary.json` (the contract keys: t_end, steps, stop_reason, bodies, work,
//!   kinetic and potential energy, work-energy residual, events with the last step before the
//!   landing, observables) and the SVG plots listed in `files.plots` (relative to the summary);
//! - `--json` prints the same summary on stdout;
//! - `mechkit check` accepts every scenario in `examples/` and `examples/book/`;
//! - `--help` shows examples and the exit codes; `list-integrators` lists every method;
//! - every bad input exits 2 with `error:` first on stderr, the location `file.toml:LINE:COL`
//!   and the specific message: unknown key (with the nearest valid key), missing, negative or
//!   zero mass, zero or negative dt, unknown unit (with a suggestion), wrong dimension (both
//!   dimensions named), undefined name in a formula (its column in the file line), invalid
//!   TOML, a missing scenario file, an unwritable output directory;
//! - a run that hits a non-finite value exits 1, explains what diverged and when, and keeps
//!   the trajectory computed so far and a summary with `stop_reason = "diverged"`;
//! - a run with no `t_max` whose stop condition never fires ends at the default step budget,
//!   exits 0 and warns about `t_max`.
//!
//! - `mechkit com IMAGE` measures the pixels of a body (`com_image.rs`).
//! - `mechkit sweep` and `sweep-merge`: 1,000 runs, threads, shards (`sweep.rs`).
//! - `mechkit md` on the gallery inputs `examples/md/` (`md_gallery.rs`).
//! - `mechkit serve` over HTTP: the workspace's bounds, bad requests, checks, runs and their
//!   limits (`serve.rs`).
//! - every kind of error message, snapshotted, with the table in `docs/reliability.md`
//!   (`messages/`).
//!
//! Numbers from files are compared within tolerances, never as strings.
mod adaptive;
mod animate;
mod bead;
mod calculator_limits;
mod calculus;
mod collide;
mod com_image;
mod conventions;
mod data;
mod diverge;
mod docs;
mod dsolve;
mod energy;
mod errors;
mod friction;
mod gallery;
mod interrupt;
mod issue_011;
mod issue_021;
mod issue_022;
mod issue_022_calc;
mod issue_022_mass;
mod issue_022_rigid;
mod issue_023_units;
mod issue_026;
mod issue_026_answers;
mod issue_026_integrity;
mod issue_026_integrity_signals;
mod issue_026_messages;
mod issue_026_numbers;
mod issue_027_solve;
mod limits;
mod mass;
mod md;
mod md_gallery;
mod md_lammps;
mod messages;
mod plots;
mod relative;
mod reproducible;
mod rigid_collide;
mod rocket;
mod roll;
mod rotation;
mod run;
mod serve;
mod serve_http;
mod spin;
mod sweep;
mod util;

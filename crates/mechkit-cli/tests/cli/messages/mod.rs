//! The catalogue of user-facing error messages: for every kind of error, one small example
//! input run through the real `mechkit` binary, with its exit code and stderr snapshotted by
//! `insta` (`snapshots/`), so that the wording is reviewed in diffs.
//!
//! What is checked:
//! - each case exits with its expected code (2 for bad input, 1 for a failed computation) and
//!   its stderr matches the committed snapshot; a missing or changed snapshot fails the test
//!   (insta writes a `.snap.new` beside it to review, or with `INSTA_UPDATE=always` replaces
//!   it);
//! - no stderr shows a Rust panic, a backtrace hint or a `Debug` rendering (`Some(`,
//!   `Error {`, `Os {`, escaped quotes);
//! - every file in `snapshots/` belongs to a case (no orphan left when a case is removed);
//! - the table of every kind in `docs/reliability.md` (between `<!-- errors:begin -->` and
//!   `<!-- errors:end -->`) is the one these cases produce; `MECHKIT_BLESS=1` rewrites it.
//!
//! Each case runs once per test process (the runs are shared by the tests through a cache).

mod answers;
mod body;
mod calculus;
mod case;
mod cli_flags;
mod commands;
mod data;
mod image;
mod limits;
mod md;
mod planar;
mod reliability;
mod runtime;
mod scenario;
mod scenario_values;
mod table;

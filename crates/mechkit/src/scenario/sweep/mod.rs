//! Parameter sweeps: one scenario run over a grid (or a seeded random sample) of values of its
//! `[constants]`, in parallel, one summary row per run.
//!
//! Overriding a constant re-reads the file with the new value in place of the old one, so
//! every later constant, body and force that uses it is resolved again. Runs are independent
//! and their rows are ordered by run index, so the table is the same whatever the number of
//! threads, and `--shard K/N` slices (runs with `index % N == K - 1`) merged back by
//! [`merge_parts`] (from their files) or [`merge_tables`] (in memory, carried between
//! processes as [`SweepTable::to_bytes`]) equal the unsharded table byte for byte.
//!
//! ```
//! use mechkit::scenario::sweep::{Parameter, Sampling, SweepGrid, SweepOptions, run_sweep};
//! let text = r#"
//!     [constants]
//!     v0 = "10 m/s"
//!     [[body]]
//!     mass = "1 kg"
//!     velocity = "v0"
//!     [[force]]
//!     name = "gravity"
//!     kind = "uniform-gravity"
//!     g = "9.8 m/s^2"
//!     [integrator]
//!     method = "verlet"
//!     dt = "1 ms"
//!     [stop]
//!     when = "x < 0"
//!     t_max = "10 s"
//!     [observe]
//!     x_max = "max(x)"
//! "#;
//! let grid = SweepGrid::new(vec![Parameter::parse("v0=1 m/s:4 m/s:4").unwrap()], Sampling::Grid);
//! let table = run_sweep("ball.toml", text, &grid, &SweepOptions::default(), &|| {})
//!     .unwrap();
//! assert_eq!(table.rows.len(), 4);
//! // the highest point of a throw is v0²/2g
//! let x_max = table.rows[3].observables[0];
//! assert!((x_max - 16.0 / 19.6).abs() < 1e-5);
//! ```

mod error;
mod grid;
mod merge;
mod param;
mod run;
mod table;
mod wire;

pub use error::SweepError;
pub use grid::{Sampling, Shard, SweepGrid};
pub use merge::{SweepPart, merge_parts, merge_tables};
pub(crate) use param::unknown_override;
pub use param::{ConstantOverride, MAX_RUNS, Parameter};
pub use run::{SweepOptions, SweepRow, run_sweep};
pub use table::{SweepTable, manifest_name};

//! The batch commands from Python: `mechkit.md(...)` (`mechkit md`: many particles with a
//! pair potential) and `mechkit.sweep(...)` (`mechkit sweep`: a scenario over a grid of its
//! constants), run in memory with the GIL released; Ctrl-C stops them (`interrupt.rs`).
//!
//! Each reads its keyword arguments into plain data first (`md_options.rs`, `sweep_run.rs`),
//! then makes the command's library calls and hands back the library's results: the report
//! as a dict equal to the command's `--json`, the series it writes to CSV as numpy arrays.

mod arguments;
mod md_options;
mod md_result;
mod md_run;
mod sweep_parts;
mod sweep_result;
mod sweep_run;

pub use md_result::MdResult;
pub use md_run::md;
pub use sweep_parts::{sweep_merge, sweep_part, sweep_plan};
pub use sweep_result::SweepResult;
pub use sweep_run::sweep;

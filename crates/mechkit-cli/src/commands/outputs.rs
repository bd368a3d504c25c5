//! Writing a model's outputs into the `-o DIR` of a command: its table through the one CSV
//! writer (`mechkit::csv::Table`: `NAME.csv` and `NAME.units.json`) and its plots, drawn from
//! the library's `PlotData` and named by their stems (`v_t.svg`).

use std::path::Path;

use anyhow::{Context, Result};
use mechkit::csv::Table;
use mechkit::figure::PlotData;

use crate::args::PlotFormat;
use crate::plot::render;

/// Creates the output directory.
pub fn create_dir(dir: &Path) -> Result<()> {
    std::fs::create_dir_all(dir).with_context(|| format!("--out: cannot create {}", dir.display()))
}

/// Writes `dir/NAME.csv` and its units sidecar; returns the CSV's path. A table may hold
/// NaN or ±inf where a quantity is not defined (docs/scenario.md, "Output files"): the
/// finiteness rule is for answers ([`super::report`]), not for the samples of a curve.
pub fn write_table(dir: &Path, name: &str, table: &Table) -> Result<String> {
    let path = table
        .write(dir, name)
        .with_context(|| format!("cannot write {}", dir.join(format!("{name}.csv")).display()))?;
    Ok(path.display().to_string())
}

/// Draws `plots` into `dir` as `<stem>.svg` (or `.png`) under `title`; returns their paths.
pub fn write_plots(
    dir: &Path,
    plots: &[PlotData],
    title: &str,
    format: PlotFormat,
) -> Result<Vec<String>> {
    plots
        .iter()
        .map(|p| {
            let path = dir.join(format.file(&p.file_stem));
            render(p, title, &path, format)?;
            Ok(path.display().to_string())
        })
        .collect()
}

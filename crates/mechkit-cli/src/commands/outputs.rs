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

/// Writes `dir/NAME.csv` and its units sidecar; returns the CSV's path. The finiteness rule:
/// a table that holds an infinity or NaN is not written ([`mechkit::finite::NonFinite`],
/// exit 1, naming its row and column).
pub fn write_table(dir: &Path, name: &str, table: &Table) -> Result<String> {
    if let Some((row, column, value)) = table.first_non_finite() {
        return Err(mechkit::finite::NonFinite {
            quantity: format!("{column} in row {row} of {name}.csv"),
            value,
        }
        .into());
    }
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

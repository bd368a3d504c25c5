//! The sweep's table: one CSV row per run (`sweep.csv`, plain: a header row, then the rows,
//! so pandas, polars and numpy read it as it is), and beside it a manifest that identifies the
//! sweep (`sweep.manifest.json`: the scenario's file name and text hash, the `--set` values,
//! the sampling, the number of runs, and the shard of a part), so parts written by shards can
//! be checked and merged.
//!
//! ```text
//! sweep.csv            index,v0,stop_reason,t_end,steps,x_max,K_end,U_end,E_end,work_energy_residual
//!                      0,0.1,event:stop,…
//! sweep.manifest.json  {"sweep": "mechkit sweep of ball.toml (fnv1a 3c4b…) --set \"v0=0:5:51\" grid; 51 runs",
//!                       "runs": 51, "shard": null}
//! ```

use std::fmt::Write as _;
use std::path::Path;

use super::{Shard, SweepGrid, SweepRow};
use crate::Real;
use crate::figure::{ColourScale, PlotData, Series};
use crate::scenario::push_number;

pub(super) const MAGIC: &str = "mechkit sweep of ";

/// The most curves an overlay tells apart by a legend (the plot palette's colours): a sweep
/// of one parameter with more runs colours them by the parameter's value.
const COLOURED: usize = 8;

/// The rows of a sweep, or of one shard of it.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepTable {
    /// The manifest line's text (without `# `).
    pub manifest: String,
    /// How many runs the whole sweep has.
    pub runs: usize,
    /// The slice these rows are, if not all.
    pub shard: Option<Shard>,
    /// Parameter names (columns after `index`).
    pub params: Vec<String>,
    /// Their SI units for people (`m/s`; empty when dimensionless or unknown).
    pub units: Vec<String>,
    /// Observable names.
    pub observables: Vec<String>,
    /// The rows, by run index.
    pub rows: Vec<SweepRow>,
}

/// The manifest of a sweep of `text`: what every part of it has in common.
pub(crate) fn manifest(name: &str, text: &str, grid: &SweepGrid) -> String {
    let file = Path::new(name)
        .file_name()
        .map_or_else(|| name.to_string(), |f| f.to_string_lossy().into_owned());
    format!(
        "{}{file} (fnv1a {:016x}) {}; {} runs",
        MAGIC,
        fnv1a(text.as_bytes()),
        grid.describe(),
        grid.len()
    )
}

use crate::scenario::provenance::fnv1a;

fn field(out: &mut String, s: &str) {
    if s.contains([',', '"', '\n']) {
        out.push('"');
        out.push_str(&s.replace('"', "\"\""));
        out.push('"');
    } else {
        out.push_str(s);
    }
}

impl SweepTable {
    /// The columns with their units, given the swept scenario (built with any values of the
    /// parameters): a parameter has its constant's unit, an observable its own, `stop_reason`
    /// is text (unit `null`), `index` and `steps` are counts (`"1"`).
    pub fn columns(&self, scenario: &crate::scenario::Scenario) -> Vec<crate::csv::Column> {
        use crate::csv::Column;
        let unit = |d: mechkit_expr::units::Dimension| {
            d.derived_symbol()
                .map_or_else(|| d.to_string(), str::to_string)
        };
        let mut cols = vec![Column::new("index", "1")];
        for p in &self.params {
            let dim = scenario
                .constants
                .iter()
                .find(|(n, _, _)| n == p)
                .and_then(|(_, _, d)| d.known());
            cols.push(match dim {
                Some(d) => Column::new(p.as_str(), unit(d)),
                None => Column::unknown(p.as_str()),
            });
        }
        cols.push(Column::unknown("stop_reason"));
        cols.push(Column::new("t_end", "s"));
        cols.push(Column::new("steps", "1"));
        for o in &self.observables {
            let known = scenario
                .observables
                .iter()
                .find(|x| &x.name == o)
                .and_then(crate::scenario::Observable::unit);
            cols.push(match known {
                Some(u) => Column::new(o.as_str(), u),
                None => Column::unknown(o.as_str()),
            });
        }
        for name in ["K_end", "U_end", "E_end", "work_energy_residual"] {
            cols.push(Column::new(name, "J"));
        }
        cols
    }

    /// The column names.
    pub fn header(&self) -> Vec<String> {
        let mut h = vec!["index".to_string()];
        h.extend(self.params.iter().cloned());
        h.extend(["stop_reason", "t_end", "steps"].map(String::from));
        h.extend(self.observables.iter().cloned());
        h.extend(["K_end", "U_end", "E_end", "work_energy_residual"].map(String::from));
        h
    }

    /// The CSV text: the header, then one row per run. Numbers are SI, printed to round-trip;
    /// an absent potential energy is an empty cell.
    pub fn to_csv(&self) -> String {
        let header: Vec<String> = self
            .header()
            .iter()
            .map(|h| {
                let mut s = String::new();
                field(&mut s, h);
                s
            })
            .collect();
        let mut out = header.join(",");
        out.push('\n');
        for r in &self.rows {
            out.push_str(&r.index.to_string());
            for &v in &r.values {
                out.push(',');
                push_number(&mut out, v);
            }
            out.push(',');
            field(&mut out, &r.stop_reason);
            out.push(',');
            push_number(&mut out, r.t_end);
            let _ = write!(out, ",{}", r.steps);
            for &v in r.observables.iter().chain([&r.kinetic_end]) {
                out.push(',');
                push_number(&mut out, v);
            }
            out.push(',');
            if let Some(u) = r.potential_end {
                push_number(&mut out, u);
            }
            for v in [r.energy_end, r.work_energy_residual] {
                out.push(',');
                push_number(&mut out, v);
            }
            out.push('\n');
        }
        out
    }

    /// The manifest beside the CSV ([`SweepTable::manifest_file_name`]): the sweep's
    /// identity, its number of runs, and the shard of a part (`null` for the whole).
    pub fn manifest_json(&self) -> String {
        let shard = self.shard.map_or(
            serde_json::Value::Null,
            |s| serde_json::json!({"k": s.k, "n": s.n}),
        );
        let json = serde_json::json!({
            "sweep": self.manifest,
            "runs": self.runs,
            "shard": shard,
        });
        format!("{json:#}\n")
    }

    /// The file name of this table: `sweep.csv`, or `sweep.partK.csv` for shard K.
    pub fn file_name(&self) -> String {
        match self.shard {
            Some(s) => format!("sweep.part{}.csv", s.k),
            None => "sweep.csv".into(),
        }
    }

    /// The file name of its manifest: `sweep.manifest.json`, or `sweep.partK.manifest.json`.
    pub fn manifest_file_name(&self) -> String {
        manifest_name(&self.file_name())
    }

    /// The recorded plots of all runs in one figure, each curve labelled by its parameter
    /// values; with more than `legend` curves, only about `legend` evenly spaced ones are
    /// labelled. A sweep of one parameter with more than eight runs, each of one
    /// curve, colours its curves by the parameter's value instead (a [`ColourScale`] named
    /// after the parameter and its unit, each curve valued), for a colour bar to replace the
    /// legend. `None` when no plot was recorded.
    pub fn overlay(&self, legend: usize) -> Option<PlotData> {
        let first = self.rows.iter().find_map(|r| r.plot.as_ref())?;
        let mut plot = PlotData::new(
            first.spec.clone(),
            format!("sweep_{}", first.file_stem),
            first.x_label.clone(),
            first.y_label.clone(),
        );
        plot.equal_aspect = first.equal_aspect;
        let stride = self.rows.len().div_ceil(legend.max(1)).max(1);
        for (n, r) in self.rows.iter().enumerate() {
            let Some(p) = &r.plot else { continue };
            let label = self
                .params
                .iter()
                .zip(&r.values)
                .map(|(name, v)| format!("{name} = {}", short(*v)))
                .collect::<Vec<_>>()
                .join(", ");
            for s in &p.series {
                let mut l = label.clone();
                if p.series.len() > 1 {
                    l = format!("{l} ({})", s.label);
                }
                let shown = n % stride == 0 || n + 1 == self.rows.len();
                plot.series.push(Series::line(
                    if shown { l } else { String::new() },
                    s.points.clone(),
                ));
            }
        }
        if let Some(scale) = self.colour_scale() {
            for (s, r) in plot
                .series
                .iter_mut()
                .zip(self.rows.iter().filter(|r| r.plot.is_some()))
            {
                s.value = r.values.first().copied();
            }
            plot.colour_scale = Some(scale);
        }
        Some(plot)
    }

    /// The colour scale of the overlay when its curves are one per run of a sweep of one
    /// parameter, more than [`COLOURED`] of them: from the smallest value to the largest.
    fn colour_scale(&self) -> Option<ColourScale> {
        let [name] = &self.params[..] else {
            return None;
        };
        let mut plots = self.rows.iter().filter_map(|r| r.plot.as_ref());
        if plots.clone().count() <= COLOURED || !plots.all(|p| p.series.len() == 1) {
            return None;
        }
        let (from, to) = self
            .rows
            .iter()
            .filter(|r| r.plot.is_some())
            .filter_map(|r| r.values.first().copied())
            .filter(|v| v.is_finite())
            .fold((Real::INFINITY, Real::NEG_INFINITY), |(lo, hi), v| {
                (lo.min(v), hi.max(v))
            });
        if from > to {
            return None;
        }
        let label = match self.units.first().map(String::as_str) {
            None | Some("") => name.clone(),
            Some(unit) => format!("{name} [{unit}]"),
        };
        Some(ColourScale { label, from, to })
    }
}

/// A value for a legend: 4 significant digits.
fn short(v: f64) -> String {
    let s = mechkit_expr::short_fixed(v, 4);
    // trailing zeros of the decimals go, also before an exponent (`1.5000e20` → `1.5e20`)
    let (digits, exponent) = s.split_once('e').unwrap_or((s.as_str(), ""));
    let digits = digits.trim_end_matches('0').trim_end_matches('.');
    if digits.is_empty() || digits == "-" {
        "0".into()
    } else if exponent.is_empty() {
        digits.to_string()
    } else {
        format!("{digits}e{exponent}")
    }
}

/// The name of the manifest beside the CSV file `csv` (`sweep.part2.csv` →
/// `sweep.part2.manifest.json`).
pub fn manifest_name(csv: &str) -> String {
    format!("{}.manifest.json", csv.strip_suffix(".csv").unwrap_or(csv))
}

#[cfg(test)]
mod tests {
    use super::{SweepRow, SweepTable};
    use crate::figure::{PlotData, Series};

    /// A table of `n` runs of `params`, run `i` with the values `i` and a `v(x)` curve.
    fn table(n: usize, params: &[&str]) -> SweepTable {
        let rows = (0..n)
            .map(|i| {
                let v = i as f64;
                SweepRow {
                    index: i,
                    values: vec![v; params.len()],
                    stop_reason: "t_max".into(),
                    t_end: 1.0,
                    steps: 10,
                    observables: Vec::new(),
                    kinetic_end: 0.0,
                    potential_end: None,
                    energy_end: 0.0,
                    work_energy_residual: 0.0,
                    plot: Some(
                        PlotData::new("v(x)", "v_x", "x [m]", "v [m/s]")
                            .with_series(Series::line("v", vec![(0.0, v), (1.0, v)])),
                    ),
                    diagnosis: None,
                }
            })
            .collect();
        SweepTable {
            manifest: String::new(),
            runs: n,
            shard: None,
            params: params.iter().map(ToString::to_string).collect(),
            units: vec!["m/s".into(); params.len()],
            observables: Vec::new(),
            rows,
        }
    }

    #[test]
    fn many_runs_of_one_parameter_are_coloured_by_its_value() {
        let plot = table(9, &["v0"]).overlay(10).unwrap();
        let scale = plot.colour_scale.expect("a colour scale");
        assert_eq!(scale.label, "v0 [m/s]");
        assert_eq!((scale.from, scale.to), (0.0, 8.0));
        let values: Vec<Option<f64>> = plot.series.iter().map(|s| s.value).collect();
        assert_eq!(
            values,
            (0..9).map(|i| Some(f64::from(i))).collect::<Vec<_>>()
        );
        // eight runs, or two parameters, keep the legend
        assert!(
            table(8, &["v0"])
                .overlay(10)
                .unwrap()
                .colour_scale
                .is_none()
        );
        assert!(
            table(20, &["v0", "g"])
                .overlay(10)
                .unwrap()
                .colour_scale
                .is_none()
        );
    }
}

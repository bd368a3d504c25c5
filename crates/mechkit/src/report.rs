//! Pieces the models' reports share: a closed form next to its simulation
//! ([`Comparison`]), a value at the start and at the end of a run ([`StartEnd`]), the
//! settings and counters of an adaptive run ([`SimulationInfo`]), the files a front wrote
//! ([`Files`]), the table of a run's samples ([`sample_table`]) and the phases of a run shaded
//! on its plots ([`shade`]).
//!
//! A model's report (`mechkit::rocket::RocketReport`, `mechkit::rigid::rolling::RollReport`,
//! …) is the value a front prints: its `serde` shape (feature `serde`) is the `--json` output
//! of the command, its tables ([`crate::csv::Table`]) the CSV files, its
//! [`crate::figure::PlotData`] the plots.
//!
//! ```
//! use mechkit::report::Comparison;
//! let c = Comparison::of(2.0, 2.5);
//! assert_eq!(c.difference, 0.5);
//! ```

use crate::Real;
use crate::csv::{Column, Table};
use crate::figure::{Band, PlotData};
use crate::ode::{AdaptiveConfig, AdaptiveStats};

/// A quantity in closed form and simulated, and their difference `simulated − closed_form`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Comparison<T = Real> {
    /// The closed form.
    pub closed_form: T,
    /// The simulation.
    pub simulated: T,
    /// `simulated − closed_form`.
    pub difference: T,
}

impl Comparison {
    /// Both values and their difference.
    pub fn of(closed_form: Real, simulated: Real) -> Self {
        Self {
            closed_form,
            simulated,
            difference: simulated - closed_form,
        }
    }
}

impl Comparison<Option<Real>> {
    /// Either value may be missing (a closed form that does not apply, an event that did not
    /// happen); the difference needs both.
    pub fn of_options(closed_form: Option<Real>, simulated: Option<Real>) -> Self {
        Self {
            closed_form,
            simulated,
            difference: closed_form.zip(simulated).map(|(c, s)| s - c),
        }
    }
}

/// A value at the start and at the end of a run (an energy, J).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct StartEnd {
    /// At the start.
    pub start: Real,
    /// At the end.
    pub end: Real,
}

impl StartEnd {
    /// Both values.
    pub fn new(start: Real, end: Real) -> Self {
        Self { start, end }
    }
}

/// The table of a run's `samples`, one row each: `row` gives a sample's cells in the order of
/// `columns` (as many, which the types check).
///
/// ```
/// use mechkit::csv::Column;
/// use mechkit::report::sample_table;
/// let samples = [(0.0, 1.0), (0.5, 0.75)];
/// let table = sample_table(
///     [Column::new("t", "s"), Column::new("x", "m")],
///     &samples,
///     |&(t, x)| [t, x],
/// );
/// assert_eq!(table.column("x"), Some(vec![1.0, 0.75]));
/// ```
pub fn sample_table<S, const N: usize>(
    columns: [Column; N],
    samples: &[S],
    row: impl Fn(&S) -> [Real; N],
) -> Table {
    let mut table = Table::new(columns);
    for s in samples {
        table.push(&row(s));
    }
    table
}

/// Shades the intervals `(from, to)` of the horizontal axis, each labelled `label`, on every
/// plot of `plots`: the phases of a run (where a block sticks, where a ball rolls).
pub fn shade(plots: &mut [PlotData], label: &str, intervals: impl Iterator<Item = (Real, Real)>) {
    let bands: Vec<Band> = intervals
        .map(|(from, to)| Band {
            from,
            to,
            label: label.to_string(),
        })
        .collect();
    for p in plots {
        p.bands.clone_from(&bands);
    }
}

/// How an adaptive run was integrated: its method, tolerances and largest step, and its
/// counters.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SimulationInfo {
    /// The method's name (`dopri5`, `dop853`).
    pub method: &'static str,
    /// Relative tolerance (`None` for per-component tolerances).
    pub rtol: Option<Real>,
    /// Absolute tolerance.
    pub atol: Option<Real>,
    /// Largest step (s).
    pub h_max: Real,
    /// Accepted steps.
    pub steps: u64,
    /// Rejected steps.
    pub rejected: u64,
    /// Right-hand-side evaluations.
    pub evaluations: u64,
    /// Samples recorded.
    pub samples: usize,
}

impl SimulationInfo {
    /// From the method's name, its settings, its counters and the number of samples kept.
    pub fn new(
        method: &'static str,
        config: &AdaptiveConfig,
        stats: AdaptiveStats,
        samples: usize,
    ) -> Self {
        Self {
            method,
            rtol: config.rtol.as_scalar(),
            atol: config.atol.as_scalar(),
            h_max: config.h_max,
            steps: stats.accepted,
            rejected: stats.rejected,
            evaluations: stats.evaluations,
            samples,
        }
    }
}

/// The files a front wrote for a report: a CSV file and plots (paths as the front wrote them).
/// Reports hold it as `files`, `None` until something is written.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Files {
    /// The CSV file.
    pub csv: Option<String>,
    /// The plots.
    pub plots: Vec<String>,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn comparisons_need_both_values_for_a_difference() {
        let c = Comparison::of_options(Some(1.0), None);
        assert_eq!(c.difference, None);
        let c = Comparison::of_options(Some(1.0), Some(0.75));
        assert_eq!(c.difference, Some(-0.25));
        let info = SimulationInfo::new(
            "dopri5",
            &AdaptiveConfig::from_rtol(1e-8).sampled_over(2.0),
            AdaptiveStats::default(),
            3,
        );
        assert_eq!(info.rtol, Some(1e-8));
        assert_eq!(info.h_max, 2.0 / crate::ode::STEPS_PER_SPAN);
    }
}

//! Running a sweep: each point's scenario built with its values and run in memory, in
//! parallel (rayon), the rows kept in run order.

use rayon::prelude::*;

use mechkit_expr::Dim;

use super::{Parameter, Shard, SweepError, SweepGrid, SweepTable};
use crate::Real;
use crate::figure::PlotData;
use crate::scenario::build::build_with;
use crate::scenario::observe::unit_text;
use crate::scenario::{PlotSpec, Scenario};
use crate::simulate::Cancel;

/// What to run and keep besides the summary rows.
#[derive(Debug, Clone, Default)]
pub struct SweepOptions {
    /// Only this slice of the runs.
    pub shard: Option<Shard>,
    /// A plot to record in every run for the overlay, e.g. `v(x)`; `Some("")` means the
    /// scenario's first plot, if it has one.
    pub plot: Option<String>,
    /// Stops the sweep once raised: the runs in flight end with `stop_reason =
    /// "interrupted"`, and the runs not started yet are not started (they have no row).
    pub cancel: Cancel,
}

/// One run's summary (a row of `sweep.csv`; serialized with its fields' names, the recorded
/// plot left out).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SweepRow {
    /// The run index in the whole sweep.
    pub index: usize,
    /// The parameter values (SI), in the order of the sweep's parameters.
    pub values: Vec<Real>,
    /// Why the run ended (`event:…`, `t_max`, `diverged`, …).
    pub stop_reason: String,
    /// Time at the end (s).
    pub t_end: Real,
    /// Steps taken.
    pub steps: u64,
    /// The `[observe]` values, in the scenario's order.
    pub observables: Vec<Real>,
    /// Kinetic energy at the end (J).
    pub kinetic_end: Real,
    /// Potential energy at the end (J); `None` when no force has a potential.
    pub potential_end: Option<Real>,
    /// Mechanical energy at the end (J).
    pub energy_end: Real,
    /// The work-energy residual `W_net − ΔK` (J).
    pub work_energy_residual: Real,
    /// The recorded plot, when asked for.
    #[cfg_attr(feature = "serde", serde(skip))]
    pub plot: Option<PlotData>,
    /// What went wrong, for a run that failed ([`SweepRow::failed`]): the run's divergence
    /// message (not a column of `sweep.csv`).
    #[cfg_attr(feature = "serde", serde(skip))]
    pub diagnosis: Option<String>,
}

impl SweepRow {
    /// Whether the run failed numerically (`diverged`, `step_too_small`, `zeno`: what makes
    /// `mechkit run` exit with 1).
    pub fn failed(&self) -> bool {
        matches!(
            self.stop_reason.as_str(),
            "diverged" | "step_too_small" | "zeno"
        )
    }
}

/// Runs the points of `grid` (the shard's slice of them, when one is given) of the scenario
/// `text` (`name` is used in error locations). `on_done` is called after each run (from the
/// worker threads), e.g. to advance a progress bar. Runs go to rayon's current thread pool.
///
/// A run that fails numerically (diverges) is a row with its `stop_reason`; a point whose
/// values make the scenario invalid (a negative mass) is an error naming the run. Once
/// [`SweepOptions::cancel`] is raised, the runs in flight stop (`interrupted`) and no other
/// run starts: the table then holds fewer rows than runs.
pub fn run_sweep(
    name: &str,
    text: &str,
    grid: &SweepGrid,
    options: &SweepOptions,
    on_done: &(dyn Fn() + Sync),
) -> Result<SweepTable, SweepError> {
    grid.check()?;
    let overrides = |i: usize| -> Vec<_> {
        grid.params
            .iter()
            .zip(grid.point(i))
            .map(|(p, v)| p.with_value(v))
            .collect()
    };
    let base =
        build_with(name, text, &overrides(0)).map_err(|source| SweepError::Scenario { source })?;
    let spec = match &options.plot {
        None => None,
        Some(s) if s.trim().is_empty() => base.plots.first().cloned(),
        Some(s) => Some(plot_spec(&base, s)?),
    };
    let len = grid.len();
    let indices: Vec<usize> = match options.shard {
        Some(s) => s.indices(len),
        None => (0..len).collect(),
    };
    let one = |i: usize| -> Result<SweepRow, SweepError> {
        let values = grid.point(i);
        let fail = |source| SweepError::Run {
            index: i,
            values: grid
                .params
                .iter()
                .zip(&values)
                .map(|(p, v)| format!("{}={}", p.name, crate::error::short(*v)))
                .collect::<Vec<_>>()
                .join(", "),
            source,
        };
        let mut scenario = build_with(name, text, &overrides(i)).map_err(fail)?;
        scenario.plots = spec.iter().cloned().collect();
        scenario.cancel = options.cancel.clone();
        let out = scenario.run().map_err(fail)?;
        let s = &out.summary;
        let row = SweepRow {
            index: i,
            values,
            stop_reason: s.stop_reason.clone(),
            t_end: s.t_end,
            steps: s.steps,
            observables: scenario
                .observables
                .iter()
                .map(|o| s.observables.get(&o.name).copied().unwrap_or(Real::NAN))
                .collect(),
            kinetic_end: s.kinetic_energy.end.unwrap_or(Real::NAN),
            potential_end: s.potential_energy.end,
            energy_end: s.energy.end,
            work_energy_residual: s.work_energy_residual,
            plot: out.plots.into_iter().next(),
            diagnosis: s.divergence.as_ref().map(|d| d.message.clone()),
        };
        on_done();
        Ok(row)
    };
    // each run looks at the handle just before it starts
    let results: Vec<Result<SweepRow, SweepError>> = indices
        .par_iter()
        .filter(|_| !options.cancel.is_cancelled())
        .map(|&i| one(i))
        .collect();
    let rows = results.into_iter().collect::<Result<Vec<_>, _>>()?;
    Ok(SweepTable {
        manifest: super::table::manifest(name, text, grid),
        runs: len,
        shard: options.shard,
        params: grid.params.iter().map(|p| p.name.clone()).collect(),
        units: grid.params.iter().map(|p| unit(&base, p)).collect(),
        observables: base.observables.iter().map(|o| o.name.clone()).collect(),
        rows,
    })
}

/// The SI unit of the parameter `p` for people (`m/s`): the dimension it was given in, else
/// the constant's in the scenario; empty for a dimensionless or unknown one.
fn unit(s: &Scenario, p: &Parameter) -> String {
    let file = s
        .constants
        .iter()
        .find(|(name, _, _)| *name == p.name)
        .and_then(|(_, _, d)| match d {
            Dim::Known(d) => Some(*d),
            _ => None,
        });
    p.dim.or(file).map(unit_text).unwrap_or_default()
}

/// Parses a plot spec against a scenario's names ([`Scenario::plot_spec`]), its error as
/// `--plot`'s.
fn plot_spec(s: &Scenario, spec: &str) -> Result<PlotSpec, SweepError> {
    s.plot_spec(spec).map_err(|e| {
        SweepError::Options(format!(
            "--plot: {}\n  = hint: {}",
            e.message,
            e.hint.unwrap_or_default()
        ))
    })
}

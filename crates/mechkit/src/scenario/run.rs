//! Running a scenario: the simulation with its observers (CSV, observables, plots), then the
//! summary.

use std::fs;
use std::path::{Path, PathBuf};

use super::error::{ErrorKind, ScenarioError};
use super::observe::ObservableSet;
use super::output::RowSink as _;
use super::output::{
    CsvWriter, Keep, ReservedFile, SUMMARY_RESERVE, Trajectory, TrajectoryTable, csv_columns_in,
    csv_header, write_atomic,
};
use super::plot_recorder::PlotRecorder;
use super::provenance::Provenance;
use super::summary::Summary;
use super::{OutputTimes, Scenario};
use crate::figure::PlotData;
use crate::simulate::{Observer, RunReport, SimulateError, Simulation};

/// What a run produced.
#[derive(Debug, Clone)]
pub struct RunOutput {
    /// The summary (also written to `summary.json` by [`Scenario::run_to_dir`]).
    pub summary: Summary,
    /// Data of the requested plots.
    pub plots: Vec<PlotData>,
    /// The raw run report.
    pub report: RunReport,
}

impl RunOutput {
    /// Whether the computation failed (diverged, step size underflow, Zeno): the CLI exits
    /// with 1.
    pub fn failed(&self) -> bool {
        self.report.stop_reason.is_failure()
    }
}

fn io_error(what: &str, path: &Path, e: &std::io::Error) -> ScenarioError {
    ScenarioError::new(
        ErrorKind::Io,
        format!("cannot {what} {}: {e}", path.display()),
    )
    .with_hint("choose a directory you can write to with --out")
}

impl Scenario {
    fn simulation(&self) -> Simulation<'_> {
        let mut sim = Simulation::with_stepping(&self.system, self.stepping.clone())
            .cancel_on(self.cancel.clone());
        if let Some(t) = self.t_max {
            sim = sim.t_max(t);
        }
        if let Some(n) = self.max_steps {
            sim = sim.max_steps(n);
        }
        if let Some(c) = &self.stop {
            sim = sim.stop_when(c.clone());
        }
        for e in &self.events {
            sim = sim.event(e.clone());
        }
        match &self.output_times {
            Some(OutputTimes::Every(i)) => sim = sim.output_interval(*i),
            Some(OutputTimes::At(list)) => sim = sim.output_times(list.clone()),
            None => {}
        }
        sim.max_output_times(self.max_output_rows())
    }

    /// The most rows the trajectory could hold within the output limit: a row has at least
    /// one character and one separator per column. Output times beyond it could never be
    /// written, so an in-memory run (a sweep, the gallery) ends them there too, instead of
    /// interpolating 10^15 rows that `interval = "2 fs"` over five seconds asks for.
    fn max_output_rows(&self) -> u64 {
        let columns = csv_header(&self.system, false).len() as u64;
        self.max_output / (2 * columns)
    }

    fn keep(&self) -> Keep {
        Keep {
            every: self.every,
            grid: self.output_times.is_some(),
        }
    }

    fn run_with(&self, extra: Option<&mut dyn Observer>) -> Result<RunOutput, ScenarioError> {
        let dim = self.dim;
        let mass = self.system.masses();
        let mut observables = ObservableSet::new(&self.observables, dim, mass);
        let mut plots = PlotRecorder::new(&self.plots, self.keep(), dim, mass);
        let mut progress = ProgressObserver(&self.progress);
        let mut observers: Vec<&mut dyn Observer> =
            vec![&mut observables, &mut plots, &mut progress];
        if let Some(o) = extra {
            observers.push(o);
        }
        let report = self
            .simulation()
            .run(self.initial.clone(), &mut observers)
            .map_err(|e| match e {
                SimulateError::Observer(o) => ScenarioError::new(ErrorKind::Io, o.0),
                other => ScenarioError::new(ErrorKind::Invalid, other.to_string()),
            })?;
        // The scenario already warned about a missing t_max; the run's own note on it would
        // say the same again.
        let mut warnings = self.warnings.clone();
        warnings.extend(
            report
                .warnings
                .iter()
                .filter(|w| !(self.t_max.is_none() && w.starts_with("no t_max")))
                .cloned(),
        );
        let summary = Summary::new(
            &self.title,
            &self.name,
            &self.system,
            &report,
            observables.values(),
            warnings,
            Provenance::of(&report, self.source_hash),
        )
        .in_units(self.units);
        let mut plots = plots.into_data();
        if self.energy_bars {
            plots.push(summary.energy_bars());
        }
        Ok(RunOutput {
            summary,
            plots,
            report,
        })
    }

    /// Runs in memory: summary and plot data, no files.
    pub fn run(&self) -> Result<RunOutput, ScenarioError> {
        self.run_with(None)
    }

    /// Runs in memory and keeps the trajectory: the rows and columns `trajectory.csv` would
    /// have, as numbers (within the output limit, 8 bytes per number).
    pub fn run_with_trajectory(&self) -> Result<(RunOutput, Trajectory), ScenarioError> {
        let has_potential = {
            let (q, v) = self.initial.qv();
            self.system.has_potential(q, v)
        };
        let mut table = TrajectoryTable::new(
            &self.system,
            has_potential,
            self.units,
            self.keep(),
            self.max_output,
        );
        let out = self.run_with(Some(&mut table))?;
        Ok((out, table.finish()))
    }

    /// Runs and writes `dir/trajectory.csv` (streamed, kept even if the run diverges) and
    /// `dir/summary.json` (atomically). Plots are returned as data for the caller to render.
    pub fn run_to_dir(&self, dir: &Path) -> Result<RunOutput, ScenarioError> {
        self.run_to_dir_then(dir, |_| Ok(()))
    }

    /// [`Scenario::run_to_dir`], with `then` called after the run and before the summary is
    /// written (the caller's plots and animations, which add their files to
    /// `summary.files`). Its error (an output that could not be written) goes into the
    /// summary's `files.error`, as a failed write of the trajectory does.
    ///
    /// The summary's room on disk is taken before the run ([`ReservedFile`]), so a disk that
    /// fills up during the run still gets a valid summary saying what happened.
    pub fn run_to_dir_then(
        &self,
        dir: &Path,
        then: impl FnOnce(&mut RunOutput) -> Result<(), String>,
    ) -> Result<RunOutput, ScenarioError> {
        fs::create_dir_all(dir).map_err(|e| io_error("create the output directory", dir, &e))?;
        let summary_path = dir.join("summary.json");
        let mut summary_file = ReservedFile::create(&summary_path, SUMMARY_RESERVE)
            .map_err(|e| io_error("write", &summary_path, &e))?;
        let csv_path = dir.join("trajectory.csv");
        let has_potential = {
            let (q, v) = self.initial.qv();
            self.system.has_potential(q, v)
        };
        let mut csv = CsvWriter::create(
            &csv_path,
            &self.system,
            has_potential,
            self.keep(),
            self.max_output,
        )
        .map_err(|e| io_error("write", &csv_path, &e))?;
        let units_path = dir.join(crate::csv::units_file_name("trajectory"));
        let units =
            crate::csv::units_json(&csv_columns_in(&self.system, has_potential, self.units));
        write_atomic(&units_path, units.as_bytes())
            .map_err(|e| io_error("write", &units_path, &e))?;
        let result = self.run_with(Some(&mut csv));
        let write_error = match csv.stop() {
            Some((crate::simulate::StopReason::OutputError, message)) => Some(message),
            _ => None,
        };
        let (rows, last_t, closed) = csv.close();
        let mut out = result?;
        let files = &mut out.summary.files;
        files.trajectory = Some("trajectory.csv".into());
        files.units = Some(crate::csv::units_file_name("trajectory"));
        files.trajectory_rows = rows;
        files.trajectory_last_t = last_t;
        files.error = write_error.or_else(|| {
            closed.err().map(|e| {
                format!(
                    "cannot write {}: {e}; the file keeps {rows} whole rows",
                    csv_path.display()
                )
            })
        });
        if let Err(e) = then(&mut out) {
            match &out.summary.files.error {
                Some(_) => out.summary.warnings.push(e),
                None => out.summary.files.error = Some(e),
            }
        }
        write_summary_into(&mut summary_file, &mut out.summary)
            .map_err(|e| io_error("write", &summary_path, &e))?;
        Ok(out)
    }

    /// Writes `summary.json` into `dir` atomically; returns its path.
    pub fn write_summary(
        &self,
        dir: &Path,
        summary: &super::Summary,
    ) -> Result<PathBuf, ScenarioError> {
        let path = dir.join("summary.json");
        write_atomic(&path, summary.to_json().as_bytes())
            .map_err(|e| io_error("write", &path, &e))?;
        Ok(path)
    }
}

/// Writes `summary` into its reserved room. A summary too long for the room (many events)
/// on a disk that has no more keeps fewer events, and says so in its warnings.
fn write_summary_into(
    file: &mut ReservedFile,
    summary: &mut super::Summary,
) -> std::io::Result<()> {
    let first = file.write(summary.to_json().as_bytes());
    let Err(mut error) = first else {
        return Ok(());
    };
    let events = summary.events.len();
    let mut keep = events;
    while keep > 0 {
        keep /= 2;
        let mut shorter = summary.clone();
        shorter.events.truncate(keep);
        shorter.warnings.push(format!(
            "summary.json keeps the first {keep} of {events} events: the disk had no room for more ({error})"
        ));
        match file.write(shorter.to_json().as_bytes()) {
            Ok(()) => {
                *summary = shorter;
                return Ok(());
            }
            Err(e) => error = e,
        }
    }
    Err(error)
}

/// Puts the time of the run's samples into the scenario's [`Progress`](crate::simulate::Progress):
/// every [`PROGRESS_EVERY`] steps (so a compiled kernel still runs the steps between) and at
/// every event and output time.
struct ProgressObserver<'a>(&'a crate::simulate::Progress);

/// Steps between progress samples.
const PROGRESS_EVERY: u64 = 4096;

impl Observer for ProgressObserver<'_> {
    fn observe(
        &mut self,
        sample: &crate::particles::Sample<'_>,
    ) -> Result<(), crate::simulate::ObserverError> {
        self.0.set(sample.t);
        Ok(())
    }

    fn next_step(&self, step: u64) -> Option<u64> {
        Some((step / PROGRESS_EVERY + 1) * PROGRESS_EVERY)
    }
}

//! Scenario files: a problem described in TOML (values with units, forces as formulas) →
//! a checked model → a run → a summary with the energy ledger.
//!
//! ```
//! use mechkit::scenario::Scenario;
//! let scenario = Scenario::from_str("feather.toml", r#"
//!     title = "Feather falling with quadratic air resistance"
//!     dimensions = 1
//!     [constants]
//!     g   = "9.8 m/s^2"
//!     Dmg = "4.0 s^2/m^2"
//!     [[body]]
//!     name = "feather"
//!     mass = "1 g"
//!     position = "2.4 m"
//!     [[force]]
//!     name = "gravity"
//!     kind = "uniform-gravity"
//!     g = "g"
//!     [[force]]
//!     name = "air"
//!     kind = "expression"
//!     F = "-m*g*Dmg*v*abs(v)"
//!     [integrator]
//!     method = "euler-cromer"
//!     dt = "1 ms"
//!     [stop]
//!     when = "x < 0"
//!     t_max = "10 s"
//! "#).unwrap();
//! let out = scenario.run().unwrap();
//! let landing = &out.summary.events[0];
//! assert!((landing.t - 4.8354).abs() < 1e-3);
//! assert!((landing.last_step.t - 4.834).abs() < 1e-9);
//! ```
//!
//! The format is documented key by key in `docs/scenario.md`.

mod analytic;
mod animation_key;
mod bodyfile;
mod build;
mod check;
mod compare;
mod constants;
mod contact;
mod doc;
mod energy_bars;
mod error;
mod events;
mod forces;
mod integrator;
mod limits;
pub(crate) mod mechanism;
mod model;
mod observe;
mod output;
mod plot;
mod plot_recorder;
mod provenance;
mod rigid;
mod rocket;
mod run;
mod start;
mod stop;
mod summary;
pub mod sweep;
mod text;
mod values;

use std::path::Path;

pub use crate::figure::{PlotData, Series};
pub use analytic::Analytic;
pub use bodyfile::BodyFile;
pub use check::{CheckReport, CheckedBody, CheckedConstant, CheckedEvent};
pub use compare::{CompareSettings, Comparison, MethodResult};
pub use energy_bars::ENERGY_BARS;
pub use error::{ErrorKind, Location, ScenarioError};
pub use limits::{DEFAULT_MAX_OUTPUT, MAX_SCENARIO_BYTES, format_size, parse_size};
pub use model::ModelValues;
pub use observe::Observable;
pub use output::{
    FLUSH_INTERVAL, ReservedFile, SUMMARY_RESERVE, StreamFile, Trajectory, csv_columns,
    csv_columns_in, csv_header, output_limit_message, push_number, write_atomic,
};
pub use plot::{OutputTimes, PlotSpec, SeriesSpec};
pub use provenance::Provenance;
pub use run::RunOutput;
pub use summary::{
    BodyState, BodySummary, CentreOfMass, DivergenceSummary, EnergySummary, EventSummary, Files,
    MomentumSummary, Rotation, SpinSummary, StartEnd, StepControl, Summary, TimedState,
};
pub use sweep::ConstantOverride;

use crate::Real;
use crate::expr::Dim;
use crate::ode::State;
use crate::particles::ParticleSystem;
use crate::simulate::{Cancel, Condition, Event, Progress, Stepping};

/// A checked, runnable scenario.
#[derive(Debug)]
pub struct Scenario {
    name: String,
    /// Title (the file name if none is given).
    pub title: String,
    /// Spatial dimensions.
    pub dim: usize,
    /// Constants: name, SI value, dimension.
    pub constants: Vec<(String, Real, Dim)>,
    /// Bodies and forces.
    pub system: ParticleSystem,
    /// Initial state.
    pub initial: State,
    /// Integration method and step size control.
    pub stepping: Stepping,
    /// End time (s).
    pub t_max: Option<Real>,
    /// Step budget.
    pub max_steps: Option<u64>,
    /// The most bytes the run's output files may hold (`[output] max_size`, else
    /// [`DEFAULT_MAX_OUTPUT`]); the run stops with `output_limit` when the trajectory would
    /// pass it.
    pub max_output: u64,
    /// Stops its runs (and the comparison's) after their current step, with
    /// `stop_reason = "interrupted"`, once raised; a new handle, never raised, unless the
    /// caller gives its own (the command line's Ctrl-C, a sweep's
    /// [`SweepOptions::cancel`](sweep::SweepOptions::cancel)).
    pub cancel: Cancel,
    /// Where the run reports the time it has reached (a progress bar reads it).
    pub progress: Progress,
    /// Stop condition.
    pub stop: Option<Condition>,
    /// `[[event]]` entries.
    pub events: Vec<Event>,
    /// `[observe]` entries.
    pub observables: Vec<Observable>,
    /// Output decimation: keep every n-th step.
    pub every: u64,
    /// Output times (instead of the steps) in the trajectory and plots.
    pub output_times: Option<OutputTimes>,
    /// Requested plots.
    pub plots: Vec<PlotSpec>,
    /// Whether the energy ledger is drawn as bars after the run (`"energy-bars"` in
    /// `[output] plots`; [`Summary::energy_bars`]).
    pub energy_bars: bool,
    /// Warnings about the setup.
    pub warnings: Vec<String>,
    /// `units`: SI, or reduced units (every value a pure number; outputs labelled `1`).
    pub units: mechkit_expr::units::UnitSystem,
    /// FNV-1a of the scenario text (the summary's provenance).
    pub source_hash: u64,
    /// The names of a planar mechanism's rigid bodies and joints (empty otherwise).
    pub planar: crate::particles::PlanarNames,
    /// What the model looks like: bodies, springs, joints, walls ([`crate::animation`]).
    pub scene: crate::animation::Scene,
    /// `[output] animation`: the formats the front writes the run's animation in.
    pub animation: Vec<crate::animation::AnimationFormat>,
}

impl Scenario {
    /// Reads and checks a scenario from TOML text; `name` is used in error locations.
    #[allow(clippy::should_implement_trait)]
    pub fn from_str(name: &str, text: &str) -> Result<Scenario, ScenarioError> {
        build::build(name, text)
    }

    /// Reads and checks a scenario file.
    pub fn load(path: &Path) -> Result<Scenario, ScenarioError> {
        let text = read_source(path)?;
        Scenario::from_str(&path.display().to_string(), &text)
    }

    /// [`Scenario::from_str`] with some `[constants]` given other values (`mechkit run
    /// --set`, Python's `scenario.run(**constants)`): every formula that uses them sees the
    /// new values. A name that is not a constant of the file is an error, as is a value with
    /// units of another dimension than the constant's.
    pub fn from_str_with(
        name: &str,
        text: &str,
        overrides: &[ConstantOverride],
    ) -> Result<Scenario, ScenarioError> {
        build::build_with(name, text, overrides)
    }

    /// [`Scenario::load`] with some `[constants]` given other values
    /// ([`Scenario::from_str_with`]).
    pub fn load_with(
        path: &Path,
        overrides: &[ConstantOverride],
    ) -> Result<Scenario, ScenarioError> {
        let text = read_source(path)?;
        Scenario::from_str_with(&path.display().to_string(), &text, overrides)
    }

    /// The name given when loading (the file path).
    pub fn name(&self) -> &str {
        &self.name
    }
}

/// The text of a scenario or body file (at most [`MAX_SCENARIO_BYTES`]), or an error that names
/// it.
pub fn read_source(path: &Path) -> Result<String, ScenarioError> {
    if let Ok(meta) = std::fs::metadata(path)
        && meta.len() > limits::MAX_SCENARIO_BYTES
    {
        return Err(ScenarioError::new(
            ErrorKind::Io,
            format!(
                "{} is {}, more than a scenario file can be ({})",
                path.display(),
                limits::format_size(meta.len()),
                limits::format_size(limits::MAX_SCENARIO_BYTES)
            ),
        )
        .with_hint("give the scenario's .toml file; data files are named inside it"));
    }
    crate::csv::read_bounded_text(path, limits::MAX_SCENARIO_BYTES).map_err(|e| {
        ScenarioError::new(
            ErrorKind::Io,
            format!("cannot read {}: {e}", path.display()),
        )
        .with_hint("check the file name")
    })
}

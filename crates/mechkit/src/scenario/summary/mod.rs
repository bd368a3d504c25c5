//! The summary of a run: what `summary.json` holds (a contract: keys are only ever added) and
//! the short human-readable version the CLI prints.

use std::collections::BTreeMap;

use serde::Serialize;

mod bodies;
mod momentum;

pub use bodies::{BodySummary, Rotation, SpinSummary};
use momentum::centre_of_mass;
pub use momentum::{CentreOfMass, MomentumSummary};

use super::provenance::Provenance;
use crate::Real;
use crate::ode::Tolerance;
use crate::particles::ParticleSystem;
use crate::simulate::{RunReport, Snapshot, Stepping};

/// Position and velocity of one body.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BodyState {
    /// Position (m), one component per dimension.
    pub position: Vec<Real>,
    /// Velocity (m/s).
    pub velocity: Vec<Real>,
}

/// A state at one time.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TimedState {
    /// Time (s).
    pub t: Real,
    /// State of each body.
    pub state: BTreeMap<String, BodyState>,
}

/// Start and end values.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct StartEnd {
    /// At the start.
    pub start: Option<Real>,
    /// At the end.
    pub end: Option<Real>,
}

/// Mechanical energy `K + U` at the start and end, and the change.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct EnergySummary {
    /// At the start.
    pub start: Real,
    /// At the end.
    pub end: Real,
    /// `end - start`: for conservative forces alone, the method's energy drift.
    pub change: Real,
    /// Work of the forces without a potential (drag, formulas), which `change` should equal.
    pub non_conservative_work: Real,
    /// Energy changed by events' state changes (J; a bounce's loss).
    pub events_change: Real,
    /// The method's energy error relative to the start: `(change - non_conservative_work -
    /// events_change)/|start|`; null when no force has a potential (or the start is zero).
    pub relative_drift: Option<Real>,
}

/// How the step size was controlled.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StepControl {
    /// `fixed` or `adaptive`.
    pub mode: String,
    /// Relative tolerance (adaptive).
    pub rtol: Option<Real>,
    /// Absolute tolerance, when the same for every component (adaptive).
    pub atol: Option<Real>,
    /// Accepted steps.
    pub accepted: u64,
    /// Rejected steps (adaptive).
    pub rejected: u64,
    /// Right-hand-side evaluations of the integrator itself.
    pub evaluations: u64,
    /// Steps run in the compiled step kernel (fixed steps no output looked at; the same
    /// numbers as the general loop's).
    pub fused_steps: u64,
    /// Smallest step taken (s).
    pub h_min: Option<Real>,
    /// Largest step taken (s).
    pub h_max: Option<Real>,
}

/// A located event.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct EventSummary {
    /// The event's name (the stop condition as written).
    pub name: String,
    /// Which occurrence of this event (1 for the first).
    pub occurrence: u32,
    /// Whether it ended the run.
    pub terminal: bool,
    /// Time of the crossing, located between steps (s).
    pub t: Real,
    /// The state at the crossing.
    pub state: BTreeMap<String, BodyState>,
    /// The last step before the crossing (the answer of a `while` loop).
    pub last_step: TimedState,
    /// The step that crossed.
    pub crossing_step: TimedState,
    /// The state right after the event's state change, if it has one.
    pub after: Option<BTreeMap<String, BodyState>>,
}

/// Why and where a run diverged.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DivergenceSummary {
    /// Time of the last finite state (s).
    pub t: Real,
    /// What went bad.
    pub quantity: String,
    /// The full explanation.
    pub message: String,
}

/// Files written by the run, relative to the directory of `summary.json`.
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct Files {
    /// The trajectory CSV.
    pub trajectory: Option<String>,
    /// Rows in the trajectory (header excluded).
    pub trajectory_rows: u64,
    /// The time of the trajectory's last row (s; `null` without rows): `t_end` unless the
    /// output limit refused the rows after it.
    pub trajectory_last_t: Option<Real>,
    /// The units of the trajectory's columns: a JSON object from column name to unit
    /// (`"trajectory.units.json"`), beside the CSV.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub units: Option<String>,
    /// Plots.
    pub plots: Vec<String>,
    /// Why an output file could not be written (a full disk: which file, the system's
    /// reason, how far it got); absent when every file was written. The run's results in
    /// this summary hold all the same, up to `t_end`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
}

/// The summary of a run (`summary.json`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Summary {
    /// Scenario title.
    pub title: String,
    /// `"angle"` for rigid bodies hinged to the world: each body's `position` is then its angle
    /// (rad), `velocity` its angular velocity (rad/s), `mass` its moment of inertia about the
    /// axis (kg m²), the momentum its angular momentum about the axis (kg m²/s) and the
    /// impulses angular impulses (N m s). Absent for particles.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub coordinates: Option<&'static str>,
    /// `"reduced"` for a scenario in reduced units (`units = "reduced"`): every number is in
    /// the scenario's own units, not SI, and every unit in `observable_units` and in the
    /// trajectory's units file is `"1"`. Absent in SI units.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub units: Option<&'static str>,
    /// The scenario file.
    pub scenario: String,
    /// Integration method.
    pub method: String,
    /// Time step (s): the fixed step, or the mean accepted step of an adaptive run.
    pub dt: Real,
    /// Step size control: fixed or adaptive, tolerances, accepted and rejected steps.
    pub step_control: StepControl,
    /// Start time (s).
    pub t_start: Real,
    /// End time (s): `t_max`, the located event, or the last finite state.
    pub t_end: Real,
    /// Steps taken.
    pub steps: u64,
    /// Force evaluations.
    pub evaluations: u64,
    /// `t_max`, `event`, `max_steps`, `diverged`, `step_too_small`, `zeno`, `interrupted`,
    /// `output_limit` or `output_error`.
    pub stop_reason: String,
    /// Every body's final state.
    pub bodies: BTreeMap<String, BodySummary>,
    /// Work done by each force (J), integrated as power along the computed path.
    pub work: BTreeMap<String, Real>,
    /// Average power of each force over the run (W): its work divided by the duration (null
    /// for a run of zero duration).
    pub average_power: BTreeMap<String, Option<Real>>,
    /// Total momentum `Σ m v` (kg·m/s), one component per dimension, at the start and the end:
    /// it changes only by the impulse of external forces (and of walls).
    pub momentum: MomentumSummary,
    /// Impulse `∫F dt` of each force (N·s), its net force summed over the bodies it acts on.
    pub impulse: BTreeMap<String, Vec<Real>>,
    /// The centre of mass of all bodies at the start and the end.
    pub centre_of_mass: CentreOfMass,
    /// Kinetic energy (J).
    pub kinetic_energy: StartEnd,
    /// The part of the kinetic energy in the rigid bodies' turning, `Σ ½ Iω²` (J); absent
    /// without free rigid bodies.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rotational_kinetic_energy: Option<StartEnd>,
    /// Potential energy of the conservative forces (J); null when none has a potential.
    pub potential_energy: StartEnd,
    /// Mechanical energy (J).
    pub energy: EnergySummary,
    /// `Σ work - ΔK` (J): zero for an exact trajectory.
    pub work_energy_residual: Real,
    /// Located events, every occurrence in time order (at most 100,000).
    pub events: Vec<EventSummary>,
    /// `[observe]` results.
    pub observables: BTreeMap<String, Real>,
    /// SI unit of each observable whose dimension is known (`""` for pure numbers).
    pub observable_units: BTreeMap<String, String>,
    /// Set when the run failed (diverged, step size underflow, Zeno).
    pub divergence: Option<DivergenceSummary>,
    /// Warnings about the setup or the run.
    pub warnings: Vec<String>,
    /// Files written.
    pub files: Files,
    /// Where the result came from: version, scenario hash, method and step control,
    /// seed, threads.
    pub provenance: Provenance,
}

fn states(sys: &ParticleSystem, q: &[Real], v: &[Real]) -> BTreeMap<String, BodyState> {
    let d = sys.dim();
    sys.bodies()
        .iter()
        .enumerate()
        .map(|(i, b)| {
            (
                b.name.clone(),
                BodyState {
                    position: q[i * d..(i + 1) * d].to_vec(),
                    velocity: v[i * d..(i + 1) * d].to_vec(),
                },
            )
        })
        .collect()
}

fn step_control(report: &RunReport) -> StepControl {
    let finite = |x: Real| x.is_finite().then_some(x);
    let (h_min, h_max) = (finite(report.step_range.0), finite(report.step_range.1));
    match (&report.stepping, report.adaptive) {
        (Stepping::Adaptive { config, .. }, Some(stats)) => StepControl {
            mode: "adaptive".into(),
            rtol: match &config.rtol {
                Tolerance::Scalar(r) => Some(*r),
                Tolerance::PerComponent(_) => None,
            },
            atol: match &config.atol {
                Tolerance::Scalar(a) => Some(*a),
                Tolerance::PerComponent(_) => None,
            },
            accepted: stats.accepted,
            rejected: stats.rejected,
            evaluations: stats.evaluations,
            fused_steps: 0,
            h_min,
            h_max,
        },
        _ => StepControl {
            mode: "fixed".into(),
            rtol: None,
            atol: None,
            accepted: report.steps,
            rejected: 0,
            evaluations: report.evaluations,
            fused_steps: report.fused_steps,
            h_min,
            h_max,
        },
    }
}

fn timed(sys: &ParticleSystem, s: &Snapshot) -> TimedState {
    TimedState {
        t: s.t,
        state: states(sys, &s.q, &s.v),
    }
}

impl Summary {
    pub(crate) fn new(
        title: &str,
        scenario: &str,
        sys: &ParticleSystem,
        report: &RunReport,
        observables: Vec<(String, Real, Option<String>)>,
        warnings: Vec<String>,
        provenance: Provenance,
    ) -> Self {
        let (q, v) = report.final_state.qv();
        let d = sys.dim();
        let bodies = bodies::bodies(sys, q, v);
        let l = &report.ledger;
        let (e0, e1) = l.energy();
        Summary {
            provenance,
            title: title.to_string(),
            coordinates: (sys.coordinates() == crate::particles::Coordinates::Angle)
                .then_some("angle"),
            units: None,
            scenario: scenario.to_string(),
            method: report.method.name().to_string(),
            dt: report.dt,
            step_control: step_control(report),
            t_start: report.initial.t,
            t_end: report.final_state.t,
            steps: report.steps,
            evaluations: report.evaluations,
            stop_reason: report.stop_reason.name().to_string(),
            bodies,
            work: l
                .names()
                .iter()
                .cloned()
                .zip(l.work().iter().copied())
                .collect(),
            average_power: {
                let duration = report.final_state.t - report.initial.t;
                l.names()
                    .iter()
                    .cloned()
                    .zip(
                        l.work()
                            .iter()
                            .map(|w| (duration > 0.0).then(|| w / duration)),
                    )
                    .collect()
            },
            momentum: MomentumSummary {
                start: l.momentum_start().to_vec(),
                end: l.momentum_end().to_vec(),
                external_impulse: (0..d)
                    .map(|k| (0..l.names().len()).map(|i| l.impulse(i)[k]).sum::<Real>() + 0.0)
                    .collect(),
                events_change: l.jump_momentum().to_vec(),
                residual: l.momentum_residual(),
            },
            centre_of_mass: {
                let (q0, v0) = report.initial.qv();
                let (start, internal_start) = centre_of_mass(sys, q0, v0);
                let (end, internal) = centre_of_mass(sys, q, v);
                let potential_change = |internal: bool| {
                    let changes: Vec<Real> = sys
                        .forces()
                        .iter()
                        .enumerate()
                        .filter(|(_, f)| f.internal() == internal)
                        .filter_map(|(i, _)| l.potential_change(i))
                        .collect();
                    (!changes.is_empty()).then(|| changes.iter().sum())
                };
                CentreOfMass {
                    total_mass: sys.masses().iter().sum(),
                    start,
                    end,
                    internal_kinetic_end: internal,
                    internal_kinetic_start: internal_start,
                    internal_potential_change: potential_change(true),
                    external_potential_change: potential_change(false),
                }
            },
            impulse: l
                .names()
                .iter()
                .enumerate()
                .map(|(i, n)| (n.clone(), l.impulse(i).to_vec()))
                .collect(),
            kinetic_energy: StartEnd {
                start: Some(l.kinetic_start()),
                end: Some(l.kinetic_end()),
            },
            rotational_kinetic_energy: sys.has_rotation().then(|| {
                let (q0, v0) = report.initial.qv();
                StartEnd {
                    start: Some(sys.rotational_kinetic_energy(q0, v0)),
                    end: Some(sys.rotational_kinetic_energy(q, v)),
                }
            }),
            potential_energy: StartEnd {
                start: l.potential_start(),
                end: l.potential_end(),
            },
            energy: EnergySummary {
                start: e0,
                end: e1,
                change: e1 - e0,
                non_conservative_work: l.non_conservative_work(),
                events_change: l.jump_energy(),
                relative_drift: (l.potential_start().is_some() && e0 != 0.0)
                    .then(|| (e1 - e0 - l.non_conservative_work() - l.jump_energy()) / e0.abs()),
            },
            work_energy_residual: l.work_energy_residual(),
            events: report
                .events
                .iter()
                .map(|e| EventSummary {
                    name: e.name.clone(),
                    occurrence: e.occurrence,
                    terminal: e.terminal,
                    t: e.t,
                    state: states(sys, &e.state.q, &e.state.v),
                    last_step: timed(sys, &e.last_step),
                    crossing_step: timed(sys, &e.crossing_step),
                    after: e.after.as_ref().map(|a| states(sys, &a.q, &a.v)),
                })
                .collect(),
            observable_units: observables
                .iter()
                .filter_map(|(n, _, u)| u.clone().map(|u| (n.clone(), u)))
                .collect(),
            observables: observables.into_iter().map(|(n, v, _)| (n, v)).collect(),
            divergence: report.divergence.as_ref().map(|d| DivergenceSummary {
                t: d.t,
                quantity: d.quantity.clone(),
                message: d.message.clone(),
            }),
            warnings,
            files: Files::default(),
        }
    }

    /// The summary labelled in `units`: in reduced units `units` is `"reduced"` and every
    /// observable's unit `"1"`; in SI unchanged.
    #[must_use]
    pub fn in_units(mut self, units: mechkit_expr::units::UnitSystem) -> Self {
        if units == mechkit_expr::units::UnitSystem::Reduced {
            self.units = Some(units.name());
            self.observable_units = self
                .observables
                .keys()
                .map(|n| (n.clone(), units.label("").to_string()))
                .collect();
        }
        self
    }

    /// Whether the numbers are in reduced units (printed without SI units).
    pub fn is_reduced(&self) -> bool {
        self.units == Some(mechkit_expr::units::UnitSystem::Reduced.name())
    }

    /// Pretty JSON, ending with a newline.
    pub fn to_json(&self) -> String {
        let mut s = serde_json::to_string_pretty(self).expect("a summary always serializes");
        s.push('\n');
        s
    }
}

//! The summary of a run: what `summary.json` holds (a contract: keys are only ever added) and
//! the short human-readable version the CLI prints.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use serde::Serialize;

use crate::Real;
use crate::particles::ParticleSystem;
use crate::simulate::{RunReport, Snapshot};

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

/// A body at the end of the run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BodySummary {
    /// Mass (kg).
    pub mass: Real,
    /// Final position (m).
    pub position: Vec<Real>,
    /// Final velocity (m/s).
    pub velocity: Vec<Real>,
    /// Final speed (m/s).
    pub speed: Real,
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
}

/// A located event.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct EventSummary {
    /// The condition, as written.
    pub name: String,
    /// Time of the crossing, located between steps (s).
    pub t: Real,
    /// The state at the crossing.
    pub state: BTreeMap<String, BodyState>,
    /// The last step before the crossing (the answer of a `while` loop).
    pub last_step: TimedState,
    /// The step that crossed.
    pub crossing_step: TimedState,
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
    /// Plots.
    pub plots: Vec<String>,
}

/// The summary of a run (`summary.json`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Summary {
    /// Scenario title.
    pub title: String,
    /// The scenario file.
    pub scenario: String,
    /// Integration method.
    pub method: String,
    /// Time step (s).
    pub dt: Real,
    /// Start time (s).
    pub t_start: Real,
    /// End time (s): `t_max`, the located event, or the last finite state.
    pub t_end: Real,
    /// Steps taken.
    pub steps: u64,
    /// Force evaluations.
    pub evaluations: u64,
    /// `t_max`, `event`, `max_steps` or `diverged`.
    pub stop_reason: String,
    /// Every body's final state.
    pub bodies: BTreeMap<String, BodySummary>,
    /// Work done by each force (J), integrated as power along the computed path.
    pub work: BTreeMap<String, Real>,
    /// Kinetic energy (J).
    pub kinetic_energy: StartEnd,
    /// Potential energy of the conservative forces (J); null when none has a potential.
    pub potential_energy: StartEnd,
    /// Mechanical energy (J).
    pub energy: EnergySummary,
    /// `Σ work - ΔK` (J): zero for an exact trajectory.
    pub work_energy_residual: Real,
    /// Located events.
    pub events: Vec<EventSummary>,
    /// `[observe]` results.
    pub observables: BTreeMap<String, Real>,
    /// SI unit of each observable whose dimension is known (`""` for pure numbers).
    pub observable_units: BTreeMap<String, String>,
    /// Set when the run diverged.
    pub divergence: Option<DivergenceSummary>,
    /// Warnings about the setup or the run.
    pub warnings: Vec<String>,
    /// Files written.
    pub files: Files,
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
    ) -> Self {
        let (q, v) = report.final_state.qv();
        let d = sys.dim();
        let bodies = sys
            .bodies()
            .iter()
            .enumerate()
            .map(|(i, b)| {
                let vel = v[i * d..(i + 1) * d].to_vec();
                let speed = vel.iter().map(|x| x * x).sum::<Real>().sqrt();
                (
                    b.name.clone(),
                    BodySummary {
                        mass: b.mass,
                        position: q[i * d..(i + 1) * d].to_vec(),
                        velocity: vel,
                        speed,
                    },
                )
            })
            .collect();
        let l = &report.ledger;
        let (e0, e1) = l.energy();
        Summary {
            title: title.to_string(),
            scenario: scenario.to_string(),
            method: report.method.name().to_string(),
            dt: report.dt,
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
            kinetic_energy: StartEnd {
                start: Some(l.kinetic_start()),
                end: Some(l.kinetic_end()),
            },
            potential_energy: StartEnd {
                start: l.potential_start(),
                end: l.potential_end(),
            },
            energy: EnergySummary {
                start: e0,
                end: e1,
                change: e1 - e0,
                non_conservative_work: l.non_conservative_work(),
            },
            work_energy_residual: l.work_energy_residual(),
            events: report
                .event
                .iter()
                .map(|e| EventSummary {
                    name: e.name.clone(),
                    t: e.t,
                    state: states(sys, &e.state.q, &e.state.v),
                    last_step: timed(sys, &e.last_step),
                    crossing_step: timed(sys, &e.crossing_step),
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

    /// Pretty JSON, ending with a newline.
    pub fn to_json(&self) -> String {
        let mut s = serde_json::to_string_pretty(self).expect("a summary always serializes");
        s.push('\n');
        s
    }

    /// A short report for people: final state, stop reason, energy ledger, observables
    /// (warnings are left to the caller, for stderr).
    pub fn to_text(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(s, "{}", self.title);
        let _ = writeln!(
            s,
            "  {} with dt = {} s: {} steps, t = {} → {} s, stopped by {}",
            self.method,
            num(self.dt),
            self.steps,
            num(self.t_start),
            num(self.t_end),
            self.stop_reason
        );
        for e in &self.events {
            let _ = writeln!(
                s,
                "  event `{}` at t = {} s (last step before it: t = {} s)",
                e.name,
                num(e.t),
                num(e.last_step.t)
            );
        }
        if let Some(d) = &self.divergence {
            let _ = writeln!(s, "  DIVERGED: {}", d.message);
        }
        let _ = writeln!(s, "final state");
        for (name, b) in &self.bodies {
            let _ = writeln!(
                s,
                "  {name}: position {} m, velocity {} m/s",
                vec_text(&b.position),
                vec_text(&b.velocity)
            );
        }
        let _ = writeln!(s, "energy ledger (J)");
        for (name, w) in &self.work {
            let _ = writeln!(s, "  work of {name:<16} {}", num(*w));
        }
        let (k0, k1) = (
            self.kinetic_energy.start.unwrap_or(0.0),
            self.kinetic_energy.end.unwrap_or(0.0),
        );
        let _ = writeln!(
            s,
            "  kinetic energy         {} → {} (ΔK = {})",
            num(k0),
            num(k1),
            num(k1 - k0)
        );
        if let (Some(u0), Some(u1)) = (self.potential_energy.start, self.potential_energy.end) {
            let _ = writeln!(
                s,
                "  potential energy       {} → {} (ΔU = {})",
                num(u0),
                num(u1),
                num(u1 - u0)
            );
            let _ = writeln!(
                s,
                "  mechanical energy      {} → {} (ΔE = {})",
                num(self.energy.start),
                num(self.energy.end),
                num(self.energy.change)
            );
        }
        let _ = writeln!(
            s,
            "  work-energy residual   {} (Σ work - ΔK)",
            num(self.work_energy_residual)
        );
        if !self.observables.is_empty() {
            let _ = writeln!(s, "observables");
            for (name, v) in &self.observables {
                let unit = self.observable_units.get(name).filter(|u| !u.is_empty());
                match unit {
                    Some(u) => {
                        let _ = writeln!(s, "  {name} = {} {u}", num(*v));
                    }
                    None => {
                        let _ = writeln!(s, "  {name} = {}", num(*v));
                    }
                }
            }
        }
        s
    }
}

/// A number with 7 significant digits, for people.
fn num(x: Real) -> String {
    if x == 0.0 {
        return "0".into();
    }
    if !x.is_finite() {
        return format!("{x}");
    }
    let a = x.abs();
    if (1e-4..1e7).contains(&a) {
        let digits = (6 - a.log10().floor() as i32).max(0) as usize;
        let s = format!("{x:.digits$}");
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    } else {
        format!("{x:.6e}")
    }
}

fn vec_text(v: &[Real]) -> String {
    if v.len() == 1 {
        num(v[0])
    } else {
        format!(
            "({})",
            v.iter().map(|x| num(*x)).collect::<Vec<_>>().join(", ")
        )
    }
}

#[cfg(test)]
mod tests {
    use super::num;

    #[test]
    fn numbers_for_people() {
        assert_eq!(num(4.834_559_8), "4.83456");
        assert_eq!(num(-0.499_999_999), "-0.5");
        assert_eq!(num(2.8e-4), "0.00028");
        assert_eq!(num(1.5e-9), "1.500000e-9");
        assert_eq!(num(1538.0), "1538");
        assert_eq!(num(-0.0), "0");
    }
}

//! "Which method should I trust?": one scenario run with several methods and compared with a
//! reference solution (DOP853 at rtol 1e-12) at common output times: the position error and
//! the energy error of each over time, the cost, and the time of the stop event.

use serde::Serialize;

use super::Scenario;
use super::error::{ErrorKind, ScenarioError};
use crate::Real;
use crate::figure::{PlotData, Scale, Series};
use crate::ode::{AdaptiveConfig, Method, MethodKind, Tolerance};
use crate::particles::{Sample, SampleKind};
use crate::simulate::{Observer, ObserverError, RunReport, Simulation, Stepping};

/// Output times per comparison run.
const POINTS: u32 = 2000;

/// How each compared method steps when the scenario does not say.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct CompareSettings {
    /// Step for fixed-step methods (default: the scenario's `dt`).
    pub dt: Option<Real>,
    /// Relative tolerance for adaptive methods (default: the scenario's, else 1e-6).
    pub rtol: Option<Real>,
    /// Absolute tolerance for adaptive methods (default: the scenario's, else 1e-9).
    pub atol: Option<Real>,
}

/// One method's result against the reference.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MethodResult {
    /// The method and its step size control, for people.
    pub method: String,
    /// Why it could not run, if it could not (then the numbers are absent).
    pub error: Option<String>,
    /// Steps taken.
    pub steps: u64,
    /// Force evaluations.
    pub evaluations: u64,
    /// Largest distance from the reference position at the common output times (m).
    pub max_position_error: Option<Real>,
    /// Distance from the reference at the last common output time (m).
    pub final_position_error: Option<Real>,
    /// The method's energy error relative to `|E(0)|`, at its largest: with conservative forces
    /// only, `|E(t) - E(0)|` over every step; with non-conservative ones (drag),
    /// `|E(t) - E_ref(t)|` at the output times. Null without potentials.
    pub max_energy_error: Option<Real>,
    /// Its value at the end of the run (signed).
    pub final_energy_error: Option<Real>,
    /// Time of the stop event, if one fired (s).
    pub event_t: Option<Real>,
    /// Its difference from the reference's (s).
    pub event_error: Option<Real>,
    /// How the run ended.
    pub stop_reason: String,
}

/// The comparison.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Comparison {
    /// Scenario title.
    pub title: String,
    /// The reference solution's settings.
    pub reference: String,
    /// Its stop event time, if any.
    pub reference_event_t: Option<Real>,
    /// Output time spacing (s).
    pub interval: Real,
    /// One entry per method, in the order asked.
    pub methods: Vec<MethodResult>,
    /// Error over time, per method (for plots).
    #[serde(skip)]
    pub plots: Vec<PlotData>,
}

/// Keeps the output-time samples: positions and the energy error.
#[derive(Default)]
struct Track {
    t: Vec<Real>,
    q: Vec<Vec<Real>>,
    /// Largest |energy error| between consecutive output times.
    energy_error: Vec<Real>,
    window: Real,
    /// Mechanical energy at the output times.
    e_grid: Vec<Real>,
    e0: Option<Real>,
    final_energy_error: Option<Real>,
    last_signed: Option<Real>,
}

impl Observer for Track {
    fn observe(&mut self, s: &Sample<'_>) -> Result<(), ObserverError> {
        let e = s.eval.potential_total.map(|u| s.eval.kinetic + u);
        if s.step == 0 && s.kind == SampleKind::Step {
            self.e0 = e;
        }
        let err = match (e, self.e0) {
            (Some(e), Some(e0)) if e0 != 0.0 => ((e - e0) / e0.abs()).abs(),
            _ => Real::NAN,
        };
        // the largest error since the last output time: the envelope, free of strobing
        self.window = if self.window.is_nan() {
            err
        } else {
            self.window.max(err)
        };
        self.last_signed = match (e, self.e0) {
            (Some(e), Some(e0)) if e0 != 0.0 => Some((e - e0) / e0.abs()),
            _ => None,
        };
        if s.kind == SampleKind::Grid || (s.step == 0 && s.kind == SampleKind::Step) {
            self.t.push(s.t);
            self.q.push(s.q.to_vec());
            self.energy_error.push(self.window);
            self.e_grid.push(e.unwrap_or(Real::NAN));
            self.window = Real::NAN;
        }
        Ok(())
    }

    fn finish(&mut self, _last: &Sample<'_>) -> Result<(), ObserverError> {
        self.final_energy_error = self.last_signed;
        Ok(())
    }
}

impl Scenario {
    /// Runs the scenario with each of `methods` and with a reference (DOP853, rtol 1e-12), and
    /// compares them at common output times.
    pub fn compare(
        &self,
        methods: &[Method],
        settings: &CompareSettings,
    ) -> Result<Comparison, ScenarioError> {
        let span = self.t_max.ok_or_else(|| {
            ScenarioError::new(ErrorKind::Invalid, "comparing methods needs [stop] t_max")
                .with_hint("add `t_max` to [stop]; the comparison samples the run at common times")
        })?;
        let interval = span / Real::from(POINTS);
        let (q, v) = self.initial.qv();
        let (q, v) = (q.to_vec(), v.to_vec());
        // potential-free forces count as non-conservative
        let nonconservative: Vec<usize> = {
            let mut eval = crate::particles::Evaluation::default();
            self.system
                .evaluate(0.0, &q, &v, &mut eval, &mut Vec::new());
            eval.potential
                .iter()
                .enumerate()
                .filter(|(_, u)| u.is_nan())
                .map(|(i, _)| i)
                .collect()
        };
        let scale = q
            .iter()
            .chain(&v)
            .fold(0.0, |m: Real, x| m.max(x.abs()))
            .max(1e-300);
        let reference = Stepping::Adaptive {
            method: Method::Dop853,
            config: AdaptiveConfig {
                rtol: Tolerance::Scalar(1e-12),
                atol: Tolerance::Scalar(1e-14 * scale),
                ..AdaptiveConfig::default()
            },
        };
        let run = |stepping: &Stepping| -> Result<(RunReport, Track), String> {
            let mut track = Track {
                window: Real::NAN,
                ..Track::default()
            };
            let mut sim = Simulation::with_stepping(&self.system, stepping.clone())
                .t_max(span)
                .output_interval(interval)
                .cancel_on(self.cancel.clone());
            if let Some(c) = &self.stop {
                sim = sim.stop_when(c.clone());
            }
            for e in &self.events {
                sim = sim.event(e.clone());
            }
            if let Some(n) = self.max_steps {
                sim = sim.max_steps(n);
            }
            let report = sim
                .run(self.initial.clone(), &mut [&mut track])
                .map_err(|e| e.to_string())?;
            Ok((report, track))
        };
        let (ref_report, ref_track) = run(&reference).map_err(|e| {
            ScenarioError::new(ErrorKind::Invalid, format!("the reference run failed: {e}"))
        })?;
        let ref_event = ref_report.event.as_ref().map(|e| e.t);

        let mut results = Vec::new();
        let mut error_series = Vec::new();
        let mut energy_series = Vec::new();
        for &method in methods {
            let stepping = self.stepping_for(method, settings);
            let label = stepping
                .as_ref()
                .map_or_else(|_| method.name().to_string(), Stepping::describe);
            let outcome = stepping.and_then(|s| run(&s));
            let (report, track) = match outcome {
                Ok(x) => x,
                Err(e) => {
                    results.push(MethodResult {
                        method: label,
                        error: Some(e),
                        steps: 0,
                        evaluations: 0,
                        max_position_error: None,
                        final_position_error: None,
                        max_energy_error: None,
                        final_energy_error: None,
                        event_t: None,
                        event_error: None,
                        stop_reason: "not run".into(),
                    });
                    continue;
                }
            };
            let n = track.t.len().min(ref_track.t.len());
            let errors: Vec<(Real, Real)> = (0..n)
                .map(|k| {
                    let d = track.q[k]
                        .iter()
                        .zip(&ref_track.q[k])
                        .map(|(a, b)| (a - b) * (a - b))
                        .sum::<Real>()
                        .sqrt();
                    (track.t[k], d)
                })
                .collect();
            // conservative forces only: the envelope of |E - E0|/|E0| over every step; with
            // drag the energy is compared with the reference's at the output times (the ledger's
            // work integral would add its own quadrature error)
            let conservative = nonconservative.is_empty();
            let e0 = track.e0.unwrap_or(Real::NAN).abs();
            let energy: Vec<(Real, Real)> = if conservative {
                track
                    .t
                    .iter()
                    .copied()
                    .zip(track.energy_error.iter().copied())
                    .collect()
            } else {
                (0..n)
                    .map(|k| {
                        (
                            track.t[k],
                            ((track.e_grid[k] - ref_track.e_grid[k]) / e0).abs(),
                        )
                    })
                    .collect()
            };
            let final_energy = if conservative {
                track.final_energy_error
            } else {
                n.checked_sub(1)
                    .map(|k| (track.e_grid[k] - ref_track.e_grid[k]) / e0)
            };
            let finite_max = |v: &mut dyn Iterator<Item = Real>| {
                v.filter(|x| x.is_finite())
                    .fold(None, |m: Option<Real>, x| Some(m.map_or(x, |m| m.max(x))))
            };
            let event_t = report.event.as_ref().map(|e| e.t);
            results.push(MethodResult {
                method: label.clone(),
                error: None,
                steps: report.steps,
                evaluations: report.evaluations,
                max_position_error: finite_max(&mut errors.iter().map(|p| p.1)),
                final_position_error: errors.last().map(|p| p.1),
                max_energy_error: finite_max(&mut energy.iter().map(|p| p.1.abs())),
                final_energy_error: final_energy.filter(|x| x.is_finite()),
                event_t,
                event_error: event_t.zip(ref_event).map(|(a, b)| a - b),
                stop_reason: report.stop_reason.name().to_string(),
            });
            // drawn on log axes: an exact zero (the common start) is cut out of the curve there
            error_series.push(Series::line(method.name(), errors));
            if energy.iter().any(|p| p.1.is_finite()) {
                energy_series.push(Series::line(
                    method.name(),
                    energy.iter().map(|&(t, e)| (t, e.abs())).collect(),
                ));
            }
        }
        let mut error_plot = PlotData::new(
            "position error against the reference",
            "compare_error",
            "t [s]",
            "position error [m]",
        )
        .with_y_scale(Scale::Log);
        error_plot.series = error_series;
        let mut plots = vec![error_plot];
        if !energy_series.is_empty() {
            let mut energy_plot = PlotData::new(
                if nonconservative.is_empty() {
                    "largest energy error |E - E0|/|E0| between output times"
                } else {
                    "energy error |E - E_ref|/|E0|"
                },
                "compare_energy",
                "t [s]",
                "relative energy error",
            )
            .with_y_scale(Scale::Log);
            energy_plot.series = energy_series;
            plots.push(energy_plot);
        }
        Ok(Comparison {
            title: self.title.clone(),
            reference: reference.describe(),
            reference_event_t: ref_event,
            interval,
            methods: results,
            plots,
        })
    }

    fn stepping_for(&self, method: Method, settings: &CompareSettings) -> Result<Stepping, String> {
        let scenario_dt = self.stepping.dt();
        // an implicit method has adaptive steps only
        if method.kind() == MethodKind::Implicit
            || method.kind() == MethodKind::Adaptive && settings.dt.is_none()
        {
            let mut config = match &self.stepping {
                Stepping::Adaptive { config, .. } => config.clone(),
                Stepping::Fixed { .. } => AdaptiveConfig::default(),
            };
            if let Some(r) = settings.rtol {
                config.rtol = Tolerance::Scalar(r);
            }
            if let Some(a) = settings.atol {
                config.atol = Tolerance::Scalar(a);
            }
            return Ok(Stepping::Adaptive { method, config });
        }
        let dt = settings.dt.or(scenario_dt).ok_or_else(|| {
            format!(
                "{} takes fixed steps and the scenario has no dt: give --dt",
                method.name()
            )
        })?;
        Ok(Stepping::Fixed { method, dt })
    }
}

impl Comparison {
    /// A table for people.
    pub fn to_text(&self) -> String {
        use std::fmt::Write as _;
        let mut s = String::new();
        let _ = writeln!(
            s,
            "{}: methods against the reference ({})",
            self.title, self.reference
        );
        let _ = writeln!(
            s,
            "  {:<42} {:>9} {:>11} {:>12} {:>12} {:>12}{}",
            "method",
            "steps",
            "evaluations",
            "max |Δr| m",
            "final |Δr| m",
            "max |ΔE/E|",
            if self.reference_event_t.is_some() {
                "    event Δt s"
            } else {
                ""
            }
        );
        let show = |x: Option<Real>| x.map_or_else(|| "-".to_string(), |x| format!("{x:.3e}"));
        for m in &self.methods {
            if let Some(e) = &m.error {
                let _ = writeln!(s, "  {:<42} not run: {e}", m.method);
                continue;
            }
            let _ = write!(
                s,
                "  {:<42} {:>9} {:>11} {:>12} {:>12} {:>12}",
                m.method,
                m.steps,
                m.evaluations,
                show(m.max_position_error),
                show(m.final_position_error),
                show(m.max_energy_error),
            );
            if self.reference_event_t.is_some() {
                let _ = write!(s, "  {:>12}", show(m.event_error));
            }
            let _ = writeln!(s);
        }
        if let Some(t) = self.reference_event_t {
            let _ = writeln!(
                s,
                "  reference stop event at t = {} s",
                crate::error::short(t)
            );
        }
        s
    }

    /// Pretty JSON.
    pub fn to_json(&self) -> String {
        let mut s = serde_json::to_string_pretty(self).expect("a comparison serializes");
        s.push('\n');
        s
    }
}

//! What `mechkit check` reports about a scenario it read without running it.

use serde::Serialize;

use super::Scenario;
use crate::Real;

/// A scenario's setup, as read and checked (`mechkit check --json`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CheckReport {
    /// Scenario title.
    pub title: String,
    /// Spatial dimensions (1, 2 or 3).
    pub dimensions: usize,
    /// The constants with their SI values.
    pub constants: Vec<CheckedConstant>,
    /// The bodies.
    pub bodies: Vec<CheckedBody>,
    /// The forces' names.
    pub forces: Vec<String>,
    /// The integration method, described (`rk4, dt = 0.001 s`).
    pub method: String,
    /// The events, with the state change each makes.
    pub events: Vec<CheckedEvent>,
    /// The stop condition, as written.
    pub stop_when: Option<String>,
    /// The end time (s).
    pub t_max: Option<Real>,
    /// The observables: name and formula.
    pub observables: Vec<(String, String)>,
    /// The plots' specifications.
    pub plots: Vec<String>,
    /// Warnings about the setup.
    pub warnings: Vec<String>,
    /// `"reduced"` for a scenario in reduced units (its numbers are not SI); absent in SI.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub units: Option<&'static str>,
}

/// A constant.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CheckedConstant {
    /// Its name.
    pub name: String,
    /// Its value in SI units.
    pub value: Real,
}

/// A body.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CheckedBody {
    /// Its name.
    pub name: String,
    /// Its mass (kg; for a hinged body its moment of inertia, kg m²).
    pub mass: Real,
}

/// An event.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CheckedEvent {
    /// Its name.
    pub name: String,
    /// The state change it makes (`vy = -0.9*vy`), if any.
    pub sets: Option<String>,
}

impl Scenario {
    /// What the scenario sets up (`mechkit check`).
    pub fn check_report(&self) -> CheckReport {
        let sys = &self.system;
        let reduced = self.units == mechkit_expr::units::UnitSystem::Reduced;
        CheckReport {
            title: self.title.clone(),
            dimensions: self.dim,
            constants: self
                .constants
                .iter()
                .map(|(name, value, _)| CheckedConstant {
                    name: name.clone(),
                    value: *value,
                })
                .collect(),
            bodies: sys
                .bodies()
                .iter()
                .map(|b| CheckedBody {
                    name: b.name.clone(),
                    mass: b.mass,
                })
                .collect(),
            forces: sys.forces().iter().map(|f| f.name().to_string()).collect(),
            method: match &self.stepping {
                crate::simulate::Stepping::Fixed { method, dt } if reduced => {
                    format!("{method} with dt = {}", crate::error::short(*dt))
                }
                other => other.describe(),
            },
            events: self
                .events
                .iter()
                .map(|e| CheckedEvent {
                    name: e.name().to_string(),
                    sets: e.state_change_description().map(str::to_string),
                })
                .collect(),
            stop_when: self.stop.as_ref().map(|c| c.description().to_string()),
            t_max: self.t_max,
            observables: self
                .observables
                .iter()
                .map(|o| (o.name.clone(), o.source.clone()))
                .collect(),
            plots: self.plots.iter().map(|p| p.spec.clone()).collect(),
            warnings: self.warnings.clone(),
            units: reduced.then_some(self.units.name()),
        }
    }
}

impl CheckReport {
    /// The text `mechkit check` prints.
    pub fn to_text(&self) -> String {
        use std::fmt::Write as _;
        let short = crate::error::short;
        let plural =
            |n: usize, one: &str, many: &str| format!("{n} {}", if n == 1 { one } else { many });
        let mut text = String::new();
        let _ = writeln!(text, "ok: {}", mechkit_expr::span::printable(&self.title));
        let _ = writeln!(
            text,
            "  {}, {}, {}",
            plural(self.dimensions, "dimension", "dimensions"),
            plural(self.bodies.len(), "body", "bodies"),
            plural(self.forces.len(), "force", "forces")
        );
        // SI units after numbers, none in reduced units
        let (kg, s) = if self.units.is_some() {
            ("", "")
        } else {
            (" kg", " s")
        };
        if let Some(u) = self.units {
            let _ = writeln!(text, "  in {u} units");
        }
        for b in &self.bodies {
            let _ = writeln!(text, "  body {}: {}{kg}", b.name, short(b.mass));
        }
        for f in &self.forces {
            let _ = writeln!(text, "  force {f}");
        }
        let _ = writeln!(text, "  method {}", self.method);
        for e in &self.events {
            let _ = writeln!(
                text,
                "  event `{}`{}",
                e.name,
                e.sets
                    .as_ref()
                    .map(|d| format!(": set {d}"))
                    .unwrap_or_default()
            );
        }
        let _ = match (&self.stop_when, self.t_max) {
            (Some(c), Some(t)) => writeln!(text, "  stops when `{c}` or at t = {}{s}", short(t)),
            (Some(c), None) => writeln!(text, "  stops when `{c}`"),
            (None, Some(t)) => writeln!(text, "  stops at t = {}{s}", short(t)),
            (None, None) => Ok(()),
        };
        for (name, source) in &self.observables {
            let _ = writeln!(text, "  observe {name} = {source}");
        }
        for p in &self.plots {
            let _ = writeln!(text, "  plot {p}");
        }
        text
    }
}

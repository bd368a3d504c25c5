//! Plots as data: `"x(t)"`, `"v(x)"`, `"y(x)"`, `"energy(t)"` name what to draw against what;
//! the samples are collected during the run, and a front end (the CLI) renders them.
//!
//! A name without a body (`x`) is drawn for every body; `feather.x` for one. `energy(t)`
//! draws `K`, `U`, `E` and the work of each force.

use mechkit_expr::nearest;
use toml::de::DeValue;

use super::analytic::{Analytic, read_analytic};
use super::doc::Table;
use super::energy_bars::ENERGY_BARS;
use super::error::{ErrorKind, ScenarioError};
use super::values::{ValueEnv, resolve, scalar};
use mechkit_expr::units::Dimension;

use crate::Real;
use crate::particles::{BodyRef, NameContext, StateVar, VarLevel};

const OUTPUT_KEYS: &[&str] = &[
    "every",
    "interval",
    "times",
    "plots",
    "max_size",
    "analytic",
    "animation",
];

/// Output times: every `interval`, or a list.
#[derive(Debug, Clone, PartialEq)]
pub enum OutputTimes {
    /// Every so many seconds from the start.
    Every(Real),
    /// At these times (s).
    At(Vec<Real>),
}

/// The decimation, the output times, the plots, and whether the energy bars are drawn.
type Output = (u64, Option<OutputTimes>, Vec<PlotSpec>, bool);

/// `times = ["0.5 s", "1 s", …]`: increasing times.
fn output_times(t: &Table<'_, '_>, env: ValueEnv<'_>) -> Result<Option<Vec<Real>>, ScenarioError> {
    let Some(v) = t.get("times") else {
        return Ok(None);
    };
    let DeValue::Array(items) = v.get_ref() else {
        return Err(t.wrong_type("times", v, "a list such as [\"0.5 s\", \"1 s\"]"));
    };
    let mut out: Vec<Real> = Vec::new();
    for item in items {
        let x = resolve(&t.src, "times", item, Dimension::TIME, env)?;
        if let Some(prev) = out.last()
            && x.partial_cmp(prev) != Some(std::cmp::Ordering::Greater)
        {
            return Err(t
                .src
                .error(
                    ErrorKind::Invalid,
                    format!(
                        "the output times must increase: {} s comes after {} s",
                        crate::error::short(x),
                        crate::error::short(*prev)
                    ),
                    item.span(),
                )
                .with_hint("list the times in increasing order"));
        }
        out.push(x);
    }
    Ok(Some(out))
}

/// Reads `[output]`: the decimation `every`, the output times (`interval` or `times`) and the
/// plots (`energy-bars` among them is the ledger's bar chart, drawn after the run).
pub(crate) fn read_output(
    root: &Table<'_, '_>,
    names: &NameContext<'_>,
    dim: usize,
    env: ValueEnv<'_>,
) -> Result<Output, ScenarioError> {
    let t = root.table("output")?;
    let interval = match &t {
        Some(t) => {
            let i = scalar(t, "interval", Dimension::TIME, env)?;
            if let Some(i) = i
                && !(i > 0.0 && i.is_finite())
            {
                return Err(t.src.error(
                    ErrorKind::Invalid,
                    format!(
                        "`interval` must be a positive time, not {} s",
                        crate::error::short(i)
                    ),
                    t.key_span("interval"),
                ));
            }
            let times = output_times(t, env)?;
            if (i.is_some() || times.is_some()) && t.get("every").is_some() {
                return Err(t
                    .src
                    .error(
                        ErrorKind::Invalid,
                        "`every` thins the steps, `interval` and `times` replace them by output times: give one or the other",
                        t.key_span("every"),
                    ));
            }
            match (i, times) {
                (Some(_), Some(_)) => {
                    return Err(t.src.error(
                        ErrorKind::Invalid,
                        "give `interval` (regular output times) or `times` (a list), not both",
                        t.key_span("times"),
                    ));
                }
                (Some(i), None) => Some(OutputTimes::Every(i)),
                (None, Some(list)) => Some(OutputTimes::At(list)),
                (None, None) => None,
            }
        }
        None => None,
    };
    let every = match &t {
        Some(t) => {
            t.check_keys(OUTPUT_KEYS)?;
            match t.count("every")? {
                Some((0, span)) => {
                    return Err(t
                        .src
                        .error(ErrorKind::Invalid, "`every` must be at least 1", span)
                        .with_hint("`every = 10` writes every tenth step (and the last); 1 writes every step"));
                }
                Some((n, _)) => n,
                None => 1,
            }
        }
        None => 1,
    };
    let specs: Vec<(String, Option<std::ops::Range<usize>>)> =
        match t.as_ref().and_then(|t| t.get("plots")) {
            Some(v) => match v.get_ref() {
                DeValue::Array(items) => items
                    .iter()
                    .map(|item| match item.get_ref() {
                        DeValue::String(s) => Ok((s.to_string(), Some(item.span()))),
                        _ => Err(t.as_ref().expect("plots came from the table").wrong_type(
                            "plots",
                            item,
                            "a string such as \"x(t)\"",
                        )),
                    })
                    .collect::<Result<_, _>>()?,
                _ => {
                    return Err(t.as_ref().expect("plots came from the table").wrong_type(
                        "plots",
                        v,
                        "a list such as [\"x(t)\", \"v(t)\"]",
                    ));
                }
            },
            None if names.coordinates == crate::particles::Coordinates::Angle => {
                ["theta(t)", "omega(t)", "energy(t)"]
                    .into_iter()
                    .map(|s| (s.to_string(), None))
                    .collect()
            }
            None => default_plots(dim)
                .into_iter()
                .map(|s| (s.to_string(), None))
                .collect(),
        };
    let src = root.src;
    let mut plots = Vec::new();
    let mut energy_bars = false;
    for (spec, span) in specs {
        if spec.trim() == ENERGY_BARS {
            energy_bars = true;
            continue;
        }
        let p = PlotSpec::parse(&spec, names).map_err(|(msg, hint)| match &span {
            Some(span) => src
                .error(ErrorKind::Invalid, msg, span.clone())
                .with_hint(hint),
            None => ScenarioError::new(ErrorKind::Invalid, msg).with_hint(hint),
        })?;
        plots.push(p);
    }
    if let Some(a) = t
        .as_ref()
        .map(|t| t.table("analytic"))
        .transpose()?
        .flatten()
    {
        read_analytic(&a, &mut plots, env)?;
    }
    Ok((every, interval, plots, energy_bars))
}

fn default_plots(dim: usize) -> Vec<&'static str> {
    match dim {
        1 => vec!["x(t)", "v(t)", "energy(t)"],
        2 => vec!["y(x)", "v(t)", "energy(t)"],
        _ => vec!["z(t)", "v(t)", "energy(t)"],
    }
}

/// One curve: `y` against `x`, for a body when the names are body-local.
#[derive(Debug, Clone, PartialEq)]
pub struct SeriesSpec {
    /// Legend label.
    pub label: String,
    /// Horizontal quantity.
    pub x: StateVar,
    /// Vertical quantity.
    pub y: StateVar,
    /// The body bare names refer to.
    pub body: Option<usize>,
}

/// A requested plot.
#[derive(Debug, Clone, PartialEq)]
pub struct PlotSpec {
    /// As written, e.g. `v(x)`.
    pub spec: String,
    /// Axis label of `x` with unit, e.g. `t [s]`.
    pub x_label: String,
    /// Axis label of `y` with unit.
    pub y_label: String,
    /// The curves.
    pub series: Vec<SeriesSpec>,
    /// The horizontal quantity as written, e.g. `t`.
    pub x_name: String,
    /// A formula of `x_name` drawn over the curves as markers (`[output.analytic]`).
    pub analytic: Option<Analytic>,
}

impl PlotSpec {
    /// Parses `Y(X)` against the scenario's names. Errors carry a message and a hint.
    pub fn parse(spec: &str, names: &NameContext<'_>) -> Result<PlotSpec, (String, String)> {
        let usage = "a plot is written `y(x)` with quantities such as t, x, y, vx, v, a, K, U, E: \"x(t)\", \"v(x)\", \"y(x)\", \"energy(t)\"; \"energy-bars\" draws the energy ledger as bars".to_string();
        let s = spec.trim();
        let open = s
            .rfind('(')
            .filter(|_| s.ends_with(')'))
            .ok_or_else(|| (format!("`{spec}` is not a plot"), usage.clone()))?;
        let y_name = s[..open].trim();
        let x_name = s[open + 1..s.len() - 1].trim();
        if y_name.is_empty() || x_name.is_empty() {
            return Err((format!("`{spec}` is not a plot"), usage));
        }
        let local = NameContext {
            bare: Some(BodyRef::Local),
            level: VarLevel::Derived,
            constants: &[],
            ..names.clone()
        };
        let resolve = |n: &str| {
            local.resolve(n).ok_or_else(|| {
                let all = local.all_names();
                let mut candidates: Vec<&str> = all.iter().map(String::as_str).collect();
                candidates.push("energy");
                let hint =
                    mechkit_expr::did_you_mean(&nearest(n, candidates)).unwrap_or(usage.clone());
                (
                    format!("`{n}` in the plot `{spec}` is not a quantity of this scenario"),
                    hint,
                )
            })
        };
        let x = resolve(x_name)?;
        let x_label = format!("{x_name} [{}]", local.coordinates.unit_in(x, local.units));
        let n_bodies = names.bodies.len();
        // `label` names the quantity when it is not the plot's own (energy plots); a series per
        // body is then labelled with both.
        let expand = |y: StateVar, label: Option<&str>| -> Vec<SeriesSpec> {
            let local_names = is_local(x) || is_local(y);
            if local_names && n_bodies > 1 {
                (0..n_bodies)
                    .map(|b| SeriesSpec {
                        label: match label {
                            Some(l) => format!("{l}, {}", names.bodies[b]),
                            None => names.bodies[b].clone(),
                        },
                        x,
                        y,
                        body: Some(b),
                    })
                    .collect()
            } else {
                let fallback = if n_bodies == 1 {
                    names.bodies[0].as_str()
                } else {
                    y_name
                };
                vec![SeriesSpec {
                    label: label.unwrap_or(fallback).to_string(),
                    x,
                    y,
                    body: local_names.then_some(0),
                }]
            }
        };
        if y_name == "energy" {
            let mut series = expand(StateVar::Kinetic, Some("K"));
            series.extend(expand(StateVar::Potential, Some("U")));
            series.extend(expand(StateVar::Energy, Some("E = K + U")));
            for (i, f) in names.forces.iter().enumerate() {
                series.extend(expand(StateVar::Work(i), Some(&format!("work of {f}"))));
            }
            return Ok(PlotSpec {
                spec: spec.to_string(),
                x_label,
                y_label: format!("energy [{}]", local.units.label("J")),
                series,
                x_name: x_name.to_string(),
                analytic: None,
            });
        }
        let y = resolve(y_name)?;
        Ok(PlotSpec {
            spec: spec.to_string(),
            x_label,
            y_label: format!("{y_name} [{}]", local.coordinates.unit_in(y, local.units)),
            series: expand(y, None),
            x_name: x_name.to_string(),
            analytic: None,
        })
    }

    /// A file name for the plot: `v(x)` → `v_x`, `feather.x(t)` → `feather.x_t`.
    pub fn file_stem(&self) -> String {
        let mut s: String = self
            .spec
            .trim()
            .chars()
            .map(|c| {
                if c.is_alphanumeric() || c == '.' || c == '_' || c == '-' {
                    c
                } else {
                    '_'
                }
            })
            .collect();
        while s.ends_with('_') {
            s.pop();
        }
        s.replace("__", "_")
    }
}

impl super::Scenario {
    /// Parses a plot spec (`"v(x)"`, `"energy(t)"`, `"b.x(t)"`) against this scenario's
    /// bodies, forces and coordinates, as `[output] plots` reads it: a front asks for a plot
    /// the file does not list (a sweep's `--plot`, the Python package's `Run.plot`) and gets
    /// it by running the scenario with `plots = vec![spec]`. `"energy-bars"` is no curve
    /// plot: it is [`Summary::energy_bars`](super::Summary::energy_bars).
    ///
    /// A spec that is not a plot of this scenario is an [`ErrorKind::Invalid`] error that
    /// names it, with a hint listing what a plot is written with (or the nearest name).
    ///
    /// ```
    /// use mechkit::scenario::Scenario;
    /// let s = Scenario::from_str("ball.toml", r#"
    ///     [[body]]
    ///     name = "ball"
    ///     mass = "1 kg"
    ///     [[force]]
    ///     kind = "uniform-gravity"
    ///     [integrator]
    ///     method = "rk4"
    ///     dt = "1 ms"
    ///     [stop]
    ///     t_max = "1 s"
    /// "#).unwrap();
    /// let p = s.plot_spec("v(x)").unwrap();
    /// assert_eq!((p.x_label.as_str(), p.y_label.as_str()), ("x [m]", "v [m/s]"));
    /// let e = s.plot_spec("w(t)").unwrap_err();
    /// assert!(e.message.contains("`w` in the plot `w(t)`"));
    /// ```
    pub fn plot_spec(&self, spec: &str) -> Result<PlotSpec, ScenarioError> {
        let bodies: Vec<String> = self
            .system
            .bodies()
            .iter()
            .map(|b| b.name.clone())
            .collect();
        let forces: Vec<String> = self
            .system
            .forces()
            .iter()
            .map(|f| f.name().to_string())
            .collect();
        let names = NameContext {
            dim: self.dim,
            bodies: &bodies,
            forces: &forces,
            constants: &self.constants,
            bare: (bodies.len() == 1).then_some(BodyRef::Index(0)),
            level: VarLevel::Derived,
            coordinates: self.system.coordinates(),
            units: self.units,
            planar: &self.planar,
        };
        PlotSpec::parse(spec, &names).map_err(|(message, hint)| {
            ScenarioError::new(ErrorKind::Invalid, message).with_hint(hint)
        })
    }
}

fn is_local(v: StateVar) -> bool {
    matches!(
        v,
        StateVar::Position(BodyRef::Local, _)
            | StateVar::Velocity(BodyRef::Local, _)
            | StateVar::Speed(BodyRef::Local)
            | StateVar::Distance(BodyRef::Local)
            | StateVar::Mass(BodyRef::Local)
            | StateVar::Acceleration(BodyRef::Local, _)
            | StateVar::AccelerationMagnitude(BodyRef::Local)
            | StateVar::BodyKinetic(BodyRef::Local)
    )
}

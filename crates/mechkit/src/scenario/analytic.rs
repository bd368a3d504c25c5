//! `[output.analytic]`: an exact solution drawn over a plot as markers, the way the course's
//! figures compare a simulation with its closed form.

use mechkit_expr::{ExprError, Formula, MapScope, Program};
use toml::de::DeValue;

use super::doc::Table;
use super::error::{ErrorKind, ScenarioError};
use super::plot::PlotSpec;
use super::values::{ValueEnv, formula_error};
use crate::Real;
use crate::figure::{LineStyle, PlotData, Series};

/// Points of an analytic curve drawn over a plot.
const ANALYTIC_POINTS: usize = 25;

/// An exact solution drawn over a plot: a formula of the plot's horizontal quantity.
#[derive(Debug, Clone)]
pub struct Analytic {
    /// As written.
    pub formula: String,
    /// Compiled, with the horizontal quantity in slot 0.
    pub program: Program,
}

impl PartialEq for Analytic {
    fn eq(&self, other: &Self) -> bool {
        self.formula == other.formula
    }
}

impl Analytic {
    /// Adds the formula as markers over the plot's curves, across their horizontal range.
    pub fn draw_over(&self, plot: &mut PlotData) {
        let (lo, hi) = plot
            .series
            .iter()
            .flat_map(|s| s.points.iter().map(|p| p.0))
            .filter(|x| x.is_finite())
            .fold((Real::INFINITY, Real::NEG_INFINITY), |(lo, hi), x| {
                (lo.min(x), hi.max(x))
            });
        if lo <= hi {
            plot.series.push(Series {
                label: format!("exact: {}", self.formula),
                points: self.sample(lo, hi, ANALYTIC_POINTS),
                style: LineStyle::Markers,
                value: None,
            });
        }
    }

    /// The formula at `n` evenly spaced points over `[lo, hi]` (finite values only).
    pub fn sample(&self, lo: Real, hi: Real, n: usize) -> Vec<(Real, Real)> {
        (0..n)
            .map(|i| {
                let x = if n > 1 {
                    lo + (hi - lo) * i as Real / (n - 1) as Real
                } else {
                    lo
                };
                (x, self.program.eval(&[x]))
            })
            .filter(|(_, y)| y.is_finite())
            .collect()
    }
}

/// `[output.analytic]`: `"v(t)" = "formula of t"` draws the formula over the plot `v(t)` as
/// markers, from the scenario's constants and the plot's horizontal quantity.
pub(super) fn read_analytic(
    a: &Table<'_, '_>,
    plots: &mut [PlotSpec],
    env: ValueEnv<'_>,
) -> Result<(), ScenarioError> {
    for (key, value) in a.entries {
        let spec: &str = key.get_ref();
        let drawn: Vec<String> = plots.iter().map(|p| p.spec.clone()).collect();
        let Some(plot) = plots.iter_mut().find(|p| p.spec.trim() == spec.trim()) else {
            return Err(a
                .src
                .error(
                    ErrorKind::Invalid,
                    format!("`{spec}` in [output.analytic] is not one of the plots"),
                    key.span(),
                )
                .with_hint(format!(
                    "the plots drawn are {}; name one of them, or add it to `plots`",
                    drawn.join(", ")
                )));
        };
        let DeValue::String(text) = value.get_ref() else {
            return Err(a.wrong_type(spec, value, "a formula string such as \"-g*t\""));
        };
        let mut scope = MapScope::new().described(format!(
            "an analytic curve is a formula of `{}` and the names of [constants]",
            plot.x_name
        ));
        for (name, v, _) in env.constants {
            scope = scope.constant(name, *v);
        }
        scope = scope.slot(&plot.x_name, 0);
        let located = |e: &ExprError| formula_error(&a.src, &value.span(), e);
        let formula = Formula::parse(text).map_err(|e| located(&e))?;
        let program = formula.compile(&scope).map_err(|e| located(&e))?;
        plot.analytic = Some(Analytic {
            formula: text.to_string(),
            program,
        });
    }
    Ok(())
}

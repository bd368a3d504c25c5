//! The whole question about a one-dimensional potential, as `mechkit potential` asks it: the
//! force (or the potential from a force), the equilibria with their stability on a range, the
//! singular points, what a total energy (or a body released with a speed) allows, and `U`, `F`
//! and `v` at chosen points, with the energy diagram and `v(x)` as plot data and a table.
//!
//! ```
//! use mechkit::energy::{Given, PotentialQuestion, Release, Stability, analyse_potential};
//! let q = PotentialQuestion {
//!     release: Some(Release { mass: 1.0, x0: 0.0, v0: 0.5 }),
//!     ..PotentialQuestion::new(Given::Force("-sin(2*pi*x)"), "x", (-1.0, 2.0))
//! };
//! let a = analyse_potential(&q).unwrap();
//! assert_eq!(a.equilibria[1].stability, Stability::Stable);
//! let m = a.motion.as_ref().unwrap();
//! assert!((m.right_turn.unwrap() + m.left_turn.unwrap()).abs() < 1e-12);
//! assert_eq!(a.table().columns()[0].name, "x");
//! ```

use mechkit_expr::Sym;

pub use super::axis_units::AxisUnits;
use super::diagram::{EnergyCut, Equilibrium, Stability};
use super::motion::Motion;
use super::potential::{Origin, Potential};
use crate::Real;
use crate::calculus::{CalculusError, Params};
use crate::csv::{Column, Table};
use crate::inputs::{Input, InputError};

/// What the formula of a potential question is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Given<'a> {
    /// The potential `U(x)`.
    Potential(&'a str),
    /// The force `F(x)`; `U = -∫F dx`.
    Force(&'a str),
}

/// A body released in the potential.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Release {
    /// Its mass (positive).
    pub mass: Real,
    /// Where it starts (inside the range).
    pub x0: Real,
    /// Its velocity there (the sign is the direction).
    pub v0: Real,
}

/// The question of `mechkit potential` in one dimension.
#[derive(Debug, Clone, PartialEq)]
pub struct PotentialQuestion<'a> {
    /// The potential or the force, a formula of `var` and the names in `params`.
    pub given: Given<'a>,
    /// The variable.
    pub var: &'a str,
    /// The range to analyse, increasing and finite.
    pub range: (Real, Real),
    /// Values of the other names (SI).
    pub params: &'a Params,
    /// A total energy: its turning points and regions.
    pub energy: Option<Real>,
    /// A body released in the potential (sets the energy).
    pub release: Option<Release>,
    /// Points to report `U`, `F` (and `v`) at.
    pub at: Vec<Real>,
    /// Grid intervals to find equilibria and turning points (at least 10 are used).
    pub samples: usize,
    /// The units of the axes, where known.
    pub units: AxisUnits,
}

impl<'a> PotentialQuestion<'a> {
    /// The question about `given` on `range`, with nothing else asked: no parameters, no
    /// energy, 2000 grid intervals, no units.
    pub fn new(given: Given<'a>, var: &'a str, range: (Real, Real)) -> Self {
        Self {
            given,
            var,
            range,
            params: &[],
            energy: None,
            release: None,
            at: Vec::new(),
            samples: 2000,
            units: AxisUnits::default(),
        }
    }
}

/// `U`, `F` (and the speed of the released body) at a point; null where not finite.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct PointValues {
    /// Where.
    pub x: Real,
    /// `U(x)`.
    pub potential: Option<Real>,
    /// `F(x)`.
    pub force: Option<Real>,
    /// `v(x)` of the released body (null where it cannot be, or without a body).
    pub speed: Option<Real>,
}

/// The positions of the equilibria of each kind.
#[derive(Debug, Clone, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct ByStability {
    /// Minima of `U`.
    pub stable: Vec<Real>,
    /// Maxima of `U`.
    pub unstable: Vec<Real>,
    /// Inflections of `U`.
    pub neutral: Vec<Real>,
}

/// The answer of `mechkit potential` in one dimension. Its serde shape is the command's
/// JSON; `plot`, `speed_plot` and `csv` are the files a front wrote (set by the front).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct PotentialAnalysis {
    /// The variable.
    pub var: String,
    /// The range analysed, `[a, b]`.
    pub range: (Real, Real),
    /// The values given to the other names (a JSON object).
    #[cfg_attr(
        feature = "serde",
        serde(serialize_with = "crate::calculus::text::params")
    )]
    pub parameters: Vec<(String, Real)>,
    /// `U` as a formula (null when it is a numeric integral of the force).
    #[cfg_attr(
        feature = "serde",
        serde(serialize_with = "crate::calculus::text::display_opt")
    )]
    pub potential: Option<Sym>,
    /// How `U` was obtained.
    #[cfg_attr(feature = "serde", serde(serialize_with = "origin_name"))]
    pub potential_origin: Origin,
    /// `F = -dU/dx`.
    #[cfg_attr(
        feature = "serde",
        serde(serialize_with = "crate::calculus::text::display")
    )]
    pub force: Sym,
    /// `U''`.
    #[cfg_attr(
        feature = "serde",
        serde(serialize_with = "crate::calculus::text::display")
    )]
    pub curvature: Sym,
    /// The equilibria, ascending.
    pub equilibria: Vec<Equilibrium>,
    /// Their positions by kind.
    pub by_stability: ByStability,
    /// Where `U` or `F` is infinite or undefined.
    pub singularities: Vec<Real>,
    /// What the energy allows (given, or of the released body).
    pub energy: Option<EnergyCut>,
    /// The released body's motion.
    pub motion: Option<Motion>,
    /// The values at the points asked.
    pub at: Vec<PointValues>,
    /// The units of the axes, where known.
    pub units: AxisUnits,
    /// The energy diagram's file, when a front wrote one.
    pub plot: Option<String>,
    /// The file of `v(x)`, when a front wrote one.
    pub speed_plot: Option<String>,
    /// The table's CSV file, when a front wrote one.
    pub csv: Option<String>,
    /// The potential itself (for more values).
    #[cfg_attr(feature = "serde", serde(skip))]
    pub model: Potential,
    /// The sampled diagram.
    #[cfg_attr(feature = "serde", serde(skip))]
    pub diagram: super::Diagram,
}

#[cfg(feature = "serde")]
fn origin_name<S: serde::Serializer>(o: &Origin, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(o.describe())
}

impl Origin {
    /// `"given"`, `"symbolic integral of the force"` or `"numeric integral of the force (U =
    /// 0 at the range start)"`.
    pub fn describe(self) -> &'static str {
        match self {
            Origin::Given => "given",
            Origin::Symbolic => "symbolic integral of the force",
            Origin::Numeric { .. } => "numeric integral of the force (U = 0 at the range start)",
        }
    }
}

fn finite(v: Real) -> Option<Real> {
    v.is_finite().then_some(v)
}

/// Answers a [`PotentialQuestion`].
///
/// # Errors
/// A formula that does not read or lacks values ([`CalculusError::Formula`], `Invalid`), a
/// range that is not finite and increasing ([`Input::Range`]), a mass that is not positive
/// ([`Input::Mass`]), a start outside the range ([`Input::StartPosition`]), a start speed
/// that is not finite ([`Input::StartSpeed`]).
pub fn analyse_potential(q: &PotentialQuestion<'_>) -> Result<PotentialAnalysis, CalculusError> {
    let (a, b) = q.range;
    if !(a.is_finite() && b.is_finite()) {
        return Err(InputError::new(
            Input::Range,
            "a diagram samples its range, so both ends must be finite (for the speed far away use a large end, e.g. 0.01:1e9, or a point at 1e15)",
        )
        .into());
    }
    if a >= b {
        return Err(InputError::new(
            Input::Range,
            format!(
                "the range must be increasing (its start below its end), not {}:{}",
                crate::error::short(a),
                crate::error::short(b)
            ),
        )
        .into());
    }
    crate::sample_bound::check_samples("grid intervals", q.samples)
        .map_err(|e| InputError::new(Input::Samples, e.to_string()))?;
    let x = q.var;
    let pot = match q.given {
        Given::Potential(u) => Potential::from_potential(u, x, q.params)?,
        Given::Force(f) => Potential::from_force(f, x, q.params, a)?,
    };
    let samples = q.samples.max(10);
    let motion = q
        .release
        .map(|r| release(&pot, r, (a, b), samples))
        .transpose()?;
    let diagram = match &motion {
        Some(m) => m.diagram.clone(),
        None => pot.diagram(a, b, q.energy, samples),
    };
    let at =
        q.at.iter()
            .map(|&v| PointValues {
                x: v,
                potential: finite(pot.potential(v)),
                force: finite(pot.force(v)),
                speed: motion.as_ref().and_then(|m| finite(m.speed_at(&pot, v))),
            })
            .collect();
    let kind = |k: Stability| -> Vec<Real> {
        diagram
            .equilibria
            .iter()
            .filter(|e| e.stability == k)
            .map(|e| e.x)
            .collect()
    };
    Ok(PotentialAnalysis {
        var: x.to_string(),
        range: (a, b),
        parameters: q.params.to_vec(),
        potential: pot.potential_formula().cloned(),
        potential_origin: pot.origin(),
        force: pot.force_formula().clone(),
        curvature: pot.curvature_formula(),
        equilibria: diagram.equilibria.clone(),
        by_stability: ByStability {
            stable: kind(Stability::Stable),
            unstable: kind(Stability::Unstable),
            neutral: kind(Stability::Neutral),
        },
        singularities: diagram.singularities.clone(),
        energy: diagram.energy.clone(),
        motion,
        at,
        units: q.units.clone(),
        plot: None,
        speed_plot: None,
        csv: None,
        model: pot,
        diagram,
    })
}

fn release(
    pot: &Potential,
    r: Release,
    (a, b): (Real, Real),
    samples: usize,
) -> Result<Motion, CalculusError> {
    if r.mass.is_nan() || r.mass <= 0.0 {
        return Err(InputError::new(
            Input::Mass,
            format!(
                "the mass must be positive, not {}",
                crate::error::short(r.mass)
            ),
        )
        .into());
    }
    if !(a..=b).contains(&r.x0) {
        return Err(InputError::new(
            Input::StartPosition,
            format!(
                "the start {} is outside the range {}:{}",
                crate::error::short(r.x0),
                crate::error::short(a),
                crate::error::short(b)
            ),
        )
        .into());
    }
    if !r.v0.is_finite() {
        return Err(InputError::new(
            Input::StartSpeed,
            format!("the start speed must be finite, not {}", r.v0),
        )
        .into());
    }
    Ok(pot.motion(r.mass, r.x0, r.v0, a, b, samples))
}

impl PotentialAnalysis {
    /// The diagram as a table: `x`, `U`, `F` at the grid points (and `v` with a released
    /// body), with the units where known.
    pub fn table(&self) -> Table {
        let column = |name: &str, unit: Option<String>| match unit {
            Some(u) => Column::new(name, u),
            None => Column::unknown(name),
        };
        let mut columns = vec![
            column(&self.var, self.units.x.clone()),
            column("U", self.units.potential.clone()),
            column("F", self.units.force()),
        ];
        if self.motion.is_some() {
            columns.push(column("v", self.units.speed()));
        }
        let mut t = Table::new(columns);
        let d = &self.diagram;
        for i in 0..d.x.len() {
            let mut row = vec![d.x[i], d.potential[i], d.force[i]];
            if let Some(m) = &self.motion {
                row.push(m.speed[i]);
            }
            t.push(&row);
        }
        t
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bad_inputs_are_named() {
        let q = PotentialQuestion::new(Given::Potential("x^2"), "x", (0.0, Real::INFINITY));
        let input = |e: CalculusError| match e {
            CalculusError::Input(e) => e.input,
            other => panic!("{other}"),
        };
        assert_eq!(input(analyse_potential(&q).unwrap_err()), Input::Range);
        let q = PotentialQuestion {
            release: Some(Release {
                mass: -1.0,
                x0: 0.5,
                v0: 0.0,
            }),
            ..PotentialQuestion::new(Given::Potential("x^2"), "x", (0.0, 1.0))
        };
        assert_eq!(input(analyse_potential(&q).unwrap_err()), Input::Mass);
        let q = PotentialQuestion {
            release: Some(Release {
                mass: 1.0,
                x0: 5.0,
                v0: 0.0,
            }),
            ..q
        };
        assert_eq!(
            input(analyse_potential(&q).unwrap_err()),
            Input::StartPosition
        );
    }

    /// Issue 22: a body that turns on one side and leaves the range on the other.
    #[test]
    fn the_bounds_of_a_motion() {
        use super::super::motion::Bound;
        // U = -x^2 (a hill at 0), released at 0.5 moving left with E < 0: it turns at -sqrt(-E)
        // and leaves the range at the right end
        let q = PotentialQuestion {
            release: Some(Release {
                mass: 2.0,
                x0: 0.5,
                v0: -0.3,
            }),
            ..PotentialQuestion::new(Given::Potential("-x^2"), "x", (-1.0, 2.0))
        };
        let a = analyse_potential(&q).unwrap();
        let m = a.motion.as_ref().unwrap();
        let e: Real = 0.5 * 2.0 * 0.09 - 0.25;
        assert!((m.energy - e).abs() < 1e-15);
        assert!(matches!(m.left, Bound::TurningPoint { x } if (x - (-e).sqrt()).abs() < 1e-12));
        assert_eq!(m.right, Bound::RangeEnd { x: 2.0 });
        // a pole that attracts: -1/x, released at rest at 1, falls into it
        let q = PotentialQuestion {
            release: Some(Release {
                mass: 1.0,
                x0: 1.0,
                v0: 0.0,
            }),
            ..PotentialQuestion::new(Given::Potential("-1/x"), "x", (-1.0, 2.0))
        };
        let m = analyse_potential(&q).unwrap().motion.unwrap();
        assert!(
            matches!(m.left, Bound::SingularPoint { x } if x.abs() < 1e-9),
            "{m:?}"
        );
    }
}

//! The work (or impulse) of a force measured in a data file, as `mechkit work FILE` and
//! `mechkit impulse FILE` ask it: the integral by a rule, the running integral, the average and
//! the largest force, and by the work-energy theorem the speed `v(x)` and where the body stops,
//! or by the impulse-momentum theorem `Δv = J/m`; with the table and the plot of the running
//! integral.
//!
//! A column whose header gives its unit (`x [cm]`) is converted to SI; one without is taken
//! as SI, and its unit is reported as unknown.
//!
//! ```
//! use mechkit::data::Table;
//! use mechkit::energy::{Abscissa, DataWorkQuestion, data_work};
//! let table = Table::parse("x [cm], F [N]\n0, 2\n50, 2\n100, 2\n", "push.csv").unwrap();
//! let w = data_work(&DataWorkQuestion::new(&table)).unwrap();
//! assert_eq!((w.of, w.work), (Abscissa::Position, Some(2.0)));
//! assert_eq!(w.units.integral.as_deref(), Some("J"));
//! let csv = w.table();
//! assert_eq!(csv.columns().iter().map(|c| c.name.as_str()).collect::<Vec<_>>(), ["x", "F", "W"]);
//! ```

use thiserror::Error;

use super::sampled_work::SampledIntegral;
use crate::Real;
use crate::csv::{Column, Table as CsvTable};
use crate::data::{ColumnRef, DataError, Order, Table, plain_name, product_unit};
use crate::figure::{PlotData, Series};
use crate::inputs::{Input, InputError};
use crate::quad::{SampleRule, SamplesError};

/// What the abscissa of the data is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "lowercase"))]
pub enum Abscissa {
    /// Positions: `∫F dx` is a work.
    Position,
    /// Times: `∫F dt` is an impulse.
    Time,
}

/// The question of `mechkit work FILE` and `mechkit impulse FILE`.
#[derive(Debug, Clone, PartialEq)]
pub struct DataWorkQuestion<'a> {
    /// The data.
    pub table: &'a Table,
    /// The abscissa column (default: the first).
    pub x: ColumnRef,
    /// The force column (default: the second).
    pub f: ColumnRef,
    /// The quadrature rule (default: trapezoids).
    pub rule: SampleRule,
    /// What the abscissa is; `None`: time when its column is named `t` or `time`, else
    /// position.
    pub of: Option<Abscissa>,
    /// A mass: the speed `v(x)` for positions, `Δv = J/m` for times.
    pub mass: Option<Real>,
    /// The start speed (for `v(x)` and `Δv`).
    pub v0: Real,
}

impl<'a> DataWorkQuestion<'a> {
    /// The work of the second column over the first by trapezoids, nothing else asked.
    pub fn new(table: &'a Table) -> Self {
        Self {
            table,
            x: ColumnRef::Index(0),
            f: ColumnRef::Index(1),
            rule: SampleRule::Trapezoid,
            of: None,
            mass: None,
            v0: 0.0,
        }
    }
}

/// Why the integral of a data file could not be taken.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum DataWorkError {
    /// A column that is not there (`input` is [`Input::AbscissaColumn`] or
    /// [`Input::ValueColumn`]).
    #[error("{error}")]
    Column {
        /// Which column.
        input: Input,
        /// What is wrong with it.
        error: DataError,
    },
    /// The abscissa is not strictly monotone (the message names the lines).
    #[error("{0}")]
    Data(DataError),
    /// Time runs backwards: an integral over time (an impulse, whichever command asks it)
    /// needs it to increase.
    #[error(
        "{file}: the time column `{column}` decreases (negative time steps); an impulse needs increasing time: sort the file by time"
    )]
    Decreasing {
        /// The file.
        file: String,
        /// The time column.
        column: String,
    },
    /// The rule cannot integrate these samples (the midpoint rule on an odd number of
    /// intervals).
    #[error("{file}: {error}")]
    Samples {
        /// The file.
        file: String,
        /// Why.
        error: SamplesError,
    },
    /// Another input does not fit (a mass that is not positive).
    #[error("{0}")]
    Input(#[from] InputError),
}

/// The sample of largest `|F|`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Peak {
    /// Where.
    pub x: Real,
    /// `F` there, with its sign.
    pub f: Real,
    /// `|F|` there: the largest magnitude.
    pub magnitude: Real,
}

/// The units of the result's columns, where the file gave them (SI).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct DataUnits {
    /// The abscissa's.
    pub x: Option<String>,
    /// The force's.
    pub f: Option<String>,
    /// The integral's (`J`, `N*s`).
    pub integral: Option<String>,
    /// The speed's (`m/s` when the work is in joules).
    pub v: Option<String>,
}

/// The answer of `mechkit work FILE` (`impulse FILE`). Its serde shape is the command's JSON;
/// `csv` and `plot` are the files a front wrote (set by the front).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct DataWork {
    /// The file (as named when read).
    pub file: String,
    /// The number of rows.
    pub rows: usize,
    /// The abscissa column's plain name (`x`, `t` for unnamed columns).
    pub x: String,
    /// The force column's plain name (`F` for an unnamed column).
    pub f: String,
    /// What the abscissa is.
    pub of: Abscissa,
    /// The rule.
    #[cfg_attr(feature = "serde", serde(serialize_with = "rule_name"))]
    pub rule: SampleRule,
    /// `∫F dx` (or `∫F dt`), SI.
    pub integral: Real,
    /// The integral as a work, for positions.
    pub work: Option<Real>,
    /// The integral as an impulse, for times.
    pub impulse: Option<Real>,
    /// `x_last - x_first`.
    pub span: Real,
    /// The average force, `integral / span`.
    pub mean_force: Real,
    /// The largest `|F|`.
    pub peak: Peak,
    /// The mass given.
    pub mass: Option<Real>,
    /// The start speed.
    pub v0: Real,
    /// `J/m`, for times with a mass.
    pub delta_v: Option<Real>,
    /// The speed at the end (`v0 + Δv`, or `v(x_last)` when the body gets there).
    pub v_end: Option<Real>,
    /// Where the kinetic energy runs out, for positions with a mass.
    pub turning_point: Option<Real>,
    /// The running integral at every row.
    pub cumulative: Vec<Real>,
    /// The units, where known.
    pub units: DataUnits,
    /// The table's CSV file, when a front wrote one.
    pub csv: Option<String>,
    /// The plot's file, when a front wrote one.
    pub plot: Option<String>,
    /// The abscissa (SI).
    #[cfg_attr(feature = "serde", serde(skip))]
    pub x_values: Vec<Real>,
    /// The force (SI).
    #[cfg_attr(feature = "serde", serde(skip))]
    pub f_values: Vec<Real>,
    /// `v(x)` with a mass, for positions (NaN past a turning point).
    #[cfg_attr(feature = "serde", serde(skip))]
    pub speeds: Option<Vec<Real>>,
}

#[cfg(feature = "serde")]
#[allow(clippy::trivially_copy_pass_by_ref)] // serde's `serialize_with` passes a reference
fn rule_name<S: serde::Serializer>(r: &SampleRule, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(r.name())
}

/// Whether a column named `name` holds times (`t`, `time`, `t [s]`).
fn is_time(name: &str) -> bool {
    let n = name.trim().to_ascii_lowercase();
    let head = n.split([' ', '[', '(']).next().unwrap_or("");
    head == "t" || head == "time"
}

/// Answers a [`DataWorkQuestion`].
///
/// # Errors
/// See [`DataWorkError`].
pub fn data_work(q: &DataWorkQuestion<'_>) -> Result<DataWork, DataWorkError> {
    let table = q.table;
    let column = |r: &ColumnRef, input: Input| {
        table
            .column_index(r)
            .map_err(|error| DataWorkError::Column { input, error })
    };
    let x_index = column(&q.x, Input::AbscissaColumn)?;
    let f_index = column(&q.f, Input::ValueColumn)?;
    let of = q.of.unwrap_or(if is_time(&table.label(x_index)) {
        Abscissa::Time
    } else {
        Abscissa::Position
    });
    let time = of == Abscissa::Time;
    let what = if time {
        "the impulse integral"
    } else {
        "the work integral"
    };
    let (_, order) = table.abscissa(&q.x, what).map_err(DataWorkError::Data)?;
    // a path may be walked backwards (a work over decreasing x), time may not
    if time && order == Order::Decreasing {
        return Err(DataWorkError::Decreasing {
            file: table.source().to_string(),
            column: table.label(x_index),
        });
    }
    if let Some(m) = q.mass
        && (m.is_nan() || m <= 0.0)
    {
        return Err(InputError::new(
            Input::Mass,
            format!("the mass must be positive, not {}", crate::error::short(m)),
        )
        .into());
    }
    let (x, x_unit) = table.si(x_index);
    let (f, f_unit) = table.si(f_index);
    let w = SampledIntegral::new(&x, &f, q.rule).map_err(|error| DataWorkError::Samples {
        file: table.source().to_string(),
        error,
    })?;
    // unnamed columns are called t or x, and F
    let (x_name, f_name) = match table.names() {
        Some(_) => (
            plain_name(&table.label(x_index)),
            plain_name(&table.label(f_index)),
        ),
        None => ((if time { "t" } else { "x" }).to_string(), "F".to_string()),
    };
    let integral_unit = match (&f_unit, &x_unit) {
        (Some(f), Some(x)) => Some(product_unit(f, x)),
        _ => None,
    };
    let speeds = q.mass.filter(|_| !time).map(|m| w.speeds(m, q.v0));
    let turning_point = q
        .mass
        .filter(|_| !time)
        .and_then(|m| w.turning_point(&x, m, q.v0));
    let delta_v = q.mass.filter(|_| time).map(|m| w.total / m);
    let v_end = delta_v.map(|d| q.v0 + d).or_else(|| {
        speeds
            .as_ref()
            .and_then(|s| s.last().copied())
            .filter(|v| v.is_finite())
    });
    Ok(DataWork {
        file: table.source().to_string(),
        rows: x.len(),
        x: x_name,
        f: f_name,
        of,
        rule: q.rule,
        integral: w.total,
        work: (!time).then_some(w.total),
        impulse: time.then_some(w.total),
        span: w.span,
        mean_force: w.mean(),
        peak: Peak {
            x: w.peak.0,
            f: w.peak.1,
            magnitude: w.peak.1.abs(),
        },
        mass: q.mass,
        v0: q.v0,
        delta_v,
        v_end,
        turning_point,
        cumulative: w.cumulative,
        units: DataUnits {
            v: (integral_unit.as_deref() == Some("J")).then(|| "m/s".to_string()),
            x: x_unit,
            f: f_unit,
            integral: integral_unit,
        },
        csv: None,
        plot: None,
        x_values: x,
        f_values: f,
        speeds,
    })
}

impl DataWork {
    /// What the integral is called: `W` (a work) or `J` (an impulse).
    pub fn symbol(&self) -> &'static str {
        match self.of {
            Abscissa::Position => "W",
            Abscissa::Time => "J",
        }
    }

    /// The file name for its table, without `.csv`: `work` or `impulse`.
    pub fn name(&self) -> &'static str {
        match self.of {
            Abscissa::Position => "work",
            Abscissa::Time => "impulse",
        }
    }

    /// The table: the abscissa, the force, the running integral (`W` or `J`), and `v` with a
    /// mass over positions; units where known.
    pub fn table(&self) -> CsvTable {
        let column = |name: &str, unit: &Option<String>| match unit {
            Some(u) => Column::new(name, u.clone()),
            None => Column::unknown(name),
        };
        let mut columns = vec![
            column(&self.x, &self.units.x),
            column(&self.f, &self.units.f),
            column(self.symbol(), &self.units.integral),
        ];
        if self.speeds.is_some() {
            columns.push(column("v", &self.units.v));
        }
        let mut t = CsvTable::new(columns);
        for i in 0..self.x_values.len() {
            let mut row = vec![self.x_values[i], self.f_values[i], self.cumulative[i]];
            if let Some(v) = &self.speeds {
                row.push(v[i]);
            }
            t.push(&row);
        }
        t
    }

    /// The running integral against the abscissa, named `W_<x>` (or `J_<t>`), its axes with
    /// units where known.
    pub fn plot(&self) -> PlotData {
        let (name, x) = (self.symbol(), &self.x);
        let label = |n: &str, u: &Option<String>| match u {
            Some(u) => format!("{n} [{u}]"),
            None => n.to_string(),
        };
        PlotData::new(
            format!("{name}({x}) = ∫ F d{x} ({})", self.rule.name()),
            format!("{name}_{x}"),
            label(x, &self.units.x),
            label(name, &self.units.integral),
        )
        .with_series(Series::line(
            format!("{name}({x})"),
            self.x_values
                .iter()
                .copied()
                .zip(self.cumulative.iter().copied())
                .collect(),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table(text: &str) -> Table {
        Table::parse(text, "f.dat").unwrap()
    }

    #[test]
    fn the_largest_force_is_a_magnitude() {
        let t = table("0 0\n1 -3\n2 1\n");
        let w = data_work(&DataWorkQuestion::new(&t)).unwrap();
        assert_eq!(
            w.peak,
            Peak {
                x: 1.0,
                f: -3.0,
                magnitude: 3.0
            }
        );
        assert_eq!((w.x.as_str(), w.f.as_str()), ("x", "F"));
        assert_eq!(w.units, DataUnits::default());
        assert!(w.table().columns().iter().all(|c| c.unit.is_none()));
    }

    #[test]
    fn time_impulse_units_and_errors() {
        let t = table("t [ms]  F [kN]\n0 1\n1 1\n2 1\n");
        let q = DataWorkQuestion {
            mass: Some(0.5),
            ..DataWorkQuestion::new(&t)
        };
        let j = data_work(&q).unwrap();
        assert_eq!(j.of, Abscissa::Time);
        assert!((j.impulse.unwrap() - 2.0).abs() < 1e-12);
        assert!((j.delta_v.unwrap() - 4.0).abs() < 1e-12);
        assert_eq!(j.units.integral.as_deref(), Some("N*s"));
        assert_eq!((j.name(), j.plot().file_stem.as_str()), ("impulse", "J_t"));
        let bad = DataWorkQuestion {
            mass: Some(-1.0),
            ..q.clone()
        };
        assert!(matches!(
            data_work(&bad),
            Err(DataWorkError::Input(InputError {
                input: Input::Mass,
                ..
            }))
        ));
        let missing = DataWorkQuestion {
            f: ColumnRef::Index(5),
            ..q
        };
        assert!(matches!(
            data_work(&missing),
            Err(DataWorkError::Column {
                input: Input::ValueColumn,
                ..
            })
        ));
        let back = table("2 1\n1 2\n0 3\n");
        let q = DataWorkQuestion {
            of: Some(Abscissa::Time),
            ..DataWorkQuestion::new(&back)
        };
        assert!(matches!(
            data_work(&q),
            Err(DataWorkError::Decreasing { .. })
        ));
    }

    #[test]
    fn a_decreasing_time_column_is_refused_whichever_command_asks() {
        // `work` on a column named `t` integrates over time, as `impulse` does
        let back = table("t,x\n3,1\n2,2\n1,3\n0,4\n");
        assert!(matches!(
            data_work(&DataWorkQuestion::new(&back)),
            Err(DataWorkError::Decreasing { .. })
        ));
        // a path walked backwards is a work, and allowed
        let path = table("x,F\n3,1\n2,2\n1,3\n0,4\n");
        let w = data_work(&DataWorkQuestion::new(&path)).unwrap();
        assert_eq!(w.work, Some(-7.5));
    }
}

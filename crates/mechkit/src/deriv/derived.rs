//! Velocity and acceleration of the position columns of a data file, as `mechkit derive`
//! asks it: the derivatives of each column, their summaries, the table `t, x, dx_dt, d2x_dt2`
//! and the plots of positions, velocities and accelerations against time.
//!
//! A column whose header gives its unit (`t [ms]`) is converted to SI; the derivatives' units
//! follow (`m/s`, `m/s^2`). Columns without a unit are taken as they are and their units, and
//! those of their derivatives, are unknown (the plots' axes then carry no unit, like the units
//! sidecar of the table).
//!
//! ```
//! use mechkit::data::Table;
//! use mechkit::deriv::{Derivation, Difference, DeriveQuestion, derive_motion};
//! let table = Table::parse("t [s], y [cm]\n0, 0\n1, 100\n2, 400\n3, 900\n", "drop.csv").unwrap();
//! let how = Derivation::Differences(Difference::Central);
//! let d = derive_motion(&DeriveQuestion::new(&table, how)).unwrap();
//! assert!((d.columns[0].acceleration.unwrap().median - 2.0).abs() < 1e-12);
//! assert_eq!(d.columns[0].units.acceleration.as_deref(), Some("m/s^2"));
//! let names: Vec<_> = d.table().columns().iter().map(|c| c.name.clone()).collect();
//! assert_eq!(names, ["t", "y", "dy_dt", "d2y_dt2"]);
//! ```

use thiserror::Error;

use super::error::DerivError;
use super::kinematics::{Derivation, kinematics};
use super::savitzky_golay::uniform_step;
use crate::Real;
use crate::csv::{Column, Table as CsvTable};
use crate::data::{ColumnRef, DataError, Order, Stats, Table, plain_name, quotient_unit};
use crate::figure::{PlotData, Series};
use crate::inputs::Input;

/// The question of `mechkit derive`.
#[derive(Debug, Clone, PartialEq)]
pub struct DeriveQuestion<'a> {
    /// The data.
    pub table: &'a Table,
    /// The time column (default: the first).
    pub t: ColumnRef,
    /// The position columns (default: every other column).
    pub x: Option<Vec<ColumnRef>>,
    /// How to differentiate.
    pub how: Derivation,
}

impl<'a> DeriveQuestion<'a> {
    /// Every column but the first, against the first, by `how`.
    pub fn new(table: &'a Table, how: Derivation) -> Self {
        Self {
            table,
            t: ColumnRef::Index(0),
            x: None,
            how,
        }
    }
}

/// Why the data could not be differentiated.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum DeriveError {
    /// A column that is not there (`input` is [`Input::AbscissaColumn`] for time,
    /// [`Input::ValueColumn`] for a position).
    #[error("{error}")]
    Column {
        /// Which column.
        input: Input,
        /// What is wrong with it.
        error: DataError,
    },
    /// The time column is not strictly monotone (the message names the lines).
    #[error("{0}")]
    Data(DataError),
    /// Time decreases.
    #[error(
        "{file}: the time column `{column}` decreases; derivatives need increasing time (sort the file by time)"
    )]
    Decreasing {
        /// The file.
        file: String,
        /// The time column.
        column: String,
    },
    /// Only the time column.
    #[error("{file}: there is no column to differentiate besides the time column")]
    NothingToDerive {
        /// The file.
        file: String,
    },
    /// The method cannot differentiate these samples.
    #[error("{file}: {error}")]
    Deriv {
        /// The file.
        file: String,
        /// Why.
        error: DerivError,
    },
}

/// The units of a position column and of its derivatives, where known.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct DerivedUnits {
    /// The position's.
    pub position: Option<String>,
    /// The velocity's.
    pub velocity: Option<String>,
    /// The acceleration's.
    pub acceleration: Option<String>,
}

/// One position column and its derivatives.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct DerivedColumn {
    /// Its plain name (`x`, or `x2`, `x3`, … for unnamed columns).
    pub name: String,
    /// The summary of the velocity (null when no value is finite).
    pub velocity: Option<Stats>,
    /// The summary of the acceleration.
    pub acceleration: Option<Stats>,
    /// The units.
    pub units: DerivedUnits,
    /// The positions (SI where the unit is known).
    #[cfg_attr(feature = "serde", serde(skip))]
    pub x: Vec<Real>,
    /// `dx/dt` at each sample.
    #[cfg_attr(feature = "serde", serde(skip))]
    pub v: Vec<Real>,
    /// `d²x/dt²` at each sample.
    #[cfg_attr(feature = "serde", serde(skip))]
    pub a: Vec<Real>,
}

/// The answer of `mechkit derive`. Its serde shape is the command's JSON; `csv` and `plots`
/// are the files a front wrote (set by the front).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct DerivedMotion {
    /// The file (as named when read).
    pub file: String,
    /// The number of rows.
    pub rows: usize,
    /// The time column's plain name.
    pub time: String,
    /// The time's unit, where known.
    pub time_unit: Option<String>,
    /// The step, when the times are evenly spaced.
    pub uniform_step: Option<Real>,
    /// The method, described (`central`, `savitzky-golay window 21 order 2`).
    pub method: String,
    /// Each position column.
    pub columns: Vec<DerivedColumn>,
    /// The table's CSV file, when a front wrote one.
    pub csv: Option<String>,
    /// The plot files a front wrote.
    pub plots: Vec<String>,
    /// The times (SI where the unit is known).
    #[cfg_attr(feature = "serde", serde(skip))]
    pub t: Vec<Real>,
}

/// Answers a [`DeriveQuestion`].
///
/// # Errors
/// See [`DeriveError`].
pub fn derive_motion(q: &DeriveQuestion<'_>) -> Result<DerivedMotion, DeriveError> {
    let table = q.table;
    let column = |r: &ColumnRef, input: Input| {
        table
            .column_index(r)
            .map_err(|error| DeriveError::Column { input, error })
    };
    let t_index = column(&q.t, Input::AbscissaColumn)?;
    let (_, order) = table
        .abscissa(&q.t, "the derivative")
        .map_err(DeriveError::Data)?;
    if order == Order::Decreasing {
        return Err(DeriveError::Decreasing {
            file: table.source().to_string(),
            column: table.label(t_index),
        });
    }
    let xs: Vec<usize> = match &q.x {
        Some(list) => list
            .iter()
            .map(|r| column(r, Input::ValueColumn))
            .collect::<Result<_, _>>()?,
        None => (0..table.width()).filter(|&i| i != t_index).collect(),
    };
    if xs.is_empty() {
        return Err(DeriveError::NothingToDerive {
            file: table.source().to_string(),
        });
    }
    // unnamed columns are called t and x (x2, x3, … when there are several)
    let name = |i: usize| match table.names() {
        Some(_) => plain_name(&table.label(i)),
        None if i == t_index => "t".to_string(),
        None if xs.len() == 1 => "x".to_string(),
        None => format!("x{}", i + 1),
    };
    let (t, t_unit) = table.si(t_index);
    let mut columns = Vec::new();
    for &i in &xs {
        let (x, x_unit) = table.si(i);
        let k = kinematics(&t, &x, q.how).map_err(|error| DeriveError::Deriv {
            file: table.source().to_string(),
            error,
        })?;
        let per = |power| match (&x_unit, &t_unit) {
            (Some(x), Some(t)) => Some(quotient_unit(x, t, power)),
            _ => None,
        };
        columns.push(DerivedColumn {
            name: name(i),
            velocity: Stats::of(&k.velocity),
            acceleration: Stats::of(&k.acceleration),
            units: DerivedUnits {
                velocity: per(1),
                acceleration: per(2),
                position: x_unit,
            },
            x,
            v: k.velocity,
            a: k.acceleration,
        });
    }
    Ok(DerivedMotion {
        file: table.source().to_string(),
        rows: t.len(),
        time: name(t_index),
        time_unit: t_unit,
        uniform_step: uniform_step(&t),
        method: q.how.describe(),
        columns,
        csv: None,
        plots: Vec::new(),
        t,
    })
}

/// Which unit of a column a plot shows.
type Pick = fn(&DerivedUnits) -> &Option<String>;

/// `name [unit]`, or `name` when the unit is not known.
fn label(name: &str, unit: Option<&str>) -> String {
    unit.map_or_else(|| name.to_string(), |u| format!("{name} [{u}]"))
}

impl DerivedMotion {
    /// The table: the time, then for each position column `x, dx_dt, d2x_dt2`, with units
    /// where known.
    pub fn table(&self) -> CsvTable {
        let column = |name: String, unit: &Option<String>| match unit {
            Some(u) => Column::new(name, u.clone()),
            None => Column::unknown(name),
        };
        let t = &self.time;
        let mut columns = vec![column(t.clone(), &self.time_unit)];
        for d in &self.columns {
            let x = &d.name;
            columns.push(column(x.clone(), &d.units.position));
            columns.push(column(format!("d{x}_d{t}"), &d.units.velocity));
            columns.push(column(format!("d2{x}_d{t}2"), &d.units.acceleration));
        }
        let mut table = CsvTable::new(columns);
        let mut row = Vec::with_capacity(1 + 3 * self.columns.len());
        for (i, &ti) in self.t.iter().enumerate() {
            row.clear();
            row.push(ti);
            for d in &self.columns {
                row.extend([d.x[i], d.v[i], d.a[i]]);
            }
            table.push(&row);
        }
        table
    }

    /// The plots of the positions, velocities and accelerations against time, named
    /// `<x>_<t>` (the column's name, or `x` for several columns), `v_<t>` and `a_<t>`; axes
    /// with units where all the columns' are known and the same.
    pub fn plots(&self) -> Vec<PlotData> {
        let t = &self.time;
        let t_label = label(t, self.time_unit.as_deref());
        let x_name = match self.columns.as_slice() {
            [one] => one.name.clone(),
            _ => "x".to_string(),
        };
        let common = |pick: Pick| {
            let first = pick(&self.columns[0].units).clone();
            self.columns
                .iter()
                .all(|c| *pick(&c.units) == first)
                .then_some(first)
                .flatten()
        };
        let kinds: [(&str, String, String, Pick); 3] = [
            ("position", x_name.clone(), x_name, |u| &u.position),
            ("velocity", format!("v_{t}"), "v".to_string(), |u| {
                &u.velocity
            }),
            ("acceleration", format!("a_{t}"), "a".to_string(), |u| {
                &u.acceleration
            }),
        ];
        kinds
            .into_iter()
            .enumerate()
            .map(|(k, (what, stem, y, unit))| {
                let stem = if k == 0 { format!("{stem}_{t}") } else { stem };
                let mut plot = PlotData::new(
                    format!("{what}({t})"),
                    stem,
                    t_label.clone(),
                    label(&y, common(unit).as_deref()),
                );
                for d in &self.columns {
                    let (ys, series) = match k {
                        0 => (&d.x, d.name.clone()),
                        1 => (&d.v, format!("d{}/d{t}", d.name)),
                        _ => (&d.a, format!("d²{}/d{t}²", d.name)),
                    };
                    plot.series.push(Series::line(
                        series,
                        self.t.iter().copied().zip(ys.iter().copied()).collect(),
                    ));
                }
                plot
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::deriv::Difference;

    #[test]
    fn unnamed_columns_have_no_units_and_named_ones_do() {
        let how = Derivation::Differences(Difference::Central);
        let bare = Table::parse("0 0\n1 1\n2 4\n3 9\n", "f.dat").unwrap();
        let d = derive_motion(&DeriveQuestion::new(&bare, how)).unwrap();
        let plots = d.plots();
        let labels: Vec<_> = plots
            .iter()
            .map(|p| (p.file_stem.as_str(), p.x_label.as_str(), p.y_label.as_str()))
            .collect();
        assert_eq!(
            labels,
            [("x_t", "t", "x"), ("v_t", "t", "v"), ("a_t", "t", "a")]
        );
        assert!(d.table().columns().iter().all(|c| c.unit.is_none()));
        let named = Table::parse("t [s], x [m]\n0, 0\n1, 1\n2, 4\n3, 9\n", "f.csv").unwrap();
        let d = derive_motion(&DeriveQuestion::new(&named, how)).unwrap();
        let plots = d.plots();
        assert_eq!(plots[1].x_label, "t [s]");
        assert_eq!(plots[1].y_label, "v [m/s]");
        assert_eq!(plots[2].y_label, "a [m/s^2]");
        let units: Vec<_> = d
            .table()
            .columns()
            .iter()
            .map(|c| c.unit.clone().unwrap())
            .collect();
        assert_eq!(units, ["s", "m", "m/s", "m/s^2"]);
    }

    #[test]
    fn errors_name_the_column() {
        let how = Derivation::Differences(Difference::Central);
        let t = Table::parse("0 0\n1 1\n2 4\n", "f.dat").unwrap();
        let q = DeriveQuestion {
            x: Some(vec![ColumnRef::Index(7)]),
            ..DeriveQuestion::new(&t, how)
        };
        assert!(matches!(
            derive_motion(&q),
            Err(DeriveError::Column {
                input: Input::ValueColumn,
                ..
            })
        ));
        let back = Table::parse("2 1\n1 2\n0 3\n", "b.dat").unwrap();
        assert!(matches!(
            derive_motion(&DeriveQuestion::new(&back, how)),
            Err(DeriveError::Decreasing { .. })
        ));
    }
}

//! The trajectory kept in memory, column by column: the same rows and columns as
//! `trajectory.csv` ([`super::csv_columns`]), as numbers (for the Python package's numpy
//! arrays, for plots and checks without a file).

use super::row::{Keep, RowLayout, RowSink, csv_columns_in};
use super::{SCENARIO_LIMIT_HINT, output_limit_message, rows_end};
use crate::Real;
use crate::csv::Column;
use crate::particles::{ParticleSystem, Sample};
use crate::simulate::StopReason;

/// A run's trajectory: one column of numbers per name of `trajectory.csv`, with its unit.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Trajectory {
    columns: Vec<Column>,
    data: Vec<Vec<Real>>,
}

impl Trajectory {
    /// The columns (names and units), in the CSV's order.
    pub fn columns(&self) -> &[Column] {
        &self.columns
    }

    /// The values of the column named `name`.
    pub fn column(&self, name: &str) -> Option<&[Real]> {
        self.columns
            .iter()
            .position(|c| c.name == name)
            .map(|i| self.data[i].as_slice())
    }

    /// The columns' values, in the order of [`Trajectory::columns`].
    pub fn data(&self) -> &[Vec<Real>] {
        &self.data
    }

    /// The columns' values, taken out.
    pub fn into_data(self) -> (Vec<Column>, Vec<Vec<Real>>) {
        (self.columns, self.data)
    }

    /// The number of rows.
    pub fn len(&self) -> usize {
        self.data.first().map_or(0, Vec::len)
    }

    /// Whether it has no rows.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// Collects the kept samples (see [`Keep`]) and the last into a [`Trajectory`], within a byte
/// budget (8 per number, the scenario's output limit).
pub(crate) struct TrajectoryTable {
    table: Trajectory,
    keep: Keep,
    layout: RowLayout,
    row: Vec<Real>,
    last_t: Option<Real>,
    max_rows: usize,
    halt: Option<(StopReason, String)>,
}

impl TrajectoryTable {
    /// An empty table of `sys`'s trajectory, with room for `limit` bytes.
    pub fn new(
        sys: &ParticleSystem,
        has_potential: bool,
        units: mechkit_expr::units::UnitSystem,
        keep: Keep,
        limit: u64,
    ) -> Self {
        let columns = csv_columns_in(sys, has_potential, units);
        let width = columns.len().max(1);
        let max_rows = usize::try_from(limit / (8 * width as u64)).unwrap_or(usize::MAX);
        Self {
            table: Trajectory {
                data: vec![Vec::new(); columns.len()],
                columns,
            },
            keep,
            layout: RowLayout::new(sys, has_potential),
            row: Vec::new(),
            last_t: None,
            max_rows,
            halt: None,
        }
    }

    fn push(&mut self, s: &Sample<'_>) {
        if self.halt.is_some() {
            return;
        }
        if self.table.len() >= self.max_rows {
            self.halt = Some((
                StopReason::OutputLimit,
                output_limit_message(
                    std::path::Path::new("the trajectory in memory"),
                    8 * (self.max_rows * self.table.columns.len()) as u64,
                    &rows_end(s.t, self.table.len() as u64, self.last_t),
                    SCENARIO_LIMIT_HINT,
                ),
            ));
            return;
        }
        self.layout.values(s, &mut self.row);
        for (column, &x) in self.table.data.iter_mut().zip(&self.row) {
            column.push(x);
        }
        self.last_t = Some(s.t);
    }

    /// The table.
    pub fn finish(self) -> Trajectory {
        self.table
    }
}

impl RowSink for TrajectoryTable {
    fn keep(&self) -> Keep {
        self.keep
    }

    fn last_t(&self) -> Option<Real> {
        self.last_t
    }

    fn write(&mut self, s: &Sample<'_>) {
        self.push(s);
    }

    fn stop(&self) -> Option<(StopReason, String)> {
        self.halt.clone()
    }
}

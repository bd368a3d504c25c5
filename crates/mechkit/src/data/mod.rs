//! Measured data files: columns of numbers with an optional header, read with line numbers so
//! that every problem is reported where it is (`forcedata.d:12:5: column 2 is `1.2.3`, which
//! is not a number, …`).
//!
//! A [`Table`] is read once ([`Table::parse`], [`Table::read`]); its columns are asked for by
//! number (counted from 1, as users do) or by name ([`ColumnRef`]). An abscissa (the `x` of a
//! work integral, the `t` of a derivative) must be strictly monotone in file order
//! ([`check_abscissa`], [`Table::abscissa`]). A header may give a column's unit (`t [s]`:
//! [`header_unit`]); results computed from columns name theirs plainly ([`plain_name`]) with
//! units composed from the columns' ([`product_unit`], [`quotient_unit`]), and columns are
//! summarised by [`Stats`].

mod column;
mod error;
mod format;
mod order;
mod stats;
mod table;
mod units;

pub use column::ColumnRef;
pub use error::DataError;
pub use format::Separator;
pub use order::{Order, check_abscissa};
pub use stats::Stats;
pub use table::Table;
pub use units::{header_unit, plain_name, product_unit, quotient_unit};

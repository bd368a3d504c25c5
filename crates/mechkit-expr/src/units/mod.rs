//! Physical units: dimensions, the unit table, and quantities written with units.
//!
//! Every value is converted to SI on input. A bare number is taken to be in SI already.

mod dimension;
mod parse;
mod quantity;
mod table;

pub use dimension::Dimension;
pub use quantity::{Quantity, Unit, UnitError, UnitErrorKind};
pub use table::{PREFIXES, UNITS, UnitDef, lookup};

//! Physical units: dimensions, the unit table, and quantities written with units.
//!
//! Every value is converted to SI on input. A bare number is taken to be in SI already.
//! Dimensions have exact rational exponents ([`Ratio`]): `N/m^1.5` and `N/m^(3/2)` are the
//! same unit, a Hertz contact stiffness.

mod dimension;
mod parse;
mod quantity;
mod ratio;
mod system;
mod table;

pub use dimension::{Dimension, DimensionError};
pub use quantity::{Quantity, Unit, UnitError, UnitErrorKind};
pub use ratio::{MAX_WRITTEN_DENOMINATOR, Ratio};
pub use system::UnitSystem;
pub use table::{PREFIXES, UNITS, UnitDef, lookup};

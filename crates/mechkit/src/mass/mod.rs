//! Mass properties: systems of point masses (centre of mass, momentum, the centre-of-mass
//! frame and the kinetic-energy split).

mod points;

pub use points::{MassSummary, PointMassError, PointMasses};

//! Integration tests of the mechkit library, one module per area (as in nalgebra's tests).

mod calculus;
mod collisions;
mod data;
mod deriv;
mod energy;
mod forces;
mod mass;
mod md;
mod ode;
mod quad;
mod rigid;
mod rocket;
mod scenario;
mod simulate;
mod util;

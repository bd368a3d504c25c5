//! Quadrature of functions: adaptive Gauss-Kronrod (7/15 points) with an error estimate, like
//! MATLAB's `integral` and QUADPACK's `qags` without extrapolation; infinite limits by a change
//! of variable.

mod gauss_kronrod;
mod gauss_legendre;
mod rule;

pub use gauss_kronrod::{QuadError, QuadResult, Tolerance, integrate};
pub use gauss_legendre::{MAX_GAUSS_POINTS, gauss_legendre};
pub use rule::{Rule, RuleError, integrate_rule};

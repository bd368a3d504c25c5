//! Quadrature of functions: adaptive Gauss-Kronrod (7/15 points) with an error estimate, like
//! MATLAB's `integral` and QUADPACK's `qags` without extrapolation; infinite limits by a change
//! of variable.

mod gauss_kronrod;

pub use gauss_kronrod::{QuadError, QuadResult, Tolerance, integrate};

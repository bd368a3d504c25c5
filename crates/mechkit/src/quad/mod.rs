//! Quadrature of functions and of sampled data.
//!
//! - [`integrate`]: adaptive Gauss-Kronrod (7/15 points) with an error estimate, like MATLAB's
//!   `integral` and QUADPACK's `qags` without extrapolation; infinite limits by a change of
//!   variable.
//! - [`tanh_sinh`]: the double exponential rule, for integrable singularities at the ends
//!   (the integrand given as functions of the distance to each end).
//! - [`integrate_rule`]: the fixed composite rules a course compares on `n` equal intervals
//!   ([`Rule`]: left, right, midpoint, trapezoid, Simpson, Gauss-Legendre with the nodes of
//!   [`gauss_legendre`]), errors `O(h^p)` with `p` = [`Rule::order`].
//! - Samples `(x_i, y_i)`: [`trapz`], [`trapz_uniform`], [`cumtrapz`], [`simpson`] (NumPy's
//!   `trapezoid`, SciPy's `cumulative_trapezoid` and `simpson`), and by name of rule
//!   ([`SampleRule`]) [`integrate_samples`] and the running integral [`cumulative`].

mod double_exponential;
mod gauss_kronrod;
mod gauss_legendre;
mod rule;
mod sample_rule;
mod samples;
mod summation;

pub use double_exponential::tanh_sinh;
pub use gauss_kronrod::{QuadError, QuadResult, Tolerance, integrate};
pub use gauss_legendre::{MAX_GAUSS_POINTS, gauss_legendre};
pub use rule::{MAX_EVALUATIONS, Rule, RuleError, integrate_rule};
pub use sample_rule::{SampleRule, SamplesError, cumulative, integrate_samples};
pub use samples::{cumtrapz, cumtrapz_into, simpson, trapz, trapz_uniform};

use crate::error::short;

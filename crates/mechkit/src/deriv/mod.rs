//! Derivatives of sampled data and of functions.
//!
//! - Samples `x(tᵢ)` on any increasing grid: finite differences ([`differentiate`] with a
//!   [`Difference`] scheme, [`second_derivative`]); the course's `v[i] = (x[i+1] - x[i])/dt`
//!   is [`Difference::Forward`], and [`Difference::Central`] (second order, also on uneven
//!   grids) is the better default.
//! - Noisy samples on a uniform grid: [`SavitzkyGolay`] filters smooth and differentiate by
//!   local least-squares polynomials ([`uniform_step`] tells whether the grid is uniform).
//! - Positions in time: [`kinematics`] gives velocity and acceleration either way; for the
//!   columns of a data file, [`derive_motion`] (what `mechkit derive` answers) adds units,
//!   summaries, the table and the plots.
//! - Functions: [`central`] differences, and [`derivative`] by Ridders' extrapolation with an
//!   error estimate.
//!
//! ## Finite differences
//!
//! One value per sample `x(tᵢ)`, on any strictly increasing grid. With `hᵢ = tᵢ − tᵢ₋₁` and
//! the slopes `sᵢ = (xᵢ − xᵢ₋₁)/hᵢ`:
//! - forward: `x'ᵢ ≈ sᵢ₊₁`, first order; the last point takes the backward slope;
//! - backward: `x'ᵢ ≈ sᵢ`, first order; the first point takes the forward slope;
//! - central: the derivative of the parabola through `tᵢ₋₁, tᵢ, tᵢ₊₁`,
//!   `x'ᵢ ≈ (hᵢ₊₁ sᵢ + hᵢ sᵢ₊₁)/(hᵢ + hᵢ₊₁)`, second order on any grid, which is
//!   `(xᵢ₊₁ − xᵢ₋₁)/2h` on a uniform one; at each end the same parabola through the three
//!   outermost points is differentiated at the end point (second order, `(−3x₀ + 4x₁ − x₂)/2h`
//!   on a uniform grid);
//! - second derivative: `x''ᵢ ≈ 2(sᵢ₊₁ − sᵢ)/(hᵢ + hᵢ₊₁)`, second order on a uniform or
//!   smoothly graded grid, first order where neighbouring steps differ by O(h) (its error is
//!   `(hᵢ₊₁ − hᵢ) x'''/3 + O(h²)`); at each end the cubic through the four outermost points
//!   (second order on any grid).
//!
//! Fornberg, "Generation of finite difference formulas on arbitrarily spaced grids", *Math.
//! Comp.* 51 (1988) 699-706, derives these weights in general.
//!
//! ## Savitzky-Golay filters
//!
//! A polynomial of order `p` is fitted by least squares to a moving window of `2m + 1` evenly
//! spaced samples and evaluated (or differentiated) at the centre; near the ends, the
//! polynomial fitted to the first (last) window is evaluated at the first (last) `m` samples,
//! as SciPy's `savgol_filter(..., mode="interp")` does, whose values the tests reproduce.
//! Savitzky and Golay, *Analytical Chemistry* 36 (1964) 1627-1639.
//!
//! ## Derivatives of functions
//!
//! Ridders' method extrapolates central differences with steps `h, h/1.4, h/1.4², …` to step
//! zero (a Richardson tableau, one even power of `h` removed per column) and stops when the
//! error estimate starts to grow. Ridders, *Advances in Engineering Software* 4 (1982) 75-76;
//! *Numerical Recipes*, 3rd ed., §5.7.
//!
//! ## Noise
//!
//! Differencing amplifies noise: an error `ε` in the samples becomes `~ε/h` in `x'` and
//! `~4ε/h²` in `x''`. Measured data usually needs smoothing (a wider window) before a second
//! derivative means anything.

mod confirm;
mod derived;
mod difference;
mod error;
mod kinematics;
mod polyfit;
mod richardson;
mod savitzky_golay;

pub use confirm::{Verdict, confirm};
pub use derived::{
    DeriveError, DeriveQuestion, DerivedColumn, DerivedMotion, DerivedUnits, derive_motion,
};
pub(crate) use difference::check_samples;
pub use difference::{Difference, differentiate, differentiate_into, second_derivative};
pub use error::DerivError;
pub use kinematics::{Derivation, Kinematics, kinematics};
pub use richardson::{Estimate, central, derivative};
pub use savitzky_golay::{SavitzkyGolay, uniform_step};

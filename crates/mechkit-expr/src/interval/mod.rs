//! Interval arithmetic: guaranteed bounds of a formula over a box of inputs, and of its
//! derivative along one parameter, so that a caller can *prove* that an event function has
//! no root (or is monotone) on a stretch of time instead of sampling it.
//!
//! ## Enclosures
//!
//! An [`Interval`] `X = [lo, hi]` encloses a set of values. For every operation `f` the result
//! `F(X, Y)` contains `f(x, y)` for every `x ∈ X`, `y ∈ Y`, both the exact real value and the
//! `f64` value that [`crate::Program::eval`] computes (the *inclusion property*). Composing
//! operations keeps it, so a whole formula evaluated over intervals
//! ([`crate::Program::eval_interval`]) encloses the formula over the box, usually with some
//! overestimation (each occurrence of a variable varies independently: `X − X ≠ 0`).
//!
//! ## Outward rounding
//!
//! The ends are `f64`. `+ − × ÷` and `sqrt`, correctly rounded in round-to-nearest, are moved
//! one float outwards (`next_down` below, `next_up` above), which holds the exact result and
//! the rounded one. The maths library (`sin`, `exp`, `ln`, …) is not correctly rounded: its
//! ends are widened by 4 floats (libraries stay within 2 ulps), `powi` (repeated
//! multiplication) by 20. Exact operations (negation, `abs`, `floor`, `min`, comparisons) are
//! not widened.
//!
//! ## Unknown values
//!
//! [`Interval::ENTIRE`] `[−∞, +∞]` is the unknown value, and the only one that may stand for
//! NaN: anything that could produce NaN somewhere in the box (`sqrt` of a negative, `0·∞`,
//! `sin(∞)`, division by an interval holding 0) gives ENTIRE, and ENTIRE stays ENTIRE through
//! every function. ENTIRE contains 0 and is neither positive nor negative, so a proof never
//! rests on a NaN.
//!
//! ## Proving a sign
//!
//! `g.is_positive()` (`lo > 0`) proves `g > 0` everywhere on the box; `g.is_negative()`
//! (`hi < 0`) proves `g < 0`. Anything else proves nothing (the enclosure may simply be loose:
//! split the box and try again).
//!
//! ## Derivatives
//!
//! A [`Jet`] carries the value and the derivative with respect to one parameter `t` over an
//! interval `T` ([`crate::Program::eval_jet`]): feed it `t` as [`Jet::variable`] and each state
//! variable with an enclosure of its value and of its rate over `T`. `d` bounds `f′` for `f`
//! as an absolutely continuous function on `T` (kinks of `abs`, `min`, `max` are fine), and is
//! ENTIRE where `f` may jump; so `d.is_positive()` proves `f` strictly increasing on `T`
//! ([`Jet::is_increasing`]).
//!
//! ```
//! use mechkit_expr::{Formula, Interval, Jet, MapScope};
//! // the gap of a falling ball: g(t) = h − 4.9 t²
//! let scope = MapScope::new().constant("h", 2.0).slot("t", 0);
//! let gap = Formula::parse("h - 4.9*t^2").unwrap().compile(&scope).unwrap();
//! let early = Interval::new(0.0, 0.6);
//! assert!(gap.eval_interval(&[early]).is_positive()); // no impact before t = 0.6
//! let late = gap.eval_jet(&[Jet::variable(Interval::new(0.6, 0.7))]);
//! assert!(late.is_decreasing()); // at most one crossing in [0.6, 0.7]
//! ```
//!
//! Reference: R. E. Moore, R. B. Kearfott, M. J. Cloud, *Introduction to Interval Analysis*,
//! SIAM 2009 (inclusion functions and their rounded-arithmetic implementation; automatic
//! differentiation).

mod bounds;
mod functions;
mod jet;
mod jet_functions;
mod logic;
mod ops;
mod trig;

pub use bounds::Interval;
pub use jet::Jet;

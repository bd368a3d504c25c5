//! Why samples cannot be differentiated, or a filter cannot be built.

use thiserror::Error;

use crate::Real;

/// Samples that cannot be differentiated, or a Savitzky-Golay filter that cannot be built.
///
/// Indices in messages are 0-based positions in the slices passed; a caller reading a file
/// can translate them to lines with [`Table::line_of`](crate::data::Table::line_of).
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum DerivError {
    /// `t` and `x` differ in length.
    #[error("t has {t} values but x has {x}; each time needs exactly one value")]
    LengthMismatch {
        /// Length of `t`.
        t: usize,
        /// Length of `x`.
        x: usize,
    },
    /// Not enough samples for the method.
    #[error("{method} needs at least {needed} points, got {got}")]
    TooFewPoints {
        /// The method (`the central difference`, `a Savitzky-Golay window of 21 points`).
        method: String,
        /// Points it needs.
        needed: usize,
        /// Points given.
        got: usize,
    },
    /// A time that does not exceed the one before (repeated, out of order, or NaN).
    #[error(
        "t must increase strictly, but t[{index}] = {} follows t[{previous_index}] = \
         {}; sort the samples by time and remove or average repeated times",
        crate::error::short(*value),
        crate::error::short(*previous)
    )]
    NotIncreasing {
        /// Position of the offending time.
        index: usize,
        /// Its value.
        value: Real,
        /// Position of the time before it.
        previous_index: usize,
        /// The time before it.
        previous: Real,
    },
    /// An even Savitzky-Golay window.
    #[error(
        "a Savitzky-Golay window must be an odd number of points (a centre and as many points on \
         each side), not {window}: use {}",
        odd_neighbours(*.window)
    )]
    EvenWindow {
        /// The window asked for.
        window: usize,
    },
    /// A Savitzky-Golay window too short for the polynomial order.
    #[error(
        "a Savitzky-Golay window of {window} points cannot fit a polynomial of order {order}: it \
         has {} coefficients, more than the window has points; use a window of at least {} \
         points, or a lower order",
        .order + 1,
        min_window(*.order)
    )]
    WindowTooShort {
        /// The window asked for.
        window: usize,
        /// The polynomial order asked for.
        order: usize,
    },
    /// Samples that are not evenly spaced, where a method needs them to be.
    #[error(
        "the samples are not evenly spaced: t[{}] - t[{index}] = {}, but the average step \
         is {}; Savitzky-Golay filters need a uniform step: resample the data onto a \
         uniform grid, or use plain differences (method `central`)",
        .index + 1,
        crate::error::short(*step),
        crate::error::short(*expected)
    )]
    NotUniform {
        /// Position of the first uneven step's start.
        index: usize,
        /// That step.
        step: Real,
        /// The average step.
        expected: Real,
    },
}

fn odd_neighbours(window: usize) -> String {
    if window == 0 {
        "1 or more (e.g. 11)".to_string()
    } else {
        format!("{} or {}", window - 1, window + 1)
    }
}

/// The shortest odd window longer than `order`.
pub(crate) fn min_window(order: usize) -> usize {
    if order.is_multiple_of(2) {
        order + 1
    } else {
        order + 2
    }
}

//! The sample bound: every result sampled on a grid whose size the user chooses (`potential
//! --samples`, `spin --samples`) holds at most [`MAX_SAMPLES`] samples, checked before the
//! first one is computed.
//!
//! A grid of `usize::MAX` intervals asked for a vector that no memory holds (an abort, or a
//! capacity overflow); 10^9 of them ran for minutes and wrote gigabytes.

use thiserror::Error;

/// The most grid intervals (rows of a sampled result) one answer may hold: 10^7, a CSV of
/// about a gigabyte and a few seconds of work; a plot of more points shows nothing new.
pub const MAX_SAMPLES: usize = 10_000_000;

/// A sampled result asked for more than [`MAX_SAMPLES`] samples.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
#[error(
    "{samples} {what} are more than the {MAX_SAMPLES} a result may hold; ask for fewer (the default, 2000, draws a smooth curve)"
)]
pub struct SampleBoundError {
    /// What is sampled (`grid intervals`, `output intervals`).
    pub what: &'static str,
    /// How many were asked for.
    pub samples: usize,
}

/// Checks that `samples` `what` are within [`MAX_SAMPLES`].
///
/// ```
/// use mechkit::sample_bound::{MAX_SAMPLES, check_samples};
/// assert!(check_samples("grid intervals", MAX_SAMPLES).is_ok());
/// assert!(check_samples("grid intervals", MAX_SAMPLES + 1).is_err());
/// ```
pub fn check_samples(what: &'static str, samples: usize) -> Result<(), SampleBoundError> {
    if samples > MAX_SAMPLES {
        Err(SampleBoundError { what, samples })
    } else {
        Ok(())
    }
}

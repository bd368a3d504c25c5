//! The summary of a column of numbers: the range, the mean, the median, and the first and last
//! values.

use crate::Real;

/// Minimum, maximum, mean and median of the finite values of a column, and its first and last
/// values (as they are, finite or not).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Stats {
    /// The smallest finite value.
    pub min: Real,
    /// The largest finite value.
    pub max: Real,
    /// The mean of the finite values.
    pub mean: Real,
    /// The median of the finite values (the mean of the middle two for an even count).
    pub median: Real,
    /// The first value.
    pub first: Real,
    /// The last value.
    pub last: Real,
}

impl Stats {
    /// The summary of `values`; `None` when none is finite.
    ///
    /// ```
    /// use mechkit::data::Stats;
    /// let s = Stats::of(&[3.0, f64::NAN, 1.0, 2.0, 10.0]).unwrap();
    /// assert_eq!((s.min, s.max, s.median, s.mean), (1.0, 10.0, 2.5, 4.0));
    /// assert_eq!(s.first, 3.0);
    /// assert!(Stats::of(&[f64::NAN]).is_none());
    /// ```
    pub fn of(values: &[Real]) -> Option<Self> {
        let mut sorted: Vec<Real> = values.iter().copied().filter(|v| v.is_finite()).collect();
        sorted.sort_by(Real::total_cmp);
        let n = sorted.len();
        if n == 0 {
            return None;
        }
        let median = if n % 2 == 1 {
            sorted[n / 2]
        } else {
            0.5 * (sorted[n / 2 - 1] + sorted[n / 2])
        };
        Some(Self {
            min: sorted[0],
            max: sorted[n - 1],
            mean: sorted.iter().sum::<Real>() / n as Real,
            median,
            first: values[0],
            last: values[values.len() - 1],
        })
    }
}

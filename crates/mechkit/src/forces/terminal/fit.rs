//! The steady part of a fall: a least-squares line through position samples, whose slope is
//! the terminal velocity, and whether the speed was steady there.

use super::TerminalError;
use crate::Real;

/// A straight line fitted through position samples: the steady speed and how well a line
/// describes them.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SteadyFit {
    /// The slope (m/s): the velocity, signed.
    pub velocity: Real,
    /// The intercept at `t = 0` (m).
    pub intercept: Real,
    /// The root-mean-square distance of the samples from the line (m).
    pub rms_residual: Real,
    /// The slopes of the first and second halves of the samples: equal when the speed is
    /// steady, different while the body still accelerates.
    pub half_slopes: (Real, Real),
    /// How many samples were fitted.
    pub samples: usize,
}

/// Fits a line `x = v t + x₀` by least squares through the samples from index `from` on (the
/// part of the fall where the speed is steady).
pub fn steady_fit(t: &[Real], x: &[Real], from: usize) -> Result<SteadyFit, TerminalError> {
    let n = t.len().min(x.len());
    let (t, x) = (&t[from.min(n)..n], &x[from.min(n)..n]);
    if t.len() < 3 {
        return Err(TerminalError::TooFewSamples(t.len()));
    }
    if let Some(i) = t.windows(2).position(|w| w[1] <= w[0]) {
        return Err(TerminalError::Unordered(from + i + 1));
    }
    let (velocity, intercept) = line(t, x);
    let rms = (t
        .iter()
        .zip(x)
        .map(|(ti, xi)| (xi - velocity * ti - intercept).powi(2))
        .sum::<Real>()
        / t.len() as Real)
        .sqrt();
    let half = t.len() / 2;
    let first = line(&t[..half.max(2)], &x[..half.max(2)]).0;
    let second = line(&t[half.min(t.len() - 2)..], &x[half.min(t.len() - 2)..]).0;
    Ok(SteadyFit {
        velocity,
        intercept,
        rms_residual: rms,
        half_slopes: (first, second),
        samples: t.len(),
    })
}

/// [`steady_fit`] from the first sample at or after the time `from` (s), or through the
/// second half of the samples without it.
pub fn steady_fit_from(
    t: &[Real],
    x: &[Real],
    from: Option<Real>,
) -> Result<SteadyFit, TerminalError> {
    let start = match from {
        Some(t0) => t
            .iter()
            .position(|&ti| ti >= t0)
            .ok_or(TerminalError::NothingAfter {
                from: t0,
                last: t.last().copied().unwrap_or(Real::NAN),
            })?,
        None => t.len() / 2,
    };
    steady_fit(t, x, start)
}

impl SteadyFit {
    /// A warning when the two halves of the fitted part fall at speeds more than 5% apart:
    /// the body was still accelerating there.
    pub fn unsteady_warning(&self) -> Option<String> {
        let (a, b) = self.half_slopes;
        let spread = (a - b).abs() / a.abs().max(b.abs());
        (spread > 0.05).then(|| {
            format!(
                "the speed is not steady in the fitted part: its halves fall at {} and {} m/s ({:.0}% apart); fit a later part with --from",
                number(a),
                number(b),
                100.0 * spread
            )
        })
    }
}

/// The written form of a number: the shortest text that reads back as it.
fn number(x: Real) -> String {
    let mut s = String::new();
    crate::csv::push_number(&mut s, x);
    s
}

/// Least-squares slope and intercept (centred sums, for accuracy).
fn line(t: &[Real], x: &[Real]) -> (Real, Real) {
    let n = t.len() as Real;
    let tm = t.iter().sum::<Real>() / n;
    let xm = x.iter().sum::<Real>() / n;
    let (mut stt, mut stx) = (0.0, 0.0);
    for (ti, xi) in t.iter().zip(x) {
        stt += (ti - tm) * (ti - tm);
        stx += (ti - tm) * (xi - xm);
    }
    let slope = stx / stt;
    (slope, xm - slope * tm)
}

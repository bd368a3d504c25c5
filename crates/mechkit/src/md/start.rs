//! The start of a run that cannot work, refused before its first step.

use crate::Real;

use super::MdError;

/// Two particles at exactly the same place (0-based, the first in order first), if any:
/// found by sorting, O(N log N).
pub(crate) fn coincident_pair(x: &[[Real; 3]]) -> Option<(usize, usize)> {
    let mut order: Vec<usize> = (0..x.len()).collect();
    let key = |i: usize| x[i].map(|c| (c + 0.0).to_bits());
    order.sort_unstable_by_key(|&i| (key(i), i));
    order
        .windows(2)
        .filter(|w| key(w[0]) == key(w[1]))
        .map(|w| (w[0].min(w[1]), w[0].max(w[1])))
        .min()
}

/// The start of a run that cannot work, refused before it: two particles at the same place
/// (an infinite force), or a particle crossing more than the whole box (its shortest edge
/// `edge`) in one step: the velocities of a temperature far too high, or a time step far too
/// long, for which a step is no motion through the box (a merely too large step that the
/// box holds is a run that diverges, found as it goes).
pub(super) fn check_start(
    x: &[[Real; 3]],
    v: &[[Real; 3]],
    dt: Real,
    edge: Real,
) -> Result<(), MdError> {
    if let Some((first, second)) = coincident_pair(x) {
        return Err(MdError::Coincident {
            first: first + 1,
            second: second + 1,
            at: x[first],
        });
    }
    let speed = v
        .iter()
        .map(|u| {
            let big = u.iter().fold(0.0, |m: Real, c| m.max(c.abs()));
            if big == 0.0 || !big.is_finite() {
                return big;
            }
            big * u.iter().map(|c| (c / big).powi(2)).sum::<Real>().sqrt()
        })
        .fold(0.0, Real::max);
    let distance = speed * dt;
    // (NaN or infinite distances are refused too)
    if distance.is_nan() || distance > edge {
        return Err(MdError::StepTooLong {
            dt,
            speed,
            distance,
            edge,
        });
    }
    Ok(())
}

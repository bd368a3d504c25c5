//! The error weights and the first step the implicit methods share: the weights
//! `atol + rtol max(|y₀|, |y₁|)`, the root-mean-square norm in them over the controlled
//! components, and Hairer's first step (*Solving ODEs I*, Sec. II.4).

use super::control::AdaptiveConfig;
use crate::Real;

/// How many of `n` components the error is measured on (`error_components`, the leading
/// ones: the motion, not the works carried along).
pub(super) fn controlled(config: &AdaptiveConfig, n: usize) -> usize {
    config.error_components.unwrap_or(n).min(n)
}

/// Writes the weights `atol_i + rtol_i max(|y0_i|, |y1_i|)` into `w`.
pub(super) fn set_weights(
    config: &AdaptiveConfig,
    y0: &[Real],
    y1: Option<&[Real]>,
    w: &mut [Real],
) {
    for (i, wi) in w.iter_mut().enumerate().take(y0.len()) {
        let size = match y1 {
            Some(y1) => y0[i].abs().max(y1[i].abs()),
            None => y0[i].abs(),
        };
        *wi = config.atol.at(i) + config.rtol.at(i) * size;
    }
}

/// The RMS of `v(i)/w_i` over the first `n` components (a zero weight makes any non-zero
/// component infinite).
pub(super) fn weighted_rms(w: &[Real], n: usize, v: impl Fn(usize) -> Real) -> Real {
    if n == 0 {
        return 0.0;
    }
    let sum: Real = (0..n)
        .map(|i| {
            let vi = v(i);
            if w[i] > 0.0 {
                let r = vi / w[i];
                r * r
            } else if vi == 0.0 {
                0.0
            } else {
                Real::INFINITY
            }
        })
        .sum();
    (sum / n as Real).sqrt()
}

/// The trial step `h0` from the norms of `y` (`d0`) and `f(t, y)` (`d1`).
pub(super) fn trial_step(config: &AdaptiveConfig, d0: Real, d1: Real, span: Real) -> Real {
    let h0 = if d0 < 1e-5 || d1 < 1e-5 {
        1e-6
    } else {
        0.01 * d0 / d1
    };
    h0.min(config.h_max).min(span)
}

/// The first step from the trial `h0`, `d1` and the norm `d2` of the change of `f` along the
/// trial step over `h0`, for an error estimate of order `order`.
pub(super) fn first_step(
    config: &AdaptiveConfig,
    h0: Real,
    d1: Real,
    d2: Real,
    span: Real,
    order: i32,
) -> Real {
    let h1 = if d1.max(d2) <= 1e-15 {
        (h0 * 1e-3).max(1e-6)
    } else {
        (0.01 / d1.max(d2)).powf(1.0 / Real::from(order + 1))
    };
    let h = (100.0 * h0).min(h1).min(config.h_max).min(span);
    if h > 0.0 && h.is_finite() {
        h
    } else {
        Real::min(1e-6, config.h_max).min(span)
    }
}

//! The physical pendulum's period: small-angle `T₀ = 2π √(I/(m g d))` and the exact period at
//! amplitude `θ₀`, `T = 4 √(I/(m g d)) K(sin(θ₀/2))`, with `K` the complete elliptic integral of
//! the first kind.

use std::f64::consts::PI;

use super::HingedBody;
use crate::Real;
use crate::elliptic::complete_k_complement;

/// The complete elliptic integral of the first kind `K(k) = ∫₀^{π/2} dφ/√(1 - k² sin²φ)` of
/// modulus `k` (`|k| < 1`; the parameter is `m = k²`), by the arithmetic-geometric mean
/// ([`crate::elliptic`]), with `1 - k²` formed as `(1 - k)(1 + k)` so that no digits
/// are lost near the top. `None` for `|k| ≥ 1`.
pub fn elliptic_k(k: Real) -> Option<Real> {
    if k.is_nan() || k.abs() >= 1.0 {
        return None;
    }
    Some(complete_k_complement((1.0 - k.abs()) * (1.0 + k.abs())))
}

/// The small-angle period of `body` swinging in gravity `g` perpendicular to its axis,
/// `2π √(I/(m g d))` with `d` the distance of the centre of mass from the axis (hanging
/// weights included in `I`). `None` when the centre of mass is on the axis.
pub fn small_angle_period(body: &HingedBody, g: Real) -> Option<Real> {
    let stiffness = body.mass() * g * body.lever();
    (stiffness > 0.0).then(|| 2.0 * PI * (body.effective_moment() / stiffness).sqrt())
}

/// The exact period at amplitude `amplitude` (radians from the lowest point, below π):
/// `T₀ · (2/π) K(sin(θ₀/2))`. `None` when the body does not swing (centre of mass on the axis,
/// or an amplitude of π or more, which goes over the top).
pub fn period(body: &HingedBody, g: Real, amplitude: Real) -> Option<Real> {
    let t0 = small_angle_period(body, g)?;
    Some(t0 * 2.0 / PI * elliptic_k((0.5 * amplitude).sin())?).filter(|_| amplitude.abs() < PI)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn elliptic_k_known_values() {
        // K(0) = π/2; K(1/√2) = Γ(1/4)²/(4√π) (Abramowitz & Stegun 17.3)
        assert_eq!(elliptic_k(0.0), Some(PI / 2.0));
        let lemniscate = 1.854_074_677_301_371_9;
        assert!((elliptic_k(0.5_f64.sqrt()).unwrap() - lemniscate).abs() < 4e-16);
        // K(sin 80°) = 3.153385251887838 (A&S table 17.1)
        let k80 = elliptic_k(80f64.to_radians().sin()).unwrap();
        assert!((k80 - 3.153_385_251_887_838).abs() < 1e-14, "{k80}");
        assert_eq!(elliptic_k(1.0), None);
    }
}

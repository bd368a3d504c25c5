//! The laws of a contact force: the elastic force of an overlap `δ > 0` (linear or Hertz), the
//! damping of its rate `δ̇`, and the closed forms of a head-on contact that tests and users
//! check simulations against.
//!
//! | law | elastic force `F_e(δ)` | elastic energy `U(δ)` |
//! |---|---|---|
//! | [`ContactLaw::Linear`] | `k δ` | `k δ²/2` |
//! | [`ContactLaw::Hertz`] | `k δ^(3/2)` | `(2/5) k δ^(5/2)` |
//!
//! | damping | damping force `F_d(δ, δ̇)` |
//! |---|---|
//! | [`ContactDamping::None`] | `0` |
//! | [`ContactDamping::Linear`] | `c δ̇` (the linear spring-dashpot, Kelvin-Voigt) |
//! | [`ContactDamping::HuntCrossley`] | `α F_e(δ) δ̇` (`α k δ^(3/2) δ̇`, or `α k δ δ̇` for the linear law) |
//!
//! Sign convention: both are magnitudes along the contact normal, positive when they push the
//! bodies apart; `δ̇ > 0` while the overlap grows (approach), so a damper adds to the repulsion
//! during compression and subtracts from it during restitution.
//!
//! References: K. L. Johnson, *Contact Mechanics* (Cambridge, 1985), §11.1 (Hertz impact);
//! K. H. Hunt and F. R. E. Crossley, "Coefficient of restitution interpreted as damping in
//! vibroimpact", J. Appl. Mech. 42 (1975) 440; T. Schwager and T. Pöschel, "Coefficient of
//! restitution and linear-dashpot model revisited", Granular Matter 9 (2007) 465 (the
//! restitution of the dashpot without attraction).

use std::f64::consts::PI;

use crate::Real;

/// The elastic law of a contact: the normal force of an overlap `δ > 0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ContactLaw {
    /// A linear spring, `F = k δ` (`k` in N/m).
    Linear {
        /// Stiffness (N/m).
        k: Real,
    },
    /// Hertz's law of two elastic spheres, `F = k δ^(3/2)` (`k` in N/m^(3/2); for spheres
    /// `k = (4/3) E* sqrt(R*)`).
    Hertz {
        /// Stiffness (N/m^(3/2)).
        k: Real,
    },
}

impl ContactLaw {
    /// The linear law `k δ`.
    pub fn linear(k: Real) -> Self {
        ContactLaw::Linear { k }
    }

    /// Hertz's law `k δ^(3/2)`.
    pub fn hertz(k: Real) -> Self {
        ContactLaw::Hertz { k }
    }

    /// Looks a law up by name (`linear`/`spring`, `hertz`), with stiffness `k`.
    ///
    /// # Example
    /// ```
    /// use mechkit::forces::ContactLaw;
    /// assert_eq!(ContactLaw::from_name("spring", 1e3), Some(ContactLaw::linear(1e3)));
    /// assert_eq!(ContactLaw::from_name("Hertz", 1e6), Some(ContactLaw::hertz(1e6)));
    /// assert_eq!(ContactLaw::from_name("rubber", 1.0), None);
    /// ```
    pub fn from_name(name: &str, k: Real) -> Option<Self> {
        match name.trim().to_ascii_lowercase().as_str() {
            "linear" | "spring" | "hooke" => Some(Self::linear(k)),
            "hertz" => Some(Self::hertz(k)),
            _ => None,
        }
    }

    /// Its name: `linear` or `hertz`.
    pub fn name(self) -> &'static str {
        match self {
            ContactLaw::Linear { .. } => "linear",
            ContactLaw::Hertz { .. } => "hertz",
        }
    }

    /// The stiffness `k`.
    pub fn k(self) -> Real {
        match self {
            ContactLaw::Linear { k } | ContactLaw::Hertz { k } => k,
        }
    }

    /// The elastic force `F_e(δ)`: `k δ` or `k δ^(3/2)` for `δ > 0`, zero otherwise.
    #[inline]
    pub fn force(self, delta: Real) -> Real {
        if delta <= 0.0 {
            return 0.0;
        }
        match self {
            ContactLaw::Linear { k } => k * delta,
            ContactLaw::Hertz { k } => k * delta * delta.sqrt(),
        }
    }

    /// The elastic energy `U(δ)`: `k δ²/2` or `(2/5) k δ^(5/2)` for `δ > 0`, zero otherwise.
    #[inline]
    pub fn energy(self, delta: Real) -> Real {
        if delta <= 0.0 {
            return 0.0;
        }
        match self {
            ContactLaw::Linear { k } => 0.5 * k * delta * delta,
            ContactLaw::Hertz { k } => 0.4 * k * delta * delta * delta.sqrt(),
        }
    }
}

/// How a contact dissipates energy. The damping acts only while the bodies overlap, along the
/// normal; see the module doc for the sign convention.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum ContactDamping {
    /// No damping: the contact is elastic.
    #[default]
    None,
    /// The linear dashpot `F_d = c δ̇` (`c` in N·s/m). Its force jumps to `c v` when a contact
    /// starts.
    Linear {
        /// Damping coefficient (N·s/m).
        c: Real,
    },
    /// Hunt and Crossley's damping `F_d = α F_e(δ) δ̇` (`α` in s/m), which vanishes with the
    /// overlap, so the force is continuous when a contact starts.
    HuntCrossley {
        /// Damping factor (s/m).
        alpha: Real,
    },
}

impl ContactDamping {
    /// The damping force `F_d` at overlap `δ > 0` growing at the rate `δ̇`, for the law `law`
    /// (zero when `δ ≤ 0`).
    #[inline]
    pub fn force(self, law: ContactLaw, delta: Real, rate: Real) -> Real {
        if delta <= 0.0 {
            return 0.0;
        }
        match self {
            ContactDamping::None => 0.0,
            ContactDamping::Linear { c } => c * rate,
            ContactDamping::HuntCrossley { alpha } => alpha * law.force(delta) * rate,
        }
    }

    /// Whether it dissipates at all (a coefficient of zero does not).
    pub fn is_active(self) -> bool {
        match self {
            ContactDamping::None => false,
            ContactDamping::Linear { c } => c != 0.0,
            ContactDamping::HuntCrossley { alpha } => alpha != 0.0,
        }
    }
}

/// Duration of an elastic contact with the linear law: half a period of the oscillator of the
/// reduced mass, `π sqrt(m/k)` (s), whatever the approach speed.
///
/// # Example
/// ```
/// use mechkit::forces::linear_contact_time;
/// assert!((linear_contact_time(1e4, 0.5) - 0.022_214_414_690_791_83).abs() < 1e-15);
/// ```
pub fn linear_contact_time(k: Real, m_reduced: Real) -> Real {
    PI * (m_reduced / k).sqrt()
}

/// The damping ratio `ζ = c/(2 sqrt(k m))` of the linear spring-dashpot.
pub fn linear_damping_ratio(k: Real, c: Real, m_reduced: Real) -> Real {
    c / (2.0 * (k * m_reduced).sqrt())
}

/// Coefficient of restitution of the linear spring-dashpot when the force may pull (no
/// clamping, [`crate::forces::ContactForceBuilder::allow_attraction`]): the bodies separate
/// when the overlap returns to zero, after half a damped period, so
/// `e = exp(-π ζ / sqrt(1 - ζ²))`. For `ζ ≥ 1` the overlap never returns to zero and `e = 0`.
///
/// # Example
/// ```
/// use mechkit::forces::linear_restitution;
/// // ζ = 0.2
/// let e = linear_restitution(100.0, 4.0, 1.0);
/// assert!((e - (-std::f64::consts::PI * 0.2 / 0.96f64.sqrt()).exp()).abs() < 1e-15);
/// ```
pub fn linear_restitution(k: Real, c: Real, m_reduced: Real) -> Real {
    let zeta = linear_damping_ratio(k, c, m_reduced);
    if zeta >= 1.0 {
        return 0.0;
    }
    (-PI * zeta / (1.0 - zeta * zeta).sqrt()).exp()
}

/// Coefficient of restitution of the linear spring-dashpot when the normal force is clamped at
/// zero (the default): the bodies separate as soon as `k δ + c δ̇` reaches zero, before the
/// overlap does, and `e = exp(-β t_c)` with `β = c/(2m)` and the contact time
/// `t_c = atan2(2ζ sqrt(1-ζ²), 2ζ² - 1)/ω` (`ω = ω₀ sqrt(1-ζ²)`) for `ζ < 1` (Schwager and
/// Pöschel 2007; for `ζ ≥ 1` the hyperbolic continuation). Always larger than
/// [`linear_restitution`].
///
/// # Example
/// ```
/// use mechkit::forces::{linear_restitution, linear_restitution_clamped};
/// let (k, c, m) = (100.0, 4.0, 1.0);
/// assert!(linear_restitution_clamped(k, c, m) > linear_restitution(k, c, m));
/// // critical damping: e = exp(-2)
/// assert!((linear_restitution_clamped(k, 20.0, m) - (-2.0f64).exp()).abs() < 1e-12);
/// ```
pub fn linear_restitution_clamped(k: Real, c: Real, m_reduced: Real) -> Real {
    let w0 = (k / m_reduced).sqrt();
    let beta = c / (2.0 * m_reduced);
    let zeta = beta / w0;
    let t_c = if zeta < 1.0 {
        let w = w0 * (1.0 - zeta * zeta).sqrt();
        (2.0 * beta * w).atan2(beta * beta - w * w) / w
    } else if zeta == 1.0 {
        2.0 / beta
    } else {
        let big_w = (beta * beta - w0 * w0).sqrt();
        ((beta + big_w) / (beta - big_w)).ln() / big_w
    };
    (-beta * t_c).exp()
}

/// Maximum overlap of a Hertz contact approached at speed `v`, from `m v²/2 = (2/5) k δ^(5/2)`:
/// `δ_max = (5 m v²/(4 k))^(2/5)` (m).
///
/// # Example
/// ```
/// use mechkit::forces::hertz_max_overlap;
/// let d = hertz_max_overlap(1e6, 0.5, 2.0);
/// assert!((0.4 * 1e6 * d.powf(2.5) - 0.5 * 0.5 * 4.0).abs() < 1e-12);
/// ```
pub fn hertz_max_overlap(k: Real, m_reduced: Real, v: Real) -> Real {
    (1.25 * m_reduced * v * v / k).powf(0.4)
}

/// Duration of an elastic Hertz contact approached at speed `v`:
/// `t_c = 2 (δ_max/v) ∫₀¹ dx/sqrt(1 - x^(5/2)) ≈ 2.943 δ_max/v` (Johnson 1985, §11.1).
pub fn hertz_contact_time(k: Real, m_reduced: Real, v: Real) -> Real {
    /// `(4/5) sqrt(π) Γ(2/5)/Γ(9/10)`.
    const FACTOR: Real = 2.943_275_184_324_705;
    FACTOR * hertz_max_overlap(k, m_reduced, v) / v.abs()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_force_is_minus_the_derivative_of_the_energy() {
        for law in [ContactLaw::linear(300.0), ContactLaw::hertz(2e4)] {
            for d in [1e-3, 0.01, 0.2] {
                let h = 1e-6 * d;
                let du = (law.energy(d + h) - law.energy(d - h)) / (2.0 * h);
                assert!(
                    (du - law.force(d)).abs() < 1e-7 * law.force(d),
                    "{law:?} at {d}"
                );
            }
            assert_eq!(law.force(-0.1), 0.0);
            assert_eq!(law.energy(0.0), 0.0);
        }
    }

    #[test]
    fn clamped_restitution_tends_to_the_unclamped_one_for_light_damping() {
        let (k, m): (Real, Real) = (1e4, 0.3);
        for zeta in [1e-4, 0.01, 0.3, 0.7, 0.999, 1.0, 1.001, 3.0] {
            let c = 2.0 * zeta * (k * m).sqrt();
            let (e0, e1) = (
                linear_restitution(k, c, m),
                linear_restitution_clamped(k, c, m),
            );
            assert!(e1 > e0 && e1 < 1.0, "ζ = {zeta}: {e0} {e1}");
            if zeta < 0.01 {
                assert!((e1 - e0).abs() < 4.0 * zeta * zeta, "ζ = {zeta}: {e0} {e1}");
            }
        }
        // continuous through critical damping
        let e = |z: Real| linear_restitution_clamped(k, 2.0 * z * (k * m).sqrt(), m);
        assert!((e(1.0 - 1e-9) - e(1.0)).abs() < 1e-6);
        assert!((e(1.0 + 1e-9) - e(1.0)).abs() < 1e-6);
    }

    #[test]
    fn hertz_time_factor_is_the_integral() {
        // ∫₀¹ dx/sqrt(1 - x^(5/2)) with x = 1 - y² (smooth in y), midpoint rule
        let n: u32 = 20_000;
        let integral: Real = (0..n)
            .map(|i| {
                let y = (Real::from(i) + 0.5) / Real::from(n);
                2.0 * y / (1.0 - (1.0 - y * y).powf(2.5)).sqrt() / Real::from(n)
            })
            .sum();
        assert!((2.0 * integral - 2.943_275_184_324_705).abs() < 1e-6);
    }
}

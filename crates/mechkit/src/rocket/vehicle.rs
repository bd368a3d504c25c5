//! The rocket's parameters, their checks, and the closed forms of its drag-free flight.

use super::error::{Input, RocketError};
use crate::Real;

/// A rocket burning at a constant mass rate, flying along a vertical line (or in free space),
/// starting from rest at `x = 0`.
///
/// The fields are public for reading; [`Rocket::new`], [`Rocket::with_gravity`] and
/// [`Rocket::with_drag`] check them, and [`Rocket::simulate`] checks them again.
///
/// # Example
/// ```
/// use approx::assert_relative_eq;
/// use mechkit::rocket::Rocket;
/// // 1000 kg at ignition, 400 kg at burnout, 10 kg/s at 2 km/s, in uniform gravity
/// let rocket = Rocket::new(1000.0, 400.0, 10.0, 2000.0)?.with_gravity(9.81)?;
/// assert_relative_eq!(rocket.burn_time(), 60.0);
/// assert_relative_eq!(rocket.delta_v(), 2000.0 * 2.5f64.ln()); // Tsiolkovsky
/// let (t1, x1, v1) = rocket.burnout();
/// assert_relative_eq!(v1, 2000.0 * 2.5f64.ln() - 9.81 * 60.0);
/// let (_, apex) = rocket.apex().unwrap();
/// assert_relative_eq!(apex, x1 + v1 * v1 / (2.0 * 9.81));
/// # Ok::<(), mechkit::rocket::RocketError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rocket {
    /// Mass at ignition, `m0` (kg).
    pub m0: Real,
    /// Mass at burnout, `m1 < m0` (kg): the rocket without its propellant.
    pub m1: Real,
    /// Mass ejected per second, `ṁ > 0` (kg/s).
    pub mass_rate: Real,
    /// Exhaust speed relative to the rocket, `u > 0` (m/s).
    pub exhaust_speed: Real,
    /// Uniform gravity `g ≥ 0` (m/s²), pointing against the thrust; 0 in free space.
    pub g: Real,
    /// Quadratic drag coefficient `D` in `F = −D v|v|` (kg/m); `None` for no drag.
    pub drag: Option<Real>,
}

impl Rocket {
    /// A rocket in free space without drag: mass `m0` at ignition and `m1` at burnout, mass
    /// rate `mass_rate` and exhaust speed `exhaust_speed`. Checks that the masses and the rate
    /// and speed are positive and finite and that `m1 < m0`.
    pub fn new(
        m0: Real,
        m1: Real,
        mass_rate: Real,
        exhaust_speed: Real,
    ) -> Result<Self, RocketError> {
        let rocket = Self {
            m0,
            m1,
            mass_rate,
            exhaust_speed,
            g: 0.0,
            drag: None,
        };
        rocket.validate()?;
        Ok(rocket)
    }

    /// The same rocket in a uniform gravity `g ≥ 0` (m/s²).
    pub fn with_gravity(self, g: Real) -> Result<Self, RocketError> {
        let rocket = Self { g, ..self };
        rocket.validate()?;
        Ok(rocket)
    }

    /// The same rocket with quadratic drag `F = −D v|v|`, `D ≥ 0` (kg/m).
    pub fn with_drag(self, d: Real) -> Result<Self, RocketError> {
        let rocket = Self {
            drag: Some(d),
            ..self
        };
        rocket.validate()?;
        Ok(rocket)
    }

    /// Checks every field (what the constructors check).
    pub fn validate(&self) -> Result<(), RocketError> {
        let positive = |v: Real| v.is_finite() && v > 0.0;
        let non_negative = |v: Real| v.is_finite() && v >= 0.0;
        for (input, which, value) in [
            (Input::IgnitionMass, "the mass at ignition m0", self.m0),
            (Input::BurnoutMass, "the burnout mass m1", self.m1),
        ] {
            if !positive(value) {
                return Err(RocketError::Mass {
                    input,
                    which,
                    value,
                });
            }
        }
        if self.m1 >= self.m0 {
            return Err(RocketError::Burnout {
                m0: self.m0,
                m1: self.m1,
            });
        }
        if !positive(self.mass_rate) {
            return Err(RocketError::MassRate {
                value: self.mass_rate,
            });
        }
        if !self.burn_time().is_finite() {
            return Err(RocketError::BurnTime {
                propellant: self.m0 - self.m1,
                mass_rate: self.mass_rate,
            });
        }
        if !positive(self.exhaust_speed) {
            return Err(RocketError::ExhaustSpeed {
                value: self.exhaust_speed,
            });
        }
        if !non_negative(self.g) {
            return Err(RocketError::Gravity { value: self.g });
        }
        if let Some(d) = self.drag
            && !non_negative(d)
        {
            return Err(RocketError::Drag { value: d });
        }
        Ok(())
    }

    /// The drag coefficient, 0 without drag.
    pub fn drag_coefficient(&self) -> Real {
        self.drag.unwrap_or(0.0)
    }

    /// The duration of the burn, `T = (m0 − m1)/ṁ` (s).
    pub fn burn_time(&self) -> Real {
        (self.m0 - self.m1) / self.mass_rate
    }

    /// The thrust `u ṁ` (N).
    pub fn thrust(&self) -> Real {
        self.exhaust_speed * self.mass_rate
    }

    /// Whether the thrust exceeds the weight at ignition, `u ṁ > m0 g` (always in free
    /// space). If not, the rocket sinks at first: the model has no launch pad.
    pub fn lifts_off(&self) -> bool {
        self.thrust() > self.m0 * self.g
    }

    /// The mass at time `t ≥ 0`: `m0 − ṁ t` during the burn, `m1` after.
    pub fn mass(&self, t: Real) -> Real {
        if t >= self.burn_time() {
            self.m1
        } else {
            self.m0 - self.mass_rate * t
        }
    }

    /// The rocket equation's change of speed in free space, `Δv = u ln(m0/m1)` (Tsiolkovsky).
    pub fn delta_v(&self) -> Real {
        self.exhaust_speed * (self.m0 / self.m1).ln()
    }

    /// The speed and height the thrust alone has given after ejecting the fraction `r` of
    /// `m0`, with `q = 1 − r` the fraction left: `u ln(1/q)` and `(u m0/ṁ)(r + q ln q)`.
    fn thrust_part(&self, r: Real, q: Real) -> (Real, Real) {
        let u = self.exhaust_speed;
        (
            -u * q.ln(),
            u * self.m0 / self.mass_rate * burn_distance(r, q),
        )
    }

    /// Burnout without drag: `(T, x(T), v(T))` with `v(T) = u ln(m0/m1) − g T` and
    /// `x(T) = u T − (u m1/ṁ) ln(m0/m1) − g T²/2`.
    pub fn burnout(&self) -> (Real, Real, Real) {
        let t = self.burn_time();
        let (dv, dx) = self.thrust_part((self.m0 - self.m1) / self.m0, self.m1 / self.m0);
        (t, dx - 0.5 * self.g * t * t, dv - self.g * t)
    }

    /// The speed at time `t ≥ 0` without drag: `u ln(m0/m(t)) − g t` during the burn, then
    /// `v1 − g (t − T)` on the ballistic coast.
    pub fn speed(&self, t: Real) -> Real {
        self.speed_and_height(t).0
    }

    /// The height at time `t ≥ 0` without drag: `u t − (u m(t)/ṁ) ln(m0/m(t)) − g t²/2` during
    /// the burn, then `x1 + v1 (t − T) − g (t − T)²/2` on the ballistic coast.
    pub fn height(&self, t: Real) -> Real {
        self.speed_and_height(t).1
    }

    fn speed_and_height(&self, t: Real) -> (Real, Real) {
        assert!(t >= 0.0, "the flight starts at t = 0, not t = {t}");
        let t1 = self.burn_time();
        if t < t1 {
            let r = self.mass_rate * t / self.m0;
            let (dv, dx) = self.thrust_part(r, 1.0 - r);
            (dv - self.g * t, dx - 0.5 * self.g * t * t)
        } else {
            let (_, x1, v1) = self.burnout();
            let s = t - t1;
            (v1 - self.g * s, x1 + v1 * s - 0.5 * self.g * s * s)
        }
    }

    /// The highest point of the drag-free coast after burnout, `(t1 + v1/g, x1 + v1²/(2g))`;
    /// the burnout point itself if the rocket is not rising then. `None` in free space
    /// (`g = 0`), where the coast never turns.
    pub fn apex(&self) -> Option<(Real, Real)> {
        if self.g == 0.0 {
            return None;
        }
        let (t1, x1, v1) = self.burnout();
        if v1 <= 0.0 {
            return Some((t1, x1));
        }
        Some((t1 + v1 / self.g, x1 + v1 * v1 / (2.0 * self.g)))
    }
}

/// `r + q ln q` with `q = 1 − r`: the thrust's contribution to the height in units of
/// `u m0/ṁ`. For small `r` the two terms nearly cancel, so the series
/// `Σ_{k≥2} r^k/(k(k−1))` is summed instead.
fn burn_distance(r: Real, q: Real) -> Real {
    if r >= 0.1 {
        return r + q * q.ln();
    }
    let mut sum = 0.0;
    let mut power = r;
    for k in 2..60 {
        power *= r;
        let kf = Real::from(k);
        let term = power / (kf * (kf - 1.0));
        sum += term;
        if term <= Real::EPSILON * sum {
            break;
        }
    }
    sum
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_series_continues_the_closed_form() {
        for r in [0.099_999_9_f64, 0.05, 1e-3] {
            let direct = r + (1.0 - r) * (-r).ln_1p();
            let series = burn_distance(r, 1.0 - r);
            assert!(
                (series - direct).abs() <= 1e-12 * direct,
                "{r}: {series} {direct}"
            );
        }
        assert_eq!(burn_distance(0.0, 1.0), 0.0);
        let r: Real = 1e-8;
        let leading = r * r / 2.0 + r.powi(3) / 6.0;
        assert!((burn_distance(r, 1.0 - r) - leading).abs() <= 1e-15 * leading);
    }

    #[test]
    fn the_height_is_the_integral_of_the_speed() {
        let rocket = Rocket::new(1000.0, 400.0, 10.0, 2000.0)
            .unwrap()
            .with_gravity(9.81)
            .unwrap();
        let t_end = 80.0; // past burnout at 60 s
        let tol = crate::quad::Tolerance {
            abs: 1e-9,
            rel: 1e-13,
        };
        let x = crate::quad::integrate(|t| rocket.speed(t), 0.0, t_end, tol)
            .unwrap()
            .value;
        assert!((x - rocket.height(t_end)).abs() <= 1e-9 * x, "{x}");
        let (t1, x1, v1) = rocket.burnout();
        assert!((rocket.speed(t1 - 1e-9) - v1).abs() < 1e-4);
        assert!((rocket.height(t1) - x1).abs() < 1e-12 * x1);
    }

    #[test]
    fn checks() {
        let ok = Rocket::new(2.0, 1.0, 1.0, 1.0).unwrap();
        assert!(matches!(
            Rocket::new(1.0, 1.0, 1.0, 1.0),
            Err(RocketError::Burnout { .. })
        ));
        assert!(matches!(
            Rocket::new(2.0, 0.0, 1.0, 1.0),
            Err(RocketError::Mass { .. })
        ));
        assert!(ok.with_gravity(-1.0).is_err());
        assert!(ok.with_drag(Real::NAN).is_err());
        assert!(Rocket::new(2.0, 1.0, -1.0, 1.0).is_err());
        assert!(Rocket::new(2.0, 1.0, 1.0, 0.0).is_err());
        // a burn of 1e600 s: the run had failed with "the step size fell to inf at t = 1.1e308"
        let endless = Rocket::new(1e300, 1.0, 1e-300, 1.0).unwrap_err();
        assert!(matches!(endless, RocketError::BurnTime { .. }));
        assert_eq!(endless.input(), Some(Input::MassRate));
        assert!(
            endless.to_string().contains("1e300 kg / 1e-300 kg/s"),
            "{endless}"
        );
        assert_eq!(ok.apex(), None);
    }
}

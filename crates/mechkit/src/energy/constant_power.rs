//! Motion at constant power: an engine delivering power `P` to a body of mass `m` (no other
//! forces) along a straight line. From `d(½mv²)/dt = P`:
//! `v(t) = sqrt(v0² + 2Pt/m)`, `a = P/(m v)`, `x(t) = x0 + m (v(t)³ - v0³)/(3P)`;
//! from rest `v = sqrt(2Pt/m)`, `a = sqrt(P/(2mt))`, `x = (2/3) sqrt(2P/m) t^{3/2}`.
//! The force `P/v` is infinite at rest, which is why a step-by-step simulation cannot start
//! there and this closed form is the tool (a simulation from `v0 > 0` agrees with it: see the
//! tests).

use crate::Real;

/// Straight-line motion under a constant power.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ConstantPower {
    /// Power delivered (W), positive.
    pub power: Real,
    /// Mass (kg), positive.
    pub mass: Real,
    /// Speed at `t = 0` (m/s), non-negative.
    pub v0: Real,
    /// Position at `t = 0` (m).
    pub x0: Real,
}

impl ConstantPower {
    /// From rest at the origin. `None` unless power and mass are positive and finite.
    ///
    /// ```
    /// use mechkit::energy::ConstantPower;
    /// let bike = ConstantPower::from_rest(20e3, 200.0).unwrap();
    /// assert!((bike.speed(5.0) - 1000f64.sqrt()).abs() < 1e-12);
    /// assert!((bike.position(5.0) - 105.409_255_338_946).abs() < 1e-9);
    /// ```
    pub fn from_rest(power: Real, mass: Real) -> Option<Self> {
        Self::new(power, mass, 0.0, 0.0)
    }

    /// With a start speed `v0 ≥ 0` and position `x0`. `None` for non-positive power or mass or
    /// a negative or non-finite speed.
    pub fn new(power: Real, mass: Real, v0: Real, x0: Real) -> Option<Self> {
        let ok = power.is_finite()
            && power > 0.0
            && mass.is_finite()
            && mass > 0.0
            && v0.is_finite()
            && v0 >= 0.0
            && x0.is_finite();
        ok.then_some(Self {
            power,
            mass,
            v0,
            x0,
        })
    }

    /// `v(t)` for `t ≥ 0`.
    pub fn speed(&self, t: Real) -> Real {
        (self.v0 * self.v0 + 2.0 * self.power * t / self.mass).sqrt()
    }

    /// `a(t) = P/(m v)` (infinite at `t = 0` from rest).
    pub fn acceleration(&self, t: Real) -> Real {
        self.power / (self.mass * self.speed(t))
    }

    /// `x(t)`.
    pub fn position(&self, t: Real) -> Real {
        let v = self.speed(t);
        self.x0 + self.mass * (v.powi(3) - self.v0.powi(3)) / (3.0 * self.power)
    }

    /// The time to reach speed `v` (`None` if `v < v0`).
    pub fn time_to_speed(&self, v: Real) -> Option<Real> {
        (v >= self.v0).then(|| self.mass * (v * v - self.v0 * self.v0) / (2.0 * self.power))
    }

    /// The work done up to `t`: `P t`, equal to the kinetic energy gained.
    pub fn work(&self, t: Real) -> Real {
        self.power * t
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_course_formulas() {
        let m = ConstantPower::from_rest(20e3, 200.0).unwrap();
        let t: Real = 5.0;
        let (p, mass) = (20e3, 200.0);
        assert!((m.speed(t) - (2.0 * p * t / mass).sqrt()).abs() < 1e-12);
        assert!((m.acceleration(t) - (p / (2.0 * mass * t)).sqrt()).abs() < 1e-12);
        let x = 2.0 / 3.0 * (2.0 * p / mass).sqrt() * t.powf(1.5);
        assert!((m.position(t) - x).abs() < 1e-10);
        let k = 0.5 * mass * m.speed(t).powi(2);
        assert!((m.work(t) - k).abs() < 1e-9);
        assert!((m.time_to_speed(m.speed(t)).unwrap() - t).abs() < 1e-12);
        assert!(ConstantPower::from_rest(-1.0, 1.0).is_none());
    }
}

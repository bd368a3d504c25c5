//! Reference problems with exact solutions, for verifying steppers: each returns the system
//! and its exact solution.

#![allow(clippy::excessive_precision)] // coefficients as published

use super::system::SecondOrderSystem;
use crate::Real;

/// Harmonic oscillator `x'' = -ω² x` from `x = 1`, `v = 0`: exact `x = cos ωt`,
/// `v = -ω sin ωt`, energy `(v² + ω² x²)/2` conserved.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Oscillator {
    /// Angular frequency ω (1/s).
    pub omega: Real,
}

impl Oscillator {
    /// Exact position and velocity at time `t`.
    pub fn exact(&self, t: Real) -> (Real, Real) {
        let w = self.omega;
        ((w * t).cos(), -w * (w * t).sin())
    }

    /// Energy per unit mass of a state.
    pub fn energy(&self, x: Real, v: Real) -> Real {
        0.5 * (v * v + self.omega * self.omega * x * x)
    }
}

impl SecondOrderSystem for Oscillator {
    fn dof(&self) -> usize {
        1
    }

    fn accel_into(&self, _t: Real, q: &[Real], _v: &[Real], a: &mut [Real]) {
        a[0] = -self.omega * self.omega * q[0];
    }

    fn velocity_dependent(&self) -> bool {
        false
    }
}

/// Exponential decay `y' = -λ y` from `y = 1`: exact `y = e^{-λt}` (a first-order system).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Decay {
    /// Rate λ (1/s).
    pub lambda: Real,
}

impl Decay {
    /// Exact solution at `t`.
    pub fn exact(&self, t: Real) -> Real {
        (-self.lambda * t).exp()
    }
}

impl super::system::OdeSystem for Decay {
    fn dim(&self) -> usize {
        1
    }

    fn rhs_into(&self, _t: Real, y: &[Real], dydt: &mut [Real]) {
        dydt[0] = -self.lambda * y[0];
    }
}

/// A Kepler orbit (`r'' = -GM r/|r|³` in the plane) with `GM = 1` and semi-major axis 1,
/// started at perihelion with eccentricity `e`; state `[x, y, vx, vy]`. The period is 2π and
/// the exact solution follows from Kepler's equation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Kepler {
    /// Eccentricity (0 ≤ e < 1).
    pub e: Real,
}

impl Kepler {
    /// The initial state at perihelion: `(1 - e, 0)`, velocity `(0, sqrt((1 + e)/(1 - e)))`.
    pub fn initial(&self) -> [Real; 4] {
        let e = self.e;
        [1.0 - e, 0.0, 0.0, ((1.0 + e) / (1.0 - e)).sqrt()]
    }

    /// The exact state at time `t`.
    pub fn exact(&self, t: Real) -> [Real; 4] {
        let e = self.e;
        // mean anomaly → eccentric anomaly by Newton's method
        let m = t.rem_euclid(2.0 * std::f64::consts::PI);
        let mut big_e = if e > 0.8 { std::f64::consts::PI } else { m };
        for _ in 0..50 {
            let d = (big_e - e * big_e.sin() - m) / (1.0 - e * big_e.cos());
            big_e -= d;
            if d.abs() < 1e-16 {
                break;
            }
        }
        let (s, c) = big_e.sin_cos();
        let b = (1.0 - e * e).sqrt();
        let edot = 1.0 / (1.0 - e * c);
        [c - e, b * s, -s * edot, b * c * edot]
    }

    /// Energy per unit mass (exactly -1/2 on the orbit).
    pub fn energy(&self, y: &[Real]) -> Real {
        0.5 * (y[2] * y[2] + y[3] * y[3]) - 1.0 / (y[0] * y[0] + y[1] * y[1]).sqrt()
    }
}

impl SecondOrderSystem for Kepler {
    fn dof(&self) -> usize {
        2
    }

    fn accel_into(&self, _t: Real, q: &[Real], _v: &[Real], a: &mut [Real]) {
        let r2 = q[0] * q[0] + q[1] * q[1];
        let s = -1.0 / (r2 * r2.sqrt());
        a[0] = s * q[0];
        a[1] = s * q[1];
    }

    fn velocity_dependent(&self) -> bool {
        false
    }
}

/// A plane pendulum `θ'' = -ω₀² sin θ` released from rest at `θ₀`; state `[θ, θ']`. Its energy
/// per unit `m L²` is conserved and its period is `4K(sin(θ₀/2))/ω₀`, computed here with the
/// arithmetic-geometric mean.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pendulum {
    /// Small-oscillation angular frequency `sqrt(g/L)` (1/s).
    pub omega0: Real,
    /// Release angle (rad, below π).
    pub theta0: Real,
}

impl Pendulum {
    /// Energy per unit `m L²`: `θ'²/2 - ω₀² cos θ`.
    pub fn energy(&self, y: &[Real]) -> Real {
        0.5 * y[1] * y[1] - self.omega0 * self.omega0 * y[0].cos()
    }

    /// The exact period `2π / (ω₀ AGM(1, cos(θ₀/2)))`.
    pub fn period(&self) -> Real {
        let agm = crate::elliptic::agm(1.0, (0.5 * self.theta0).cos());
        2.0 * std::f64::consts::PI / (self.omega0 * agm)
    }

    /// The initial state.
    pub fn initial(&self) -> [Real; 2] {
        [self.theta0, 0.0]
    }
}

impl SecondOrderSystem for Pendulum {
    fn dof(&self) -> usize {
        1
    }

    fn accel_into(&self, _t: Real, q: &[Real], _v: &[Real], a: &mut [Real]) {
        a[0] = -self.omega0 * self.omega0 * q[0].sin();
    }

    fn velocity_dependent(&self) -> bool {
        false
    }
}

/// The Arenstorf orbit of the restricted three-body problem (Hairer, Nørsett & Wanner,
/// *Solving ODEs I*, Sec. II.0): a periodic satellite orbit around the Earth and Moon whose
/// speed varies by a factor of ~60, the classic test of step-size control. State
/// `[x, y, vx, vy]` in the rotating frame; the orbit closes after [`Arenstorf::PERIOD`].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Arenstorf;

impl Arenstorf {
    /// Moon/(Earth + Moon) mass ratio.
    pub const MU: Real = 0.012_277_471;
    /// The period.
    pub const PERIOD: Real = 17.065_216_560_157_962_558_891_720_624_9;

    /// The initial state (which is also the state after each period).
    pub fn initial(&self) -> [Real; 4] {
        [0.994, 0.0, 0.0, -2.001_585_106_379_082_522_405_378_622_24]
    }
}

impl SecondOrderSystem for Arenstorf {
    fn dof(&self) -> usize {
        2
    }

    fn accel_into(&self, _t: Real, q: &[Real], v: &[Real], a: &mut [Real]) {
        let (mu, nu) = (Self::MU, 1.0 - Self::MU);
        let d1 = ((q[0] + mu).powi(2) + q[1] * q[1]).powf(1.5);
        let d2 = ((q[0] - nu).powi(2) + q[1] * q[1]).powf(1.5);
        a[0] = q[0] + 2.0 * v[1] - nu * (q[0] + mu) / d1 - mu * (q[0] - nu) / d2;
        a[1] = q[1] - 2.0 * v[0] - nu * q[1] / d1 - mu * q[1] / d2;
    }
}

//! The course's spring-block model of stick-slip (the "earthquake" model): a block on a
//! surface moving at speed `u` (a belt; `u = 0` is a fixed floor), pulled by a spring whose
//! far end (the anchor) moves at speed `w` (`w = 0`: a fixed wall). Its parameters, their
//! checks, and the closed forms of each regime.

use super::coulomb::Coulomb;
use super::error::{FrictionError, finite, gravity, positive};
use crate::Real;
use crate::rigid::Input;

/// A block of mass `m` on a flat surface moving at `belt_speed`, pulled by a spring of
/// stiffness `k` attached to an anchor at `a(t) = anchor_speed · t`; the block starts at
/// `x0` (the spring's extension then; the rest length is absorbed in `x`) with velocity `v0`.
///
/// Forces along the surface: the spring `F_s = −k (x − a(t))` and friction `f`. While the
/// block sticks to the surface (`v = u`, the surface moving steadily) `f = −F_s`, which holds
/// while `|F_s| ≤ μs N` (`N = m g`). While it slips with `s = sign(v − u)`, `f = −s μd N` and
/// `m ẍ = F_s + f`: a harmonic oscillator of angular frequency `Ω = √(k/m)` about the
/// extension `−s μd N/k` ([`SpringBlock::exact_slip`]).
///
/// # Example
/// ```
/// use approx::assert_relative_eq;
/// use mechkit::rigid::friction::{Coulomb, SpringBlock};
/// // a block at rest, the anchor pulled at 1 cm/s: it sticks until k w t = μs m g
/// let block = SpringBlock::new(1.0, 100.0, Coulomb::new(0.6, 0.4)?)?.driven(0.01);
/// let t_stick = block.exact_stick_end(0.0, 0.0).unwrap();
/// assert_relative_eq!(t_stick, 0.6 * 9.81 / (100.0 * 0.01));
/// # Ok::<(), mechkit::rigid::friction::FrictionError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpringBlock {
    /// Mass of the block (kg).
    pub mass: Real,
    /// Spring constant (N/m).
    pub k: Real,
    /// Gravity (m/s²), pressing the block into the surface: `N = m g`. 9.81 by default.
    pub g: Real,
    /// Friction between block and surface.
    pub friction: Coulomb,
    /// Speed of the surface (m/s); 0 for a fixed floor.
    pub belt_speed: Real,
    /// Speed of the spring's anchor (m/s); 0 for a fixed wall.
    pub anchor_speed: Real,
    /// Position of the block at `t = 0` (m), the anchor being at 0: the spring's extension.
    pub x0: Real,
    /// Velocity of the block at `t = 0` (m/s).
    pub v0: Real,
    /// The most stick and slip phases a simulation may have (a guard against switches that
    /// accumulate); 100 000 by default.
    pub max_phases: usize,
}

/// The state at the start of a regime: time, position, velocity.
pub type PhaseStart = (Real, Real, Real);

impl SpringBlock {
    /// A block of `mass` (kg) on a fixed floor, on a spring `k` (N/m) to a fixed wall, at rest
    /// with the spring relaxed, in standard gravity. Checked.
    pub fn new(mass: Real, k: Real, friction: Coulomb) -> Result<Self, FrictionError> {
        let block = Self {
            mass,
            k,
            g: 9.81,
            friction,
            belt_speed: 0.0,
            anchor_speed: 0.0,
            x0: 0.0,
            v0: 0.0,
            max_phases: 100_000,
        };
        block.validate()?;
        Ok(block)
    }

    /// The same block on a belt moving at `u` (m/s).
    #[must_use]
    pub fn on_belt(self, u: Real) -> Self {
        Self {
            belt_speed: u,
            ..self
        }
    }

    /// The same block with the spring's anchor moving at `w` (m/s).
    #[must_use]
    pub fn driven(self, w: Real) -> Self {
        Self {
            anchor_speed: w,
            ..self
        }
    }

    /// The same block starting at `x0` (m) with velocity `v0` (m/s).
    #[must_use]
    pub fn starting_at(self, x0: Real, v0: Real) -> Self {
        Self { x0, v0, ..self }
    }

    /// The same block in gravity `g` (m/s²).
    #[must_use]
    pub fn with_gravity(self, g: Real) -> Self {
        Self { g, ..self }
    }

    /// Checks every field.
    pub fn validate(&self) -> Result<(), FrictionError> {
        positive((Input::Mass, "the mass m (kg)"), self.mass)?;
        positive(
            (Input::SpringConstant, "the spring constant k (N/m)"),
            self.k,
        )?;
        gravity(self.g)?;
        self.friction.validate()?;
        finite((Input::BeltSpeed, "the belt speed (m/s)"), self.belt_speed)?;
        finite(
            (Input::AnchorSpeed, "the anchor speed (m/s)"),
            self.anchor_speed,
        )?;
        finite((Input::StartPosition, "the start position x0 (m)"), self.x0)?;
        finite((Input::StartSpeed, "the start velocity v0 (m/s)"), self.v0)?;
        Ok(())
    }

    /// The normal force `N = m g` (N).
    pub fn normal(&self) -> Real {
        self.mass * self.g
    }

    /// The angular frequency of the spring and block, `Ω = √(k/m)` (rad/s).
    pub fn omega(&self) -> Real {
        (self.k / self.mass).sqrt()
    }

    /// The anchor's position at `t`, `a(t) = w t` (m).
    pub fn anchor(&self, t: Real) -> Real {
        self.anchor_speed * t
    }

    /// The spring's force on the block, `F_s = −k (x − a(t))` (N).
    pub fn spring_force(&self, t: Real, x: Real) -> Real {
        -self.k * (x - self.anchor(t))
    }

    /// The spring's energy `k (x − a(t))²/2` (J).
    pub fn spring_energy(&self, t: Real, x: Real) -> Real {
        let y = x - self.anchor(t);
        0.5 * self.k * y * y
    }

    /// The bound on the spring force while sticking, `μs N` (with μd if that is larger).
    pub fn stick_bound(&self) -> Real {
        self.friction.max_static(self.normal())
    }

    /// The end of a stick that starts at `(t0, x0)`: the time when `|F_s|` reaches `μs N`.
    /// Sticking, the extension changes at the constant rate `u − w`, so the end is where a
    /// straight line meets `±μs N/k`. `None` if the spring force never changes (`u = w`) or
    /// the block cannot stick there.
    pub fn exact_stick_end(&self, t0: Real, x0: Real) -> Option<Real> {
        let rate = self.belt_speed - self.anchor_speed;
        let y0 = x0 - self.anchor(t0);
        let bound = self.stick_bound() / self.k;
        if rate == 0.0 || y0.abs() > bound {
            return None;
        }
        Some(t0 + (bound * rate.signum() - y0) / rate)
    }

    /// The exact motion while slipping in direction `s = ±1` (the sign of `v − u`) from
    /// `start = (t0, x0, v0)`: `(x, v)` at time `t`. With the extension `y = x − w t`,
    /// `ÿ = −Ω² (y − y_eq)`, `y_eq = −s μd N/k`, so
    /// `y = y_eq + (y0 − y_eq) cos Ωτ + ((v0 − w)/Ω) sin Ωτ`, `τ = t − t0`.
    pub fn exact_slip(&self, start: PhaseStart, direction: Real, t: Real) -> (Real, Real) {
        let (t0, x0, v0) = start;
        let om = self.omega();
        let w = self.anchor_speed;
        let y_eq = -direction * self.friction.dynamic(self.normal()) / self.k;
        let d = x0 - self.anchor(t0) - y_eq;
        let (s, c) = (om * (t - t0)).sin_cos();
        let y = y_eq + d * c + (v0 - w) / om * s;
        let ydot = -d * om * s + (v0 - w) * c;
        (y + self.anchor(t), ydot + w)
    }

    /// The end of a slip in direction `s` from `start`: the first time after `t0` at which
    /// the velocity relative to the surface, `v − u = A cos Ωτ + B sin Ωτ + (w − u)` with
    /// `A = v0 − w`, `B = −Ω (y0 − y_eq)`, is zero. `None` if it never is (the block
    /// oscillates while always slower, or always faster, than the surface).
    pub fn exact_slip_end(&self, start: PhaseStart, direction: Real) -> Option<Real> {
        let (t0, x0, v0) = start;
        let om = self.omega();
        let (u, w) = (self.belt_speed, self.anchor_speed);
        let y_eq = -direction * self.friction.dynamic(self.normal()) / self.k;
        let a = v0 - w;
        let b = -om * (x0 - self.anchor(t0) - y_eq);
        let c = w - u;
        let r = a.hypot(b);
        if r == 0.0 || c.abs() > r {
            return None;
        }
        // R cos(θ − φ) = −C, θ = Ωτ
        let phi = b.atan2(a);
        let delta = (-c / r).clamp(-1.0, 1.0).acos();
        let period = std::f64::consts::TAU;
        // the start itself is a root when it begins at v = u: skip roots within rounding of 0
        let tiny = 1e-9;
        let first = |theta: Real| {
            let mut th = theta.rem_euclid(period);
            if th < tiny {
                th += period;
            }
            th
        };
        // the relative velocity must arrive at zero from the side of `direction`
        let theta = [first(phi + delta), first(phi - delta)]
            .into_iter()
            .filter(|&th| {
                let slope = -a * th.sin() + b * th.cos();
                slope * direction <= 0.0
            })
            .fold(Real::INFINITY, Real::min);
        theta.is_finite().then(|| t0 + theta / om)
    }
}

//! A rolling body on an incline with Coulomb friction: the set-up, its checks, and the
//! closed forms of the slipping phase, of the start of rolling, and of rolling itself.

use super::body::RollingBody;
use super::error::RollingError;
use crate::Real;
use crate::rigid::Input;
use crate::rigid::friction::Coulomb;

/// A [`RollingBody`] on a plane inclined at `angle` (0: a flat floor) with Coulomb friction,
/// launched with speed `v0` and spin `omega0`.
///
/// Conventions: `x` is measured along the incline, down the slope positive (on a flat floor,
/// the direction of `x`); `ω` is positive for the forward spin of rolling down the slope, so
/// rolling without slipping is `v = ω R`, and `ω0 < 0` with `v0 > 0` is backspin. The contact
/// point slides at `v_c = v − ω R` (down the slope positive). The friction `f` acts on the
/// body at the contact point along the slope:
///
/// - slipping: `f = −μd N sign(v_c)`, `m v̇ = m g sin α + f`, `I ω̇ = −f R`, so
///   `v̇_c = g sin α − sign(v_c) μd g cos α (1 + k)/k` is constant;
/// - rolling (`v_c = 0`): `f = −m g sin α · k/(1 + k)`, `a = g sin α/(1 + k)`, which lasts
///   while `|f| ≤ μs N`, i.e. `|tan α| ≤ μs (1 + k)/k`.
///
/// # Example
/// ```
/// use approx::assert_relative_eq;
/// use mechkit::rigid::friction::Coulomb;
/// use mechkit::rigid::rolling::{RollingBody, RollingMotion};
/// // a ball thrown along a floor with backspin: rolling starts when v = ω R, at the speed
/// // conserving the angular momentum about the contact point, (v0 + k R ω0)/(1 + k)
/// let ball = RollingBody::sphere(0.45, 0.11)?;
/// let motion = RollingMotion::new(ball, 0.0, Coulomb::single(0.3)?).launched(2.0, -30.0);
/// let (t, v) = motion.roll_start().unwrap();
/// assert_relative_eq!(v, (2.0 - 0.4 * 0.11 * 30.0) / 1.4, max_relative = 1e-14);
/// assert_relative_eq!(t, (2.0 + 0.11 * 30.0) / (0.3 * 9.81 * 3.5), max_relative = 1e-14);
/// # Ok::<(), mechkit::rigid::rolling::RollingError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollingMotion {
    /// The body.
    pub body: RollingBody,
    /// Incline angle α (rad), in −π/2 … π/2.
    pub angle: Real,
    /// Gravity (m/s²); 9.81 by default.
    pub g: Real,
    /// Friction between the body and the incline.
    pub friction: Coulomb,
    /// Start position along the incline (m).
    pub x0: Real,
    /// Start speed along the incline (m/s).
    pub v0: Real,
    /// Start angular velocity (rad/s), positive for forward spin.
    pub omega0: Real,
}

/// The sign of `x`, or 0.
fn sign(x: Real) -> Real {
    if x == 0.0 { 0.0 } else { x.signum() }
}

impl RollingMotion {
    /// The body at rest at `x = 0` on an incline at `angle` (rad), standard gravity.
    pub fn new(body: RollingBody, angle: Real, friction: Coulomb) -> Self {
        Self {
            body,
            angle,
            g: 9.81,
            friction,
            x0: 0.0,
            v0: 0.0,
            omega0: 0.0,
        }
    }

    /// The same set-up launched with speed `v0` (m/s) and spin `omega0` (rad/s).
    #[must_use]
    pub fn launched(self, v0: Real, omega0: Real) -> Self {
        Self { v0, omega0, ..self }
    }

    /// The same set-up in gravity `g` (m/s²).
    #[must_use]
    pub fn with_gravity(self, g: Real) -> Self {
        Self { g, ..self }
    }

    /// Checks every field.
    pub fn validate(&self) -> Result<(), RollingError> {
        self.body.validate()?;
        self.friction.validate()?;
        if !(self.angle.is_finite() && self.angle.abs() <= std::f64::consts::FRAC_PI_2) {
            return Err(RollingError::Angle {
                degrees: self.angle.to_degrees(),
            });
        }
        if !(self.g.is_finite() && self.g >= 0.0) {
            return Err(RollingError::Gravity { value: self.g });
        }
        for (input, what, value) in [
            (Input::StartPosition, "the start position x0 (m)", self.x0),
            (Input::StartSpeed, "the start speed v0 (m/s)", self.v0),
            (Input::StartSpin, "the start spin ω0 (rad/s)", self.omega0),
        ] {
            if !value.is_finite() {
                return Err(RollingError::Invalid {
                    input,
                    what,
                    value,
                    expected: "a finite number",
                });
            }
        }
        Ok(())
    }

    /// The normal force `N = m g cos α` (N).
    pub fn normal(&self) -> Real {
        self.body.mass * self.g * self.angle.cos()
    }

    /// The slip velocity of the contact point, `v_c = v − ω R` (m/s).
    pub fn slip_velocity(&self, v: Real, omega: Real) -> Real {
        v - omega * self.body.radius
    }

    /// The friction while rolling, `f = −m g sin α · k/(1 + k)` (N, down the slope positive).
    pub fn rolling_friction(&self) -> Real {
        let k = self.body.k;
        -self.body.mass * self.g * self.angle.sin() * k / (1.0 + k)
    }

    /// The acceleration while rolling, `g sin α/(1 + k)` (m/s²).
    pub fn rolling_acceleration(&self) -> Real {
        self.g * self.angle.sin() / (1.0 + self.body.k)
    }

    /// Whether rolling can last: the friction it needs is within the static bound,
    /// `|f| ≤ μs N` (`|tan α| ≤ μs (1 + k)/k`).
    pub fn can_roll(&self) -> bool {
        self.rolling_friction().abs() <= self.friction.max_static(self.normal())
    }

    /// The steepest slope on which the body can roll without slipping,
    /// `atan(μs (1 + k)/k)` (rad).
    pub fn steepest_rolling_angle(&self) -> Real {
        let k = self.body.k;
        (self.friction.static_bound() * (1.0 + k) / k).atan()
    }

    /// The friction while slipping with `v_c` of sign `direction`, `−direction μd N` (N).
    pub fn slip_friction(&self, direction: Real) -> Real {
        -direction * self.friction.dynamic(self.normal())
    }

    /// The accelerations `(v̇, ω̇)` while slipping in `direction`:
    /// `g sin α + f/m` and `−f R/I`.
    pub fn slip_accelerations(&self, direction: Real) -> (Real, Real) {
        let f = self.slip_friction(direction);
        let b = &self.body;
        (
            self.g * self.angle.sin() + f / b.mass,
            -f * b.radius / b.moment_of_inertia(),
        )
    }

    /// The direction the contact point slides in when rolling is not possible from
    /// `v_c = 0`: down the slope (`sign(sin α)`).
    pub fn breakaway_direction(&self) -> Real {
        sign(self.angle.sin())
    }

    /// The closed form of the start of rolling from the launch: `(t, v)` with
    /// `t = −v_c0/v̇_c` (the slip velocity changes at the constant rate `v̇_c` while
    /// slipping) and `v = v0 + v̇ t`. `(0, v0)` if the body starts rolling; `None` if it never
    /// rolls (the slope is too steep for the friction).
    pub fn roll_start(&self) -> Option<(Real, Real)> {
        let vc0 = self.slip_velocity(self.v0, self.omega0);
        if vc0 == 0.0 && self.can_roll() {
            return Some((0.0, self.v0));
        }
        let s = if vc0 == 0.0 {
            self.breakaway_direction()
        } else {
            sign(vc0)
        };
        let (a_v, a_w) = self.slip_accelerations(s);
        let rate = a_v - a_w * self.body.radius;
        if vc0 == 0.0 || rate * s >= 0.0 {
            return None;
        }
        let t = -vc0 / rate;
        // rolling begins there only if it can last; otherwise it slips on the other way
        self.can_roll().then_some((t, self.v0 + a_v * t))
    }

    /// On a flat floor (`α = 0`), the rolling speed reached from any launch:
    /// `(v0 + k R ω0)/(1 + k)`, since friction passes through the contact point and the
    /// angular momentum about it, `m R (v + k R ω)`, is conserved.
    pub fn flat_floor_rolling_speed(&self) -> Real {
        let b = &self.body;
        (self.v0 + b.k * b.radius * self.omega0) / (1.0 + b.k)
    }

    /// The kinetic energies `(½ m v², ½ I ω²)` (J).
    pub fn kinetic(&self, v: Real, omega: Real) -> (Real, Real) {
        let b = &self.body;
        (
            0.5 * b.mass * v * v,
            0.5 * b.moment_of_inertia() * omega * omega,
        )
    }

    /// The potential energy `−m g x sin α` (J), zero at `x = 0`.
    pub fn potential(&self, x: Real) -> Real {
        -self.body.mass * self.g * x * self.angle.sin()
    }
}

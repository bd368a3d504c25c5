//! Coulomb friction: the static bound `|f| ≤ μs N` while the surfaces stick, the dynamic
//! force `f = −μd N sign(v_rel)` while they slip; and the contact on a flat or inclined
//! surface (normal force, marginal angle, whether a block at rest slides).

use std::fmt;

use super::error::{FrictionError, finite, gravity, positive};
use crate::Real;
use crate::rigid::Input;

/// Coulomb friction with a static and a dynamic (kinetic) coefficient.
///
/// # Example
/// ```
/// use approx::assert_relative_eq;
/// use mechkit::rigid::friction::Coulomb;
/// let c = Coulomb::new(0.5, 0.3)?;
/// assert_relative_eq!(c.marginal_angle(), 0.5f64.atan());
/// // at rest against an applied 8 N with N = 20 N: static friction balances it
/// assert_eq!(c.stick_force(8.0, 20.0), Some(-8.0));
/// // 12 N exceeds μs N = 10 N: no sticking; sliding forward, friction is −μd N
/// assert_eq!(c.stick_force(12.0, 20.0), None);
/// assert_relative_eq!(c.slip_force(1.5, 20.0), -6.0);
/// assert!(c.warning().is_none());
/// # Ok::<(), mechkit::rigid::friction::FrictionError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Coulomb {
    /// Static coefficient μs: sticking holds while the needed friction is at most μs N.
    pub mu_static: Real,
    /// Dynamic (kinetic) coefficient μd: the friction while slipping is μd N.
    pub mu_dynamic: Real,
}

/// `μs < μd`: allowed, but outside what the course's models assume (μs ≥ μd).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrictionWarning {
    /// μs.
    pub mu_static: Real,
    /// μd.
    pub mu_dynamic: Real,
}

impl fmt::Display for FrictionWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "μs = {} is below μd = {}; the models assume μs ≥ μd. A body at rest cannot start to slide while the force on it is below μd N (sliding friction would stop it at once), so μd is used as the static bound too",
            crate::error::short(self.mu_static),
            crate::error::short(self.mu_dynamic)
        )
    }
}

impl Coulomb {
    /// Checked: both coefficients finite and `≥ 0`. `μs < μd` is accepted; see
    /// [`Coulomb::warning`].
    pub fn new(mu_static: Real, mu_dynamic: Real) -> Result<Self, FrictionError> {
        for (which, value) in [("static", mu_static), ("dynamic", mu_dynamic)] {
            if !(value.is_finite() && value >= 0.0) {
                return Err(FrictionError::Coefficient { which, value });
            }
        }
        Ok(Self {
            mu_static,
            mu_dynamic,
        })
    }

    /// One coefficient for sticking and slipping, `μs = μd = mu`.
    pub fn single(mu: Real) -> Result<Self, FrictionError> {
        Self::new(mu, mu)
    }

    /// No friction.
    pub fn frictionless() -> Self {
        Self {
            mu_static: 0.0,
            mu_dynamic: 0.0,
        }
    }

    /// Checks the coefficients again (the fields are public).
    pub fn validate(&self) -> Result<(), FrictionError> {
        Self::new(self.mu_static, self.mu_dynamic).map(|_| ())
    }

    /// A warning when `μs < μd`.
    pub fn warning(&self) -> Option<FrictionWarning> {
        (self.mu_static < self.mu_dynamic).then_some(FrictionWarning {
            mu_static: self.mu_static,
            mu_dynamic: self.mu_dynamic,
        })
    }

    /// The coefficient that bounds sticking: `max(μs, μd)`. Below μd N a body at rest cannot
    /// start sliding (the sliding friction would exceed the force and stop it at once), so
    /// with `μs < μd` the bound is μd; otherwise it is μs.
    pub fn static_bound(&self) -> Real {
        self.mu_static.max(self.mu_dynamic)
    }

    /// The largest static friction, `μs N` (with the bound of [`Coulomb::static_bound`]).
    pub fn max_static(&self, normal: Real) -> Real {
        self.static_bound() * normal
    }

    /// The magnitude of the sliding friction, `μd N`.
    pub fn dynamic(&self, normal: Real) -> Real {
        self.mu_dynamic * normal
    }

    /// The marginal angle: a block at rest on an incline starts to slide above
    /// `α = atan μs` (rad).
    pub fn marginal_angle(&self) -> Real {
        self.static_bound().atan()
    }

    /// The static friction that keeps a body at rest against the tangential force `applied`
    /// (everything but friction, along the surface): `−applied`, or `None` when that exceeds
    /// the bound `μs N`, so the body slides.
    pub fn stick_force(&self, applied: Real, normal: Real) -> Option<Real> {
        (applied.abs() <= self.max_static(normal)).then_some(-applied)
    }

    /// The sliding friction `−μd N sign(v_rel)` for the velocity `v_rel` of the body
    /// relative to the surface (0 at `v_rel = 0`, where the regime is sticking).
    pub fn slip_force(&self, relative_velocity: Real, normal: Real) -> Real {
        if relative_velocity == 0.0 {
            0.0
        } else {
            -self.dynamic(normal) * relative_velocity.signum()
        }
    }
}

/// A block on a flat (α = 0) or inclined surface with Coulomb friction, the incline rising
/// to one side; positions along the surface are measured down the slope.
///
/// # Example
/// ```
/// use approx::assert_relative_eq;
/// use mechkit::rigid::friction::{Coulomb, Incline};
/// let block = Incline::new(2.0, 20f64.to_radians(), Coulomb::new(0.5, 0.3)?)?;
/// let at_rest = block.at_rest()?;
/// assert_relative_eq!(at_rest.normal, 2.0 * 9.81 * 20f64.to_radians().cos());
/// assert!(!at_rest.slides); // tan 20° = 0.36 < μs = 0.5
/// assert_relative_eq!(at_rest.friction, -2.0 * 9.81 * 20f64.to_radians().sin());
/// let steep = Incline::new(2.0, 30f64.to_radians(), Coulomb::new(0.5, 0.3)?)?.at_rest()?;
/// assert!(steep.slides); // tan 30° = 0.577 > 0.5
/// let (s, c) = 30f64.to_radians().sin_cos();
/// assert_relative_eq!(steep.acceleration, 9.81 * (s - 0.3 * c));
/// # Ok::<(), mechkit::rigid::friction::FrictionError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Incline {
    /// Mass of the block (kg).
    pub mass: Real,
    /// Incline angle α (rad), in −π/2 … π/2; 0 is a flat floor.
    pub angle: Real,
    /// Gravity g ≥ 0 (m/s²); 9.81 by default.
    pub g: Real,
    /// The friction between block and surface.
    pub friction: Coulomb,
    /// Other loads pressing the block into the surface (N); negative pulls it away.
    pub extra_normal: Real,
    /// Other tangential loads on the block, down the slope positive (N): a push or a pull.
    pub extra_along: Real,
}

/// What happens to a block released at rest ([`Incline::at_rest`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InclineReport {
    /// Normal force `N = m g cos α + extra normal load` (N).
    pub normal: Real,
    /// The tangential force without friction, `m g sin α + extra along` (N, down the slope
    /// positive).
    pub driving: Real,
    /// The largest static friction μs N (N).
    pub max_static: Real,
    /// The sliding friction μd N (N).
    pub dynamic: Real,
    /// The marginal angle atan μs (rad): the steepest incline on which a block stays at rest
    /// without other loads.
    pub marginal_angle: Real,
    /// Whether the block slides: `|driving| > μs N`.
    pub slides: bool,
    /// The friction force on the block (N, down the slope positive): `−driving` at rest,
    /// `−μd N sign(driving)` sliding.
    pub friction: Real,
    /// The acceleration down the slope (m/s²): 0 at rest, `(driving + friction)/m` sliding.
    pub acceleration: Real,
}

impl Incline {
    /// A block of `mass` on an incline at `angle` (rad) in standard gravity (9.81 m/s²), no
    /// other loads. Checked.
    pub fn new(mass: Real, angle: Real, friction: Coulomb) -> Result<Self, FrictionError> {
        let incline = Self {
            mass,
            angle,
            g: 9.81,
            friction,
            extra_normal: 0.0,
            extra_along: 0.0,
        };
        incline.validate()?;
        Ok(incline)
    }

    /// The same block in gravity `g`.
    #[must_use]
    pub fn with_gravity(self, g: Real) -> Self {
        Self { g, ..self }
    }

    /// The same block with an extra load pressing it into the surface (N) and one along the
    /// surface, down the slope positive (N).
    #[must_use]
    pub fn with_loads(self, normal: Real, along: Real) -> Self {
        Self {
            extra_normal: normal,
            extra_along: along,
            ..self
        }
    }

    /// Checks every field.
    pub fn validate(&self) -> Result<(), FrictionError> {
        positive((Input::Mass, "the mass m (kg)"), self.mass)?;
        gravity(self.g)?;
        self.friction.validate()?;
        if !(self.angle.is_finite() && self.angle.abs() <= std::f64::consts::FRAC_PI_2) {
            return Err(FrictionError::Angle {
                degrees: self.angle.to_degrees(),
            });
        }
        finite(
            (Input::NormalLoad, "the extra normal load (N)"),
            self.extra_normal,
        )?;
        finite(
            (Input::Push, "the extra load along the surface (N)"),
            self.extra_along,
        )?;
        Ok(())
    }

    /// The normal force `N = m g cos α + extra` (N); an error if the loads pull the block off
    /// the surface (`N < 0`).
    pub fn normal_force(&self) -> Result<Real, FrictionError> {
        let normal = self.mass * self.g * self.angle.cos() + self.extra_normal;
        if normal < 0.0 {
            return Err(FrictionError::NoContact { normal });
        }
        Ok(normal)
    }

    /// A block released at rest: does it slide, with which friction and acceleration.
    pub fn at_rest(&self) -> Result<InclineReport, FrictionError> {
        self.validate()?;
        let normal = self.normal_force()?;
        let driving = self.mass * self.g * self.angle.sin() + self.extra_along;
        let (slides, friction) = match self.friction.stick_force(driving, normal) {
            Some(f) => (false, f),
            None => (true, -self.friction.dynamic(normal) * driving.signum()),
        };
        Ok(InclineReport {
            normal,
            driving,
            max_static: self.friction.max_static(normal),
            dynamic: self.friction.dynamic(normal),
            marginal_angle: self.friction.marginal_angle(),
            slides,
            friction,
            acceleration: if slides {
                (driving + friction) / self.mass
            } else {
                0.0
            },
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn coefficients_are_checked() {
        assert!(matches!(
            Coulomb::new(-0.1, 0.1),
            Err(FrictionError::Coefficient {
                which: "static",
                ..
            })
        ));
        assert!(Coulomb::new(0.1, Real::NAN).is_err());
        let odd = Coulomb::new(0.2, 0.4).unwrap();
        assert_eq!(odd.static_bound(), 0.4);
        let text = odd.warning().unwrap().to_string();
        assert!(text.contains("μs = 0.2 is below μd = 0.4"), "{text}");
    }

    #[test]
    fn the_marginal_angle_separates_rest_from_sliding() {
        let c = Coulomb::new(0.5, 0.3).unwrap();
        let alpha = c.marginal_angle();
        let below = Incline::new(1.0, alpha - 1e-9, c)
            .unwrap()
            .at_rest()
            .unwrap();
        let above = Incline::new(1.0, alpha + 1e-9, c)
            .unwrap()
            .at_rest()
            .unwrap();
        assert!(!below.slides && above.slides);
        assert_eq!(below.acceleration, 0.0);
        // just above the marginal angle the block accelerates at g (sin α − μd cos α) > 0
        let (s, co) = (alpha + 1e-9).sin_cos();
        assert!((above.acceleration - 9.81 * (s - 0.3 * co)).abs() < 1e-14);
        assert!(matches!(
            Incline::new(1.0, 0.0, c)
                .unwrap()
                .with_loads(-20.0, 0.0)
                .at_rest(),
            Err(FrictionError::NoContact { .. })
        ));
        assert!(Incline::new(1.0, 2.0, c).is_err());
    }
}

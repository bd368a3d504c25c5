//! Angular kinematics and circular motion.
//!
//! - [`AngularMotion`]: θ(t) given as a formula, with ω = dθ/dt and α = d²θ/dt² derived
//!   symbolically; or ω(t) given, with θ = θ₀ + ∫₀ᵗ ω dt by the symbolic rule table (adaptive
//!   quadrature where it has no rule) and α = dω/dt. Every value at a time comes with an
//!   independent numerical cross-check by Ridders' extrapolation of central differences.
//! - [`UniformAngularAcceleration`]: ω₁ = ω₀ + α t, Δθ = (ω₀ + ω₁) t / 2, in revolutions.
//! - [`CircularMotion`]: a point at radius R turning at ω (from v = ωR or from the period
//!   T = 2π/ω), the centripetal acceleration a_c = v²/R = ω²R and the tangential a_t = αR;
//!   at latitude λ on a turning sphere the circle's radius is R cos λ.
//! - [`Rolling`]: the rolling condition v = ωR, a = αR, and the slip speed v − ωR.
//! - [`point_velocity`], [`point_acceleration`]: v = ω × r and
//!   a = α × r + ω × (ω × r) for a point of a rigid body turning about the origin in 3-D.

use std::f64::consts::TAU;

use mechkit_expr::Sym;

use super::Input;
use crate::Real;
use crate::calculus::Params;
use crate::deriv::{Verdict, confirm};
use crate::function::Function;
use crate::mass::Vec3;
use crate::quad::{Tolerance, integrate as quadrature};

mod error;

pub use error::KinematicsError;
pub(super) use error::{check, finite, positive};

/// Which function of time the motion was given by.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Given {
    /// θ(t).
    Angle,
    /// ω(t) and θ₀.
    AngularVelocity,
}

impl Given {
    /// `theta` or `omega`: the name of the function given.
    pub fn name(self) -> &'static str {
        match self {
            Given::Angle => "theta",
            Given::AngularVelocity => "omega",
        }
    }
}

/// The rotation about a fixed axis given by θ(t) or ω(t) as formulas of `t`.
#[derive(Debug, Clone, PartialEq)]
pub struct AngularMotion {
    given: Given,
    /// θ(t) − θ₀ when known in closed form.
    theta: Option<Function>,
    theta0: Real,
    omega: Function,
    alpha: Function,
}

/// θ, ω and α at one time, each derivative also by Ridders' method.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct AngularState {
    /// Time (s).
    pub t: Real,
    /// Angle (rad).
    pub theta: Real,
    /// Angular velocity (rad/s), from the symbolic formula.
    pub omega: Real,
    /// Angular acceleration (rad/s²), from the symbolic formula.
    pub alpha: Real,
    /// ω by Ridders' extrapolation of central differences of θ (none when θ was given by ω
    /// and has no closed form: then θ itself is the quadrature).
    pub omega_numeric: Option<Real>,
    /// α by Ridders' extrapolation of central differences of ω.
    pub alpha_numeric: Real,
    /// Whether the symbolic and numerical derivatives agree (within 10 × Ridders' error
    /// estimate, or 1e-9 relative).
    pub agree: bool,
}

impl AngularMotion {
    /// θ(t) from the formula `text` of `t` (other names from `params`, SI):
    /// ω = θ', α = θ'' symbolically.
    ///
    /// ```
    /// use mechkit::rigid::kinematics::AngularMotion;
    /// let p = [("c1".to_string(), 1.0), ("t1".to_string(), 1.0),
    ///          ("c2".to_string(), 2.0), ("t2".to_string(), 2.0)];
    /// let m = AngularMotion::from_angle("c1*t/t1 + c2*(t/t2)^2", &p).unwrap();
    /// let s = m.at(1.0);
    /// assert_eq!((s.omega, s.alpha), (2.0, 1.0));
    /// assert!(s.agree);
    /// ```
    pub fn from_angle(text: &str, params: &Params) -> Result<Self, KinematicsError> {
        crate::calculus::check_not_given(params, &["t"])?;
        let theta = Function::parse(text, &["t"], params)?;
        let omega = theta.diff("t");
        let alpha = omega.diff("t");
        Ok(Self {
            given: Given::Angle,
            theta: Some(theta),
            theta0: 0.0,
            omega,
            alpha,
        })
    }

    /// ω(t) from the formula `text` of `t`, with θ(0) = `theta0`: θ = θ₀ + F(t) − F(0) with F
    /// an antiderivative from the rule table (verified by differentiation), or by adaptive
    /// quadrature where there is none; α = ω' symbolically.
    pub fn from_angular_velocity(
        text: &str,
        params: &Params,
        theta0: Real,
    ) -> Result<Self, KinematicsError> {
        let theta0 = finite((Input::InitialAngle, "θ₀"), theta0)?;
        crate::calculus::check_not_given(params, &["t"])?;
        let omega = Function::parse(text, &["t"], params)?;
        let alpha = omega.diff("t");
        let theta = omega.sym().integrate("t").map(|anti| {
            let at0 = anti.result.substitute("t", &Sym::zero());
            omega.with_sym(Sym::difference(anti.result, at0))
        });
        Ok(Self {
            given: Given::AngularVelocity,
            theta,
            theta0,
            omega,
            alpha,
        })
    }

    /// Which function was given.
    pub fn given(&self) -> Given {
        self.given
    }

    /// θ(t) as a formula (without θ₀ when ω was given: θ − θ₀), if known in closed form.
    pub fn theta_formula(&self) -> Option<&Sym> {
        self.theta.as_ref().map(Function::sym)
    }

    /// θ₀ (zero when θ(t) was given).
    pub fn theta0(&self) -> Real {
        self.theta0
    }

    /// ω(t) as a formula.
    pub fn omega_formula(&self) -> &Sym {
        self.omega.sym()
    }

    /// α(t) as a formula.
    pub fn alpha_formula(&self) -> &Sym {
        self.alpha.sym()
    }

    /// `Ok` when θ(t) is finite: always for θ given; for ω given, when ω has no pole on
    /// `[0, t]` ([`crate::calculus::integrable`], the check `integrate` makes), where
    /// neither the closed form's F(t) − F(0) nor a quadrature is the integral.
    pub fn check_time(&self, t: Real) -> Result<(), KinematicsError> {
        if self.given == Given::Angle {
            return Ok(());
        }
        match crate::calculus::integrable(self.omega.sym(), "t", self.omega.params(), 0.0, t) {
            Ok(_) => Ok(()),
            Err(s) => Err(KinematicsError::Diverges {
                t,
                pole: s.at,
                omega: self.omega.sym().to_string(),
                growth: crate::calculus::pole_growth("t", s),
            }),
        }
    }

    /// θ at `t`: the closed form, else θ₀ + ∫₀ᵗ ω by adaptive Gauss-Kronrod (NaN if that
    /// fails). See [`AngularMotion::check_time`] for where θ is finite.
    pub fn theta(&self, t: Real) -> Real {
        if let Some(f) = &self.theta {
            return self.theta0 + f.at1(t);
        }
        let q = quadrature(|s| self.omega.at1(s), 0.0, t, Tolerance::default());
        q.map_or(Real::NAN, |q| self.theta0 + q.value)
    }

    /// θ, ω, α at `t`, with the numerical cross-checks (initial step 0.1 max(1, |t|) s).
    pub fn at(&self, t: Real) -> AngularState {
        let h = 0.1 * t.abs().max(1.0);
        let omega = self.omega.at1(t);
        let alpha = self.alpha.at1(t);
        let omega_est = self
            .theta
            .as_ref()
            .map(|f| confirm(|s| f.at1(s), t, h, omega));
        let (alpha_est, alpha_verdict) = confirm(|s| self.omega.at1(s), t, h, alpha);
        let agree =
            alpha_verdict == Verdict::Agree && omega_est.is_none_or(|(_, v)| v == Verdict::Agree);
        let omega_est = omega_est.map(|(e, _)| e);
        AngularState {
            t,
            theta: self.theta(t),
            omega,
            alpha,
            omega_numeric: omega_est.map(|e| e.value),
            alpha_numeric: alpha_est.value,
            agree,
        }
    }
}

/// Rotation at constant angular acceleration from ω₀ to ω₁ in a time t.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct UniformAngularAcceleration {
    /// Initial angular velocity (rad/s).
    pub omega0: Real,
    /// Final angular velocity (rad/s).
    pub omega1: Real,
    /// Duration (s).
    pub duration: Real,
}

impl UniformAngularAcceleration {
    /// Checks the values (finite, duration positive).
    ///
    /// ```
    /// use mechkit::rigid::kinematics::UniformAngularAcceleration;
    /// let rpm = std::f64::consts::TAU / 60.0;
    /// let u = UniformAngularAcceleration::new(1000.0 * rpm, 2000.0 * rpm, 15.0).unwrap();
    /// assert!((u.alpha() - 6.981_317_007_977_318).abs() < 1e-12);
    /// assert!((u.revolutions() - 375.0).abs() < 1e-12);
    /// ```
    pub fn new(omega0: Real, omega1: Real, duration: Real) -> Result<Self, KinematicsError> {
        Ok(Self {
            omega0: finite((Input::InitialAngularVelocity, "ω₀"), omega0)?,
            omega1: finite((Input::FinalAngularVelocity, "ω₁"), omega1)?,
            duration: positive((Input::Time, "the duration"), duration)?,
        })
    }

    /// α = (ω₁ − ω₀)/t.
    pub fn alpha(&self) -> Real {
        (self.omega1 - self.omega0) / self.duration
    }

    /// Δθ = (ω₀ + ω₁) t / 2 (rad).
    pub fn angle(&self) -> Real {
        0.5 * (self.omega0 + self.omega1) * self.duration
    }

    /// Δθ / 2π.
    pub fn revolutions(&self) -> Real {
        self.angle() / TAU
    }
}

/// A point moving on a circle of radius R at angular velocity ω (and angular acceleration α).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CircularMotion {
    /// Radius of the circle (m).
    pub radius: Real,
    /// Angular velocity (rad/s).
    pub omega: Real,
    /// Angular acceleration (rad/s²).
    pub alpha: Real,
}

impl CircularMotion {
    /// From ω and R (α = 0).
    pub fn new(radius: Real, omega: Real) -> Result<Self, KinematicsError> {
        Ok(Self {
            radius: check(
                (Input::Radius, "the radius"),
                radius,
                "non-negative and finite",
                radius >= 0.0,
            )?,
            omega: finite((Input::AngularSpeed, "ω"), omega)?,
            alpha: 0.0,
        })
    }

    /// From the speed v = ωR and R (which must be positive).
    ///
    /// ```
    /// use mechkit::rigid::kinematics::CircularMotion;
    /// let c = CircularMotion::from_speed(10.0, 50.0).unwrap();
    /// assert_eq!(c.omega, 0.2);
    /// assert!((c.centripetal() - 2.0).abs() < 1e-15);
    /// ```
    pub fn from_speed(speed: Real, radius: Real) -> Result<Self, KinematicsError> {
        // ω = v/R: a radius it divides by must be a normal double (1e-320 m made ω = ∞)
        let r = check(
            (Input::Radius, "the radius"),
            radius,
            "positive, finite and at least 2.2e-308 m (ω = v/R divides by it)",
            crate::invertible(radius),
        )?;
        let speed = finite((Input::Speed, "the speed"), speed)?;
        let omega = check(
            (Input::Speed, "ω = v/R"),
            speed / r,
            "finite: the speed is too large for the radius",
            true,
        )?;
        Self::new(r, omega)
    }

    /// From the period T = 2π/ω and R.
    pub fn from_period(period: Real, radius: Real) -> Result<Self, KinematicsError> {
        Self::new(
            radius,
            TAU / positive((Input::Period, "the period"), period)?,
        )
    }

    /// With the angular acceleration α.
    pub fn with_alpha(self, alpha: Real) -> Result<Self, KinematicsError> {
        Ok(Self {
            alpha: finite((Input::AngularAcceleration, "α"), alpha)?,
            ..self
        })
    }

    /// The circle of a point at latitude λ (rad, |λ| ≤ π/2) on a sphere of this radius turning
    /// about its polar axis: radius R cos λ, same ω and α.
    pub fn at_latitude(self, latitude: Real) -> Result<Self, KinematicsError> {
        // shown in degrees, as the latitude is given
        check(
            (Input::Latitude, "the latitude (in degrees)"),
            latitude.to_degrees(),
            "between -90° and 90°",
            latitude.abs() <= std::f64::consts::FRAC_PI_2 * (1.0 + 1e-15),
        )?;
        let lat = latitude;
        Ok(Self {
            radius: self.radius * lat.cos().max(0.0),
            ..self
        })
    }

    /// v = ωR (m/s; signed as ω).
    pub fn speed(&self) -> Real {
        self.omega * self.radius
    }

    /// a_c = ω²R = v²/R (m/s²), towards the centre.
    pub fn centripetal(&self) -> Real {
        self.omega * self.omega * self.radius
    }

    /// a_t = αR (m/s²), along the motion.
    pub fn tangential(&self) -> Real {
        self.alpha * self.radius
    }

    /// |a| = sqrt(a_c² + a_t²).
    pub fn acceleration(&self) -> Real {
        self.centripetal().hypot(self.tangential())
    }

    /// T = 2π/|ω| (infinite at rest).
    pub fn period(&self) -> Real {
        TAU / self.omega.abs()
    }
}

/// A wheel of radius R: the rolling condition v = ωR, a = αR.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rolling {
    /// Radius (m).
    pub radius: Real,
}

impl Rolling {
    /// A wheel of positive radius.
    pub fn new(radius: Real) -> Result<Self, KinematicsError> {
        Ok(Self {
            radius: positive((Input::Radius, "the radius"), radius)?,
        })
    }

    /// The speed of the centre when rolling at ω: v = ωR.
    pub fn speed(&self, omega: Real) -> Real {
        omega * self.radius
    }

    /// The angular velocity when rolling at speed v: ω = v/R.
    pub fn omega(&self, speed: Real) -> Real {
        speed / self.radius
    }

    /// The acceleration of the centre when rolling with α: a = αR.
    pub fn acceleration(&self, alpha: Real) -> Real {
        alpha * self.radius
    }

    /// The angular acceleration when rolling with acceleration a: α = a/R.
    pub fn alpha(&self, acceleration: Real) -> Real {
        acceleration / self.radius
    }

    /// The speed of the contact point over the ground, v − ωR: zero when rolling.
    pub fn slip(&self, speed: Real, omega: Real) -> Real {
        speed - omega * self.radius
    }
}

/// The velocity v = ω × r of the point at `r` of a body turning at `omega` about the origin.
///
/// ```
/// use mechkit::mass::Vec3;
/// use mechkit::rigid::kinematics::point_velocity;
/// let v = point_velocity(&Vec3::new(0.0, 0.0, 2.0), &Vec3::new(1.0, 0.0, 5.0));
/// assert_eq!(v, Vec3::new(0.0, 2.0, 0.0));
/// ```
pub fn point_velocity(omega: &Vec3, r: &Vec3) -> Vec3 {
    omega.cross(r)
}

/// The acceleration of a point of a rigid body turning about the origin: the tangential part
/// α × r and the centripetal part ω × (ω × r) (towards the axis, of size ω² times the
/// distance from the axis).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointAcceleration {
    /// α × r.
    pub tangential: Vec3,
    /// ω × (ω × r).
    pub centripetal: Vec3,
}

impl PointAcceleration {
    /// The sum a = α × r + ω × (ω × r).
    pub fn total(&self) -> Vec3 {
        self.tangential + self.centripetal
    }
}

/// The acceleration of the point at `r` of a body with angular velocity `omega` and angular
/// acceleration `alpha` about the origin.
pub fn point_acceleration(alpha: &Vec3, omega: &Vec3, r: &Vec3) -> PointAcceleration {
    PointAcceleration {
        tangential: alpha.cross(r),
        centripetal: omega.cross(&omega.cross(r)),
    }
}

/// The distance of the point `r` from the axis through the origin along `omega` (the radius
/// of its circle), zero for ω = 0.
pub fn distance_from_axis(omega: &Vec3, r: &Vec3) -> Real {
    let w = omega.norm();
    if w == 0.0 {
        0.0
    } else {
        omega.cross(r).norm() / w
    }
}

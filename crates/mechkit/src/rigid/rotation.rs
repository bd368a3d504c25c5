//! The answers of `mechkit rotation` as values, one per kind of question ([`RotationReport`]):
//! θ, ω, α from a formula ([`AngularMotion::report`]), uniform angular acceleration
//! ([`UniformAngularAcceleration::report`]), circular motion ([`circle`]: v = ωR,
//! a_c = ω²R = v²/R, a_t = αR, T = 2π/ω, from any two of R, v, ω (or T) and a_c), and a point
//! of a body turning in 3-D ([`point_motion`]: v = ω × r, a = α × r + ω × (ω × r)).
//!
//! ```
//! use approx::assert_relative_eq;
//! use mechkit::rigid::rotation::{CircleGiven, CircleQuestion, circle};
//! // a centrifuge of radius 5 m giving 9.81 m/s² at its rim: ω = √(a/R)
//! let c = circle(&CircleQuestion::new(CircleGiven::Centripetal(9.81)).with_radius(5.0))?;
//! assert_relative_eq!(c.omega, (9.81_f64 / 5.0).sqrt(), max_relative = 1e-15);
//! assert_relative_eq!(c.omega_rpm, c.omega * 60.0 / std::f64::consts::TAU);
//! assert_relative_eq!(c.speed.unwrap(), (9.81_f64 * 5.0).sqrt(), max_relative = 1e-15);
//! # Ok::<(), mechkit::rigid::kinematics::KinematicsError>(())
//! ```

use std::f64::consts::TAU;

use super::Input;
use super::kinematics::{
    AngularMotion, AngularState, CircularMotion, Given, KinematicsError,
    UniformAngularAcceleration, check, distance_from_axis, finite, point_acceleration,
    point_velocity, positive,
};
use crate::Real;
use crate::mass::Vec3;

/// The answer to one rotation question; its `mode` says which.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize),
    serde(tag = "mode", rename_all = "lowercase")
)]
pub enum RotationReport {
    /// θ, ω, α from θ(t) or ω(t).
    Formula(FormulaReport),
    /// Uniform angular acceleration.
    Uniform(UniformReport),
    /// Circular motion.
    Circle(CircleReport),
    /// A point of a body turning in 3-D.
    Point(PointReport),
}

/// θ(t), ω(t), α(t) as formulas and their values at some times.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct FormulaReport {
    /// Which function was given: `theta` or `omega`.
    pub given: &'static str,
    /// θ(t), with θ₀ (a quadrature's description when ω has no antiderivative in closed form).
    pub theta: String,
    /// Whether θ(t) is known in closed form.
    pub theta_closed_form: bool,
    /// ω(t) = dθ/dt.
    pub omega: String,
    /// α(t) = dω/dt.
    pub alpha: String,
    /// The values at the times asked, with the numerical cross-checks.
    pub at: Vec<AngularState>,
}

/// The written form of a number: the shortest text that reads back as it.
fn number(x: Real) -> String {
    let mut s = String::new();
    crate::csv::push_number(&mut s, x);
    s
}

impl AngularMotion {
    /// The formulas and their values at `times` (s); an error at a time where θ = θ₀ + ∫₀ᵗ ω dt
    /// diverges ([`AngularMotion::check_time`]).
    ///
    /// ```
    /// use mechkit::rigid::kinematics::AngularMotion;
    /// let m = AngularMotion::from_angular_velocity("2*t", &[], 1.0).unwrap();
    /// let r = m.report(&[3.0]).unwrap();
    /// assert_eq!(r.theta, "1 + t^2");
    /// assert_eq!(r.at[0].theta, 10.0);
    /// // across the pole of tan at π/2 the integral diverges
    /// let m = AngularMotion::from_angular_velocity("tan(t)", &[], 0.0).unwrap();
    /// assert!(m.report(&[2.0]).is_err());
    /// ```
    pub fn report(&self, times: &[Real]) -> Result<FormulaReport, KinematicsError> {
        for &t in times {
            self.check_time(t)?;
        }
        let theta = match self.theta_formula() {
            Some(f) if self.given() == Given::AngularVelocity && self.theta0() != 0.0 => {
                format!("{} + {f}", number(self.theta0()))
            }
            Some(f) => f.to_string(),
            None => format!(
                "{} + ∫₀ᵗ ω dt (no closed form: adaptive quadrature)",
                number(self.theta0())
            ),
        };
        Ok(FormulaReport {
            given: self.given().name(),
            theta,
            theta_closed_form: self.theta_formula().is_some(),
            omega: self.omega_formula().to_string(),
            alpha: self.alpha_formula().to_string(),
            at: times.iter().map(|&t| self.at(t)).collect(),
        })
    }
}

/// Uniform angular acceleration from ω₀ to ω₁ in a time.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct UniformReport {
    /// ω₀ (rad/s).
    pub omega0: Real,
    /// ω₁ (rad/s).
    pub omega1: Real,
    /// The duration (s).
    pub time: Real,
    /// α = (ω₁ − ω₀)/t (rad/s²).
    pub alpha: Real,
    /// Δθ = (ω₀ + ω₁) t/2 (rad).
    pub angle: Real,
    /// Δθ/2π.
    pub revolutions: Real,
}

impl UniformAngularAcceleration {
    /// α, the angle turned and the revolutions.
    pub fn report(&self) -> UniformReport {
        UniformReport {
            omega0: self.omega0,
            omega1: self.omega1,
            time: self.duration,
            alpha: self.alpha(),
            angle: self.angle(),
            revolutions: self.revolutions(),
        }
    }
}

/// What fixes the motion on the circle (with [`CircleQuestion::radius`] where needed).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CircleGiven {
    /// The speed v (m/s), with the radius: ω = v/R.
    Speed(Real),
    /// The angular speed ω (rad/s); the radius is optional.
    AngularSpeed(Real),
    /// The period T (s): ω = 2π/T; the radius is optional.
    Period(Real),
    /// The centripetal acceleration a_c (m/s²), with the radius: ω = √(a_c/R).
    Centripetal(Real),
    /// A speed and the largest centripetal acceleration allowed, without a radius: the
    /// smallest circle R = v²/a_c.
    SpeedAndCentripetal {
        /// v (m/s).
        speed: Real,
        /// a_c (m/s²).
        centripetal: Real,
    },
}

/// A question about circular motion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CircleQuestion {
    /// What fixes the motion.
    pub given: CircleGiven,
    /// The radius R (m).
    pub radius: Option<Real>,
    /// The angular acceleration α (rad/s²) for a_t = αR [default: 0].
    pub alpha: Option<Real>,
    /// An angle to turn through (rad): the time θ/ω and the arc θR.
    pub turn: Option<Real>,
    /// A latitude (rad) on a sphere of radius R turning about its axis: the circle of radius
    /// R cos λ there.
    pub latitude: Option<Real>,
}

impl CircleQuestion {
    /// A question with nothing but `given`.
    pub fn new(given: CircleGiven) -> Self {
        Self {
            given,
            radius: None,
            alpha: None,
            turn: None,
            latitude: None,
        }
    }

    /// The same question on a circle of `radius` (m).
    #[must_use]
    pub fn with_radius(self, radius: Real) -> Self {
        Self {
            radius: Some(radius),
            ..self
        }
    }
}

/// Turning through an angle on the circle.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Turn {
    /// The angle (rad).
    pub angle: Real,
    /// The time it takes, |θ/ω| (s).
    pub time: Real,
    /// The arc |θ| R (m), when the radius is known.
    pub arc: Option<Real>,
}

/// The circle at a latitude of a turning sphere.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct LatitudeCircle {
    /// The latitude λ (rad).
    pub latitude: Real,
    /// The circle's radius R cos λ (m).
    pub radius: Real,
    /// The speed there (m/s).
    pub speed: Real,
    /// The centripetal acceleration there (m/s²).
    pub centripetal: Real,
    /// The tangential acceleration there (m/s²).
    pub tangential: Real,
}

/// Circular motion: ω (also in rpm) and the period, and with the radius the speed and the
/// accelerations.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct CircleReport {
    /// R (m), given or from v²/a_c; `None` when only ω or T was given.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub radius: Option<Real>,
    /// ω (rad/s).
    pub omega: Real,
    /// ω in revolutions per minute, 60 ω/2π.
    pub omega_rpm: Real,
    /// T = 2π/|ω| (s).
    pub period: Real,
    /// v = ωR (m/s).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub speed: Option<Real>,
    /// α (rad/s²).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub alpha: Option<Real>,
    /// a_c = ω²R (m/s²).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub centripetal: Option<Real>,
    /// a_t = αR (m/s²).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub tangential: Option<Real>,
    /// |a| = √(a_c² + a_t²) (m/s²).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub acceleration: Option<Real>,
    /// Turning through an angle.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub turn: Option<Turn>,
    /// The circle at a latitude.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub latitude: Option<LatitudeCircle>,
    /// Whether the radius is the smallest one the acceleration limit allows, v²/a_c.
    #[cfg_attr(feature = "serde", serde(skip))]
    pub smallest_radius: bool,
}

/// Answers a question about circular motion.
///
/// # Errors
/// A value that is not finite or not positive where it must be (the error names its
/// [`Input`]); the speed or the centripetal acceleration without the radius.
///
/// ```
/// use mechkit::rigid::rotation::{CircleGiven, CircleQuestion, circle};
/// // 30 m/s with at most 2 m/s²: the smallest circle has R = v²/a = 450 m
/// let q = CircleQuestion::new(CircleGiven::SpeedAndCentripetal { speed: 30.0, centripetal: 2.0 });
/// assert_eq!(circle(&q)?.radius, Some(450.0));
/// # Ok::<(), mechkit::rigid::kinematics::KinematicsError>(())
/// ```
pub fn circle(q: &CircleQuestion) -> Result<CircleReport, KinematicsError> {
    let need_radius = |why| {
        q.radius.ok_or(KinematicsError::Missing {
            input: Input::Radius,
            what: "the radius of the circle",
            why,
        })
    };
    let mut smallest_radius = false;
    let (motion, radius) = match q.given {
        CircleGiven::Speed(v) => {
            let r = need_radius("with the speed")?;
            (CircularMotion::from_speed(v, r)?, Some(r))
        }
        CircleGiven::AngularSpeed(w) => {
            (CircularMotion::new(q.radius.unwrap_or(0.0), w)?, q.radius)
        }
        CircleGiven::Period(t) => (
            CircularMotion::from_period(t, q.radius.unwrap_or(0.0))?,
            q.radius,
        ),
        CircleGiven::Centripetal(a) => {
            let r = need_radius("with the centripetal acceleration")?;
            let r = positive((Input::Radius, "the radius"), r)?;
            let a = centripetal(a)?;
            (CircularMotion::new(r, (a / r).sqrt())?, Some(r))
        }
        CircleGiven::SpeedAndCentripetal {
            speed,
            centripetal: a,
        } => {
            let v = finite((Input::Speed, "the speed"), speed)?;
            let r = v * v / centripetal(a)?;
            smallest_radius = true;
            (CircularMotion::from_speed(v, r)?, Some(r))
        }
    };
    let motion = match q.alpha {
        Some(a) => motion.with_alpha(a)?,
        None => motion,
    };
    let turn = q
        .turn
        .map(|angle| {
            let angle = finite((Input::Turn, "the angle to turn through"), angle)?;
            check(
                (Input::Turn, "ω"),
                motion.omega,
                "non-zero to turn through an angle",
                motion.omega != 0.0,
            )?;
            Ok::<_, KinematicsError>(Turn {
                angle,
                time: (angle / motion.omega).abs(),
                arc: radius.map(|r| angle.abs() * r),
            })
        })
        .transpose()?;
    let latitude = q
        .latitude
        .map(|lambda| {
            let at = motion.at_latitude(lambda)?;
            Ok::<_, KinematicsError>(LatitudeCircle {
                latitude: lambda,
                radius: at.radius,
                speed: at.speed(),
                centripetal: at.centripetal(),
                tangential: at.tangential(),
            })
        })
        .transpose()?;
    let with_radius = |f: fn(&CircularMotion) -> Real| radius.map(|_| f(&motion));
    Ok(CircleReport {
        radius,
        omega: motion.omega,
        omega_rpm: motion.omega * 60.0 / TAU,
        period: motion.period(),
        speed: with_radius(CircularMotion::speed),
        alpha: radius.map(|_| motion.alpha),
        centripetal: with_radius(CircularMotion::centripetal),
        tangential: with_radius(CircularMotion::tangential),
        acceleration: with_radius(CircularMotion::acceleration),
        turn,
        latitude,
        smallest_radius,
    })
}

fn centripetal(a: Real) -> Result<Real, KinematicsError> {
    positive((Input::Centripetal, "the centripetal acceleration"), a)
}

/// The tangential and centripetal parts of a point's acceleration, and their sum.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct PointAccelerations {
    /// α × r (m/s²).
    pub tangential: [Real; 3],
    /// ω × (ω × r) (m/s²).
    pub centripetal: [Real; 3],
    /// Their sum (m/s²).
    pub total: [Real; 3],
}

/// A point of a rigid body turning about the origin.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct PointReport {
    /// ω (rad/s).
    pub omega: [Real; 3],
    /// α (rad/s²).
    pub alpha: [Real; 3],
    /// The point r (m).
    pub point: [Real; 3],
    /// v = ω × r (m/s).
    pub velocity: [Real; 3],
    /// |v| (m/s).
    pub speed: Real,
    /// The distance of the point from the axis (m).
    pub distance_from_axis: Real,
    /// a = α × r + ω × (ω × r).
    pub acceleration: PointAccelerations,
}

/// The components of `v`, with −0 written as 0.
fn components(v: &Vec3) -> [Real; 3] {
    [v.x + 0.0, v.y + 0.0, v.z + 0.0]
}

/// The velocity and acceleration of the point `r` of a body turning about the origin with
/// angular velocity `omega` and angular acceleration `alpha`.
///
/// ```
/// use mechkit::mass::Vec3;
/// use mechkit::rigid::rotation::point_motion;
/// let p = point_motion(&Vec3::new(0.0, 0.0, 3.0), &Vec3::zeros(), &Vec3::new(2.0, 0.0, 1.0));
/// assert_eq!(p.velocity, [0.0, 6.0, 0.0]);
/// assert_eq!(p.acceleration.centripetal, [-18.0, 0.0, 0.0]);
/// assert_eq!(p.distance_from_axis, 2.0);
/// ```
pub fn point_motion(omega: &Vec3, alpha: &Vec3, r: &Vec3) -> PointReport {
    let v = point_velocity(omega, r);
    let a = point_acceleration(alpha, omega, r);
    PointReport {
        omega: components(omega),
        alpha: components(alpha),
        point: components(r),
        velocity: components(&v),
        speed: v.norm(),
        distance_from_axis: distance_from_axis(omega, r),
        acceleration: PointAccelerations {
            tangential: components(&a.tangential),
            centripetal: components(&a.centripetal),
            total: components(&a.total()),
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_pair_of_circle_inputs_gives_the_same_motion() {
        let (r, w) = (2.5, 1.2);
        let (v, a, t) = (w * r, w * w * r, TAU / w);
        let answers = [
            CircleQuestion::new(CircleGiven::Speed(v)).with_radius(r),
            CircleQuestion::new(CircleGiven::AngularSpeed(w)).with_radius(r),
            CircleQuestion::new(CircleGiven::Period(t)).with_radius(r),
            CircleQuestion::new(CircleGiven::Centripetal(a)).with_radius(r),
            CircleQuestion::new(CircleGiven::SpeedAndCentripetal {
                speed: v,
                centripetal: a,
            }),
        ]
        .map(|q| circle(&q).unwrap());
        for c in answers {
            assert!((c.omega - w).abs() < 1e-14, "{c:?}");
            assert!((c.radius.unwrap() - r).abs() < 1e-14);
            assert!((c.speed.unwrap() - v).abs() < 1e-14);
            assert!((c.centripetal.unwrap() - a).abs() < 1e-13);
            assert!((c.period - t).abs() < 1e-13);
            assert!((c.omega_rpm - w * 60.0 / TAU).abs() < 1e-13);
        }
        assert!(answers[4].smallest_radius && !answers[3].smallest_radius);
    }

    #[test]
    fn a_circle_question_names_the_input_at_fault() {
        let no_radius = circle(&CircleQuestion::new(CircleGiven::Centripetal(9.81))).unwrap_err();
        assert_eq!(no_radius.input(), Some(Input::Radius));
        let limit = circle(&CircleQuestion::new(CircleGiven::SpeedAndCentripetal {
            speed: 3.0,
            centripetal: 0.0,
        }))
        .unwrap_err();
        assert_eq!(limit.input(), Some(Input::Centripetal));
        let mut q = CircleQuestion::new(CircleGiven::AngularSpeed(0.0)).with_radius(1.0);
        q.turn = Some(1.0);
        assert_eq!(circle(&q).unwrap_err().input(), Some(Input::Turn));
        q.turn = None;
        q.latitude = Some(2.0);
        assert_eq!(circle(&q).unwrap_err().input(), Some(Input::Latitude));
        // only ω: no radius, so no speeds
        let c = circle(&CircleQuestion::new(CircleGiven::Period(86_400.0))).unwrap();
        assert_eq!((c.radius, c.speed), (None, None));
    }
}

//! A body hinged at a pivot struck by a free particle (a block, a bullet, Tarzan).

use super::error::ImpactError;
use super::{Contact, cross, spin};
use crate::Real;
use crate::mass::{MassProperties, Vec3};
use crate::rigid::Input;

/// A rigid body turning about a fixed pivot at the origin (axis z).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PivotedBody {
    /// Moment of inertia about the pivot's axis, I_O (kg m²).
    pub inertia: Real,
    /// Mass (kg).
    pub mass: Real,
    /// The centre of mass relative to the pivot (m).
    pub centre_of_mass: [Real; 2],
    /// Angular velocity just before the impact (rad/s, counter-clockwise positive).
    pub omega: Real,
    /// The nearest and farthest distance of the body's material from the pivot, when known
    /// (a rod): used for warnings.
    pub reach: Option<(Real, Real)>,
}

pub(super) fn positive(
    (input, what): (Input, &'static str),
    value: Real,
) -> Result<Real, ImpactError> {
    if value > 0.0 && value.is_finite() {
        Ok(value)
    } else {
        Err(ImpactError::Value {
            input,
            what,
            value,
            must_be: "positive and finite",
        })
    }
}

pub(super) fn finite(
    (input, what): (Input, &'static str),
    value: Real,
) -> Result<Real, ImpactError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(ImpactError::Value {
            input,
            what,
            value,
            must_be: "finite",
        })
    }
}

impl PivotedBody {
    /// A checked body: I_O > 0 (else [`ImpactError::ZeroInertia`]), M > 0, and I_O ≥ M d²
    /// (the parallel-axis theorem).
    pub fn new(
        inertia: Real,
        mass: Real,
        centre_of_mass: [Real; 2],
        omega: Real,
    ) -> Result<Self, ImpactError> {
        if inertia == 0.0 {
            return Err(ImpactError::ZeroInertia {
                which: "the hinged body",
            });
        }
        let inertia = positive(
            (Input::Inertia, "the moment of inertia about the pivot"),
            inertia,
        )?;
        let mass = positive((Input::Mass, "the mass of the hinged body"), mass)?;
        let d2 = finite(
            (Input::CentreOfMass, "the centre of mass"),
            centre_of_mass[0],
        )?
        .powi(2)
            + finite(
                (Input::CentreOfMass, "the centre of mass"),
                centre_of_mass[1],
            )?
            .powi(2);
        if inertia < mass * d2 * (1.0 - 1e-12) {
            return Err(ImpactError::ParallelAxis {
                inertia,
                minimum: mass * d2,
            });
        }
        Ok(Self {
            inertia,
            mass,
            centre_of_mass,
            omega: finite((Input::AngularVelocity, "ω"), omega)?,
            reach: None,
        })
    }

    /// A uniform rod of mass `mass` and length `length` hanging from a pivot `pivot_offset`
    /// above its centre (along the rod; `length/2` is the top end): the centre of mass at
    /// (0, −offset), I_O = M L²/12 + M offset².
    ///
    /// ```
    /// use mechkit::rigid::impact::PivotedBody;
    /// let rod = PivotedBody::rod(3.0, 2.0, 1.0, 0.0).unwrap();
    /// assert!((rod.inertia - 3.0 * 4.0 / 3.0).abs() < 1e-15);
    /// assert_eq!(rod.centre_of_mass, [0.0, -1.0]);
    /// ```
    pub fn rod(
        mass: Real,
        length: Real,
        pivot_offset: Real,
        omega: Real,
    ) -> Result<Self, ImpactError> {
        let length = positive((Input::Length, "the rod's length"), length)?;
        let mass = positive((Input::Mass, "the rod's mass"), mass)?;
        let d = finite((Input::Pivot, "the pivot's position"), pivot_offset)?;
        let mut body = Self::new(
            mass * (length * length / 12.0 + d * d),
            mass,
            [0.0, -d],
            omega,
        )?;
        body.reach = Some(((d.abs() - 0.5 * length).max(0.0), d.abs() + 0.5 * length));
        Ok(body)
    }

    /// A body's mass properties turning about the axis z through `pivot`: I_O about that
    /// axis, the centre of mass's x, y relative to the pivot.
    pub fn from_properties(
        props: &MassProperties,
        pivot: &Vec3,
        omega: Real,
    ) -> Result<Self, ImpactError> {
        let inertia =
            props
                .moment_about_axis(pivot, &Vec3::z())
                .map_err(|_| ImpactError::Value {
                    input: Input::Pivot,
                    what: "the pivot",
                    value: pivot.norm(),
                    must_be: "finite",
                })?;
        let c = props.centre_of_mass - pivot;
        Self::new(inertia, props.mass, [c[0], c[1]], omega)
    }

    /// The distance d of the centre of mass from the pivot.
    pub fn cm_distance(&self) -> Real {
        self.centre_of_mass[0].hypot(self.centre_of_mass[1])
    }

    /// The radius of gyration about the centre of mass, sqrt(I_O/M − d²).
    pub fn gyration_radius(&self) -> Real {
        (self.inertia / self.mass - self.cm_distance().powi(2))
            .max(0.0)
            .sqrt()
    }

    /// The distance from the pivot of the centre of percussion, I_O/(M d), along the line
    /// through the centre of mass: a blow there, perpendicular to that line, leaves no
    /// impulse in the hinge. `None` when the pivot is at the centre of mass.
    pub fn centre_of_percussion(&self) -> Option<Real> {
        let d = self.cm_distance();
        (d > 0.0).then(|| self.inertia / (self.mass * d))
    }

    /// Kinetic energy ½ I_O ω².
    pub fn kinetic_energy(&self) -> Real {
        0.5 * self.inertia * self.omega * self.omega
    }

    /// Things that look wrong about the body and a contact at `point`, in words: a pivot
    /// outside the body, a contact beyond its reach, a pivot far from the centre of mass
    /// for its size.
    pub fn warnings(&self, point: [Real; 2]) -> Vec<String> {
        let mut out = Vec::new();
        let r = point[0].hypot(point[1]);
        let d = self.cm_distance();
        if let Some((near, far)) = self.reach {
            if near > 0.0 {
                out.push(format!(
                        "the pivot is {} m outside the body (the body swings on a massless arm); is the pivot's position right?",
                        crate::error::short(near)
                    ));
            }
            if r > far * (1.0 + 1e-9) || r < near * (1.0 - 1e-9) {
                out.push(format!(
                        "the contact point is {} m from the pivot, but the body reaches from {} m to {} m: the contact is off the body",
                        crate::error::short(r),
                        crate::error::short(near),
                        crate::error::short(far)
                    ));
            }
        } else {
            let k = self.gyration_radius();
            if d > 3.0 * k {
                out.push(format!(
                        "the centre of mass is {} m from the pivot, more than three radii of gyration ({} m): the pivot is probably outside the body",
                        crate::error::short(d),
                        crate::error::short(k)
                    ));
            }
            if r > 3.0 * (d + k) {
                out.push(format!(
                        "the contact point is {} m from the pivot, far beyond the body's size (d + k = {} m)",
                        crate::error::short(r),
                        crate::error::short(d + k)
                    ));
            }
        }
        out
    }
}

/// The angular velocity at the lowest point of a body released from rest with its centre of
/// mass at angle `theta0` from the vertical below the pivot: ω₀ = sqrt(2 M g d (1 − cos θ₀)/I_O).
///
/// ```
/// use mechkit::rigid::impact::{PivotedBody, release_omega};
/// let rod = PivotedBody::rod(1.0, 1.0, 0.5, 0.0).unwrap();
/// let w = release_omega(&rod, 9.81, std::f64::consts::FRAC_PI_2);
/// assert!((w - (3.0 * 9.81_f64).sqrt()).abs() < 1e-14);
/// ```
pub fn release_omega(body: &PivotedBody, g: Real, theta0: Real) -> Real {
    (2.0 * body.mass * g * body.cm_distance() * (1.0 - theta0.cos()) / body.inertia).sqrt()
}

/// A free particle (a block treated as a point) at the contact point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Particle {
    /// Mass (kg).
    pub mass: Real,
    /// Velocity before the impact (m/s).
    pub velocity: [Real; 2],
}

/// The result of [`hinged_impact`]. Momenta are about the pivot.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HingedImpact {
    /// The body's ω after (rad/s).
    pub omega_after: Real,
    /// The particle's velocity after (m/s).
    pub velocity_after: [Real; 2],
    /// The impulse on the particle along the normal, J (N s); the body receives −J n.
    pub impulse: Real,
    /// The impulse of the hinge on the body (N s).
    pub hinge_impulse: [Real; 2],
    /// The effective mass along the normal, 1/(1/m + (r × n)²/I_O) (kg).
    pub effective_mass: Real,
    /// The normal relative velocity before, (v − ω × r)·n (negative: approaching).
    pub normal_speed_before: Real,
    /// The normal relative velocity after (−e times the one before).
    pub normal_speed_after: Real,
    /// Kinetic energy before and after (J).
    pub kinetic: (Real, Real),
    /// The closed-form change of kinetic energy, −½ (1 − e²) m_eff u² (J).
    pub kinetic_change_exact: Real,
    /// Angular momentum about the pivot before and after, I_O ω + r × m v (kg m²/s).
    pub angular_momentum: (Real, Real),
    /// Linear momentum of body and particle before and after (kg m/s): it changes by the
    /// hinge impulse.
    pub momentum: ([Real; 2], [Real; 2]),
}

/// A free particle hits a hinged body at `contact` (the normal from the body into the
/// particle). Frictionless: the impulse is along the normal.
///
/// ```
/// use mechkit::rigid::impact::{Contact, PivotedBody, Particle, hinged_impact};
/// // a rod (M = 1 kg, L = 1 m) hanging from its top end, swinging at 2 rad/s, hits a block
/// // of M/3 at its lower end elastically: the rod stops, the block takes ω₀ L
/// let rod = PivotedBody::rod(1.0, 1.0, 0.5, 2.0).unwrap();
/// let block = Particle { mass: 1.0 / 3.0, velocity: [0.0, 0.0] };
/// let hit = Contact { point: [0.0, -1.0], normal: [1.0, 0.0], restitution: 1.0 };
/// let r = hinged_impact(&rod, &block, &hit).unwrap();
/// assert!(r.omega_after.abs() < 1e-15);
/// assert!((r.velocity_after[0] - 2.0).abs() < 1e-15);
/// ```
pub fn hinged_impact(
    body: &PivotedBody,
    particle: &Particle,
    contact: &Contact,
) -> Result<HingedImpact, ImpactError> {
    let c = contact.checked()?;
    let m = positive((Input::BlockMass, "the particle's mass"), particle.mass)?;
    let v = particle.velocity;
    finite(
        (Input::BlockVelocity, "the particle's velocity"),
        v[0] + v[1],
    )?;
    let (n, p) = (c.normal, c.point);
    let arm = cross(p, n);
    let inv_m_eff = 1.0 / m + arm * arm / body.inertia;
    let m_eff = 1.0 / inv_m_eff;
    let vp = spin(body.omega, p);
    let u = (v[0] - vp[0]) * n[0] + (v[1] - vp[1]) * n[1];
    if u >= 0.0 {
        return Err(ImpactError::Separating { normal_speed: u });
    }
    let j = -(1.0 + c.restitution) * m_eff * u;
    let omega_after = body.omega - arm * j / body.inertia;
    let velocity_after = [v[0] + j * n[0] / m, v[1] + j * n[1] / m];
    let vp_after = spin(omega_after, p);
    let u_after =
        (velocity_after[0] - vp_after[0]) * n[0] + (velocity_after[1] - vp_after[1]) * n[1];
    let cm = body.centre_of_mass;
    let body_p = |w: Real| spin(w, cm).map(|x| body.mass * x);
    let (pb0, pb1) = (body_p(body.omega), body_p(omega_after));
    // M Δv_cm = −J n + J_hinge
    let hinge_impulse = [pb1[0] - pb0[0] + j * n[0], pb1[1] - pb0[1] + j * n[1]];
    let kinetic =
        |w: Real, u: [Real; 2]| 0.5 * body.inertia * w * w + 0.5 * m * (u[0] * u[0] + u[1] * u[1]);
    let ang = |w: Real, u: [Real; 2]| body.inertia * w + m * cross(p, u);
    Ok(HingedImpact {
        omega_after,
        velocity_after,
        impulse: j,
        hinge_impulse,
        effective_mass: m_eff,
        normal_speed_before: u,
        normal_speed_after: u_after,
        kinetic: (kinetic(body.omega, v), kinetic(omega_after, velocity_after)),
        kinetic_change_exact: -0.5 * (1.0 - c.restitution * c.restitution) * m_eff * u * u,
        angular_momentum: (ang(body.omega, v), ang(omega_after, velocity_after)),
        momentum: (
            [pb0[0] + m * v[0], pb0[1] + m * v[1]],
            [
                pb1[0] + m * velocity_after[0],
                pb1[1] + m * velocity_after[1],
            ],
        ),
    })
}

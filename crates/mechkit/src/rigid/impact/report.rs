//! The answers of `mechkit rigid-collide` as values: a hinged body struck by a block
//! ([`HingedReport`], [`hinged_report`]), with the rod hinged along its length
//! ([`PivotedBody::hinged_rod`]) and the swing from a release angle
//! ([`PivotedBody::released`]); and a free rod landing on its lower end on the ground
//! ([`LandingReport`], [`rod_landing`]), its moment of inertia m L²/12 from the mass
//! properties of a rod ([`crate::mass::Shape::Rod`]).

use super::Contact;
use super::error::ImpactError;
use super::free::{PlanarBody, impact};
use super::hinged::{HingedImpact, Particle, PivotedBody, finite, hinged_impact, positive};
use crate::Real;
use crate::mass::{Shape, Vec3};
use crate::rigid::Input;

/// The hinged body's numbers.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct HingedBodyNumbers {
    /// I_O (kg m²).
    pub inertia: Real,
    /// M (kg).
    pub mass: Real,
    /// d, the centre of mass's distance from the pivot (m).
    pub cm_distance: Real,
    /// I_O/(M d) (m): a blow there leaves no impulse in the hinge.
    pub centre_of_percussion: Option<Real>,
}

/// The contact.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct ContactNumbers {
    /// The contact point relative to the pivot (m).
    pub point: [Real; 2],
    /// The normal from the body into the block.
    pub normal: [Real; 2],
    /// e.
    pub restitution: Real,
}

/// The block.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct BlockNumbers {
    /// m (kg).
    pub mass: Real,
    /// Before (m/s).
    pub velocity_before: [Real; 2],
    /// After (m/s).
    pub velocity_after: [Real; 2],
}

/// A value before and after.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct BeforeAfter<T = Real> {
    /// Before the impact.
    pub before: T,
    /// After it.
    pub after: T,
}

/// The kinetic energy (J).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct KineticEnergy {
    /// Before.
    pub before: Real,
    /// After.
    pub after: Real,
    /// after − before.
    pub change: Real,
    /// −½ (1 − e²) m_eff u².
    pub change_closed_form: Real,
    /// after/before (`None` from rest).
    pub ratio: Option<Real>,
}

/// Angular momentum about the pivot (kg m²/s).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct AngularMomentumChange {
    /// Before.
    pub before: Real,
    /// After.
    pub after: Real,
    /// after − before: zero, the hinge's impulse having no moment about the pivot.
    pub difference: Real,
}

/// A hinged body struck by a block.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct HingedReport {
    /// The body.
    pub body: HingedBodyNumbers,
    /// The angle it was released from at rest (rad), if it was.
    pub release_angle: Option<Real>,
    /// ω just before (rad/s).
    pub omega0: Real,
    /// ω just after (rad/s).
    pub omega_after: Real,
    /// The contact.
    pub contact: ContactNumbers,
    /// The block.
    pub block: BlockNumbers,
    /// The impulse on the block along the normal (N s).
    pub impulse: Real,
    /// The hinge's impulse on the body (N s).
    pub hinge_impulse: [Real; 2],
    /// 1/(1/m + (r × n)²/I_O) (kg).
    pub effective_mass: Real,
    /// The normal relative velocity (m/s).
    pub normal_speed: BeforeAfter,
    /// The kinetic energy.
    pub kinetic_energy: KineticEnergy,
    /// The angular momentum about the pivot.
    pub angular_momentum_about_pivot: AngularMomentumChange,
    /// The momentum of body and block (kg m/s): it changes by the hinge's impulse.
    pub momentum: BeforeAfter<[Real; 2]>,
    /// What looks wrong about the set-up, in words.
    pub warnings: Vec<String>,
}

impl PivotedBody {
    /// A uniform rod of `mass` and `length` hanging from a pivot `from_top` (m) below its top
    /// end (0: hinged at the end, `length/2`: at the centre), at rest; with its lower end
    /// relative to the pivot, `(0, −(length − from_top))`.
    ///
    /// ```
    /// use mechkit::rigid::impact::PivotedBody;
    /// let (rod, end) = PivotedBody::hinged_rod(3.0, 1.0, 0.25).unwrap();
    /// assert!((rod.inertia - 3.0 * (1.0 / 12.0 + 0.25 * 0.25)).abs() < 1e-15);
    /// assert_eq!(end, [0.0, -0.75]);
    /// ```
    pub fn hinged_rod(
        mass: Real,
        length: Real,
        from_top: Real,
    ) -> Result<(Self, [Real; 2]), ImpactError> {
        let length = positive((Input::Length, "the rod's length"), length)?;
        let from_top = finite(
            (Input::Pivot, "the pivot's distance from the top"),
            from_top,
        )?;
        let rod = Self::rod(mass, length, 0.5 * length - from_top, 0.0)?;
        Ok((rod, [0.0, -(length - from_top)]))
    }

    /// The same body swinging through the bottom after a release from rest with its centre of
    /// mass at `angle` (rad) from the vertical below the pivot, in gravity `g`
    /// ([`super::release_omega`]).
    pub fn released(self, g: Real, angle: Real) -> Result<Self, ImpactError> {
        let angle = finite((Input::ReleaseAngle, "the release angle"), angle)?;
        // hanging straight down (0, or a whole turn) it does not swing, and more than half a
        // turn from the bottom is no release from rest below the pivot
        if !(angle != 0.0 && angle.abs() <= std::f64::consts::PI) {
            return Err(ImpactError::Value {
                input: Input::ReleaseAngle,
                what: "the release angle (rad)",
                value: angle,
                must_be: "between -180° and 180° and not 0: the angle from hanging straight down, where a body released from rest does not swing",
            });
        }
        let g = positive((Input::Gravity, "g"), g)?;
        if self.cm_distance() == 0.0 {
            return Err(ImpactError::Value {
                input: Input::ReleaseAngle,
                what: "the centre of mass's distance from the pivot",
                value: 0.0,
                must_be: "positive for gravity to do work on the swing (give the angular velocity instead)",
            });
        }
        Ok(Self {
            omega: super::release_omega(&self, g, angle),
            ..self
        })
    }
}

/// A block struck by a hinged body, with the release angle the body swung from (if any).
///
/// # Errors
/// As [`hinged_impact`].
pub fn hinged_report(
    body: &PivotedBody,
    block: &Particle,
    contact: &Contact,
    release_angle: Option<Real>,
) -> Result<HingedReport, ImpactError> {
    let r: HingedImpact = hinged_impact(body, block, contact)?;
    let (k0, k1) = r.kinetic;
    let (l0, l1) = r.angular_momentum;
    Ok(HingedReport {
        body: HingedBodyNumbers {
            inertia: body.inertia,
            mass: body.mass,
            cm_distance: body.cm_distance(),
            centre_of_percussion: body.centre_of_percussion(),
        },
        release_angle,
        omega0: body.omega,
        omega_after: r.omega_after,
        contact: ContactNumbers {
            point: contact.point,
            normal: contact.normal,
            restitution: contact.restitution,
        },
        block: BlockNumbers {
            mass: block.mass,
            velocity_before: block.velocity,
            velocity_after: r.velocity_after,
        },
        impulse: r.impulse,
        hinge_impulse: r.hinge_impulse,
        effective_mass: r.effective_mass,
        normal_speed: BeforeAfter {
            before: r.normal_speed_before,
            after: r.normal_speed_after,
        },
        kinetic_energy: KineticEnergy {
            before: k0,
            after: k1,
            change: k1 - k0,
            change_closed_form: r.kinetic_change_exact,
            ratio: (k0 > 0.0).then(|| k1 / k0),
        },
        angular_momentum_about_pivot: AngularMomentumChange {
            before: l0,
            after: l1,
            difference: l1 - l0,
        },
        momentum: BeforeAfter {
            before: r.momentum.0,
            after: r.momentum.1,
        },
        warnings: body.warnings(contact.point),
    })
}

/// The rod's numbers.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct RodNumbers {
    /// m (kg).
    pub mass: Real,
    /// L (m).
    pub length: Real,
    /// m L²/12 (kg m²).
    pub inertia_cm: Real,
    /// The angle above the horizontal (rad).
    pub tilt: Real,
}

/// The rod's motion at one instant.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct RodMotion {
    /// The centre of mass's velocity (m/s).
    pub velocity: [Real; 2],
    /// ω (rad/s).
    pub omega: Real,
    /// The lower end's velocity (m/s).
    pub end_velocity: [Real; 2],
}

/// The kinetic energy of a landing (J).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct LandingEnergy {
    /// Before.
    pub before: Real,
    /// After.
    pub after: Real,
    /// after − before.
    pub change: Real,
    /// −½ (1 − e²) m_eff u².
    pub change_closed_form: Real,
}

/// A free rod landing on its lower end.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct LandingReport {
    /// The rod.
    pub rod: RodNumbers,
    /// e.
    pub restitution: Real,
    /// The lower end relative to the centre of mass (m).
    pub contact: [Real; 2],
    /// Before the impact.
    pub before: RodMotion,
    /// After it.
    pub after: RodMotion,
    /// The ground's impulse (N s).
    pub impulse: Real,
    /// The effective mass at the end along the normal (kg).
    pub effective_mass: Real,
    /// The kinetic energy.
    pub kinetic_energy: LandingEnergy,
    /// The angular momentum about the contact point (kg m²/s): conserved, the only impulse
    /// acting there.
    pub angular_momentum_contact: BeforeAfter,
}

/// A uniform rod of `mass` and `length`, tilted `tilt` (rad, 0 to π/2) above the horizontal,
/// its centre of mass moving at `velocity` and turning at `omega`, lands on its lower end on
/// frictionless ground with restitution `e`.
///
/// # Errors
/// Invalid values (the error names its input), or a lower end not moving down into the
/// ground ([`ImpactError::Separating`]).
///
/// ```
/// use mechkit::rigid::impact::rod_landing;
/// // falling flat at 4 m/s, plastic: ω = 3v/(2L), the centre keeps 3v/4
/// let r = rod_landing(2.0, 1.0, 0.0, [0.0, -4.0], 0.0, 0.0).unwrap();
/// assert!((r.after.omega + 6.0).abs() < 1e-14);
/// assert!((r.after.velocity[1] + 3.0).abs() < 1e-14);
/// assert!((r.rod.inertia_cm - 2.0 / 12.0).abs() < 1e-15);
/// ```
pub fn rod_landing(
    mass: Real,
    length: Real,
    tilt: Real,
    velocity: [Real; 2],
    omega: Real,
    e: Real,
) -> Result<LandingReport, ImpactError> {
    let mass = positive((Input::Mass, "the rod's mass"), mass)?;
    let length = positive((Input::Length, "the rod's length"), length)?;
    if !(0.0..=std::f64::consts::FRAC_PI_2).contains(&tilt) {
        return Err(ImpactError::Value {
            input: Input::Tilt,
            what: "the rod's angle above the horizontal (rad)",
            value: tilt,
            must_be: "from 0 to π/2, i.e. 0 to 90° (a bare number is in radians: write \"30 deg\")",
        });
    }
    let inertia = Shape::Rod { length }
        .with_mass(mass)
        .and_then(|p| p.moment_about_axis(&Vec3::zeros(), &Vec3::x()))
        .map_err(|_| ImpactError::Value {
            input: Input::Length,
            what: "the rod's length",
            value: length,
            must_be: "positive and finite",
        })?;
    let rod = PlanarBody::new(mass, inertia, [0.0, 0.0], velocity, omega)?;
    // the lower end touches the ground; the ground pushes up
    let end = [-0.5 * length * tilt.cos(), -0.5 * length * tilt.sin()];
    let contact = Contact {
        point: end,
        normal: [0.0, 1.0],
        restitution: e,
    };
    let r = impact(&PlanarBody::fixed(end), &rod, &contact)?;
    let after = r.b;
    let motion = |b: &PlanarBody| RodMotion {
        velocity: b.velocity,
        omega: b.omega,
        end_velocity: b.velocity_at(end),
    };
    Ok(LandingReport {
        rod: RodNumbers {
            mass,
            length,
            inertia_cm: inertia,
            tilt,
        },
        restitution: e,
        contact: end,
        before: motion(&rod),
        after: motion(&after),
        impulse: r.impulse,
        effective_mass: r.effective_mass,
        kinetic_energy: LandingEnergy {
            before: r.kinetic.0,
            after: r.kinetic.1,
            change: r.kinetic.1 - r.kinetic.0,
            change_closed_form: r.kinetic_change_exact,
        },
        angular_momentum_contact: BeforeAfter {
            before: r.angular_momentum_contact.0,
            after: r.angular_momentum_contact.1,
        },
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// c16-B6: a rod hinged at its top, released from 90°, strikes a block of a third of its
    /// mass elastically at its lower end: the rod stops, the block takes ω₀ L.
    #[test]
    fn the_rod_from_90_degrees_hands_its_motion_to_the_block() {
        let (rod, end) = PivotedBody::hinged_rod(1.0, 1.0, 0.0).unwrap();
        let rod = rod.released(9.81, std::f64::consts::FRAC_PI_2).unwrap();
        assert!((rod.omega - (3.0f64 * 9.81).sqrt()).abs() < 1e-14);
        let block = Particle {
            mass: 1.0 / 3.0,
            velocity: [0.0, 0.0],
        };
        let hit = Contact {
            point: end,
            normal: [1.0, 0.0],
            restitution: 1.0,
        };
        let r = hinged_report(&rod, &block, &hit, Some(std::f64::consts::FRAC_PI_2)).unwrap();
        assert!(r.omega_after.abs() < 1e-14);
        assert!((r.block.velocity_after[0] - rod.omega).abs() < 1e-14);
        assert!(r.angular_momentum_about_pivot.difference.abs() < 1e-14);
        assert!((r.kinetic_energy.ratio.unwrap() - 1.0).abs() < 1e-14);
        assert!(r.warnings.is_empty());
        // about its centre the swing has no work to draw on
        let (centre, _) = PivotedBody::hinged_rod(1.0, 1.0, 0.5).unwrap();
        let e = centre.released(9.81, 1.0).unwrap_err();
        assert_eq!(e.input(), Some(Input::ReleaseAngle));
    }

    #[test]
    fn a_landing_names_the_input_at_fault() {
        let e = rod_landing(1.0, 1.0, 2.0, [0.0, -1.0], 0.0, 0.5).unwrap_err();
        assert_eq!(e.input(), Some(Input::Tilt));
        let e = rod_landing(1.0, 0.0, 0.5, [0.0, -1.0], 0.0, 0.5).unwrap_err();
        assert_eq!(e.input(), Some(Input::Length));
        let e = rod_landing(1.0, 1.0, 0.5, [0.0, 2.0], 0.0, 0.5).unwrap_err();
        assert!(matches!(e, ImpactError::Separating { .. }));
    }
}

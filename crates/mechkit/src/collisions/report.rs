//! A collision as a front states it ([`CollisionSetup`]: masses, velocities, the contact as a
//! normal or two sphere centres, restitution, friction, optionally gravity) and its result
//! ([`CollisionReport`]: what `mechkit collide --json` prints): the velocities after, the
//! impulse, the energy lost, the centre-of-mass frame and, with gravity, the rise `v²/(2g)`
//! of each body.

use crate::Real;

use super::{Collision, CollisionError, Outcome, Resolution, Restitution};

/// The input of a collision that a [`CollisionError`] is about ([`CollisionError::input`]),
/// so that a front can name its own field for it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum CollisionInput {
    /// The mass of body 1.
    Mass1,
    /// The mass of body 2.
    Mass2,
    /// The velocity of body 1.
    Velocity1,
    /// The velocity of body 2.
    Velocity2,
    /// The coefficient of restitution.
    Restitution,
    /// The contact normal.
    Normal,
    /// The centres of the two spheres (the normal from one to the other).
    Centres,
    /// The friction coefficient.
    Friction,
    /// The gravitational acceleration (for the rise after the collision).
    Gravity,
}

impl CollisionInput {
    /// The input as messages name it.
    pub fn name(self) -> &'static str {
        match self {
            Self::Mass1 => "the mass of body 1",
            Self::Mass2 => "the mass of body 2",
            Self::Velocity1 => "the velocity of body 1",
            Self::Velocity2 => "the velocity of body 2",
            Self::Restitution => "the coefficient of restitution",
            Self::Normal => "the normal",
            Self::Centres => "the centres of the spheres",
            Self::Friction => "the friction coefficient",
            Self::Gravity => "the gravitational acceleration",
        }
    }
}

impl std::fmt::Display for CollisionInput {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// Where the bodies touch.
#[derive(Debug, Clone, PartialEq)]
pub enum Contact {
    /// Not given: head-on along x, which only a 1-D collision can be.
    HeadOn,
    /// The contact normal from body 1 to body 2 (any length but zero).
    Normal(Vec<Real>),
    /// The centres of two spheres: the normal is `r2 − r1`.
    Centres {
        /// Centre of sphere 1.
        r1: Vec<Real>,
        /// Centre of sphere 2.
        r2: Vec<Real>,
    },
}

/// A collision of two bodies as a front states it, before it is checked.
#[derive(Debug, Clone, PartialEq)]
pub struct CollisionSetup {
    /// Mass of body 1 (kg; `inf` for an immovable body).
    pub m1: Real,
    /// Mass of body 2 (kg; `inf` for a wall).
    pub m2: Real,
    /// Velocity of body 1 (1 to 3 components).
    pub v1: Vec<Real>,
    /// Velocity of body 2; a single 0 is "at rest" in any dimension.
    pub v2: Vec<Real>,
    /// Coefficient of restitution.
    pub restitution: Restitution,
    /// Where the bodies touch.
    pub contact: Contact,
    /// Coulomb friction coefficient along the contact plane (0: frictionless).
    pub friction: Real,
    /// Gravity for the rise of each body afterwards, `h = v²/(2g)` (m/s²).
    pub g: Option<Real>,
}

impl CollisionSetup {
    /// A head-on collision of two bodies (1-D unless the velocities say otherwise).
    pub fn new(m1: Real, v1: Vec<Real>, m2: Real, v2: Vec<Real>, e: Restitution) -> Self {
        Self {
            m1,
            m2,
            v1,
            v2,
            restitution: e,
            contact: Contact::HeadOn,
            friction: 0.0,
            g: None,
        }
    }

    /// The checked [`Collision`]: a single zero velocity is padded to the other's dimension,
    /// the normal follows from the contact. Errors name the input at fault
    /// ([`CollisionError::input`]).
    pub fn collision(&self) -> Result<Collision, CollisionError> {
        let d = self.v1.len().max(self.v2.len());
        let pad = |v: &[Real], input: CollisionInput| -> Result<Vec<Real>, CollisionError> {
            if v.is_empty() || v.len() > 3 {
                return Err(CollisionError::Components {
                    input,
                    got: v.len(),
                    expected: d.clamp(1, 3),
                });
            }
            if v.len() == 1 && d > 1 && v[0] == 0.0 {
                return Ok(vec![0.0; d]);
            }
            if v.len() != d {
                return Err(CollisionError::Components {
                    input,
                    got: v.len(),
                    expected: d,
                });
            }
            Ok(v.to_vec())
        };
        let v1 = pad(&self.v1, CollisionInput::Velocity1)?;
        let v2 = pad(&self.v2, CollisionInput::Velocity2)?;
        let normal = match &self.contact {
            Contact::HeadOn if d == 1 => vec![1.0],
            Contact::HeadOn => return Err(CollisionError::NormalNeeded { dim: d }),
            Contact::Normal(n) => n.clone(),
            Contact::Centres { r1, r2 } => {
                if r1.len() != r2.len() {
                    return Err(CollisionError::CentresDiffer {
                        r1: r1.len(),
                        r2: r2.len(),
                    });
                }
                Collision::normal_between(r1, r2).map_err(|e| match e {
                    CollisionError::ZeroNormal => CollisionError::SameCentres,
                    e => e,
                })?
            }
        };
        if normal.len() != d {
            let input = match self.contact {
                Contact::Centres { .. } => CollisionInput::Centres,
                _ => CollisionInput::Normal,
            };
            return Err(CollisionError::Components {
                input,
                got: normal.len(),
                expected: d,
            });
        }
        if let Some(g) = self.g
            && !(g > 0.0 && g.is_finite())
        {
            return Err(CollisionError::Gravity { g });
        }
        Ok(Collision {
            m1: self.m1,
            m2: self.m2,
            v1,
            v2,
            normal,
            restitution: self.restitution,
            friction: self.friction,
        })
    }

    /// Resolves the collision: its [`CollisionReport`].
    ///
    /// ```
    /// use mechkit::collisions::{CollisionReport, CollisionSetup, Restitution};
    /// // a 1 kg ball at 1 m/s into a 2 kg one at rest, elastic; then each swings up in g = 0.5
    /// let mut setup = CollisionSetup::new(1.0, vec![1.0], 2.0, vec![0.0], Restitution::ELASTIC);
    /// setup.g = Some(0.5);
    /// let CollisionReport::Collided(r) = setup.report().unwrap() else { unreachable!() };
    /// assert!((r.v1[0] + 1.0 / 3.0).abs() < 1e-15 && (r.v2[0] - 2.0 / 3.0).abs() < 1e-15);
    /// let rise = r.rise.unwrap();
    /// assert!((rise.rise2 - (2.0f64 / 3.0).powi(2)).abs() < 1e-15); // v²/(2g) with 2g = 1
    /// ```
    pub fn report(&self) -> Result<CollisionReport, CollisionError> {
        let c = self.collision()?;
        Ok(match c.resolve()? {
            Resolution::Separating { approach_speed } => CollisionReport::Separating(NoCollision {
                collided: false,
                approach_speed,
            }),
            Resolution::Collided(o) => {
                CollisionReport::Collided(Box::new(Collided::new(&c, &o, self.g)))
            }
        })
    }
}

/// What a collision did: nothing (the bodies separate), or the impulse and its effects. As
/// JSON, an object with `collided` false or true.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize), serde(untagged))]
pub enum CollisionReport {
    /// They do not approach along the normal.
    Separating(NoCollision),
    /// They collided.
    Collided(Box<Collided>),
}

/// No collision: along the normal the bodies are not approaching.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct NoCollision {
    /// Always `false`.
    pub collided: bool,
    /// `u·n ≤ 0`, the (non-positive) approach speed (m/s).
    pub approach_speed: Real,
}

/// The velocities of the two bodies in one frame.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct VelocityPair {
    /// Body 1 (m/s).
    pub v1: Vec<Real>,
    /// Body 2 (m/s).
    pub v2: Vec<Real>,
}

/// The velocities relative to the centre of mass, before and after.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct CmFrame {
    /// Before the collision.
    pub before: VelocityPair,
    /// After it.
    pub after: VelocityPair,
}

/// How high each body rises afterwards when its speed turns into height: `h = v²/(2g)`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Rise {
    /// The gravitational acceleration (m/s²).
    pub g: Real,
    /// Body 1 (m).
    pub rise1: Real,
    /// Body 2 (m).
    pub rise2: Real,
}

/// A resolved collision: the input and what the impulse did.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Collided {
    /// Always `true`.
    pub collided: bool,
    /// Mass of body 1 (kg; `"inf"` in JSON for an immovable body).
    #[cfg_attr(feature = "serde", serde(serialize_with = "mass_or_inf"))]
    pub m1: Real,
    /// Mass of body 2 (kg; `"inf"` in JSON for a wall).
    #[cfg_attr(feature = "serde", serde(serialize_with = "mass_or_inf"))]
    pub m2: Real,
    /// The coefficient of restitution.
    pub restitution: Real,
    /// The friction coefficient.
    pub friction: Real,
    /// Velocity of body 1 before (m/s).
    pub v1_before: Vec<Real>,
    /// Velocity of body 2 before (m/s).
    pub v2_before: Vec<Real>,
    /// Velocity of body 1 after (m/s).
    pub v1: Vec<Real>,
    /// Velocity of body 2 after (m/s).
    pub v2: Vec<Real>,
    /// The impulse on body 2 (N·s).
    pub impulse: Vec<Real>,
    /// Its normal part `J_n` (N·s).
    pub normal_impulse: Real,
    /// The magnitude of its tangential part (N·s).
    pub tangential_impulse: Real,
    /// Whether friction stopped the sliding (only with friction and a tangential velocity).
    pub sticks: Option<bool>,
    /// Approach speed along the normal before (m/s).
    pub approach_speed: Real,
    /// Separation speed along the normal after (m/s).
    pub separation_speed: Real,
    /// Kinetic energy before (J).
    pub kinetic_before: Real,
    /// Kinetic energy after (J).
    pub kinetic_after: Real,
    /// Kinetic energy lost (J).
    pub kinetic_lost: Real,
    /// Velocity of the centre of mass (m/s).
    pub v_cm: Vec<Real>,
    /// Velocities relative to the centre of mass.
    pub cm_frame: CmFrame,
    /// With gravity: the rise of each body (`g`, `rise1`, `rise2` in JSON).
    #[cfg_attr(
        feature = "serde",
        serde(flatten, skip_serializing_if = "Option::is_none")
    )]
    pub rise: Option<Rise>,
}

#[cfg(feature = "serde")]
#[allow(clippy::trivially_copy_pass_by_ref)] // the signature serde asks for
fn mass_or_inf<S: serde::Serializer>(m: &Real, s: S) -> Result<S::Ok, S::Error> {
    if m.is_finite() {
        s.serialize_f64(*m)
    } else {
        s.serialize_str("inf")
    }
}

impl Collided {
    /// The report of collision `c` resolved to `o`, with the rise under `g` if given.
    pub fn new(c: &Collision, o: &Outcome, g: Option<Real>) -> Self {
        Self {
            collided: true,
            m1: c.m1,
            m2: c.m2,
            restitution: c.restitution.value(),
            friction: c.friction,
            v1_before: c.v1.clone(),
            v2_before: c.v2.clone(),
            v1: o.v1.clone(),
            v2: o.v2.clone(),
            impulse: o.impulse.clone(),
            normal_impulse: o.normal_impulse,
            tangential_impulse: o.tangential_impulse,
            sticks: o.sticks,
            approach_speed: o.approach_speed,
            separation_speed: o.separation_speed,
            kinetic_before: o.kinetic_before,
            kinetic_after: o.kinetic_after,
            kinetic_lost: o.energy_lost(),
            v_cm: o.v_cm.clone(),
            cm_frame: CmFrame {
                before: VelocityPair {
                    v1: o.cm_frame_before[0].clone(),
                    v2: o.cm_frame_before[1].clone(),
                },
                after: VelocityPair {
                    v1: o.cm_frame_after[0].clone(),
                    v2: o.cm_frame_after[1].clone(),
                },
            },
            rise: g.map(|g| {
                let [rise1, rise2] = o.rise(g);
                Rise { g, rise1, rise2 }
            }),
        }
    }

    /// The same report for display: velocities and energies smaller than 1e-12 of the speeds
    /// (energies) involved are rounding noise and set to 0, and `-0` is `0`.
    #[must_use]
    pub fn without_noise(&self) -> Self {
        let speed = self
            .v1_before
            .iter()
            .chain(&self.v2_before)
            .fold(self.approach_speed, |m, v| m.max(v.abs()));
        let snap = |x: Real, scale: Real| {
            if x.abs() <= 1e-12 * scale {
                0.0
            } else {
                x + 0.0
            }
        };
        let vec = |v: &[Real]| v.iter().map(|&x| snap(x, speed)).collect::<Vec<_>>();
        let mut r = self.clone();
        for v in [
            &mut r.v1,
            &mut r.v2,
            &mut r.v_cm,
            &mut r.cm_frame.before.v1,
            &mut r.cm_frame.before.v2,
            &mut r.cm_frame.after.v1,
            &mut r.cm_frame.after.v2,
        ] {
            *v = vec(v);
        }
        r.separation_speed = snap(r.separation_speed, speed);
        r.kinetic_after = snap(r.kinetic_after, r.kinetic_before);
        r.kinetic_lost = r.kinetic_before - r.kinetic_after + 0.0;
        r
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn setup(v1: &[Real], v2: &[Real]) -> CollisionSetup {
        CollisionSetup::new(1.0, v1.to_vec(), 1.0, v2.to_vec(), Restitution::ELASTIC)
    }

    #[test]
    fn a_single_zero_is_at_rest_in_any_dimension() {
        let c = setup(&[3.0, 0.0], &[0.0]);
        let c = CollisionSetup {
            contact: Contact::Normal(vec![1.0, 0.0]),
            ..c
        }
        .collision()
        .unwrap();
        assert_eq!(c.v2, vec![0.0, 0.0]);
        // a nonzero single component is not padded
        let e = CollisionSetup {
            contact: Contact::Normal(vec![1.0, 0.0]),
            ..setup(&[3.0, 0.0], &[1.0])
        }
        .collision()
        .unwrap_err();
        assert_eq!(e.input(), Some(CollisionInput::Velocity2));
        assert_eq!(
            e.to_string(),
            "the velocity of body 2 has 1 component but the velocity of body 1 has 2; give both with the same number of components (a single 0 is at rest)"
        );
    }

    #[test]
    fn errors_name_their_input() {
        let input = |s: CollisionSetup| s.report().unwrap_err().input();
        assert_eq!(
            input(setup(&[1.0, 0.0], &[0.0])),
            Some(CollisionInput::Normal)
        );
        assert_eq!(
            input(CollisionSetup {
                contact: Contact::Normal(vec![1.0, 0.0, 0.0]),
                ..setup(&[1.0, 0.0], &[0.0])
            }),
            Some(CollisionInput::Normal)
        );
        assert_eq!(
            input(CollisionSetup {
                contact: Contact::Centres {
                    r1: vec![0.0, 1.0],
                    r2: vec![0.0, 1.0]
                },
                ..setup(&[1.0, 0.0], &[0.0])
            }),
            Some(CollisionInput::Centres)
        );
        assert_eq!(
            input(CollisionSetup {
                m2: -1.0,
                ..setup(&[1.0], &[0.0])
            }),
            Some(CollisionInput::Mass2)
        );
        assert_eq!(
            input(CollisionSetup {
                g: Some(0.0),
                ..setup(&[1.0], &[0.0])
            }),
            Some(CollisionInput::Gravity)
        );
        assert_eq!(
            input(CollisionSetup {
                friction: -0.1,
                ..setup(&[1.0], &[0.0])
            }),
            Some(CollisionInput::Friction)
        );
        assert_eq!(
            Restitution::parse("2").unwrap_err().input(),
            Some(CollisionInput::Restitution)
        );
    }

    #[test]
    fn separating_bodies_report_no_collision() {
        let r = setup(&[-1.0], &[1.0]).report().unwrap();
        assert_eq!(
            r,
            CollisionReport::Separating(NoCollision {
                collided: false,
                approach_speed: -2.0
            })
        );
    }

    #[test]
    fn noise_is_removed_for_display_only() {
        // equal masses, elastic, oblique: body 1 keeps a tangential velocity only
        let s = CollisionSetup {
            contact: Contact::Centres {
                r1: vec![0.0, 0.0],
                r2: vec![0.8, 0.6],
            },
            ..setup(&[3.0, 0.0], &[0.0])
        };
        let CollisionReport::Collided(r) = s.report().unwrap() else {
            panic!("a collision")
        };
        let clean = r.without_noise();
        assert_eq!(clean.kinetic_lost, 0.0);
        assert!(clean.v1.iter().zip(&r.v1).all(|(a, b)| *a == 0.0 || a == b));
        assert_eq!(clean.kinetic_before, r.kinetic_before);
    }
}

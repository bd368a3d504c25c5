//! A collision as a front states it ([`CollisionSetup`]: masses, velocities, the contact as a
//! normal or two sphere centres, restitution, friction, optionally gravity) and its result
//! ([`CollisionReport`]: what `mechkit collide --json` prints): the velocities after, the
//! impulse, the energy lost, the centre-of-mass frame and, with gravity, the rise `v²/(2g)`
//! of each body.
//!
//! The inputs that errors name are [`CollisionInput`] (`report/input.rs`); the set-up and its
//! checks, [`CollisionSetup`] (`report/setup.rs`).

mod input;
mod setup;

pub use input::CollisionInput;
pub use setup::{CollisionSetup, Contact};

use crate::Real;

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

/// A resolved collision: the collision it resolved and what the impulse did. This is what
/// [`Collision::resolve`](crate::collisions::Collision::resolve) returns (its
/// [`Outcome`](crate::collisions::Outcome)) and what the report prints.
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
    /// The impulse on body 2 (N·s); body 1 receives its opposite.
    pub impulse: Vec<Real>,
    /// Its normal part `J_n ≥ 0` (N·s).
    pub normal_impulse: Real,
    /// The magnitude of its tangential part (N·s).
    pub tangential_impulse: Real,
    /// Whether friction stopped the sliding (only with friction and a tangential velocity).
    pub sticks: Option<bool>,
    /// Approach speed `u·n` along the normal before (m/s).
    pub approach_speed: Real,
    /// Separation speed along the normal after, `e` times the approach speed (m/s).
    pub separation_speed: Real,
    /// Kinetic energy before (J; an immovable body counts for nothing, and the energies are
    /// then those in its frame, which is the centre-of-mass frame).
    pub kinetic_before: Real,
    /// Kinetic energy after (J; in the immovable body's frame, if there is one).
    pub kinetic_after: Real,
    /// Kinetic energy lost, `K_before − K_after ≥ 0` (J).
    pub kinetic_lost: Real,
    /// Velocity of the centre of mass (m/s; that of the immovable body, if any).
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
    /// The same collision with the height each body rises afterwards under gravity `g` (none
    /// for `None`) when its whole speed turns into height: `h = |v|²/(2 g)`, the swing of a
    /// pendulum bob or of a ballistic pendulum (a string or a track turns the velocity upward
    /// without work).
    #[must_use]
    pub fn with_rise(self, g: Option<Real>) -> Self {
        let h = |v: &[Real], g: Real| v.iter().map(|x| x * x).sum::<Real>() / (2.0 * g);
        Self {
            rise: g.map(|g| Rise {
                g,
                rise1: h(&self.v1, g),
                rise2: h(&self.v2, g),
            }),
            ..self
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
    use crate::collisions::Restitution;

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

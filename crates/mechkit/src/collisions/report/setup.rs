//! A collision as a front states it ([`CollisionSetup`]: masses, velocities, the contact as a
//! normal or two sphere centres, restitution, friction, optionally gravity), checked into a
//! [`Collision`] (a single zero velocity padded to the other's dimension, the normal from the
//! contact) and resolved into its [`CollisionReport`].

use super::{CollisionInput, CollisionReport, NoCollision};
use crate::Real;
use crate::collisions::{Collision, CollisionError, Resolution, Restitution};

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
            Resolution::Collided(o) => CollisionReport::Collided(Box::new(o.with_rise(self.g))),
        })
    }
}

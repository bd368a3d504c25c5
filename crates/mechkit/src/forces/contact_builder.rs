//! Building a [`ContactForce`]: which bodies touch which (pairs of spheres, spheres and walls),
//! with which law and damping, checked before anything runs.

use thiserror::Error;

use super::contact::ContactForce;
use super::contact_law::{ContactDamping, ContactLaw};
use crate::Real;

/// Two bodies that push each other apart when their centres are closer than `reach`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactPair {
    /// First body.
    pub a: usize,
    /// Second body.
    pub b: usize,
    /// Centre distance at first touch, `R_a + R_b` (m).
    pub reach: Real,
}

/// A fixed plane wall (a line in 2-D, a point in 1-D) that a body of radius `radius` may not
/// cross: the overlap is `δ = radius - (x - point)·normal`.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactWall {
    /// The body.
    pub body: usize,
    /// The body's radius (m; zero for a point).
    pub radius: Real,
    /// A point of the wall.
    pub point: Vec<Real>,
    /// Unit normal pointing to the side where the body belongs (normalised by the builder).
    pub normal: Vec<Real>,
}

/// An invalid contact description.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum ContactError {
    /// Dimension other than 1, 2 or 3.
    #[error("contacts need 1, 2 or 3 dimensions, not {0}")]
    BadDimension(usize),
    /// No law given.
    #[error("the contact `{0}` has no law (linear or hertz)")]
    NoLaw(String),
    /// Stiffness not positive and finite.
    #[error("the contact stiffness must be positive and finite, not {}", crate::error::short(*.0))]
    BadStiffness(Real),
    /// A damping coefficient negative or not finite.
    #[error("the contact damping `{name}` must be non-negative and finite, not {}", crate::error::short(*value))]
    BadDamping {
        /// `c` or `alpha`.
        name: &'static str,
        /// Value given.
        value: Real,
    },
    /// A body paired with itself.
    #[error("body {0} cannot be in contact with itself")]
    SameBody(usize),
    /// The same two bodies listed twice (their force would count twice).
    #[error("the contact between bodies {a} and {b} is listed twice")]
    DuplicatePair {
        /// First body.
        a: usize,
        /// Second body.
        b: usize,
    },
    /// A pair's reach not positive and finite.
    #[error("the reach of bodies {a} and {b} must be positive and finite, not {} m", crate::error::short(*reach))]
    BadReach {
        /// First body.
        a: usize,
        /// Second body.
        b: usize,
        /// Value given.
        reach: Real,
    },
    /// A radius negative or not finite.
    #[error("the radius of body {body} must be non-negative and finite, not {} m", crate::error::short(*radius))]
    BadRadius {
        /// Body.
        body: usize,
        /// Value given.
        radius: Real,
    },
    /// A wall's point or normal with the wrong number of components.
    #[error(
        "a wall in {dim}-D needs {dim} components, its point has {point} and its normal {normal}"
    )]
    WallDimension {
        /// Dimensions of the contact.
        dim: usize,
        /// Components of the point.
        point: usize,
        /// Components of the normal.
        normal: usize,
    },
    /// A wall's point not finite.
    #[error("a wall's point must be finite, not {}", crate::error::short_tuple(.0))]
    BadWallPoint(Vec<Real>),
    /// A wall's normal zero or not finite.
    #[error("a wall's normal must be a finite non-zero vector, not {}", crate::error::short_tuple(.0))]
    BadNormal(Vec<Real>),
}

/// Builds a [`ContactForce`].
///
/// By default the force is named `contact`, undamped, and the total normal force of each
/// contact is clamped at zero (no attraction; see [`ContactForceBuilder::allow_attraction`]).
///
/// # Example
/// ```
/// use mechkit::forces::{ContactDamping, ContactForce, ContactLaw};
/// // three balls on a table, bouncing off each other and off the floor y = 0
/// let balls = [(0, 0.1), (1, 0.1), (2, 0.15)];
/// let contact = ContactForce::builder(2)
///     .law(ContactLaw::linear(1e4))
///     .damping(ContactDamping::Linear { c: 2.0 })
///     .spheres(&balls)
///     .wall(&[0.0, 0.0], &[0.0, 2.0], &balls)
///     .build()
///     .unwrap();
/// assert_eq!(contact.pairs().len(), 3);
/// assert_eq!(contact.pairs()[2].reach, 0.25);
/// assert_eq!(contact.walls()[0].normal, vec![0.0, 1.0]);
/// ```
#[derive(Debug, Clone, Default)]
pub struct ContactForceBuilder {
    dim: usize,
    name: Option<String>,
    law: Option<ContactLaw>,
    damping: ContactDamping,
    attraction: bool,
    pairs: Vec<ContactPair>,
    walls: Vec<ContactWall>,
}

impl ContactForceBuilder {
    /// Starts a contact force in `dim` dimensions.
    pub fn new(dim: usize) -> Self {
        Self {
            dim,
            ..Self::default()
        }
    }

    /// Names the force (default `contact`; its damper is `<name>_damping`).
    #[must_use]
    pub fn name(mut self, name: impl Into<String>) -> Self {
        self.name = Some(name.into());
        self
    }

    /// The elastic law.
    #[must_use]
    pub fn law(mut self, law: ContactLaw) -> Self {
        self.law = Some(law);
        self
    }

    /// The damping (default none).
    #[must_use]
    pub fn damping(mut self, damping: ContactDamping) -> Self {
        self.damping = damping;
        self
    }

    /// Whether the total normal force `F_e + F_d` may become negative, pulling the bodies
    /// together at the end of a damped contact. By default (`false`) it is clamped at zero, as
    /// real bodies do not stick; allowing it gives the textbook spring-dashpot, whose
    /// restitution is [`crate::forces::linear_restitution`].
    #[must_use]
    pub fn allow_attraction(mut self, allow: bool) -> Self {
        self.attraction = allow;
        self
    }

    /// Bodies `a` and `b` touch when their centres are `reach = R_a + R_b` apart.
    #[must_use]
    pub fn pair(mut self, a: usize, b: usize, reach: Real) -> Self {
        self.pairs.push(ContactPair { a, b, reach });
        self
    }

    /// Every two of `spheres` (body index, radius) touch: `reach = R_a + R_b`.
    #[must_use]
    pub fn spheres(mut self, spheres: &[(usize, Real)]) -> Self {
        for (n, &(a, ra)) in spheres.iter().enumerate() {
            for &(b, rb) in &spheres[n + 1..] {
                self.pairs.push(ContactPair {
                    a,
                    b,
                    reach: ra + rb,
                });
            }
        }
        self
    }

    /// A wall through `point` with `normal` (any length; pointing to the side where the
    /// bodies belong) that each of `bodies` (body index, radius) touches.
    #[must_use]
    pub fn wall(mut self, point: &[Real], normal: &[Real], bodies: &[(usize, Real)]) -> Self {
        for &(body, radius) in bodies {
            self.walls.push(ContactWall {
                body,
                radius,
                point: point.to_vec(),
                normal: normal.to_vec(),
            });
        }
        self
    }

    /// Checks everything, normalises the walls' normals and builds.
    pub fn build(self) -> Result<ContactForce, ContactError> {
        let dim = self.dim;
        if !(1..=3).contains(&dim) {
            return Err(ContactError::BadDimension(dim));
        }
        let name = self.name.unwrap_or_else(|| "contact".into());
        let law = self.law.ok_or_else(|| ContactError::NoLaw(name.clone()))?;
        let k = law.k();
        if !(k > 0.0 && k.is_finite()) {
            return Err(ContactError::BadStiffness(k));
        }
        let (coefficient, value) = match self.damping {
            ContactDamping::None => ("", 0.0),
            ContactDamping::Linear { c } => ("c", c),
            ContactDamping::HuntCrossley { alpha } => ("alpha", alpha),
        };
        if !(value >= 0.0 && value.is_finite()) {
            return Err(ContactError::BadDamping {
                name: coefficient,
                value,
            });
        }
        for (i, p) in self.pairs.iter().enumerate() {
            if p.a == p.b {
                return Err(ContactError::SameBody(p.a));
            }
            if !(p.reach > 0.0 && p.reach.is_finite()) {
                return Err(ContactError::BadReach {
                    a: p.a,
                    b: p.b,
                    reach: p.reach,
                });
            }
            let same = |o: &ContactPair| (o.a, o.b) == (p.a, p.b) || (o.a, o.b) == (p.b, p.a);
            if self.pairs[..i].iter().any(same) {
                return Err(ContactError::DuplicatePair { a: p.a, b: p.b });
            }
        }
        let mut walls = self.walls;
        for w in &mut walls {
            if !(w.radius >= 0.0 && w.radius.is_finite()) {
                return Err(ContactError::BadRadius {
                    body: w.body,
                    radius: w.radius,
                });
            }
            if w.point.len() != dim || w.normal.len() != dim {
                return Err(ContactError::WallDimension {
                    dim,
                    point: w.point.len(),
                    normal: w.normal.len(),
                });
            }
            if !w.point.iter().all(|x| x.is_finite()) {
                return Err(ContactError::BadWallPoint(w.point.clone()));
            }
            let norm = w.normal.iter().map(|x| x * x).sum::<Real>().sqrt();
            if !(norm > 0.0 && norm.is_finite()) {
                return Err(ContactError::BadNormal(w.normal.clone()));
            }
            for c in &mut w.normal {
                *c /= norm;
            }
        }
        Ok(ContactForce {
            name,
            dim,
            law,
            damping: self.damping,
            attraction: self.attraction,
            pairs: self.pairs,
            walls,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn linear() -> ContactForceBuilder {
        ContactForceBuilder::new(2).law(ContactLaw::linear(100.0))
    }

    #[test]
    fn bad_descriptions_are_refused() {
        let err = |b: ContactForceBuilder| b.build().unwrap_err();
        assert_eq!(
            err(ContactForceBuilder::new(4)),
            ContactError::BadDimension(4)
        );
        assert!(matches!(
            err(ContactForceBuilder::new(2)),
            ContactError::NoLaw(_)
        ));
        let nan_damping = linear().damping(ContactDamping::HuntCrossley { alpha: Real::NAN });
        assert!(matches!(
            err(nan_damping),
            ContactError::BadDamping { name: "alpha", .. }
        ));
        assert_eq!(err(linear().pair(1, 1, 0.2)), ContactError::SameBody(1));
        assert!(matches!(
            err(linear().pair(0, 1, 0.0)),
            ContactError::BadReach { .. }
        ));
        assert_eq!(
            err(linear().spheres(&[(0, 0.1), (1, 0.1)]).pair(1, 0, 0.2)),
            ContactError::DuplicatePair { a: 1, b: 0 }
        );
        let wall = |p: &[Real], n: &[Real], r: Real| linear().wall(p, n, &[(0, r)]);
        assert!(matches!(
            err(wall(&[0.0, 0.0], &[0.0, 1.0], -0.1)),
            ContactError::BadRadius { .. }
        ));
        assert!(matches!(
            err(wall(&[0.0], &[0.0, 1.0], 0.1)),
            ContactError::WallDimension {
                dim: 2,
                point: 1,
                normal: 2
            }
        ));
        assert!(matches!(
            err(wall(&[0.0, Real::INFINITY], &[0.0, 1.0], 0.1)),
            ContactError::BadWallPoint(_)
        ));
        assert!(matches!(
            err(wall(&[0.0, 0.0], &[Real::NAN, 1.0], 0.1)),
            ContactError::BadNormal(_)
        ));
    }

    #[test]
    fn zero_radius_and_zero_damping_are_fine() {
        let c = linear()
            .damping(ContactDamping::Linear { c: 0.0 })
            .wall(&[1.0, 0.0], &[-3.0, 4.0], &[(0, 0.0)])
            .build()
            .unwrap();
        assert_eq!(c.walls()[0].normal, vec![-0.6, 0.8]);
        assert!(c.damper().is_none());
    }
}

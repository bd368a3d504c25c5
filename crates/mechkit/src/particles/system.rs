//! A system of point particles under a set of forces.

use thiserror::Error;

mod evaluate;
mod jacobian;

pub use jacobian::CompiledJacobian;

use super::kinematics::{Kinematics, dot};
use super::spin::{Mat3, Spinner};
use super::vars::Coordinates;
use crate::Real;
use crate::forces::{Force, ForceSet};

/// A point mass.
#[derive(Debug, Clone, PartialEq)]
pub struct Body {
    /// Name, unique in its system.
    pub name: String,
    /// Mass in kg (positive).
    pub mass: Real,
}

/// Invalid system description.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum SystemError {
    /// Dimension other than 1, 2 or 3.
    #[error("dimensions must be 1, 2 or 3, not {0}")]
    BadDimension(usize),
    /// Mass not positive, finite and invertible ([`crate::invertible`]).
    #[error("the mass of `{name}` must be positive, finite and at least 2.2e-308 kg (its reciprocal must be finite), not {} kg", crate::error::short(*mass))]
    BadMass {
        /// Body.
        name: String,
        /// Mass given.
        mass: Real,
    },
    /// Two bodies with one name.
    #[error("two bodies are named `{0}`")]
    DuplicateBody(String),
    /// Two forces with one name.
    #[error("two forces are named `{0}`")]
    DuplicateForce(String),
    /// A force refers to a body that does not exist.
    #[error("force `{force}` acts on body {body}, but the system has {n} bodies")]
    NoSuchBody {
        /// Force.
        force: String,
        /// Body index.
        body: usize,
        /// Number of bodies.
        n: usize,
    },
    /// No bodies.
    #[error("the system has no bodies")]
    Empty,
    /// An inertia tensor that is not symmetric positive definite.
    #[error("the inertia tensor of `{0}` must be symmetric with positive principal moments")]
    BadInertia(String),
    /// A rigid body turning in space outside 3 dimensions.
    #[error("a rigid body turns in space only in 3 dimensions, not {0}")]
    SpinNotThreeDimensional(usize),
    /// Angle coordinates in more than one dimension.
    #[error("angle coordinates have one angle per body (dimension 1), not {0}")]
    AngleNotOneDimensional(usize),
}

/// A coordinate after the bodies' positions: the angle of a rigid body in a plane (its
/// "mass" the moment of inertia about the centre of mass), or a mode of a joint (a frozen
/// coordinate: infinite inertia, changed only by events).
#[derive(Debug, Clone, PartialEq)]
pub struct Extra {
    /// Its name in outputs (`ladder.theta`, `wall.mode`).
    pub name: String,
    /// The body it turns, for an angle.
    pub body: Option<usize>,
    /// Moment of inertia about the centre of mass (kg m²); 0 for a mode.
    pub inertia: Real,
    /// The body whose mass it is, for a variable mass (its rate is `dm/dt`, changed only by
    /// events: a burn ending).
    pub mass_of: Option<usize>,
    /// The body whose orientation it is a component of, for a rigid body in space (four
    /// coordinates: a quaternion, see [`super::spin`]).
    pub orientation: Option<usize>,
}

/// Bodies and forces in 1, 2 or 3 dimensions.
#[derive(Debug)]
pub struct ParticleSystem {
    dim: usize,
    bodies: Vec<Body>,
    extras: Vec<Extra>,
    mass: Vec<Real>,
    inv_mass: Vec<Real>,
    forces: ForceSet,
    velocity_dependent: bool,
    coordinates: Coordinates,
    /// `(body, index in q)` of the variable masses.
    variable: Vec<(usize, usize)>,
    /// The rigid bodies turning in space.
    spinners: Vec<Spinner>,
    /// The compiled Jacobian of the accelerations, built the first time an implicit method
    /// asks for it (`None` inside when it cannot be compiled).
    jacobian: std::sync::OnceLock<Option<CompiledJacobian>>,
}

/// Builds a [`ParticleSystem`].
///
/// # Example
/// ```
/// use mechkit::particles::ParticleSystem;
/// use mechkit::forces::UniformGravity;
/// let sys = ParticleSystem::builder(1)
///     .body("ball", 0.1)
///     .force(UniformGravity::new("gravity", vec![0], 9.81))
///     .build()
///     .unwrap();
/// let mut a = [0.0];
/// use mechkit::ode::SecondOrderSystem;
/// sys.accel_into(0.0, &[1.0], &[0.0], &mut a);
/// assert_eq!(a[0], -9.81);
/// ```
#[derive(Debug, Default)]
pub struct ParticleSystemBuilder {
    dim: usize,
    bodies: Vec<Body>,
    extras: Vec<Extra>,
    forces: ForceSet,
    coordinates: Coordinates,
    spin_inertia: Vec<(usize, Mat3)>,
}

impl ParticleSystemBuilder {
    /// Adds a body.
    #[must_use]
    pub fn body(mut self, name: impl Into<String>, mass: Real) -> Self {
        self.bodies.push(Body {
            name: name.into(),
            mass,
        });
        self
    }

    /// Adds a force.
    #[must_use]
    pub fn force(mut self, force: impl Force + 'static) -> Self {
        self.forces.push(Box::new(force));
        self
    }

    /// Adds an angle coordinate to body `body`, a rigid body in a plane with moment of
    /// inertia `inertia` about its centre of mass; returns its index among the extras.
    #[must_use]
    pub fn rotor(mut self, name: impl Into<String>, body: usize, inertia: Real) -> Self {
        self.extras.push(Extra {
            name: name.into(),
            body: Some(body),
            inertia,
            mass_of: None,
            orientation: None,
        });
        self
    }

    /// Adds the orientation of body `body`, a rigid body in space whose inertia tensor about
    /// the centre of mass is `inertia` (body frame): four coordinates `name.q0` … `name.q3`, a
    /// quaternion (body → world) whose rate gives the angular velocity ([`super::spin`]).
    #[must_use]
    pub fn spinner(mut self, name: &str, body: usize, inertia: Mat3) -> Self {
        for k in 0..4 {
            self.extras.push(Extra {
                name: format!("{name}.q{k}"),
                body: None,
                inertia: 0.0,
                mass_of: None,
                orientation: Some(body),
            });
        }
        self.spin_inertia.push((body, inertia));
        self
    }

    /// Adds a frozen mode coordinate (changed only by events).
    #[must_use]
    pub fn mode(mut self, name: impl Into<String>) -> Self {
        self.extras.push(Extra {
            name: name.into(),
            body: None,
            inertia: 0.0,
            mass_of: None,
            orientation: None,
        });
        self
    }

    /// Makes the mass of body `body` a coordinate (its value the mass, its rate `dm/dt`).
    #[must_use]
    pub fn variable_mass(mut self, name: impl Into<String>, body: usize) -> Self {
        self.extras.push(Extra {
            name: name.into(),
            body: None,
            inertia: 0.0,
            mass_of: Some(body),
            orientation: None,
        });
        self
    }

    /// Adds a boxed force.
    #[must_use]
    pub fn boxed_force(mut self, force: Box<dyn Force>) -> Self {
        self.forces.push(force);
        self
    }

    /// Sets what the coordinates are: [`Coordinates::Angle`] makes every body a rigid body
    /// turning about a fixed axis (1-D only: one angle per body, the "mass" is the moment of
    /// inertia about the axis and the forces are torques).
    #[must_use]
    pub fn coordinates(mut self, coordinates: Coordinates) -> Self {
        self.coordinates = coordinates;
        self
    }

    /// Validates and builds.
    pub fn build(self) -> Result<ParticleSystem, SystemError> {
        if !(1..=3).contains(&self.dim) {
            return Err(SystemError::BadDimension(self.dim));
        }
        if self.bodies.is_empty() {
            return Err(SystemError::Empty);
        }
        if self.coordinates == Coordinates::Angle && self.dim != 1 {
            return Err(SystemError::AngleNotOneDimensional(self.dim));
        }
        for (i, b) in self.bodies.iter().enumerate() {
            if !crate::invertible(b.mass) {
                return Err(SystemError::BadMass {
                    name: b.name.clone(),
                    mass: b.mass,
                });
            }
            if self.bodies[..i].iter().any(|o| o.name == b.name) {
                return Err(SystemError::DuplicateBody(b.name.clone()));
            }
        }
        let n = self.bodies.len();
        for (i, f) in self.forces.iter().enumerate() {
            if self.forces.iter().take(i).any(|o| o.name() == f.name()) {
                return Err(SystemError::DuplicateForce(f.name().to_string()));
            }
            if let Some(&body) = f.bodies().iter().find(|&&b| b >= n) {
                return Err(SystemError::NoSuchBody {
                    force: f.name().to_string(),
                    body,
                    n,
                });
            }
        }
        for e in &self.extras {
            if e.body.is_some() && !crate::invertible(e.inertia) {
                return Err(SystemError::BadMass {
                    name: e.name.clone(),
                    mass: e.inertia,
                });
            }
        }
        let start = self.dim * self.bodies.len();
        let mut spinners = Vec::new();
        for (body, inertia) in &self.spin_inertia {
            if self.dim != 3 {
                return Err(SystemError::SpinNotThreeDimensional(self.dim));
            }
            let name = || {
                self.bodies
                    .get(*body)
                    .map_or(String::new(), |b| b.name.clone())
            };
            if *body >= self.bodies.len() {
                return Err(SystemError::NoSuchBody {
                    force: "orientation".into(),
                    body: *body,
                    n: self.bodies.len(),
                });
            }
            let first = self
                .extras
                .iter()
                .position(|e| e.orientation == Some(*body))
                .map_or(0, |k| start + k);
            spinners.push(
                Spinner::new(*body, first, *inertia)
                    .ok_or_else(|| SystemError::BadInertia(name()))?,
            );
        }
        let mass: Vec<Real> = self.bodies.iter().map(|b| b.mass).collect();
        let inv_mass = self
            .bodies
            .iter()
            .flat_map(|b| std::iter::repeat_n(1.0 / b.mass, self.dim))
            .chain(self.extras.iter().map(|e| {
                if e.body.is_some() {
                    1.0 / e.inertia
                } else if e.orientation.is_some() {
                    // the spinners' step leaves accelerations there
                    1.0
                } else {
                    0.0
                }
            }))
            .collect();
        let velocity_dependent = self.forces.velocity_dependent() || !spinners.is_empty();
        let variable = self
            .extras
            .iter()
            .enumerate()
            .filter_map(|(i, e)| e.mass_of.map(|b| (b, start + i)))
            .collect();
        Ok(ParticleSystem {
            variable,
            dim: self.dim,
            bodies: self.bodies,
            extras: self.extras,
            mass,
            inv_mass,
            forces: self.forces,
            velocity_dependent,
            coordinates: self.coordinates,
            spinners,
            jacobian: std::sync::OnceLock::new(),
        })
    }
}

impl ParticleSystem {
    /// Starts a system in `dim` dimensions.
    pub fn builder(dim: usize) -> ParticleSystemBuilder {
        ParticleSystemBuilder {
            dim,
            ..Default::default()
        }
    }

    /// Spatial dimensions.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// What the coordinates are (positions, or angles about fixed axes).
    pub fn coordinates(&self) -> Coordinates {
        self.coordinates
    }

    /// The bodies.
    pub fn bodies(&self) -> &[Body] {
        &self.bodies
    }

    /// The coordinates after the bodies' positions (angles of rigid bodies, joint modes).
    pub fn extras(&self) -> &[Extra] {
        &self.extras
    }

    /// Index in `q` of the first extra coordinate.
    pub fn extras_start(&self) -> usize {
        self.dim * self.bodies.len()
    }

    /// Rotational kinetic energy `Σ ½ I ω²` of the rigid bodies in a plane, and `Σ ½ ω·Iω`
    /// of those turning in space (which reads their orientation from `q`).
    pub fn rotational_kinetic_energy(&self, q: &[Real], v: &[Real]) -> Real {
        let start = self.extras_start();
        let planar: Real = self
            .extras
            .iter()
            .enumerate()
            .filter(|(_, e)| e.body.is_some())
            .map(|(i, e)| 0.5 * e.inertia * v[start + i] * v[start + i])
            .sum();
        planar
            + self
                .spinners
                .iter()
                .map(|s| {
                    let (qq, qd) = s.of(q, v);
                    s.kinetic(qq, qd)
                })
                .sum::<Real>()
    }

    /// The rigid bodies turning in space.
    pub fn spinners(&self) -> &[Spinner] {
        &self.spinners
    }

    /// Whether some body turns (a rigid body in a plane or in space).
    pub fn has_rotation(&self) -> bool {
        !self.spinners.is_empty() || self.extras.iter().any(|e| e.body.is_some())
    }

    /// Replaces the generalized forces on the spinners' coordinates in `a` by their `q̈`
    /// (Euler's equations); before the division by the masses, which leaves them.
    #[inline]
    fn turn(&self, q: &[Real], v: &[Real], a: &mut [Real]) {
        for s in &self.spinners {
            let (qq, qd) = s.of(q, v);
            let f = s.first;
            let out = s.accel(qq, qd, [a[f], a[f + 1], a[f + 2], a[f + 3]]);
            a[f..f + 4].copy_from_slice(&out);
        }
    }

    /// Masses, one per body.
    pub fn masses(&self) -> &[Real] {
        &self.mass
    }

    /// `1/m` of each coordinate's body.
    pub(crate) fn inverse_masses(&self) -> &[Real] {
        &self.inv_mass
    }

    /// Index of the body named `name`.
    pub fn body_index(&self, name: &str) -> Option<usize> {
        self.bodies.iter().position(|b| b.name == name)
    }

    /// The forces.
    pub fn forces(&self) -> &ForceSet {
        &self.forces
    }

    /// Whether any potential is defined (so `U` and `E` mean something).
    pub fn has_potential(&self, q: &[Real], v: &[Real]) -> bool {
        let k = self.kinematics(0.0, q, v);
        self.forces.iter().any(|f| f.potential(&k).is_some())
    }

    /// Whether some body's mass varies (a rocket).
    pub fn has_variable_mass(&self) -> bool {
        !self.variable.is_empty()
    }

    /// The masses at a state (the variable ones read from `q`).
    pub fn masses_at(&self, q: &[Real], out: &mut Vec<Real>) {
        out.clear();
        out.extend_from_slice(&self.mass);
        for &(b, i) in &self.variable {
            out[b] = q[i];
        }
    }

    /// The force view of a state.
    pub fn kinematics<'a>(&'a self, t: Real, q: &'a [Real], v: &'a [Real]) -> Kinematics<'a> {
        Kinematics {
            t,
            dim: self.dim,
            x: q,
            v,
            mass: &self.mass,
        }
    }

    /// Kinetic energy `Σ m v²/2` (and `Σ I ω²/2` of the rigid bodies) at `(q, v)`.
    pub fn kinetic_energy(&self, q: &[Real], v: &[Real]) -> Real {
        self.rotational_kinetic_energy(q, v)
            + self
                .mass
                .iter()
                .enumerate()
                .map(|(i, m)| {
                    let vi = &v[i * self.dim..(i + 1) * self.dim];
                    0.5 * m * dot(vi, vi)
                })
                .sum::<Real>()
    }
}

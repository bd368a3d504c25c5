//! The names formulas use for the state: `t`, `x`, `vy`, `v`, `r`, `m`, `feather.x`, `K`,
//! `work.air`, … and formulas compiled against them.
//!
//! | name | meaning | unit |
//! |---|---|---|
//! | `t` | time | s |
//! | `x`, `y`, `z` | position components (as many as dimensions) | m |
//! | `vx`, `vy`, `vz` | velocity components | m/s |
//! | `v` | velocity in 1-D (signed); speed in 2-D/3-D | m/s |
//! | `speed` | speed `|v|` | m/s |
//! | `r` | distance from the origin | m |
//! | `m` | mass | kg |
//! | `ax`, `ay`, `az`, `a` | acceleration (`a`: signed in 1-D, magnitude otherwise)¹ | m/s² |
//! | `K` (per body: `name.K`) | kinetic energy¹ | J |
//! | `U`, `E` | potential energy of the conservative forces, `K + U`¹ | J |
//! | `work.F`, `power.F` | work done so far and power of the force named `F`¹ | J, W |
//!
//! Body quantities are written `name.x`; a bare `x` means the body a force acts on, or the only
//! body of a one-body scenario. ¹ Not available inside forces (they would depend on forces).

use mechkit_expr::Dim;
use mechkit_expr::units::{Dimension, UnitSystem};

use super::body_refs::{PointRef, SpinField, SpinRef};
use super::kinematics::{Kinematics, dot, norm};
use super::sample::Sample;
use crate::Real;

/// Which body a name refers to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BodyRef {
    /// The body the formula is being evaluated for (a force's target).
    Local,
    /// A specific body.
    Index(usize),
}

/// A quantity of the state, by meaning.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum StateVar {
    /// Time.
    Time,
    /// Position component.
    Position(BodyRef, usize),
    /// Velocity component.
    Velocity(BodyRef, usize),
    /// Speed.
    Speed(BodyRef),
    /// Distance from the origin.
    Distance(BodyRef),
    /// Mass.
    Mass(BodyRef),
    /// Acceleration component.
    Acceleration(BodyRef, usize),
    /// Magnitude of the acceleration.
    AccelerationMagnitude(BodyRef),
    /// Kinetic energy of one body.
    BodyKinetic(BodyRef),
    /// Total kinetic energy.
    Kinetic,
    /// Total potential energy of the conservative forces.
    Potential,
    /// `K + U`.
    Energy,
    /// Work done by force `i` so far.
    Work(usize),
    /// Power of force `i`.
    Power(usize),
    /// Coordinate `i` of `q` (the angle of a rigid body in a plane).
    Coordinate(usize),
    /// Rate of coordinate `i` (an angular velocity).
    CoordinateRate(usize),
    /// Second derivative of coordinate `i` (an angular acceleration).
    CoordinateAccel(usize),
    /// Component of the position of a body point.
    PointPosition(PointRef, usize),
    /// Component of the velocity of a body point.
    PointVelocity(PointRef, usize),
    /// Kinetic energy of a rigid body, `½ m v² + ½ I ω²`.
    RigidKinetic(PointRef),
    /// Rotational kinetic energy of all the rigid bodies.
    KineticRotation,
    /// The mass of a body whose mass varies: coordinate `i` of `q`.
    VariableMass(usize),
    /// The kinetic energy `½ m v²` of body `.0`, whose mass is coordinate `.1` of `q`.
    VariableKinetic(usize, usize),
    /// Field `k` of what constraint force `i` reports
    /// ([`crate::rigid::mechanism::REPORT_FIELDS`]).
    Constraint(usize, usize),
    /// A quantity of a rigid body turning in space.
    Spin(SpinRef, SpinField),
}

/// Which names a formula may use.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum VarLevel {
    /// Time, positions, velocities, masses: what a force may depend on.
    Kinematic,
    /// Also accelerations, energies, work and power: for conditions, observables and plots.
    Derived,
}

pub(crate) const AXES: [&str; 3] = ["x", "y", "z"];
pub(crate) const ANGLE: [&str; 3] = ["theta", "omega", "alpha"];

/// What a body's coordinate is: a position in space, or the angle of a body turning about a
/// fixed axis (a hinged rigid body, whose "mass" is then its moment of inertia about the
/// axis and whose forces are torques).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Coordinates {
    /// Positions `x`, `y`, `z` in metres, velocities `vx`…, masses in kg.
    #[default]
    Cartesian,
    /// One angle `theta` in radians per body (1-D), angular velocity `omega`, angular
    /// acceleration `alpha`, moment of inertia `I`; the generalised forces are torques and
    /// the momentum is the angular momentum `I omega` about the axis.
    Angle,
}

impl Coordinates {
    /// The dimension of a state quantity in these coordinates.
    pub fn dimension(self, var: StateVar) -> Dimension {
        match (self, var) {
            (Coordinates::Angle, StateVar::Position(..)) => Dimension::NONE,
            (Coordinates::Angle, StateVar::Velocity(..)) => Dimension::FREQUENCY,
            (Coordinates::Angle, StateVar::Acceleration(..)) => {
                Dimension::base([0, 0, -2, 0, 0, 0, 0])
            }
            (Coordinates::Angle, StateVar::Mass(_)) => Dimension::MOMENT_OF_INERTIA,
            _ => var.dimension(),
        }
    }

    /// The SI unit to label a state quantity with in these coordinates.
    pub fn unit(self, var: StateVar) -> &'static str {
        match (self, var) {
            (Coordinates::Angle, StateVar::Position(..)) => "rad",
            (Coordinates::Angle, StateVar::Velocity(..)) => "rad/s",
            (Coordinates::Angle, StateVar::Acceleration(..)) => "rad/s²",
            (Coordinates::Angle, StateVar::Mass(_)) => "kg m²",
            _ => var.unit(),
        }
    }

    /// The names of the position, velocity and acceleration components of a body in `dim`
    /// dimensions: `x`, `vx`, `ax`, … or `theta`, `omega`, `alpha`.
    pub fn component_names(self, dim: usize) -> [Vec<&'static str>; 3] {
        match self {
            Coordinates::Cartesian => [
                AXES[..dim].to_vec(),
                VAXES[..dim].to_vec(),
                AAXES[..dim].to_vec(),
            ],
            Coordinates::Angle => [vec![ANGLE[0]], vec![ANGLE[1]], vec![ANGLE[2]]],
        }
    }
}

impl Coordinates {
    /// The dimension a formula sees for a state quantity: its dimension in SI units; in
    /// reduced units none that could conflict (a pure number of unstated scale, so
    /// `(b.x - a.x)^-12 - (b.x - a.x)^-6` is a valid formula).
    pub fn dim_in(self, var: StateVar, units: UnitSystem) -> Dim {
        match units {
            UnitSystem::Si => Dim::Known(self.dimension(var)),
            UnitSystem::Reduced => Dim::Unknown,
        }
    }

    /// The unit to label a state quantity with: [`Coordinates::unit`] in SI, `1` in reduced
    /// units.
    pub fn unit_in(self, var: StateVar, units: UnitSystem) -> &'static str {
        match units {
            UnitSystem::Si => self.unit(var),
            UnitSystem::Reduced => UnitSystem::REDUCED_UNIT,
        }
    }
}

pub(crate) const VAXES: [&str; 3] = ["vx", "vy", "vz"];
pub(crate) const AAXES: [&str; 3] = ["ax", "ay", "az"];

impl StateVar {
    /// Whether a force may depend on it.
    pub fn is_kinematic(self) -> bool {
        matches!(
            self,
            StateVar::Time
                | StateVar::Position(..)
                | StateVar::Velocity(..)
                | StateVar::Speed(_)
                | StateVar::Distance(_)
                | StateVar::Mass(_)
                | StateVar::Coordinate(_)
                | StateVar::CoordinateRate(_)
                | StateVar::PointPosition(..)
                | StateVar::PointVelocity(..)
                | StateVar::VariableMass(_)
        ) || matches!(self, StateVar::Spin(_, f) if !matches!(f, SpinField::Alpha(_) | SpinField::Kinetic))
    }

    /// Its dimension.
    pub fn dimension(self) -> Dimension {
        match self {
            StateVar::Time => Dimension::TIME,
            StateVar::Position(..)
            | StateVar::Distance(_)
            | StateVar::PointPosition(..)
            | StateVar::Constraint(_, 4) => Dimension::LENGTH,
            StateVar::Velocity(..) | StateVar::Speed(_) | StateVar::PointVelocity(..) => {
                Dimension::VELOCITY
            }
            StateVar::Mass(_) | StateVar::VariableMass(_) => Dimension::MASS,
            StateVar::Acceleration(..) | StateVar::AccelerationMagnitude(_) => {
                Dimension::ACCELERATION
            }
            StateVar::BodyKinetic(_)
            | StateVar::Kinetic
            | StateVar::Potential
            | StateVar::Energy
            | StateVar::Work(_)
            | StateVar::RigidKinetic(_)
            | StateVar::VariableKinetic(..)
            | StateVar::KineticRotation => Dimension::ENERGY,
            StateVar::Power(_) => Dimension::POWER,
            StateVar::Coordinate(_) => Dimension::NONE,
            StateVar::CoordinateRate(_) => Dimension::FREQUENCY,
            StateVar::CoordinateAccel(_) => Dimension::base([0, 0, -2, 0, 0, 0, 0]),
            StateVar::Constraint(..) => Dimension::FORCE,
            StateVar::Spin(_, f) => match f {
                SpinField::Omega(_) | SpinField::OmegaBody(_) | SpinField::Speed => {
                    Dimension::FREQUENCY
                }
                SpinField::Quaternion(_) => Dimension::NONE,
                SpinField::Alpha(_) => Dimension::base([0, 0, -2, 0, 0, 0, 0]),
                SpinField::Momentum(_) | SpinField::MomentumMagnitude => {
                    Dimension::ANGULAR_MOMENTUM
                }
                SpinField::Kinetic => Dimension::ENERGY,
            },
        }
    }

    /// The SI unit to label it with.
    pub fn unit(self) -> &'static str {
        match self {
            StateVar::Time => "s",
            StateVar::Position(..)
            | StateVar::Distance(_)
            | StateVar::PointPosition(..)
            | StateVar::Constraint(_, 4) => "m",
            StateVar::Velocity(..) | StateVar::Speed(_) | StateVar::PointVelocity(..) => "m/s",
            StateVar::Mass(_) | StateVar::VariableMass(_) => "kg",
            StateVar::Acceleration(..) | StateVar::AccelerationMagnitude(_) => "m/s²",
            StateVar::Power(_) => "W",
            StateVar::Coordinate(_) => "rad",
            StateVar::CoordinateRate(_) => "rad/s",
            StateVar::CoordinateAccel(_) => "rad/s²",
            StateVar::Constraint(..) => "N",
            StateVar::Spin(_, f) => match f {
                SpinField::Omega(_) | SpinField::OmegaBody(_) | SpinField::Speed => "rad/s",
                SpinField::Quaternion(_) => "1",
                SpinField::Alpha(_) => "rad/s²",
                SpinField::Momentum(_) | SpinField::MomentumMagnitude => "kg m²/s",
                SpinField::Kinetic => "J",
            },
            _ => "J",
        }
    }

    fn body(self, local: Option<usize>) -> usize {
        let (StateVar::Position(r, _)
        | StateVar::Velocity(r, _)
        | StateVar::Speed(r)
        | StateVar::Distance(r)
        | StateVar::Mass(r)
        | StateVar::Acceleration(r, _)
        | StateVar::AccelerationMagnitude(r)
        | StateVar::BodyKinetic(r)) = self
        else {
            return 0;
        };
        match r {
            BodyRef::Index(i) => i,
            BodyRef::Local => local.expect("a formula with body-local names needs a body"),
        }
    }

    /// Value from the kinematics (only for [`StateVar::is_kinematic`] quantities).
    #[inline]
    pub fn value_kinematic(self, k: &Kinematics<'_>, local: Option<usize>) -> Real {
        let d = k.dim;
        match self {
            StateVar::Time => k.t,
            StateVar::Position(_, i) => k.x[self.body(local) * d + i],
            StateVar::Velocity(_, i) => k.v[self.body(local) * d + i],
            StateVar::Speed(_) => norm(k.velocity(self.body(local))),
            StateVar::Distance(_) => norm(k.position(self.body(local))),
            StateVar::Mass(_) => k.mass[self.body(local)],
            StateVar::Coordinate(i) | StateVar::VariableMass(i) => k.x[i],
            StateVar::CoordinateRate(i) => k.v[i],
            StateVar::PointPosition(p, i) => p.value(k.x, k.v, d, i, false),
            StateVar::PointVelocity(p, i) => p.value(k.x, k.v, d, i, true),
            StateVar::Spin(s, f) if self.is_kinematic() => {
                s.value(f, k.x, k.v, &[], k.mass[s.body], d)
            }
            other => panic!("{other:?} is not a kinematic quantity"),
        }
    }

    /// Value in a sample of a system with `dim` dimensions and body masses `mass`.
    pub fn value(self, s: &Sample<'_>, dim: usize, mass: &[Real], local: Option<usize>) -> Real {
        let b = self.body(local);
        match self {
            StateVar::Acceleration(_, i) => s.eval.a[b * dim + i],
            StateVar::AccelerationMagnitude(_) => norm(&s.eval.a[b * dim..(b + 1) * dim]),
            StateVar::BodyKinetic(_) => {
                let v = &s.v[b * dim..(b + 1) * dim];
                0.5 * mass[b] * dot(v, v)
            }
            StateVar::Kinetic => s.eval.kinetic,
            StateVar::Potential => s.eval.potential_total.unwrap_or(Real::NAN),
            StateVar::Energy => s.energy(),
            StateVar::Work(i) => s.work[i],
            StateVar::Power(i) => s.eval.power[i],
            StateVar::CoordinateAccel(i) => s.eval.a[i],
            StateVar::KineticRotation => s.eval.kinetic_rotation,
            StateVar::VariableKinetic(b, i) => {
                let v = &s.v[b * dim..(b + 1) * dim];
                0.5 * s.q[i] * dot(v, v)
            }
            StateVar::Constraint(i, k) => s
                .eval
                .constraint
                .get(i * crate::rigid::mechanism::REPORT_LEN + k)
                .copied()
                .unwrap_or(Real::NAN),
            StateVar::Spin(r, f @ (SpinField::Alpha(_) | SpinField::Kinetic)) => {
                r.value(f, s.q, s.v, &s.eval.a, mass[r.body], dim)
            }
            StateVar::RigidKinetic(p) => {
                let v = &s.v[p.body * dim..(p.body + 1) * dim];
                let inertia = p.r()[0];
                0.5 * mass[p.body] * dot(v, v) + 0.5 * inertia * s.v[p.angle] * s.v[p.angle]
            }
            kin => kin.value_kinematic(
                &Kinematics {
                    t: s.t,
                    dim,
                    x: s.q,
                    v: s.v,
                    mass,
                },
                local,
            ),
        }
    }
}

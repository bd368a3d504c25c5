//! Formulas compiled against the state names, evaluated on kinematics (inside forces) or on
//! samples (conditions, observables).

use mechkit_expr::interval::Jet;
use mechkit_expr::{Program, Val};

use super::enclosure::StateJets;

use super::kinematics::Kinematics;
use super::sample::Sample;
use super::vars::{BodyRef, StateVar};
use crate::Real;
use crate::forces::ForceEmitter;

/// Most distinct state names one formula may use before evaluation allocates.
const INLINE_VARS: usize = 16;

/// A formula compiled against the state names: evaluate it on kinematics (in forces) or on a
/// sample (conditions, observables).
#[derive(Debug, Clone)]
pub struct StateExpr {
    source: String,
    program: Program,
    vars: Vec<StateVar>,
}

impl StateExpr {
    pub(crate) fn new(source: String, program: Program, vars: Vec<StateVar>) -> Self {
        Self {
            source,
            program,
            vars,
        }
    }

    /// The formula as written.
    pub fn source(&self) -> &str {
        &self.source
    }

    /// The state quantities it reads.
    pub fn vars(&self) -> &[StateVar] {
        &self.vars
    }

    /// Whether it reads only time, positions, velocities and masses.
    pub fn is_kinematic(&self) -> bool {
        self.vars.iter().all(|v| v.is_kinematic())
    }

    /// Whether it reads velocities.
    pub fn reads_velocity(&self) -> bool {
        self.vars.iter().any(|v| {
            matches!(
                v,
                StateVar::Velocity(..)
                    | StateVar::Speed(_)
                    | StateVar::CoordinateRate(_)
                    | StateVar::PointVelocity(..)
            ) || matches!(v, StateVar::Spin(_, f) if !matches!(f, super::SpinField::Quaternion(_)))
        })
    }

    /// The value, if it reads no state at all.
    pub fn as_constant(&self) -> Option<Real> {
        self.program.as_constant()
    }

    #[inline]
    fn eval_with(&self, fill: impl Fn(StateVar) -> Real) -> Real {
        let n = self.vars.len();
        if n <= INLINE_VARS {
            let mut slots = [0.0; INLINE_VARS];
            for (s, v) in slots.iter_mut().zip(&self.vars) {
                *s = fill(*v);
            }
            self.program.eval(&slots[..n])
        } else {
            let slots: Vec<Real> = self.vars.iter().map(|v| fill(*v)).collect();
            self.program.eval(&slots)
        }
    }

    /// The formula inlined into a fused step kernel, its names read from the emitter's
    /// kinematics (`local` is the body bare names mean); `None` when it reads anything but
    /// time, positions, velocities, speeds, distances and masses.
    pub fn emit(&self, e: &mut ForceEmitter<'_>, local: Option<usize>) -> Option<Val> {
        let mut args = Vec::with_capacity(self.vars.len());
        for var in &self.vars {
            let body = |r: BodyRef| match r {
                BodyRef::Index(i) => Some(i),
                BodyRef::Local => local,
            };
            let d = e.dim();
            let value = match *var {
                StateVar::Time => e.t(),
                StateVar::Position(r, i) => e.x(body(r)?, i),
                StateVar::Velocity(r, i) => e.v(body(r)?, i),
                StateVar::Speed(r) => {
                    let b = body(r)?;
                    let v: Vec<Val> = (0..d).map(|i| e.v(b, i)).collect();
                    e.norm(&v)
                }
                StateVar::Distance(r) => {
                    let b = body(r)?;
                    let x: Vec<Val> = (0..d).map(|i| e.x(b, i)).collect();
                    e.norm(&x)
                }
                StateVar::Mass(r) => {
                    let m = e.mass(body(r)?);
                    e.constant(m)
                }
                _ => return None,
            };
            args.push(value);
        }
        Some(e.b().inline(&self.program, &args))
    }

    /// Encloses the formula and its time derivative over the times of `j` (see
    /// [`StateJets`]), bare names meaning body `local`; `None` when it reads a quantity that
    /// cannot be enclosed there (one that depends on the forces).
    pub fn enclose(&self, j: &StateJets<'_>, local: Option<usize>) -> Option<Jet> {
        let n = self.vars.len();
        if n <= INLINE_VARS {
            let mut slots = [Jet::constant(0.0); INLINE_VARS];
            for (s, v) in slots.iter_mut().zip(&self.vars) {
                *s = v.enclose(j, local)?;
            }
            Some(self.program.eval_jet(&slots[..n]))
        } else {
            let slots: Option<Vec<Jet>> = self.vars.iter().map(|v| v.enclose(j, local)).collect();
            Some(self.program.eval_jet(&slots?))
        }
    }

    /// Evaluates on kinematics, bare names meaning body `local`.
    #[inline]
    pub fn eval_kinematic(&self, k: &Kinematics<'_>, local: Option<usize>) -> Real {
        self.eval_with(|v| v.value_kinematic(k, local))
    }

    /// Evaluates on a sample.
    pub fn eval_sample(
        &self,
        s: &Sample<'_>,
        dim: usize,
        mass: &[Real],
        local: Option<usize>,
    ) -> Real {
        self.eval_with(|v| v.value(s, dim, mass, local))
    }
}

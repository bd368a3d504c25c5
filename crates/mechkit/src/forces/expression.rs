//! A force typed as a formula, one per component, evaluated for each body it acts on with bare
//! names (`x`, `v`, `m`) meaning that body.

use super::emit::ForceEmitter;
use super::force::Force;
use crate::Real;
use crate::particles::{Kinematics, StateExpr};

/// A formula force.
#[derive(Debug, Clone)]
pub struct ExpressionForce {
    name: String,
    bodies: Vec<usize>,
    components: Vec<StateExpr>,
    velocity_dependent: bool,
}

impl ExpressionForce {
    /// Components `components` (one per dimension, compiled with bare names local) on each of
    /// `bodies`.
    pub fn new(name: impl Into<String>, bodies: Vec<usize>, components: Vec<StateExpr>) -> Self {
        let velocity_dependent = components.iter().any(StateExpr::reads_velocity);
        Self {
            name: name.into(),
            bodies,
            components,
            velocity_dependent,
        }
    }

    /// The component formulas.
    pub fn components(&self) -> &[StateExpr] {
        &self.components
    }
}

impl Force for ExpressionForce {
    fn name(&self) -> &str {
        &self.name
    }

    fn add_forces(&self, k: &Kinematics<'_>, out: &mut [Real]) {
        for &b in &self.bodies {
            for (i, c) in self.components.iter().enumerate() {
                out[b * k.dim + i] += c.eval_kinematic(k, Some(b));
            }
        }
    }

    fn emit(&self, e: &mut ForceEmitter<'_>) -> bool {
        let d = e.dim();
        for &b in &self.bodies {
            for (i, c) in self.components.iter().enumerate() {
                let Some(f) = c.emit(e, Some(b)) else {
                    return false;
                };
                e.add(b * d + i, f);
            }
        }
        true
    }

    fn velocity_dependent(&self) -> bool {
        self.velocity_dependent
    }

    fn local(&self) -> bool {
        true
    }

    fn bodies(&self) -> Vec<usize> {
        self.bodies.clone()
    }
}

//! The wind a drag force is relative to: still air, a constant vector, or a field given by
//! formulas of position and time.

use crate::Real;
use crate::particles::{Kinematics, StateExpr};

/// Velocity of the medium.
#[derive(Debug, Clone, Default)]
pub enum Wind {
    /// Still air.
    #[default]
    Calm,
    /// The same wind everywhere, one component per dimension.
    Constant(Vec<Real>),
    /// One formula per component, of `t`, `x`, `y`, `z` (and anything kinematic).
    Field(Vec<StateExpr>),
}

impl Wind {
    /// Writes the wind at body `b` into `w` (`dim` components).
    #[inline]
    pub fn at(&self, k: &Kinematics<'_>, b: usize, w: &mut [Real; 3]) {
        match self {
            Wind::Calm => *w = [0.0; 3],
            Wind::Constant(c) => w[..c.len()].copy_from_slice(c),
            Wind::Field(f) => {
                for (wi, fi) in w.iter_mut().zip(f) {
                    *wi = fi.eval_kinematic(k, Some(b));
                }
            }
        }
    }
}

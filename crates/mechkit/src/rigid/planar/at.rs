//! A force applied at a point of a rigid body other than its centre of mass.

use super::joint::perp;
use crate::Real;
use crate::forces::Force;
use crate::particles::Kinematics;

/// `inner` (a force on body `body` alone) applied at the body point `r` (body frame, from
/// the centre of mass): the same force on the centre of mass, plus its torque `w × F` (`w` the
/// point's offset in the world) on the body's angle `angle`. Its work is measured (`F` at the
/// point times the point's velocity); it has no potential.
#[derive(Debug)]
pub struct AppliedAt {
    inner: Box<dyn Force>,
    body: usize,
    angle: usize,
    r: [Real; 2],
}

impl AppliedAt {
    /// `inner` applied at `r` of body `body`, whose angle is coordinate `angle` of `q`.
    pub fn new(inner: Box<dyn Force>, body: usize, angle: usize, r: [Real; 2]) -> Self {
        Self {
            inner,
            body,
            angle,
            r,
        }
    }
}

impl Force for AppliedAt {
    fn name(&self) -> &str {
        self.inner.name()
    }

    fn add_forces(&self, k: &Kinematics<'_>, out: &mut [Real]) {
        let b = self.body;
        let before = [out[2 * b], out[2 * b + 1]];
        self.inner.add_forces(k, out);
        let f = [out[2 * b] - before[0], out[2 * b + 1] - before[1]];
        let (s, c) = k.x[self.angle].sin_cos();
        let w = [c * self.r[0] - s * self.r[1], s * self.r[0] + c * self.r[1]];
        let p = perp(w);
        out[self.angle] += p[0] * f[0] + p[1] * f[1];
    }

    fn velocity_dependent(&self) -> bool {
        self.inner.velocity_dependent()
    }

    fn bodies(&self) -> Vec<usize> {
        vec![self.body]
    }
}

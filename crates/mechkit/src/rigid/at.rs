//! Forces applied at a point of a rigid body other than its centre of mass, and torques, in
//! a plane or in space.

use crate::Real;
use crate::forces::Force;
use crate::particles::spin::{cross, rotate, torque_force};
use crate::particles::{Kinematics, StateExpr};

/// How a rigid body turns: its angle in a plane, or its orientation quaternion in space
/// ([`crate::particles::spin`]), by index in `q`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Turn {
    /// The angle coordinate (a plane).
    Angle(usize),
    /// The first of four quaternion coordinates (space).
    Quaternion(usize),
}

impl Turn {
    /// Adds the world torque `tau` (`z` alone in a plane) as the generalized force on the
    /// turning coordinates, at the state `x`.
    #[inline]
    pub fn add_torque(self, x: &[Real], tau: [Real; 3], out: &mut [Real]) {
        match self {
            Turn::Angle(i) => out[i] += tau[2],
            Turn::Quaternion(f) => {
                let q = [x[f], x[f + 1], x[f + 2], x[f + 3]];
                for (o, g) in out[f..f + 4].iter_mut().zip(torque_force(q, tau)) {
                    *o += g;
                }
            }
        }
    }

    /// The body-frame offset `r` turned into the world at the state `x`.
    #[inline]
    pub fn offset(self, x: &[Real], r: [Real; 3]) -> [Real; 3] {
        match self {
            Turn::Angle(i) => {
                let (s, c) = x[i].sin_cos();
                [c * r[0] - s * r[1], s * r[0] + c * r[1], 0.0]
            }
            Turn::Quaternion(f) => rotate([x[f], x[f + 1], x[f + 2], x[f + 3]], r),
        }
    }
}

/// `inner` (a force on body `body` alone) applied at the body point `r` (body frame, from
/// the centre of mass): the same force on the centre of mass, plus its torque `w × F` (`w` the
/// point's offset in the world) on the body's turning coordinates. Its work is measured (the
/// force's power over all the coordinates is `F` at the point times the point's velocity); it
/// has no potential.
#[derive(Debug)]
pub struct AppliedAt {
    inner: Box<dyn Force>,
    body: usize,
    turn: Turn,
    r: [Real; 3],
}

impl AppliedAt {
    /// `inner` applied at `r` of body `body` in a plane, whose angle is coordinate `angle`.
    pub fn new(inner: Box<dyn Force>, body: usize, angle: usize, r: [Real; 2]) -> Self {
        Self::turning(inner, body, Turn::Angle(angle), [r[0], r[1], 0.0])
    }

    /// `inner` applied at `r` of body `body`, which turns by `turn`.
    pub fn turning(inner: Box<dyn Force>, body: usize, turn: Turn, r: [Real; 3]) -> Self {
        Self {
            inner,
            body,
            turn,
            r,
        }
    }
}

impl Force for AppliedAt {
    fn name(&self) -> &str {
        self.inner.name()
    }

    fn add_forces(&self, k: &Kinematics<'_>, out: &mut [Real]) {
        let (d, b) = (k.dim, self.body);
        let mut before = [0.0; 3];
        before[..d].copy_from_slice(&out[d * b..d * (b + 1)]);
        self.inner.add_forces(k, out);
        let mut f = [0.0; 3];
        for i in 0..d {
            f[i] = out[d * b + i] - before[i];
        }
        let w = self.turn.offset(k.x, self.r);
        self.turn.add_torque(k.x, cross(w, f), out);
    }

    fn velocity_dependent(&self) -> bool {
        self.inner.velocity_dependent()
    }

    fn bodies(&self) -> Vec<usize> {
        vec![self.body]
    }
}

/// A torque on a rigid body, given by formulas of the state: its `z` component in a plane,
/// its world components in space. It moves no centre of mass; its power is `τ·ω`.
#[derive(Debug)]
pub struct Torque {
    name: String,
    body: usize,
    turn: Turn,
    components: Vec<StateExpr>,
}

impl Torque {
    /// The torque `components` (one in a plane, three in space, compiled with bare names
    /// meaning body `body`) on body `body`, which turns by `turn`.
    pub fn new(
        name: impl Into<String>,
        body: usize,
        turn: Turn,
        components: Vec<StateExpr>,
    ) -> Self {
        Self {
            name: name.into(),
            body,
            turn,
            components,
        }
    }
}

impl Force for Torque {
    fn name(&self) -> &str {
        &self.name
    }

    fn add_forces(&self, k: &Kinematics<'_>, out: &mut [Real]) {
        let mut tau = [0.0; 3];
        match self.components.as_slice() {
            [z] => tau[2] = z.eval_kinematic(k, Some(self.body)),
            c => {
                for (t, e) in tau.iter_mut().zip(c) {
                    *t = e.eval_kinematic(k, Some(self.body));
                }
            }
        }
        self.turn.add_torque(k.x, tau, out);
    }

    fn velocity_dependent(&self) -> bool {
        self.components.iter().any(StateExpr::reads_velocity)
    }

    fn bodies(&self) -> Vec<usize> {
        vec![self.body]
    }
}

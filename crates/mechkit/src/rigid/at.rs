//! Forces applied at a point of a rigid body other than its centre of mass, and torques, in
//! a plane or in space.

use crate::Real;
use crate::forces::Force;
use crate::particles::spin::{cross, omega_world, rotate, torque_force};
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

    /// The body's angular velocity (world; `z` alone in a plane) at the state `(x, v)`.
    #[inline]
    pub fn omega(self, x: &[Real], v: &[Real]) -> [Real; 3] {
        match self {
            Turn::Angle(i) => [0.0, 0.0, v[i]],
            Turn::Quaternion(f) => omega_world(
                [x[f], x[f + 1], x[f + 2], x[f + 3]],
                [v[f], v[f + 1], v[f + 2], v[f + 3]],
            ),
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

/// `inner` applied at the body point `r` (body frame, from the centre of mass) of body
/// `body`: it acts on the centre of mass, and its torque `w × F` (`w` the point's offset in
/// the world) turns the body. Its power over all the coordinates is `F` at the point times the
/// point's velocity. A force law of positions and velocities (a spring, drag, gravitation) is
/// evaluated at the point ([`AppliedAt::at_point`]: the body's position and velocity replaced
/// by the point's), so a spring tied to the point stretches from it and keeps its potential,
/// measured there; a formula force reads its names as they are (`box.tip.x` is the point,
/// `box.x` the centre).
#[derive(Debug)]
pub struct AppliedAt {
    inner: Box<dyn Force>,
    body: usize,
    turn: Turn,
    r: [Real; 3],
    at_point: bool,
}

impl AppliedAt {
    /// `inner` applied at `r` of body `body` in a plane, whose angle is coordinate `angle`.
    pub fn new(inner: Box<dyn Force>, body: usize, angle: usize, r: [Real; 2]) -> Self {
        Self::turning(inner, body, Turn::Angle(angle), [r[0], r[1], 0.0])
    }

    /// `inner` applied at `r` of body `body`, which turns by `turn` (evaluated at the centre
    /// of mass: see [`AppliedAt::at_point`]).
    pub fn turning(inner: Box<dyn Force>, body: usize, turn: Turn, r: [Real; 3]) -> Self {
        Self {
            inner,
            body,
            turn,
            r,
            at_point: false,
        }
    }

    /// Evaluates the inner force with the body's position and velocity replaced by the
    /// point's: for force laws of the body's state (springs, drag, gravitation), not for
    /// formulas, which name what they read.
    #[must_use]
    pub fn at_point(mut self) -> Self {
        self.at_point = true;
        self
    }

    /// The state the inner force sees (`x`, `v` copies, the body moved to the point when
    /// [`AppliedAt::at_point`]), and the point's offset `w` in the world.
    fn seen(&self, k: &Kinematics<'_>) -> (Vec<Real>, Vec<Real>, [Real; 3]) {
        let (d, b) = (k.dim, self.body);
        let w = self.turn.offset(k.x, self.r);
        let (mut x, mut v) = (k.x.to_vec(), k.v.to_vec());
        if self.at_point {
            let vw = cross(self.turn.omega(k.x, k.v), w);
            for i in 0..d {
                x[d * b + i] += w[i];
                v[d * b + i] += vw[i];
            }
        }
        (x, v, w)
    }
}

impl Force for AppliedAt {
    fn name(&self) -> &str {
        self.inner.name()
    }

    fn add_forces(&self, k: &Kinematics<'_>, out: &mut [Real]) {
        let (d, b) = (k.dim, self.body);
        let (x, v, w) = self.seen(k);
        let moved = Kinematics { x: &x, v: &v, ..*k };
        let mut before = [0.0; 3];
        before[..d].copy_from_slice(&out[d * b..d * (b + 1)]);
        self.inner.add_forces(&moved, out);
        let mut f = [0.0; 3];
        for i in 0..d {
            f[i] = out[d * b + i] - before[i];
        }
        self.turn.add_torque(k.x, cross(w, f), out);
    }

    fn potential(&self, k: &Kinematics<'_>) -> Option<Real> {
        let (x, v, _) = self.seen(k);
        self.inner.potential(&Kinematics { x: &x, v: &v, ..*k })
    }

    fn velocity_dependent(&self) -> bool {
        self.inner.velocity_dependent()
    }

    fn bodies(&self) -> Vec<usize> {
        self.inner.bodies()
    }

    fn internal(&self) -> bool {
        self.inner.internal()
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

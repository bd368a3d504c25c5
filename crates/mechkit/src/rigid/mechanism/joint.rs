//! The joints of a planar mechanism and the constraint rows they contribute.

use std::sync::Arc;

use mechkit_expr::{Expr, MapScope, Program, Sym};

use super::super::at::Turn;
use crate::Real;
use crate::particles::spin::{Quat, cross, dot3, torque_force};

/// A curve `y = f(x)` of the plane, with `f'` and `f''` derived symbolically and compiled.
#[derive(Debug, Clone)]
pub struct Curve {
    source: String,
    programs: [Program; 3],
}

impl PartialEq for Curve {
    fn eq(&self, other: &Self) -> bool {
        self.source == other.source
    }
}

impl Curve {
    /// `y = f(x)` given by `f`, a formula of `x` and of the names in `constants`; `Err` names
    /// a name that is neither.
    pub fn new(f: &Expr, constants: &[(String, Real)]) -> Result<Self, String> {
        let mut scope = MapScope::new();
        for (name, value) in constants {
            scope = scope.constant(name, *value);
        }
        let scope = scope.slot("x", 0);
        let d1 = Sym::from_expr(f).diff("x");
        let d2 = d1.diff("x");
        let programs = [
            Program::compile(f, &scope)?.native(),
            Program::compile(&d1.to_expr(), &scope)?.native(),
            Program::compile(&d2.to_expr(), &scope)?.native(),
        ];
        Ok(Self {
            source: Sym::from_expr(f).to_string(),
            programs,
        })
    }

    /// `f(x)`, `f'(x)`, `f''(x)`.
    pub fn eval(&self, x: Real) -> [Real; 3] {
        [
            self.programs[0].eval(&[x]),
            self.programs[1].eval(&[x]),
            self.programs[2].eval(&[x]),
        ]
    }
}

/// A point a joint holds: fixed in the world, or fixed in a body (`z` is 0 in a plane).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Anchor {
    /// A fixed point (m).
    World([Real; 3]),
    /// A point of body `body` (index in the particle system), `r` from its centre of mass in
    /// the body's own frame (the frame the body is described in, turned by its angle `θ` in a
    /// plane, by its orientation in space).
    Body {
        /// Body index.
        body: usize,
        /// Offset from the centre of mass in the body frame (m).
        r: [Real; 3],
    },
}

/// Friction of a contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Friction {
    /// A smooth surface: only the normal force.
    None,
    /// Coulomb friction with static and kinetic coefficients; `mode` is the state coordinate
    /// holding 0 while the contact sticks and the sliding direction ±1 while it slides.
    Coulomb {
        /// Static coefficient.
        mu_s: Real,
        /// Kinetic coefficient.
        mu_k: Real,
        /// Index of the mode coordinate in `q`.
        mode: usize,
    },
    /// The contact point never slides (rolling without slipping, whatever the force).
    NoSlip,
}

/// What a joint does.
#[derive(Debug, Clone, PartialEq)]
pub enum JointKind {
    /// A pin: the two points coincide. In space it is a ball joint, or with `axis` a hinge
    /// that turns only about that axis (the axis as fixed in `a`'s body and in `b`'s: world
    /// directions for the world and for particles).
    Hinge {
        /// First point.
        a: Anchor,
        /// Second point.
        b: Anchor,
        /// The hinge's axis in the frames of `a` and `b`, in space.
        axis: Option<[[Real; 3]; 2]>,
    },
    /// A massless rigid rod: the points keep their distance.
    Rod {
        /// First end.
        a: Anchor,
        /// Second end.
        b: Anchor,
        /// Length (m).
        length: Real,
    },
    /// An inextensible massless string: the distance is at most `length`; it pulls only while
    /// taut (`mode` holds 1 while taut, 0 while slack).
    String {
        /// First end.
        a: Anchor,
        /// Second end.
        b: Anchor,
        /// Length (m).
        length: Real,
        /// Index of the mode coordinate in `q`.
        mode: usize,
    },
    /// A point (or a disk or ball of radius `radius` around it) on the positive side of a
    /// line (a plane in space), pushed by its normal force while touching (`mode` 1) and free
    /// while apart (0).
    Contact {
        /// The body point (a disk's centre).
        on: Anchor,
        /// Radius of the disk (0 for a point).
        radius: Real,
        /// A point of the line: fixed, or a point of a particle (the surface of a body that
        /// moves without turning: a block on a cart).
        point: Anchor,
        /// The surface's unit normal, towards the side the body is on (`z` 0 in a plane).
        normal: [Real; 3],
        /// Index of the touching-mode coordinate in `q`.
        mode: usize,
        /// Friction along the line.
        friction: Friction,
    },
    /// A point kept on the curve `y = f(x)` (a bead on a wire, a car on a track); the curve
    /// pushes both ways.
    Curve {
        /// The point.
        on: Anchor,
        /// The curve.
        curve: Arc<Curve>,
    },
    /// An ideal string over the top of a pulley of radius `radius` centred at `centre`, from
    /// `a` to `b`: the two straight pieces and the arc between their tangent points add up to
    /// `length`. `sense` is +1 when `b` hangs on the right of `a` (seen with `y` up), −1 on the
    /// left. With `wheel` (the index of a rigid body's angle in `q`) the string does not slip on
    /// the rim: the wheel turns by the string's travel over `radius`.
    Pulley {
        /// First end.
        a: Anchor,
        /// Second end.
        b: Anchor,
        /// The pulley's centre.
        centre: Anchor,
        /// Radius (m).
        radius: Real,
        /// The string's length (m).
        length: Real,
        /// +1 when `b` is on the right of `a`, −1 on the left.
        sense: Real,
        /// The wheel's angle coordinate.
        wheel: Option<usize>,
    },
}

/// A named joint.
#[derive(Debug, Clone, PartialEq)]
pub struct Joint {
    /// Name (as in the energy ledger and in formulas: `name.N`).
    pub name: String,
    /// What it does.
    pub kind: JointKind,
}

/// The most coordinates one row involves: two bodies turning in space (3 + 4 each), or three
/// points of a pulley in a plane with its wheel.
const ROW_CAPACITY: usize = 16;

/// One scalar constraint at the acceleration level: `J a + bias = 0` (with stabilisation).
#[derive(Debug, Clone)]
pub(crate) struct Row {
    /// Coordinates it involves.
    pub idx: [usize; ROW_CAPACITY],
    /// `∂C/∂q` (or the velocity constraint's row).
    pub j: [Real; ROW_CAPACITY],
    /// The direction its force acts in (`J`, except a sliding contact's normal row).
    pub d: [Real; ROW_CAPACITY],
    pub n: usize,
    /// `J̇ v`.
    pub bias: Real,
    /// `J v`.
    pub jv: Real,
    /// The constraint's value, for rows at the position level.
    pub c: Option<Real>,
    /// The joint it belongs to.
    pub joint: usize,
}

impl Row {
    pub(crate) fn new(joint: usize) -> Self {
        Self {
            idx: [0; ROW_CAPACITY],
            j: [0.0; ROW_CAPACITY],
            d: [0.0; ROW_CAPACITY],
            n: 0,
            bias: 0.0,
            jv: 0.0,
            c: None,
            joint,
        }
    }

    pub(crate) fn push(&mut self, idx: usize, j: Real) {
        if let Some(k) = self.idx[..self.n].iter().position(|&i| i == idx) {
            self.j[k] += j;
            self.d[k] += j;
            return;
        }
        self.idx[self.n] = idx;
        self.j[self.n] = j;
        self.d[self.n] = j;
        self.n += 1;
    }

    /// `self · x` over the row's entries.
    pub(crate) fn dot(&self, x: &[Real]) -> Real {
        (0..self.n).map(|k| self.j[k] * x[self.idx[k]]).sum()
    }
}

/// Where a body's coordinates are: its centre of mass from `x` (`dim` of them), and how it
/// turns (with its orientation `quat`, for a body in space).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Coords {
    pub x: usize,
    pub dim: usize,
    pub turn: Option<Turn>,
    pub quat: Quat,
}

/// A point's kinematics in the world (`z` components 0 in a plane).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Point {
    pub p: [Real; 3],
    pub vel: [Real; 3],
    /// World offset from the body's centre of mass (zero for world points).
    pub w: [Real; 3],
    /// The body's angular velocity (world).
    pub omega: [Real; 3],
    /// The body's coordinates, if any.
    pub coords: Option<Coords>,
    /// The offset of the material point it follows (its centripetal acceleration
    /// `ω × (ω × w)`): `w` itself, or less for a point shifted along a fixed direction.
    pub material: [Real; 3],
}

pub(crate) fn add3(a: [Real; 3], b: [Real; 3]) -> [Real; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

pub(crate) fn sub3(a: [Real; 3], b: [Real; 3]) -> [Real; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

pub(crate) fn norm3(a: [Real; 3]) -> Real {
    dot3(a, a).sqrt()
}

/// The distance between two points.
pub fn distance(a: [Real; 3], b: [Real; 3]) -> Real {
    norm3(sub3(a, b))
}

impl Point {
    /// The point at `offset` (a direction fixed in the world) from this one: a disk's or a
    /// ball's contact point, which is not a material point of the body (its velocity is that
    /// of the body's material point there, but as the body turns, other material points take
    /// its place, so its acceleration has only the centre's centripetal part).
    pub(crate) fn shifted(self, offset: [Real; 3]) -> Self {
        let w = add3(self.w, offset);
        let base = sub3(self.vel, cross(self.omega, self.w));
        Self {
            p: add3(self.p, offset),
            vel: add3(base, cross(self.omega, w)),
            w,
            omega: self.omega,
            coords: self.coords,
            material: self.material,
        }
    }

    /// Adds `sign · u·p` to `row`: its Jacobian entries, `J̇ v` (for a fixed `u`) and `J v`.
    pub(crate) fn add(&self, row: &mut Row, u: [Real; 3], sign: Real) {
        if let Some(c) = self.coords {
            for (k, uk) in u.iter().take(c.dim).enumerate() {
                row.push(c.x + k, sign * uk);
            }
            let arm = cross(self.w, u);
            match c.turn {
                Some(Turn::Angle(a)) => row.push(a, sign * arm[2]),
                Some(Turn::Quaternion(f)) => {
                    for (k, g) in torque_force(c.quat, arm).into_iter().enumerate() {
                        row.push(f + k, sign * g);
                    }
                }
                None => {}
            }
        }
        row.bias += sign * dot3(u, cross(self.omega, cross(self.omega, self.material)));
        row.jv += sign * dot3(u, self.vel);
    }

    /// Adds `sign · e·ω` (the body's angular velocity along the world direction `e`) to
    /// `row`: its Jacobian entries and `J v` (the bias depends on how `e` turns: the caller's).
    pub(crate) fn add_angular(&self, row: &mut Row, e: [Real; 3], sign: Real) {
        if let Some(c) = self.coords {
            match c.turn {
                Some(Turn::Angle(a)) => row.push(a, sign * e[2]),
                Some(Turn::Quaternion(f)) => {
                    for (k, g) in torque_force(c.quat, e).into_iter().enumerate() {
                        row.push(f + k, sign * g);
                    }
                }
                None => {}
            }
        }
        row.jv += sign * dot3(e, self.omega);
    }

    /// The body-frame direction `d` in the world (as is for the world and particles).
    pub(crate) fn direction(&self, d: [Real; 3]) -> [Real; 3] {
        self.coords
            .map_or(d, |c| crate::particles::spin::rotate(c.quat, d))
    }
}

//! The constraint solver of a planar mechanism: its bodies, the rows of its engaged joints,
//! and the multipliers, forces, reports and impulses they give.

use std::sync::{Arc, Mutex};

use super::gauss::gauss;
use super::joint::{Anchor, Friction, Joint, JointKind, Point, Row, dot2, perp};
use crate::Real;

/// What each joint reports, in this order (`name.fx`, …): the force on its first body (world
/// components, N), the normal force or tension (N), the friction force along the surface (N)
/// and the constraint's violation (m).
pub const REPORT_FIELDS: [&str; 5] = ["fx", "fy", "N", "F", "drift"];

/// A body of a planar mechanism, as the solver sees it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlanarBody {
    /// Index of its `x` coordinate in `q` (`y` follows).
    pub x: usize,
    /// Index of its angle in `q`, for a rigid body.
    pub angle: Option<usize>,
    /// `1/m`.
    pub inv_mass: Real,
    /// `1/I` about the centre of mass (0 for a particle).
    pub inv_inertia: Real,
}

/// Bodies and joints, with the stabilisation time constant.
#[derive(Debug)]
pub struct Mechanism {
    bodies: Vec<PlanarBody>,
    pub(super) joints: Vec<Joint>,
    tau: std::sync::OnceLock<Real>,
    inv_mass: Vec<Real>,
    /// The last solution and the state and applied forces it was solved for (`[q, v,
    /// applied]`): every joint's force of one evaluation shares one solve.
    last: Mutex<(Vec<Real>, Option<Arc<Solution>>)>,
}

/// The rows and multipliers at one state.
#[derive(Debug)]
pub(crate) struct Solution {
    rows: Vec<Row>,
    lambda: Vec<Real>,
}

impl Mechanism {
    /// A mechanism of `bodies` in a system of `dof` coordinates, joined by `joints`; its
    /// Baumgarte time constant is set once by [`Mechanism::set_tau`] (1 ms until then).
    pub fn new(bodies: Vec<PlanarBody>, joints: Vec<Joint>, dof: usize) -> Self {
        let mut inv_mass = vec![0.0; dof];
        for b in &bodies {
            inv_mass[b.x] = b.inv_mass;
            inv_mass[b.x + 1] = b.inv_mass;
            if let Some(a) = b.angle {
                inv_mass[a] = b.inv_inertia;
            }
        }
        Self {
            bodies,
            joints,
            tau: std::sync::OnceLock::new(),
            inv_mass,
            last: Mutex::new((Vec::new(), None)),
        }
    }

    /// Sets the stabilisation time constant (s; once: later calls are ignored).
    pub fn set_tau(&self, tau: Real) {
        let _ = self.tau.set(tau);
    }

    /// The joints.
    pub fn joints(&self) -> &[Joint] {
        &self.joints
    }

    /// The stabilisation time constant (s).
    pub fn tau(&self) -> Real {
        self.tau.get().copied().unwrap_or(1e-3)
    }

    pub(super) fn point(&self, a: Anchor, q: &[Real], v: &[Real]) -> Point {
        match a {
            Anchor::World(p) => Point {
                p,
                vel: [0.0; 2],
                w: [0.0; 2],
                omega: 0.0,
                coords: None,
            },
            Anchor::Body { body, r } => {
                let b = self.bodies[body];
                let (theta, omega) = b.angle.map_or((0.0, 0.0), |i| (q[i], v[i]));
                let (s, c) = theta.sin_cos();
                let w = [c * r[0] - s * r[1], s * r[0] + c * r[1]];
                let pw = perp(w);
                Point {
                    p: [q[b.x] + w[0], q[b.x + 1] + w[1]],
                    vel: [v[b.x] + omega * pw[0], v[b.x + 1] + omega * pw[1]],
                    w,
                    omega,
                    coords: Some((b.x, b.angle)),
                }
            }
        }
    }

    /// Whether a switching joint is engaged (contact touching, string taut) at `q`.
    fn engaged(q: &[Real], mode: usize) -> bool {
        q[mode] > 0.5
    }

    /// The rows of every engaged constraint at a state.
    pub(crate) fn rows(&self, q: &[Real], v: &[Real]) -> Vec<Row> {
        let mut rows = Vec::with_capacity(2 * self.joints.len());
        for (ji, joint) in self.joints.iter().enumerate() {
            match joint.kind {
                JointKind::Hinge { a, b } => {
                    let (pa, pb) = (self.point(a, q, v), self.point(b, q, v));
                    for (axis, u) in [[1.0, 0.0], [0.0, 1.0]].into_iter().enumerate() {
                        let mut row = Row::new(ji);
                        pa.add(&mut row, u, 1.0);
                        pb.add(&mut row, u, -1.0);
                        row.c = Some(pa.p[axis] - pb.p[axis]);
                        rows.push(row);
                    }
                }
                JointKind::Rod { a, b, length } => {
                    rows.push(self.distance_row(ji, a, b, length, q, v));
                }
                JointKind::String {
                    a, b, length, mode, ..
                } => {
                    if Self::engaged(q, mode) {
                        rows.push(self.distance_row(ji, a, b, length, q, v));
                    }
                }
                JointKind::Contact {
                    on,
                    radius,
                    point,
                    normal,
                    mode,
                    friction,
                } => {
                    if !Self::engaged(q, mode) {
                        continue;
                    }
                    let p = self.point(on, q, v);
                    let base = self.point(point, q, v);
                    let mut nrow = Row::new(ji);
                    p.add(&mut nrow, normal, 1.0);
                    base.add(&mut nrow, normal, -1.0);
                    nrow.c = Some(dot2([p.p[0] - base.p[0], p.p[1] - base.p[1]], normal) - radius);
                    let tangent = [normal[1], -normal[0]];
                    let contact = p.shifted([-radius * normal[0], -radius * normal[1]]);
                    let mut trow = Row::new(ji);
                    contact.add(&mut trow, tangent, 1.0);
                    base.add(&mut trow, tangent, -1.0);
                    match friction {
                        Friction::None => rows.push(nrow),
                        Friction::NoSlip => {
                            rows.push(nrow);
                            rows.push(trow);
                        }
                        Friction::Coulomb { mu_k, mode, .. } => {
                            let s = q[mode];
                            if s == 0.0 {
                                rows.push(nrow);
                                rows.push(trow);
                            } else {
                                // the normal force drags kinetic friction −μₖ s N with it
                                for k in 0..trow.n {
                                    let idx = trow.idx[k];
                                    let slot = (0..nrow.n).find(|&m| nrow.idx[m] == idx);
                                    let f = -mu_k * s * trow.j[k];
                                    if let Some(m) = slot {
                                        nrow.d[m] += f;
                                    } else {
                                        nrow.idx[nrow.n] = idx;
                                        nrow.j[nrow.n] = 0.0;
                                        nrow.d[nrow.n] = f;
                                        nrow.n += 1;
                                    }
                                }
                                rows.push(nrow);
                            }
                        }
                    }
                }
                JointKind::Curve { on, ref curve } => {
                    let p = self.point(on, q, v);
                    let [f, f1, f2] = curve.eval(p.p[0]);
                    let mut row = Row::new(ji);
                    // C = y - f(x): J = (-f', 1) at the point; d/dt of J adds -f'' ẋ²
                    p.add(&mut row, [-f1, 1.0], 1.0);
                    row.bias -= f2 * p.vel[0] * p.vel[0];
                    row.c = Some(p.p[1] - f);
                    rows.push(row);
                }
                JointKind::Pulley {
                    a,
                    b,
                    centre,
                    radius,
                    length,
                    sense,
                    wheel,
                } => {
                    let c = self.point(centre, q, v);
                    let mut row = Row::new(ji);
                    let (pa, pb) = (self.point(a, q, v), self.point(b, q, v));
                    let (la, psi_a) = Self::segment(&pa, &c, radius, -sense, &mut row);
                    let mut travel = Row::new(ji);
                    let (lb, psi_b) = Self::segment(&pb, &c, radius, sense, &mut travel);
                    for k in 0..travel.n {
                        row.push(travel.idx[k], travel.j[k]);
                    }
                    row.bias += travel.bias;
                    row.jv += travel.jv;
                    let wrap = (sense * (psi_a - psi_b)).rem_euclid(std::f64::consts::TAU);
                    row.c = Some(la + lb + radius * wrap - length);
                    rows.push(row);
                    if let Some(angle) = wheel {
                        // no slip on the rim: R ω + sense · (the string's travel at b) = 0
                        let mut w = Row::new(ji);
                        w.push(angle, radius);
                        w.jv += radius * v[angle];
                        for k in 0..travel.n {
                            w.push(travel.idx[k], sense * travel.j[k]);
                        }
                        w.bias += sense * travel.bias;
                        w.jv += sense * travel.jv;
                        rows.push(w);
                    }
                }
            }
        }
        rows
    }

    /// Adds the straight piece of a pulley's string from its tangent point to `p` into `row`
    /// (the string's length grows along the piece's direction `t̂`, whatever the wrap does:
    /// `∂L/∂p = t̂`); `side` is +1 for the piece on the right of the centre, −1 on the left.
    /// Returns the piece's length and the angle of its tangent point.
    fn segment(p: &Point, c: &Point, radius: Real, side: Real, row: &mut Row) -> (Real, Real) {
        let d = [p.p[0] - c.p[0], p.p[1] - c.p[1]];
        let dd = [p.vel[0] - c.vel[0], p.vel[1] - c.vel[1]];
        let r = d[0].hypot(d[1]).max(Real::MIN_POSITIVE);
        let psi = d[1].atan2(d[0]) + side * (radius / r).clamp(-1.0, 1.0).acos();
        let tp = [radius * psi.cos(), radius * psi.sin()];
        let piece = [d[0] - tp[0], d[1] - tp[1]];
        let l = piece[0].hypot(piece[1]).max(Real::MIN_POSITIVE);
        let u = [piece[0] / l, piece[1] / l];
        p.add(row, u, 1.0);
        c.add(row, u, -1.0);
        let ud = dot2(u, dd);
        row.bias += (dot2(dd, dd) - ud * ud) / l;
        (l, psi)
    }

    fn distance_row(
        &self,
        ji: usize,
        a: Anchor,
        b: Anchor,
        length: Real,
        q: &[Real],
        v: &[Real],
    ) -> Row {
        let (pa, pb) = (self.point(a, q, v), self.point(b, q, v));
        let d = [pa.p[0] - pb.p[0], pa.p[1] - pb.p[1]];
        let dd = [pa.vel[0] - pb.vel[0], pa.vel[1] - pb.vel[1]];
        let l = d[0].hypot(d[1]).max(Real::MIN_POSITIVE);
        let u = [d[0] / l, d[1] / l];
        let mut row = Row::new(ji);
        pa.add(&mut row, u, 1.0);
        pb.add(&mut row, u, -1.0);
        let ud = dot2(u, dd);
        row.bias += (dot2(dd, dd) - ud * ud) / l;
        row.c = Some(l - length);
        row
    }

    /// The first engaged joint whose constraint is violated by more than `tol` at a state
    /// (a body inside its surface, a string stretched past its length, a rod or hinge not
    /// closed), with the violation.
    pub fn violation(&self, q: &[Real], v: &[Real], tol: Real) -> Option<(usize, Real)> {
        self.rows(q, v)
            .iter()
            .find_map(|r| r.c.filter(|c| c.abs() > tol).map(|c| (r.joint, c)))
    }

    /// The length of the string of a mechanism whose only joint is a pulley (the reader's
    /// default length: the string as placed at the start).
    pub fn pulley_length(&self, q: &[Real], v: &[Real]) -> Real {
        self.rows(q, v).first().and_then(|r| r.c).unwrap_or(0.0)
    }

    /// [`Mechanism::solve`], remembered: the joints of one evaluation ask for the same state
    /// and applied forces, and only the first solves.
    pub(crate) fn solved(&self, q: &[Real], v: &[Real], applied: &[Real]) -> Arc<Solution> {
        let mut last = self
            .last
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        let (key, solution) = &mut *last;
        let (n, m) = (q.len(), v.len());
        let same = key.len() == n + m + applied.len()
            && key[..n] == *q
            && key[n..n + m] == *v
            && key[n + m..] == *applied;
        if let (true, Some(s)) = (same, solution.as_ref()) {
            return Arc::clone(s);
        }
        let s = Arc::new(self.solve(q, v, applied));
        key.clear();
        key.extend_from_slice(q);
        key.extend_from_slice(v);
        key.extend_from_slice(applied);
        *solution = Some(Arc::clone(&s));
        s
    }

    /// The multipliers of the engaged constraints under the applied generalised forces.
    pub(crate) fn solve(&self, q: &[Real], v: &[Real], applied: &[Real]) -> Solution {
        let rows = self.rows(q, v);
        let n = rows.len();
        let mut a = vec![0.0; n * n];
        let mut rhs = vec![0.0; n];
        let tau = self.tau();
        let (k1, k2) = (2.0 / tau, 1.0 / (tau * tau));
        for (i, ri) in rows.iter().enumerate() {
            let free: Real = (0..ri.n)
                .map(|e| ri.j[e] * self.inv_mass[ri.idx[e]] * applied[ri.idx[e]])
                .sum();
            rhs[i] = -(free + ri.bias + k1 * ri.jv + ri.c.map_or(0.0, |c| k2 * c));
            for (k, rk) in rows.iter().enumerate() {
                let mut s = 0.0;
                for e in 0..ri.n {
                    for f in 0..rk.n {
                        if ri.idx[e] == rk.idx[f] {
                            s += ri.j[e] * self.inv_mass[ri.idx[e]] * rk.d[f];
                        }
                    }
                }
                a[i * n + k] = s;
            }
        }
        let lambda = gauss(&mut a, rhs, n);
        Solution { rows, lambda }
    }

    /// Adds joint `joint`'s constraint forces `Dᵀλ` into `out`.
    pub(crate) fn add_forces(s: &Solution, joint: usize, out: &mut [Real]) {
        for (r, l) in s.rows.iter().zip(&s.lambda) {
            if r.joint == joint {
                for e in 0..r.n {
                    out[r.idx[e]] += r.d[e] * l;
                }
            }
        }
    }

    /// Joint `joint`'s report ([`REPORT_FIELDS`]) at a state.
    pub(crate) fn report(&self, s: &Solution, joint: usize, q: &[Real], v: &[Real]) -> [Real; 5] {
        let lambdas: Vec<Real> = s
            .rows
            .iter()
            .zip(&s.lambda)
            .filter(|(r, _)| r.joint == joint)
            .map(|(_, l)| *l)
            .collect();
        let l0 = lambdas.first().copied().unwrap_or(0.0);
        match self.joints[joint].kind {
            JointKind::Hinge { a, b } => {
                let (pa, pb) = (self.point(a, q, v), self.point(b, q, v));
                let l1 = lambdas.get(1).copied().unwrap_or(0.0);
                let drift = (pa.p[0] - pb.p[0]).hypot(pa.p[1] - pb.p[1]);
                [l0, l1, l0.hypot(l1), 0.0, drift]
            }
            JointKind::Rod { a, b, length } | JointKind::String { a, b, length, .. } => {
                let (pa, pb) = (self.point(a, q, v), self.point(b, q, v));
                let d = [pa.p[0] - pb.p[0], pa.p[1] - pb.p[1]];
                let l = d[0].hypot(d[1]).max(Real::MIN_POSITIVE);
                let engaged = !lambdas.is_empty();
                let drift = if engaged { l - length } else { 0.0 };
                [l0 * d[0] / l, l0 * d[1] / l, -l0, 0.0, drift]
            }
            JointKind::Contact {
                on,
                radius,
                point,
                normal,
                friction,
                ..
            } => {
                if lambdas.is_empty() {
                    return [0.0; 5];
                }
                let tangent = [normal[1], -normal[0]];
                let f = match friction {
                    Friction::Coulomb { mu_k, mode, .. } if q[mode] != 0.0 => -mu_k * q[mode] * l0,
                    Friction::None => 0.0,
                    _ => lambdas.get(1).copied().unwrap_or(0.0),
                };
                let p = self.point(on, q, v);
                let base = self.point(point, q, v);
                let gap = dot2([p.p[0] - base.p[0], p.p[1] - base.p[1]], normal) - radius;
                [
                    l0 * normal[0] + f * tangent[0],
                    l0 * normal[1] + f * tangent[1],
                    l0,
                    f,
                    gap,
                ]
            }
            JointKind::Curve { on, ref curve } => {
                let p = self.point(on, q, v);
                let [f, f1, _] = curve.eval(p.p[0]);
                let n = [-f1, 1.0];
                let len = n[0].hypot(n[1]);
                // the curve's force on the point: λ (-f', 1), its normal force λ √(1 + f'²)
                [l0 * n[0], l0 * n[1], l0 * len, 0.0, (p.p[1] - f) / len]
            }
            JointKind::Pulley { .. } => {
                let row = s.rows.iter().find(|r| r.joint == joint);
                // the force on `a` is the tension along its piece, towards the pulley
                let (fx, fy) = row.map_or((0.0, 0.0), |r| (r.j[0] * l0, r.j[1] * l0));
                let drift = row.and_then(|r| r.c).unwrap_or(0.0);
                [fx, fy, -l0, 0.0, drift]
            }
        }
    }

    /// The velocity change that makes every engaged constraint's rate zero (an inelastic
    /// impulse, applied when a contact or a string engages).
    pub(crate) fn impulse(&self, q: &[Real], v: &mut [Real]) {
        let rows = self.rows(q, v);
        let n = rows.len();
        let mut a = vec![0.0; n * n];
        let rhs: Vec<Real> = rows.iter().map(|r| -r.dot(v)).collect();
        for (i, ri) in rows.iter().enumerate() {
            for (k, rk) in rows.iter().enumerate() {
                let mut s = 0.0;
                for e in 0..ri.n {
                    for f in 0..rk.n {
                        if ri.idx[e] == rk.idx[f] {
                            s += ri.j[e] * self.inv_mass[ri.idx[e]] * rk.j[f];
                        }
                    }
                }
                a[i * n + k] = s;
            }
        }
        let lambda = gauss(&mut a, rhs, n);
        for (r, l) in rows.iter().zip(&lambda) {
            for e in 0..r.n {
                v[r.idx[e]] += self.inv_mass[r.idx[e]] * r.j[e] * l;
            }
        }
    }
}

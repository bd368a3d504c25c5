//! The constraint solver of a mechanism: its bodies, the rows of its engaged joints, and the
//! multipliers, forces, reports and impulses they give.

use std::sync::{Arc, Mutex};

use super::super::at::Turn;
use super::gauss::gauss;
use super::joint::{Anchor, Coords, Friction, Joint, JointKind, Point, Row, norm3, sub3};
use crate::Real;
use crate::particles::spin::{Quat, Spinner, cross, dot3, omega_world, rotate};

/// What each joint reports, in this order (`name.fx`, …): the force on its first body (world
/// components `fx`, `fy`, and `fz` last), the normal force or tension (N), the friction force
/// along the surface (N) and the constraint's violation (m).
pub const REPORT_FIELDS: [&str; REPORT_LEN] = ["fx", "fy", "N", "F", "drift", "fz"];

/// How many values each joint reports.
pub const REPORT_LEN: usize = 6;

/// A body of a mechanism, as the solver sees it.
#[derive(Debug, Clone, PartialEq)]
pub struct MechanismBody {
    /// Index of its `x` coordinate in `q` (`y`, and `z` in space, follow).
    pub x: usize,
    /// Index of its angle in `q`, for a rigid body in a plane.
    pub angle: Option<usize>,
    /// Its orientation, for a rigid body in space.
    pub spinner: Option<Spinner>,
    /// `1/m`.
    pub inv_mass: Real,
    /// `1/I` about the centre of mass (0 for a particle; unused in space).
    pub inv_inertia: Real,
}

/// The response `δq̈ = B Q` of a body turning in space to a generalized force on its
/// quaternion coordinates from `first`.
type Block = (usize, [[Real; 4]; 4]);

/// Bodies and joints, with the stabilisation time constant.
#[derive(Debug)]
pub struct Mechanism {
    dim: usize,
    bodies: Vec<MechanismBody>,
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
    /// A mechanism of `bodies` in `dim` dimensions (2 or 3) in a system of `dof` coordinates,
    /// joined by `joints`; its Baumgarte time constant is set once by [`Mechanism::set_tau`]
    /// (1 ms until then).
    pub fn new(bodies: Vec<MechanismBody>, joints: Vec<Joint>, dof: usize, dim: usize) -> Self {
        let mut inv_mass = vec![0.0; dof];
        for b in &bodies {
            for k in 0..dim {
                inv_mass[b.x + k] = b.inv_mass;
            }
            if let Some(a) = b.angle {
                inv_mass[a] = b.inv_inertia;
            }
        }
        Self {
            dim,
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

    /// The spatial dimension (2 or 3).
    pub fn dim(&self) -> usize {
        self.dim
    }

    pub(super) fn point(&self, a: Anchor, q: &[Real], v: &[Real]) -> Point {
        match a {
            Anchor::World(p) => Point {
                p,
                vel: [0.0; 3],
                w: [0.0; 3],
                omega: [0.0; 3],
                coords: None,
                material: [0.0; 3],
            },
            Anchor::Body { body, r } => {
                let b = &self.bodies[body];
                let (d, x) = (self.dim, b.x);
                let mut centre = [0.0; 3];
                let mut cv = [0.0; 3];
                centre[..d].copy_from_slice(&q[x..x + d]);
                cv[..d].copy_from_slice(&v[x..x + d]);
                let mut quat: Quat = [1.0, 0.0, 0.0, 0.0];
                let (w, omega, turn) = if let Some(sp) = &b.spinner {
                    let (qq, qd) = sp.of(q, v);
                    quat = qq;
                    (
                        rotate(qq, r),
                        omega_world(qq, qd),
                        Some(Turn::Quaternion(sp.first)),
                    )
                } else if let Some(i) = b.angle {
                    let (s, c) = q[i].sin_cos();
                    (
                        [c * r[0] - s * r[1], s * r[0] + c * r[1], r[2]],
                        [0.0, 0.0, v[i]],
                        Some(Turn::Angle(i)),
                    )
                } else {
                    (r, [0.0; 3], None)
                };
                let vel = cross(omega, w);
                Point {
                    p: [centre[0] + w[0], centre[1] + w[1], centre[2] + w[2]],
                    vel: [cv[0] + vel[0], cv[1] + vel[1], cv[2] + vel[2]],
                    w,
                    omega,
                    material: w,
                    coords: Some(Coords {
                        x,
                        dim: d,
                        turn,
                        quat,
                    }),
                }
            }
        }
    }

    /// The first engaged joint whose constraint is violated by more than `tol` at a state
    /// (a body inside its surface, a string stretched past its length, a rod or hinge not
    /// closed), with the violation.
    pub fn violation(&self, q: &[Real], v: &[Real], tol: Real) -> Option<(usize, Real)> {
        self.rows(q, v)
            .iter()
            .find_map(|r| r.c.filter(|c| c.abs() > tol).map(|c| (r.joint, c)))
    }

    /// The first engaged joint whose constraint's rate breaks it by more than `tol` at a state
    /// (a hinge's points moving apart, a contact's body moving into its surface, a string
    /// being stretched), with the rate.
    pub fn velocity_violation(&self, q: &[Real], v: &[Real], tol: Real) -> Option<(usize, Real)> {
        self.rows(q, v).iter().find_map(|r| {
            let breaks = match self.joints[r.joint].kind {
                JointKind::Contact { .. } if r.c.is_some() => r.jv < -tol,
                JointKind::String { .. } => r.jv > tol,
                _ => r.jv.abs() > tol,
            };
            breaks.then_some((r.joint, r.jv))
        })
    }

    /// Makes the velocities `v` satisfy every engaged joint at `q`: an inelastic impulse, the
    /// one a contact or a string takes when it engages.
    pub fn project_velocities(&self, q: &[Real], v: &mut [Real]) {
        self.impulse(q, v);
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

    /// The response blocks of the bodies turning in space at `q`.
    fn blocks(&self, q: &[Real]) -> Vec<Block> {
        self.bodies
            .iter()
            .filter_map(|b| b.spinner.as_ref())
            .map(|sp| {
                let (qq, _) = sp.of(q, q);
                let mut m = [[0.0; 4]; 4];
                for c in 0..4 {
                    let mut e = [0.0; 4];
                    e[c] = 1.0;
                    let r = sp.response(qq, e);
                    for (row, x) in m.iter_mut().zip(r) {
                        row[c] = x;
                    }
                }
                (sp.first, m)
            })
            .collect()
    }

    /// `M⁻¹` between coordinates `i` and `j`.
    fn minv(&self, blocks: &[Block], i: usize, j: usize) -> Real {
        if i == j && self.inv_mass[i] != 0.0 {
            return self.inv_mass[i];
        }
        blocks
            .iter()
            .find(|(f, _)| (*f..f + 4).contains(&i) && (*f..f + 4).contains(&j))
            .map_or(0.0, |(f, m)| m[i - f][j - f])
    }

    /// `J M⁻¹ Dᵀ` between two rows.
    fn coupling(&self, blocks: &[Block], ri: &Row, rk: &Row, d: bool) -> Real {
        let mut s = 0.0;
        for e in 0..ri.n {
            for f in 0..rk.n {
                let m = self.minv(blocks, ri.idx[e], rk.idx[f]);
                if m != 0.0 {
                    s += ri.j[e] * m * if d { rk.d[f] } else { rk.j[f] };
                }
            }
        }
        s
    }

    /// The accelerations the applied generalized forces alone give (Euler's equations for
    /// the bodies turning in space).
    fn free_accel(&self, q: &[Real], v: &[Real], applied: &[Real]) -> Vec<Real> {
        let mut a: Vec<Real> = applied
            .iter()
            .zip(&self.inv_mass)
            .map(|(f, w)| f * w)
            .collect();
        for sp in self.bodies.iter().filter_map(|b| b.spinner.as_ref()) {
            let (qq, qd) = sp.of(q, v);
            let f = sp.first;
            let out = sp.accel(
                qq,
                qd,
                [applied[f], applied[f + 1], applied[f + 2], applied[f + 3]],
            );
            a[f..f + 4].copy_from_slice(&out);
        }
        a
    }

    /// The multipliers of the engaged constraints under the applied generalised forces.
    pub(crate) fn solve(&self, q: &[Real], v: &[Real], applied: &[Real]) -> Solution {
        let rows = self.rows(q, v);
        let n = rows.len();
        let mut a = vec![0.0; n * n];
        let mut rhs = vec![0.0; n];
        let tau = self.tau();
        let (k1, k2) = (2.0 / tau, 1.0 / (tau * tau));
        let blocks = self.blocks(q);
        let free_accel = self.free_accel(q, v, applied);
        for (i, ri) in rows.iter().enumerate() {
            let free = ri.dot(&free_accel);
            rhs[i] = -(free + ri.bias + k1 * ri.jv + ri.c.map_or(0.0, |c| k2 * c));
            for (k, rk) in rows.iter().enumerate() {
                a[i * n + k] = self.coupling(&blocks, ri, rk, true);
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
    pub(crate) fn report(
        &self,
        s: &Solution,
        joint: usize,
        q: &[Real],
        v: &[Real],
    ) -> [Real; REPORT_LEN] {
        let lambdas: Vec<Real> = s
            .rows
            .iter()
            .zip(&s.lambda)
            .filter(|(r, _)| r.joint == joint)
            .map(|(_, l)| *l)
            .collect();
        let l = |k: usize| lambdas.get(k).copied().unwrap_or(0.0);
        let l0 = l(0);
        match self.joints[joint].kind {
            JointKind::Hinge { a, b, .. } => {
                let (pa, pb) = (self.point(a, q, v), self.point(b, q, v));
                let drift = norm3(sub3(pa.p, pb.p));
                let f = [l0, l(1), l(2)];
                [f[0], f[1], norm3(f), 0.0, drift, f[2]]
            }
            JointKind::Rod { a, b, length } | JointKind::String { a, b, length, .. } => {
                let (pa, pb) = (self.point(a, q, v), self.point(b, q, v));
                let d = sub3(pa.p, pb.p);
                let len = norm3(d).max(Real::MIN_POSITIVE);
                let engaged = !lambdas.is_empty();
                let drift = if engaged { len - length } else { 0.0 };
                let k = l0 / len;
                [k * d[0], k * d[1], -l0, 0.0, drift, k * d[2]]
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
                    return [0.0; REPORT_LEN];
                }
                let [t, b] = self.tangents(normal);
                let (ft, fb) = match friction {
                    Friction::Coulomb { mu_k, mode, .. } if q[mode] != 0.0 => {
                        (-mu_k * q[mode] * l0, 0.0)
                    }
                    Friction::None => (0.0, 0.0),
                    _ => (l(1), if self.dim == 3 { l(2) } else { 0.0 }),
                };
                let p = self.point(on, q, v);
                let base = self.point(point, q, v);
                let gap = dot3(sub3(p.p, base.p), normal) - radius;
                let f = [0, 1, 2].map(|k| l0 * normal[k] + ft * t[k] + fb * b[k]);
                // in a plane the friction is signed along the tangent; in space its magnitude
                let friction = if self.dim == 2 { ft } else { ft.hypot(fb) };
                [f[0], f[1], l0, friction, gap, f[2]]
            }
            JointKind::Curve { on, ref curve } => {
                let p = self.point(on, q, v);
                let [f, f1, _] = curve.eval(p.p[0]);
                let n = [-f1, 1.0];
                let len = n[0].hypot(n[1]);
                // the curve's force on the point: λ (-f', 1), its normal force λ √(1 + f'²)
                [l0 * n[0], l0 * n[1], l0 * len, 0.0, (p.p[1] - f) / len, 0.0]
            }
            JointKind::Pulley { .. } => {
                let row = s.rows.iter().find(|r| r.joint == joint);
                // the force on `a` is the tension along its piece, towards the pulley
                let (fx, fy) = row.map_or((0.0, 0.0), |r| (r.j[0] * l0, r.j[1] * l0));
                let drift = row.and_then(|r| r.c).unwrap_or(0.0);
                [fx, fy, -l0, 0.0, drift, 0.0]
            }
        }
    }

    /// The velocity change that makes every engaged constraint's rate zero (an inelastic
    /// impulse, applied when a contact or a string engages), with the modes as in `q`: a
    /// sliding contact's impulse carries its kinetic friction, `−μₖ s` times its normal part
    /// (the rows' force directions `D`, as in [`Mechanism::solve`]). Returns each row's joint
    /// and multiplier (a contact's normal impulse first, then its tangential ones).
    pub(crate) fn impulse(&self, q: &[Real], v: &mut [Real]) -> Vec<(usize, Real)> {
        let rows = self.rows(q, v);
        let n = rows.len();
        let blocks = self.blocks(q);
        let mut a = vec![0.0; n * n];
        let rhs: Vec<Real> = rows.iter().map(|r| -r.dot(v)).collect();
        for (i, ri) in rows.iter().enumerate() {
            for (k, rk) in rows.iter().enumerate() {
                a[i * n + k] = self.coupling(&blocks, ri, rk, true);
            }
        }
        let lambda = gauss(&mut a, rhs, n);
        let mut impulse = vec![0.0; v.len()];
        for (r, l) in rows.iter().zip(&lambda) {
            for e in 0..r.n {
                impulse[r.idx[e]] += r.d[e] * l;
            }
        }
        for (i, p) in impulse.iter().enumerate() {
            v[i] += self.inv_mass[i] * p;
        }
        for (f, m) in &blocks {
            for (r, row) in m.iter().enumerate() {
                v[f + r] += (0..4).map(|c| row[c] * impulse[f + c]).sum::<Real>();
            }
        }
        rows.iter().map(|r| r.joint).zip(lambda).collect()
    }
}

//! The rows of a mechanism's engaged joints at a state: each a scalar constraint on body
//! points at the acceleration level (`J a + J̇ v`, with the constraint's value and rate for
//! the stabilisation).

use super::joint::{Anchor, Friction, JointKind, Point, Row, norm3, sub3};
use super::solve::Mechanism;
use crate::Real;
use crate::particles::spin::{cross, dot3};

impl Mechanism {
    /// Whether a switching joint is engaged (contact touching, string taut) at `q`.
    fn engaged(q: &[Real], mode: usize) -> bool {
        q[mode] > 0.5
    }

    /// The rows of every engaged constraint at a state.
    pub(crate) fn rows(&self, q: &[Real], v: &[Real]) -> Vec<Row> {
        let mut rows = Vec::with_capacity(2 * self.joints.len());
        for (ji, joint) in self.joints.iter().enumerate() {
            match joint.kind {
                JointKind::Hinge { a, b, axis } => {
                    let (pa, pb) = (self.point(a, q, v), self.point(b, q, v));
                    let axes = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
                    for (axis, u) in axes.into_iter().take(self.dim()).enumerate() {
                        let mut row = Row::new(ji);
                        pa.add(&mut row, u, 1.0);
                        pb.add(&mut row, u, -1.0);
                        row.c = Some(pa.p[axis] - pb.p[axis]);
                        rows.push(row);
                    }
                    if let Some([da, db]) = axis {
                        // the bodies turn alike about the two directions across the axis
                        let (ua, ub) = (pa.direction(da), pb.direction(db));
                        let [e1, e2] = self.tangents(ua);
                        let rel = sub3(pa.omega, pb.omega);
                        for (e, c) in [(e1, dot3(e2, ub)), (e2, -dot3(e1, ub))] {
                            let mut row = Row::new(ji);
                            pa.add_angular(&mut row, e, 1.0);
                            pb.add_angular(&mut row, e, -1.0);
                            row.bias += dot3(rel, cross(pa.omega, e));
                            row.c = Some(c);
                            rows.push(row);
                        }
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
                    nrow.c = Some(dot3(sub3(p.p, base.p), normal) - radius);
                    let [tangent, binormal] = self.tangents(normal);
                    let contact = p.shifted([
                        -radius * normal[0],
                        -radius * normal[1],
                        -radius * normal[2],
                    ]);
                    let mut trow = Row::new(ji);
                    contact.add(&mut trow, tangent, 1.0);
                    base.add(&mut trow, tangent, -1.0);
                    match friction {
                        Friction::None => rows.push(nrow),
                        Friction::NoSlip => {
                            rows.push(nrow);
                            rows.push(trow);
                            if self.dim() == 3 {
                                let mut brow = Row::new(ji);
                                contact.add(&mut brow, binormal, 1.0);
                                base.add(&mut brow, binormal, -1.0);
                                rows.push(brow);
                            }
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
                    p.add(&mut row, [-f1, 1.0, 0.0], 1.0);
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
        let u = [piece[0] / l, piece[1] / l, 0.0];
        p.add(row, u, 1.0);
        c.add(row, u, -1.0);
        let ud = u[0] * dd[0] + u[1] * dd[1];
        row.bias += (dd[0] * dd[0] + dd[1] * dd[1] - ud * ud) / l;
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
        let d = sub3(pa.p, pb.p);
        let dd = sub3(pa.vel, pb.vel);
        let l = norm3(d).max(Real::MIN_POSITIVE);
        let u = [d[0] / l, d[1] / l, d[2] / l];
        let mut row = Row::new(ji);
        pa.add(&mut row, u, 1.0);
        pb.add(&mut row, u, -1.0);
        let ud = dot3(u, dd);
        row.bias += (dot3(dd, dd) - ud * ud) / l;
        row.c = Some(l - length);
        row
    }

    /// Two unit vectors along a surface of unit normal `normal`: in a plane the tangent
    /// `(n_y, −n_x)` (and `z`), in space an orthonormal pair with the normal.
    pub(super) fn tangents(&self, normal: [Real; 3]) -> [[Real; 3]; 2] {
        if self.dim() == 2 {
            return [[normal[1], -normal[0], 0.0], [0.0, 0.0, 1.0]];
        }
        // the axis least along the normal, made orthogonal to it
        let k = (0..3)
            .min_by(|&i, &j| normal[i].abs().total_cmp(&normal[j].abs()))
            .unwrap_or(0);
        let mut e = [0.0; 3];
        e[k] = 1.0;
        let t = cross(normal, e);
        let n = norm3(t);
        let t = [t[0] / n, t[1] / n, t[2] / n];
        [t, cross(normal, t)]
    }
}

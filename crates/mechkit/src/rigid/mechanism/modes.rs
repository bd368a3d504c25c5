//! The switching of a planar mechanism's joints: gaps, sliding speeds, the modes at the start
//! and the events that engage and release contacts and strings, and make them stick or slide.

use std::sync::Arc;

use super::joint::{Friction, JointKind, norm3, sub3};
use super::solve::Mechanism;
use super::solve::REPORT_LEN;
use crate::Real;
use crate::particles::spin::dot3;
use crate::particles::{ParticleSystem, Sample};
use crate::simulate::{Condition, Direction, Event};

/// Static friction holds up to `μₛ N` and this relative margin: the friction a contact at rest
/// needs is computed with rounding errors (and the drift corrections of the constraints), so
/// at a load of exactly `μₛ N` (a cylinder at the least `μ` for rolling, a block at the angle
/// of friction) rounding would decide, at a time that depends on the steps, whether it holds.
/// At the bound it holds, as `|f| ≤ μₛ N` says; a load 1e-8 above it slips.
pub const STATIC_MARGIN: Real = 1e-8;

/// Whether static friction `f` exceeds `mu_s` times the normal force `n` (by more than
/// [`STATIC_MARGIN`]).
fn beyond_static(f: Real, mu_s: Real, n: Real) -> bool {
    f.abs() > mu_s * n * (1.0 + STATIC_MARGIN)
}

impl Mechanism {
    /// A switching joint's gap: how far a contact is from its line, how much slack a string
    /// has (negative when stretched past its length).
    pub(crate) fn gap(&self, joint: usize, q: &[Real]) -> Real {
        let zero = vec![0.0; q.len()];
        match self.joints[joint].kind {
            JointKind::Contact {
                on,
                radius,
                point,
                normal,
                ..
            } => {
                let (p, base) = (self.point(on, q, &zero), self.point(point, q, &zero));
                dot3(sub3(p.p, base.p), normal) - radius
            }
            JointKind::String { a, b, length, .. } => {
                let (pa, pb) = (self.point(a, q, &zero), self.point(b, q, &zero));
                length - norm3(sub3(pa.p, pb.p))
            }
            _ => 0.0,
        }
    }

    /// A contact's sliding velocity along its line (the velocity of the body's material point
    /// at the contact).
    pub(crate) fn slip(&self, joint: usize, q: &[Real], v: &[Real]) -> Real {
        if let JointKind::Contact {
            on,
            radius,
            normal,
            point,
            ..
        } = self.joints[joint].kind
        {
            let p = self.point(on, q, v).shifted([
                -radius * normal[0],
                -radius * normal[1],
                -radius * normal[2],
            ]);
            let base = self.point(point, q, v);
            dot3(sub3(p.vel, base.vel), [normal[1], -normal[0], 0.0])
        } else {
            0.0
        }
    }

    /// The report of joint `joint` at a state of `sys` with its modes as in `q`.
    pub(crate) fn report_at(
        &self,
        sys: &ParticleSystem,
        joint: usize,
        t: Real,
        q: &[Real],
        v: &[Real],
    ) -> [Real; REPORT_LEN] {
        let mut applied = vec![0.0; q.len()];
        sys.forces()
            .applied_into(&sys.kinematics(t, q, v), &mut applied);
        let s = self.solve(q, v, &applied);
        self.report(&s, joint, q, v)
    }

    /// The modes at the start: contacts touching where their gap is within `tol` of zero and
    /// the line pushes, strings taut where stretched to their length and pulling, friction
    /// sticking where the contact point is at rest and static friction holds, else sliding.
    pub fn initial_modes(&self, sys: &ParticleSystem, q: &mut [Real], v: &mut [Real], tol: Real) {
        for (ji, joint) in self.joints.iter().enumerate() {
            let (JointKind::Contact { mode, .. } | JointKind::String { mode, .. }) = joint.kind
            else {
                continue;
            };
            q[mode] = if self.gap(ji, q) <= tol { 1.0 } else { 0.0 };
            if let JointKind::Contact {
                friction: Friction::Coulomb { mode: m, .. },
                ..
            } = joint.kind
            {
                let u = self.slip(ji, q, v);
                q[m] = if u.abs() > tol { u.signum() } else { 0.0 };
            }
        }
        self.settle(sys, 0.0, q, v);
    }

    /// Makes the modes at a state agree with the forces they give: an engaged contact or
    /// string whose force pulls the wrong way lets go, and a sticking contact whose friction
    /// would exceed `μₛ N` slides, against that friction (at the start, and after an impact
    /// or a switch, where no event can see a bound already broken: its function does not
    /// cross zero, it starts beyond it).
    pub(crate) fn settle(&self, sys: &ParticleSystem, t: Real, q: &mut [Real], v: &[Real]) {
        for _ in 0..=self.joints.len() {
            let mut changed = false;
            for (ji, joint) in self.joints.iter().enumerate() {
                let r = self.report_at(sys, ji, t, q, v);
                match joint.kind {
                    JointKind::Contact { mode, friction, .. } => {
                        if q[mode] > 0.5 && r[2] < 0.0 {
                            q[mode] = 0.0;
                            changed = true;
                        } else if let Friction::Coulomb { mu_s, mode: m, .. } = friction
                            && q[mode] > 0.5
                            && q[m] == 0.0
                            && beyond_static(r[3], mu_s, r[2])
                        {
                            q[m] = -r[3].signum();
                            changed = true;
                        }
                    }
                    JointKind::String { mode, .. } if q[mode] > 0.5 && r[2] < 0.0 => {
                        q[mode] = 0.0;
                        changed = true;
                    }
                    _ => {}
                }
            }
            if !changed {
                break;
            }
        }
    }

    /// The events that switch the joints' modes; the joint forces are the system's forces
    /// `first_force..`, in the order of the joints.
    pub fn events(self: &Arc<Self>, first_force: usize) -> Vec<Event> {
        let mut events = Vec::new();
        for (ji, joint) in self.joints.iter().enumerate() {
            let name = joint.name.clone();
            let field = move |s: &Sample<'_>, k: usize| {
                s.eval
                    .constraint
                    .get((first_force + ji) * REPORT_LEN + k)
                    .copied()
                    .unwrap_or(Real::NAN)
            };
            let (mode, what) = match joint.kind {
                JointKind::Contact { mode, .. } => (mode, ("lets go", "touches")),
                JointKind::String { mode, .. } => (mode, ("goes slack", "goes taut")),
                JointKind::Pulley {
                    a,
                    b,
                    centre,
                    radius,
                    length,
                    ..
                } => {
                    // an end drawn up to the wheel: the ideal string over a pulley is not
                    // modelled past it (it would carry the body round the rim), so the run
                    // ends there, as at a stop condition. The straight piece's length
                    // `l = √(d² − R²)` falls to zero at the string's speed and rises again
                    // past the tangent point; near the rim (within a hundredth of the
                    // string's length) it is signed by whether the end approaches the wheel,
                    // so that passing the tangent point is a crossing of zero
                    for (end, anchor) in [("a", a), ("b", b)] {
                        let mech = Arc::clone(self);
                        let near = 0.01 * length;
                        events.push(
                            Event::new(format!("{name} end {end} reaches the rim"), move |s, _| {
                                let (p, c) =
                                    (mech.point(anchor, s.q, s.v), mech.point(centre, s.q, s.v));
                                let r = sub3(p.p, c.p);
                                let d = norm3(r);
                                let l = ((d - radius) * (d + radius)).max(0.0).sqrt();
                                if l < near && dot3(r, sub3(p.vel, c.vel)) > 0.0 {
                                    -l
                                } else {
                                    l
                                }
                            })
                            .direction(Direction::Falling)
                            .stop(),
                        );
                    }
                    continue;
                }
                _ => continue,
            };
            // engaged → free when the force reaches zero
            events.push(
                Event::from_function(Condition::from_fn(
                    format!("{name} {}", what.0),
                    false,
                    true,
                    move |s, _| if s.q[mode] > 0.5 { field(s, 2) } else { 1.0 },
                ))
                .direction(Direction::Falling)
                .set(move |_, _, y| y[mode] = 0.0),
            );
            // free → engaged when the gap closes
            let mech = Arc::clone(self);
            let mech2 = Arc::clone(self);
            events.push(
                Event::new(format!("{name} {}", what.1), move |s, _| {
                    if s.q[mode] > 0.5 {
                        1.0
                    } else {
                        mech.gap(ji, s.q)
                    }
                })
                .direction(Direction::Falling)
                .set(move |s, sys, y| {
                    let n = s.q.len();
                    y[mode] = 1.0;
                    let (q, v) = y.split_at_mut(n);
                    mech2.engage(sys, s.t, q, v);
                }),
            );
            if let JointKind::Contact {
                friction: Friction::Coulomb { mu_s, mode: m, .. },
                ..
            } = joint.kind
            {
                // sticking → sliding when static friction cannot hold
                events.push(
                    Event::from_function(Condition::from_fn(
                        format!("{name} slips"),
                        false,
                        true,
                        move |s, _| {
                            if s.q[mode] > 0.5 && s.q[m] == 0.0 {
                                mu_s * field(s, 2) * (1.0 + STATIC_MARGIN) - field(s, 3).abs()
                            } else {
                                1.0
                            }
                        },
                    ))
                    .direction(Direction::Falling)
                    .set(move |s, _, y| y[m] = -field(s, 3).signum()),
                );
                // sliding → sticking when the sliding stops, if static friction holds
                let mech = Arc::clone(self);
                let mech2 = Arc::clone(self);
                events.push(
                    Event::new(format!("{name} sticks"), move |s, _| {
                        if s.q[mode] > 0.5 && s.q[m] != 0.0 {
                            s.q[m] * mech.slip(ji, s.q, s.v)
                        } else {
                            1.0
                        }
                    })
                    .direction(Direction::Falling)
                    .set(move |s, sys, y| {
                        let n = s.q.len();
                        y[m] = 0.0;
                        let (q, v) = y.split_at_mut(n);
                        let r = mech2.report_at(sys, ji, s.t, q, v);
                        if beyond_static(r[3], mu_s, r[2]) {
                            // it slides on the way static friction cannot hold it, against
                            // that friction (the other way than before when the sliding
                            // reverses, the same way when it only touched zero)
                            q[m] = -r[3].signum();
                        } else {
                            mech2.impulse(q, v);
                        }
                    }),
                );
            }
        }
        events
    }
}

//! Each joint of a planar mechanism as a force of the particle system ([`JointForce`]).

use std::sync::Arc;

use super::joint::{Anchor, Joint, JointKind};
use super::solve::{Mechanism, REPORT_LEN};
use crate::Real;
use crate::animation::{Attachment, SceneItem};
use crate::forces::Force;
use crate::particles::Kinematics;

/// One joint of a mechanism as a force of the particle system: the constraint forces of that
/// joint, given the applied forces (every force that is not a joint).
#[derive(Debug, Clone)]
pub struct JointForce {
    mechanism: Arc<Mechanism>,
    joint: usize,
    bodies: Vec<usize>,
}

impl JointForce {
    /// Joint `joint` of `mechanism`, acting on `bodies`.
    pub fn new(mechanism: Arc<Mechanism>, joint: usize, bodies: Vec<usize>) -> Self {
        Self {
            mechanism,
            joint,
            bodies,
        }
    }
}

impl Force for JointForce {
    fn sketch(&self) -> Vec<SceneItem> {
        let Some(joint) = self.mechanism.joints.get(self.joint) else {
            return Vec::new();
        };
        let end = |a: &Anchor| match *a {
            Anchor::World(p) => Attachment::Fixed(p),
            Anchor::Body { body, r } => Attachment::Body { body, offset: r },
        };
        match &joint.kind {
            JointKind::Rod { a, b, .. } | JointKind::Hinge { a, b, .. } => vec![SceneItem::Rod {
                a: end(a),
                b: end(b),
            }],
            JointKind::String { a, b, .. } => vec![SceneItem::String {
                a: end(a),
                b: end(b),
            }],
            JointKind::Pulley {
                a,
                b,
                centre,
                radius,
                sense,
                ..
            } => {
                // the string leaves the wheel at its side towards each end
                let side = |s: Real| match end(centre) {
                    Attachment::Fixed(c) => Attachment::Fixed([c[0] + s * radius, c[1], c[2]]),
                    Attachment::Body { body, .. } | Attachment::Beside { body, .. } => {
                        Attachment::Beside {
                            body,
                            offset: [s * radius, 0.0, 0.0],
                        }
                    }
                };
                let mut items = vec![
                    SceneItem::String {
                        a: end(a),
                        b: side(-sense),
                    },
                    SceneItem::String {
                        a: side(*sense),
                        b: end(b),
                    },
                ];
                if let Anchor::World(c) = centre {
                    items.push(SceneItem::Pulley {
                        centre: *c,
                        radius: *radius,
                    });
                }
                items
            }
            JointKind::Contact {
                point: Anchor::World(point),
                normal,
                ..
            } => vec![SceneItem::Wall {
                point: *point,
                normal: *normal,
            }],
            JointKind::Contact { .. } | JointKind::Curve { .. } => Vec::new(),
        }
    }

    fn name(&self) -> &str {
        &self.mechanism.joints[self.joint].name
    }

    fn add_forces(&self, k: &Kinematics<'_>, out: &mut [Real]) {
        let applied = vec![0.0; out.len()];
        self.add_constraint_forces(k, &applied, out);
    }

    fn velocity_dependent(&self) -> bool {
        true
    }

    fn bodies(&self) -> Vec<usize> {
        self.bodies.clone()
    }

    fn constraint(&self) -> bool {
        true
    }

    fn add_constraint_forces(&self, k: &Kinematics<'_>, applied: &[Real], out: &mut [Real]) {
        let s = self.mechanism.solved(k.x, k.v, applied);
        Mechanism::add_forces(&s, self.joint, out);
    }

    fn constraint_report(&self, k: &Kinematics<'_>, applied: &[Real]) -> [Real; REPORT_LEN] {
        let s = self.mechanism.solved(k.x, k.v, applied);
        self.mechanism.report(&s, self.joint, k.x, k.v)
    }

    fn internal(&self) -> bool {
        !self.mechanism.joints[self.joint].touches_world()
    }
}

impl Joint {
    /// Whether it holds a body to the world (and so can change the momentum).
    pub fn touches_world(&self) -> bool {
        let world = |a: &Anchor| matches!(a, Anchor::World(_));
        match &self.kind {
            JointKind::Hinge { a, b, .. }
            | JointKind::Rod { a, b, .. }
            | JointKind::String { a, b, .. } => world(a) || world(b),
            JointKind::Contact { point, .. } => world(point),
            JointKind::Pulley { .. } | JointKind::Curve { .. } => true,
        }
    }
}

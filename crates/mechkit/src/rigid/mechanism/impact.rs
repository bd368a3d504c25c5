//! A contact or a string engaging: the inelastic impulse, bounded by Coulomb friction, and
//! the modes that follow.
//!
//! The impulse removes the approach speed of every engaged joint. At a contact with Coulomb
//! friction it first tries to stop the sliding too (sticking: a normal impulse `Pₙ` and a
//! tangential one `Pₜ`); where that needs `|Pₜ| > μₛ Pₙ` friction cannot stop it within the
//! impact, and the contact slides through it, opposed by `μₖ Pₙ` (Routh's impact with
//! friction, for sliding that does not reverse during the impact). A sliding contact whose
//! slip the impulse would reverse sticks instead. After the impulse the modes are settled
//! against the forces ([`Mechanism::settle`]): a block landing on a slope steeper than its
//! friction angle slides on, whatever the impact left of its speed along the slope.

use super::joint::{Friction, JointKind};
use super::solve::Mechanism;
use crate::Real;
use crate::particles::ParticleSystem;

impl Mechanism {
    /// Engages at time `t` what the modes in `q` say is engaged: the impulse bounded by
    /// friction, then the modes settled against the forces.
    pub(crate) fn engage(&self, sys: &ParticleSystem, t: Real, q: &mut [Real], v: &mut [Real]) {
        let v0 = v.to_vec();
        let mut changed = true;
        for _ in 0..=self.joints.len() {
            v.copy_from_slice(&v0);
            let lambdas = self.impulse(q, v);
            changed = false;
            for (ji, joint) in self.joints.iter().enumerate() {
                let JointKind::Contact {
                    mode,
                    friction: Friction::Coulomb { mu_s, mode: m, .. },
                    ..
                } = joint.kind
                else {
                    continue;
                };
                if q[mode] < 0.5 {
                    continue;
                }
                if q[m] == 0.0 {
                    let mut mine = lambdas.iter().filter(|(j, _)| *j == ji).map(|(_, l)| *l);
                    let (pn, pt) = (mine.next().unwrap_or(0.0), mine.next().unwrap_or(0.0));
                    if pt.abs() > mu_s * pn.max(0.0) {
                        // it slides the way friction would have had to stop it from
                        q[m] = -pt.signum();
                        changed = true;
                    }
                } else if q[m] * self.slip(ji, q, v) < 0.0 {
                    q[m] = 0.0;
                    changed = true;
                }
            }
            if !changed {
                break;
            }
        }
        if changed {
            // out of rounds: the impulse of the modes as they ended
            v.copy_from_slice(&v0);
            self.impulse(q, v);
        }
        self.settle(sys, t, q, v);
    }
}

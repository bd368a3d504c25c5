//! The damping part of a contact force, a force of its own so that the energy ledger books its
//! work as non-conservative (see [`super::ContactForce`]).

use super::contact::ContactForce;
use super::contact_emit::emit_damping;
use super::emit::ForceEmitter;
use super::force::Force;
use crate::Real;
use crate::particles::Kinematics;

/// The damping part of a contact, `F - F_e` along each contact's normal (with the clamping of
/// the total at zero): velocity-dependent, without a potential. Made by
/// [`ContactForce::damper`].
#[derive(Debug, Clone, PartialEq)]
pub struct ContactDamper {
    name: String,
    contact: ContactForce,
}

impl ContactDamper {
    /// The damper of `contact`, named `name`.
    pub(super) fn new(name: String, contact: ContactForce) -> Self {
        Self { name, contact }
    }

    /// The contact it damps.
    pub fn contact(&self) -> &ContactForce {
        &self.contact
    }
}

impl Force for ContactDamper {
    fn name(&self) -> &str {
        &self.name
    }

    /// `(F - F_e) n̂` of every overlapping contact, `F` being the clamped total
    /// ([`ContactForce::normal_force`]).
    fn add_forces(&self, k: &Kinematics<'_>, out: &mut [Real]) {
        let c = &self.contact;
        let (law, dim) = (c.law(), c.dim());
        c.for_each_touch(k, |t| {
            let f = c.normal_force(t.delta, t.rate) - law.force(t.delta);
            t.apply(f, dim, out);
        });
    }

    fn emit(&self, e: &mut ForceEmitter<'_>) -> bool {
        let c = &self.contact;
        c.emit_touches(e, |e, t| emit_damping(e, c, t))
    }

    fn velocity_dependent(&self) -> bool {
        true
    }

    fn bodies(&self) -> Vec<usize> {
        self.contact.body_list()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::forces::{ContactDamping, ContactLaw};

    fn forces(f: &dyn Force, x: &[Real], v: &[Real]) -> Vec<Real> {
        let k = Kinematics {
            t: 0.0,
            dim: 1,
            x,
            v,
            mass: &[1.0, 1.0],
        };
        let mut out = vec![0.0; x.len()];
        f.add_forces(&k, &mut out);
        out
    }

    #[test]
    fn attraction_when_allowed() {
        let c = ContactForce::builder(1)
            .law(ContactLaw::linear(10.0))
            .damping(ContactDamping::Linear { c: 4.0 })
            .allow_attraction(true)
            .pair(0, 1, 1.0)
            .build()
            .unwrap();
        assert!((c.normal_force(0.2, -1.0) + 2.0).abs() < 1e-12);
        assert_eq!(c.normal_force(-0.2, 5.0), 0.0);
        // in 1-D the normal is the sign of x_b - x_a: b left of a is pushed left
        assert_eq!(forces(&c, &[0.0, -0.5], &[0.0, 0.0]), vec![5.0, -5.0]);
        // receding at 2 m/s: the damper pulls with 8 N, more than the spring's 5 N push
        let d = c.damper().unwrap();
        assert_eq!(forces(&d, &[0.0, -0.5], &[0.0, -2.0]), vec![-8.0, 8.0]);
        assert!(d.velocity_dependent() && !c.velocity_dependent());
        assert_eq!((d.name(), d.bodies()), ("contact_damping", vec![0, 1]));
        assert_eq!(c.clone().into_forces().len(), 2);
    }
}

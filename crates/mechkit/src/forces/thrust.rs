//! Variable mass: the thrust of a rocket ejecting mass, and the kinetic energy the ejected
//! mass carries away.
//!
//! A body of mass `m` that ejects `|ṁ|` kilograms per second at the exhaust speed `u` relative
//! to itself feels the thrust `u |ṁ| ê` (ê the thrust direction): with it, `m dv/dt = F_ext +
//! u |ṁ| ê` is the rocket equation. Its kinetic energy then changes by
//! `d(½ m v²)/dt = (F_ext + thrust)·v + ½ ṁ v²`: the last term, the kinetic energy that leaves
//! with the ejected mass, is booked as the "work" of [`Exhaust`] so that the energy ledger
//! closes, and the momentum it carries away, `ṁ v` per second, as its impulse, so that the
//! momentum ledger closes too. The mass itself is a coordinate of the particle system
//! ([`crate::particles::ParticleSystemBuilder::variable_mass`]) whose rate is `ṁ` while the
//! engine burns and zero after burnout.

use super::force::Force;
use crate::Real;
use crate::particles::{Kinematics, dot};

/// The thrust `u |ṁ| ê` on body `body` while its mass coordinate `mass` decreases.
#[derive(Debug, Clone, PartialEq)]
pub struct Thrust {
    name: String,
    body: usize,
    mass: usize,
    exhaust_speed: Real,
    direction: Vec<Real>,
}

impl Thrust {
    /// The thrust on `body`, whose mass is coordinate `mass` of `q`, ejecting at
    /// `exhaust_speed` (m/s) against the unit vector `direction`.
    pub fn new(
        name: impl Into<String>,
        body: usize,
        mass: usize,
        exhaust_speed: Real,
        direction: Vec<Real>,
    ) -> Self {
        Self {
            name: name.into(),
            body,
            mass,
            exhaust_speed,
            direction,
        }
    }
}

impl Force for Thrust {
    fn name(&self) -> &str {
        &self.name
    }

    fn add_forces(&self, k: &Kinematics<'_>, out: &mut [Real]) {
        let rate = -k.v[self.mass];
        if rate > 0.0 {
            let d = k.dim;
            for (o, e) in out[self.body * d..(self.body + 1) * d]
                .iter_mut()
                .zip(&self.direction)
            {
                *o += self.exhaust_speed * rate * e;
            }
        }
    }

    fn bodies(&self) -> Vec<usize> {
        vec![self.body]
    }
}

/// The kinetic energy the mass ejected by body `body` carries away, `½ ṁ v²` per second
/// (negative while it burns), and its momentum, `ṁ v` per second: a ledger entry with no
/// force.
#[derive(Debug, Clone, PartialEq)]
pub struct Exhaust {
    name: String,
    body: usize,
    mass: usize,
}

impl Exhaust {
    /// The exhaust of `body`, whose mass is coordinate `mass` of `q`.
    pub fn new(name: impl Into<String>, body: usize, mass: usize) -> Self {
        Self {
            name: name.into(),
            body,
            mass,
        }
    }
}

impl Force for Exhaust {
    fn name(&self) -> &str {
        &self.name
    }

    fn add_forces(&self, _k: &Kinematics<'_>, _out: &mut [Real]) {}

    fn extra_power(&self, k: &Kinematics<'_>) -> Real {
        let v = k.velocity(self.body);
        0.5 * k.v[self.mass] * dot(v, v)
    }

    /// The momentum the ejected mass carries away at the body's velocity, `ṁ v` per second:
    /// with it the momentum ledger closes, `d(m v)/dt = F + thrust + ṁ v`.
    fn extra_momentum_rate(&self, k: &Kinematics<'_>, net: &mut [Real]) {
        let rate = k.v[self.mass];
        for (n, vk) in net.iter_mut().zip(k.velocity(self.body)) {
            *n += rate * vk;
        }
    }

    fn velocity_dependent(&self) -> bool {
        true
    }

    fn bodies(&self) -> Vec<usize> {
        vec![self.body]
    }
}

//! What the contact tests share: systems with a contact force, tight DOP853 settings, and an
//! observer of the energy.

use mechkit::forces::ContactForce;
use mechkit::particles::Sample;
use mechkit::prelude::*;
use mechkit::simulate::{Observer, ObserverError};

/// Gravity (m/s²), as in the course.
pub const G: f64 = 9.81;

/// Bodies of masses `masses` (named b0, b1, …) under the contact and `extra` forces.
pub fn system(
    dim: usize,
    masses: &[f64],
    contact: ContactForce,
    extra: Vec<Box<dyn Force>>,
) -> ParticleSystem {
    let mut b = ParticleSystem::builder(dim);
    for (i, &m) in masses.iter().enumerate() {
        b = b.body(format!("b{i}"), m);
    }
    for f in contact.into_forces().into_iter().chain(extra) {
        b = b.boxed_force(f);
    }
    b.build().unwrap()
}

pub fn dop853(rtol: f64) -> AdaptiveConfig {
    AdaptiveConfig {
        rtol: Tolerance::Scalar(rtol),
        atol: Tolerance::Scalar(rtol * 1e-2),
        ..AdaptiveConfig::default()
    }
}

/// The largest deviation of `K + U` from its start, and the largest elastic energy of the
/// contact (the first force of [`system`]), over every sample.
pub struct EnergyWatch {
    e0: Option<f64>,
    /// Largest `|K + U - E₀|`.
    pub max_dev: f64,
    /// Largest elastic energy.
    pub max_u: f64,
    /// The elastic energy at the samples where the bodies are apart (must be 0).
    pub u_apart: f64,
    /// The smallest elastic energy at the samples where they touch (must be positive).
    pub u_min_touching: f64,
    /// Whether the bodies are apart at positions `q`.
    pub apart: Option<fn(&[f64]) -> bool>,
}

impl EnergyWatch {
    /// Also checks the elastic energy against `apart(q)`: zero when apart, positive otherwise.
    pub fn with_apart(apart: fn(&[f64]) -> bool) -> Self {
        Self {
            apart: Some(apart),
            ..Self::default()
        }
    }
}

impl Default for EnergyWatch {
    fn default() -> Self {
        Self {
            e0: None,
            max_dev: 0.0,
            max_u: 0.0,
            u_apart: 0.0,
            u_min_touching: f64::INFINITY,
            apart: None,
        }
    }
}

impl Observer for EnergyWatch {
    fn observe(&mut self, s: &Sample<'_>) -> Result<(), ObserverError> {
        let e = s.energy();
        let e0 = *self.e0.get_or_insert(e);
        self.max_dev = self.max_dev.max((e - e0).abs());
        let u = s.eval.potential[0];
        self.max_u = self.max_u.max(u);
        match self.apart.map(|apart| apart(s.q)) {
            Some(true) => self.u_apart = self.u_apart.max(u.abs()),
            Some(false) => self.u_min_touching = self.u_min_touching.min(u),
            None => {}
        }
        Ok(())
    }
}

//! Air resistance relative to the wind `w`: linear (viscous, Stokes) `F = -b (v - w)` and
//! quadratic `F = -D |v - w| (v - w)`.

use super::force::{Force, Target};
use super::wind::Wind;
use crate::Real;
use crate::particles::Kinematics;

/// Linear (viscous) drag `F = -b (v - w)`; `b` in kg/s, per body.
#[derive(Debug, Clone)]
pub struct LinearDrag {
    name: String,
    targets: Vec<Target>,
    wind: Wind,
}

impl LinearDrag {
    /// Drag with coefficient `b` on each target (the target's coefficient), in still air.
    pub fn new(name: impl Into<String>, targets: Vec<Target>) -> Self {
        Self {
            name: name.into(),
            targets,
            wind: Wind::Calm,
        }
    }

    /// Relative to `wind`.
    #[must_use]
    pub fn with_wind(mut self, wind: Wind) -> Self {
        self.wind = wind;
        self
    }
}

/// Quadratic drag `F = -D |v - w| (v - w)`; `D` in kg/m, per body.
#[derive(Debug, Clone)]
pub struct QuadraticDrag {
    name: String,
    targets: Vec<Target>,
    wind: Wind,
}

impl QuadraticDrag {
    /// Drag with coefficient `D` on each target (the target's coefficient), in still air.
    pub fn new(name: impl Into<String>, targets: Vec<Target>) -> Self {
        Self {
            name: name.into(),
            targets,
            wind: Wind::Calm,
        }
    }

    /// Relative to `wind`.
    #[must_use]
    pub fn with_wind(mut self, wind: Wind) -> Self {
        self.wind = wind;
        self
    }
}

#[inline]
fn relative_velocity(k: &Kinematics<'_>, wind: &Wind, b: usize, u: &mut [Real; 3]) -> Real {
    let mut w = [0.0; 3];
    wind.at(k, b, &mut w);
    let v = k.velocity(b);
    let mut s2 = 0.0;
    for i in 0..k.dim {
        u[i] = v[i] - w[i];
        s2 += u[i] * u[i];
    }
    s2.sqrt()
}

impl Force for LinearDrag {
    fn name(&self) -> &str {
        &self.name
    }

    fn add_forces(&self, k: &Kinematics<'_>, out: &mut [Real]) {
        let mut u = [0.0; 3];
        for t in &self.targets {
            relative_velocity(k, &self.wind, t.body, &mut u);
            for i in 0..k.dim {
                out[t.body * k.dim + i] -= t.coefficient * u[i];
            }
        }
    }

    fn velocity_dependent(&self) -> bool {
        true
    }

    fn bodies(&self) -> Vec<usize> {
        self.targets.iter().map(|t| t.body).collect()
    }
}

impl Force for QuadraticDrag {
    fn name(&self) -> &str {
        &self.name
    }

    fn add_forces(&self, k: &Kinematics<'_>, out: &mut [Real]) {
        let mut u = [0.0; 3];
        for t in &self.targets {
            let speed = relative_velocity(k, &self.wind, t.body, &mut u);
            for i in 0..k.dim {
                out[t.body * k.dim + i] -= t.coefficient * speed * u[i];
            }
        }
    }

    fn velocity_dependent(&self) -> bool {
        true
    }

    fn bodies(&self) -> Vec<usize> {
        self.targets.iter().map(|t| t.body).collect()
    }
}

//! Air resistance relative to the wind `w`: linear (viscous, Stokes) `F = -b (v - w)` and
//! quadratic `F = -D |v - w| (v - w)`.

use super::force::{Force, Target};
use super::wind::Wind;
use crate::Real;
use crate::particles::Kinematics;

/// What both drag laws share: a name, the bodies with their coefficients, the wind.
#[derive(Debug, Clone)]
struct Drag {
    name: String,
    targets: Vec<Target>,
    wind: Wind,
}

impl Drag {
    /// Adds `-c f(|u|) u` to each target, where `u = v - w` and `c` its coefficient.
    #[inline]
    fn add(&self, k: &Kinematics<'_>, out: &mut [Real], f: impl Fn(Real) -> Real) {
        let mut w = [0.0; 3];
        for t in &self.targets {
            self.wind.at(k, t.body, &mut w);
            let v = k.velocity(t.body);
            let mut u = [0.0; 3];
            let mut s2 = 0.0;
            for i in 0..k.dim {
                u[i] = v[i] - w[i];
                s2 += u[i] * u[i];
            }
            let scale = t.coefficient * f(s2.sqrt());
            for i in 0..k.dim {
                out[t.body * k.dim + i] -= scale * u[i];
            }
        }
    }

    fn bodies(&self) -> Vec<usize> {
        self.targets.iter().map(|t| t.body).collect()
    }
}

macro_rules! drag_law {
    ($(#[$doc:meta])* $name:ident, $law:expr) => {
        $(#[$doc])*
        #[derive(Debug, Clone)]
        pub struct $name(Drag);

        impl $name {
            /// Drag on each target with the target's coefficient, in still air.
            pub fn new(name: impl Into<String>, targets: Vec<Target>) -> Self {
                Self(Drag {
                    name: name.into(),
                    targets,
                    wind: Wind::Calm,
                })
            }

            /// Relative to `wind`.
            #[must_use]
            pub fn with_wind(mut self, wind: Wind) -> Self {
                self.0.wind = wind;
                self
            }
        }

        impl Force for $name {
            fn name(&self) -> &str {
                &self.0.name
            }

            fn add_forces(&self, k: &Kinematics<'_>, out: &mut [Real]) {
                self.0.add(k, out, $law);
            }

            fn velocity_dependent(&self) -> bool {
                true
            }

            fn bodies(&self) -> Vec<usize> {
                self.0.bodies()
            }
        }
    };
}

drag_law!(
    /// Linear (viscous) drag `F = -b (v - w)`; `b` in kg/s, per body.
    LinearDrag,
    |_speed| 1.0
);

drag_law!(
    /// Quadratic drag `F = -D |v - w| (v - w)`; `D` in kg/m, per body.
    QuadraticDrag,
    |speed| speed
);

//! Air resistance relative to the wind `w`: linear (viscous, Stokes) `F = -b (v - w)` and
//! quadratic `F = -D |v - w| (v - w)`.

use super::emit::ForceEmitter;
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

    /// [`Drag::add`] into a kernel; `quadratic` scales by the speed, else by 1.
    fn emit(&self, e: &mut ForceEmitter<'_>, quadratic: bool) -> bool {
        let dim = e.dim();
        for t in &self.targets {
            let mut u = Vec::with_capacity(dim);
            for i in 0..dim {
                let v = e.v(t.body, i);
                // v - 0.0 is v exactly: still air needs no subtraction
                let ui = match &self.wind {
                    Wind::Calm => v,
                    Wind::Constant(w) => {
                        let w = e.constant(w.get(i).copied().unwrap_or(0.0));
                        e.b().sub(v, w)
                    }
                    Wind::Field(f) => {
                        let Some(w) = f[i].emit(e, Some(t.body)) else {
                            return false;
                        };
                        e.b().sub(v, w)
                    }
                };
                u.push(ui);
            }
            let c = e.constant(t.coefficient);
            let scale = if quadratic {
                let speed = e.norm(&u);
                e.b().mul(c, speed)
            } else {
                let one = e.constant(1.0);
                e.b().mul(c, one)
            };
            for (i, ui) in u.into_iter().enumerate() {
                let f = e.b().mul(scale, ui);
                e.sub(t.body * dim + i, f);
            }
        }
        true
    }
}

macro_rules! drag_law {
    ($(#[$doc:meta])* $name:ident, $law:expr, $quadratic:literal) => {
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

            fn emit(&self, e: &mut ForceEmitter<'_>) -> bool {
                self.0.emit(e, $quadratic)
            }

            fn velocity_dependent(&self) -> bool {
                true
            }

            fn local(&self) -> bool {
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
    |_speed| 1.0,
    false
);

drag_law!(
    /// Quadratic drag `F = -D |v - w| (v - w)`; `D` in kg/m, per body.
    QuadraticDrag,
    |speed| speed,
    true
);

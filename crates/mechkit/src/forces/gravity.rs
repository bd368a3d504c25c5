//! Gravity: uniform near a planet's surface, and Newton's inverse-square law.

use mechkit_expr::Val;

use super::emit::ForceEmitter;
use super::force::Force;
use crate::Real;
use crate::particles::Kinematics;

/// Uniform gravity `-m g` along the last axis (the vertical: `x` in 1-D, `y` in 2-D, `z` in
/// 3-D); potential `m g h`.
#[derive(Debug, Clone, PartialEq)]
pub struct UniformGravity {
    name: String,
    bodies: Vec<usize>,
    g: Real,
}

impl UniformGravity {
    /// Gravity of strength `g` (m/s², positive) on `bodies`.
    pub fn new(name: impl Into<String>, bodies: Vec<usize>, g: Real) -> Self {
        Self {
            name: name.into(),
            bodies,
            g,
        }
    }

    /// Standard gravity, 9.80665 m/s².
    pub fn earth(bodies: Vec<usize>) -> Self {
        Self::new("gravity", bodies, 9.806_65)
    }
}

impl Force for UniformGravity {
    fn name(&self) -> &str {
        &self.name
    }

    fn add_forces(&self, k: &Kinematics<'_>, out: &mut [Real]) {
        for &b in &self.bodies {
            out[b * k.dim + k.dim - 1] -= k.mass[b] * self.g;
        }
    }

    fn emit(&self, e: &mut ForceEmitter<'_>) -> bool {
        let d = e.dim();
        for &b in &self.bodies {
            let w = e.constant(e.mass(b) * self.g);
            e.sub(b * d + d - 1, w);
        }
        true
    }

    fn potential(&self, k: &Kinematics<'_>) -> Option<Real> {
        Some(
            self.bodies
                .iter()
                .map(|&b| k.mass[b] * self.g * k.x[b * k.dim + k.dim - 1])
                .sum(),
        )
    }

    fn local(&self) -> bool {
        true
    }

    fn bodies(&self) -> Vec<usize> {
        self.bodies.clone()
    }
}

/// What attracts in [`NewtonianGravity`].
#[derive(Debug, Clone, PartialEq)]
pub enum Attractor {
    /// A fixed mass at `center` with gravitational parameter `gm = G M` (m³/s²).
    FixedCentre {
        /// `G M`.
        gm: Real,
        /// Position of the centre.
        center: Vec<Real>,
    },
    /// The bodies attract each other pairwise with constant `g` (`G`).
    Mutual {
        /// The gravitational constant.
        g: Real,
    },
}

/// Newton's law of gravitation, `F = -G M m r̂ / r²`, potential `-G M m / r`.
#[derive(Debug, Clone, PartialEq)]
pub struct NewtonianGravity {
    name: String,
    bodies: Vec<usize>,
    attractor: Attractor,
}

impl NewtonianGravity {
    /// The gravitational constant (CODATA 2018), m³/(kg·s²).
    pub const G: Real = 6.674_30e-11;

    /// Attraction of `bodies` towards a fixed centre with `G M = gm`.
    pub fn fixed_centre(
        name: impl Into<String>,
        bodies: Vec<usize>,
        gm: Real,
        center: Vec<Real>,
    ) -> Self {
        Self {
            name: name.into(),
            bodies,
            attractor: Attractor::FixedCentre { gm, center },
        }
    }

    /// Mutual attraction between every pair of `bodies`, with gravitational constant `g`.
    pub fn mutual(name: impl Into<String>, bodies: Vec<usize>, g: Real) -> Self {
        Self {
            name: name.into(),
            bodies,
            attractor: Attractor::Mutual { g },
        }
    }
}

/// `r = a - b` into `d`; returns |r|.
#[inline]
fn separation(a: &[Real], b: &[Real], d: &mut [Real; 3]) -> Real {
    let mut r2 = 0.0;
    for i in 0..a.len() {
        d[i] = a[i] - b[i];
        r2 += d[i] * d[i];
    }
    r2.sqrt()
}

impl Force for NewtonianGravity {
    fn name(&self) -> &str {
        &self.name
    }

    fn add_forces(&self, k: &Kinematics<'_>, out: &mut [Real]) {
        let dim = k.dim;
        let mut d = [0.0; 3];
        match &self.attractor {
            Attractor::FixedCentre { gm, center } => {
                for &b in &self.bodies {
                    let r = separation(k.position(b), center, &mut d);
                    let s = -gm * k.mass[b] / (r * r * r);
                    for i in 0..dim {
                        out[b * dim + i] += s * d[i];
                    }
                }
            }
            Attractor::Mutual { g } => {
                for (n, &a) in self.bodies.iter().enumerate() {
                    for &b in &self.bodies[n + 1..] {
                        let r = separation(k.position(a), k.position(b), &mut d);
                        let s = -g * k.mass[a] * k.mass[b] / (r * r * r);
                        for i in 0..dim {
                            out[a * dim + i] += s * d[i];
                            out[b * dim + i] -= s * d[i];
                        }
                    }
                }
            }
        }
    }

    fn emit(&self, e: &mut ForceEmitter<'_>) -> bool {
        let dim = e.dim();
        // separation(a, b): d = a - b, r = sqrt(0 + Σ d²); s / (r r r), in add_forces' order
        let pull = |e: &mut ForceEmitter<'_>, a: &[Val], b: &[Val], coefficient: Real| {
            let (d, r) = e.separation(a, b);
            let rr = e.b().mul(r, r);
            let r3 = e.b().mul(rr, r);
            let c = e.constant(coefficient);
            let s = e.b().div(c, r3);
            let f: Vec<Val> = d.iter().map(|di| e.b().mul(s, *di)).collect();
            f
        };
        match &self.attractor {
            Attractor::FixedCentre { gm, center } => {
                let centre: Vec<Val> = center.iter().map(|c| e.constant(*c)).collect();
                for &b in &self.bodies {
                    let x: Vec<Val> = (0..dim).map(|i| e.x(b, i)).collect();
                    let f = pull(e, &x, &centre, -gm * e.mass(b));
                    for (i, fi) in f.into_iter().enumerate() {
                        e.add(b * dim + i, fi);
                    }
                }
            }
            Attractor::Mutual { g } => {
                for (n, &a) in self.bodies.iter().enumerate() {
                    for &b in &self.bodies[n + 1..] {
                        let xa: Vec<Val> = (0..dim).map(|i| e.x(a, i)).collect();
                        let xb: Vec<Val> = (0..dim).map(|i| e.x(b, i)).collect();
                        let f = pull(e, &xa, &xb, -g * e.mass(a) * e.mass(b));
                        for (i, fi) in f.into_iter().enumerate() {
                            e.add(a * dim + i, fi);
                            e.sub(b * dim + i, fi);
                        }
                    }
                }
            }
        }
        true
    }

    fn potential(&self, k: &Kinematics<'_>) -> Option<Real> {
        let mut d = [0.0; 3];
        Some(match &self.attractor {
            Attractor::FixedCentre { gm, center } => self
                .bodies
                .iter()
                .map(|&b| -gm * k.mass[b] / separation(k.position(b), center, &mut d))
                .sum(),
            Attractor::Mutual { g } => {
                let mut u = 0.0;
                for (n, &a) in self.bodies.iter().enumerate() {
                    for &b in &self.bodies[n + 1..] {
                        u -= g * k.mass[a] * k.mass[b]
                            / separation(k.position(a), k.position(b), &mut d);
                    }
                }
                u
            }
        })
    }

    fn internal(&self) -> bool {
        matches!(self.attractor, Attractor::Mutual { .. })
    }

    fn local(&self) -> bool {
        true
    }

    fn bodies(&self) -> Vec<usize> {
        self.bodies.clone()
    }
}

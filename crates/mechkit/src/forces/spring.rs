//! Linear springs with a rest length (Hooke's law), `F = -k (r - L) r̂`, potential
//! `k (r - L)² / 2`, where `r` is the spring's length.

use mechkit_expr::{BinOp, Val};

use super::emit::ForceEmitter;
use super::force::Force;
use crate::Real;
use crate::animation::{Attachment, SceneItem};
use crate::particles::Kinematics;

/// What a spring connects.
#[derive(Debug, Clone, PartialEq)]
pub enum SpringEnds {
    /// Each of `bodies` is tied to the fixed point `anchor` by its own spring.
    Anchor {
        /// The bodies.
        bodies: Vec<usize>,
        /// The fixed end.
        anchor: Vec<Real>,
    },
    /// A spring between two bodies.
    Pair(usize, usize),
}

/// A linear spring.
#[derive(Debug, Clone, PartialEq)]
pub struct Spring {
    name: String,
    k: Real,
    rest_length: Real,
    ends: SpringEnds,
}

impl Spring {
    /// A spring of stiffness `k` (N/m) and rest length `rest_length` (m).
    pub fn new(name: impl Into<String>, k: Real, rest_length: Real, ends: SpringEnds) -> Self {
        Self {
            name: name.into(),
            k,
            rest_length,
            ends,
        }
    }

    /// Adds the force of a spring from `b_pos` to `a_pos` on `a` into `fa` (and `-` that on b).
    #[inline]
    fn pull(&self, a_pos: &[Real], b_pos: &[Real], f: &mut [Real; 3]) {
        let dim = a_pos.len();
        let mut r2 = 0.0;
        for i in 0..dim {
            f[i] = a_pos[i] - b_pos[i];
            r2 += f[i] * f[i];
        }
        let r = r2.sqrt();
        // At r = 0 the direction is undefined; a zero-length spring pulls with -k r, finite.
        let s = if r > 0.0 {
            -self.k * (r - self.rest_length) / r
        } else {
            -self.k
        };
        for c in f.iter_mut().take(dim) {
            *c *= s;
        }
    }

    fn energy(&self, a_pos: &[Real], b_pos: &[Real]) -> Real {
        let r = a_pos
            .iter()
            .zip(b_pos)
            .map(|(a, b)| (a - b) * (a - b))
            .sum::<Real>()
            .sqrt();
        0.5 * self.k * (r - self.rest_length).powi(2)
    }
}

impl Force for Spring {
    fn sketch(&self) -> Vec<SceneItem> {
        let body = |body: usize| Attachment::Body {
            body,
            offset: [0.0; 3],
        };
        match &self.ends {
            SpringEnds::Pair(a, b) => vec![SceneItem::Spring {
                a: body(*a),
                b: body(*b),
            }],
            SpringEnds::Anchor { bodies, anchor } => {
                let fixed: [Real; 3] =
                    std::array::from_fn(|a| anchor.get(a).copied().unwrap_or(0.0));
                bodies
                    .iter()
                    .map(|&b| SceneItem::Spring {
                        a: Attachment::Fixed(fixed),
                        b: body(b),
                    })
                    .collect()
            }
        }
    }

    fn name(&self) -> &str {
        &self.name
    }

    fn add_forces(&self, k: &Kinematics<'_>, out: &mut [Real]) {
        let dim = k.dim;
        let mut f = [0.0; 3];
        match &self.ends {
            SpringEnds::Anchor { bodies, anchor } => {
                for &b in bodies {
                    self.pull(k.position(b), anchor, &mut f);
                    for i in 0..dim {
                        out[b * dim + i] += f[i];
                    }
                }
            }
            SpringEnds::Pair(a, b) => {
                self.pull(k.position(*a), k.position(*b), &mut f);
                for i in 0..dim {
                    out[a * dim + i] += f[i];
                    out[b * dim + i] -= f[i];
                }
            }
        }
    }

    fn emit(&self, e: &mut ForceEmitter<'_>) -> bool {
        let dim = e.dim();
        // pull(a, b): f = a - b, r = sqrt(0 + Σ f²), s = r > 0 ? -k (r - L) / r : -k, f *= s
        let pull = |e: &mut ForceEmitter<'_>, a: &[Val], b: &[Val]| {
            let (d, r) = e.separation(a, b);
            let zero = e.constant(0.0);
            let positive = e.b().compare(BinOp::Gt, r, zero);
            let minus_k = e.constant(-self.k);
            let rest = e.constant(self.rest_length);
            let stretch = e.b().sub(r, rest);
            let num = e.b().mul(minus_k, stretch);
            let per_length = e.b().div(num, r);
            let s = e.b().select(positive, per_length, minus_k);
            let f: Vec<Val> = d.iter().map(|di| e.b().mul(*di, s)).collect();
            f
        };
        match &self.ends {
            SpringEnds::Anchor { bodies, anchor } => {
                let anchor: Vec<Val> = anchor.iter().map(|c| e.constant(*c)).collect();
                for &b in bodies {
                    let x: Vec<Val> = (0..dim).map(|i| e.x(b, i)).collect();
                    let f = pull(e, &x, &anchor);
                    for (i, fi) in f.into_iter().enumerate() {
                        e.add(b * dim + i, fi);
                    }
                }
            }
            SpringEnds::Pair(a, b) => {
                let xa: Vec<Val> = (0..dim).map(|i| e.x(*a, i)).collect();
                let xb: Vec<Val> = (0..dim).map(|i| e.x(*b, i)).collect();
                let f = pull(e, &xa, &xb);
                for (i, fi) in f.into_iter().enumerate() {
                    e.add(a * dim + i, fi);
                    e.sub(b * dim + i, fi);
                }
            }
        }
        true
    }

    fn potential(&self, k: &Kinematics<'_>) -> Option<Real> {
        Some(match &self.ends {
            SpringEnds::Anchor { bodies, anchor } => bodies
                .iter()
                .map(|&b| self.energy(k.position(b), anchor))
                .sum(),
            SpringEnds::Pair(a, b) => self.energy(k.position(*a), k.position(*b)),
        })
    }

    fn internal(&self) -> bool {
        matches!(self.ends, SpringEnds::Pair(..))
    }

    fn local(&self) -> bool {
        true
    }

    fn bodies(&self) -> Vec<usize> {
        match &self.ends {
            SpringEnds::Anchor { bodies, .. } => bodies.clone(),
            SpringEnds::Pair(a, b) => vec![*a, *b],
        }
    }
}

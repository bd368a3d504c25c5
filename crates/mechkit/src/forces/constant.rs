//! A constant force, e.g. a thrust or a pull: a fixed vector `F` on each body it acts on;
//! potential `-F·x`.

use super::emit::ForceEmitter;
use super::force::Force;
use crate::Real;
use crate::particles::Kinematics;
use crate::particles::dot;

/// A constant vector force on each of its bodies (the vector may differ per body, e.g. when it
/// was given as `m*a`).
#[derive(Debug, Clone, PartialEq)]
pub struct ConstantForce {
    name: String,
    per_body: Vec<(usize, Vec<Real>)>,
}

impl ConstantForce {
    /// The same force vector `force` (one component per dimension) on each of `bodies`.
    pub fn new(name: impl Into<String>, bodies: Vec<usize>, force: &[Real]) -> Self {
        let per_body = bodies.into_iter().map(|b| (b, force.to_vec())).collect();
        Self {
            name: name.into(),
            per_body,
        }
    }

    /// A force vector per body.
    pub fn per_body(name: impl Into<String>, per_body: Vec<(usize, Vec<Real>)>) -> Self {
        Self {
            name: name.into(),
            per_body,
        }
    }
}

impl Force for ConstantForce {
    fn name(&self) -> &str {
        &self.name
    }

    fn add_forces(&self, k: &Kinematics<'_>, out: &mut [Real]) {
        for (b, force) in &self.per_body {
            for (o, f) in out[b * k.dim..(b + 1) * k.dim].iter_mut().zip(force) {
                *o += f;
            }
        }
    }

    fn emit(&self, e: &mut ForceEmitter<'_>) -> bool {
        let d = e.dim();
        for (b, force) in &self.per_body {
            for (i, f) in force.iter().enumerate() {
                let f = e.constant(*f);
                e.add(b * d + i, f);
            }
        }
        true
    }

    fn potential(&self, k: &Kinematics<'_>) -> Option<Real> {
        Some(
            -self
                .per_body
                .iter()
                .map(|(b, f)| dot(f, k.position(*b)))
                .sum::<Real>(),
        )
    }

    fn local(&self) -> bool {
        true
    }

    fn bodies(&self) -> Vec<usize> {
        self.per_body.iter().map(|(b, _)| *b).collect()
    }
}

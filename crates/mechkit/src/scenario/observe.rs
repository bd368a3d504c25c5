//! `[observe]`: named reductions of formulas over every sample of a run.

use crate::Real;
use crate::particles::{Sample, StateExpr};
use crate::simulate::{Observer, ObserverError, Reducer, Reduction};

/// One `[observe]` entry.
#[derive(Debug, Clone)]
pub struct Observable {
    /// Its name (the key).
    pub name: String,
    /// The text as written, e.g. `max(x)`.
    pub source: String,
    /// How it reduces.
    pub reduction: Reduction,
    expr: StateExpr,
}

impl Observable {
    pub(crate) fn new(name: String, source: String, reduction: Reduction, expr: StateExpr) -> Self {
        Self {
            name,
            source,
            reduction,
            expr,
        }
    }

    /// The formula being reduced.
    pub fn expr(&self) -> &StateExpr {
        &self.expr
    }
}

/// Evaluates every observable on every sample.
pub(crate) struct ObservableSet<'a> {
    items: &'a [Observable],
    reducers: Vec<Reducer>,
    dim: usize,
    mass: &'a [Real],
}

impl<'a> ObservableSet<'a> {
    pub fn new(items: &'a [Observable], dim: usize, mass: &'a [Real]) -> Self {
        Self {
            items,
            reducers: items.iter().map(|o| Reducer::new(o.reduction)).collect(),
            dim,
            mass,
        }
    }

    /// Name and value of each observable.
    pub fn values(&self) -> Vec<(String, Real)> {
        self.items
            .iter()
            .zip(&self.reducers)
            .map(|(o, r)| (o.name.clone(), r.value()))
            .collect()
    }
}

impl Observer for ObservableSet<'_> {
    fn observe(&mut self, s: &Sample<'_>) -> Result<(), ObserverError> {
        for (o, r) in self.items.iter().zip(&mut self.reducers) {
            r.push(s.t, o.expr.eval_sample(s, self.dim, self.mass, None));
        }
        Ok(())
    }
}

//! What the names in a formula mean where it is used: constants, or slots of a variable array.

use std::collections::HashMap;

/// What a name is bound to.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Binding {
    /// A fixed value, folded into the compiled program.
    Const(f64),
    /// Index into the variable slice passed to [`crate::Program::eval`].
    Slot(usize),
}

/// Resolves names for compilation.
pub trait Scope {
    /// The binding of `name`, or `None` if it is not defined here.
    fn lookup(&self, name: &str) -> Option<Binding>;

    /// Every name defined here, used to suggest corrections for typos.
    fn candidates(&self) -> Vec<String>;

    /// A short description of what is available here, shown with "undefined name" errors
    /// (e.g. "names here: t, x, v, m and the constants").
    fn describe(&self) -> Option<String> {
        None
    }
}

/// A scope backed by a map; build it with [`MapScope::constant`] and [`MapScope::slot`].
#[derive(Debug, Clone, Default)]
pub struct MapScope {
    bindings: HashMap<String, Binding>,
    order: Vec<String>,
    description: Option<String>,
}

impl MapScope {
    /// An empty scope.
    pub fn new() -> Self {
        Self::default()
    }

    /// Binds `name` to a constant value (replacing any earlier binding).
    #[must_use]
    pub fn constant(mut self, name: &str, value: f64) -> Self {
        self.insert(name, Binding::Const(value));
        self
    }

    /// Binds `name` to slot `index` of the variable slice.
    #[must_use]
    pub fn slot(mut self, name: &str, index: usize) -> Self {
        self.insert(name, Binding::Slot(index));
        self
    }

    /// Sets the description shown with "undefined name" errors.
    #[must_use]
    pub fn described(mut self, description: impl Into<String>) -> Self {
        self.description = Some(description.into());
        self
    }

    /// Binds `name` (replacing any earlier binding).
    pub fn insert(&mut self, name: &str, binding: Binding) {
        if self.bindings.insert(name.to_string(), binding).is_none() {
            self.order.push(name.to_string());
        }
    }
}

impl Scope for MapScope {
    fn lookup(&self, name: &str) -> Option<Binding> {
        self.bindings.get(name).copied()
    }

    fn candidates(&self) -> Vec<String> {
        self.order.clone()
    }

    fn describe(&self) -> Option<String> {
        self.description.clone()
    }
}

/// Names every formula knows unless the scope redefines them.
pub const BUILTIN_CONSTANTS: &[(&str, f64)] =
    &[("pi", std::f64::consts::PI), ("e", std::f64::consts::E)];

/// The value of a built-in constant.
pub fn builtin_constant(name: &str) -> Option<f64> {
    BUILTIN_CONSTANTS
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, v)| *v)
}

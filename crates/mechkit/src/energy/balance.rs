//! The energy balance every model reports: kinetic and potential energy at the start and the
//! end (each optionally split into named parts), the work of each named force, the energy
//! changed by events, and the work-energy residual
//!
//! `R = (K + U)_end − (K + U)_start − Σ W_nc − ΔE_events`,
//!
//! where `W_nc` runs over the forces whose work is not already counted as `−ΔU` (forces
//! without a potential, and external agents such as a moving belt or anchor), and
//! `ΔE_events` is the change of `K + U` by events' state changes (a bounce). For an exact
//! trajectory `R = 0`; computed, it measures the integration error. It is computed here and
//! only here ([`EnergyBalance::residual`]).
//!
//! The particle simulation's ledger gives its balance with [`EnergyLedger::balance`]
//! (it also keeps the kinetic form `Σ W − ΔK`, [`EnergyLedger::work_energy_residual`]); the
//! rigid-body models (stick-slip, rolling) report one directly.
//!
//! [`EnergyLedger::balance`]: super::EnergyLedger::balance
//! [`EnergyLedger::work_energy_residual`]: super::EnergyLedger::work_energy_residual

use crate::Real;

/// A named part of an energy (`"translational"`, `"spring"`) at the start and the end (J).
#[derive(Debug, Clone, PartialEq)]
pub struct EnergyPart {
    /// What it is.
    pub name: String,
    /// At the start (J).
    pub start: Real,
    /// At the end (J).
    pub end: Real,
}

/// A kinetic or potential energy at the start and the end of a run, with its named parts
/// (empty when it is not split).
#[derive(Debug, Clone, PartialEq)]
pub struct EnergyTerm {
    /// At the start (J).
    pub start: Real,
    /// At the end (J).
    pub end: Real,
    /// The parts, summing to `start` and `end`; empty when not split.
    pub parts: Vec<EnergyPart>,
}

impl EnergyTerm {
    /// An energy not split into parts.
    pub fn new(start: Real, end: Real) -> Self {
        Self {
            start,
            end,
            parts: Vec::new(),
        }
    }

    /// An energy as the sum of named parts `(name, start, end)`, added in order.
    ///
    /// ```
    /// use mechkit::energy::EnergyTerm;
    /// let k = EnergyTerm::from_parts([("translational", 1.0, 3.0), ("rotational", 0.5, 1.5)]);
    /// assert_eq!((k.start, k.end), (1.5, 4.5));
    /// assert_eq!(k.part("rotational").unwrap().end, 1.5);
    /// ```
    pub fn from_parts<'a>(parts: impl IntoIterator<Item = (&'a str, Real, Real)>) -> Self {
        let parts: Vec<EnergyPart> = parts
            .into_iter()
            .map(|(name, start, end)| EnergyPart {
                name: name.to_string(),
                start,
                end,
            })
            .collect();
        // seeded with the first part, so a single part keeps its value to the bit (even −0)
        let total = |f: fn(&EnergyPart) -> Real| parts.iter().map(f).reduce(|a, b| a + b);
        Self {
            start: total(|p| p.start).unwrap_or(0.0),
            end: total(|p| p.end).unwrap_or(0.0),
            parts,
        }
    }

    /// The part named `name`.
    pub fn part(&self, name: &str) -> Option<&EnergyPart> {
        self.parts.iter().find(|p| p.name == name)
    }

    /// `end − start` (J).
    pub fn change(&self) -> Real {
        self.end - self.start
    }
}

/// The work done on the system by one named force or agent over a run.
#[derive(Debug, Clone, PartialEq)]
pub struct ForceWork {
    /// The force's name.
    pub name: String,
    /// The work (J).
    pub work: Real,
    /// Whether the force has a potential counted in [`EnergyBalance::potential`]: its work is
    /// then `−ΔU` (a check), and the residual leaves it out.
    pub conservative: bool,
}

/// The energy balance of a run, the one energy result every model reports: `K` and `U` at the
/// start and the end, the work of each named force, the energy changed by events, and the
/// work-energy residual `(K + U)_end − (K + U)_start − Σ W_nc − ΔE_events`
/// ([`EnergyBalance::residual`]), `W_nc` the work of the forces whose potential is not in `U`.
///
/// ```
/// use approx::assert_relative_eq;
/// use mechkit::energy::{EnergyBalance, EnergyTerm};
/// // a 2 kg block slides from rest 1 m down a 30° slope (a drop of 0.5 m), losing 3 J to drag
/// let (m, g, h) = (2.0, 9.81, 0.5);
/// let k_end = m * g * h - 3.0;
/// let b = EnergyBalance::new(EnergyTerm::new(0.0, k_end))
///     .with_potential(EnergyTerm::from_parts([("gravity", m * g * h, 0.0)]))
///     .with_work("drag", -3.0);
/// assert_relative_eq!(b.residual(), 0.0, epsilon = 1e-12);
/// assert_eq!(b.work_of("drag"), Some(-3.0));
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct EnergyBalance {
    /// Kinetic energy `K`.
    pub kinetic: EnergyTerm,
    /// Potential energy `U`; `None` where no force has one.
    pub potential: Option<EnergyTerm>,
    /// The work of each named force, in the model's order.
    pub work: Vec<ForceWork>,
    /// `ΔE_events`: the change of `K + U` by events' state changes, not done by any force (J).
    pub events: Real,
}

impl EnergyBalance {
    /// A balance with kinetic energy only: no potential, no work, no events yet.
    pub fn new(kinetic: EnergyTerm) -> Self {
        Self {
            kinetic,
            potential: None,
            work: Vec::new(),
            events: 0.0,
        }
    }

    /// Sets the potential energy.
    #[must_use]
    pub fn with_potential(mut self, potential: EnergyTerm) -> Self {
        self.potential = Some(potential);
        self
    }

    /// Adds the work of a force without a potential (it enters the residual).
    #[must_use]
    pub fn with_work(mut self, name: &str, work: Real) -> Self {
        self.work.push(ForceWork {
            name: name.to_string(),
            work,
            conservative: false,
        });
        self
    }

    /// Adds the work of a force whose potential is in [`EnergyBalance::potential`] (listed,
    /// left out of the residual).
    #[must_use]
    pub fn with_conservative_work(mut self, name: &str, work: Real) -> Self {
        self.work.push(ForceWork {
            name: name.to_string(),
            work,
            conservative: true,
        });
        self
    }

    /// Sets the energy changed by events.
    #[must_use]
    pub fn with_events(mut self, events: Real) -> Self {
        self.events = events;
        self
    }

    /// The work of the force named `name` (J).
    pub fn work_of(&self, name: &str) -> Option<Real> {
        self.work.iter().find(|w| w.name == name).map(|w| w.work)
    }

    /// `Σ W_nc`: the work of the forces without a potential (J).
    pub fn non_conservative_work(&self) -> Real {
        self.work
            .iter()
            .filter(|w| !w.conservative)
            .map(|w| w.work)
            .reduce(|a, b| a + b)
            .unwrap_or(0.0)
    }

    /// Mechanical energy `K + U` at the start and the end (`U = 0` without a potential).
    pub fn energy(&self) -> (Real, Real) {
        match &self.potential {
            Some(u) => (self.kinetic.start + u.start, self.kinetic.end + u.end),
            None => (self.kinetic.start, self.kinetic.end),
        }
    }

    /// The work-energy residual `(K + U)_end − (K + U)_start − Σ W_nc − ΔE_events` (J): zero
    /// for an exact trajectory.
    pub fn residual(&self) -> Real {
        let (e0, e1) = self.energy();
        (e1 - e0) - self.non_conservative_work() - self.events
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A ball dropped from 2 m falls 1.5 m: `K = m g Δh` exactly.
    #[test]
    fn free_fall_balances_exactly() {
        let (m, g) = (0.5, 8.0);
        let b = EnergyBalance::new(EnergyTerm::new(0.0, m * g * 1.5))
            .with_potential(EnergyTerm::from_parts([(
                "gravity",
                m * g * 2.0,
                m * g * 0.5,
            )]))
            .with_conservative_work("gravity", m * g * 1.5);
        assert_eq!(b.residual(), 0.0);
        assert_eq!(b.non_conservative_work(), 0.0);
        assert_eq!(b.energy(), (8.0, 8.0));
    }

    /// A sliding block stopped by friction: `W_friction = −K0`, the heat.
    #[test]
    fn friction_takes_the_kinetic_energy() {
        let b = EnergyBalance::new(EnergyTerm::new(4.0, 0.0)).with_work("friction", -4.0);
        assert!(b.potential.is_none());
        assert_eq!(b.residual(), 0.0);
        assert_eq!(b.work_of("friction"), Some(-4.0));
        assert_eq!(b.work_of("drag"), None);
    }

    /// A bounce losing 1 J is booked as an event, not as work; parts sum in order.
    #[test]
    fn events_and_parts() {
        let k = EnergyTerm::from_parts([("translational", 3.0, 1.0), ("rotational", 1.0, 2.0)]);
        assert_eq!((k.start, k.end, k.change()), (4.0, 3.0, -1.0));
        let b = EnergyBalance::new(k).with_events(-1.0);
        assert_eq!(b.residual(), 0.0);
        assert_eq!(b.with_events(0.0).residual(), -1.0);
        // a single part keeps its sign of zero
        assert!(
            EnergyTerm::from_parts([("gravity", -0.0, 1.0)])
                .start
                .is_sign_negative()
        );
        assert_eq!(EnergyTerm::from_parts([]), EnergyTerm::new(0.0, 0.0));
    }
}

//! The integration methods by name, for scenario files and the command line.

use std::fmt;

use super::stepper::Stepper;
use super::symplectic::{Composition, Symplectic};
use super::system::SecondOrderSystem;
use super::tableau::Tableau;
use super::{Euler, EulerCromer, ExplicitRk, Rk4, VelocityVerlet};

/// An integration method.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Method {
    /// Forward Euler ([`super::Euler`]).
    Euler,
    /// Euler-Cromer ([`super::EulerCromer`]).
    EulerCromer,
    /// Velocity Verlet ([`super::VelocityVerlet`]).
    VelocityVerlet,
    /// Classical Runge-Kutta ([`super::Rk4`]).
    Rk4,
    /// Heun's method with an embedded Euler error estimate ([`Tableau::heun`]).
    Heun,
    /// Bogacki-Shampine 3(2) ([`Tableau::bogacki_shampine`]).
    BogackiShampine,
    /// Dormand-Prince 5(4) ([`Tableau::dopri5`]).
    Dopri5,
    /// DOP853 ([`Tableau::dop853`]).
    Dop853,
    /// Yoshida's 4th-order triple jump ([`Composition::yoshida4`]).
    Yoshida4,
    /// Forest-Ruth 4th order ([`Composition::forest_ruth`]).
    ForestRuth,
    /// PEFRL 4th order ([`Composition::pefrl`]).
    Pefrl,
    /// Yoshida's 6th-order composition ([`Composition::yoshida6`]).
    Yoshida6,
    /// Radau IIA of order 5, implicit, for stiff systems ([`super::Radau5`]).
    Radau5,
    /// Variable-order (1–5) BDF/NDF, implicit, for stiff systems ([`super::Bdf`]).
    Bdf,
    /// DOP853 until Hairer's stiffness test fires, then Radau IIA(5) (as LSODA switches).
    Auto,
}

/// A method described: what `mechkit list-integrators` lists.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct MethodInfo {
    /// Its name in `[integrator] method`.
    pub name: &'static str,
    /// `fixed`, `adaptive` or `symplectic`.
    pub kind: &'static str,
    /// Global order of accuracy.
    pub order: u32,
    /// A one-line description.
    pub description: &'static str,
}

/// What kind of method it is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MethodKind {
    /// A fixed-step method without error estimate.
    Fixed,
    /// A Runge-Kutta pair with an error estimate: adaptive step size by default, or a fixed
    /// step when `dt` is given.
    Adaptive,
    /// A symplectic splitting method: fixed step, forces of position and time only.
    Symplectic,
    /// An implicit method for stiff systems: adaptive steps, Newton iterations with the
    /// Jacobian of the forces.
    Implicit,
}

impl Method {
    /// Every method available.
    pub const ALL: [Method; 15] = [
        Method::Euler,
        Method::EulerCromer,
        Method::VelocityVerlet,
        Method::Rk4,
        Method::Heun,
        Method::BogackiShampine,
        Method::Dopri5,
        Method::Dop853,
        Method::Yoshida4,
        Method::ForestRuth,
        Method::Pefrl,
        Method::Yoshida6,
        Method::Radau5,
        Method::Bdf,
        Method::Auto,
    ];

    /// The name used in scenario files.
    pub fn name(self) -> &'static str {
        match self {
            Method::Euler => "euler",
            Method::EulerCromer => "euler-cromer",
            Method::VelocityVerlet => "verlet",
            Method::Rk4 => "rk4",
            Method::Heun => "heun",
            Method::BogackiShampine => "bs3",
            Method::Dopri5 => "dopri5",
            Method::Dop853 => "dop853",
            Method::Yoshida4 => "yoshida4",
            Method::ForestRuth => "forest-ruth",
            Method::Pefrl => "pefrl",
            Method::Yoshida6 => "yoshida6",
            Method::Radau5 => "radau5",
            Method::Bdf => "bdf",
            Method::Auto => "auto",
        }
    }

    /// Global order of accuracy.
    pub fn order(self) -> u32 {
        match self {
            Method::Euler | Method::EulerCromer => 1,
            Method::VelocityVerlet | Method::Heun => 2,
            Method::BogackiShampine => 3,
            Method::Rk4 | Method::Yoshida4 | Method::ForestRuth | Method::Pefrl => 4,
            Method::Dopri5 | Method::Radau5 | Method::Bdf => 5,
            Method::Yoshida6 => 6,
            Method::Dop853 | Method::Auto => 8,
        }
    }

    /// Fixed, adaptive or symplectic.
    pub fn kind(self) -> MethodKind {
        match self {
            Method::Euler | Method::EulerCromer | Method::VelocityVerlet | Method::Rk4 => {
                MethodKind::Fixed
            }
            Method::Heun | Method::BogackiShampine | Method::Dopri5 | Method::Dop853 => {
                MethodKind::Adaptive
            }
            Method::Yoshida4 | Method::ForestRuth | Method::Pefrl | Method::Yoshida6 => {
                MethodKind::Symplectic
            }
            Method::Radau5 | Method::Bdf | Method::Auto => MethodKind::Implicit,
        }
    }

    /// The Butcher tableau of a Runge-Kutta pair.
    pub fn tableau(self) -> Option<Tableau> {
        Some(match self {
            Method::Heun => Tableau::heun(),
            Method::BogackiShampine => Tableau::bogacki_shampine(),
            Method::Dopri5 => Tableau::dopri5(),
            Method::Dop853 => Tableau::dop853(),
            _ => return None,
        })
    }

    /// The coefficients of a splitting method.
    pub fn composition(self) -> Option<Composition> {
        Some(match self {
            Method::Yoshida4 => Composition::yoshida4(),
            Method::ForestRuth => Composition::forest_ruth(),
            Method::Pefrl => Composition::pefrl(),
            Method::Yoshida6 => Composition::yoshida6(),
            _ => return None,
        })
    }

    /// Whether the method needs forces of position and time only (symplectic splitting).
    pub fn needs_position_forces(self) -> bool {
        self.kind() == MethodKind::Symplectic
    }

    /// Whether the method chooses its steps by an error estimate (the Runge-Kutta pairs and
    /// the implicit methods): a run without `dt` is adaptive.
    pub fn is_adaptive(self) -> bool {
        matches!(self.kind(), MethodKind::Adaptive | MethodKind::Implicit)
    }

    /// A fixed-step stepper for this method.
    ///
    /// # Panics
    /// For an implicit method, which has adaptive steps only.
    pub fn stepper<S: SecondOrderSystem + ?Sized>(self) -> Box<dyn Stepper<S>> {
        match self {
            Method::Euler => Box::new(Euler::new()),
            Method::EulerCromer => Box::new(EulerCromer::new()),
            Method::VelocityVerlet => Box::new(VelocityVerlet::new()),
            Method::Rk4 => Box::new(Rk4::new()),
            m => match (m.tableau(), m.composition()) {
                (Some(t), _) => Box::new(ExplicitRk::new(t)),
                (None, Some(c)) => Box::new(Symplectic::new(c)),
                (None, None) => unreachable!("{m} has adaptive steps only"),
            },
        }
    }

    /// Every method as a [`MethodInfo`] (`mechkit list-integrators`).
    pub fn catalogue() -> Vec<MethodInfo> {
        Method::ALL
            .iter()
            .map(|&m| MethodInfo {
                name: m.name(),
                kind: match m.kind() {
                    MethodKind::Fixed => "fixed",
                    MethodKind::Adaptive => "adaptive",
                    MethodKind::Symplectic => "symplectic",
                    MethodKind::Implicit => "implicit",
                },
                order: m.order(),
                description: m.description(),
            })
            .collect()
    }

    /// A one-line description.
    pub fn description(self) -> &'static str {
        match self {
            Method::Euler => "forward Euler, 1st order",
            Method::EulerCromer => {
                "Euler-Cromer (semi-implicit Euler: v first, then x with the new v), 1st order, symplectic"
            }
            Method::VelocityVerlet => {
                "velocity Verlet (leapfrog), 2nd order, symplectic for position-only forces"
            }
            Method::Rk4 => "classical Runge-Kutta, 4th order",
            Method::Heun => {
                "Heun (explicit trapezoid) with Euler error estimate, 2nd order, adaptive"
            }
            Method::BogackiShampine => {
                "Bogacki-Shampine 3(2), 3rd order, adaptive, cubic dense output"
            }
            Method::Dopri5 => {
                "Dormand-Prince 5(4), 5th order, adaptive, 4th-order dense output (MATLAB ode45, SciPy RK45)"
            }
            Method::Dop853 => "Dormand-Prince 8(5,3), 8th order, adaptive, 7th-order dense output",
            Method::Yoshida4 => {
                "Yoshida triple jump of velocity Verlet, 4th order, symplectic (position-only forces)"
            }
            Method::ForestRuth => "Forest-Ruth, 4th order, symplectic (position-only forces)",
            Method::Pefrl => {
                "PEFRL (Omelyan-Mryglod-Folk), 4th order, symplectic, ~100x smaller error than Forest-Ruth"
            }
            Method::Yoshida6 => "Yoshida 6th-order composition, symplectic (position-only forces)",
            Method::Radau5 => {
                "Radau IIA, 5th order, implicit, adaptive, L-stable, for stiff systems (SciPy Radau, Hairer's RADAU5)"
            }
            Method::Bdf => {
                "BDF/NDF of variable order 1-5 (order 5 listed), implicit, adaptive, for stiff systems (SciPy BDF, MATLAB ode15s)"
            }
            Method::Auto => {
                "DOP853, switching to Radau IIA 5 where the problem turns stiff (Hairer's test; like LSODA), adaptive"
            }
        }
    }

    /// Looks a method up by name; accepts a few common spellings.
    pub fn from_name(name: &str) -> Option<Method> {
        let norm = name.trim().to_ascii_lowercase().replace(['_', ' '], "-");
        Some(match norm.as_str() {
            "euler" | "forward-euler" | "explicit-euler" => Method::Euler,
            "euler-cromer" | "eulercromer" | "semi-implicit-euler" | "symplectic-euler" => {
                Method::EulerCromer
            }
            "verlet" | "velocity-verlet" | "leapfrog" => Method::VelocityVerlet,
            "rk4" | "runge-kutta" | "runge-kutta-4" => Method::Rk4,
            "heun" | "rk12" => Method::Heun,
            "bs3" | "bogacki-shampine" | "rk23" | "ode23" => Method::BogackiShampine,
            "dopri5" | "rk45" | "dormand-prince" | "ode45" => Method::Dopri5,
            "dop853" => Method::Dop853,
            "yoshida4" | "yoshida" | "triple-jump" => Method::Yoshida4,
            "forest-ruth" | "forestruth" => Method::ForestRuth,
            "pefrl" => Method::Pefrl,
            "yoshida6" => Method::Yoshida6,
            "radau5" | "radau" | "radau-iia" => Method::Radau5,
            "bdf" | "ndf" | "ode15s" => Method::Bdf,
            "auto" | "lsoda" => Method::Auto,
            _ => return None,
        })
    }
}

impl fmt::Display for Method {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_orders_match_the_steppers() {
        use crate::ode::reference::Oscillator;
        for m in Method::ALL {
            assert_eq!(Method::from_name(m.name()), Some(m));
            if m.kind() == MethodKind::Implicit {
                assert!(m.is_adaptive() && m.tableau().is_none(), "{m}");
                continue;
            }
            assert_eq!(m.stepper::<Oscillator>().order(), m.order(), "{m}");
            assert_eq!(m.stepper::<Oscillator>().name(), m.name(), "{m}");
        }
    }
}

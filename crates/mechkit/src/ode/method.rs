//! The fixed-step methods by name, for scenario files and the command line.

use std::fmt;

/// A fixed-step integration method.
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
}

impl Method {
    /// Every method available.
    pub const ALL: [Method; 4] = [
        Method::Euler,
        Method::EulerCromer,
        Method::VelocityVerlet,
        Method::Rk4,
    ];

    /// The name used in scenario files.
    pub fn name(self) -> &'static str {
        match self {
            Method::Euler => "euler",
            Method::EulerCromer => "euler-cromer",
            Method::VelocityVerlet => "verlet",
            Method::Rk4 => "rk4",
        }
    }

    /// Global order of accuracy.
    pub fn order(self) -> u32 {
        match self {
            Method::Euler | Method::EulerCromer => 1,
            Method::VelocityVerlet => 2,
            Method::Rk4 => 4,
        }
    }

    /// A one-line description.
    pub fn description(self) -> &'static str {
        match self {
            Method::Euler => "forward Euler, 1st order",
            Method::EulerCromer => {
                "Euler-Cromer (semi-implicit Euler: v first, then x with the new v), 1st order, symplectic"
            }
            Method::VelocityVerlet => {
                "velocity Verlet, 2nd order, symplectic for position-only forces"
            }
            Method::Rk4 => "classical Runge-Kutta, 4th order",
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
            _ => return None,
        })
    }
}

impl fmt::Display for Method {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

//! Energy: the ledger of a run (the work done by each force along the computed path, kinetic
//! and potential energy, and the work-energy theorem as a check, `W_net = ΔK`), the energy
//! balance every model reports ([`EnergyBalance`]: `Δ(K + U) = Σ W_nc + ΔE_events`), and the tools
//! of the work-energy chapters: potentials and forces in 1-D, energy diagrams with equilibria
//! and turning points, the speed a body has by the work-energy theorem, line integrals of force
//! fields, motion at constant power, and the work (or impulse) of a sampled force.

mod balance;
mod constant_power;
mod diagram;
mod ledger;
mod line_integral;
mod motion;
mod potential;
mod sampled_work;

pub use balance::{EnergyBalance, EnergyPart, EnergyTerm, ForceWork};
pub use constant_power::ConstantPower;
pub use diagram::{Diagram, EnergyCut, Equilibrium, Region, Stability};
pub use ledger::EnergyLedger;
pub use line_integral::{ForceField, Path, PathWork};
pub use motion::Motion;
pub use potential::{Origin, Potential};
pub use sampled_work::SampledIntegral;

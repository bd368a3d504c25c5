//! Energy: the ledger of a run (the work done by each force along the computed path, kinetic
//! and potential energy, and the work-energy theorem as a check, `W_net = ΔK`), the energy
//! balance every model reports ([`EnergyBalance`]: `Δ(K + U) = Σ W_nc + ΔE_events`), and the tools
//! of the work-energy chapters: potentials and forces in 1-D, energy diagrams with equilibria
//! and turning points, the speed a body has by the work-energy theorem, line integrals of force
//! fields, motion at constant power, and the work (or impulse) of a sampled force.
//!
//! The one-question answers (`mechkit potential`, `work`, `impulse`, `power`) are values here:
//! [`PotentialAnalysis`] ([`analyse_potential`]), [`FieldForce`] ([`potential_field`]),
//! [`FieldWork`] ([`ForceField::work_report`]), [`DataWork`] ([`data_work`]) and
//! [`PowerAnswer`] ([`constant_power_motion`], [`average_power`]); each serializes to the
//! command's JSON and builds its tables and plot data.

mod analysis;
mod axis_units;
mod balance;
mod constant_power;
mod data_work;
mod diagram;
mod diagram_plot;
mod field_report;
mod ledger;
mod line_integral;
mod motion;
mod potential;
mod power_report;
mod sampled_work;

pub use analysis::{
    AxisUnits, ByStability, Given, PointValues, PotentialAnalysis, PotentialQuestion, Release,
    analyse_potential,
};
pub use balance::{EnergyBalance, EnergyPart, EnergyTerm, ForceWork};
pub use constant_power::ConstantPower;
pub use data_work::{
    Abscissa, DataUnits, DataWork, DataWorkError, DataWorkQuestion, Peak, data_work,
};
pub use diagram::{Diagram, EnergyCut, Equilibrium, Region, Stability};
pub use field_report::{FieldForce, FieldPoint, FieldWork, potential_field};
pub use ledger::EnergyLedger;
pub use line_integral::{ForceField, Path, PathWork};
pub use motion::{Bound, Motion};
pub use potential::{Origin, Potential};
pub use power_report::{
    AveragePower, PowerAnswer, PowerMotion, PowerSample, SpeedReached, average_power,
    constant_power_motion,
};
pub use sampled_work::SampledIntegral;

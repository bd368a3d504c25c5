//! Energy bookkeeping: the work done by each force along the computed path, kinetic and
//! potential energy, and the work-energy theorem as a check (`W_net = ΔK`).

mod ledger;

pub use ledger::EnergyLedger;

//! Friction and contact forces: Coulomb friction (static and dynamic), the normal force on a
//! flat or inclined surface, the marginal angle, and stick-slip motion with the switches
//! located exactly.
//!
//! **Coulomb's law.** While two surfaces stick, friction is whatever keeps them together, up
//! to `|f| ≤ μs N`; while they slip, `f = −μd N sign(v_rel)`, opposing the relative velocity
//! ([`Coulomb`]). The course's models assume `μs ≥ μd`; with `μs < μd` a body at rest cannot
//! start sliding below `μd N` (sliding friction would stop it at once), so `max(μs, μd)`
//! bounds sticking and [`Coulomb::warning`] says so.
//!
//! **Incline.** On an incline at `α` the normal force is `N = m g cos α` (plus other normal
//! loads), the pull down the slope `m g sin α`; a block at rest stays while
//! `tan α ≤ μs`, so the marginal angle is `atan μs`; sliding, it accelerates at
//! `g (sin α − μd cos α)` ([`Incline`]).
//!
//! **Stick-slip.** A block on a belt moving at `u` (or a fixed floor), pulled by a spring `k`
//! whose anchor moves at `w` (the earthquake model: a slowly driven spring, stick-slip
//! cycles) ([`SpringBlock`]). Sticking, `x = x_s + u (t − t_s)` and static friction balances
//! the spring until `|F_s|` reaches `μs N`; slipping in direction `s`, `m ẍ = −k (x − w t) −
//! s μd N`, a harmonic oscillation about a shifted centre, until `v − u` returns to 0. Both
//! switches are events located inside the integrator's step ([`SpringBlock::simulate`]); the
//! closed forms ([`SpringBlock::exact_slip`], [`SpringBlock::exact_slip_end`],
//! [`SpringBlock::exact_stick_end`]) check it. The energy balance
//! ([`crate::energy::EnergyBalance`]) closes `K + U_spring + Q = K0 + U0 + W_belt + W_anchor`,
//! with `Q = ∫ μd N |v − u| dt` the heat, the negative work of friction relative to the surface.
//!
//! **Reports.** [`Incline::report`] and [`SpringBlock::report`] are the answers of
//! `mechkit friction` as values ([`FrictionReport`], [`StickSlipReport`] with its table and
//! plots).

mod coulomb;
mod error;
mod report;
mod spring_block;
mod stick_slip;

pub use coulomb::{Coulomb, FrictionWarning, Incline, InclineReport};
pub use error::FrictionError;
pub use report::{
    FrictionReport, PhaseReport, StartEnd, StickSlipEnergy, StickSlipReport, regime_name,
};
pub use spring_block::{PhaseStart, SpringBlock};
pub use stick_slip::{Phase, PhaseEnd, Regime, StickSlipRun, StickSlipSample};

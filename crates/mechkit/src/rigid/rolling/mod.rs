//! Planar rigid bodies rolling and slipping on an incline: a sphere, cylinder or hoop of
//! radius `R` and moment `I = k m R²` about its centre of mass, with Coulomb friction at the
//! contact point.
//!
//! The state is the position `x` along the incline (down the slope positive), the velocity
//! `v`, the angle `θ` and the angular velocity `ω` (forward spin positive, so rolling is
//! `v = ω R`). The friction `f` acts at the contact point, one radius below the centre, so it
//! gives the torque `−f R`:
//!
//! `m v̇ = m g sin α + f`, `I ω̇ = −f R`.
//!
//! **Slipping** (`v_c = v − ω R ≠ 0`): `f = −μd N sign(v_c)`, `N = m g cos α`; `v̇_c` is
//! constant, so from a launch `(v0, ω0)` rolling starts at `t* = −v_c0/v̇_c` with the speed
//! `v0 + v̇ t*` ([`RollingMotion::roll_start`]). On a flat floor friction passes through the
//! contact point, so the angular momentum about it, `m R (v + k R ω)`, is conserved and the
//! rolling speed is `(v0 + k R ω0)/(1 + k)`: with enough backspin the ball comes back.
//!
//! **Rolling** (`v_c = 0`): `f = −m g sin α · k/(1 + k)` and `a = g sin α/(1 + k)`, possible
//! while `|f| ≤ μs N`, i.e. `|tan α| ≤ μs (1 + k)/k`; on a steeper slope the body slips on.
//!
//! [`RollingMotion::simulate`] integrates each regime with DOP853 and locates the switch
//! exactly when `v_c` reaches zero; its energy balance checks `K_trans + K_rot + U − W_friction`
//! constant, with the work of friction `∫ f v_c dt` negative while slipping and zero while
//! rolling. [`RollingMotion::report`] is the answer of `mechkit roll` as a value
//! ([`RollReport`]: each phase with its accelerations, the table and the plots).

mod body;
mod error;
mod motion;
mod report;
mod run;

pub use body::RollingBody;
pub use error::RollingError;
pub use motion::RollingMotion;
pub use report::{
    BodyNumbers, PhaseMotion, PhaseReport, RollEnergy, RollReport, RollStart, StartEnd, regime_name,
};
pub use run::{Contact, RollPhase, RollSample, RollingRun};

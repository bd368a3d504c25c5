//! The rocket: closed forms against the simulation, momentum of rocket and exhaust, drag,
//! bad input.

mod closed_forms;
mod drag;
mod errors;
mod momentum;

use mechkit::ode::{AdaptiveConfig, Tolerance};
use mechkit::rocket::Rocket;

/// 1000 kg at ignition, 400 kg at burnout, 10 kg/s at 2 km/s: a 60 s burn.
fn rocket() -> Rocket {
    Rocket::new(1000.0, 400.0, 10.0, 2000.0).unwrap()
}

/// Dormand-Prince at `rtol`, with `atol` a thousand times smaller.
fn config(rtol: f64) -> AdaptiveConfig {
    AdaptiveConfig {
        rtol: Tolerance::Scalar(rtol),
        atol: Tolerance::Scalar(rtol * 1e-3),
        ..AdaptiveConfig::default()
    }
}

//! Joints in space (`dimensions = 3` with `[[joint]]`): ball hinges, rods, strings that go
//! slack and taut, and contacts of a point or a ball with a plane, smooth or rolling. The
//! mechanism solver keeps each constraint's acceleration zero, with Euler's equations in the
//! response of the bodies that turn. Checked against closed forms: the conical pendulum, the
//! physical pendulum (and the same scenario in a plane), the heavy top's steady precession and
//! its nutation bottom (and `mechkit::rigid::free3d`), a ball rolling down an incline, a
//! string's slack and taut events against the projectile, a ball coming to rest on the floor,
//! the projection of initial velocities that break a joint, and the errors of what works in a
//! plane only.

use std::f64::consts::PI;

use mechkit::mass::Vec3;
use mechkit::rigid::free3d::{FreeBody, SpinOptions, SpinningBody, complete_k};
use mechkit::scenario::sweep::ConstantOverride;
use mechkit::scenario::{Scenario, ScenarioError, Summary};
use nalgebra::{Unit, UnitQuaternion, Vector3};

use crate::util::workspace;

mod pendulums;
mod rolling;
mod strings;
mod top;
mod unheld;

const G: f64 = 9.81;

fn run_text(text: &str) -> Summary {
    Scenario::from_str("test.toml", text)
        .unwrap_or_else(|e| panic!("{e}"))
        .run()
        .unwrap()
        .summary
}

fn error(text: &str) -> ScenarioError {
    Scenario::from_str("test.toml", text).expect_err("the scenario should be rejected")
}

/// The line of the file an error points at.
fn line(e: &ScenarioError) -> usize {
    e.location
        .as_ref()
        .unwrap_or_else(|| panic!("no location: {e}"))
        .line
}

/// A scenario in space with uniform gravity `g`: `tables`, run by DOP853 at `rtol` (absolute
/// `1e-2 rtol`) for `t_max` seconds, with the `[observe]` lines `observe`. The joints pull a
/// drift back over 0.1 s: with the default 10 ms DOP853 takes steps of about τ/10 whatever
/// `rtol` (ten times as many), and the rolling contacts' forces wobble by 1e-5.
fn space(tables: &str, rtol: f64, t_max: f64, observe: &str) -> String {
    format!(
        "dimensions = 3\nstabilisation = \"0.1 s\"\n{tables}\n[[force]]\nkind = \"uniform-gravity\"\ng = \"{G} m/s^2\"\n\
         [integrator]\nmethod = \"dop853\"\nrtol = {rtol:e}\natol = {:e}\n\
         [stop]\nt_max = \"{t_max} s\"\n[observe]\n{observe}\n",
        1e-2 * rtol
    )
}

/// The mean time between the occurrences of the event `name` (more than five of them).
fn mean_period(s: &Summary, name: &str) -> f64 {
    let times: Vec<f64> = event_times(s, name);
    assert!(times.len() > 5, "{name}: {} occurrences", times.len());
    (times[times.len() - 1] - times[0]) / (times.len() - 1) as f64
}

fn event_times(s: &Summary, name: &str) -> Vec<f64> {
    s.events
        .iter()
        .filter(|e| e.name == name)
        .map(|e| e.t)
        .collect()
}

fn close(a: f64, b: f64, tol: f64) {
    assert!((a - b).abs() <= tol, "{a} vs {b} (tolerance {tol})");
}

fn close3(a: &[f64], b: [f64; 3], tol: f64) {
    assert_eq!(a.len(), 3, "{a:?}");
    for k in 0..3 {
        assert!(
            (a[k] - b[k]).abs() <= tol,
            "{a:?} vs {b:?} (tolerance {tol})"
        );
    }
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn vec3(v: &[f64]) -> [f64; 3] {
    [v[0], v[1], v[2]]
}

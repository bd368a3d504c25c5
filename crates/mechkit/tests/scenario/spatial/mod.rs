//! Free rigid bodies in space (`dimensions = 3` with `[[rigid_body]]`): the orientation is a
//! quaternion turned by Euler's equations `I ω̇ = τ − ω × I ω` (body frame), the centre of
//! mass moves by Newton's law, forces act at body points with their torque `r × F`. Checked
//! against closed forms: the torque-free symmetric top (ω precessing about the figure axis at
//! `Ω = (I₃ − I₁) ω₃ / I₁`), small oscillations about a stable principal axis, the exact
//! Euler-Poinsot motion and `mechkit::rigid::free3d` for the tennis-racket flip, spin-up by
//! a constant torque, the first accelerations of a body pushed at a point, a spinning body
//! thrown in uniform gravity, and the inertia of bodies made of parts.

use mechkit::mass::Vec3;
use mechkit::rigid::free3d::{FreeBody, Poinsot, SpinIntegrator, SpinOptions, SpinningBody};
use mechkit::scenario::sweep::ConstantOverride;
use mechkit::scenario::{Scenario, ScenarioError, Summary};
use nalgebra::{Unit, UnitQuaternion};

use crate::util::workspace;

mod pushed;
mod refused;
mod turning;

fn run_text(text: &str) -> Summary {
    Scenario::from_str("test.toml", text)
        .unwrap_or_else(|e| panic!("{e}"))
        .run()
        .unwrap()
        .summary
}

/// A scenario in space: `tables` run by DOP853 at `rtol` (absolute `1e-2 rtol`) for `t_max`
/// seconds, with the `[observe]` lines `observe`.
fn space(tables: &str, rtol: f64, t_max: f64, observe: &str) -> String {
    format!(
        "dimensions = 3\n{tables}\n[integrator]\nmethod = \"dop853\"\nrtol = {rtol:e}\natol = {:e}\n\
         [stop]\nt_max = \"{t_max} s\"\n[observe]\n{observe}\n",
        1e-2 * rtol
    )
}

/// The mean time between the occurrences of the event `name` (more than five of them).
fn mean_period(s: &Summary, name: &str) -> f64 {
    let times: Vec<f64> = s
        .events
        .iter()
        .filter(|e| e.name == name)
        .map(|e| e.t)
        .collect();
    assert!(times.len() > 5, "{name}: {} occurrences", times.len());
    (times[times.len() - 1] - times[0]) / (times.len() - 1) as f64
}

fn close(a: f64, b: f64, tol: f64) {
    assert!((a - b).abs() <= tol, "{a} vs {b} (tolerance {tol})");
}

fn close3(a: [f64; 3], b: [f64; 3], tol: f64) {
    for k in 0..3 {
        assert!(
            (a[k] - b[k]).abs() <= tol,
            "{a:?} vs {b:?} (tolerance {tol})"
        );
    }
}

fn norm(v: [f64; 3]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}

/// `v` turned by `angle` about the unit vector `axis` (Rodrigues).
fn turned(v: [f64; 3], axis: [f64; 3], angle: f64) -> [f64; 3] {
    let r = UnitQuaternion::from_axis_angle(&Unit::new_normalize(Vec3::from(axis)), angle);
    (r * Vec3::from(v)).into()
}

//! Diagnosing a run that stopped being finite: which coordinate or force, when, and why.

use super::report::Divergence;
use crate::Real;
use crate::error::short;
use crate::ode::{SecondOrderSystem, State};
use crate::particles::{Evaluation, ParticleSystem};

/// Name of state component `i`: `feather.x`, `ball.vy`.
pub(crate) fn coordinate_name(sys: &ParticleSystem, i: usize) -> String {
    let dim = sys.dim();
    let n = sys.dof();
    let (velocity, j) = if i >= n { (true, i - n) } else { (false, i) };
    let body = &sys.bodies()[j / dim].name;
    let axis = ["x", "y", "z"][j % dim];
    if velocity {
        format!("{body}.v{axis}")
    } else {
        format!("{body}.{axis}")
    }
}

pub(crate) fn diagnose_state(
    sys: &ParticleSystem,
    prev_y: &[Real],
    bad: &State,
    t_prev: Real,
    step: u64,
) -> Divergence {
    let i = bad
        .y
        .iter()
        .position(|x| !x.is_finite())
        .expect("called for a non-finite state");
    let quantity = coordinate_name(sys, i);
    let value = bad.y[i];
    let message = format!(
        "the step from t = {t0} s to t = {} s made {quantity} = {}, although every force was finite at t = {t0} s (where {quantity} = {}): a stage of the step left the region where the forces are defined, or the step is too large for how fast the forces change; try a smaller dt",
        short(bad.t),
        short(value),
        short(prev_y[i]),
        t0 = short(t_prev)
    );
    Divergence {
        t: t_prev,
        step,
        quantity,
        value,
        message,
    }
}

/// A force with a component that is not a number at a state: which force, on which body, and
/// where the bodies are.
pub(crate) struct BadForce {
    /// The force's name.
    pub force: String,
    /// The body (its index) whose component is not finite.
    pub body: usize,
    /// `x`, `y` or `z`.
    pub axis: &'static str,
    /// The component.
    pub value: Real,
    /// `ball at position (0, 0) m and velocity (1, 0) m/s (the other bodies: sun at (0, 0) m)`.
    pub situation: String,
}

/// The first force with a component that is not finite at `state` (forces in their order,
/// components in theirs), with where the bodies are.
pub(crate) fn non_finite_force(sys: &ParticleSystem, state: &State) -> Option<BadForce> {
    let (q, v) = state.qv();
    let k = sys.kinematics(state.t, q, v);
    let dim = sys.dim();
    let mut f = vec![0.0; q.len()];
    for force in sys.forces().iter() {
        f.fill(0.0);
        force.add_forces(&k, &mut f);
        let Some(i) = f.iter().position(|x| !x.is_finite()) else {
            continue;
        };
        let body = i / dim;
        let name = &sys.bodies()[body].name;
        let pos = vector(k.position(body), "m");
        let vel = vector(k.velocity(body), "m/s");
        // A force on one body may depend on the others (a pair force, `other.x` in a
        // formula): show where they all are.
        let others: Vec<String> = sys
            .bodies()
            .iter()
            .enumerate()
            .filter(|(j, _)| *j != body)
            .take(6)
            .map(|(j, b)| format!("{} at {}", b.name, vector(k.position(j), "m")))
            .collect();
        let others = if others.is_empty() {
            String::new()
        } else {
            format!(" (the other bodies: {})", others.join(", "))
        };
        return Some(BadForce {
            force: force.name().to_string(),
            body,
            axis: ["x", "y", "z"][i % dim],
            value: f[i],
            situation: format!("{name} at position {pos} and velocity {vel}{others}"),
        });
    }
    None
}

/// The first force whose potential energy is not finite at `state`: its name and the value.
pub(crate) fn non_finite_potential(sys: &ParticleSystem, state: &State) -> Option<(String, Real)> {
    let (q, v) = state.qv();
    let k = sys.kinematics(state.t, q, v);
    sys.forces().iter().find_map(|force| {
        force
            .potential(&k)
            .filter(|u| !u.is_finite())
            .map(|u| (force.name().to_string(), u))
    })
}

/// Checks an evaluation for non-finite values and names the force responsible.
pub(crate) fn diagnose_evaluation(
    sys: &ParticleSystem,
    state: &State,
    eval: &Evaluation,
    step: u64,
) -> Option<Divergence> {
    let finite = eval.a.iter().all(|x| x.is_finite())
        && eval.power.iter().all(|x| x.is_finite())
        && eval.kinetic.is_finite()
        && eval.potential_total.is_none_or(Real::is_finite);
    if finite {
        return None;
    }
    if let Some(bad) = non_finite_force(sys, state) {
        let body = &sys.bodies()[bad.body].name;
        return Some(Divergence {
            t: state.t,
            step,
            quantity: format!("force `{}` on {body} ({} component)", bad.force, bad.axis),
            value: bad.value,
            message: format!(
                "at t = {} s the force `{}` on {body} is {} ({} component), with {}: a division by zero or a value outside a function's domain (sqrt, log of a negative number) in the force: a body at its singular point (the centre of an inverse-square force, two bodies at one place) or a formula's; check where the bodies start and the force's formula, or end the run before them with an event",
                short(state.t),
                bad.force,
                short(bad.value),
                bad.axis,
                bad.situation
            ),
        });
    }
    if let Some((force, u)) = non_finite_potential(sys, state) {
        return Some(Divergence {
            t: state.t,
            step,
            quantity: format!("potential energy of `{force}`"),
            value: u,
            message: format!(
                "at t = {} s the potential energy of `{force}` is {}: the bodies it acts on have reached a singular point (r = 0?)",
                short(state.t),
                short(u)
            ),
        });
    }
    let value = eval.kinetic;
    Some(Divergence {
        t: state.t,
        step,
        quantity: "kinetic energy".into(),
        value,
        message: format!(
            "at t = {} s the kinetic energy is {}",
            short(state.t),
            short(value)
        ),
    })
}

/// A position or velocity for a message: `0.5 m` in 1-D, `(0.5, 2) m` otherwise.
fn vector(v: &[Real], unit: &str) -> String {
    if let [x] = v {
        format!("{} {unit}", short(*x))
    } else {
        let parts: Vec<String> = v.iter().map(|x| short(*x)).collect();
        format!("({}) {unit}", parts.join(", "))
    }
}

/// Why an adaptive run could not go on: a force that is not finite at the states the steps
/// reach (named, from the first such state `bad`), or a step size that collapsed.
pub(crate) fn step_failure(
    sys: &ParticleSystem,
    bad: Option<&State>,
    (t, h, h_min, component, non_finite): (Real, Real, Real, usize, bool),
    step: u64,
    scratch: &mut Vec<Real>,
) -> (super::report::StopReason, Divergence) {
    use super::report::StopReason;
    let named = bad.and_then(|b| {
        let mut e = Evaluation::default();
        let (q, v) = b.qv();
        sys.evaluate(b.t, q, v, &mut e, scratch);
        diagnose_evaluation(sys, b, &e, step)
    });
    match named {
        Some(d) if non_finite => (
            StopReason::Diverged,
            Divergence {
                t,
                message: format!(
                    "the run cannot continue past t = {} s: every step tried from there (down to {} s) reaches states where a force is not finite; the first: {}",
                    short(t),
                    short(h),
                    d.message
                ),
                ..d
            },
        ),
        _ => {
            let quantity = coordinate_name(sys, component.min(2 * sys.dof() - 1));
            (
                StopReason::StepTooSmall,
                Divergence {
                    t,
                    step,
                    quantity: quantity.clone(),
                    value: h,
                    message: format!(
                        "the step size fell to {} s at t = {} s (minimum {} s) without meeting the tolerance; the error is dominated by {quantity}: the solution is not smooth there (a discontinuous force, a collision, a singularity), or the tolerance is below what double precision allows; loosen rtol/atol, or model the discontinuity as an event",
                        short(h),
                        short(t),
                        short(h_min)
                    ),
                },
            )
        }
    }
}

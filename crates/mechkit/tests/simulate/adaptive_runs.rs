//! Adaptive runs of particle systems: the ground hit of a projectile with quadratic drag to
//! 1e-10 s, the energy ledger integrated with the motion, and the failures a user can cause
//! (velocity-dependent forces with a symplectic method, a singular force, a force that stops
//! being finite, bad tolerances).

use mechkit::forces::Force;
use mechkit::particles::Kinematics;
use mechkit::prelude::*;
use mechkit::simulate::SimulateError;

const G: f64 = 9.81;

fn projectile_with_drag() -> ParticleSystem {
    ParticleSystem::builder(2)
        .body("ball", 1.0)
        .force(UniformGravity::new("gravity", vec![0], G))
        .force(QuadraticDrag::new(
            "air",
            vec![Target {
                body: 0,
                coefficient: 0.01,
            }],
        ))
        .build()
        .unwrap()
}

fn tolerances(rtol: f64, atol: f64) -> AdaptiveConfig {
    AdaptiveConfig {
        rtol: Tolerance::Scalar(rtol),
        atol: Tolerance::Scalar(atol),
        ..AdaptiveConfig::default()
    }
}

fn ground_hit(
    method: Method,
    config: AdaptiveConfig,
) -> (f64, Vec<f64>, mechkit::simulate::RunReport) {
    let sys = projectile_with_drag();
    let r = Simulation::adaptive(&sys, method, config)
        .t_max(10.0)
        .stop_when(Condition::below(0, 1, 0.0))
        .run(State::from_qv(0.0, &[0.0, 0.0], &[10.0, 20.0]), &mut [])
        .unwrap();
    let e = r.event.clone().expect("it lands");
    (e.t, e.state.q.clone(), r)
}

/// v0 = (10, 20) m/s, D/m = 0.01 1/m: the landing time at rtol 1e-10 agrees with DOP853 at
/// rtol 1e-13 to 1e-10 s, and the located height is zero to 1e-9 m.
#[test]
fn projectile_with_quadratic_drag_lands_to_a_tenth_of_a_nanosecond() {
    let (t_ref, _, _) = ground_hit(Method::Dop853, tolerances(1e-13, 1e-15));
    for method in [Method::Dopri5, Method::Dop853] {
        let (t, q, r) = ground_hit(method, tolerances(1e-10, 1e-12));
        println!(
            "{method}: landing at {t:.12} s (reference {t_ref:.12}), y = {:e}, {} steps, {:?}",
            q[1], r.steps, r.adaptive
        );
        assert!((t - t_ref).abs() < 1e-10, "{method}: {t} vs {t_ref}");
        assert!(q[1].abs() < 1e-9, "{method}: y = {}", q[1]);
        // the work of gravity is exactly -ΔU; the drag's work is the energy lost
        let l = &r.ledger;
        assert!((l.work_of("gravity").unwrap() + l.potential_change(0).unwrap()).abs() < 1e-9);
        assert!((l.energy_change() - l.work_of("air").unwrap()).abs() < 1e-8 * l.energy().0.abs());
        assert!(
            l.work_energy_residual().abs() < 1e-8,
            "{}",
            l.work_energy_residual()
        );
    }
}

/// Energy of a Kepler orbit over ten periods through the simulation loop.
#[test]
fn adaptive_kepler_conserves_energy_to_the_tolerance() {
    let sys = ParticleSystem::builder(2)
        .body("planet", 1.0)
        .force(NewtonianGravity::fixed_centre(
            "sun",
            vec![0],
            1.0,
            vec![0.0, 0.0],
        ))
        .build()
        .unwrap();
    let e: f64 = 0.5;
    let v = ((1.0 + e) / (1.0 - e)).sqrt();
    let r = Simulation::adaptive(&sys, Method::Dop853, tolerances(1e-10, 1e-12))
        .t_max(20.0 * std::f64::consts::PI)
        .run(State::from_qv(0.0, &[1.0 - e, 0.0], &[0.0, v]), &mut [])
        .unwrap();
    let drift = r.ledger.energy_change() / r.ledger.energy().0.abs();
    println!("{:?}, relative energy drift {drift:e}", r.adaptive);
    assert!(drift.abs() < 1e-8);
    // back at perihelion after ten orbits
    assert!((r.final_state.y[0] - (1.0 - e)).abs() < 1e-6);
    assert!(r.ledger.work_energy_residual().abs() < 1e-8);
}

#[test]
fn symplectic_methods_refuse_velocity_dependent_forces() {
    let sys = projectile_with_drag();
    let err = Simulation::new(&sys, Method::Yoshida4, 0.01)
        .t_max(1.0)
        .run(State::from_qv(0.0, &[0.0, 0.0], &[1.0, 1.0]), &mut [])
        .unwrap_err();
    assert!(err.to_string().contains("velocity-dependent"), "{err}");
}

#[test]
fn bad_tolerances_are_refused() {
    let sys = projectile_with_drag();
    let x0 = State::from_qv(0.0, &[0.0, 0.0], &[1.0, 1.0]);
    for (config, want) in [
        (tolerances(0.0, 1e-9), "rtol"),
        (tolerances(-1e-6, 1e-9), "rtol"),
        (tolerances(1e-6, -1.0), "atol"),
        (
            AdaptiveConfig {
                atol: Tolerance::PerComponent(vec![1e-9; 3]),
                ..AdaptiveConfig::default()
            },
            "4",
        ),
    ] {
        let err = Simulation::adaptive(&sys, Method::Dopri5, config)
            .t_max(1.0)
            .run(x0.clone(), &mut [])
            .unwrap_err();
        assert!(matches!(err, SimulateError::Config(_)), "{err:?}");
        assert!(err.to_string().contains(want), "{err}");
    }
    let err = Simulation::adaptive(&sys, Method::Rk4, AdaptiveConfig::default())
        .run(x0, &mut [])
        .unwrap_err();
    assert!(err.to_string().contains("no error estimator"), "{err}");
}

/// A body falling straight into a point mass: the force grows without bound and the step size
/// collapses; the run stops with the time, the step and the component that dominates.
#[test]
fn radial_fall_into_a_point_mass_stops_with_a_step_size_diagnosis() {
    let sys = ParticleSystem::builder(1)
        .body("probe", 1.0)
        .force(NewtonianGravity::fixed_centre(
            "star",
            vec![0],
            1.0,
            vec![0.0],
        ))
        .build()
        .unwrap();
    let r = Simulation::adaptive(&sys, Method::Dopri5, AdaptiveConfig::default())
        .t_max(3.0)
        .run(State::from_qv(0.0, &[1.0], &[0.0]), &mut [])
        .unwrap();
    println!(
        "{:?}: {}",
        r.stop_reason,
        r.divergence.as_ref().unwrap().message
    );
    assert!(r.stop_reason.is_failure());
    let d = r.divergence.as_ref().unwrap();
    // the fall takes π/(2√2) s
    let t_hit = std::f64::consts::PI / (2.0 * 2f64.sqrt());
    assert!((d.t - t_hit).abs() < 1e-3, "{} vs {t_hit}", d.t);
    assert!(
        d.message.contains("step size") || d.message.contains("force"),
        "{}",
        d.message
    );
    assert!(r.final_state.is_finite());
}

/// A force that is not defined beyond a point: sqrt of a negative number inside a stage.
#[derive(Debug)]
struct RootForce;

impl Force for RootForce {
    fn name(&self) -> &'static str {
        "root"
    }
    fn add_forces(&self, k: &Kinematics<'_>, out: &mut [f64]) {
        out[0] -= k.x[0].sqrt();
    }
    fn bodies(&self) -> Vec<usize> {
        vec![0]
    }
}

#[test]
fn a_force_that_stops_being_finite_is_named() {
    let sys = ParticleSystem::builder(1)
        .body("p", 1.0)
        .force(RootForce)
        .build()
        .unwrap();
    let r = Simulation::adaptive(&sys, Method::Dopri5, AdaptiveConfig::default())
        .t_max(10.0)
        .run(State::from_qv(0.0, &[1.0], &[-1.0]), &mut [])
        .unwrap();
    let d = r.divergence.as_ref().expect("a diagnosis");
    println!("{:?}: {}", r.stop_reason, d.message);
    assert_eq!(r.stop_reason, StopReason::Diverged);
    assert!(d.quantity.contains("root"), "{}", d.quantity);
}

/// Fuzz finding (scenario): a free fall with `[output] interval = "2 ms"` and no `t_max`. The
/// step budget bounds the steps, not the output times inside them: the adaptive steps grew
/// without bound, and one of them held trillions of output times (the run never ended). With
/// no end the output times stop after `MAX_UNENDED_OUTPUTS`, and a warning says so.
#[test]
fn fuzz_output_times_without_an_end_are_bounded() {
    let text = std::fs::read_to_string(
        crate::util::workspace()
            .join("fuzz/regressions/scenario/output-interval-without-an-end.toml"),
    )
    .unwrap();
    let scenario = mechkit::scenario::Scenario::from_str("fall.toml", &text).unwrap();
    let out = scenario.run().unwrap();
    let warning = out
        .summary
        .warnings
        .iter()
        .find(|w| w.contains("output every 0.002 s ends after 1000000 output times"));
    assert!(warning.is_some(), "{:?}", out.summary.warnings);
    assert!(
        warning
            .unwrap()
            .contains("(t = 2000 s), as the run has no t_max; set t_max")
    );
}

/// Fuzz finding (scenario, after 4.61 M inputs): a bouncing ball with `[output] interval =
/// "2 fs"` up to `t_max = 5.06 s`, 2.5·10^15 output times. The 200 steps the fuzz target
/// allows could not bound them, and an in-memory run (a sweep, the gallery), which has no file
/// to reach the output limit, interpolated rows for ever. Since issue 26 an interval that asks
/// for more than `MAX_STEPS` = 10^9 output times is refused when the file is read, at the
/// interval; below that, the output times end where the trajectory could no longer fit in the
/// output limit, with a warning that says how to raise it, and the run goes on to its end.
#[test]
fn fuzz_a_femtosecond_output_interval_ends_at_the_output_limit() {
    let text = std::fs::read_to_string(
        crate::util::workspace().join("fuzz/regressions/scenario/femtosecond-output-interval.toml"),
    )
    .unwrap();
    let e = mechkit::scenario::Scenario::from_str("ball.toml", &text).unwrap_err();
    assert_eq!(e.location.as_ref().map(|l| l.line), Some(45), "{e}");
    assert!(
        e.message
            .contains("2530000000000000 output times, more than the 1000000000"),
        "{e}"
    );
    // 5.06·10^8 output times of 10 ns: within the bound, beyond the output limit
    let text = text.replace("interval = \"2 fs\"", "interval = \"10 ns\"");
    let mut scenario = mechkit::scenario::Scenario::from_str("ball.toml", &text).unwrap();
    // 1 MB holds at most 1e6/(2*8) rows of t, x, y, vx, vy, K, work.gravity, power.gravity
    // of at least one digit and one comma each
    scenario.max_output = 1_000_000;
    let out = scenario.run().unwrap();
    // the run goes on past the output's end, to the rest of the bounces
    assert!(
        out.summary.t_end > 3.9,
        "{} {}",
        out.summary.t_end,
        out.summary.stop_reason
    );
    let warning = out
        .summary
        .warnings
        .iter()
        .find(|w| {
            w.contains("output every 1e-8 s up to t_max = 5.06 s asks for 5.060e8 output times")
        })
        .unwrap_or_else(|| panic!("{:?}", out.summary.warnings));
    assert!(
        warning.contains("raise the output limit (`[output] max_size`"),
        "{warning}"
    );
    assert!(warning.contains("more than the 62500 allowed: the output ends at t = 0.000625"));
    // 62,500 output times of 10 ns, then only the apexes (the first after the first bounce)
    let points = &out.plots[0].series[0].points;
    let last_grid = points
        .iter()
        .filter(|p| p.0 < 0.1)
        .map(|p| p.0)
        .fold(0.0, f64::max);
    assert!((last_grid - 6.25e-4).abs() < 1e-12, "{last_grid}");
    assert!(points.iter().filter(|p| p.0 >= 0.1).all(|p| p.0 > 0.4));
}

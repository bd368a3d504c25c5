//! Issue 11 (reliability): a ball dropped from h = 1 m bouncing with `v ← −e v` makes
//! infinitely many bounces before the accumulation time t∞ = t1 (1 + e)/(1 − e),
//! t1 = √(2h/g). With e = 0.5 under `dopri5` (and with any e under long fixed steps) the
//! bounces once stopped being found and the ball fell through the floor to x = −47 km, the run
//! ending "successfully" at t_max. Every bounce must be located (at the analytic times), the
//! ball must never go below the floor, and the run must end as Zeno at t∞.

use mechkit::particles::Sample;
use mechkit::prelude::*;
use mechkit::scenario::Scenario;
use mechkit::simulate::{Observer, ObserverError, RunReport};

const G: f64 = 9.81;

/// The lowest position any sample shows.
struct Lowest(f64);

impl Observer for Lowest {
    fn observe(&mut self, s: &Sample<'_>) -> Result<(), ObserverError> {
        self.0 = self.0.min(s.q[0]);
        Ok(())
    }
}

fn bounce_run(e: f64, fixed_dt: Option<f64>) -> (RunReport, f64) {
    let sys = ParticleSystem::builder(1)
        .body("ball", 1.0)
        .force(UniformGravity::new("gravity", vec![0], G))
        .build()
        .unwrap();
    let bounce = Event::new("bounce", |s, _| s.q[0])
        .direction(Direction::Falling)
        .set(move |_, _, y| y[1] *= -e);
    let sim = match fixed_dt {
        Some(dt) => Simulation::new(&sys, Method::Rk4, dt),
        None => Simulation::adaptive(&sys, Method::Dopri5, AdaptiveConfig::default()),
    };
    let mut lowest = Lowest(f64::INFINITY);
    let r = sim
        .t_max(100.0)
        .event(bounce)
        .run(State::from_qv(0.0, &[1.0], &[0.0]), &mut [&mut lowest])
        .unwrap();
    (r, lowest.0)
}

fn check(e: f64, fixed_dt: Option<f64>) {
    let label = format!("e = {e}, dt = {fixed_dt:?}");
    let (r, lowest) = bounce_run(e, fixed_dt);
    let t1 = (2.0 / G).sqrt();
    let t_inf = t1 * (1.0 + e) / (1.0 - e);
    assert_eq!(r.stop_reason, StopReason::Zeno, "{label}");
    assert!(
        r.divergence.as_ref().unwrap().message.contains("Zeno"),
        "{label}"
    );
    assert!(
        (r.final_state.t - t_inf).abs() < 1e-9 * t_inf,
        "{label}: stopped at {} instead of t∞ = {t_inf}",
        r.final_state.t
    );
    assert!(lowest > -1e-12, "{label}: the ball went down to {lowest} m");
    assert!(r.final_state.y[0].abs() < 1e-12, "{label}");
    // no bounce skipped: the gaps between bounces shrink by e each time, as long as they are
    // well above the time resolution
    let t: Vec<f64> = r.events.iter().map(|ev| ev.t).collect();
    for k in 2..t.len() {
        let (g0, g1) = (t[k - 1] - t[k - 2], t[k] - t[k - 1]);
        if g1 > 1e-11 {
            assert!(
                (g1 / g0 - e).abs() < 1e-3,
                "{label}: bounce {}: gap ratio {}",
                k + 1,
                g1 / g0
            );
        }
    }
    // every bounce, at its analytic time t_k = t1 + 2 t1 e (1 − e^(k−1))/(1 − e)
    assert!(r.events.len() >= 20, "{label}: {} bounces", r.events.len());
    for (k, ev) in r.events.iter().take(20).enumerate() {
        let want = t1 + 2.0 * t1 * e * (1.0 - e.powi(k as i32)) / (1.0 - e);
        assert!(
            (ev.t - want).abs() < 1e-9,
            "{label}: bounce {} at {} vs {want}",
            k + 1,
            ev.t
        );
    }
}

#[test]
fn issue_011_zeno_ball_falls_through_dopri5() {
    check(0.5, None);
    check(0.9, None);
}

#[test]
fn issue_011_zeno_ball_falls_through_rk4_fixed_steps() {
    check(0.5, Some(1e-3));
    check(0.9, Some(1e-3));
    // steps longer than whole bounces
    check(0.5, Some(0.05));
}

#[test]
fn issue_011_zeno_ball_falls_through_a_wall() {
    // the same ball (radius 1 cm) on a `[[wall]]` with restitution 0.5
    let toml = r#"
dimensions = 1
[[body]]
name = "ball"
mass = "1 kg"
position = "1 m"
radius = "1 cm"
[[force]]
name = "gravity"
kind = "uniform-gravity"
g = "9.81 m/s^2"
[integrator]
method = "dopri5"
[[wall]]
name = "floor"
point = 0
normal = 1
restitution = 0.5
[stop]
t_max = "100 s"
"#;
    let out = Scenario::from_str("wall.toml", toml)
        .unwrap()
        .run()
        .unwrap();
    let r = &out.report;
    let t_inf = (2.0 * 0.99 / G).sqrt() * 3.0;
    assert_eq!(r.stop_reason, StopReason::Zeno);
    assert!(
        (r.final_state.t - t_inf).abs() < 1e-6,
        "{} vs {t_inf}",
        r.final_state.t
    );
    assert!((r.final_state.y[0] - 0.01).abs() < 1e-9);
}

/// What the fix must not change: a state change that does not turn the function back in place
/// (a jump elsewhere: a periodic coordinate wrapped from 1 to 0 at unit speed) fires once per
/// period and never looks like Zeno; a jump below the floor with the ball rising fires again only
/// when the ball comes back down through it.
#[test]
fn issue_011_jumps_are_not_rearmed() {
    let sys = ParticleSystem::builder(1).body("p", 1.0).build().unwrap();
    let wrap = Event::new("wrap", |s, _| s.q[0] - 1.0)
        .direction(Direction::Rising)
        .set(|_, _, y| y[0] -= 1.0);
    let r = Simulation::adaptive(&sys, Method::Dopri5, AdaptiveConfig::default())
        .t_max(10.5)
        .event(wrap)
        .run(State::from_qv(0.0, &[0.0], &[1.0]), &mut [])
        .unwrap();
    assert_eq!(r.stop_reason, StopReason::TMax);
    assert_eq!(r.events.len(), 10);
    for (k, ev) in r.events.iter().enumerate() {
        assert!((ev.t - (k + 1) as f64).abs() < 1e-9, "{}", ev.t);
    }
    // a ball reaching the floor is put 1 m below it, moving up at 1 m/s; g = 9.81 brings it
    // back down without reaching the floor, so it never crosses it again
    let sys = ParticleSystem::builder(1)
        .body("ball", 1.0)
        .force(UniformGravity::new("gravity", vec![0], G))
        .build()
        .unwrap();
    let sink = Event::new("sink", |s, _| s.q[0])
        .direction(Direction::Falling)
        .set(|_, _, y| {
            y[0] = -1.0;
            y[1] = 1.0;
        });
    let r = Simulation::adaptive(&sys, Method::Dopri5, AdaptiveConfig::default())
        .t_max(2.0)
        .event(sink)
        .run(State::from_qv(0.0, &[1.0], &[0.0]), &mut [])
        .unwrap();
    assert_eq!(r.stop_reason, StopReason::TMax);
    assert_eq!(r.events.len(), 1);
}

/// A ball released at rest on the floor (y = 0, vy = 0): `bounce` fires at t = 0 and its
/// `vy -> -e vy` leaves vy = 0, so it cannot turn the ball back; the ball once fell through to
/// y = −176 m with exit 0. It must stop on the Zeno diagnosis at t = 0 (the limit of bounces
/// of zero height), as a ball starting into the floor does, never below it.
#[test]
fn a_ball_released_at_rest_on_the_floor_does_not_fall_through_it() {
    for (vy, method) in [(0.0, None), (0.0, Some(1e-3)), (-1.0, None)] {
        let sys = ParticleSystem::builder(1)
            .body("ball", 1.0)
            .force(UniformGravity::new("gravity", vec![0], G))
            .build()
            .unwrap();
        let bounce = Event::new("bounce", |s, _| s.q[0])
            .direction(Direction::Falling)
            .set(|_, _, y| y[1] *= -0.9);
        let sim = match method {
            Some(dt) => Simulation::new(&sys, Method::Rk4, dt),
            None => Simulation::adaptive(&sys, Method::Dopri5, AdaptiveConfig::default()),
        };
        let mut lowest = Lowest(f64::INFINITY);
        let r = sim
            .t_max(6.0)
            .event(bounce)
            .run(State::from_qv(0.0, &[0.0], &[vy]), &mut [&mut lowest])
            .unwrap();
        let lowest = lowest.0;
        let label = format!("vy = {vy}, dt = {method:?}");
        assert_eq!(r.stop_reason, StopReason::Zeno, "{label}");
        assert!(lowest > -1e-9, "{label}: the ball went down to {lowest} m");
        if vy == 0.0 {
            assert_eq!(r.final_state.t, 0.0, "{label}");
        }
    }
}

/// The same on a `[[wall]]`, in 1-D and 2-D, under an adaptive and a fixed-step method: the
/// wall's gap is snapped to zero within rounding, so it stayed at zero over the first samples
/// of the run and lost its "as at the start" side there; the ball then fell through the wall
/// (to y = −4.9 m in 1 s, exit 0), or, once that side was kept, crawled through bounces of
/// rounding height every 6 ns. A function that stays at zero since the start of its step
/// and then leaves it the firing way fires at that start: here at t = 0, twice, and Zeno.
#[test]
fn a_ball_at_rest_on_a_wall_does_not_fall_through_it() {
    for (dimensions, point, normal, position) in [
        (1, "0", "1", "\"5 cm\""),
        (2, "[0, 0]", "[0, 1]", "[\"0 m\", \"5 cm\"]"),
    ] {
        for integrator in [
            "method = \"dop853\"\nrtol = 1e-12",
            "method = \"rk4\"\ndt = \"1 ms\"",
        ] {
            let toml = format!(
                "dimensions = {dimensions}\n[[body]]\nname = \"ball\"\nmass = \"60 g\"\n\
                 radius = \"5 cm\"\nposition = {position}\n[[force]]\nname = \"gravity\"\n\
                 kind = \"uniform-gravity\"\n[[wall]]\nname = \"floor\"\npoint = {point}\n\
                 normal = {normal}\nrestitution = 0.8\n[integrator]\n{integrator}\n\
                 [stop]\nt_max = \"1 s\"\n"
            );
            let out = Scenario::from_str("rest.toml", &toml)
                .unwrap()
                .run()
                .unwrap();
            let r = &out.report;
            let label = format!("{dimensions}-D, {integrator}");
            assert_eq!(r.stop_reason, StopReason::Zeno, "{label}");
            assert_eq!(r.final_state.t, 0.0, "{label}");
            let height = r.final_state.y[dimensions - 1];
            assert!(
                (height - 0.05).abs() < 1e-12,
                "{label}: the ball is at {height} m"
            );
        }
    }
}

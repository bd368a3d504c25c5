//! The cost of the event guarantee (issue 21): the same runs without events, with events whose
//! functions are bounded by interval arithmetic (the proof `mechkit run` uses for every
//! `[[event]]` written in the state), and with the same events sampled at 7 interior points
//! per step (what a function without an enclosure gets, and what every event got before).
//!
//! - the bouncing ball: 1-D, gravity, rk4 with dt = 1 ms for 6 s, a `bounce` event
//!   (`x` falling, `v → −0.9 v`) and an `apex` event (`v` falling);
//! - Kepler: 2-D, e = 0.5, dopri5 at rtol 1e-9, 20 orbits, an apoapsis event (`x vx + y vy`
//!   falling).
//!
//! "No events, general loop" is the run without events with the fused fixed-step kernel off
//! (`Simulation::fuse(false)`): events need the general loop, so the difference between it and
//! the run with events is the cost of the events themselves.
//!
//! A plain harness: each case runs 11 times after a warm-up and the median is printed, with
//! its ratio to the run without events. Run with `cargo bench -p mechkit --bench events`.

use std::hint::black_box;
use std::time::Instant;

use mechkit::interval::Jet;
use mechkit::prelude::*;
use mechkit::simulate::Condition;

fn median_s(mut f: impl FnMut() -> usize) -> (f64, usize) {
    let count = f(); // warm-up
    let mut samples: Vec<f64> = (0..11)
        .map(|_| {
            let t = Instant::now();
            black_box(f());
            t.elapsed().as_secs_f64()
        })
        .collect();
    samples.sort_by(f64::total_cmp);
    (samples[5], count)
}

#[derive(Clone, Copy, PartialEq)]
enum Events {
    None,
    /// No events, and the fused kernel off: the general loop that events run in.
    NoneGeneral,
    Proven,
    Sampled,
}

/// An event at the zeros of `g`, bounded by `bound` when proven.
fn event(
    name: &str,
    how: Events,
    g: impl Fn(&[f64], &[f64]) -> f64 + Send + Sync + 'static,
    bound: impl Fn(&mechkit::particles::StateJets<'_>) -> Jet + Send + Sync + 'static,
) -> Event {
    let c = Condition::from_fn(name, false, false, move |s, _| g(s.q, s.v));
    Event::from_function(match how {
        Events::Proven => c.with_enclosure(move |j, _| Some(bound(j))),
        _ => c,
    })
}

fn bouncing_ball(how: Events) -> usize {
    let sys = ParticleSystem::builder(1)
        .body("ball", 1.0)
        .force(UniformGravity::new("gravity", vec![0], 9.81))
        .build()
        .unwrap();
    let mut sim = Simulation::with_stepping(
        &sys,
        Stepping::Fixed {
            method: Method::Rk4,
            dt: 1e-3,
        },
    )
    .t_max(6.0)
    .fuse(how != Events::NoneGeneral);
    if !matches!(how, Events::None | Events::NoneGeneral) {
        sim = sim
            .event(
                event("bounce", how, |q, _| q[0], |j| j.position(0, 0))
                    .direction(Direction::Falling)
                    .set(|_, _, y| y[1] *= -0.9),
            )
            .event(
                event("apex", how, |_, v| v[0], |j| j.velocity(0, 0)).direction(Direction::Falling),
            );
    }
    let r = sim
        .run(State::from_qv(0.0, &[1.0], &[0.0]), &mut [])
        .unwrap();
    r.events.len()
}

fn kepler(how: Events) -> usize {
    let gm = 4.0 * std::f64::consts::PI.powi(2);
    let sys = ParticleSystem::builder(2)
        .body("planet", 1.0)
        .force(NewtonianGravity::fixed_centre(
            "sun",
            vec![0],
            gm,
            vec![0.0, 0.0],
        ))
        .build()
        .unwrap();
    // perihelion 0.5 AU, e = 0.5: a = 1 AU, period 1 year
    let vp = (gm * 3.0).sqrt();
    let config = AdaptiveConfig {
        rtol: Tolerance::Scalar(1e-9),
        atol: Tolerance::Scalar(1e-12),
        ..AdaptiveConfig::default()
    };
    let mut sim = Simulation::with_stepping(
        &sys,
        Stepping::Adaptive {
            method: Method::Dopri5,
            config,
        },
    )
    .t_max(20.0);
    if !matches!(how, Events::None | Events::NoneGeneral) {
        sim = sim.event(
            event(
                "apoapsis",
                how,
                |q, v| q[0] * v[0] + q[1] * v[1],
                |j| j.position(0, 0) * j.velocity(0, 0) + j.position(0, 1) * j.velocity(0, 1),
            )
            .direction(Direction::Falling),
        );
    }
    let r = sim
        .run(State::from_qv(0.0, &[0.5, 0.0], &[0.0, vp]), &mut [])
        .unwrap();
    r.events.len()
}

fn main() {
    if let Ok(only) = std::env::var("EVENTS_PROFILE") {
        for _ in 0..300 {
            black_box(match only.as_str() {
                "ball" => bouncing_ball(Events::Proven),
                _ => kepler(Events::Proven),
            });
        }
        return;
    }
    println!(
        "| run | no events | no events, general loop | proven events | sampled events (7 per step) |"
    );
    println!("|---|---|---|---|---|");
    for (name, run) in [
        (
            "bouncing ball, rk4 dt = 1 ms, 6 s",
            bouncing_ball as fn(Events) -> usize,
        ),
        ("Kepler, dopri5 rtol 1e-9, 20 orbits", kepler),
    ] {
        let (none, _) = median_s(|| run(Events::None));
        let (general, _) = median_s(|| run(Events::NoneGeneral));
        let (proven, n_proven) = median_s(|| run(Events::Proven));
        let (sampled, n_sampled) = median_s(|| run(Events::Sampled));
        assert_eq!(n_proven, n_sampled, "{name}: both find the same events");
        println!(
            "| {name} ({n_proven} events) | {:.3} ms | {:.3} ms ({:.2}×) | {:.3} ms ({:.2}×) | {:.3} ms ({:.2}×) |",
            none * 1e3,
            general * 1e3,
            general / none,
            proven * 1e3,
            proven / none,
            sampled * 1e3,
            sampled / none
        );
    }
}

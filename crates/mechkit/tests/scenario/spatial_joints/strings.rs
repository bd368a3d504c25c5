//! A string that goes slack and taut, and a ball dropped on or launched from the floor.

use super::*;

// ---------------------------------------------------------------------------------------
// 5. A string that goes slack and taut

/// The first time after `t0 > 0` at which `f` changes sign (scanned by `step`, then bisected).
fn first_root(f: impl Fn(f64) -> f64, t0: f64, step: f64) -> f64 {
    let (mut a, mut b) = (t0, t0 + step);
    while f(a).signum() == f(b).signum() {
        (a, b) = (b, b + step);
        assert!(b < 100.0, "no root");
    }
    for _ in 0..200 {
        let c = 0.5 * (a + b);
        if f(c).signum() == f(a).signum() {
            a = c;
        } else {
            b = c;
        }
    }
    0.5 * (a + b)
}

#[test]
fn whirled_ball_slackens_where_the_tension_vanishes_and_flies_until_taut() {
    // at the bottom with v0² = 3.5 g L: the tension m v²/L − m g cos φ (φ from the top)
    // vanishes at the height L/2, where v² = g L/2; it then flies as a projectile
    let l = 0.8_f64;
    for beta in [0.0_f64, 0.7, 2.5] {
        let v0 = (3.5 * G * l).sqrt();
        let text = space(
            &format!(
                r#"
[[body]]
name = "ball"
mass = "0.2 kg"
position = [0, 0, {z}]
velocity = [{vx}, {vy}, 0]
[[joint]]
name = "rope"
kind = "string"
a = "ball"
b = [0, 0, 0]
"#,
                z = -l,
                vx = v0 * beta.cos(),
                vy = v0 * beta.sin(),
            ),
            1e-12,
            1.5,
            "",
        );
        let s = run_text(&text);
        let slack = s
            .events
            .iter()
            .find(|e| e.name == "rope goes slack")
            .unwrap_or_else(|| panic!("{:?}", s.events));
        let p = vec3(&slack.state["ball"].position);
        let u = vec3(&slack.state["ball"].velocity);
        close(p[2], 0.5 * l, 1e-7);
        close(p[0].hypot(p[1]), 0.75_f64.sqrt() * l, 1e-7);
        close(p[0] * beta.sin() - p[1] * beta.cos(), 0.0, 1e-9);
        close(dot(u, u), 0.5 * G * l, 1e-6);
        // t = ∫ L dφ / v(φ), v² = v0² − 2 g L (1 − cos φ), φ from the bottom to 2π/3
        let n = 2000;
        let h = 2.0 * PI / 3.0 / f64::from(n);
        let speed = |phi: f64| (v0 * v0 - 2.0 * G * l * (1.0 - phi.cos())).sqrt();
        let simpson: f64 = (0..=n)
            .map(|k| {
                let w = if k == 0 || k == n {
                    1.0
                } else if k % 2 == 1 {
                    4.0
                } else {
                    2.0
                };
                w * l / speed(f64::from(k) * h)
            })
            .sum::<f64>()
            * h
            / 3.0;
        close(slack.t, simpson, 1e-8);
        // the projectile from there reaches the string's length again
        let distance2 = |t: f64| {
            let q = [
                p[0] + u[0] * t,
                p[1] + u[1] * t,
                p[2] + u[2] * t - 0.5 * G * t * t,
            ];
            dot(q, q) - l * l
        };
        let flight = first_root(distance2, 1e-3, 1e-3);
        let taut = s
            .events
            .iter()
            .find(|e| e.name == "rope goes taut")
            .unwrap_or_else(|| panic!("{:?}", s.events));
        close(taut.t - slack.t, flight, 1e-7);
        let x = vec3(&taut.state["ball"].position);
        close(dot(x, x).sqrt(), l, 1e-8);
        // the jerk takes the radial velocity: ½ m (v·x̂)² is lost
        let v = vec3(&taut.state["ball"].velocity);
        let radial = dot(v, x) / l;
        let after = vec3(&taut.after.as_ref().expect("the state after the jerk")["ball"].velocity);
        close3(&after, [0, 1, 2].map(|k| v[k] - radial * x[k] / l), 1e-8);
        close(s.energy.events_change, -0.5 * 0.2 * radial * radial, 1e-7);
    }
}

#[test]
fn ball_thrown_sideways_on_a_slack_string_jerks_it_taut() {
    // from (a, 0, 0) at (0, v0, 0): a² + v0² t² + g² t⁴/4 = L², a quadratic in t²
    let l = 1.0_f64;
    for (a, v0) in [(0.2_f64, 1.0_f64), (0.5, 3.0), (0.05, 0.2)] {
        let text = space(
            &format!(
                r#"
[[body]]
name = "ball"
mass = "0.2 kg"
position = [{a}, 0, 0]
velocity = [0, {v0}, 0]
[[joint]]
name = "rope"
kind = "string"
a = "ball"
b = [0, 0, 0]
length = "{l} m"
"#
            ),
            1e-12,
            0.8,
            "",
        );
        let s = run_text(&text);
        let taut = s
            .events
            .iter()
            .find(|e| e.name == "rope goes taut")
            .unwrap_or_else(|| panic!("{:?}", s.events));
        let g2 = G * G / 4.0;
        let tt = (-v0 * v0 + (v0.powi(4) + 4.0 * g2 * (l * l - a * a)).sqrt()) / (2.0 * g2);
        close(taut.t, tt.sqrt(), 1e-9);
        // no slack at the start: it was never taut
        assert!(
            s.events
                .iter()
                .all(|e| e.name != "rope goes slack" || e.t > taut.t),
            "{:?}",
            s.events
        );
        let x = vec3(&taut.state["ball"].position);
        close3(&x, [a, v0 * tt.sqrt(), -0.5 * G * tt], 1e-9);
        let v = [0.0, v0, -G * tt.sqrt()];
        let radial = dot(v, x) / l;
        let after = vec3(&taut.after.as_ref().expect("the state after the jerk")["ball"].velocity);
        close3(&after, [0, 1, 2].map(|k| v[k] - radial * x[k] / l), 1e-8);
    }
}

// ---------------------------------------------------------------------------------------
// 6. A ball dropped on the floor

#[test]
fn ball_dropped_on_a_smooth_floor_stops_falling_and_rests() {
    let (m, r) = (0.5_f64, 0.1_f64);
    for (h, vx, spin) in [(1.0_f64, 0.0, [0.0; 3]), (0.3, 0.8, [3.0, -2.0, 5.0])] {
        let text = space(
            &format!(
                r#"
[[rigid_body]]
name = "ball"
mass = "{m} kg"
inertia = "{i} kg m^2"
position = [0, 0, {z}]
velocity = [{vx}, 0, 0]
omega = [{w0}, {w1}, {w2}]
[[joint]]
name = "floor"
kind = "contact"
on = "ball"
radius = "{r} m"
"#,
                i = 0.4 * m * r * r,
                z = r + h,
                w0 = spin[0],
                w1 = spin[1],
                w2 = spin[2],
            ),
            1e-11,
            1.0,
            "n_end = \"final(floor.N)\"\nz_min = \"min(ball.z)\"",
        );
        let s = run_text(&text);
        let touch = s
            .events
            .iter()
            .find(|e| e.name == "floor touches")
            .unwrap_or_else(|| panic!("{:?}", s.events));
        let t_fall = (2.0 * h / G).sqrt();
        close(touch.t, t_fall, 1e-9);
        close(touch.state["ball"].velocity[2], -G * t_fall, 1e-8);
        let after = &touch.after.as_ref().expect("the state after the touch")["ball"];
        close3(&after.velocity, [vx, 0.0, 0.0], 1e-9);
        // it rests on the floor: the smooth floor keeps its sliding and its spin
        let ball = &s.bodies["ball"];
        close3(&ball.velocity, [vx, 0.0, 0.0], 1e-9);
        close3(&ball.position, [vx * 1.0, 0.0, r], 1e-9);
        close3(&ball.spin.unwrap().omega, spin, 1e-9);
        close(s.observables["n_end"], m * G, 1e-8);
        assert!(s.observables["z_min"] > r - 1e-9, "{:?}", s.observables);
        assert_eq!(event_times(&s, "floor lets go"), Vec::<f64>::new());
        // the inelastic touch takes ½ m v² = m g h
        close(s.energy.events_change, -m * G * h, 1e-7);
    }
}

#[test]
fn ball_launched_from_the_floor_leaves_it_and_lands_after_two_v_over_g() {
    for v in [1.0_f64, 3.0] {
        let text = space(
            &format!(
                r#"
[[body]]
name = "ball"
mass = "1 kg"
position = [0, 0, 0]
velocity = [0.5, 0, {v}]
[[joint]]
name = "floor"
kind = "contact"
on = "ball"
"#
            ),
            1e-11,
            2.5 * v / G,
            "",
        );
        let s = run_text(&text);
        // the floor lets go at once (it would have to pull), and catches the ball again
        assert!(s.warnings.is_empty(), "{:?}", s.warnings);
        let touches = event_times(&s, "floor touches");
        assert_eq!(touches.len(), 1, "{:?}", s.events);
        close(touches[0], 2.0 * v / G, 1e-10);
        close3(&s.bodies["ball"].velocity, [0.5, 0.0, 0.0], 1e-9);
    }
}

//! A ball rolling without slipping: down an incline, and on the floor.

use super::*;

// ---------------------------------------------------------------------------------------
// 4. A ball rolling without slipping

/// A ball (solid, `I = 2/5 m R²`) of 2 kg and radius `r` at rest on a plane through the
/// origin tilted by `alpha` towards the azimuth `beta`, rolling (`rolling = true`).
fn ball_on_incline(r: f64, alpha: f64, beta: f64) -> String {
    let n = [
        alpha.sin() * beta.cos(),
        alpha.sin() * beta.sin(),
        alpha.cos(),
    ];
    space(
        &format!(
            r#"
[[rigid_body]]
name = "ball"
mass = "2 kg"
inertia = "{i} kg m^2"
position = [{x}, {y}, {z}]
[[joint]]
name = "slope"
kind = "contact"
on = "ball"
radius = "{r} m"
rolling = true
surface = {{ point = [0, 0, 0], normal = [{n0}, {n1}, {n2}] }}
"#,
            i = 0.4 * 2.0 * r * r,
            x = r * n[0],
            y = r * n[1],
            z = r * n[2],
            n0 = n[0],
            n1 = n[1],
            n2 = n[2],
        ),
        1e-10,
        1.0,
        "f_min = \"min(slope.F)\"\nf_max = \"max(slope.F)\"\nn_mean = \"mean(slope.N)\"\n\
         gap = \"max(abs(slope.drift))\"",
    )
}

#[test]
fn ball_rolls_down_an_incline_at_five_sevenths_g_sin_alpha() {
    let (m, t) = (2.0, 1.0);
    for (r, alpha_deg, beta_deg) in [(0.1, 20.0, 0.0), (0.05, 35.0, 120.0), (0.3, 8.0, -70.0)] {
        let (alpha, beta) = (f64::to_radians(alpha_deg), f64::to_radians(beta_deg));
        let s = run_text(&ball_on_incline(r, alpha, beta));
        let n = [
            alpha.sin() * beta.cos(),
            alpha.sin() * beta.sin(),
            alpha.cos(),
        ];
        // down the slope
        let down = [
            alpha.cos() * beta.cos(),
            alpha.cos() * beta.sin(),
            -alpha.sin(),
        ];
        let a = 5.0 / 7.0 * G * alpha.sin();
        let ball = &s.bodies["ball"];
        close3(&ball.velocity, down.map(|d| a * t * d), 1e-8);
        close3(
            &ball.position,
            [0, 1, 2].map(|k| r * n[k] + 0.5 * a * t * t * down[k]),
            1e-8,
        );
        // rolling: ω = n × v / R
        let omega = ball.spin.unwrap().omega;
        close3(
            &omega,
            cross(n, vec3(&ball.velocity)).map(|w| w / r),
            1e-7 / r,
        );
        let o = &s.observables;
        let friction = 2.0 / 7.0 * m * G * alpha.sin();
        close(o["f_min"], friction, 1e-7);
        close(o["f_max"], friction, 1e-7);
        close(o["n_mean"], m * G * alpha.cos(), 1e-7);
        assert!(o["gap"] < 1e-10, "{o:?}");
        close(s.work["slope"], 0.0, 1e-8);
    }
}

/// A ball of 2 kg and radius 0.1 m on the floor, rolling (`rolling = true`) at `v` with the
/// angular velocity `omega` (world), for 2 s.
fn ball_on_floor(v: [f64; 2], omega: [f64; 3]) -> String {
    let (m, r) = (2.0, 0.1);
    space(
        &format!(
            r#"
[[rigid_body]]
name = "ball"
mass = "{m} kg"
inertia = "{i} kg m^2"
position = [0, 0, {r}]
velocity = [{vx}, {vy}, 0]
omega = [{wx}, {wy}, {wz}]
[[joint]]
name = "floor"
kind = "contact"
on = "ball"
radius = "{r} m"
rolling = true
"#,
            i = 0.4 * m * r * r,
            vx = v[0],
            vy = v[1],
            wx = omega[0],
            wy = omega[1],
            wz = omega[2],
        ),
        1e-11,
        2.0,
        "f_max = \"max(floor.F)\"\nn_min = \"min(floor.N)\"\nn_max = \"max(floor.N)\"",
    )
}

/// Checks that the ball of [`ball_on_floor`] rolled on uniformly: no friction, `N = m g`.
fn rolls_uniformly(v: [f64; 2], omega: [f64; 3]) {
    let (m, r) = (2.0, 0.1);
    let s = run_text(&ball_on_floor(v, omega));
    assert!(s.warnings.is_empty(), "{:?}", s.warnings);
    let ball = &s.bodies["ball"];
    close3(&ball.velocity, [v[0], v[1], 0.0], 1e-8);
    close3(&ball.position, [2.0 * v[0], 2.0 * v[1], r], 1e-8);
    close3(&ball.spin.unwrap().omega, omega, 1e-7);
    let o = &s.observables;
    // a ball rolling uniformly needs no friction (1e-5 m g: the joints' stabilisation)
    assert!(o["f_max"] < 1e-5 * m * G, "{o:?}");
    close(o["n_min"], m * G, 1e-9);
    close(o["n_max"], m * G, 1e-9);
}

#[test]
fn ball_rolling_on_the_floor_keeps_its_velocity() {
    let r = 0.1;
    for v in [[1.0, 0.0], [0.7, -1.3], [-2.0, 0.5]] {
        // the contact point at rest: v + ω × (−R ẑ) = 0
        rolls_uniformly(v, [-v[1] / r, v[0] / r, 0.0]);
    }
    // spinning in place about the vertical, it stays
    rolls_uniformly([0.0, 0.0], [0.0, 0.0, 4.0]);
}

/// A rolling ball that also spins about the vertical rolls on uniformly too (no torque about
/// its centre, `N` through it). The contact point is not a material point of the ball: a
/// rolling row's `J̇ v` that took it for one would add `ω × (ω × (−R n))`, whose tangential
/// part `−R (ω·n)(ω·t)` is a friction `(2/7) m R ωz ω_t` that turns the path.
#[test]
fn ball_rolling_and_spinning_about_the_vertical_keeps_its_velocity() {
    let r = 0.1;
    for (v, wz) in [([1.0, 0.0], 4.0), ([0.7, -1.3], -10.0)] {
        rolls_uniformly(v, [-v[1] / r, v[0] / r, wz]);
    }
}

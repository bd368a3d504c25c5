//! Initial velocities that break a joint, what works in a plane only, and joints that do not
//! hold.

use super::*;

// ---------------------------------------------------------------------------------------
// 7. Initial velocities that break a joint

#[test]
fn radial_velocity_of_a_pendulum_bob_is_projected_away_with_a_warning() {
    let (m, l) = (0.4_f64, 1.2_f64);
    // the bob below the pivot: the rod's direction is z
    for (u, w, radial) in [(0.5_f64, -0.3_f64, 0.8_f64), (0.0, 1.0, -2.0)] {
        let text = space(
            &format!(
                r#"
[[body]]
name = "bob"
mass = "{m} kg"
position = [0, 0, {z}]
velocity = [{u}, {w}, {radial}]
[[joint]]
name = "rod"
kind = "rod"
a = "bob"
b = [0, 0, 0]
"#,
                z = -l
            ),
            1e-10,
            0.1,
            "vx0 = \"initial(bob.vx)\"\nvy0 = \"initial(bob.vy)\"\nvz0 = \"initial(bob.vz)\"",
        );
        let s = run_text(&text);
        assert!(
            s.warnings
                .iter()
                .any(|w| w.contains("break the joint `rod`") && w.contains("projected")),
            "{:?}",
            s.warnings
        );
        let o = &s.observables;
        close(o["vx0"], u, 1e-12);
        close(o["vy0"], w, 1e-12);
        close(o["vz0"], 0.0, 1e-12);
        close(
            s.kinetic_energy.start.unwrap(),
            0.5 * m * (u * u + w * w),
            1e-12,
        );
    }
}

#[test]
fn a_body_spun_on_a_ball_hinge_keeps_its_angular_momentum_about_the_pivot() {
    // the projection is an impulse at the pivot: its moment about the pivot is zero, so the
    // angular momentum about the pivot is kept, and the pivot ends at rest
    let (m, d) = (2.0_f64, 0.25_f64);
    let moments = [0.03_f64, 0.05, 0.07];
    let omega = [1.0_f64, -2.0, 0.5];
    let velocity = [0.3_f64, 0.1, -0.4];
    let text = space(
        &format!(
            r#"
[[rigid_body]]
name = "body"
mass = "{m} kg"
inertia = ["{i0} kg m^2", "{i1} kg m^2", "{i2} kg m^2"]
position = [0, 0, {z}]
velocity = [{v0}, {v1}, {v2}]
omega = [{w0}, {w1}, {w2}]
points = {{ pivot = [0, 0, {d}] }}
[[joint]]
name = "pivot"
kind = "hinge"
a = "body.pivot"
"#,
            i0 = moments[0],
            i1 = moments[1],
            i2 = moments[2],
            z = -d,
            v0 = velocity[0],
            v1 = velocity[1],
            v2 = velocity[2],
            w0 = omega[0],
            w1 = omega[1],
            w2 = omega[2],
        ),
        1e-10,
        0.1,
        &format!(
            "lx = \"initial(body.Lx + {m}*(body.y*body.vz - body.z*body.vy))\"\n\
             ly = \"initial(body.Ly + {m}*(body.z*body.vx - body.x*body.vz))\"\n\
             lz = \"initial(body.Lz + {m}*(body.x*body.vy - body.y*body.vx))\"\n\
             pvx = \"initial(body.pivot.vx)\"\npvy = \"initial(body.pivot.vy)\"\n\
             pvz = \"initial(body.pivot.vz)\""
        ),
    );
    let s = run_text(&text);
    assert!(
        s.warnings.iter().any(|w| w.contains("`pivot`")),
        "{:?}",
        s.warnings
    );
    // before: L = I ω + m r × v with r = (0, 0, −d) from the pivot (the body frame is the world's)
    let r = [0.0, 0.0, -d];
    let before = [0, 1, 2].map(|k| moments[k] * omega[k] + m * cross(r, velocity)[k]);
    let o = &s.observables;
    close3(&[o["lx"], o["ly"], o["lz"]], before, 1e-12);
    close3(&[o["pvx"], o["pvy"], o["pvz"]], [0.0; 3], 1e-12);
}

// ---------------------------------------------------------------------------------------
// 8. What works in a plane only, and joints that do not hold

const BALL: &str = r#"dimensions = 3
[[body]]
name = "ball"
mass = "1 kg"
position = [0, 0, "1 m"]
[[force]]
kind = "uniform-gravity"
g = "9.81 m/s^2"
[integrator]
method = "rk4"
dt = "1 ms"
[stop]
t_max = "1 s"
"#;

/// The line of the `k`th line (from 1) of a joint appended to [`BALL`].
fn joint_line(k: usize) -> usize {
    BALL.lines().count() + k
}

#[test]
fn pulley_and_curve_work_in_a_plane_only() {
    for (kind, keys) in [
        (
            "pulley",
            "a = \"ball\"\nb = [0, 0, 0]\ncentre = [0, 0, \"2 m\"]",
        ),
        ("curve", "on = \"ball\"\ny = \"x^2\""),
    ] {
        let e = error(&format!(
            "{BALL}[[joint]]\nname = \"j\"\nkind = \"{kind}\"\n{keys}\n"
        ));
        assert!(
            e.message
                .contains(&format!("a {kind} joint works in a plane")),
            "{e}"
        );
        // at `kind`
        assert_eq!(line(&e), joint_line(3), "{e}");
    }
}

#[test]
fn sliding_friction_and_a_surface_angle_are_refused_in_space() {
    for (key, text) in [("mu", "mu = 0.3"), ("mu_k", "mu_k = 0.2")] {
        let e = error(&format!(
            "{BALL}[[joint]]\nname = \"floor\"\nkind = \"contact\"\non = \"ball\"\n{text}\n"
        ));
        assert!(e.message.contains("sliding friction"), "{key}: {e}");
        assert!(e.message.contains("in space"), "{e}");
        assert_eq!(line(&e), joint_line(5), "{e}");
        assert!(
            e.hint.as_deref().unwrap_or("").contains("rolling = true"),
            "{e:?}"
        );
    }
    let e = error(&format!(
        "{BALL}[[joint]]\nname = \"floor\"\nkind = \"contact\"\non = \"ball\"\n\
         surface = {{ point = [0, 0, 0], angle = \"10 deg\" }}\n"
    ));
    assert!(
        e.message.contains("give its `normal`, not an `angle`"),
        "{e}"
    );
    assert_eq!(line(&e), joint_line(5), "{e}");
}

#[test]
fn a_joint_that_does_not_hold_at_the_start_is_an_error() {
    // a ball hinge between the ball and a point a metre off
    let e = error(&format!(
        "{BALL}[[joint]]\nname = \"pin\"\nkind = \"hinge\"\na = \"ball\"\nb = [\"1 m\", 0, \"1 m\"]\n"
    ));
    assert!(
        e.message
            .contains("the joint `pin` does not hold at the start"),
        "{e}"
    );
    assert!(
        e.message.contains("off by 1 m") || e.message.contains("off by -1 m"),
        "{e}"
    );
    assert_eq!(line(&e), joint_line(1), "{e}");
    // a ball under its floor
    let e = error(&format!(
        "{BALL}[[joint]]\nname = \"floor\"\nkind = \"contact\"\non = \"ball\"\nradius = \"1.5 m\"\n"
    ));
    assert!(
        e.message
            .contains("the joint `floor` does not hold at the start"),
        "{e}"
    );
}

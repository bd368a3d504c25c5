//! The conical pendulum, and the physical pendulum on a ball hinge in space and in a plane.

use super::*;

// ---------------------------------------------------------------------------------------
// 1. The conical pendulum

/// A bob of 0.3 kg held by a `kind` joint of length `l` from the origin, started on the
/// horizontal circle at angle `alpha` from the downward vertical with the speed that keeps it
/// there: `v² = g L sin α tan α`.
fn conical(kind: &str, l: f64, alpha: f64, t_max: f64) -> String {
    let (s, c) = alpha.sin_cos();
    let v = (G * l * s * alpha.tan()).sqrt();
    space(
        &format!(
            r#"
[[body]]
name = "bob"
mass = "0.3 kg"
position = [{x}, 0, {z}]
velocity = [0, {v}, 0]
[[joint]]
name = "tie"
kind = "{kind}"
a = "bob"
b = [0, 0, 0]
length = "{l} m"
[[event]]
name = "round"
function = "bob.x"
direction = "falling"
"#,
            x = l * s,
            z = -l * c,
        ),
        1e-10,
        t_max,
        "height = \"max(bob.z) - min(bob.z)\"\nn_min = \"min(tie.N)\"\nn_max = \"max(tie.N)\"\n\
         drift = \"max(abs(tie.drift))\"",
    )
}

#[test]
fn conical_pendulum_keeps_its_height_period_and_tension() {
    for (kind, cases) in [
        ("rod", [(1.0, 30.0), (0.4, 60.0)]),
        ("string", [(2.5, 10.0), (0.7, 45.0)]),
    ] {
        for (l, alpha_deg) in cases {
            let alpha = f64::to_radians(alpha_deg);
            // Ω² = g/(L cos α): period 2π √(L cos α / g); tension m g / cos α
            let period = 2.0 * PI * (l * alpha.cos() / G).sqrt();
            let s = run_text(&conical(kind, l, alpha, 5.5 * period));
            let o = &s.observables;
            assert!(o["height"] < 1e-9 * l, "{kind} {l} {alpha_deg}: {o:?}");
            assert!(o["drift"] < 1e-9 * l, "{o:?}");
            close(mean_period(&s, "round"), period, 1e-8 * period);
            let tension = 0.3 * G / alpha.cos();
            close(o["n_min"], tension, 1e-7 * tension);
            close(o["n_max"], tension, 1e-7 * tension);
            close(s.work["tie"], 0.0, 1e-9);
            // the string never slackens
            assert!(
                event_times(&s, "tie goes slack").is_empty(),
                "{:?}",
                s.events
            );
            let end = &s.bodies["bob"];
            close(end.position[2], -l * alpha.cos(), 1e-9 * l);
        }
    }
}

#[test]
fn conical_pendulum_example_goes_round_in_its_period() {
    let path = workspace().join("examples/rigid/conical_pendulum.toml");
    for set in ["L = 1 m, tilt = 30 deg", "L = 0.5 m, tilt = 70 deg"] {
        let s = Scenario::load_with(&path, &ConstantOverride::parse_list(set).unwrap())
            .unwrap_or_else(|e| panic!("{e}"))
            .run()
            .unwrap()
            .summary;
        let o = &s.observables;
        let expected = o["expected_period"];
        close(o["period"], expected, 1e-9 * expected);
        close(
            o["tension"],
            o["expected_tension"],
            1e-7 * o["expected_tension"],
        );
        assert!(o["height_change"] < 1e-9, "{set}: {o:?}");
        close(o["rod_work"], 0.0, 1e-9);
        assert_eq!(s.stop_reason, "event");
    }
}

// ---------------------------------------------------------------------------------------
// 2. The physical pendulum on a ball hinge, in space and in a plane

/// The period of a physical pendulum of `ω₀² = m g d / (I + m d²)` swinging to `theta0`:
/// `4 K(sin²(θ₀/2)) / ω₀`.
fn physical_period(inertia: f64, m: f64, d: f64, theta0: f64) -> f64 {
    let w0 = (m * G * d / (inertia + m * d * d)).sqrt();
    4.0 * complete_k((0.5 * theta0).sin().powi(2)) / w0
}

/// A body of mass `m` and principal moments `moments` hung from its point `pivot` at `d`
/// above its centre of mass, turned about the world axis `axis` (x or y) by `theta0` and
/// released: it swings in the plane normal to `axis`.
fn pendulum3(moments: [f64; 3], m: f64, d: f64, axis: [f64; 3], theta0: f64) -> String {
    let turn = UnitQuaternion::from_axis_angle(&Unit::new_normalize(Vector3::from(axis)), theta0);
    let cm = -(turn * Vector3::new(0.0, 0.0, d));
    // six rising crossings of the centre over the pivot (the first within 3/4 of a period)
    let swing = dot(moments, axis.map(f64::abs));
    let t = 6.0 * physical_period(swing, m, d, theta0);
    space(
        &format!(
            r#"
[[rigid_body]]
name = "pend"
mass = "{m} kg"
inertia = ["{i1} kg m^2", "{i2} kg m^2", "{i3} kg m^2"]
orientation = {{ axis = [{a0}, {a1}, {a2}], angle = {theta0} }}
position = [{x}, {y}, {z}]
points = {{ pivot = [0, 0, "{d} m"] }}
[[joint]]
name = "ball"
kind = "hinge"
a = "pend.pivot"
[[event]]
name = "turn"
function = "pend.x + pend.y"
direction = "rising"
"#,
            i1 = moments[0],
            i2 = moments[1],
            i3 = moments[2],
            a0 = axis[0],
            a1 = axis[1],
            a2 = axis[2],
            x = cm.x,
            y = cm.y,
            z = cm.z,
        ),
        1e-11,
        t,
        "drift = \"max(ball.drift)\"\n\
         off_plane = \"max(abs(pend.x*pend.y))\"",
    )
}

/// The same pendulum in a plane (`y` up): moment `inertia` about the centre of mass.
fn pendulum2(inertia: f64, m: f64, d: f64, theta0: f64) -> String {
    let t = 6.0 * physical_period(inertia, m, d, theta0);
    format!(
        r#"
dimensions = 2
stabilisation = "0.1 s"
[[rigid_body]]
name = "pend"
mass = "{m} kg"
inertia = "{inertia} kg m^2"
theta = {theta0}
position = [{x}, {y}]
points = {{ pivot = [0, "{d} m"] }}
[[force]]
kind = "uniform-gravity"
g = "{G} m/s^2"
[[joint]]
name = "pin"
kind = "hinge"
a = "pend.pivot"
[[event]]
name = "turn"
function = "pend.x"
direction = "rising"
[integrator]
method = "dop853"
rtol = 1e-11
atol = 1e-13
[stop]
t_max = "{t} s"
"#,
        x = d * theta0.sin(),
        y = -d * theta0.cos(),
    )
}

#[test]
fn physical_pendulum_on_a_ball_hinge_has_the_planar_period() {
    let (m, d) = (1.5, 0.3);
    let moments = [0.02, 0.05, 0.04];
    // turned about x it swings about x, with I₁; about y, with I₂
    for (axis, inertia, theta0) in [
        ([1.0, 0.0, 0.0], moments[0], 0.6_f64),
        ([0.0, 1.0, 0.0], moments[1], 0.05),
    ] {
        let expected = physical_period(inertia, m, d, theta0);
        let s = run_text(&pendulum3(moments, m, d, axis, theta0));
        let period3 = mean_period(&s, "turn");
        close(period3, expected, 1e-8 * expected);
        assert!(s.observables["drift"] < 1e-10, "{:?}", s.observables);
        // it stays in its plane: one of x, y is zero throughout
        assert!(s.observables["off_plane"] < 1e-12, "{:?}", s.observables);
        close(s.work["ball"], 0.0, 1e-9);
        // the same pendulum through the planar path
        let s2 = run_text(&pendulum2(inertia, m, d, theta0));
        let period2 = mean_period(&s2, "turn");
        close(period3, period2, 1e-9 * expected);
    }
}

/// A pendulum on a hinge whose `axis` is tilted by `beta` from the horizontal: it swings in the
/// plane normal to the axis under the gravity across it, `g cos β`, with the period of a
/// physical pendulum there; it never leaves that plane, and the hinge does no work.
fn tilted_hinge(beta: f64, theta0: f64, omega: [f64; 3]) -> (String, f64) {
    let (m, d, inertia) = (0.8, 0.25, 0.01);
    let u = Vector3::new(beta.cos(), 0.0, beta.sin());
    // at rest the centre hangs across the axis, below the pivot: R_y(−β) puts the body axis
    // (from the centre to the pivot) at (−sin β, 0, cos β); then the swing turns it about u
    let hang = UnitQuaternion::from_axis_angle(&Vector3::y_axis(), -beta);
    let q = UnitQuaternion::from_axis_angle(&Unit::new_normalize(u), theta0) * hang;
    let cm = -(q * Vector3::new(0.0, 0.0, d));
    let w0 = (m * G * beta.cos() * d / (inertia + m * d * d)).sqrt();
    let period = 4.0 * complete_k((0.5 * theta0).sin().powi(2)) / w0;
    let c = q.quaternion();
    let text = space(
        &format!(
            r#"
[[rigid_body]]
name = "door"
mass = "{m} kg"
inertia = "{inertia} kg m^2"
orientation = [{w}, {i}, {j}, {k}]
position = [{x}, {y}, {z}]
omega = [{o0}, {o1}, {o2}]
points = {{ pin = [0, 0, "{d} m"] }}
[[joint]]
name = "hinge"
kind = "hinge"
a = "door.pin"
axis = [{u0}, 0, {u2}]
[[event]]
name = "turn"
function = "door.wx*{u0} + door.wz*{u2}"
direction = "falling"
"#,
            w = c.w,
            i = c.i,
            j = c.j,
            k = c.k,
            x = cm.x,
            y = cm.y,
            z = cm.z,
            o0 = omega[0],
            o1 = omega[1],
            o2 = omega[2],
            u0 = u.x,
            u2 = u.z,
        ),
        1e-11,
        7.5 * period,
        &format!(
            "across = \"max(abs(door.wx*{s} - door.wz*{c}) + abs(door.wy))\"\n\
             drift = \"max(hinge.drift)\"",
            s = beta.sin(),
            c = beta.cos()
        ),
    );
    (text, period)
}

#[test]
fn a_hinge_with_an_axis_swings_only_about_it() {
    for (beta, theta0) in [(0.0, 0.4), (0.5, 0.2), (1.1, 0.7)] {
        let (text, period) = tilted_hinge(beta, theta0, [0.0; 3]);
        let s = run_text(&text);
        close(mean_period(&s, "turn"), period, 1e-8 * period);
        let o = &s.observables;
        // the angular velocity stays along the axis
        assert!(o["across"] < 1e-9, "beta {beta}: {o:?}");
        assert!(o["drift"] < 1e-10, "beta {beta}: {o:?}");
        close(s.work["hinge"], 0.0, 1e-9);
        assert!(s.warnings.is_empty(), "{:?}", s.warnings);
    }
}

#[test]
fn a_spin_across_a_hinge_axis_is_projected_away() {
    // at rest at the bottom, spun about a direction across the axis: the hinge allows none of
    // it, so the projection leaves the body at rest, with a warning naming the hinge
    let beta = 0.3;
    let (text, _) = tilted_hinge(beta, 0.0, [-beta.sin(), 0.0, beta.cos()]);
    let s = run_text(&text);
    assert!(
        s.warnings.iter().any(|w| w.contains("`hinge`")),
        "{:?}",
        s.warnings
    );
    assert!(s.observables["across"] < 1e-10, "{:?}", s.observables);
    let spin = s.bodies["door"].spin.as_ref().unwrap();
    for w in spin.omega {
        assert!(w.abs() < 1e-10, "{:?}", spin.omega);
    }
}

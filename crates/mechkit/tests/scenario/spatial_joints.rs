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

// ---------------------------------------------------------------------------------------
// 3. The heavy top

const TOP: &str = "rigid/heavy_top.toml";

fn run_top(set: &str) -> Summary {
    let path = workspace().join("examples").join(TOP);
    Scenario::load_with(&path, &ConstantOverride::parse_list(set).unwrap())
        .unwrap_or_else(|e| panic!("{e}"))
        .run()
        .unwrap()
        .summary
}

#[test]
fn heavy_top_precesses_steadily_at_the_slow_root() {
    for (w3, tilt) in [(150.0, 30.0_f64.to_radians()), (200.0, 0.3), (400.0, 1.2)] {
        let s = run_top(&format!("w3 = {w3}, tilt = {tilt}"));
        let o = &s.observables;
        let w = o["W"];
        // the slow root, near the fast-top approximation m g l / (I3 ω3)
        let (m, l, i1, i3) = (0.5, 0.04, 2e-4, 3e-4);
        let a = (i1 + m * l * l - i3) * tilt.cos();
        let slow = (i3 * w3 - ((i3 * w3).powi(2) - 4.0 * a * m * G * l).sqrt()) / (2.0 * a);
        close(w, slow, 1e-12 * slow);
        close(o["precession"], w, 1e-6 * w);
        assert!(o["nutation"] < 1e-9, "{w3} {tilt}: {o:?}");
        assert!(o["drift"] < 1e-9, "{o:?}");
        close(o["pivot_work"], 0.0, 1e-9);
        close(s.work["pivot"], 0.0, 1e-9);
    }
}

/// The example's top released with its spin alone (no precession): it nods down to the
/// other root of the turning points and precesses on average.
fn top_released(w3: f64, tilt: f64) -> String {
    let text = std::fs::read_to_string(workspace().join("examples").join(TOP)).unwrap();
    let from_v = "velocity = [\"W*l*sin(tilt)\", 0, 0]";
    let from_w = "\"w3*cos(tilt) + W\"";
    assert!(text.contains(from_v) && text.contains(from_w));
    text.replace(from_v, "velocity = [0, 0, 0]")
        .replace(from_w, "\"w3*cos(tilt)\"")
        .replace("w3 = \"150 rad/s\"", &format!("w3 = \"{w3} rad/s\""))
        .replace("tilt = \"30 deg\"", &format!("tilt = {tilt}"))
        + "z_min = \"min(top.z)\"\nenergy_error = \"max(E) - min(E)\"\n\
           [[event]]\nname = \"bottom\"\nfunction = \"top.vz\"\ndirection = \"rising\"\n"
}

#[test]
fn heavy_top_released_without_precession_nods_to_the_closed_form_bottom() {
    let (m, l, i1, i3) = (0.5_f64, 0.04_f64, 2e-4_f64, 3e-4_f64);
    for (w3, tilt) in [(150.0_f64, 0.5_f64), (100.0, 0.3), (300.0, 1.0)] {
        let s = run_text(&top_released(w3, tilt));
        // turning points from E, L_z and L_3: with u = cos θ, L3 = I3 ω3, J = I1 + m l²,
        // (u0 − u) L3² = 2 J m g l (1 − u²); the start u0 is one root, the bottom the other
        let (j, l3, u0) = (i1 + m * l * l, i3 * w3, tilt.cos());
        let beta = 2.0 * j * m * G * l / (l3 * l3);
        let u1 = (1.0 - (1.0 - 4.0 * beta * (u0 - beta)).sqrt()) / (2.0 * beta);
        let bottoms = s
            .events
            .iter()
            .filter(|e| e.name == "bottom")
            .collect::<Vec<_>>();
        assert!(!bottoms.is_empty(), "{:?}", s.events);
        for b in &bottoms {
            close(b.state["top"].position[2], l * u1, 1e-9 * l);
        }
        close(s.observables["z_min"], l * u1, 1e-6 * l);
        assert!(s.observables["energy_error"] < 1e-10, "{:?}", s.observables);
        close(s.work["pivot"], 0.0, 1e-9);

        // the library's own heavy top, from the same start, at t = 0.5 s
        let top = SpinningBody::on_pivot(
            FreeBody::new([i1, i1, i3], m).unwrap(),
            Vec3::new(0.0, 0.0, l),
            G,
        )
        .unwrap();
        let turn = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), tilt);
        let start = top.attitude(turn, Vec3::new(0.0, 0.0, w3)).unwrap();
        let spin = top.simulate(&start, 0.5, &SpinOptions::default()).unwrap();
        let cm = spin.end.q * Vec3::new(0.0, 0.0, l);
        close3(&s.bodies["top"].position, [cm.x, cm.y, cm.z], 1e-8 * l);
        let omega = top.omega_world(&spin.end);
        let got = s.bodies["top"].spin.unwrap().omega;
        close3(&got, [omega.x, omega.y, omega.z], 1e-7 * w3);
    }
}

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

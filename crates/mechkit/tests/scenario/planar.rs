//! Planar mechanisms (issue 23): free rigid bodies, joints, contacts with friction, pulleys,
//! strings, checked against closed forms through the scenario files.

use mechkit::scenario::sweep::ConstantOverride;
use mechkit::scenario::{Scenario, Summary};

use crate::util::workspace;

fn run(example: &str, set: &str) -> Summary {
    let path = workspace().join("examples").join(example);
    let overrides = if set.is_empty() {
        Vec::new()
    } else {
        ConstantOverride::parse_list(set).unwrap()
    };
    Scenario::load_with(&path, &overrides)
        .unwrap()
        .run()
        .unwrap()
        .summary
}

fn run_text(text: &str) -> Summary {
    Scenario::from_str("test.toml", text)
        .unwrap()
        .run()
        .unwrap()
        .summary
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

#[test]
fn ladder_leaves_the_wall_at_two_thirds_of_its_height() {
    for (l, theta0) in [(4.0, 20.0), (2.5, 35.0), (6.0, 5.0)] {
        let s = run(
            "rigid/ladder.toml",
            &format!("L = {l} m, theta0 = {theta0} deg"),
        );
        let expected = 2.0 / 3.0 * l * f64::to_radians(theta0).cos();
        close(s.observables["h_leave"], expected, 1e-7 * l);
        // the smooth floor and wall do no work; gravity's work is the kinetic energy
        close(s.work["wall"], 0.0, 1e-6);
        close(s.work["floor"], 0.0, 1e-6);
        assert!(s.observables["energy_error"] < 1e-9);
        assert_eq!(s.stop_reason, "event");
    }
}

#[test]
fn cylinder_rolls_while_friction_holds_and_slides_beyond() {
    let g = 9.81_f64;
    for slope in [10.0_f64, 30.0, 50.0] {
        let th = slope.to_radians();
        // rolling needs mu_s >= tan(slope)/3
        let s = run(
            "rigid/rolling_incline.toml",
            &format!("slope = {slope} deg, mu = {}", th.tan() / 3.0 * 1.5),
        );
        close(s.observables["a_cm"], 2.0 / 3.0 * g * th.sin(), 1e-7);
        close(s.observables["slip_speed"], 0.0, 1e-7);
        // too little friction: it slides, with a = g (sin - mu cos)
        let mu = th.tan() / 3.0 * 0.5;
        let s = run(
            "rigid/rolling_incline.toml",
            &format!("slope = {slope} deg, mu = {mu}"),
        );
        close(s.observables["a_cm"], g * (th.sin() - mu * th.cos()), 1e-7);
        assert!(s.observables["slip_speed"] > 0.1);
        // sliding friction turns energy into heat: its work is negative
        assert!(s.work["slope"] < 0.0);
    }
}

#[test]
fn static_friction_holds_up_to_tan_slope_equal_mu_s() {
    let (mu_s, mu_k, g) = (0.5_f64, 0.3_f64, 9.81);
    let critical = mu_s.atan().to_degrees();
    for slope in [
        critical - 0.5,
        critical - 1e-3,
        critical + 1e-3,
        critical + 2.0,
    ] {
        let s = run(
            "friction/incline.toml",
            &format!("slope = {slope} deg, mu_s = {mu_s}, mu_k = {mu_k}"),
        );
        let th = slope.to_radians();
        let expected = if th.tan() <= mu_s {
            0.0
        } else {
            g * (th.sin() - mu_k * th.cos()) * 2.0
        };
        close(s.observables["distance"], expected, 1e-8);
        close(s.observables["normal"], g * th.cos(), 1e-7);
        if expected > 0.0 {
            // kinetic friction's work: -mu_k N d
            close(s.work["incline"], -mu_k * g * th.cos() * expected, 1e-7);
        } else {
            close(s.observables["friction"], -g * th.sin(), 1e-7);
        }
    }
}

#[test]
fn double_pendulum_conserves_energy_and_its_rods_do_no_work() {
    for (t1, t2) in [(90.0, 90.0), (120.0, -30.0), (10.0, 20.0)] {
        let s = run(
            "rigid/double_pendulum.toml",
            &format!("theta1 = {t1} deg, theta2 = {t2} deg"),
        );
        assert!(s.observables["energy_error"] < 1e-8, "{t1}, {t2}");
        close(s.work["rod1"], 0.0, 1e-7);
        close(s.work["rod2"], 0.0, 1e-7);
    }
}

#[test]
fn double_pendulum_small_oscillations_have_the_normal_mode_frequencies() {
    // equal masses and lengths: ω² = (g/L)(2 ∓ √2); in mode k, θ₂ = ±√2 θ₁
    let (g, l) = (9.81_f64, 1.0_f64);
    let r2 = 2.0_f64.sqrt();
    for (sign, w2) in [(1.0, 2.0 - r2), (-1.0, 2.0 + r2)] {
        let th1 = 1e-3_f64;
        let text = std::fs::read_to_string(workspace().join("examples/rigid/double_pendulum.toml"))
            .unwrap()
            .replace("t_max = \"10 s\"", "t_max = \"20 s\"")
            + "\n[[event]]\nname = \"turn\"\nfunction = \"bob1.vx\"\ndirection = \"falling\"\n";
        let set = format!("theta1 = {th1}, theta2 = {}", sign * r2 * th1);
        let s = Scenario::from_str_with(
            "double_pendulum.toml",
            &text,
            &ConstantOverride::parse_list(&set).unwrap(),
        )
        .unwrap()
        .run()
        .unwrap()
        .summary;
        let period = mean_period(&s, "turn");
        let expected = 2.0 * std::f64::consts::PI / (w2 * g / l).sqrt();
        close(period, expected, 1e-5 * expected);
    }
}

#[test]
fn atwood_machine_with_a_massive_pulley() {
    let g = 9.81;
    for (m1, m2, big_m) in [(1.0, 1.5, 0.8), (2.0, 0.5, 3.0), (1.0, 1.0, 1.0)] {
        let s = run(
            "rigid/atwood.toml",
            &format!("m1 = {m1} kg, m2 = {m2} kg, M = {big_m} kg"),
        );
        let a = (m2 - m1) * g / (m1 + m2 + big_m / 2.0);
        close(s.observables["a2"], a, 1e-8);
        close(s.observables["tension1"], m1 * (g + a), 1e-7);
        close(s.work["string"], 0.0, 1e-7);
        close(s.work["axle"], 0.0, 1e-7);
    }
}

const WHIRL: &str = r#"
dimensions = 2
[constants]
L = "1 m"
g = "9.81 m/s^2"
[[body]]
name = "ball"
mass = "0.2 kg"
position = ["0 m", "-L"]
velocity = ["sqrt(3.5*g*L)", "0 m/s"]
[[force]]
kind = "uniform-gravity"
g = "g"
[[joint]]
name = "rope"
kind = "string"
a = "ball"
b = ["0 m", "0 m"]
[integrator]
method = "dop853"
rtol = 1e-11
atol = 1e-12
[stop]
t_max = "3 s"
"#;

#[test]
fn string_goes_slack_where_the_tension_vanishes_and_taut_again() {
    // v0² = 3.5 g L: the tension m v²/L + m g cos θ vanishes at cos θ = -1/2, height L/2
    let s = run_text(WHIRL);
    let slack: Vec<_> = s
        .events
        .iter()
        .filter(|e| e.name == "rope goes slack")
        .collect();
    assert!(!slack.is_empty(), "{:?}", s.events);
    let ball = &slack[0].state["ball"];
    close(ball.position[1], 0.5, 1e-6);
    close(ball.position[0], 0.75_f64.sqrt(), 1e-6);
    // it then flies free and the string jerks taut again, losing energy to the jerk
    let taut = s
        .events
        .iter()
        .find(|e| e.name == "rope goes taut")
        .expect("the string goes taut again");
    assert!(taut.t > slack[0].t);
    let x = &taut.state["ball"].position;
    close(x[0].hypot(x[1]), 1.0, 1e-6);
}

#[test]
fn rocket_speed_and_height_at_burnout_are_tsiolkovskys() {
    let g = 9.81_f64;
    for (m0, m1, rate, u) in [
        (1000.0_f64, 300.0_f64, 10.0_f64, 2500.0_f64),
        (50.0, 20.0, 1.5, 800.0),
    ] {
        let s = run(
            "rocket.toml",
            &format!("m0 = {m0} kg, m1 = {m1} kg, mass_rate = {rate} kg/s, u = {u} m/s"),
        );
        let tb = (m0 - m1) / rate;
        let v = u * (m0 / m1).ln() - g * tb;
        let x = u * tb - u * m1 / rate * (m0 / m1).ln() - g * tb * tb / 2.0;
        close(s.observables["t_burnout"], tb, 1e-9 * tb);
        close(s.observables["v_burnout"], v, 1e-8 * v);
        close(s.observables["h_burnout"], x, 1e-8 * x);
        // the exhaust carries away ½ ṁ v² per second: the ledger closes
        close(
            s.work_energy_residual,
            0.0,
            1e-9 * s.kinetic_energy.end.unwrap_or(1.0),
        );
    }
}

#[test]
fn rocket_coasts_after_burnout() {
    let text = std::fs::read_to_string(workspace().join("examples/rocket.toml"))
        .unwrap()
        .replace("action = \"stop\"", "")
        .replace("t_max = \"1000 s\"", "t_max = \"100 s\"");
    let s = run_text(&text);
    let (m0, m1, rate, u, g) = (1000.0_f64, 300.0, 10.0, 2500.0, 9.81);
    let tb = (m0 - m1) / rate;
    let vb = u * (m0 / m1).ln() - g * tb;
    close(
        s.bodies["rocket"].velocity[0],
        vb - g * (100.0 - tb),
        1e-7 * vb,
    );
    assert_eq!(
        s.events
            .iter()
            .filter(|e| e.name == "rocket burnout")
            .count(),
        1
    );
}

const BEAD: &str = r#"
dimensions = 2
[constants]
k = "0.5 1/m"
g = "9.81 m/s^2"
x0 = "0.01 m"
[[body]]
name = "bead"
mass = "0.1 kg"
position = ["x0", "k*x0^2"]
[[force]]
kind = "uniform-gravity"
g = "g"
[[joint]]
name = "wire"
kind = "curve"
on = "bead"
y = "k*x^2"
[integrator]
method = "dop853"
rtol = 1e-11
atol = 1e-13
[stop]
t_max = "20 s"
[[event]]
name = "turn"
function = "bead.vx"
direction = "falling"
[observe]
energy_error = "max(E) - min(E)"
off_wire = "max(abs(wire.drift))"
"#;

#[test]
fn bead_on_a_parabola_oscillates_at_sqrt_2kg() {
    // y = k x²: small oscillations have ω² = 2 k g
    let s = run_text(BEAD);
    let period = mean_period(&s, "turn");
    let expected = 2.0 * std::f64::consts::PI / (2.0_f64 * 0.5 * 9.81).sqrt();
    // the amplitude is 1 cm: the nonlinearity shifts the period by ~ (k x0)² relative
    close(period, expected, 1e-4 * expected);
    assert!(s.observables["energy_error"] < 1e-10);
    assert!(s.observables["off_wire"] < 1e-10);
    close(s.work["wire"], 0.0, 1e-10);
}

const PUSHED_ROD: &str = r#"
dimensions = 2
[constants]
L = "2 m"
m = "3 kg"
F0 = "5 N"
[[rigid_body]]
name = "rod"
mass = "m"
inertia = "m*L^2/12"
points = { tip = ["L/2", "0 m"] }
[[force]]
name = "push"
kind = "constant"
F = ["0 N", "F0"]
at = "rod.tip"
[[joint]]
name = "axle"
kind = "hinge"
a = "rod"
[integrator]
method = "dop853"
rtol = 1e-11
atol = 1e-12
[stop]
t_max = "0.7 s"
[observe]
omega2_error = "final(rod.omega^2 - F0*L*sin(rod.theta)/(m*L^2/12))"
tip_y = "final(rod.tip.y)"
"#;

#[test]
fn a_force_at_a_body_point_turns_the_body_by_its_torque() {
    // hinged at its centre, pushed up at the tip: I ω²/2 = F0 (L/2) sin θ = F0 · tip.y
    let s = run_text(PUSHED_ROD);
    assert!(
        s.observables["omega2_error"].abs() < 1e-8,
        "{:?}",
        s.observables
    );
    close(s.work["push"], 5.0 * s.observables["tip_y"], 1e-9);
    assert!(s.bodies["rod"].rotation.unwrap().theta > 0.5);
    close(s.work["axle"], 0.0, 1e-9);
}

#[test]
fn block_on_a_pulled_cart_rides_along_or_slides_back() {
    let (m, big_m, mu_s, mu_k, g) = (1.0_f64, 4.0_f64, 0.4_f64, 0.3_f64, 9.81_f64);
    let limit = mu_s * g * (m + big_m);
    for f in [0.5 * limit, 0.999 * limit, 1.001 * limit, 2.0 * limit] {
        let s = run("friction/block_on_cart.toml", &format!("F = {f} N"));
        let (ab, ac) = if f <= limit {
            (f / (m + big_m), f / (m + big_m))
        } else {
            (mu_k * g, (f - mu_k * m * g) / big_m)
        };
        close(s.observables["a_block"], ab, 1e-7);
        close(s.observables["a_cart"], ac, 1e-7);
        close(s.observables["slid"], 0.5 * (ac - ab), 1e-7);
        // friction between the two is internal: the momentum changes only by the pull
        close(s.momentum.end[0], f * 1.0, 1e-6 * f);
    }
}

#[test]
fn book_rod_hits_block_as_a_scenario() {
    // c16-B6: ω0 = 5.42494 rad/s, perfectly inelastic v = ω0 L/(1 + 3m/M) = 2.71247 m/s
    let s = run("book/c16-B6-rod-hits-block.toml", "");
    let omega0 = (3.0_f64 * 9.81).sqrt();
    close(s.observables["omega0"], omega0, 1e-8);
    close(s.observables["v_inelastic"], omega0 / 2.0, 1e-8);
    assert_eq!(s.stop_reason, "event");
}

#[test]
fn a_rockets_mass_and_kinetic_energy_are_the_current_ones() {
    let text = std::fs::read_to_string(workspace().join("examples/rocket.toml")).unwrap()
        + "k_end = \"final(rocket.K)\"\nm_end = \"final(rocket.m)\"\n";
    let s = run_text(&text);
    let v = s.observables["v_burnout"];
    close(s.observables["m_end"], 300.0, 1e-9);
    close(s.observables["k_end"], 0.5 * 300.0 * v * v, 1e-6);
    close(s.bodies["rocket"].mass, 300.0, 1e-9);
}

/// An Atwood machine whose light mass is drawn up to the pulley (a review by an instructor): the
/// ideal string once carried it over the wheel and flung it off, the string doing +1612 J of
/// work, with exit 0. The run now ends when an end reaches the rim: m1 (1 kg), 0.5 m below it,
/// against m2 (3 kg) rises at g/2 and arrives at t = √(2 · 0.5 m / (g/2)).
#[test]
fn a_string_end_drawn_up_to_the_pulley_ends_the_run_at_the_rim() {
    let text = r#"
dimensions = 2
[[body]]
name = "m1"
mass = "1 kg"
position = ["-0.2 m", "-0.5 m"]
[[body]]
name = "m2"
mass = "3 kg"
position = ["0.2 m", "-0.5 m"]
[[force]]
name = "gravity"
kind = "uniform-gravity"
g = "9.81 m/s^2"
[[joint]]
name = "string"
kind = "pulley"
a = "m1"
b = "m2"
centre = ["0 m", "0 m"]
radius = "0.2 m"
[integrator]
method = "dopri5"
rtol = 1e-10
atol = 1e-12
[stop]
t_max = "1 s"
"#;
    let s = run_text(text);
    let arrival = (2.0 * 0.5 / (9.81 / 2.0_f64)).sqrt();
    assert_eq!(s.events.len(), 1, "{:?}", s.events);
    assert_eq!(s.events[0].name, "string end a reaches the rim");
    assert!(
        (s.events[0].t - arrival).abs() < 1e-8,
        "{} vs {arrival}",
        s.events[0].t
    );
    assert!((s.t_end - arrival).abs() < 1e-8);
    // energy is kept up to there: the string does no work
    assert!((s.energy.end - s.energy.start).abs() < 1e-6);
    // a pulley whose ends never reach it runs to t_max
    let far = text.replace("\"-0.5 m\"]\n[[body]]", "\"-3 m\"]\n[[body]]");
    assert!(run_text(&far).events.is_empty());
}

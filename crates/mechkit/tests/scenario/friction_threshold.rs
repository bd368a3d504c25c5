//! Contacts loaded exactly to the static bound `μₛ N` (a review by an instructor, with hand
//! answers): a cylinder on a slope at the least `μ` for rolling, `tan α / 3`; a block on a cart
//! pulled by exactly `μₛ g (m + M)`; a block that stops on a slope at its angle of friction.
//! Rounding decided whether static friction held, at a time that depended on the steps (and on
//! `t_max`), and a contact that failed to stick by rounding slid on the way it had slid before
//! with kinetic friction pushing it on: the cylinder spun backwards at twice the rolling
//! acceleration while the surface did +14.9 J of work. At the bound static friction holds
//! (`|f| ≤ μₛ N`, with a margin of 1e-8 for rounding); a contact that slips after touching zero
//! slides against the friction static friction could not give.

use mechkit::scenario::{Scenario, Summary};

fn run_text(text: &str) -> Summary {
    Scenario::from_str("test.toml", text)
        .unwrap()
        .run()
        .unwrap()
        .summary
}

fn observed(s: &Summary, name: &str) -> f64 {
    s.observables[name]
}

fn close(a: f64, b: f64, tol: f64) {
    assert!(
        (a - b).abs() <= tol * b.abs().max(1.0),
        "{a} vs {b} (tolerance {tol})"
    );
}

const G: f64 = 9.81;

/// A solid cylinder (M = 2 kg, R = 0.1 m) released on a slope with tan α = `tan`, friction
/// `mu` (static and kinetic): the observables `a_cm` (down the slope), `friction` (the
/// contact's tangential force), and the energy at the start and the end.
fn cylinder(tan: &str, mu: &str) -> String {
    format!(
        r#"
dimensions = 2
[constants]
R = "0.1 m"
slope = "atan({tan})"
M = "2 kg"
g = "9.81 m/s^2"
[[rigid_body]]
name = "body"
mass = "M"
inertia = "M*R^2/2"
position = ["R*sin(slope)", "R*cos(slope)"]
[[force]]
name = "gravity"
kind = "uniform-gravity"
g = "g"
[[joint]]
name = "slope"
kind = "contact"
on = "body"
radius = "R"
surface = {{ point = ["0 m", "0 m"], angle = "-slope" }}
mu = "{mu}"
[integrator]
method = "dopri5"
rtol = 1e-10
atol = 1e-12
[stop]
t_max = "1 s"
[observe]
a_cm = "final(body.ax*cos(slope) - body.ay*sin(slope))"
friction = "final(slope.F)"
"#
    )
}

#[test]
fn a_cylinder_at_the_least_friction_for_rolling_rolls() {
    for (tan, mu) in [("0.6", "0.2"), ("tan(pi/6)", "tan(pi/6)/3")] {
        let s = run_text(&cylinder(tan, mu));
        let alpha = if tan == "0.6" {
            0.6f64.atan()
        } else {
            30f64.to_radians()
        };
        let label = format!("tan α = {tan}, μ = {mu}");
        // rolling: a = (2/3) g sin α, friction M g sin α / 3 up the slope, no work done
        close(observed(&s, "a_cm"), 2.0 / 3.0 * G * alpha.sin(), 1e-8);
        close(
            observed(&s, "friction").abs(),
            2.0 * G * alpha.sin() / 3.0,
            1e-8,
        );
        let (e0, e1) = (s.energy.start, s.energy.end);
        assert!((e1 - e0).abs() < 1e-6, "{label}: E {e0} -> {e1}");
    }
}

#[test]
fn a_cylinder_just_below_the_least_friction_slides_down_against_it() {
    // μ a millionth below tan α / 3: it slides, friction μ N up the slope, and
    // a = g (sin α − μ cos α); the surface takes energy, never gives it
    let alpha = 0.6f64.atan();
    let mu = 0.2 * (1.0 - 1e-6);
    let s = run_text(&cylinder("0.6", &mu.to_string()));
    close(
        observed(&s, "a_cm"),
        G * (alpha.sin() - mu * alpha.cos()),
        1e-7,
    );
    assert!(s.energy.end <= s.energy.start + 1e-9);
}

/// `examples/friction/block_on_cart.toml`'s set-up pulled by `F`.
fn cart(pull: &str) -> String {
    format!(
        r#"
dimensions = 2
[constants]
m = "1 kg"
M = "4 kg"
mu_s = 0.4
mu_k = 0.3
g = "9.81 m/s^2"
h = "0.5 m"
F = "{pull}"
[[body]]
name = "cart"
mass = "M"
[[body]]
name = "block"
mass = "m"
position = ["0 m", "h"]
[[force]]
name = "gravity"
kind = "uniform-gravity"
g = "g"
[[force]]
name = "pull"
kind = "constant"
on = "cart"
F = ["F", "0 N"]
[[joint]]
name = "floor"
kind = "contact"
on = "cart"
[[joint]]
name = "deck"
kind = "contact"
on = "block"
surface = {{ on = "cart", point = ["0 m", "h"] }}
mu_s = "mu_s"
mu_k = "mu_k"
[integrator]
method = "dopri5"
rtol = 1e-10
atol = 1e-12
[stop]
t_max = "1 s"
[observe]
a_block = "final(block.ax)"
a_cart = "final(cart.ax)"
slid = "final(cart.x - block.x)"
"#
    )
}

#[test]
fn a_block_on_a_cart_pulled_by_exactly_the_largest_force_friction_transmits_rides_along() {
    for pull in ["mu_s*g*(m + M)", "mu_s*g*(m + M)*(1 - 1e-12)"] {
        let s = run_text(&cart(pull));
        close(observed(&s, "a_block"), 0.4 * G, 1e-9);
        close(observed(&s, "a_cart"), 0.4 * G, 1e-9);
        assert!(observed(&s, "slid").abs() < 1e-9, "{pull}");
        assert!(s.events.is_empty(), "{pull}: {:?}", s.events);
    }
    // a thousandth more: it slides, the block at μₖ g
    let s = run_text(&cart("mu_s*g*(m + M)*1.001"));
    close(observed(&s, "a_block"), 0.3 * G, 1e-9);
}

#[test]
fn a_block_stopped_at_its_angle_of_friction_stays_whatever_the_run_length() {
    // launched up a 30° slope at 3 m/s with μₛ = tan 30°, μₖ = 0.5: it stops at
    // s = −v0²/(2 g (sin α + μₖ cos α)) and stays (gravity along the slope is μₛ N exactly)
    let alpha = 30f64.to_radians();
    let stop = -9.0 / (2.0 * G * (alpha.sin() + 0.5 * alpha.cos()));
    for t_max in ["1 s", "2 s", "4 s", "8 s"] {
        let text = format!(
            r#"
dimensions = 2
[constants]
slope = "30 deg"
g = "9.81 m/s^2"
v0 = "3 m/s"
[[body]]
name = "block"
mass = "1 kg"
velocity = ["-v0*cos(slope)", "v0*sin(slope)"]
[[force]]
name = "gravity"
kind = "uniform-gravity"
g = "g"
[[joint]]
name = "incline"
kind = "contact"
on = "block"
surface = {{ point = ["0 m", "0 m"], angle = "-slope" }}
mu_s = "tan(slope)"
mu_k = 0.5
[integrator]
method = "dopri5"
rtol = 1e-10
atol = 1e-12
[stop]
t_max = "{t_max}"
[observe]
s_final = "final(block.x/cos(slope))"
"#
        );
        let s = run_text(&text);
        close(observed(&s, "s_final"), stop, 1e-8);
        assert_eq!(s.events.len(), 1, "t_max {t_max}: {:?}", s.events);
    }
}

//! Issue 23, step-end checks: `check = "step-end"` tests a condition only where a step ends,
//! unlocated, as a textbook `while` loop does, so the book's loops are reproduced bit for bit.
//!
//! Physics checked: the course's atom in a trap (`U = U0 |x|/x0` with damping inside, Euler-
//! Cromer) stopped by `x > 3`: with `check = "step-end"` the run ends at the first step end
//! past the wall, exactly the state of a hand-written Euler-Cromer loop; located (the default)
//! it ends at x = 3. A ball bouncing on a floor through a step-end event with a state change
//! follows the textbook loop `if x < 0: v = -v` bit for bit, and a recording event fires at the
//! step ends, not at the crossings.

use mechkit::ode::steps_to_cover;
use mechkit::scenario::{ErrorKind, Scenario, Summary};

fn run(text: &str) -> Summary {
    Scenario::from_str("step_end.toml", text)
        .unwrap_or_else(|e| panic!("{e}"))
        .run()
        .unwrap()
        .summary
}

const M: f64 = 23.0;
const U0: f64 = 150.0;
const X0: f64 = 2.0;
const ALPHA: f64 = 39.48;
const DT: f64 = 6e-5;

fn trap(stop: &str) -> String {
    format!(
        r#"
dimensions = 1
[constants]
U0    = {U0:?}
x0    = {X0:?}
alpha = {ALPHA}
[[body]]
name     = "atom"
mass     = {M:?}
position = -5.0
velocity = 10.0
[[force]]
name = "trap"
kind = "expression"
F    = "if(abs(x) < x0, -sign(x)*U0/x0 - alpha*v, 0)"
[integrator]
method = "euler-cromer"
dt     = {DT:e}
[stop]
t_max = 6.0
{stop}
"#
    )
}

/// The textbook loop: Euler-Cromer while x <= 3, on the run's time grid (t_k = k dt, each
/// step t_{k+1} - t_k long). Returns (steps, t, x, v).
fn textbook_loop() -> (u64, f64, f64, f64) {
    let (mut x, mut v, mut t) = (-5.0_f64, 10.0_f64, 0.0_f64);
    let mut k = 0_u64;
    while x <= 3.0 {
        let f = if x.abs() < X0 {
            -x.signum() * U0 / X0 - ALPHA * v
        } else {
            0.0
        };
        let a = (0.0 + f) * (1.0 / M);
        let t_next = (k + 1) as f64 * DT;
        let h = t_next - t;
        v += h * a;
        x += h * v;
        t = t_next;
        k += 1;
    }
    (k, t, x, v)
}

#[test]
fn a_step_end_stop_ends_where_the_textbook_loop_does() {
    let s = run(&trap("when = \"x > 3\"\ncheck = \"step-end\""));
    let (steps, t, x, v) = textbook_loop();
    assert_eq!(s.stop_reason, "event");
    assert_eq!(s.steps, steps);
    let atom = &s.bodies["atom"];
    assert_eq!(
        atom.position[0].to_bits(),
        x.to_bits(),
        "{} against {x}",
        atom.position[0]
    );
    assert_eq!(
        atom.velocity[0].to_bits(),
        v.to_bits(),
        "{} against {v}",
        atom.velocity[0]
    );
    assert_eq!(s.t_end.to_bits(), t.to_bits());
    assert!(
        x > 3.0 && x - 3.0 < v * DT,
        "past the wall by less than a step: {x}"
    );
    let e = &s.events[0];
    assert!(e.terminal);
    assert_eq!(e.t.to_bits(), t.to_bits());
    assert!(e.last_step.t < e.t);
}

#[test]
fn the_default_stop_is_located_at_the_wall() {
    let s = run(&trap("when = \"x > 3\""));
    let (steps, t, _, _) = textbook_loop();
    assert_eq!(s.stop_reason, "event");
    assert!((s.bodies["atom"].position[0] - 3.0).abs() < 1e-9);
    assert!(s.t_end < t && s.t_end > t - DT);
    assert_eq!(s.steps, steps, "the crossing is inside the last step");
    let explicit = run(&trap("when = \"x > 3\"\ncheck = \"located\""));
    assert_eq!(explicit.t_end.to_bits(), s.t_end.to_bits());
}

fn bouncing(check: &str) -> String {
    format!(
        r#"
dimensions = 1
[[body]]
name     = "ball"
mass     = 0.1
position = 1.0
velocity = 2.0
[[force]]
name = "gravity"
kind = "uniform-gravity"
g    = 9.81
[integrator]
method = "euler-cromer"
dt     = 0.01
[stop]
t_max = 3.0
[[event]]
name  = "bounce"
when  = "x < 0"
set   = {{ v = "-v" }}
{check}
[[event]]
name  = "apex"
function = "v"
direction = "falling"
{check}
"#
    )
}

#[test]
fn a_step_end_bounce_is_the_textbook_if() {
    let s = run(&bouncing("check = \"step-end\""));
    // the textbook loop: the step, then `if x < 0 and it was not below: v = -v`; the time grid
    // restarts at each bounce, as the run's does after a state change
    let (mut x, mut v, mut t) = (1.0_f64, 2.0_f64, 0.0_f64);
    let (mut origin, mut k) = (0.0_f64, 0_u64);
    let mut below = false;
    let mut bounces = Vec::new();
    let mut apexes = Vec::new();
    let mut rising = true;
    while t < 3.0 {
        let a = (0.0 - 0.1 * 9.81) * (1.0 / 0.1);
        let planned = steps_to_cover(3.0 - origin, 0.01) as u64;
        let t_next = if k + 1 >= planned {
            3.0
        } else {
            origin + (k + 1) as f64 * 0.01
        };
        let h = t_next - t;
        v += h * a;
        x += h * v;
        t = t_next;
        k += 1;
        if rising && v < 0.0 {
            apexes.push(t);
        }
        rising = v > 0.0;
        if x < 0.0 && !below {
            v = -v;
            bounces.push(t);
            origin = t;
            k = 0;
            rising = v > 0.0;
        }
        below = x < 0.0;
    }
    let fired = |name: &str| -> Vec<f64> {
        s.events
            .iter()
            .filter(|e| e.name == name)
            .map(|e| e.t)
            .collect()
    };
    assert!(
        bounces.len() >= 3 && apexes.len() >= 3,
        "{bounces:?} {apexes:?}"
    );
    assert_eq!(fired("bounce"), bounces);
    assert_eq!(fired("apex"), apexes);
    let ball = &s.bodies["ball"];
    assert_eq!(
        ball.position[0].to_bits(),
        x.to_bits(),
        "{} against {x}",
        ball.position[0]
    );
    assert_eq!(ball.velocity[0].to_bits(), v.to_bits());
    // located, the bounces happen at x = 0 instead, between step ends
    let located = run(&bouncing(""));
    let first = &located.events.iter().find(|e| e.name == "bounce").unwrap();
    assert!(first.state["ball"].position[0].abs() < 1e-12);
    assert!(first.t < bounces[0]);
}

#[test]
fn an_unknown_check_is_refused_where_it_is_written() {
    let e = Scenario::from_str("x.toml", &trap("when = \"x > 3\"\ncheck = \"end\""))
        .expect_err("rejected");
    assert_eq!(e.kind, ErrorKind::Invalid);
    assert!(e.message.contains("unknown check `end`"), "{e}");
    assert!(e.hint.unwrap_or_default().contains("step-end"));
    let e = Scenario::from_str("x.toml", &trap("check = \"step-end\"")).expect_err("rejected");
    assert!(e.message.contains("no `when`"), "{e}");
    let e = Scenario::from_str("x.toml", &bouncing("check = 1")).expect_err("rejected");
    assert_eq!(e.kind, ErrorKind::WrongType, "{e}");
}

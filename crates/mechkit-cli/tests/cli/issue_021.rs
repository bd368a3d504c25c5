//! Issue 21 through the binary: `mechkit run` finds every crossing of the issue's three cases
//! (a free particle through a gate far shorter than its steps, a spring passing 0.995 near
//! each maximum with dop853 at rtol = atol = 1e-3, a throw through a 5 cm hoop inside one
//! step), with the `[[event]]` keys a user writes, and records each in `summary.json` and
//! as a row of `trajectory.csv`.

use super::util::{Dir, at, num};

/// The events named `name` in the summary of `mechkit run FILE --json`.
fn events(text: &str, name: &str) -> Vec<f64> {
    let dir = Dir::new();
    dir.create("case.toml", text);
    let out = dir.run(&["run", "case.toml", "--out", "out", "--no-plots", "--json"]);
    out.assert_code(0);
    let summary = out.json();
    let list = at(&summary, "/events").as_array().expect("events").clone();
    let csv = dir.read("out/trajectory.csv");
    let times: Vec<f64> = list
        .iter()
        .filter(|e| at(e, "/name") == name)
        .map(|e| num(e, "/t"))
        .collect();
    for t in &times {
        // each event is a row of the trajectory (serde_json reads numbers to within an ulp)
        let is_row = |l: &str| {
            l.split(',')
                .next()
                .and_then(|c| c.parse::<f64>().ok())
                .is_some_and(|x| (x - t).abs() <= 4.0 * f64::EPSILON * t.abs())
        };
        assert!(csv.lines().any(is_row), "t = {t} is not a row");
    }
    times
}

#[test]
fn the_issues_three_cases() {
    let gate = r#"
title = "gate"
dimensions = 1
[constants]
c = "50 m"
w = "0.1 m"
[[body]]
name = "p"
mass = "1 kg"
position = "0 m"
velocity = "1 m/s"
[integrator]
method = "dopri5"
[[event]]
name = "gate"
function = "(x - c)^2 - w^2"
direction = "falling"
[stop]
t_max = "100 s"
"#;
    let found = events(gate, "gate");
    assert_eq!(found.len(), 1, "{found:?}");
    assert!((found[0] - 49.9).abs() < 1e-12, "{found:?}");

    let spring = r#"
title = "spring"
dimensions = 1
[[body]]
name = "m"
mass = 1
position = 1
[[force]]
name = "spring"
kind = "spring"
k = 1
[integrator]
method = "dop853"
rtol = 1e-3
atol = 1e-3
[[event]]
name = "near"
function = "x - 0.995"
direction = "both"
[stop]
t_max = 20
"#;
    assert_eq!(events(spring, "near").len(), 7);

    let hoop = r#"
title = "hoop"
dimensions = 2
[[body]]
name = "ball"
mass = 1
position = [0, 0]
velocity = [3, 7]
[[force]]
name = "gravity"
kind = "uniform-gravity"
g = 9.8
[integrator]
method = "dopri5"
[[event]]
name = "hoop"
function = "(x - 3)^2 + (y - 2.1)^2 - 0.05^2"
direction = "falling"
[stop]
t_max = 1.4
"#;
    let found = events(hoop, "hoop");
    assert_eq!(found.len(), 1, "{found:?}");
    // about t = 1 - 0.05/√(3² + 2.8²) (the velocity at the centre is (3, -2.8) m/s)
    assert!(
        (found[0] - (1.0 - 0.05 / 16.84_f64.sqrt())).abs() < 1e-3,
        "{found:?}"
    );
}

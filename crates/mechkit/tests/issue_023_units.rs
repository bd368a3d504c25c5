//! Issue 23, units: rational powers in unit strings and dimensions, and reduced units.
//!
//! - A Hertz contact, `F = k*max(0, -x)^1.5` with `k = "1e5 N/m^1.5"`, is accepted and
//!   dimension-checked (a force), and a body of mass m arriving at speed v0 is compressed to
//!   the closed-form depth δ = (5 m v0² / (4 k))^(2/5) (from ½ m v0² = (2/5) k δ^(5/2)) and
//!   leaves at v0 (the contact is elastic); the same stiffness written `N/m^(3/2)` gives the
//!   same run; a wrong exponent (`^2`) is refused as a dimension error at its line and column,
//!   and `N/m^3/2` as a power without parentheses.
//! - A Lennard-Jones pair in reduced units (`units = "reduced"`), written as two expression
//!   forces, conserves `K + U` with `U = 4((b.x - a.x)^-12 - (b.x - a.x)^-6)` (a formula
//!   SI units refuse as "cannot subtract 1/m^12 and 1/m^6"); its outputs are labelled `1` and
//!   the printed summary carries no SI units; a value with a unit is refused at the unit.

use mechkit::scenario::{ErrorKind, Scenario};

const HERTZ: &str = r#"
title = "Hertz contact"
[constants]
k  = "K_HERTZ"
v0 = "1 m/s"
[[body]]
name = "ball"
mass = "1 kg"
position = "0 m"
velocity = "-v0"
[[force]]
name = "contact"
kind = "expression"
F = "EXPONENT"
[integrator]
method = "dopri5"
rtol = 1e-11
atol = 1e-14
[stop]
t_max = "0.1 s"
[[event]]
name = "turn"
when = "v > 0"
[observe]
depth = "-min(x)"
v_end = "final(v)"
"#;

fn hertz(stiffness: &str, force: &str) -> Result<Scenario, mechkit::scenario::ScenarioError> {
    let text = HERTZ
        .replace("K_HERTZ", stiffness)
        .replace("EXPONENT", force);
    Scenario::from_str("hertz.toml", &text)
}

#[test]
fn hertz_contact_with_a_rational_power_is_a_force_and_matches_the_closed_form() {
    let (m, v0, k) = (1.0_f64, 1.0_f64, 1e5_f64);
    let depth = (5.0 * m * v0 * v0 / (4.0 * k)).powf(0.4);
    for stiffness in ["1e5 N/m^1.5", "1e5 N/m^(3/2)", "1e5 kg/(m^0.5*s^2)"] {
        let s = hertz(stiffness, "k*max(0, -x)^1.5").unwrap_or_else(|e| panic!("{e}"));
        let out = s.run().unwrap();
        let o = &out.summary.observables;
        let turn = &out.summary.events[0];
        assert_eq!(turn.name, "turn");
        let x = turn.state["ball"].position[0];
        assert!(
            (-x - depth).abs() < 1e-8 * depth,
            "{stiffness}: depth {} vs {depth}",
            -x
        );
        // the sampled minimum is no deeper than the located one
        assert!(o["depth"] <= -x + 1e-15 && o["depth"] > 0.99 * depth);
        assert!(
            (o["v_end"] - v0).abs() < 1e-7,
            "{stiffness}: {}",
            o["v_end"]
        );
        assert_eq!(out.summary.observable_units["depth"], "m");
    }
    // the same force written with the power as a fraction
    assert!(hertz("1e5 N/m^1.5", "k*max(0, -x)^(3/2)").is_ok());
    assert!(hertz("1e5 N/m^1.5", "k*sqrt(max(0, -x))^3").is_ok());
}

#[test]
fn hertz_contact_with_a_wrong_power_is_refused_where_it_is() {
    let e = hertz("1e5 N/m^1.5", "k*max(0, -x)^2").unwrap_err();
    assert_eq!(e.kind, ErrorKind::Dimension, "{e}");
    assert!(
        e.message
            .contains("must have dimension kg*m/s^2 (force, N)")
            && e.message.contains("kg*m^(3/2)/s^2"),
        "{e}"
    );
    let at = e.location.as_ref().unwrap();
    assert_eq!((at.line, at.column), (14, 6), "{e}");

    let e = hertz("1e5 N/m^3/2", "k*max(0, -x)^1.5").unwrap_err();
    assert_eq!(e.kind, ErrorKind::Unit, "{e}");
    assert!(e.message.contains("needs parentheses"), "{e}");
    assert_eq!(e.hint.as_deref(), Some("write `^(3/2)`"));
    let at = e.location.as_ref().unwrap();
    assert_eq!((at.line, at.column, at.width), (4, 15, 3), "{e}");

    let e = hertz("1e5 N/m^0.333333", "k*max(0, -x)^1.5").unwrap_err();
    assert!(e.message.contains("q at most 1000"), "{e}");
}

const LJ: &str = r#"
title = "Lennard-Jones pair in reduced units"
units = "reduced"
[constants]
eps = 1.0
[[body]]
name = "a"
mass = 1
position = 0
velocity = 0.5
[[body]]
name = "b"
mass = 1
position = 1.5
velocity = -0.5
[[force]]
name = "on_b"
kind = "expression"
on = "b"
F = "4*eps*(12*(b.x - a.x)^-13 - 6*(b.x - a.x)^-7)"
[[force]]
name = "on_a"
kind = "expression"
on = "a"
F = "-4*eps*(12*(b.x - a.x)^-13 - 6*(b.x - a.x)^-7)"
[integrator]
method = "dopri5"
rtol = 1e-11
atol = 1e-13
[stop]
t_max = 10
[[event]]
name = "closest"
when = "b.v - a.v > 0"
max_count = 1
[observe]
U0 = "initial(4*((b.x - a.x)^-12 - (b.x - a.x)^-6))"
U1 = "final(4*((b.x - a.x)^-12 - (b.x - a.x)^-6))"
t_min = "argmin(b.x - a.x)"
"#;

#[test]
fn lennard_jones_in_reduced_units_conserves_energy() {
    let s = Scenario::from_str("lj.toml", LJ).unwrap_or_else(|e| panic!("{e}"));
    let dir = tempfile::tempdir().unwrap();
    let out = s.run_to_dir(dir.path()).unwrap();
    let sum = &out.summary;
    let o = &sum.observables;
    let u = |r: f64| 4.0 * (r.powi(-12) - r.powi(-6));
    assert!((o["U0"] - u(1.5)).abs() < 1e-15);
    let (k0, k1) = (
        sum.kinetic_energy.start.unwrap(),
        sum.kinetic_energy.end.unwrap(),
    );
    assert!((k0 - 0.25).abs() < 1e-15);
    let e0 = k0 + o["U0"];
    assert!(e0 < 0.0, "a bound pair: E = {e0}");
    assert!(
        ((k1 + o["U1"]) - e0).abs() < 1e-8,
        "E: {e0} -> {}",
        k1 + o["U1"]
    );
    // closest approach: the relative velocity is zero, so U(r_min) = E - P²/(4m) = E (P = 0)
    let closest = &sum.events[0].state;
    let r_min = closest["b"].position[0] - closest["a"].position[0];
    assert!(
        (u(r_min) - e0).abs() < 1e-8,
        "U(r_min) = {} vs {e0}",
        u(r_min)
    );
    assert!(
        (sum.events[0].t - o["t_min"]).abs() < 0.01,
        "{}",
        o["t_min"]
    );
    assert!(sum.work_energy_residual.abs() < 1e-8);

    // labelled as reduced
    assert_eq!(sum.units, Some("reduced"));
    assert!(
        sum.observable_units.values().all(|u| u == "1"),
        "{:?}",
        sum.observable_units
    );
    let units: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(dir.path().join("trajectory.units.json")).unwrap(),
    )
    .unwrap();
    let units = units.as_object().unwrap();
    assert!(units.contains_key("a.x") && units.contains_key("K"));
    assert!(units.values().all(|u| u == "1"), "{units:?}");
    let json: serde_json::Value = serde_json::from_str(&sum.to_json()).unwrap();
    assert_eq!(json["units"], "reduced");
    let text = sum.to_text();
    for si in [" m,", " m/s", " J", " s,", " kg", "(J)", "kg·m/s"] {
        assert!(!text.contains(si), "{si:?} in\n{text}");
    }
    assert!(text.contains("energy ledger\n"), "{text}");
}

#[test]
fn si_units_refuse_the_reduced_formula_and_reduced_units_refuse_units() {
    let si = LJ.replace("units = \"reduced\"\n", "");
    let e = Scenario::from_str("lj.toml", &si).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Dimension, "{e}");

    // in reduced units a pure number is any quantity: a force sin(t), a velocity pi
    let driven = LJ.replace(
        "[integrator]",
        "[[force]]\nname = \"drive\"\nkind = \"expression\"\non = \"a\"\nF = \"sin(t)\"\n\
         [[event]]\nname = \"kick\"\nwhen = \"t > 5\"\nset = { \"b.v\" = \"pi\" }\n[integrator]",
    );
    Scenario::from_str("lj.toml", &driven).unwrap_or_else(|e| panic!("{e}"));
    let e =
        Scenario::from_str("lj.toml", &driven.replace("units = \"reduced\"\n", "")).unwrap_err();
    assert!(
        e.message.contains("`sin` needs a dimensionless argument"),
        "{e}"
    );

    let with_unit = LJ.replace("mass = 1\nposition = 0", "mass = \"1 kg\"\nposition = 0");
    let e = Scenario::from_str("lj.toml", &with_unit).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Unit, "{e}");
    assert!(
        e.message.contains("reduced units") && e.message.contains("the unit `kg`"),
        "{e}"
    );
    let at = e.location.as_ref().unwrap();
    assert_eq!((at.line, at.column, at.width), (8, 11, 2), "{e}");
    assert!(e.hint.as_deref().unwrap().contains("`1`"), "{e}");

    let dt = LJ
        .replace("rtol = 1e-11\natol = 1e-13", "dt = \"1 ms\"")
        .replace("dopri5", "rk4");
    let e = Scenario::from_str("lj.toml", &dt).unwrap_err();
    assert!(e.message.contains("the unit `ms`"), "{e}");

    let e = Scenario::from_str("lj.toml", &LJ.replace("\"reduced\"", "\"metric\"")).unwrap_err();
    assert!(e.message.contains("unknown unit system `metric`"), "{e}");
    let e = Scenario::from_str("lj.toml", &LJ.replace("\"reduced\"", "3")).unwrap_err();
    assert_eq!(e.kind, ErrorKind::WrongType, "{e}");
    // SI, spelled out, is the default
    let e = Scenario::from_str("lj.toml", &LJ.replace("\"reduced\"", "\"SI\"")).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Dimension, "{e}");
}

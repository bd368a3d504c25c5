//! Bad scenario files: every error names what is wrong, where (line and column of the file),
//! and what would fix it.

use mechkit::scenario::{ErrorKind, Scenario, ScenarioError};

const BASE: &str = r#"
dimensions = 1

[constants]
k = "10 N/m"

[[body]]
name = "ball"
mass = "1 kg"
position = "1 m"

[[force]]
name = "spring"
kind = "expression"
F = "-k*x"

[integrator]
method = "rk4"
dt = "1 ms"

[stop]
t_max = "1 s"
"#;

fn load(text: &str) -> Result<Scenario, ScenarioError> {
    Scenario::from_str("test.toml", text)
}

fn error(text: &str) -> ScenarioError {
    load(text).expect_err("the scenario should be rejected")
}

/// Replaces the first occurrence of `from` in the base scenario.
fn with(from: &str, to: &str) -> String {
    assert!(BASE.contains(from), "{from}");
    BASE.replacen(from, to, 1)
}

fn at(e: &ScenarioError) -> (usize, usize) {
    let l = e
        .location
        .as_ref()
        .unwrap_or_else(|| panic!("no location: {e}"));
    (l.line, l.column)
}

#[test]
fn base_scenario_is_valid() {
    load(BASE).unwrap();
}

#[test]
fn unknown_key_names_key_place_and_nearest_key() {
    let e = error(&with("mass = \"1 kg\"", "masss = \"1 kg\""));
    assert_eq!(e.kind, ErrorKind::UnknownKey);
    assert!(e.message.contains("`masss`"), "{e}");
    assert_eq!(at(&e), (9, 1));
    assert_eq!(e.hint.as_deref(), Some("did you mean `mass`?"));
    let text = e.to_string();
    assert!(text.contains("--> test.toml:9:1"), "{text}");
    assert!(text.contains("9 | masss = \"1 kg\"\n  | ^^^^^"), "{text}");

    let e = error(&with("[stop]", "[stopp]"));
    assert!(e.hint.unwrap().contains("`stop`"));
    let e = error(&with(
        "kind = \"expression\"",
        "kind = \"expression\"\nkk = 3",
    ));
    assert!(
        e.hint.unwrap().contains("`expression` force takes"),
        "unknown force parameter"
    );
}

#[test]
fn missing_mass() {
    let e = error(&with("mass = \"1 kg\"\n", ""));
    assert_eq!(e.kind, ErrorKind::Missing);
    assert!(e.message.contains("no `mass`"), "{e}");
    assert!(e.hint.unwrap().contains("mass = \"1 kg\""));
    assert!(e.location.is_some());
}

#[test]
fn non_positive_mass_and_dt() {
    for (from, to) in [
        ("mass = \"1 kg\"", "mass = \"-2 kg\""),
        ("mass = \"1 kg\"", "mass = 0"),
        ("dt = \"1 ms\"", "dt = 0"),
        ("dt = \"1 ms\"", "dt = \"-1 ms\""),
    ] {
        let e = error(&with(from, to));
        assert_eq!(e.kind, ErrorKind::Invalid, "{to}");
        assert!(e.message.contains("must be positive"), "{e}");
        let (line, _) = at(&e);
        let expected = BASE
            .replacen(from, to, 1)
            .lines()
            .position(|l| l.contains(to))
            .unwrap()
            + 1;
        assert_eq!(line, expected, "{e}");
    }
}

#[test]
fn unknown_unit_is_located_and_suggests() {
    let e = error(&with(
        "position = \"1 m\"",
        "position = \"1 mm\"\nvelocity = \"3 mps\"",
    ));
    assert_eq!(e.kind, ErrorKind::Unit);
    assert!(e.message.contains("unknown unit `mps`"), "{e}");
    assert_eq!(at(&e), (11, 15));
    assert!(e.hint.unwrap().starts_with("did you mean `m/s`"));
}

#[test]
fn wrong_dimension_names_both() {
    let e = error(&with("mass = \"1 kg\"", "mass = \"3 m\""));
    assert_eq!(e.kind, ErrorKind::Dimension);
    assert!(
        e.message.contains("kg (mass)") && e.message.contains("m (length)"),
        "{e}"
    );
}

#[test]
fn undefined_name_in_a_formula_is_named_with_its_column() {
    let e = error(&with("F = \"-k*x\"", "F = \"-k*xx\""));
    assert_eq!(e.kind, ErrorKind::Formula);
    assert!(e.message.contains("undefined name `xx`"), "{e}");
    // F = "-k*xx": the name starts at column 9 of the line
    assert_eq!(at(&e), (15, 9));
    assert!(e.hint.unwrap().contains("`x`"));
}

#[test]
fn force_formula_of_the_wrong_dimension() {
    let e = error(&with("F = \"-k*x\"", "F = \"-k*x*x\""));
    assert_eq!(e.kind, ErrorKind::Dimension);
    assert!(
        e.message
            .contains("a force must have dimension kg*m/s^2 (force, N)"),
        "{e}"
    );
}

#[test]
fn toml_syntax_error_is_located() {
    let e = error(&with("mass = \"1 kg\"", "mass = \"1 kg"));
    assert_eq!(e.kind, ErrorKind::Syntax);
    assert_eq!(at(&e).0, 9);
}

#[test]
fn unknown_method_and_force_kind() {
    let e = error(&with("method = \"rk4\"", "method = \"rk5\""));
    assert!(e.hint.unwrap().contains("rk4"));
    let e = error(&with("kind = \"expression\"", "kind = \"sprng\""));
    assert!(e.hint.unwrap().contains("`spring`"));
}

#[test]
fn integrator_settings() {
    // a Runge-Kutta pair with dt takes fixed steps; with rtol/atol adaptive ones
    assert!(load(&with("method = \"rk4\"", "method = \"dopri5\"")).is_ok());
    assert!(
        load(&with(
            "method = \"rk4\"\ndt = \"1 ms\"",
            "method = \"dop853\"\nrtol = 1e-9\natol = 1e-12"
        ))
        .is_ok()
    );
    let e = error(&with("dt = \"1 ms\"", "dt = \"1 ms\"\nrtol = 1e-8"));
    assert!(e.message.contains("`rtol` controls adaptive steps"), "{e}");
    assert_eq!(at(&e).0, 20);
    let e = error(&with(
        "method = \"rk4\"",
        "method = \"dopri5\"\nrtol = 1e-8",
    ));
    assert!(e.message.contains("`dt` fixes the step"), "{e}");
    let adaptive = |keys: &str| {
        with(
            "method = \"rk4\"\ndt = \"1 ms\"",
            &format!("method = \"dopri5\"\n{keys}"),
        )
    };
    for (keys, want) in [
        ("rtol = 0", "`rtol` must be positive"),
        ("rtol = -1e-6", "`rtol` must be positive"),
        ("rtol = 1e-16", "below what double precision"),
        ("atol = -1", "`atol` must be zero or positive"),
        ("atol = \"1 mm\"", "takes no unit"),
        ("atol = { position = \"1 mm\" }", "velocity"),
        (
            "atol = { position = \"1 mm\", velocity = \"1 mm\" }",
            "velocity",
        ),
        ("h_max = \"-1 s\"", "positive time"),
        ("h0 = \"2 kg\"", "h0"),
    ] {
        let e = error(&adaptive(keys));
        assert!(e.to_string().contains(want), "{keys}: {e}");
    }
    let e = error(&with("method = \"rk4\"\ndt = \"1 ms\"", "method = \"rk4\""));
    assert!(e.message.contains("`dt`"), "{e}");
}

#[test]
fn symplectic_methods_need_position_forces() {
    let text = with("method = \"rk4\"", "method = \"pefrl\"")
        .replace("F = \"-k*x\"", "F = \"-k*x - 0.1*vx\"");
    let e = error(&text);
    assert!(
        e.message.contains("symplectic") && e.message.contains("`spring`"),
        "{e}"
    );
    assert!(load(&with("method = \"rk4\"", "method = \"yoshida4\"")).is_ok());
}

#[test]
fn unknown_force_kind() {
    let e = error(&with("kind = \"expression\"", "kind = \"sprng\""));
    assert!(e.hint.unwrap().contains("`spring`"));
}

#[test]
fn body_references_and_stop_conditions() {
    let e = error(&with("F = \"-k*x\"", "F = \"-k*x\"\non = \"bal\""));
    assert!(e.message.contains("no body named `bal`") && e.hint.unwrap().contains("`ball`"));
    let e = error(&with("t_max = \"1 s\"", "when = \"x == 0\""));
    assert!(e.message.contains("`==`"), "{e}");
    let e = error(&with("t_max = \"1 s\"", "when = \"x < 0 <\""));
    assert_eq!(e.kind, ErrorKind::Formula);
}

#[test]
fn constants_in_order_and_reserved_names() {
    let e = error(&with("k = \"10 N/m\"", "k = \"2*k2\"\nk2 = \"5 N/m\""));
    assert!(
        e.hint.unwrap().contains("further down"),
        "constants refer upwards"
    );
    let e = error(&with("k = \"10 N/m\"", "x = \"10 N/m\""));
    assert!(e.message.contains("cannot be a constant"));
}

#[test]
fn constant_that_looks_like_a_unit() {
    // "2 k": k is a constant, not a unit
    let e = error(&with("position = \"1 m\"", "position = \"2 k\""));
    assert!(
        e.hint.unwrap().contains("2*k"),
        "hint points at multiplication"
    );
}

#[test]
fn vectors_need_one_value_per_dimension() {
    let text = with("dimensions = 1", "dimensions = 2")
        .replace("position = \"1 m\"", "position = [\"1 m\"]");
    let e = error(&text);
    assert!(
        e.message.contains("1 components") && e.message.contains("2 dimensions"),
        "{e}"
    );
}

#[test]
fn missing_integrator_and_bodies() {
    let e = error("dimensions = 1\n[[body]]\nmass = 1\n");
    assert!(e.message.contains("[integrator]"));
    let e = error("dimensions = 1\n[integrator]\ndt = 1\n");
    assert!(e.message.contains("[[body]]"));
}

#[test]
fn observables_and_plots_are_checked() {
    let e = error(&format!("{BASE}\n[observe]\nbad = \"max(x) + x\"\n"));
    assert!(
        e.hint.unwrap().contains("final(x)"),
        "state outside a reduction"
    );
    let e = error(&format!("{BASE}\n[observe]\nbad = \"max(final(x))\"\n"));
    assert!(e.message.contains("nested"), "{e}");
    let e = error(&format!("{BASE}\n[output]\nplots = [\"q(t)\"]\n"));
    assert!(e.message.contains("`q`"), "{e}");
    assert_eq!(at(&e).0, BASE.lines().count() + 3);
}

#[test]
fn typos_get_the_error_that_fits_them() {
    // a misspelt unit in a constant is a unit error, not a formula error
    let e = error(&with(
        "k = \"10 N/m\"",
        "g0 = \"9.8 m/ss^2\"\nk = \"10 N/m\"",
    ));
    assert_eq!(e.kind, ErrorKind::Unit, "{e}");
    assert!(e.message.contains("`ss`"), "{e}");
    // a misspelt constant after a number is an undefined name
    let e = error(&with("mass = \"1 kg\"", "mass = \"2*kk\""));
    assert_eq!(e.kind, ErrorKind::Formula, "{e}");
    assert!(e.message.contains("undefined name `kk`"), "{e}");
    assert!(e.hint.unwrap().contains("`k`"));
}

#[test]
fn values_must_be_finite() {
    let e = error(&with("position = \"1 m\"", "position = inf"));
    assert_eq!(e.kind, ErrorKind::Invalid);
    assert!(e.message.contains("not a finite number"), "{e}");
}

#[test]
fn named_constant_exponents_keep_dimensions_known() {
    let text = with("k = \"10 N/m\"", "k = \"10 N/m^3\"\nn = 3").replacen(
        "F = \"-k*x\"",
        "F = \"-k*x^n\"",
        1,
    );
    load(&text).unwrap();
    let bad = with("k = \"10 N/m\"", "k = \"10 N/m^3\"\nn = 2").replacen(
        "F = \"-k*x\"",
        "F = \"-k*x^n\"",
        1,
    );
    assert_eq!(error(&bad).kind, ErrorKind::Dimension);
}

#[test]
fn observables_must_be_dimensionally_consistent() {
    let e = error(&format!("{BASE}\n[observe]\nbad = \"max(x) + final(t)\"\n"));
    assert_eq!(e.kind, ErrorKind::Dimension, "{e}");
    let s = load(&format!(
        "{BASE}\n[observe]\nswing = \"max(x) - min(x)\"\nwhen = \"argmax(v)\"\nhalf = \"(max(x) - min(x))/2\"\n"
    ))
    .unwrap();
    let units: Vec<Option<String>> = s
        .observables
        .iter()
        .map(mechkit::scenario::Observable::unit)
        .collect();
    // a literal factor's unit is unknowable, so `/2` leaves the unit unknown
    assert_eq!(units, vec![Some("m".into()), Some("s".into()), None]);
}

#[test]
fn state_names_cannot_be_constants_or_force_names_hold_dashes() {
    for name in ["K", "E", "a", "x"] {
        let e = error(&with(
            "k = \"10 N/m\"",
            &format!("{name} = 2\nk = \"10 N/m\""),
        ));
        assert!(e.message.contains("cannot be a constant"), "{name}: {e}");
    }
    let e = error(&with("name = \"spring\"", "name = \"air-drag\""));
    assert!(e.message.contains("letters, digits or `_`"), "{e}");
}

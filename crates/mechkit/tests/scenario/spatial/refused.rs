//! What is refused in space, where it is written.

use super::*;

fn error(text: &str) -> ScenarioError {
    Scenario::from_str("bad.toml", text).expect_err("the scenario should be rejected")
}

/// The line of the error's location.
fn line(e: &ScenarioError) -> usize {
    e.location
        .as_ref()
        .unwrap_or_else(|| panic!("no location: {e}"))
        .line
}

const ONE_BODY: &str = r#"dimensions = 3
[[body]]
name = "ball"
mass = "1 kg"
[[rigid_body]]
name = "box"
mass = "1 kg"
inertia = [0.2, 0.5, 0.6]
points = { p = ["1 m", "0 m", "0 m"] }
[integrator]
method = "dop853"
[stop]
t_max = "1 s"
"#;

fn with(from: &str, to: &str) -> String {
    assert!(ONE_BODY.contains(from), "{from}");
    ONE_BODY.replacen(from, to, 1)
}

#[test]
fn the_base_of_the_error_cases_is_valid() {
    Scenario::from_str("ok.toml", ONE_BODY).unwrap();
}

#[test]
fn impossible_inertia_is_refused_where_it_is_written() {
    let e = error(&with(
        "inertia = [0.2, 0.5, 0.6]",
        "inertia = [[0.2, 0.3, 0], [0.3, 0.2, 0], [0, 0, 0.6]]",
    ));
    assert!(e.message.contains("positive principal moments"), "{e}");
    assert_eq!(line(&e), 8, "{e}");
    let e = error(&with(
        "inertia = [0.2, 0.5, 0.6]",
        "inertia = [0.2, -0.5, 0.6]",
    ));
    assert!(e.message.contains("positive principal moments"), "{e}");
    let e = error(&with(
        "inertia = [0.2, 0.5, 0.6]",
        "inertia = [0.2, 0.3, 0.6]",
    ));
    assert!(
        e.message.contains("the largest must be at most the sum"),
        "{e}"
    );
    assert_eq!(line(&e), 8, "{e}");
    // a thin rod is the limit the triangle inequality allows
    Scenario::from_str(
        "rod.toml",
        &with("inertia = [0.2, 0.5, 0.6]", "inertia = [0.5, 0.5, 1.0]"),
    )
    .unwrap();
}

#[test]
fn an_orientation_of_zero_length_is_refused() {
    let e = error(&with(
        "points = {",
        "orientation = [0, 0, 0, 0]\npoints = {",
    ));
    assert!(e.message.contains("is not a rotation"), "{e}");
    assert_eq!(line(&e), 9, "{e}");
    let e = error(&with(
        "points = {",
        "orientation = { axis = [0, 0, 0], angle = \"1 deg\" }\npoints = {",
    ));
    assert!(e.message.contains("no direction"), "{e}");
}

#[test]
fn a_torque_on_a_particle_is_refused() {
    let e = error(&format!(
        "{ONE_BODY}[[force]]\nname = \"motor\"\nkind = \"torque\"\non = \"ball\"\nT = [\"0 N*m\", \"0 N*m\", \"1 N*m\"]\n"
    ));
    assert!(e.message.contains("`ball` is not a rigid body"), "{e}");
    assert_eq!(line(&e), 17, "{e}");
    assert!(e.hint.as_deref().unwrap_or("").contains("box"), "{e}");
}

#[test]
fn a_force_at_an_unknown_point_is_refused() {
    let e = error(&format!(
        "{ONE_BODY}[[force]]\nname = \"push\"\nkind = \"constant\"\nF = [\"1 N\", \"0 N\", \"0 N\"]\nat = \"box.q\"\n"
    ));
    assert!(e.message.contains("`box` has no point `q`"), "{e}");
    assert!(e.message.contains("its points are: p"), "{e}");
    assert_eq!(line(&e), 18, "{e}");
    let e = error(&format!(
        "{ONE_BODY}[[force]]\nname = \"push\"\nkind = \"constant\"\nF = [\"1 N\", \"0 N\", \"0 N\"]\nat = \"ball.p\"\n"
    ));
    assert!(e.message.contains("`ball` is a particle"), "{e}");
}

#[test]
fn plane_only_joints_and_fixed_axis_torques_are_refused_in_space() {
    let e = error(&format!(
        "{ONE_BODY}[[joint]]\nname = \"wire\"\nkind = \"curve\"\non = \"box.p\"\ny = \"x^2\"\n"
    ));
    assert!(e.message.contains("works in a plane"), "{e}");
    assert!(e.hint.as_deref().unwrap_or("").contains("hinge"), "{e}");
    assert_eq!(line(&e), 16, "{e}");
    let e = error(&format!(
        "{ONE_BODY}[[torque]]\nname = \"bearing\"\nkind = \"friction\"\ntorque = \"1 N*m\"\n"
    ));
    assert!(e.message.contains("cannot have `torque`"), "{e}");
    assert!(
        e.hint.as_deref().unwrap_or("").contains("kind \"torque\""),
        "{e}"
    );
    assert_eq!(line(&e), 14, "{e}");
}

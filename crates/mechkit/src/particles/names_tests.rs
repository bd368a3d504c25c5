use mechkit_expr::units::Dimension;

use super::*;
use crate::particles::Kinematics;

fn ctx<'a>(
    bodies: &'a [String],
    forces: &'a [String],
    constants: &'a [(String, Real, Dim)],
    level: VarLevel,
) -> NameContext<'a> {
    NameContext {
        dim: 2,
        bodies,
        forces,
        constants,
        bare: Some(BodyRef::Local),
        level,
        coordinates: Coordinates::Cartesian,
        units: UnitSystem::Si,
        planar: &crate::particles::NO_PLANAR,
    }
}

#[test]
fn resolves_names() {
    let bodies = vec!["ball".to_string(), "moon".to_string()];
    let forces = vec!["air".to_string()];
    let c = ctx(&bodies, &forces, &[], VarLevel::Derived);
    assert_eq!(c.resolve("y"), Some(StateVar::Position(BodyRef::Local, 1)));
    assert_eq!(c.resolve("z"), None);
    assert_eq!(
        c.resolve("moon.vx"),
        Some(StateVar::Velocity(BodyRef::Index(1), 0))
    );
    assert_eq!(c.resolve("v"), Some(StateVar::Speed(BodyRef::Local)));
    assert_eq!(c.resolve("work.air"), Some(StateVar::Work(0)));
    assert_eq!(c.resolve("work.wind"), None);
    assert_eq!(
        c.resolve("ball.K"),
        Some(StateVar::BodyKinetic(BodyRef::Index(0)))
    );
    let k = ctx(&bodies, &forces, &[], VarLevel::Kinematic);
    assert_eq!(k.resolve("ax"), None);
    assert_eq!(k.resolve("K"), None);
}

#[test]
fn compiles_and_evaluates_with_constants() {
    let bodies = vec!["ball".to_string()];
    let constants = vec![("D".to_string(), 0.5, Dim::Known(Dimension::QUADRATIC_DRAG))];
    let c = ctx(&bodies, &[], &constants, VarLevel::Kinematic);
    let e = c.compile(&Formula::parse("-D*v*vx").unwrap()).unwrap();
    let k = Kinematics {
        t: 0.0,
        dim: 2,
        x: &[0.0, 1.0],
        v: &[3.0, 4.0],
        mass: &[1.0],
    };
    assert_eq!(e.eval_kinematic(&k, Some(0)), -0.5 * 5.0 * 3.0);
    assert!(e.reads_velocity());
}

#[test]
fn errors_suggest_and_describe() {
    let bodies = vec!["ball".to_string()];
    let c = ctx(&bodies, &[], &[], VarLevel::Kinematic);
    let err = c
        .compile(&Formula::parse("-ball.vxx").unwrap())
        .unwrap_err();
    let text = err.to_string();
    assert!(text.contains("did you mean `ball.vx`"), "{text}");
    let err = c.compile(&Formula::parse("K").unwrap()).unwrap_err();
    assert!(err.to_string().contains("forces cannot use"), "{err}");
    let err = c.compile(&Formula::parse("x + t").unwrap()).unwrap_err();
    assert!(err.to_string().contains("cannot add"), "{err}");
    let reduced = NameContext {
        units: UnitSystem::Reduced,
        ..c
    };
    assert!(reduced.compile(&Formula::parse("x + t").unwrap()).is_ok());
}

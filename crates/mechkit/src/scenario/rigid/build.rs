//! A scenario of rigid bodies hinged to the world: one angle per body.

use super::bodies::read_rigid_bodies;
use super::torques::read_torques;
use crate::ode::State;
use crate::scenario::Scenario;
use crate::scenario::build::{Model, assemble};
use crate::scenario::doc::Table;
use crate::scenario::error::{ErrorKind, ScenarioError};
use crate::scenario::integrator::read_integrator;
use crate::scenario::values::{Constant, ValueEnv};

/// State names of a scenario with rigid bodies.
pub(crate) const RIGID_RESERVED: &[&str] = &["theta", "omega", "alpha"];

/// A scenario of rigid bodies hinged to the world: one angle per body.
pub(crate) fn build_rigid(
    name: &str,
    root: &Table<'_, '_>,
    title: String,
    dim: usize,
    constants: Vec<Constant>,
    tables: &[Table<'_, '_>],
) -> Result<Scenario, ScenarioError> {
    let src = root.src;
    for key in ["body", "force", "contact", "wall", "plane"] {
        if let Some(v) = root.get(key) {
            return Err(src
                .error(
                    ErrorKind::Invalid,
                    format!("a scenario of hinged [[rigid_body]]s cannot also have `{key}`"),
                    v.span(),
                )
                .with_hint("rigid bodies turning about fixed axes are run in angle coordinates; put particles in a scenario of their own"));
        }
    }
    if dim != 1 {
        return Err(src.error(
            ErrorKind::Invalid,
            "a hinged rigid body has one coordinate, its angle: leave out `dimensions`",
            root.key_span("dimensions"),
        ));
    }
    let dir = std::path::Path::new(name).parent();
    let mut rigid = read_rigid_bodies(tables, &constants, dir)?;
    let torques = read_torques(&root.tables("torque")?, &mut rigid, &constants)?;
    let mut warnings = std::mem::take(&mut rigid.warnings);
    if torques.is_empty() {
        warnings
            .push("no [[torque]] is defined: the bodies turn at constant angular velocity".into());
    }
    let force_names: Vec<String> = torques.iter().map(|f| f.name().to_string()).collect();
    for (i, n) in force_names.iter().enumerate() {
        if force_names[..i].contains(n) {
            return Err(ScenarioError::new(
                ErrorKind::Invalid,
                format!("two torques are named `{n}`"),
            )
            .with_hint(
                "give each [[torque]] its own `name`; the energy ledger lists work by name",
            ));
        }
    }
    let system = crate::rigid::fixed_axis::system(&rigid.bodies, torques)
        .map_err(|e| ScenarioError::new(ErrorKind::Invalid, e.to_string()))?;
    let env = ValueEnv {
        constants: &constants,
        mass: None,
        later: &[],
    };
    let stepping = read_integrator(root, env, &system)?;
    let bodies = rigid.names.clone();
    let scene = crate::animation::Scene {
        dim: 3,
        bodies: rigid
            .names
            .iter()
            .zip(std::mem::take(&mut rigid.outlines))
            .zip(&rigid.bodies)
            .map(|((name, parts), body)| crate::animation::Body {
                name: name.clone(),
                shape: crate::animation::BodyShape::Outline { parts },
                hinge: Some([body.axis().x, body.axis().y, body.axis().z]),
            })
            .collect(),
        items: Vec::new(),
        upright: false,
    };
    // dry friction acts against the turning until the body stops: there the regime ends
    let mut events = Vec::new();
    for (b, direction, torque) in std::mem::take(&mut rigid.dry) {
        let body = &bodies[b];
        events.push(
            crate::simulate::Event::new(format!("{body} stopped"), move |s, _| direction * s.v[b])
                .direction(crate::simulate::Direction::Falling)
                .stop(),
        );
        warnings.push(format!(
            "`{body}` has dry bearing friction (`{torque}`): the run ends when it stops turning"
        ));
    }
    assemble(
        root,
        Model {
            name,
            title,
            dim: 1,
            constants,
            system,
            initial: State::from_qv(0.0, &rigid.theta, &rigid.omega),
            stepping,
            bodies,
            forces: force_names,
            events,
            warnings,
            planar: crate::particles::PlanarNames::default(),
            scene,
        },
    )
}

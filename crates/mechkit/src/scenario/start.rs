//! The start state checked before a run: every force and potential energy a number at t = 0.
//!
//! A body started at a force's singular point (an orbit at the attracting centre, two bodies
//! of a pair force at one place) made the run stop at its first evaluation, exit 1 with no
//! location; the same state is refused when the file is read (`mechkit check` too), located
//! at the body's `position`.

use super::doc::Table;
use super::error::{ErrorKind, ScenarioError};
use crate::error::short;
use crate::ode::State;
use crate::particles::ParticleSystem;
use crate::simulate::diagnose::{non_finite_force, non_finite_potential};

/// Refuses a start at which a force or a potential energy is not a number.
pub(crate) fn check_start(
    root: &Table<'_, '_>,
    system: &ParticleSystem,
    start: &State,
) -> Result<(), ScenarioError> {
    if let Some(bad) = non_finite_force(system, start) {
        let bodies = root.tables("body")?;
        let span = bodies.get(bad.body).map_or(root.span.clone(), |t| {
            t.get("position")
                .map_or(t.span.clone(), toml::Spanned::span)
        });
        let body = &system.bodies()[bad.body].name;
        return Err(root
            .src
            .error(
                ErrorKind::Invalid,
                format!(
                    "at the start (t = 0) the force `{}` on `{body}` is {} ({} component), with {}",
                    bad.force,
                    short(bad.value),
                    bad.axis,
                    bad.situation
                ),
                span,
            )
            .with_hint(
                "a body starts at a singular point of the force (the centre of an inverse-square force, two bodies of a pair force at one place), or the force's formula has no value there (a division by zero, sqrt or log of a negative number): move the body, or check the formula",
            ));
    }
    if let Some((force, u)) = non_finite_potential(system, start) {
        let span = root
            .tables("force")?
            .into_iter()
            .find(|t| {
                t.string("name")
                    .ok()
                    .flatten()
                    .is_some_and(|(n, _)| n == force)
            })
            .map_or(root.span.clone(), |t| t.span.clone());
        return Err(root
            .src
            .error(
                ErrorKind::Invalid,
                format!(
                    "at the start (t = 0) the potential energy of `{force}` is {}",
                    short(u)
                ),
                span,
            )
            .with_hint(
                "the bodies it acts on start at its singular point (r = 0?): move them apart, or check its formula",
            ));
    }
    Ok(())
}

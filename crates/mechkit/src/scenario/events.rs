//! `[[event]]`: things that happen during a run, located between steps (or, with
//! `check = "step-end"`, tested only at step ends); recorded, or ending the run, or changing
//! the state (a bounce).

use mechkit_expr::Formula;
use mechkit_expr::units::Dimension;
use toml::de::DeValue;

use super::doc::Table;
use super::error::{ErrorKind, ScenarioError};
use super::stop::{condition, read_check};
use super::values::formula_error;
use crate::Real;
use crate::particles::{BodyRef, NameContext, StateExpr, StateVar, VarLevel};
use crate::simulate::{Condition, Direction, Event};

const KEYS: &[&str] = &[
    "name",
    "when",
    "function",
    "direction",
    "action",
    "count",
    "max_count",
    "set",
    "check",
];

pub(crate) fn read_events(
    root: &Table<'_, '_>,
    names: &NameContext<'_>,
) -> Result<Vec<Event>, ScenarioError> {
    let mut events: Vec<Event> = Vec::new();
    for (i, t) in root.tables("event")?.iter().enumerate() {
        t.check_keys(KEYS)?;
        let name = match t.string("name")? {
            Some((n, span)) => {
                if n.trim().is_empty() {
                    return Err(t.src.error(
                        ErrorKind::Invalid,
                        "an event's `name` cannot be empty",
                        span,
                    ));
                }
                if events.iter().any(|e| e.name() == n) {
                    return Err(t
                        .src
                        .error(
                            ErrorKind::Invalid,
                            format!("two events are named `{n}`"),
                            span,
                        )
                        .with_hint("give each [[event]] its own `name`"));
                }
                n.to_string()
            }
            None => format!("event{}", i + 1),
        };
        let event = match (t.string("when")?, t.string("function")?) {
            (Some(_), Some(_)) => {
                return Err(t
                    .src
                    .error(
                        ErrorKind::Invalid,
                        "an event has either `when` (a condition) or `function` (whose zeros are the event), not both",
                        t.key_span("function"),
                    ));
            }
            (None, None) => {
                return Err(t.missing("when", "\"y < 0\"").with_hint(
                    "say when it happens: `when = \"y < 0\"` (each time the condition becomes true), or `function = \"vy\"` with `direction = \"falling\"`",
                ));
            }
            (Some((text, span)), None) => {
                if t.get("direction").is_some() {
                    return Err(t
                        .src
                        .error(
                            ErrorKind::Invalid,
                            "`direction` does not go with `when`: the event fires each time the condition becomes true",
                            t.key_span("direction"),
                        )
                        .with_hint("write the zero crossing as `function = \"…\"` with `direction`, or drop `direction`"));
                }
                let c = condition(t, text, &span, names, "an event")?;
                let (g, bound) = (c.clone(), c.clone());
                Event::from_function(
                    Condition::from_fn(
                        name.clone(),
                        c.inclusive(),
                        c.needs_forces(),
                        move |s, sys| g.value(s, sys),
                    )
                    .with_enclosure(move |j, sys| bound.enclose(j, sys)),
                )
                .direction(Direction::Rising)
            }
            (None, Some((text, span))) => {
                let f = Formula::parse(text).map_err(|e| formula_error(&t.src, &span, &e))?;
                let g = names
                    .compile(&f)
                    .map_err(|e| formula_error(&t.src, &span, &e))?;
                let needs = !g.is_kinematic();
                let direction =
                    match t.string("direction")? {
                        None => Direction::Both,
                        Some((d, dspan)) => {
                            Direction::from_name(d).ok_or_else(|| {
                                t.src
                            .error(ErrorKind::Invalid, format!("unknown direction `{d}`"), dspan)
                            .with_hint("`rising` (from negative to positive), `falling`, or `both`")
                            })?
                        }
                    };
                let bound = g.clone();
                Event::from_function(
                    Condition::from_fn(name.clone(), false, needs, move |s, sys| {
                        g.eval_sample(s, sys.dim(), sys.masses(), None)
                    })
                    .with_enclosure(move |j, _| bound.enclose(j, None)),
                )
                .direction(direction)
            }
        };
        let stops = match t.string("action")? {
            None | Some(("record", _)) => false,
            Some(("stop", _)) => true,
            Some((a, span)) => {
                return Err(t
                    .src
                    .error(ErrorKind::Invalid, format!("unknown action `{a}`"), span)
                    .with_hint("`record` (the default: note it and go on) or `stop` (end the run there); to change the state, add `set = { vy = \"-e*vy\" }`"));
            }
        };
        let mut event = if read_check(t)? {
            event.at_step_ends()
        } else {
            event
        };
        match t.count("count")? {
            Some((0, span)) => {
                return Err(t
                    .src
                    .error(ErrorKind::Invalid, "`count` must be at least 1", span)
                    .with_hint("`count = 3` ends the run at the third occurrence"));
            }
            Some((n, span)) => {
                if !stops {
                    return Err(t
                        .src
                        .error(ErrorKind::Invalid, "`count` says at which occurrence a stopping event ends the run", span)
                        .with_hint("add `action = \"stop\"`, or use `max_count` to ignore occurrences after the first few"));
                }
                event = event.stop_at(u32::try_from(n).unwrap_or(u32::MAX));
            }
            None if stops => event = event.stop(),
            None => {}
        }
        match t.count("max_count")? {
            Some((0, span)) => {
                return Err(t
                    .src
                    .error(ErrorKind::Invalid, "`max_count` must be at least 1", span)
                    .with_hint("`max_count = 3` records the first three occurrences; to ignore the event, remove it"));
            }
            Some((n, _)) => event = event.max_count(u32::try_from(n).unwrap_or(u32::MAX)),
            None => {}
        }
        if let Some(set) = t.get("set") {
            if stops {
                return Err(t
                    .src
                    .error(
                        ErrorKind::Invalid,
                        "a stopping event cannot change the state: the run ends there",
                        set.span(),
                    )
                    .with_hint("remove `set`, or make the event `action = \"record\"`"));
            }
            event = with_set(t, set, names, event)?;
        }
        events.push(event);
    }
    Ok(events)
}

/// `set = { vy = "-e*vy" }`: new positions and velocities from formulas of the state at the
/// event (all evaluated before any is assigned).
fn with_set(
    t: &Table<'_, '_>,
    set: &toml::Spanned<DeValue<'_>>,
    names: &NameContext<'_>,
    event: Event,
) -> Result<Event, ScenarioError> {
    let DeValue::Table(_) = set.get_ref() else {
        return Err(t.wrong_type("set", set, "a table such as { vy = \"-0.9*vy\" }"));
    };
    let sub = t.table("set")?.expect("set is a table");
    let kinematic = NameContext {
        level: VarLevel::Kinematic,
        ..*names
    };
    let dim = names.dim;
    let dof = dim * names.bodies.len() + names.planar.extras;
    let mut assignments: Vec<(usize, StateExpr)> = Vec::new();
    let mut described = Vec::new();
    for (key, value) in sub.entries {
        let target: &str = key.get_ref();
        let (index, want) = match kinematic.resolve(target) {
            Some(StateVar::Position(b, i)) => (body(b) * dim + i, Dimension::LENGTH),
            Some(StateVar::Velocity(b, i)) => (dof + body(b) * dim + i, Dimension::VELOCITY),
            Some(StateVar::Coordinate(i)) => (i, Dimension::NONE),
            Some(StateVar::CoordinateRate(i)) => (dof + i, Dimension::FREQUENCY),
            _ => {
                return Err(t
                    .src
                    .error(
                        ErrorKind::Invalid,
                        format!("`set` can change position and velocity components (x, vy, ball.vx), not `{target}`"),
                        key.span(),
                    )
                    .with_hint(if names.bodies.len() > 1 {
                        "with several bodies, write `body.vy`"
                    } else if dim == 1 {
                        "in 1-D the components are `x` and `v`, e.g. set = { v = \"-0.9*v\" }"
                    } else {
                        "e.g. set = { vy = \"-0.9*vy\" }"
                    }));
            }
        };
        if assignments.iter().any(|(j, _)| *j == index) {
            return Err(t.src.error(
                ErrorKind::Invalid,
                format!("`{target}` is set twice"),
                key.span(),
            ));
        }
        let (text, span) = match value.get_ref() {
            DeValue::String(s) => (s.to_string(), value.span()),
            DeValue::Integer(_) | DeValue::Float(_) => {
                let x: Real = match value.get_ref() {
                    DeValue::Integer(i) => i.as_str().parse().unwrap_or(Real::NAN),
                    DeValue::Float(f) => f.as_str().parse().unwrap_or(Real::NAN),
                    _ => unreachable!(),
                };
                (format!("{x:?}"), value.span())
            }
            _ => return Err(sub.wrong_type(target, value, "a formula such as \"-0.9*vy\"")),
        };
        let f = Formula::parse(&text).map_err(|e| formula_error(&t.src, &span, &e))?;
        let expr = names
            .compile(&f)
            .map_err(|e| formula_error(&t.src, &span, &e))?;
        f.expect_dimension_in(
            names.units,
            want,
            &format!("the new value of `{target}`"),
            &|n| names.dim_of(n),
            &|n| names.constant(n),
        )
        .map_err(|e| formula_error(&t.src, &span, &e))?;
        described.push(format!("{target} = {text}"));
        assignments.push((index, expr));
    }
    Ok(event
        .set(move |s, sys, y| {
            let values: Vec<Real> = assignments
                .iter()
                .map(|(_, e)| e.eval_sample(s, sys.dim(), sys.masses(), None))
                .collect();
            for ((i, _), v) in assignments.iter().zip(values) {
                y[*i] = v;
            }
        })
        .set_description(described.join(", ")))
}

fn body(b: BodyRef) -> usize {
    match b {
        BodyRef::Index(i) => i,
        BodyRef::Local => 0,
    }
}

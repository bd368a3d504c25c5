//! Values in scenario files: plain numbers (SI), quantities with units (`"9.8 m/s^2"`), or
//! formulas of the constants (`"g"`, `"2*k"`, `"m*g*Dmg"` with `m` the body's mass), each
//! checked against the dimension its key needs. In reduced units (`units = "reduced"`) every
//! value is a pure number and a quantity with a unit is refused.

use std::ops::Range;

use mechkit_expr::units::{Dimension, Quantity, UnitErrorKind, UnitSystem};
use mechkit_expr::{Dim, ExprError, ExprErrorKind, Formula, nearest};
use toml::de::DeValue;

use super::doc::{Source, Table, Value, type_name};
use super::error::{ErrorKind, ScenarioError};
use crate::Real;

/// A named constant: value in SI and dimension (unknown when given as a bare number).
pub(crate) type Constant = (String, Real, Dim);

/// What names a parameter value may use: the constants and, for a value that belongs to one
/// body (a drag coefficient), that body's mass `m`. `later` lists constants defined further
/// down the file, for the hint when one is used too early.
#[derive(Debug, Clone, Copy)]
pub(crate) struct ValueEnv<'c> {
    pub constants: &'c [Constant],
    pub mass: Option<Real>,
    pub later: &'c [&'c str],
}

impl ValueEnv<'_> {
    fn lookup(&self, name: &str) -> Option<(Real, Dim)> {
        if let Some((_, v, d)) = self.constants.iter().find(|(n, _, _)| n == name) {
            return Some((*v, *d));
        }
        match (name, self.mass) {
            ("m", Some(m)) => Some((m, Dim::Known(Dimension::MASS))),
            _ => None,
        }
    }

    fn candidates(&self) -> Vec<&str> {
        let mut c: Vec<&str> = self.constants.iter().map(|(n, _, _)| n.as_str()).collect();
        if self.mass.is_some() {
            c.push("m");
        }
        c
    }
}

/// The top-level `units` key: `"SI"` (the default) or `"reduced"`.
pub(crate) fn read_units(root: &Table<'_, '_>) -> Result<UnitSystem, ScenarioError> {
    let Some(v) = root.get("units") else {
        return Ok(UnitSystem::Si);
    };
    let DeValue::String(name) = v.get_ref() else {
        return Err(root.wrong_type("units", v, "a string, \"SI\" or \"reduced\""));
    };
    UnitSystem::from_name(name).ok_or_else(|| {
        root.src
            .error(
                ErrorKind::Invalid,
                format!("unknown unit system `{name}`"),
                v.span(),
            )
            .with_hint(
                "write `units = \"SI\"` (values with units, converted to SI; the default) or \
                 `units = \"reduced\"` (every value a pure number)",
            )
    })
}

/// Names a dimension for messages: "kg (mass)".
pub(crate) fn dim_text(d: Dimension) -> String {
    d.describe()
}

/// Converts an error in a formula inside a TOML string to a located scenario error.
pub(crate) fn formula_error(
    src: &Source<'_>,
    string_span: &Range<usize>,
    e: &ExprError,
) -> ScenarioError {
    let start = src.string_content_start(string_span);
    let kind = match e.kind {
        ExprErrorKind::Dimension { .. } => ErrorKind::Dimension,
        _ => ErrorKind::Formula,
    };
    let span = (start + e.span.start)..(start + e.span.end.max(e.span.start + 1));
    src.error(kind, e.message(), span).with_hint_opt(e.hint())
}

fn is_plain_number(text: &str) -> bool {
    text.trim().parse::<f64>().is_ok()
}

/// Resolves one value (a TOML number or a string) to SI, checking its dimension.
pub(crate) fn resolve(
    src: &Source<'_>,
    key: &str,
    v: &Value<'_>,
    want: Dimension,
    env: ValueEnv<'_>,
) -> Result<Real, ScenarioError> {
    let want_example = if src.units == UnitSystem::Reduced {
        "1.5"
    } else {
        example(want)
    };
    let (value, dim) = resolve_any(src, key, v, env).map_err(|e| {
        if e.kind == ErrorKind::WrongType {
            let got = e
                .message
                .rsplit_once("not ")
                .map_or("", |(_, t)| t)
                .to_string();
            src.error(
                ErrorKind::WrongType,
                format!(
                    "`{key}` must be a number or a string such as \"{want_example}\", not {got}"
                ),
                v.span(),
            )
            .with_hint(if src.units == UnitSystem::Reduced {
                format!("write `{key} = {want_example}` (the scenario is in reduced units)")
            } else {
                format!("write `{key} = \"{want_example}\"` (a plain number is in SI units)")
            })
        } else {
            e
        }
    })?;
    if want == Dimension::FREQUENCY
        && let DeValue::String(s) = v.get_ref()
        && let Some(message) = crate::values::hertz_for_an_angular_speed(&format!("`{key}`"), s)
    {
        return Err(src.error(ErrorKind::Dimension, message, v.span()));
    }
    match dim {
        Dim::Known(got) if got != want => {
            let text = match v.get_ref() {
                DeValue::String(s) => s.to_string(),
                _ => value.to_string(),
            };
            Err(src
                .error(
                    ErrorKind::Dimension,
                    format!(
                        "`{key}` must have dimension {}, but \"{text}\" has {}",
                        dim_text(want),
                        dim_text(got)
                    ),
                    v.span(),
                )
                .with_hint(format!("write it like \"{}\"", example(want))))
        }
        _ => Ok(value),
    }
}

/// Resolves one value to SI and says what dimension it has: a TOML number or a plain number
/// string is [`Dim::Unknown`] (SI, unit not stated), a quantity has its unit's dimension, a
/// formula has the dimension it computes. Non-finite values are refused.
pub(crate) fn resolve_any(
    src: &Source<'_>,
    key: &str,
    v: &Value<'_>,
    env: ValueEnv<'_>,
) -> Result<(Real, Dim), ScenarioError> {
    let (value, dim) = match v.get_ref() {
        DeValue::Integer(i) => (
            i64::from_str_radix(i.as_str(), i.radix()).map_err(|_| {
                src.error(
                    ErrorKind::Invalid,
                    format!("`{key}`: {i} is too large"),
                    v.span(),
                )
            })? as Real,
            Dim::Unknown,
        ),
        DeValue::Float(f) => (
            f.as_str().replace('_', "").parse::<Real>().map_err(|_| {
                src.error(
                    ErrorKind::Invalid,
                    format!("`{key}`: {f} is not a number"),
                    v.span(),
                )
            })?,
            Dim::Unknown,
        ),
        DeValue::String(s) => resolve_text(src, s, &v.span(), env)?,
        other => {
            return Err(src.error(
                ErrorKind::WrongType,
                format!(
                    "`{key}` must be a number or a string, not {}",
                    type_name(other)
                ),
                v.span(),
            ));
        }
    };
    if !value.is_finite() {
        return Err(src
            .error(
                ErrorKind::Invalid,
                format!("`{key}` is {value}, not a finite number"),
                v.span(),
            )
            .with_hint("every value must be a finite number"));
    }
    Ok((value, dim))
}

/// An example value of a dimension, for hints.
pub(crate) fn example(want: Dimension) -> &'static str {
    match want {
        d if d == Dimension::MASS => "1.5 kg",
        d if d == Dimension::LENGTH => "2.4 m",
        d if d == Dimension::TIME => "10 s",
        d if d == Dimension::VELOCITY => "3 m/s",
        d if d == Dimension::ACCELERATION => "9.81 m/s^2",
        d if d == Dimension::FORCE => "5 N",
        d if d == Dimension::STIFFNESS => "100 N/m",
        d if d == Dimension::LINEAR_DRAG => "0.1 kg/s",
        d if d == Dimension::QUADRATIC_DRAG => "0.01 kg/m",
        d if d == Dimension::GRAVITATIONAL_PARAMETER => "3.986e14 m^3/s^2",
        d if d == Dimension::MOMENT_OF_INERTIA => "0.5 kg*m^2",
        d if d == Dimension::MASS / Dimension::LENGTH => "0.2 kg/m",
        d if d == Dimension::MASS / Dimension::LENGTH.powi(2) => "7.8 kg/m^2",
        d if d == Dimension::MASS / Dimension::LENGTH.powi(3) => "7800 kg/m^3",
        _ => "1.0",
    }
}

/// A string value: a quantity (`"9.8 m/s^2"`), a plain number (`"4.0"`), or a formula of the
/// constants (`"2*k"`). Which one is decided so that a typo gets the right error: a string
/// that starts with a number and does not read as a formula is a quantity, and a unit error
/// is reported as such.
fn resolve_text(
    src: &Source<'_>,
    text: &str,
    span: &Range<usize>,
    env: ValueEnv<'_>,
) -> Result<(Real, Dim), ScenarioError> {
    let start = src.string_content_start(span);
    let located = |s: mechkit_expr::Span| (start + s.start)..(start + s.end.max(s.start + 1));
    match Quantity::parse(text) {
        Ok(q) if is_plain_number(text) => Ok((q.value, Dim::Unknown)),
        Ok(_) if src.units == UnitSystem::Reduced => Err(reduced_with_unit(src, text, start)),
        Ok(q) => Ok((q.value, Dim::Known(q.dim))),
        Err(unit_error) => {
            if matches!(unit_error.kind, UnitErrorKind::NoNumber) || Formula::parse(text).is_ok() {
                return resolve_formula(src, text, span, env);
            }
            let mut e = src.error(
                ErrorKind::Unit,
                unit_error.message(),
                located(unit_error.span),
            );
            e.hint = unit_error.hint();
            if let UnitErrorKind::UnknownUnit { name, .. } = &unit_error.kind
                && env.lookup(name).is_some()
            {
                e.hint = Some(format!(
                    "`{name}` here reads as a unit; to multiply by the constant `{name}` write \"{}\"",
                    text.replacen(' ', "*", 1)
                ));
            }
            Err(e)
        }
    }
}

/// A quantity with a unit (`"2.5 m"`) in a scenario in reduced units, located at the unit.
fn reduced_with_unit(src: &Source<'_>, text: &str, start: usize) -> ScenarioError {
    let at = Quantity::unit_start(text).unwrap_or(0);
    let (number, unit) = (text[..at].trim(), text[at..].trim_end());
    src.error(
        ErrorKind::Unit,
        format!(
            "the scenario is in reduced units (`units = \"reduced\"`), so values are pure numbers, \
             but this one has the unit `{unit}`"
        ),
        (start + at)..(start + at + unit.len().max(1)),
    )
    .with_hint(format!(
        "write the number alone (`{number}`) in the scenario's reduced units, or remove \
         `units = \"reduced\"` to give values with SI units"
    ))
}

fn resolve_formula(
    src: &Source<'_>,
    text: &str,
    span: &Range<usize>,
    env: ValueEnv<'_>,
) -> Result<(Real, Dim), ScenarioError> {
    let f = Formula::parse(text).map_err(|e| formula_error(src, span, &e))?;
    for name in f.names() {
        if env.lookup(name).is_none() && mechkit_expr::builtin_constant(name).is_none() {
            let context = if env.later.contains(&name) {
                format!(
                    "`{name}` is defined further down; a constant may only use the constants above it"
                )
            } else if mechkit_expr::units::Unit::parse(name).is_ok() {
                format!(
                    "`{name}` is a unit: a value is a number followed by its unit, e.g. \"1 {name}\""
                )
            } else if env.mass.is_some() {
                "values may use the constants and `m`, the mass of the body".into()
            } else {
                "values may use the constants defined in [constants]".into()
            };
            let kind = ExprErrorKind::UndefinedName {
                name: name.to_string(),
                suggestions: nearest(name, env.candidates()),
                context: Some(context),
            };
            let e = f.error(kind, f.span_of(name).unwrap_or(f.full_span()));
            return Err(formula_error(src, span, &e));
        }
    }
    let value_of = |n: &str| env.lookup(n).map(|(v, _)| v);
    let d = f
        .dimension_with(
            &|n| env.lookup(n).map_or(Dim::Unknown, |(_, d)| d),
            &value_of,
        )
        .map_err(|e| formula_error(src, span, &e))?;
    let value = f
        .eval_with(&value_of)
        .map_err(|e| formula_error(src, span, &e))?;
    Ok((value, if d == Dim::Literal { Dim::Unknown } else { d }))
}

/// An optional scalar parameter.
pub(crate) fn scalar(
    t: &Table<'_, '_>,
    key: &str,
    want: Dimension,
    env: ValueEnv<'_>,
) -> Result<Option<Real>, ScenarioError> {
    t.get(key)
        .map(|v| resolve(&t.src, key, v, want, env))
        .transpose()
}

/// A required scalar parameter.
pub(crate) fn required_scalar(
    t: &Table<'_, '_>,
    key: &str,
    want: Dimension,
    env: ValueEnv<'_>,
) -> Result<Real, ScenarioError> {
    scalar(t, key, want, env)?.ok_or_else(|| t.missing(key, &format!("\"{}\"", example(want))))
}

/// A vector parameter: an array of `dim` values, one value in 1-D, or in 2-D a polar
/// `{ magnitude = …, angle = … }` (angle from the x axis towards y).
pub(crate) fn vector(
    t: &Table<'_, '_>,
    key: &str,
    want: Dimension,
    dim: usize,
    env: ValueEnv<'_>,
) -> Result<Option<Vec<Real>>, ScenarioError> {
    let Some(v) = t.get(key) else {
        return Ok(None);
    };
    let src = &t.src;
    let hint = || {
        let one = format!("\"{}\"", example(want));
        match dim {
            1 => format!("write `{key} = {one}`"),
            2 => format!(
                "write `{key} = [{one}, {one}]` or `{key} = {{ magnitude = {one}, angle = \"30 deg\" }}`"
            ),
            _ => format!("write `{key} = [{one}, {one}, {one}]`"),
        }
    };
    match v.get_ref() {
        DeValue::Array(items) => {
            if items.len() != dim {
                return Err(t
                    .component_count(key, items.len(), dim, v.span())
                    .with_hint(hint()));
            }
            items
                .iter()
                .map(|item| resolve(src, key, item, want, env))
                .collect::<Result<Vec<_>, _>>()
                .map(Some)
        }
        DeValue::Table(polar) if dim == 2 => {
            let p = Table::new(*src, polar, v.span(), format!("`{key}`"));
            p.check_keys(&["magnitude", "angle"])?;
            let r = required_scalar(&p, "magnitude", want, env)?;
            let a = required_scalar(&p, "angle", Dimension::NONE, env)?;
            Ok(Some(vec![r * a.cos(), r * a.sin()]))
        }
        _ if dim == 1 => resolve(src, key, v, want, env).map(|x| Some(vec![x])),
        other => Err(src
            .error(
                ErrorKind::WrongType,
                format!(
                    "`{key}` must be a list of {dim} values, not {}",
                    type_name(other)
                ),
                v.span(),
            )
            .with_hint(hint())),
    }
}

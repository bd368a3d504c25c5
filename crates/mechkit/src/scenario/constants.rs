//! `[constants]`: named values, each resolved with its dimension in file order, so a constant
//! may use the ones before it; a sweep's parameters replace values as they are read.

use super::doc::Table;
use super::error::{ErrorKind, ScenarioError};
use super::sweep::{ConstantOverride, unknown_override};
use super::values::{Constant, ValueEnv, resolve_any};

/// The `[constants]` table; names in `reserved` are refused (the state names of a scenario).
pub(crate) fn constants(
    root: &Table<'_, '_>,
    reserved: &[&str],
) -> Result<Vec<Constant>, ScenarioError> {
    constants_with(root, reserved, &[])
}

/// [`constants`], with the values of `overrides` in place of those in the file; every later
/// constant, body and force that uses them sees the new value.
pub(crate) fn constants_with(
    root: &Table<'_, '_>,
    reserved: &[&str],
    overrides: &[ConstantOverride],
) -> Result<Vec<Constant>, ScenarioError> {
    let Some(t) = root.table("constants")? else {
        if let Some(o) = overrides.first() {
            return Err(unknown_override(o, &[]));
        }
        return Ok(Vec::new());
    };
    let names: Vec<&str> = t
        .entries
        .iter()
        .map(|(k, _)| k.get_ref().as_ref())
        .collect();
    let mut out: Vec<Constant> = Vec::new();
    for (i, (key, value)) in t.entries.iter().enumerate() {
        let name: &str = key.get_ref();
        let valid = name
            .chars()
            .next()
            .is_some_and(|c| c.is_alphabetic() || c == '_')
            && name.chars().all(|c| c.is_alphanumeric() || c == '_');
        if !valid {
            return Err(t.src.error(
                ErrorKind::Invalid,
                format!(
                    "constant name `{name}` must be a letter or `_` followed by letters, digits or `_`"
                ),
                key.span(),
            ));
        }
        if reserved.contains(&name) || mechkit_expr::Func::from_name(name).is_some() {
            return Err(t
                .src
                .error(
                    ErrorKind::Invalid,
                    format!(
                        "`{name}` cannot be a constant: formulas use it for the state or as a function"
                    ),
                    key.span(),
                )
                .with_hint(format!("choose another name, e.g. `{name}0`")));
        }
        let env = ValueEnv {
            constants: &out,
            mass: None,
            later: &names[i..],
        };
        let (mut v, mut d) = resolve_any(&t.src, name, value, env)?;
        if let Some(o) = overrides.iter().find(|o| o.name == name) {
            if let Some(given) = o.dim
                && t.src.units == mechkit_expr::units::UnitSystem::Reduced
            {
                return Err(ScenarioError::new(
                    ErrorKind::Unit,
                    format!(
                        "the value given for `{name}` in --set has units ({}), but the scenario \
                         is in reduced units (`units = \"reduced\"`)",
                        given.describe()
                    ),
                )
                .with_hint(format!("give `{name}` as a pure number, e.g. `{name}=1.5`")));
            }
            (v, d) = o.apply(d)?;
        }
        out.push((name.to_string(), v, d));
    }
    if let Some(o) = overrides
        .iter()
        .find(|o| !out.iter().any(|(n, _, _)| *n == o.name))
    {
        return Err(unknown_override(o, &names));
    }
    Ok(out)
}

//! The dimensions of typed values: a point at which a variable of known dimension is taken
//! (`--at "2 s"` for a time, not `"3 kg"`), and the units of the `--set` values in a formula
//! (θ = `c*t` with `c = 1 kg` is no angle). A bare number or a formula of the names has no
//! unit of its own (SI) and fits any dimension.

use mechkit_expr::units::{Dimension, Quantity};
use mechkit_expr::{Dim, Formula};

use super::{Params, ValueError, fail, split_top_level, value};
use crate::Real;

/// As [`value`], for an input of dimension `dim`: a quantity with units must have it.
///
/// ```
/// use mechkit::units::Dimension;
/// use mechkit::values::value_of;
/// assert_eq!(value_of("2 ms", "--at", &[], Dimension::TIME).unwrap(), 0.002);
/// assert_eq!(value_of("2*b", "--at", &[("b".into(), 1.5)], Dimension::TIME).unwrap(), 3.0);
/// let e = value_of("3 kg", "--at", &[], Dimension::TIME).unwrap_err();
/// assert!(e.message.contains("but s (time) is needed"), "{e}");
/// ```
///
/// # Errors
/// As [`value`]; a quantity of another dimension.
pub fn value_of(
    text: &str,
    what: &str,
    params: &Params,
    dim: Dimension,
) -> Result<Real, ValueError> {
    if let Some(d) = dimension(text)
        && d != dim
    {
        return Err(fail(
            what,
            format!(
                "{what}: `{}` is {}, but {} is needed: give it in {} (a plain number is taken in {})",
                text.trim(),
                d.describe(),
                dim.describe(),
                unit(dim),
                unit(dim)
            ),
        ));
    }
    value(text, what, params)
}

/// The dimension of a value typed with units (`"3 kg"`); `None` for a bare number or a formula.
pub fn dimension(text: &str) -> Option<Dimension> {
    Quantity::parse(text.trim())
        .ok()
        .map(|q| q.dim)
        .filter(|d| !d.is_none())
}

/// The dimension of each `name=value` item of a `--set` list given with units (`None` for a
/// bare number or a formula), in order.
pub fn param_dimensions(set: &str) -> Vec<(String, Option<Dimension>)> {
    split_top_level(set, ',')
        .into_iter()
        .filter_map(|item| item.split_once('='))
        .map(|(k, v)| (k.trim().to_string(), dimension(v)))
        .collect()
}

/// The SI unit of a dimension, as a message writes it (`s`, `1/s`, `kg*m/s^2` → `N`).
fn unit(d: Dimension) -> String {
    if d.is_none() {
        return "a plain number".into();
    }
    // an angular velocity as often as a frequency: not Hz
    if d == Dimension::FREQUENCY {
        return d.to_string();
    }
    d.derived_symbol()
        .map_or_else(|| d.to_string(), str::to_string)
}

/// Checks the formula `text` (`what`, e.g. "θ(t)") against the units its names were given in:
/// the variable `var` of dimension `var_dim` (when known: its own, as a time `t`, or typed at
/// the flag `var_flag`, which is then named when its unit is at fault), the `--set` names with units (`set`,
/// from [`param_dimensions`]; `params` their values), and the dimension `want` the formula must
/// have (when known). A `--set` value whose unit makes it fail is refused by name, with the
/// unit that fits where one does. A formula that fails for no `--set` value's sake passes: its
/// bare numbers are SI values whose units are not known (`θ = t^2`), so only units the user
/// typed can contradict it.
///
/// ```
/// use mechkit::units::Dimension;
/// use mechkit::values::{check_formula_units, param_dimensions};
/// let set = param_dimensions("c=1 kg");
/// let e = check_formula_units("c*t", "θ(t)", ("t", Some(Dimension::TIME), None), &set,
///     &[("c".into(), 1.0)], Some(Dimension::NONE)).unwrap_err();
/// assert_eq!(e.input, "--set");
/// assert!(e.message.contains("give c in 1/s"), "{e}");
/// let set = param_dimensions("c=1 Hz");
/// assert!(check_formula_units("c*t", "θ(t)", ("t", Some(Dimension::TIME), None), &set,
///     &[("c".into(), 1.0)], Some(Dimension::NONE)).is_ok());
/// ```
///
/// # Errors
/// A formula whose dimensions do not fit, by the `--set` value at fault where one is.
pub fn check_formula_units(
    text: &str,
    what: &str,
    (var, var_dim, var_flag): (&str, Option<Dimension>, Option<&str>),
    set: &[(String, Option<Dimension>)],
    params: &Params,
    want: Option<Dimension>,
) -> Result<(), ValueError> {
    let Ok(formula) = Formula::parse(text) else {
        // the formula's own errors are reported where it is read
        return Ok(());
    };
    let values = |n: &str| params.iter().find(|(k, _)| k == n).map(|(_, v)| *v);
    // the dimension of each name, one of them (`changed`) taken as another
    let dimension_of = |changed: Option<(&str, Dim)>| {
        let dims = move |n: &str| match changed {
            Some((name, d)) if name == n => d,
            _ if n == var => var_dim.map_or(Dim::Unknown, Dim::Known),
            _ => set
                .iter()
                .rev()
                .find(|(k, _)| k == n)
                .and_then(|(_, d)| *d)
                .map_or(Dim::Unknown, Dim::Known),
        };
        match want {
            Some(w) => formula
                .expect_dimension(w, what, &dims, &values)
                .map(|()| Dim::Known(w)),
            None => formula.dimension_with(&dims, &values),
        }
    };
    let Err(e) = dimension_of(None) else {
        return Ok(());
    };
    // the value at fault: the one whose unit, forgotten, lets the formula pass
    let typed = set
        .iter()
        .filter_map(|(k, d)| d.map(|d| (k.as_str(), d, "--set")))
        .chain(var_dim.zip(var_flag).map(|(d, flag)| (var, d, flag)));
    for (name, d, flag) in typed {
        if dimension_of(Some((name, Dim::Unknown))).is_err() {
            continue;
        }
        // the unit that fits: what is left with the name dimensionless, if that passes
        let fit = want.and_then(|w| {
            let dims = |n: &str| {
                if n == name {
                    Dim::NONE
                } else if n == var {
                    var_dim.map_or(Dim::Unknown, Dim::Known)
                } else {
                    set.iter()
                        .rev()
                        .find(|(k, _)| k == n)
                        .and_then(|(_, d)| *d)
                        .map_or(Dim::Unknown, Dim::Known)
                }
            };
            let rest = formula.dimension_with(&dims, &values).ok()?.known()?;
            let fit = w / rest;
            dimension_of(Some((name, Dim::Known(fit))))
                .is_ok()
                .then_some(fit)
        });
        let hint = fit.map_or_else(
            || format!("give {name} in units that fit, or as a plain number (SI)"),
            |f| format!("give {name} in {}", unit(f)),
        );
        let given = if flag == "--set" {
            format!("--set {name}: `{name}`")
        } else {
            format!("{flag}: the variable {name}")
        };
        return Err(fail(
            flag,
            format!(
                "{given} is given in {} ({}), which does not fit {what} = `{}`: {}; {hint}",
                unit(d),
                d.describe(),
                text.trim(),
                e.message()
            ),
        ));
    }
    Ok(())
}

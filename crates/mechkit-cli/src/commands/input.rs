//! Values typed on the command line: quantities with units (`"2 eV"`), constant formulas
//! (`2*pi`, `b/4` with `--set b=1`), intervals `A:B`, and `name=value` lists.

use anyhow::{Result, anyhow, bail};
use mechkit::calculus::Params;
use mechkit::expr::units::{Dimension, Quantity};
use mechkit::values;

/// `--set a=1,b=2 m,th=pi/6` as names and SI values ([`mechkit::values::params`]).
pub fn params(set: Option<&str>) -> Result<Vec<(String, f64)>> {
    Ok(match set {
        Some(s) => values::params(s)?,
        None => Vec::new(),
    })
}

/// [`mechkit::values::value`]: a number, a quantity, a formula of the `--set` names, `inf`.
pub fn value(text: &str, what: &str, params: &Params) -> Result<f64> {
    Ok(values::value(text, what, params)?)
}

/// [`mechkit::values::quantity`]: a quantity of dimension `dim` (a bare number in SI).
pub fn quantity(text: &str, what: &str, dim: Dimension) -> Result<f64> {
    Ok(values::quantity(text, what, dim)?)
}

/// [`mechkit::values::interval`]: `A:B`.
pub fn interval(text: &str, flag: &str, params: &Params) -> Result<(f64, f64)> {
    Ok(values::interval(text, flag, params)?)
}

/// [`mechkit::values::increasing_interval`]: `A:B` with `A < B`.
pub fn increasing_interval(text: &str, flag: &str, params: &Params) -> Result<(f64, f64)> {
    Ok(values::increasing_interval(text, flag, params)?)
}

/// A number as the CSV files write it: shortest round-trip digits, in exponent form when
/// that is shorter (`1e15`, `1e-31`).
pub fn show(x: f64) -> String {
    let mut s = String::new();
    mechkit::scenario::push_number(&mut s, x);
    s
}

pub use mechkit::values::split_top_level;

/// A number with fixed decimals for aligned text (`{:.N}`), in exponent form from `1e16` up
/// (`mechkit_expr::short_fixed`): never hundreds of digits.
pub use mechkit::expr::short_fixed as fixed;

/// `--in UNIT`: the unit's size in SI and its text, checked to have dimension `dim` (a unit
/// alone, "pm", is one of it; with `plain_ok` a bare number is a multiple of SI). `text` is
/// (default unit, what the unit must be, examples) for the default and the error.
pub fn output_unit(
    unit: Option<&str>,
    dim: Dimension,
    text: (&str, &str, &str),
    plain_ok: bool,
) -> Result<(f64, String)> {
    let (default, must_be, examples) = text;
    let Some(u) = unit else {
        return Ok((1.0, default.to_string()));
    };
    let q = Quantity::parse(u)
        .or_else(|_| Quantity::parse(&format!("1 {u}")))
        .map_err(|e| anyhow!("--in: {e}"))?;
    let fits = q.dim == dim || (plain_ok && q.dim.is_none());
    if !(fits && q.value > 0.0 && q.value.is_finite()) {
        bail!("--in `{u}` must be {must_be}, e.g. {examples}");
    }
    Ok((q.value, u.to_string()))
}

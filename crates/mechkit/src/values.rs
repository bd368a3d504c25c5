//! Values a user types: quantities with units (`"2 eV"`), constant formulas (`2*pi`, `b/4`
//! with `b` given), `name=value` lists (`"m=2 kg, th=pi/6"`), intervals `A:B` and vectors
//! (`"3, -1 m/s"`). One parser of each, used by every front (the CLI's flags, Python's
//! keyword arguments), and fuzzed (`crates/mechkit-fuzz`, target `values`).
//!
//! Errors are [`ValueError`]s: the input they are about (a flag such as `--range`, or a
//! name) and a message that says what was expected.
//!
//! ```
//! use mechkit::values;
//!
//! let p = values::params("m=2 kg, th=30 deg, h=2*m/4").unwrap();
//! assert_eq!(p[0], ("m".to_string(), 2.0));
//! assert!((p[1].1 - std::f64::consts::PI / 6.0).abs() < 1e-15);
//! assert_eq!(p[2].1, 1.0);
//! assert_eq!(values::interval("-1:b", "--range", &[("b".into(), 2.0)]).unwrap(), (-1.0, 2.0));
//! let v = values::vector("3, -1 m/s", "--v1", mechkit::units::Dimension::VELOCITY).unwrap();
//! assert_eq!(v, [3.0, -1.0]);
//! ```

use mechkit_expr::Sym;
use mechkit_expr::units::{Dimension, Quantity};

use crate::Real;

mod dims;

pub use dims::{check_formula_units, dimension, param_dimensions, value_of};

/// Names and SI values (`--set`, `[constants]` overrides).
pub type Params = [(String, Real)];

/// A value that could not be read.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{message}")]
pub struct ValueError {
    /// The input it is about: a flag (`--range`), a name (`m`), as the caller called it.
    pub input: String,
    /// What is wrong and what would fix it (it names the input).
    pub message: String,
}

fn fail(input: &str, message: String) -> ValueError {
    ValueError {
        input: input.to_string(),
        message,
    }
}

/// Reads `name=value` items separated by commas (outside parentheses): each value as in
/// [`value`], so it may be a quantity (`2 kg`, `30 deg`) or a formula of `pi`, `e` and the
/// names given before it (`th=pi/6`, `h=2*m/4`).
///
/// # Errors
/// An item that is not `name=value`, a name that is not a name, a value that does not read.
pub fn params(text: &str) -> Result<Vec<(String, Real)>, ValueError> {
    let mut out: Vec<(String, Real)> = Vec::new();
    for item in split_top_level(text, ',')
        .into_iter()
        .filter(|s| !s.is_empty())
    {
        let Some((name, v)) = item.split_once('=') else {
            return Err(fail(
                "--set",
                format!("--set: `{item}` is not `name=value` (e.g. `a=1`, `m=2 kg`, `th=pi/6`)"),
            ));
        };
        let name = name.trim();
        let is_name = name
            .chars()
            .next()
            .is_some_and(|c| c.is_alphabetic() || c == '_')
            && name.chars().all(|c| c.is_alphanumeric() || c == '_');
        if !is_name {
            return Err(fail(
                "--set",
                format!("--set: `{name}` is not a name (letters, digits and _, e.g. `v0`)"),
            ));
        }
        let x = value(v, name, &out).map_err(|e| ValueError {
            input: name.to_string(),
            message: format!("--set {}", e.message),
        })?;
        match out.iter_mut().find(|(k, _)| k == name) {
            Some(slot) => slot.1 = x,
            None => out.push((name.to_string(), x)),
        }
    }
    Ok(out)
}

/// A number, a quantity with units (converted to SI), a formula of the `params` names and
/// `pi`/`e` (`2*pi`, `b/4`), or `inf`/`-inf` (for integration limits). `what` names the input
/// in the error.
///
/// # Errors
/// Text that is none of these, a name without a value, a value that is not finite.
pub fn value(text: &str, what: &str, params: &Params) -> Result<Real, ValueError> {
    let bare = text.trim();
    let (sign, magnitude) = match bare.strip_prefix('-') {
        Some(rest) => (-1.0, rest.trim()),
        None => (1.0, bare.strip_prefix('+').unwrap_or(bare).trim()),
    };
    if ["inf", "infinity", "∞"].contains(&magnitude.to_ascii_lowercase().as_str()) {
        return Ok(sign * Real::INFINITY);
    }
    let quantity_error = match Quantity::parse(bare) {
        Ok(q) if q.value.is_finite() => return Ok(q.value),
        Ok(q) => format!("`{text}` is {}, not a finite number", q.value),
        Err(e) => e.to_string(),
    };
    if let Ok(sym) = Sym::parse(bare) {
        let env = |n: &str| params.iter().find(|(k, _)| k == n).map(|(_, v)| *v);
        match sym.eval(&env) {
            Ok(v) if v.is_finite() => return Ok(v),
            Ok(v) => {
                return Err(fail(
                    what,
                    format!("{what}: `{text}` is {v}, not a finite number"),
                ));
            }
            Err(name) if !name.is_empty() && text.contains(name.as_str()) => {
                return Err(fail(
                    what,
                    format!(
                        "{what}: `{text}` uses `{name}`, which has no value: give it with --set {name}=…"
                    ),
                ));
            }
            Err(_) => {}
        }
    }
    Err(fail(what, format!("{what}: {quantity_error}")))
}

/// A quantity of dimension `dim`: a bare number (SI), or a value with units of that dimension
/// (`"20 kW"` for a power). `what` names the input in the error.
///
/// # Errors
/// Text that does not read as a quantity, or one of another dimension.
pub fn quantity(text: &str, what: &str, dim: Dimension) -> Result<Real, ValueError> {
    let q = Quantity::parse(text).map_err(|e| fail(what, format!("{what}: {e}")))?;
    if dim == Dimension::FREQUENCY
        && let Some(message) = hertz_for_an_angular_speed(what, text)
    {
        return Err(fail(what, message));
    }
    if !q.dim.is_none() && q.dim != dim {
        return Err(fail(
            what,
            format!(
                "{what} `{text}` has the dimension {}, but {} is needed (a plain number is taken in {})",
                q.dim.describe(),
                dim.describe(),
                dim.derived_symbol()
                    .map_or_else(|| dim.to_string(), str::to_string)
            ),
        ));
    }
    Ok(q.value)
}

/// Units of angle, alone or in a rate (`rpm`, `rev/s`, `deg/s`, `rad/s`).
pub(crate) const ANGLES: &[&str] = &[
    "rad",
    "deg",
    "°",
    "rev",
    "rpm",
    "degree",
    "degrees",
    "revolution",
    "revolutions",
];

/// Units of frequency in cycles per second.
pub(crate) const HERTZ: &[&str] = &["Hz", "kHz", "MHz", "GHz", "hertz"];

/// Whether `text` names one of `units` as a whole word (`rpm` in `"3000 rpm"`, `Hz` in
/// `"1/s*Hz"`, not in `"Hzz"`).
pub(crate) fn names_a_unit(text: &str, units: &[&str]) -> bool {
    text.split(|c: char| !(c.is_alphanumeric() || c == '°'))
        .any(|word| units.contains(&word))
}

/// Every input of dimension 1/s in mechkit is an angular speed (`omega`, `--angular-speed`),
/// in rad/s: a value written in Hz (cycles per second) would be taken 2π too small, as
/// `rad` counts as 1. The message that refuses it, or `None` when `text` is not in Hz.
pub fn hertz_for_an_angular_speed(what: &str, text: &str) -> Option<String> {
    names_a_unit(text, HERTZ).then(|| {
        format!(
            "{what} `{}` is in Hz (cycles per second), but {what} is an angular speed (rad/s), 2π times the rate of turning: write turns per second as `rev/s` (50 Hz is `50 rev/s` = 314.16 rad/s) or the value in rad/s",
            crate::expr::span::clip(text)
        )
    })
}

/// A vector of 1 to 3 components separated by commas, each a quantity of `dim` or a bare
/// number; a unit written once after the last component applies to the bare ones
/// (`"3, -1 m/s"`).
///
/// # Errors
/// No component or more than three, an empty one, or one that is not a quantity of `dim`.
pub fn vector(text: &str, what: &str, dim: Dimension) -> Result<Vec<Real>, ValueError> {
    let items = split_top_level(text, ',');
    if items.len() > 3 || items.iter().any(|p| p.is_empty()) {
        return Err(fail(
            what,
            format!(
                "{what} `{text}`: give 1, 2 or 3 components separated by commas, e.g. \"3 m/s, -1 m/s\" or \"3, -1 m/s\""
            ),
        ));
    }
    let last = items[items.len() - 1];
    let unit = last
        .trim_start_matches(|c: char| c.is_ascii_digit() || "+-.eE ".contains(c))
        .trim();
    items
        .iter()
        .map(|c| {
            if c.parse::<Real>().is_ok() && !unit.is_empty() && !unit.starts_with('(') {
                quantity(&format!("{c} {unit}"), what, dim)
            } else {
                quantity(c, what, dim)
            }
        })
        .collect()
}

/// Checks that the two ends of an interval, each `(input, text)` (`("--from", "1 m")`), share
/// a dimension when both carry units: `--from "1 m" --to "2 s"` has no meaning. A bare number
/// or a formula has no unit of its own (SI), and fits any.
///
/// ```
/// use mechkit::values::same_dimension;
/// assert!(same_dimension(("--from", "1 m"), ("--to", "2 km")).is_ok());
/// assert!(same_dimension(("--from", "1 m"), ("--to", "2")).is_ok());
/// let e = same_dimension(("--from", "1 m"), ("--to", "2 s")).unwrap_err();
/// assert_eq!(e.input, "--from");
/// assert!(e.message.starts_with("--from `1 m` and --to `2 s` have different dimensions"));
/// ```
///
/// # Errors
/// Two ends with units of different dimensions.
pub fn same_dimension(a: (&str, &str), b: (&str, &str)) -> Result<(), ValueError> {
    let dim = |t: &str| {
        Quantity::parse(t)
            .ok()
            .map(|q| q.dim)
            .filter(|d| !d.is_none())
    };
    match (dim(a.1), dim(b.1)) {
        (Some(da), Some(db)) if da != db => Err(fail(
            a.0,
            format!(
                "{} `{}` and {} `{}` have different dimensions ({} and {}): the ends of an \
                 interval are values of one quantity; give both in units of the same dimension",
                a.0,
                a.1.trim(),
                b.0,
                b.1.trim(),
                da.describe(),
                db.describe()
            ),
        )),
        _ => Ok(()),
    }
}

/// `A:B` (each end as in [`value`]); `flag` names the input in errors.
///
/// # Errors
/// Text without one colon outside parentheses, an end that does not read, equal ends, ends
/// with units of different dimensions ([`same_dimension`]).
pub fn interval(text: &str, flag: &str, params: &Params) -> Result<(Real, Real), ValueError> {
    let Some((a, b)) = split_interval(text) else {
        return Err(fail(
            flag,
            format!("{flag} takes an interval A:B, e.g. {flag} 0:10 or {flag} -1:2, not `{text}`"),
        ));
    };
    let at = |t: &str, end: &str| {
        value(t, &format!("{flag} {end}"), params).map_err(|e| ValueError {
            input: flag.to_string(),
            ..e
        })
    };
    same_dimension((&format!("{flag} start"), a), (&format!("{flag} end"), b)).map_err(|e| {
        ValueError {
            input: flag.to_string(),
            ..e
        }
    })?;
    let (a, b) = (at(a, "start")?, at(b, "end")?);
    if a == b {
        return Err(fail(
            flag,
            format!("{flag} {text}: the interval is empty; give two different ends"),
        ));
    }
    Ok((a, b))
}

/// `A:B` with `A < B`: a range to scan or plot, where a reversed one is a slip, refused with
/// the ends swapped as the example (an oriented interval, such as the limits of an integral or
/// a path's parameter, is [`interval`]).
///
/// # Errors
/// As [`interval`], and a decreasing range.
pub fn increasing_interval(
    text: &str,
    flag: &str,
    params: &Params,
) -> Result<(Real, Real), ValueError> {
    let (a, b) = interval(text, flag, params)?;
    if a > b {
        let (start, end) = split_interval(text).unwrap_or((text, text));
        return Err(fail(
            flag,
            format!(
                "{flag} {text}: the range must be increasing (its start below its end), e.g. {flag} {}:{}",
                end.trim(),
                start.trim()
            ),
        ));
    }
    Ok((a, b))
}

/// Splits `A:B` at the one colon outside parentheses.
fn split_interval(text: &str) -> Option<(&str, &str)> {
    let mut depth = 0i32;
    for (i, c) in text.char_indices() {
        match c {
            '(' => depth += 1,
            ')' => depth -= 1,
            ':' if depth == 0 => return Some((&text[..i], &text[i + 1..])),
            _ => {}
        }
    }
    None
}

/// A number of pixels: `"240"`, `"240 px"`, `"240 pixels"`.
///
/// ```
/// assert_eq!(mechkit::values::pixels("240 px", "--origin").unwrap(), 240.0);
/// assert!(mechkit::values::pixels("2 m", "--origin").is_err());
/// ```
///
/// # Errors
/// Text that is not a finite number, with or without the unit.
pub fn pixels(text: &str, what: &str) -> Result<Real, ValueError> {
    let t = text.trim();
    let number = ["pixels", "pixel", "px"]
        .iter()
        .find_map(|u| t.strip_suffix(u))
        .unwrap_or(t)
        .trim();
    match number.parse::<Real>() {
        Ok(v) if v.is_finite() => Ok(v),
        _ => Err(fail(
            what,
            format!("{what}: `{text}` is not a number of pixels (write e.g. 240 or \"240 px\")"),
        )),
    }
}

/// The side of a pixel (m) from a known length measured in pixels and in units: `"240 px =
/// 12 cm"`, either way round; or from the two parts, `pixels` and `length`, given apart.
///
/// ```
/// let s = mechkit::values::pixel_scale("12 cm = 240 px", "--scale").unwrap();
/// assert!((s - 0.0005).abs() < 1e-15);
/// ```
///
/// # Errors
/// Text without one side in pixels and the other in units, or a count of pixels that is not
/// positive.
pub fn pixel_scale(text: &str, what: &str) -> Result<Real, ValueError> {
    let usage = || {
        fail(
            what,
            format!(
                "{what} takes a known length in pixels and in units, e.g. \"240 px = 12 cm\", \
                 not `{text}`"
            ),
        )
    };
    let (a, b) = text.split_once('=').ok_or_else(usage)?;
    let is_pixels = |s: &str| s.trim().ends_with("px") || s.trim().ends_with("pixels");
    match (is_pixels(a), is_pixels(b)) {
        (true, false) => pixels_to_length(
            pixels(a, what)?,
            quantity(b, what, Dimension::LENGTH)?,
            what,
        ),
        (false, true) => pixels_to_length(
            pixels(b, what)?,
            quantity(a, what, Dimension::LENGTH)?,
            what,
        ),
        _ => Err(usage()),
    }
}

/// The side of a pixel when `px` pixels measure `length` metres.
///
/// # Errors
/// A count of pixels that is not positive.
pub fn pixels_to_length(px: Real, length: Real, what: &str) -> Result<Real, ValueError> {
    if px > 0.0 {
        Ok(length / px)
    } else {
        Err(fail(
            what,
            format!(
                "{what}: the number of pixels must be positive, not {}",
                crate::error::short(px)
            ),
        ))
    }
}

/// A coordinate in an image: a length when the image has a scale (`scaled`), else a number
/// of pixels; `scale_inputs` names the inputs that give a scale, for the error.
///
/// # Errors
/// Not a length (with a scale), a length without a scale, or not a number of pixels.
pub fn image_coordinate(
    text: &str,
    what: &str,
    scaled: bool,
    scale_inputs: &str,
) -> Result<Real, ValueError> {
    if scaled {
        return quantity(text, what, Dimension::LENGTH);
    }
    if Quantity::parse(text).is_ok_and(|q| !q.dim.is_none()) {
        return Err(fail(
            what,
            format!(
                "{what} `{text}` is a length, but the image has no scale: give {scale_inputs}, \
                 or the point in pixels"
            ),
        ));
    }
    pixels(text, what)
}

/// Splits a list at `sep` outside parentheses and brackets (`"atan2(y, x), 0"` has two
/// items), each trimmed.
pub fn split_top_level(text: &str, sep: char) -> Vec<&str> {
    let mut out = Vec::new();
    let (mut depth, mut start) = (0i32, 0);
    for (i, c) in text.char_indices() {
        match c {
            '(' | '[' => depth += 1,
            ')' | ']' => depth -= 1,
            c if c == sep && depth == 0 => {
                out.push(text[start..i].trim());
                start = i + c.len_utf8();
            }
            _ => {}
        }
    }
    out.push(text[start..].trim());
    out
}

#[cfg(test)]
mod tests;

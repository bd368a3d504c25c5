//! Values typed on the command line: quantities with units (`"2 eV"`), constant formulas
//! (`2*pi`, `b/4` with `--set b=1`), intervals `A:B`, and `name=value` lists.

use anyhow::{Result, anyhow, bail};
use mechkit::calculus::{self, Params};
use mechkit::expr::Sym;
use mechkit::expr::units::{Dimension, Quantity};

/// `--set a=1,b=2 m` as names and SI values.
pub fn params(set: Option<&str>) -> Result<Vec<(String, f64)>> {
    Ok(match set {
        Some(s) => calculus::parse_params(s).map_err(|e| anyhow!("--set: {e}"))?,
        None => Vec::new(),
    })
}

/// A number, a quantity with units (converted to SI), a formula of the `--set` names and
/// `pi`/`e` (`2*pi`, `b/4`), or `inf`/`-inf` (for integration limits). `what` names the flag
/// in the error.
pub fn value(text: &str, what: &str, params: &Params) -> Result<f64> {
    let bare = text.trim();
    let (sign, magnitude) = match bare.strip_prefix('-') {
        Some(rest) => (-1.0, rest.trim()),
        None => (1.0, bare.strip_prefix('+').unwrap_or(bare).trim()),
    };
    if ["inf", "infinity", "∞"].contains(&magnitude.to_ascii_lowercase().as_str()) {
        return Ok(sign * f64::INFINITY);
    }
    let quantity_error = match calculus::parse_params(&format!("{what}={text}")) {
        Ok(v) => return Ok(v[0].1),
        Err(e) => e,
    };
    if let Ok(sym) = Sym::parse(text) {
        let env = |n: &str| params.iter().find(|(k, _)| k == n).map(|(_, v)| *v);
        match sym.eval(&env) {
            Ok(v) if v.is_finite() => return Ok(v),
            Ok(v) => bail!("{what}: `{text}` is {v}, not a finite number"),
            Err(name) if !name.is_empty() && text.contains(name.as_str()) => bail!(
                "{what}: `{text}` uses `{name}`, which has no value: give it with --set {name}=…"
            ),
            Err(_) => {}
        }
    }
    bail!("{what}: {quantity_error}")
}

/// A quantity of dimension `dim`: a bare number (SI), or a value with units of that dimension
/// (`"20 kW"` for a power). `what` names the flag in the error.
pub fn quantity(text: &str, what: &str, dim: Dimension) -> Result<f64> {
    let q = Quantity::parse(text).map_err(|e| anyhow!("{what}: {e}"))?;
    if !q.dim.is_none() && q.dim != dim {
        bail!(
            "{what} `{text}` has the dimension {}, but {} is needed (a plain number is taken in {})",
            q.dim.describe(),
            dim.describe(),
            dim.derived_symbol()
                .map_or_else(|| dim.to_string(), str::to_string)
        );
    }
    Ok(q.value)
}

/// `A:B` (each end as in [`value`]); `flag` names the option in errors.
pub fn interval(text: &str, flag: &str, params: &Params) -> Result<(f64, f64)> {
    let Some((a, b)) = split_interval(text) else {
        bail!("{flag} takes an interval A:B, e.g. {flag} 0:10 or {flag} -1:2, not `{text}`");
    };
    let (a, b) = (
        value(a, &format!("{flag} start"), params)?,
        value(b, &format!("{flag} end"), params)?,
    );
    if a == b {
        bail!("{flag} {text}: the interval is empty; give two different ends");
    }
    Ok((a, b))
}

/// `A:B` with `A < B`: a range to scan or plot, where a reversed one is a slip, refused with
/// the ends swapped as the example (an oriented interval, such as the limits of an integral or
/// a path's parameter, is [`interval`]).
pub fn increasing_interval(text: &str, flag: &str, params: &Params) -> Result<(f64, f64)> {
    let (a, b) = interval(text, flag, params)?;
    if a > b {
        let (start, end) = split_interval(text).unwrap_or((text, text));
        bail!(
            "{flag} {text}: the range must be increasing (its start below its end), e.g. {flag} {}:{}",
            end.trim(),
            start.trim()
        );
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

/// A number as the CSV files write it: shortest round-trip digits, in exponent form when
/// that is shorter (`1e15`, `1e-31`).
pub fn show(x: f64) -> String {
    let mut s = String::new();
    mechkit::scenario::push_number(&mut s, x);
    s
}

/// Splits a list at commas outside parentheses (`"atan2(y, x), 0"` has two items).
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values() {
        let p = vec![("b".to_string(), 2.0)];
        assert_eq!(value("3", "--x", &p).unwrap(), 3.0);
        assert!((value("60 km/h", "--v", &p).unwrap() - 16.666_666_666_666_668).abs() < 1e-12);
        assert_eq!(value("b/4", "--to", &p).unwrap(), 0.5);
        assert!((value("2*pi", "--to", &p).unwrap() - std::f64::consts::TAU).abs() < 1e-15);
        let e = value("c/4", "--to", &p).unwrap_err().to_string();
        assert!(e.contains("--set c="), "{e}");
        assert_eq!(interval("-1:2", "--range", &p).unwrap(), (-1.0, 2.0));
        assert_eq!(value("-inf", "--from", &p).unwrap(), f64::NEG_INFINITY);
        assert_eq!(value("∞", "--to", &p).unwrap(), f64::INFINITY);
        assert!(interval("1", "--range", &p).is_err());
        // issue 11: a reversed range is refused, an oriented interval is not
        assert_eq!(interval("2:1", "--param", &p).unwrap(), (2.0, 1.0));
        let e = increasing_interval("2:-1", "--range", &p)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("must be increasing") && e.contains("--range -1:2"),
            "{e}"
        );
        assert_eq!(split_top_level("atan2(y, x), 0", ','), ["atan2(y, x)", "0"]);
    }
}

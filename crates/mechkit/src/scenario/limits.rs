//! Resource limits: how large a scenario file may be and how much output a run may write.
//!
//! A run that reaches its output limit stops cleanly with `stop_reason = "output_limit"` (the
//! files hold everything up to there) and a message that says how to raise the limit.

use toml::de::DeValue;

use super::doc::Table;
use super::error::{ErrorKind, ScenarioError};

/// The largest scenario file read: 16 MB. Scenarios are a few kilobytes; anything near this
/// is not a scenario (a data file or a binary given by mistake).
pub const MAX_SCENARIO_BYTES: u64 = 16_000_000;

/// Output a run may write unless the scenario (`[output] max_size`) or the command line
/// (`--max-output`) says otherwise: 1 GB, far more than a plot or a spreadsheet can use.
pub const DEFAULT_MAX_OUTPUT: u64 = 1_000_000_000;

const SIZE_UNITS: &[(&str, u64)] = &[
    ("B", 1),
    ("kB", 1_000),
    ("KB", 1_000),
    ("MB", 1_000_000),
    ("GB", 1_000_000_000),
    ("TB", 1_000_000_000_000),
    ("KiB", 1 << 10),
    ("MiB", 1 << 20),
    ("GiB", 1 << 30),
    ("TiB", 1 << 40),
];

/// Parses a size in bytes: `"500 MB"`, `"2GB"`, `"1.5 GiB"`, or a bare number of bytes.
/// The error says what is accepted.
/// ```
/// use mechkit::scenario::parse_size;
/// assert_eq!(parse_size("2 GB"), Ok(2_000_000_000));
/// assert_eq!(parse_size("1.5 KiB"), Ok(1536));
/// assert!(parse_size("2 GG").is_err());
/// ```
pub fn parse_size(text: &str) -> Result<u64, String> {
    let text = text.trim();
    let split = text
        .find(|c: char| !(c.is_ascii_digit() || c == '.' || c == 'e' || c == 'E' || c == '+'))
        .unwrap_or(text.len());
    let (number, unit) = (text[..split].trim(), text[split..].trim());
    let expected = "a size such as \"500 MB\", \"2 GB\" or \"1 GiB\" (units B, kB, MB, GB, TB, KiB, MiB, GiB, TiB)";
    let value: f64 = number
        .parse()
        .map_err(|_| format!("`{text}` is not a size: expected {expected}"))?;
    let factor = if unit.is_empty() {
        1
    } else {
        SIZE_UNITS
            .iter()
            .find(|(u, _)| *u == unit)
            .map(|&(_, f)| f)
            .ok_or_else(|| format!("`{unit}` is not a unit of size: expected {expected}"))?
    };
    let bytes = value * factor as f64;
    if !(1.0..1.8e19).contains(&bytes) {
        return Err(format!(
            "`{text}` is not a usable size: it must be at least 1 byte and below 18 EB"
        ));
    }
    Ok(bytes.round() as u64)
}

pub use crate::csv::format_size;

/// `[output] max_size`: a string size or an integer number of bytes.
pub(crate) fn read_max_size(output: Option<&Table<'_, '_>>) -> Result<Option<u64>, ScenarioError> {
    let Some(t) = output else { return Ok(None) };
    let Some(v) = t.get("max_size") else {
        return Ok(None);
    };
    match v.get_ref() {
        DeValue::String(text) => parse_size(text).map(Some).map_err(|m| {
            t.src
                .error(ErrorKind::Invalid, format!("`max_size`: {m}"), v.span())
        }),
        DeValue::Integer(_) => Ok(t.count("max_size")?.map(|(n, _)| n.max(1))),
        _ => Err(t.wrong_type(
            "max_size",
            v,
            "a size such as \"500 MB\" or a whole number of bytes",
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_round_trip_through_the_decimal_units() {
        assert_eq!(parse_size("1000"), Ok(1000));
        assert_eq!(parse_size(" 250 MB "), Ok(250_000_000));
        assert_eq!(parse_size("2e3 kB"), Ok(2_000_000));
        assert_eq!(format_size(1_000_000_000), "1 GB");
        assert_eq!(format_size(12_500), "12.5 kB");
        assert_eq!(format_size(999), "999 B");
        for text in ["", "MB", "-1 MB", "0", "1 XB", "nan GB", "1e30 TB"] {
            assert!(parse_size(text).is_err(), "{text:?} was accepted");
        }
    }
}

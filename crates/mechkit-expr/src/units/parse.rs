//! The parser of unit expressions: `km/h`, `N*m^2`, `s^2/m^2`, `1/s`, `kg m s⁻¹`, `N/m^1.5`,
//! `m^(3/2)`.
//!
//! A power is a whole number, a short decimal or a fraction in parentheses (`^2`, `^-1`,
//! `^1.5`, `^(3/2)`, `^(-1/2)`), between -12 and 12, exactly a fraction p/q with q at most
//! [`MAX_WRITTEN_DENOMINATOR`]; exponents compose exactly (`(m^12)^12` is `m^144`), and a unit
//! whose exponents or size leave the exact or floating-point range is an error.

use super::dimension::Dimension;
use super::quantity::{Unit, UnitError, UnitErrorKind};
use super::ratio::{MAX_WRITTEN_DENOMINATOR, Ratio};
use super::table::{known_misspelling, lookup, suggestion_candidates};
use crate::span::Span;
use crate::suggest::nearest;

/// Parses the unit expression of `source` that starts at byte `start` and runs to the end.
pub(crate) fn parse_unit_at(source: &str, start: usize) -> Result<Unit, UnitError> {
    let mut p = UnitParser {
        src: source,
        pos: start,
        depth: 0,
    };
    p.skip_ws();
    if p.pos >= source.len() {
        return Err(p.err(
            UnitErrorKind::Syntax("a unit".into()),
            Span::new(start, source.len()),
        ));
    }
    let unit = p.product()?;
    p.skip_ws();
    if p.pos < source.len() {
        let c = p.peek().unwrap_or(' ');
        return Err(p.err(
            UnitErrorKind::Syntax(format!("`*`, `/` or the end of the unit, found `{c}`")),
            Span::new(p.pos, p.pos + c.len_utf8()),
        ));
    }
    Ok(unit)
}

struct UnitParser<'a> {
    src: &'a str,
    pos: usize,
    depth: usize,
}

fn is_unit_char(c: char) -> bool {
    c.is_alphabetic() || c == '°' || c == 'Ω' || c == 'µ' || c == 'μ' || c == 'Å'
}

impl<'a> UnitParser<'a> {
    fn peek(&self) -> Option<char> {
        self.src[self.pos..].chars().next()
    }

    fn skip_ws(&mut self) {
        while let Some(c) = self.peek().filter(|c| c.is_whitespace()) {
            self.pos += c.len_utf8();
        }
    }

    fn err(&self, kind: UnitErrorKind, span: Span) -> UnitError {
        UnitError {
            kind,
            span,
            source: self.src.to_string(),
        }
    }

    /// `acc` times (or divided by) `rhs`, the operand that started at byte `start`.
    fn combine(&self, acc: Unit, rhs: Unit, divide: bool, start: usize) -> Result<Unit, UnitError> {
        let (factor, dim) = if divide {
            (acc.factor / rhs.factor, acc.dim.checked_div(rhs.dim))
        } else {
            (acc.factor * rhs.factor, acc.dim.checked_mul(rhs.dim))
        };
        self.finish(factor, dim, start)
    }

    /// A unit of this size and dimension, or an error at `start..pos` if either is out of range.
    fn finish(
        &self,
        factor: f64,
        dim: Result<Dimension, super::DimensionError>,
        start: usize,
    ) -> Result<Unit, UnitError> {
        let span = Span::new(start, self.pos.max(start + 1).min(self.src.len()));
        let dim = dim.map_err(|e| self.err(UnitErrorKind::TooLarge(e.to_string()), span))?;
        if !(factor.is_finite() && factor > 0.0) {
            return Err(self.err(
                UnitErrorKind::TooLarge(format!(
                    "the unit is too {} to hold in floating point (its size in SI is {factor})",
                    if factor > 1.0 { "large" } else { "small" }
                )),
                span,
            ));
        }
        Ok(Unit { factor, dim })
    }

    /// product := power (('*' | '·' | ' ' | '/') power)*
    fn product(&mut self) -> Result<Unit, UnitError> {
        let mut acc = self.power()?;
        loop {
            let save = self.pos;
            self.skip_ws();
            let start = self.pos;
            match self.peek() {
                Some('*' | '·' | '×') => {
                    self.pos += self.peek().map_or(1, char::len_utf8);
                    let rhs = self.power()?;
                    acc = self.combine(acc, rhs, false, start)?;
                }
                Some('/') => {
                    self.pos += 1;
                    let rhs = self.power()?;
                    acc = self.combine(acc, rhs, true, start)?;
                }
                Some(c) if save != self.pos && (is_unit_char(c) || c == '(') => {
                    // juxtaposition after a space: "N m"
                    let rhs = self.power()?;
                    acc = self.combine(acc, rhs, false, start)?;
                }
                _ => {
                    self.pos = save;
                    return Ok(acc);
                }
            }
        }
    }

    /// power := atom ('^' exponent | '**' exponent | '²' | '³' | '⁻¹')?
    fn power(&mut self) -> Result<Unit, UnitError> {
        self.skip_ws();
        let start = self.pos;
        let base = self.atom()?;
        let n = match self.peek() {
            Some('^') => {
                self.pos += 1;
                self.exponent()?
            }
            Some('*') if self.src[self.pos..].starts_with("**") => {
                self.pos += 2;
                self.exponent()?
            }
            Some('²') => {
                self.pos += '²'.len_utf8();
                Ratio::int(2)
            }
            Some('³') => {
                self.pos += '³'.len_utf8();
                Ratio::int(3)
            }
            _ if self.src[self.pos..].starts_with("⁻¹") => {
                self.pos += "⁻¹".len();
                Ratio::int(-1)
            }
            _ => return Ok(base),
        };
        let factor = if n.is_integer() {
            base.factor.powi(n.num())
        } else {
            base.factor.powf(n.to_f64())
        };
        self.finish(factor, base.dim.pow_rational(n), start)
    }

    /// exponent := number | '(' number ('/' digits)? ')', number := [+-]digits['.'digits]
    fn exponent(&mut self) -> Result<Ratio, UnitError> {
        let start = self.pos;
        let parens = self.peek() == Some('(');
        if parens {
            self.pos += 1;
            self.skip_ws();
        }
        let number = self.take_number();
        if number.is_empty() {
            let found = self
                .peek()
                .map_or("the end".to_string(), |c| format!("`{c}`"));
            return Err(self.err(
                UnitErrorKind::Power {
                    message: format!("expected a number after `^`, found {found}"),
                    hint: "a power is a whole number, a decimal or a fraction: `m^2`, `m^-1`, \
                           `m^1.5`, `m^(3/2)`"
                        .into(),
                },
                Span::new(start, self.pos.max(start + 1).min(self.src.len())),
            ));
        }
        let mut denominator = None;
        if parens {
            self.skip_ws();
            if self.peek() == Some('/') {
                self.pos += 1;
                self.skip_ws();
                denominator = Some(self.take_number());
            }
            self.skip_ws();
            if self.peek() == Some(')') {
                self.pos += 1;
            } else {
                return Err(self.err(
                    UnitErrorKind::Syntax("`)` after the power".into()),
                    Span::new(self.pos, self.pos),
                ));
            }
        }
        let span = Span::new(start, self.pos.max(start + 1).min(self.src.len()));
        let written = &self.src[start..self.pos];
        let bad = |message: String, hint: &str| {
            self.err(
                UnitErrorKind::Power {
                    message,
                    hint: hint.to_string(),
                },
                span,
            )
        };
        let value = match denominator {
            None => Ratio::parse_decimal(number).ok_or_else(|| {
                bad(
                    format!("the power `{number}` is not a short decimal"),
                    "write the power as a fraction in parentheses, e.g. `m^(1/3)`",
                )
            })?,
            Some(den) => {
                let whole = |t: &str| {
                    t.trim_start_matches(['-', '+'])
                        .bytes()
                        .all(|b| b.is_ascii_digit())
                        .then(|| t.parse::<i64>().ok())
                        .flatten()
                };
                let (Some(p), Some(q)) = (whole(number), whole(den).filter(|q| *q > 0)) else {
                    return Err(bad(
                        format!("the power `{written}` is not a fraction of whole numbers"),
                        "write a fraction as `(p/q)` with whole numbers and q > 0, e.g. `m^(3/2)` or `m^(-1/2)`",
                    ));
                };
                Ratio::new(p, q).ok_or_else(|| {
                    bad(
                        format!("the power `{written}` is too large"),
                        "powers in a unit lie between -12 and 12",
                    )
                })?
            }
        };
        if i64::from(value.den()) > MAX_WRITTEN_DENOMINATOR {
            return Err(bad(
                format!(
                    "the power `{written}` is {value}: a power in a unit must be a fraction p/q with q at most {MAX_WRITTEN_DENOMINATOR}"
                ),
                "write the fraction you mean in parentheses, e.g. `m^(1/3)` rather than `m^0.333333`",
            ));
        }
        if value.num().unsigned_abs() > 12 * value.den().unsigned_abs() {
            return Err(bad(
                format!("the power `{written}` is out of range"),
                "powers in a unit lie between -12 and 12; for larger ones raise a parenthesised unit, e.g. `(m^12)^2`",
            ));
        }
        if !parens && self.peek() == Some('/') && value.is_integer() {
            let rest = &self.src[self.pos + 1..];
            let digits = rest.len() - rest.trim_start_matches(|c: char| c.is_ascii_digit()).len();
            if digits > 0 {
                let q = &rest[..digits];
                return Err(self.err(
                    UnitErrorKind::Power {
                        message: format!(
                            "`^{number}/{q}` reads as a power {number} divided by {q}: a fractional power needs parentheses"
                        ),
                        hint: format!("write `^({number}/{q})`"),
                    },
                    Span::new(start, self.pos + 1 + digits),
                ));
            }
        }
        Ok(value)
    }

    /// Takes `[+-]digits['.'digits]` (possibly malformed; checked by the caller) and returns it.
    fn take_number(&mut self) -> &'a str {
        let start = self.pos;
        if matches!(self.peek(), Some('-' | '+')) {
            self.pos += 1;
        }
        while self.peek().is_some_and(|c| c.is_ascii_digit() || c == '.') {
            self.pos += 1;
        }
        &self.src[start..self.pos]
    }

    fn atom(&mut self) -> Result<Unit, UnitError> {
        self.skip_ws();
        let start = self.pos;
        match self.peek() {
            Some('(') => {
                self.depth += 1;
                if self.depth > 16 {
                    return Err(self.err(
                        UnitErrorKind::Syntax("less nesting".into()),
                        Span::new(start, start + 1),
                    ));
                }
                self.pos += 1;
                let inner = self.product()?;
                self.skip_ws();
                if self.peek() != Some(')') {
                    return Err(self.err(
                        UnitErrorKind::Syntax("`)`".into()),
                        Span::new(self.pos, self.pos),
                    ));
                }
                self.pos += 1;
                self.depth -= 1;
                Ok(inner)
            }
            Some('1') => {
                self.pos += 1;
                Ok(Unit {
                    factor: 1.0,
                    dim: Dimension::NONE,
                })
            }
            Some(c) if is_unit_char(c) => {
                while self.peek().is_some_and(is_unit_char) {
                    self.pos += self.peek().map_or(1, char::len_utf8);
                }
                let name = &self.src[start..self.pos];
                match lookup(name) {
                    Some((factor, dim)) => Ok(Unit { factor, dim }),
                    None => Err(self.unknown(name, Span::new(start, self.pos))),
                }
            }
            Some(c) => Err(self.err(
                UnitErrorKind::Syntax(format!("a unit name, found `{c}`")),
                Span::new(start, start + c.len_utf8()),
            )),
            None => Err(self.err(
                UnitErrorKind::Syntax("a unit name".into()),
                Span::new(start, start),
            )),
        }
    }

    fn unknown(&self, name: &str, span: Span) -> UnitError {
        let mut suggestions: Vec<String> = known_misspelling(name)
            .map(str::to_string)
            .into_iter()
            .collect();
        if suggestions.is_empty() {
            // Two units run together, e.g. "kgm" for "kg*m".
            for split in 1..name.len() {
                if name.is_char_boundary(split) {
                    let (a, b) = name.split_at(split);
                    if lookup(a).is_some() && lookup(b).is_some() {
                        suggestions.push(format!("{a}*{b}"));
                        break;
                    }
                }
            }
        }
        let candidates = suggestion_candidates();
        for s in nearest(name, candidates.iter().map(String::as_str)) {
            if !suggestions.contains(&s) {
                suggestions.push(s);
            }
        }
        suggestions.truncate(3);
        self.err(
            UnitErrorKind::UnknownUnit {
                name: name.to_string(),
                suggestions,
            },
            span,
        )
    }
}

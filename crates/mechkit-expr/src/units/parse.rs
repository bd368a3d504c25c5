//! The parser of unit expressions: `km/h`, `N*m^2`, `s^2/m^2`, `1/s`, `kg m s⁻¹`.

use super::dimension::Dimension;
use super::quantity::{Unit, UnitError, UnitErrorKind};
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

impl UnitParser<'_> {
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

    /// product := power (('*' | '·' | ' ' | '/') power)*
    fn product(&mut self) -> Result<Unit, UnitError> {
        let mut acc = self.power()?;
        loop {
            let save = self.pos;
            self.skip_ws();
            match self.peek() {
                Some('*' | '·' | '×') => {
                    self.pos += self.peek().map_or(1, char::len_utf8);
                    let rhs = self.power()?;
                    acc = Unit {
                        factor: acc.factor * rhs.factor,
                        dim: acc.dim * rhs.dim,
                    };
                }
                Some('/') => {
                    self.pos += 1;
                    let rhs = self.power()?;
                    acc = Unit {
                        factor: acc.factor / rhs.factor,
                        dim: acc.dim / rhs.dim,
                    };
                }
                Some(c) if save != self.pos && (is_unit_char(c) || c == '(') => {
                    // juxtaposition after a space: "N m"
                    let rhs = self.power()?;
                    acc = Unit {
                        factor: acc.factor * rhs.factor,
                        dim: acc.dim * rhs.dim,
                    };
                }
                _ => {
                    self.pos = save;
                    return Ok(acc);
                }
            }
        }
    }

    /// power := atom ('^' int | '²' | '³' | '⁻¹')?
    fn power(&mut self) -> Result<Unit, UnitError> {
        let base = self.atom()?;
        let n = match self.peek() {
            Some('^') => {
                self.pos += 1;
                self.integer()?
            }
            Some('*') if self.src[self.pos..].starts_with("**") => {
                self.pos += 2;
                self.integer()?
            }
            Some('²') => {
                self.pos += '²'.len_utf8();
                2
            }
            Some('³') => {
                self.pos += '³'.len_utf8();
                3
            }
            _ if self.src[self.pos..].starts_with("⁻¹") => {
                self.pos += "⁻¹".len();
                -1
            }
            _ => return Ok(base),
        };
        Ok(Unit {
            factor: base.factor.powi(n),
            dim: base.dim.powi(n),
        })
    }

    fn integer(&mut self) -> Result<i32, UnitError> {
        let start = self.pos;
        let parens = self.peek() == Some('(');
        if parens {
            self.pos += 1;
        }
        let num_start = self.pos;
        if matches!(self.peek(), Some('-' | '+')) {
            self.pos += 1;
        }
        while self.peek().is_some_and(|c| c.is_ascii_digit()) {
            self.pos += 1;
        }
        let value: Option<i32> = self.src[num_start..self.pos]
            .parse()
            .ok()
            .filter(|n: &i32| n.abs() <= 12);
        if parens {
            if self.peek() == Some(')') {
                self.pos += 1;
            } else {
                return Err(self.err(
                    UnitErrorKind::Syntax("`)`".into()),
                    Span::new(self.pos, self.pos),
                ));
            }
        }
        value.ok_or_else(|| {
            self.err(
                UnitErrorKind::Syntax("a whole-number power between -12 and 12 after `^`".into()),
                Span::new(start, self.pos.max(start + 1).min(self.src.len())),
            )
        })
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

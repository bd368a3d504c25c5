//! Splits formula text into tokens, each with its byte span.

use crate::error::{ExprError, ExprErrorKind};
use crate::span::Span;

/// A token kind.
#[derive(Debug, Clone, PartialEq)]
pub enum Tok {
    /// A number literal, e.g. `1.5e-9`.
    Num(f64),
    /// A name, possibly dotted: `x`, `feather.vx`.
    Ident(String),
    /// `+`
    Plus,
    /// `-`
    Minus,
    /// `*`
    Star,
    /// `/`
    Slash,
    /// `^` or `**`
    Caret,
    /// `(`
    LParen,
    /// `)`
    RParen,
    /// `,`
    Comma,
    /// `<`
    Lt,
    /// `<=`
    Le,
    /// `>`
    Gt,
    /// `>=`
    Ge,
    /// `==`
    EqEq,
    /// `!=`
    Ne,
    /// `and`, `&&`
    And,
    /// `or`, `||`
    Or,
    /// `not`, `!`
    Not,
}

impl Tok {
    /// How the token reads in an error message.
    pub fn describe(&self) -> String {
        match self {
            Tok::Num(x) => format!("number `{}`", crate::short_number(*x)),
            Tok::Ident(s) => format!("name `{s}`"),
            Tok::Plus => "`+`".into(),
            Tok::Minus => "`-`".into(),
            Tok::Star => "`*`".into(),
            Tok::Slash => "`/`".into(),
            Tok::Caret => "`^`".into(),
            Tok::LParen => "`(`".into(),
            Tok::RParen => "`)`".into(),
            Tok::Comma => "`,`".into(),
            Tok::Lt => "`<`".into(),
            Tok::Le => "`<=`".into(),
            Tok::Gt => "`>`".into(),
            Tok::Ge => "`>=`".into(),
            Tok::EqEq => "`==`".into(),
            Tok::Ne => "`!=`".into(),
            Tok::And => "`and`".into(),
            Tok::Or => "`or`".into(),
            Tok::Not => "`not`".into(),
        }
    }
}

/// A token and where it is.
#[derive(Debug, Clone, PartialEq)]
pub struct Token {
    /// What it is.
    pub tok: Tok,
    /// Where it is.
    pub span: Span,
}

fn is_ident_start(c: char) -> bool {
    c.is_alphabetic() || c == '_'
}

fn is_ident_continue(c: char) -> bool {
    c.is_alphanumeric() || c == '_'
}

/// Splits `src` into tokens.
pub fn tokenize(src: &str) -> Result<Vec<Token>, ExprError> {
    let mut out = Vec::new();
    let bytes = src.as_bytes();
    let mut chars = src.char_indices().peekable();
    while let Some(&(i, c)) = chars.peek() {
        if c.is_whitespace() {
            chars.next();
            continue;
        }
        if c.is_ascii_digit() || (c == '.' && bytes.get(i + 1).is_some_and(u8::is_ascii_digit)) {
            let end = number_end(bytes, i);
            let text = &src[i..end];
            let value: f64 = text.parse().map_err(|_| {
                ExprError::new(
                    ExprErrorKind::BadNumber(text.to_string()),
                    Span::new(i, end),
                    src,
                )
            })?;
            if value.is_infinite() {
                return Err(ExprError::new(
                    ExprErrorKind::NumberTooLarge(text.to_string()),
                    Span::new(i, end),
                    src,
                ));
            }
            out.push(Token {
                tok: Tok::Num(value),
                span: Span::new(i, end),
            });
            while chars.peek().is_some_and(|&(j, _)| j < end) {
                chars.next();
            }
            continue;
        }
        if is_ident_start(c) {
            let mut end = i;
            // dotted names: segment(.segment)*
            loop {
                while let Some(&(j, d)) = chars.peek() {
                    if is_ident_continue(d) {
                        end = j + d.len_utf8();
                        chars.next();
                    } else {
                        break;
                    }
                }
                let dot_then_ident = chars.peek().is_some_and(|&(_, d)| d == '.')
                    && src[end + 1..].chars().next().is_some_and(is_ident_start);
                if dot_then_ident {
                    chars.next();
                    end += 1;
                } else {
                    break;
                }
            }
            let word = &src[i..end];
            let tok = match word {
                "and" => Tok::And,
                "or" => Tok::Or,
                "not" => Tok::Not,
                _ => Tok::Ident(word.to_string()),
            };
            out.push(Token {
                tok,
                span: Span::new(i, end),
            });
            continue;
        }
        chars.next();
        let next = chars.peek().map(|&(_, d)| d);
        let (tok, len) = match (c, next) {
            ('*', Some('*')) => (Tok::Caret, 2),
            ('<', Some('=')) => (Tok::Le, 2),
            ('>', Some('=')) => (Tok::Ge, 2),
            ('=', Some('=')) => (Tok::EqEq, 2),
            ('!', Some('=')) => (Tok::Ne, 2),
            ('&', Some('&')) => (Tok::And, 2),
            ('|', Some('|')) => (Tok::Or, 2),
            ('+', _) => (Tok::Plus, 1),
            ('-' | '−', _) => (Tok::Minus, 1),
            ('*' | '·' | '×', _) => (Tok::Star, 1),
            ('/', _) => (Tok::Slash, 1),
            ('^', _) => (Tok::Caret, 1),
            ('(', _) => (Tok::LParen, 1),
            (')', _) => (Tok::RParen, 1),
            (',', _) => (Tok::Comma, 1),
            ('<', _) => (Tok::Lt, 1),
            ('>', _) => (Tok::Gt, 1),
            ('!', _) => (Tok::Not, 1),
            _ => {
                let span = Span::new(i, i + c.len_utf8());
                let kind = if c == '=' {
                    ExprErrorKind::SingleEquals
                } else {
                    ExprErrorKind::UnexpectedChar(c)
                };
                return Err(ExprError::new(kind, span, src));
            }
        };
        if len == 2 {
            chars.next();
        }
        let width = if len == 2 {
            1 + next.map_or(0, char::len_utf8)
        } else {
            c.len_utf8()
        };
        out.push(Token {
            tok,
            span: Span::new(i, i + width),
        });
    }
    Ok(out)
}

/// End of a number literal starting at `start`: digits, one `.`, an exponent `e±digits`.
fn number_end(b: &[u8], start: usize) -> usize {
    let mut i = start;
    while i < b.len() && b[i].is_ascii_digit() {
        i += 1;
    }
    if i < b.len() && b[i] == b'.' {
        i += 1;
        while i < b.len() && b[i].is_ascii_digit() {
            i += 1;
        }
    }
    if i < b.len() && (b[i] == b'e' || b[i] == b'E') {
        let mut j = i + 1;
        if j < b.len() && (b[j] == b'+' || b[j] == b'-') {
            j += 1;
        }
        if j < b.len() && b[j].is_ascii_digit() {
            while j < b.len() && b[j].is_ascii_digit() {
                j += 1;
            }
            i = j;
        }
    }
    i
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(src: &str) -> Vec<Tok> {
        tokenize(src).unwrap().into_iter().map(|t| t.tok).collect()
    }

    /// Issue 26: `1e309*x` read the number as infinity; it is refused at its column.
    #[test]
    fn issue_026_a_number_too_large_for_a_double_is_refused_at_its_column() {
        let e = tokenize("2*x + 1e309").unwrap_err();
        assert!(
            matches!(e.kind, ExprErrorKind::NumberTooLarge(ref n) if n == "1e309"),
            "{e}"
        );
        assert_eq!((e.span.start, e.span.end), (6, 11));
        assert!(tokenize("1.7e308*x").is_ok());
        // a number too small for a double is 0 (or subnormal), as in every language
        assert_eq!(kinds("1e-400"), vec![Tok::Num(0.0)]);
    }

    #[test]
    fn numbers_and_names() {
        assert_eq!(
            kinds("1e-9*feather.vx"),
            vec![Tok::Num(1e-9), Tok::Star, Tok::Ident("feather.vx".into())]
        );
        assert_eq!(kinds(".5"), vec![Tok::Num(0.5)]);
        assert_eq!(kinds("2.e3"), vec![Tok::Num(2000.0)]);
    }

    #[test]
    fn operators() {
        assert_eq!(
            kinds("a**2 <= b && !c"),
            vec![
                Tok::Ident("a".into()),
                Tok::Caret,
                Tok::Num(2.0),
                Tok::Le,
                Tok::Ident("b".into()),
                Tok::And,
                Tok::Not,
                Tok::Ident("c".into())
            ]
        );
    }

    #[test]
    fn number_followed_by_e_name() {
        // `2e` is not an exponent: the number is 2 and `e` is a name.
        assert_eq!(kinds("2e"), vec![Tok::Num(2.0), Tok::Ident("e".into())]);
    }

    #[test]
    fn bad_character_is_located() {
        let err = tokenize("x + $").unwrap_err();
        assert_eq!(err.span, Span::new(4, 5));
    }
}

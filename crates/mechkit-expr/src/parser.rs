//! Pratt parser: tokens to [`Expr`], recording where each name occurs.

use crate::ast::{BinOp, Expr, Func};
use crate::error::{ExprError, ExprErrorKind};
use crate::lexer::{Tok, Token, tokenize};
use crate::span::Span;
use crate::suggest::nearest;

/// Unary minus binds tighter than `*` and looser than `^`: `-x^2 = -(x^2)`.
const PREC_NEG: u8 = 7;
/// `not` binds looser than comparisons: `not x < 1 = not (x < 1)`.
const PREC_NOT: u8 = 3;
/// Deeper nesting than this is refused rather than risking the stack.
const MAX_DEPTH: usize = 200;

/// The result of parsing: the tree and where each name occurs in the text.
#[derive(Debug, Clone)]
pub struct Parsed {
    /// The expression.
    pub expr: Expr,
    /// Every name used as a value, with its span, in reading order.
    pub names: Vec<(String, Span)>,
}

/// Parses `src` into an expression.
pub fn parse(src: &str) -> Result<Parsed, ExprError> {
    let tokens = tokenize(src)?;
    if tokens.is_empty() {
        return Err(ExprError::new(
            ExprErrorKind::Empty,
            Span::new(0, src.len()),
            src,
        ));
    }
    let mut p = Parser {
        src,
        tokens,
        pos: 0,
        names: Vec::new(),
        depth: 0,
    };
    let expr = p.expr(0)?;
    if let Some(t) = p.peek() {
        let t = t.clone();
        return Err(p.after_operand_error(&t));
    }
    Ok(Parsed {
        expr,
        names: p.names,
    })
}

struct Parser<'a> {
    src: &'a str,
    tokens: Vec<Token>,
    pos: usize,
    names: Vec<(String, Span)>,
    depth: usize,
}

fn binop(tok: &Tok) -> Option<BinOp> {
    Some(match tok {
        Tok::Or => BinOp::Or,
        Tok::And => BinOp::And,
        Tok::Lt => BinOp::Lt,
        Tok::Le => BinOp::Le,
        Tok::Gt => BinOp::Gt,
        Tok::Ge => BinOp::Ge,
        Tok::EqEq => BinOp::Eq,
        Tok::Ne => BinOp::Ne,
        Tok::Plus => BinOp::Add,
        Tok::Minus => BinOp::Sub,
        Tok::Star => BinOp::Mul,
        Tok::Slash => BinOp::Div,
        Tok::Caret => BinOp::Pow,
        _ => return None,
    })
}

impl Parser<'_> {
    fn peek(&self) -> Option<&Token> {
        self.tokens.get(self.pos)
    }

    fn next(&mut self) -> Option<Token> {
        let t = self.tokens.get(self.pos).cloned();
        self.pos += 1;
        t
    }

    fn end_span(&self) -> Span {
        Span::new(self.src.len(), self.src.len())
    }

    fn err(&self, kind: ExprErrorKind, span: Span) -> ExprError {
        ExprError::new(kind, span, self.src)
    }

    fn unexpected_end(&self, expected: &str) -> ExprError {
        self.err(
            ExprErrorKind::UnexpectedEnd {
                expected: expected.into(),
            },
            self.end_span(),
        )
    }

    /// The error for a token that follows a complete operand but is not an operator.
    fn after_operand_error(&self, t: &Token) -> ExprError {
        match t.tok {
            Tok::Num(_) | Tok::Ident(_) | Tok::LParen | Tok::Not => self.err(
                ExprErrorKind::MissingOperator {
                    found: t.tok.describe(),
                },
                t.span,
            ),
            _ => self.err(
                ExprErrorKind::UnexpectedToken {
                    found: t.tok.describe(),
                    expected: "an operator or the end of the formula".into(),
                },
                t.span,
            ),
        }
    }

    fn expr(&mut self, min_prec: u8) -> Result<Expr, ExprError> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            let span = self.peek().map_or(self.end_span(), |t| t.span);
            return Err(self.err(ExprErrorKind::TooDeep, span));
        }
        let mut lhs = self.prefix()?;
        let mut last_comparison: Option<Span> = None;
        while let Some(t) = self.peek() {
            let Some(op) = binop(&t.tok) else {
                if matches!(t.tok, Tok::RParen | Tok::Comma) {
                    break;
                }
                let t = t.clone();
                return Err(self.after_operand_error(&t));
            };
            let prec = op.precedence();
            if prec < min_prec {
                break;
            }
            let op_span = t.span;
            if op.is_comparison() {
                if let Some(prev) = last_comparison {
                    return Err(self.err(
                        ExprErrorKind::UnexpectedToken {
                            found: format!(
                                "a second comparison (first at column {})",
                                prev.column(self.src)
                            ),
                            expected: "`and` between comparisons, e.g. `0 < x and x < 1`".into(),
                        },
                        op_span,
                    ));
                }
                last_comparison = Some(op_span);
            }
            self.pos += 1;
            // `^` is right-associative; everything else associates to the left.
            let next_min = if op == BinOp::Pow { prec } else { prec + 1 };
            if self.peek().is_none() {
                return Err(self.unexpected_end(&format!("a value after `{}`", op.symbol())));
            }
            let rhs = self.expr(next_min)?;
            lhs = Expr::binary(op, lhs, rhs);
        }
        self.depth -= 1;
        Ok(lhs)
    }

    fn prefix(&mut self) -> Result<Expr, ExprError> {
        let Some(t) = self.next() else {
            return Err(self.unexpected_end("a value"));
        };
        match t.tok {
            Tok::Num(x) => Ok(Expr::Num(x)),
            Tok::Ident(name) => {
                if self.peek().is_some_and(|n| n.tok == Tok::LParen) {
                    self.call(&name, t.span)
                } else {
                    self.names.push((name.clone(), t.span));
                    Ok(Expr::Var(name))
                }
            }
            Tok::LParen => {
                if self.peek().is_none() {
                    return Err(self.err(ExprErrorKind::UnclosedParen, t.span));
                }
                let inner = self.expr(0)?;
                match self.next() {
                    Some(Token {
                        tok: Tok::RParen, ..
                    }) => Ok(inner),
                    Some(other) => Err(self.err(
                        ExprErrorKind::UnexpectedToken {
                            found: other.tok.describe(),
                            expected: "`)`".into(),
                        },
                        other.span,
                    )),
                    None => Err(self.err(ExprErrorKind::UnclosedParen, t.span)),
                }
            }
            Tok::Minus => {
                let operand = self.operand_of(&t, PREC_NEG)?;
                Ok(match operand {
                    Expr::Num(x) => Expr::Num(-x),
                    other => Expr::Neg(Box::new(other)),
                })
            }
            Tok::Plus => self.operand_of(&t, PREC_NEG),
            Tok::Not => Ok(Expr::Not(Box::new(self.operand_of(&t, PREC_NOT)?))),
            other => Err(self.err(
                ExprErrorKind::UnexpectedToken {
                    found: other.describe(),
                    expected: "a number, a name, `(` or `-`".into(),
                },
                t.span,
            )),
        }
    }

    fn operand_of(&mut self, op: &Token, prec: u8) -> Result<Expr, ExprError> {
        if self.peek().is_none() {
            return Err(self.unexpected_end(&format!("a value after {}", op.tok.describe())));
        }
        self.expr(prec)
    }

    fn call(&mut self, name: &str, name_span: Span) -> Result<Expr, ExprError> {
        let Some(func) = Func::from_name(name) else {
            let suggestions = nearest(name, Func::ALL.iter().map(|f| f.name()));
            return Err(self.err(
                ExprErrorKind::UnknownFunction {
                    name: name.to_string(),
                    suggestions,
                },
                name_span,
            ));
        };
        let open = self.next().expect("caller saw `(`");
        let mut args = Vec::new();
        if self.peek().is_some_and(|t| t.tok == Tok::RParen) {
            self.pos += 1;
        } else {
            loop {
                if self.peek().is_none() {
                    return Err(self.err(ExprErrorKind::UnclosedParen, open.span));
                }
                args.push(self.expr(0)?);
                match self.next() {
                    Some(Token {
                        tok: Tok::Comma, ..
                    }) => {}
                    Some(Token {
                        tok: Tok::RParen, ..
                    }) => break,
                    Some(other) => {
                        return Err(self.err(
                            ExprErrorKind::UnexpectedToken {
                                found: other.tok.describe(),
                                expected: "`,` or `)`".into(),
                            },
                            other.span,
                        ));
                    }
                    None => return Err(self.err(ExprErrorKind::UnclosedParen, open.span)),
                }
            }
        }
        if !func.arity().accepts(args.len()) {
            let close = self.tokens[self.pos - 1].span;
            return Err(self.err(
                ExprErrorKind::Arity {
                    name: name.to_string(),
                    expected: func.arity().to_string(),
                    found: args.len(),
                },
                name_span.to(close),
            ));
        }
        Ok(Expr::Call(func, args))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(src: &str) -> Expr {
        parse(src).unwrap_or_else(|e| panic!("{e}")).expr
    }

    fn eval(src: &str) -> f64 {
        p(src).eval_with(&|_| None).unwrap()
    }

    #[test]
    fn precedence_and_associativity() {
        assert_eq!(eval("1 + 2*3"), 7.0);
        assert_eq!(eval("2^3^2"), 512.0);
        assert_eq!(eval("-2^2"), -4.0);
        assert_eq!(eval("2^-1"), 0.5);
        assert_eq!(eval("8/2/2"), 2.0);
        assert_eq!(eval("10 - 3 - 2"), 5.0);
        assert_eq!(eval("2**3"), 8.0);
        assert_eq!(eval("-3*-2"), 6.0);
    }

    #[test]
    fn logic_and_comparisons() {
        assert_eq!(eval("1 < 2 and 3 > 4"), 0.0);
        assert_eq!(eval("1 < 2 or 3 > 4"), 1.0);
        assert_eq!(eval("not 1 > 2"), 1.0);
        assert_eq!(eval("if(2 >= 2, 10, 20)"), 10.0);
        assert_eq!(eval("1 + 1 == 2"), 1.0);
    }

    #[test]
    fn functions() {
        assert_eq!(eval("max(1, 5, 3)"), 5.0);
        assert_eq!(eval("abs(-2)"), 2.0);
        assert_eq!(eval("heaviside(0)"), 0.5);
        assert!((eval("atan2(1, 1)") - std::f64::consts::FRAC_PI_4).abs() < 1e-15);
    }

    #[test]
    fn names_are_recorded_with_spans() {
        let parsed = parse("-m*g*feather.v").unwrap();
        let names: Vec<_> = parsed
            .names
            .iter()
            .map(|(n, s)| (n.as_str(), s.start))
            .collect();
        assert_eq!(names, vec![("m", 1), ("g", 3), ("feather.v", 5)]);
    }

    #[test]
    fn errors_point_at_the_problem() {
        let e = parse("2 x").unwrap_err();
        assert!(matches!(e.kind, ExprErrorKind::MissingOperator { .. }));
        assert_eq!(e.column(), 3);

        let e = parse("sinn(x)").unwrap_err();
        assert!(e.hint().unwrap().contains("`sin`"), "{e}");

        let e = parse("(x + 1").unwrap_err();
        assert_eq!(e.kind, ExprErrorKind::UnclosedParen);
        assert_eq!(e.column(), 1);

        let e = parse("x +").unwrap_err();
        assert!(matches!(e.kind, ExprErrorKind::UnexpectedEnd { .. }));

        let e = parse("atan2(1)").unwrap_err();
        assert!(matches!(e.kind, ExprErrorKind::Arity { found: 1, .. }));

        let e = parse("x = 1").unwrap_err();
        assert_eq!(e.kind, ExprErrorKind::SingleEquals);

        let e = parse("0 < x < 1").unwrap_err();
        assert_eq!(e.column(), 7);

        assert_eq!(parse("   ").unwrap_err().kind, ExprErrorKind::Empty);
    }

    #[test]
    fn deep_nesting_is_an_error_not_a_crash() {
        let src = "(".repeat(100_000) + "1" + &")".repeat(100_000);
        assert_eq!(parse(&src).unwrap_err().kind, ExprErrorKind::TooDeep);
        let src = "-".repeat(100_000) + "1";
        assert_eq!(parse(&src).unwrap_err().kind, ExprErrorKind::TooDeep);
    }

    #[test]
    fn display_round_trips() {
        for src in [
            "-m*g*Dmg*v*abs(v)",
            "a - (b - c)",
            "a/(b*c)",
            "(a + b)^2",
            "-x^2",
            "(-2)^2",
            "2^3^2",
            "(2^3)^2",
            "x < 1 and not y > 2",
            "if(x > 0, -k*x, 0)",
            "a - -3",
            "-(a + b)",
        ] {
            let e = p(src);
            let printed = e.to_string();
            assert_eq!(p(&printed), e, "{src} printed as {printed}");
        }
    }
}

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
/// The deepest expression tree a formula may make, counted in levels above its numbers and
/// names: each operator, sign, function call and pair of parentheses is one level over its
/// deepest operand, so `x` is 0 levels deep, `(x)` and `x + 1` one, and a flat sum of `n` terms
/// `n - 1` (it is the chain `((a + b) + c) + …`). Deeper formulas are refused when parsed, so
/// that every recursive pass over the tree (evaluation, dimensions, native code, symbolic
/// simplification and derivatives, printing, dropping) fits in the smallest thread stack
/// mechkit runs on (a rayon worker's 2 MiB), with room to spare in a debug build.
pub const MAX_DEPTH: usize = 256;

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
    parse_tokens(src, tokenize(src)?).map_err(|e| *e)
}

fn parse_tokens(src: &str, tokens: Vec<Token>) -> Parse<Parsed> {
    if tokens.is_empty() {
        return Err(Box::new(ExprError::new(
            ExprErrorKind::Empty,
            Span::new(0, src.len()),
            src,
        )));
    }
    let mut p = Parser {
        src,
        tokens,
        pos: 0,
        names: Vec::new(),
        nesting: 0,
    };
    let node = p.expr(0)?;
    if let Some(t) = p.peek() {
        let t = t.clone();
        return Err(p.after_operand_error(&t));
    }
    Ok(Parsed {
        expr: node.expr,
        names: p.names,
    })
}

struct Parser<'a> {
    src: &'a str,
    tokens: Vec<Token>,
    pos: usize,
    names: Vec<(String, Span)>,
    /// Calls of [`Parser::expr`] open at once.
    nesting: usize,
}

/// A parsed subexpression and its depth, counted as [`MAX_DEPTH`] counts.
struct Node {
    expr: Expr,
    depth: usize,
}

impl Node {
    fn leaf(expr: Expr) -> Node {
        Node { expr, depth: 0 }
    }
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

/// A parser result. The error is boxed, and built out of line, so that the frames of the
/// recursion stay small: they bound how deep a formula can be parsed on a given stack.
type Parse<T> = Result<T, Box<ExprError>>;

// the errors are built boxed, for `Parse`
#[allow(clippy::unnecessary_box_returns)]
impl Parser<'_> {
    fn peek(&self) -> Option<&Token> {
        self.tokens.get(self.pos)
    }

    fn peek_is(&self, tok: &Tok) -> bool {
        self.peek().is_some_and(|t| t.tok == *tok)
    }

    fn next(&mut self) -> Option<Token> {
        let t = self.tokens.get(self.pos).cloned();
        self.pos += 1;
        t
    }

    fn end_span(&self) -> Span {
        Span::new(self.src.len(), self.src.len())
    }

    /// The span of the next token, or the end of the text.
    fn next_span(&self) -> Span {
        self.peek().map_or(self.end_span(), |t| t.span)
    }

    #[cold]
    #[inline(never)]
    fn err(&self, kind: ExprErrorKind, span: Span) -> Box<ExprError> {
        Box::new(ExprError::new(kind, span, self.src))
    }

    #[cold]
    #[inline(never)]
    fn unexpected_end(&self, expected: &str) -> Box<ExprError> {
        self.err(
            ExprErrorKind::UnexpectedEnd {
                expected: expected.into(),
            },
            self.end_span(),
        )
    }

    #[cold]
    #[inline(never)]
    fn unexpected(&self, found: &Tok, expected: &str, span: Span) -> Box<ExprError> {
        self.err(
            ExprErrorKind::UnexpectedToken {
                found: found.describe(),
                expected: expected.into(),
            },
            span,
        )
    }

    /// The error for a token that follows a complete operand but is not an operator.
    #[cold]
    #[inline(never)]
    fn after_operand_error(&self, t: &Token) -> Box<ExprError> {
        match t.tok {
            Tok::Num(_) | Tok::Ident(_) | Tok::LParen | Tok::Not => self.err(
                ExprErrorKind::MissingOperator {
                    found: t.tok.describe(),
                },
                t.span,
            ),
            _ => self.unexpected(&t.tok, "an operator or the end of the formula", t.span),
        }
    }

    #[cold]
    #[inline(never)]
    fn second_comparison(&self, first: Span, second: Span) -> Box<ExprError> {
        self.err(
            ExprErrorKind::UnexpectedToken {
                found: format!(
                    "a second comparison (first at column {})",
                    first.column(self.src)
                ),
                expected: "`and` between comparisons, e.g. `0 < x and x < 1`".into(),
            },
            second,
        )
    }

    /// Parses an expression whose operators bind at least as tightly as `min_prec`.
    ///
    /// Every call but the outermost is made for an operand of a parenthesis, a sign, an
    /// operator or a function call, each a level of the tree, so the calls open at once never
    /// outnumber the levels above the innermost operand: refusing more than [`MAX_DEPTH`] of
    /// them bounds the parser's own recursion by the same rule as the tree.
    fn expr(&mut self, min_prec: u8) -> Parse<Node> {
        if self.nesting > MAX_DEPTH {
            return Err(self.err(ExprErrorKind::TooDeep, self.next_span()));
        }
        self.nesting += 1;
        let node = self.operators(min_prec);
        self.nesting -= 1;
        node
    }

    /// One level over `depth`, refused past [`MAX_DEPTH`] at `span` (the operator, sign,
    /// parenthesis or call that makes it).
    fn level_over(&self, depth: usize, span: Span) -> Parse<usize> {
        if depth >= MAX_DEPTH {
            return Err(self.err(ExprErrorKind::TooDeep, span));
        }
        Ok(depth + 1)
    }

    /// An operand, then binary operators of precedence `min_prec` or more and their operands.
    /// A chain of operators of one precedence (`a + b + c`) builds to the left, one level per
    /// operator.
    fn operators(&mut self, min_prec: u8) -> Parse<Node> {
        let mut lhs = self.prefix()?;
        let mut last_comparison: Option<Span> = None;
        while let Some((op, op_span)) = self.binary_operator(min_prec)? {
            if op.is_comparison() {
                if let Some(first) = last_comparison {
                    return Err(self.second_comparison(first, op_span));
                }
                last_comparison = Some(op_span);
            }
            // a chain's depth grows with its length: refuse it at the operator that passes the
            // limit, before its right operand is read
            self.level_over(lhs.depth, op_span)?;
            self.pos += 1;
            if self.peek().is_none() {
                return Err(self.unexpected_end(&format!("a value after `{}`", op.symbol())));
            }
            // `^` is right-associative; everything else associates to the left.
            let prec = op.precedence();
            let rhs = self.expr(if op == BinOp::Pow { prec } else { prec + 1 })?;
            lhs = Node {
                depth: self.level_over(lhs.depth.max(rhs.depth), op_span)?,
                expr: Expr::binary(op, lhs.expr, rhs.expr),
            };
        }
        Ok(lhs)
    }

    /// The binary operator that comes next, if it binds at least as tightly as `min_prec`;
    /// `None` at the end, a `)` or a `,`.
    fn binary_operator(&self, min_prec: u8) -> Parse<Option<(BinOp, Span)>> {
        let Some(t) = self.peek() else {
            return Ok(None);
        };
        match binop(&t.tok) {
            Some(op) if op.precedence() >= min_prec => Ok(Some((op, t.span))),
            Some(_) => Ok(None),
            None if matches!(t.tok, Tok::RParen | Tok::Comma) => Ok(None),
            None => Err(self.after_operand_error(t)),
        }
    }

    fn prefix(&mut self) -> Parse<Node> {
        let Some(t) = self.next() else {
            return Err(self.unexpected_end("a value"));
        };
        match t.tok {
            Tok::Num(x) => Ok(Node::leaf(Expr::Num(x))),
            Tok::Ident(name) => {
                if self.peek_is(&Tok::LParen) {
                    self.call(&name, t.span)
                } else {
                    self.names.push((name.clone(), t.span));
                    Ok(Node::leaf(Expr::Var(name)))
                }
            }
            Tok::LParen => self.parenthesised(t.span),
            Tok::Minus | Tok::Plus | Tok::Not => self.signed(&t),
            other => Err(self.unexpected(&other, "a number, a name, `(` or `-`", t.span)),
        }
    }

    /// What follows a `(` at `open`, up to its `)`.
    fn parenthesised(&mut self, open: Span) -> Parse<Node> {
        if self.peek().is_none() {
            return Err(self.err(ExprErrorKind::UnclosedParen, open));
        }
        let inner = self.expr(0)?;
        match self.next() {
            Some(Token {
                tok: Tok::RParen, ..
            }) => Ok(Node {
                depth: self.level_over(inner.depth, open)?,
                expr: inner.expr,
            }),
            Some(other) => Err(self.unexpected(&other.tok, "`)`", other.span)),
            None => Err(self.err(ExprErrorKind::UnclosedParen, open)),
        }
    }

    /// The operand of a sign or `not` (the token `op`), and the sign applied.
    fn signed(&mut self, op: &Token) -> Parse<Node> {
        if self.peek().is_none() {
            return Err(self.unexpected_end(&format!("a value after {}", op.tok.describe())));
        }
        let operand = self.expr(if op.tok == Tok::Not {
            PREC_NOT
        } else {
            PREC_NEG
        })?;
        Ok(Node {
            depth: self.level_over(operand.depth, op.span)?,
            expr: match (&op.tok, operand.expr) {
                (Tok::Minus, Expr::Num(x)) => Expr::Num(-x),
                (Tok::Minus, other) => Expr::Neg(Box::new(other)),
                (Tok::Not, other) => Expr::Not(Box::new(other)),
                (_, other) => other,
            },
        })
    }

    fn call(&mut self, name: &str, name_span: Span) -> Parse<Node> {
        let reciprocal = Func::reciprocal_of(name);
        let Some(func) = Func::from_name(name).or(reciprocal) else {
            return Err(self.unknown_function(name, name_span));
        };
        let open = self.next().expect("caller saw `(`").span;
        let mut args = Vec::new();
        let mut deepest = 0;
        if self.peek_is(&Tok::RParen) {
            self.pos += 1;
        } else {
            loop {
                if self.peek().is_none() {
                    return Err(self.err(ExprErrorKind::UnclosedParen, open));
                }
                let arg = self.expr(0)?;
                deepest = deepest.max(arg.depth);
                args.push(arg.expr);
                match self.next() {
                    Some(Token {
                        tok: Tok::Comma, ..
                    }) => {}
                    Some(Token {
                        tok: Tok::RParen, ..
                    }) => break,
                    Some(other) => {
                        return Err(self.unexpected(&other.tok, "`,` or `)`", other.span));
                    }
                    None => return Err(self.err(ExprErrorKind::UnclosedParen, open)),
                }
            }
        }
        if !func.arity().accepts(args.len()) {
            return Err(self.arity(func, name_span, args.len()));
        }
        let depth = self.level_over(deepest, name_span)?;
        let call = Expr::Call(func, args);
        if reciprocal.is_none() {
            return Ok(Node { depth, expr: call });
        }
        // `sec(u)` is read as `1/cos(u)`: one more level, as written out
        Ok(Node {
            depth: self.level_over(depth, name_span)?,
            expr: Expr::Binary(BinOp::Div, Box::new(Expr::Num(1.0)), Box::new(call)),
        })
    }

    #[cold]
    #[inline(never)]
    fn unknown_function(&self, name: &str, span: Span) -> Box<ExprError> {
        let names = Func::ALL.iter().map(|f| f.name());
        let suggestions = nearest(name, names.chain(Func::RECIPROCALS.iter().map(|r| r.0)));
        self.err(
            ExprErrorKind::UnknownFunction {
                name: name.to_string(),
                suggestions,
            },
            span,
        )
    }

    #[cold]
    #[inline(never)]
    fn arity(&self, func: Func, name_span: Span, found: usize) -> Box<ExprError> {
        let close = self.tokens[self.pos - 1].span;
        self.err(
            ExprErrorKind::Arity {
                name: func.name().to_string(),
                expected: func.arity().to_string(),
                found,
            },
            name_span.to(close),
        )
    }
}

#[cfg(test)]
#[path = "parser_tests.rs"]
mod tests;

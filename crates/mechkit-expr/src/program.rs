//! Formulas compiled to a flat stack program: constants folded, names resolved to slots, no
//! allocation when evaluated.

use crate::ast::{BinOp, Expr, Func, select};
use crate::scope::{Binding, Scope, builtin_constant};

/// One instruction of a [`Program`].
#[derive(Debug, Clone, Copy, PartialEq)]
enum Op {
    Const(f64),
    Load(usize),
    Neg,
    Not,
    Bin(BinOp),
    Square,
    Cube,
    Powi(i32),
    Call1(Func),
    Call2(Func),
    Select,
}

/// Evaluations whose stack fits this use a fixed array on the machine stack.
const INLINE_STACK: usize = 32;

/// A compiled formula. Evaluate it with [`Program::eval`] on a slice of variable values laid
/// out as the [`Scope`] it was compiled against said.
///
/// # Example
/// ```
/// use mechkit_expr::{Formula, MapScope};
/// let f = Formula::parse("-k*(x - L)").unwrap();
/// let scope = MapScope::new().constant("k", 10.0).constant("L", 0.5).slot("x", 0);
/// let program = f.compile(&scope).unwrap();
/// assert!((program.eval(&[0.7]) + 2.0).abs() < 1e-14);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Program {
    ops: Vec<Op>,
    max_stack: usize,
    slots: usize,
}

impl Program {
    /// Compiles an expression, resolving names with `scope` (then the built-in `pi` and `e`).
    /// Fails on the first name that is not defined; without a span for it (see
    /// [`crate::Formula::compile`] for located errors).
    pub fn compile(expr: &Expr, scope: &dyn Scope) -> Result<Program, String> {
        let folded = fold(expr, scope)?;
        let mut ops = Vec::new();
        emit(&folded, scope, &mut ops);
        let (max_stack, slots) = analyse(&ops);
        Ok(Program {
            ops,
            max_stack,
            slots,
        })
    }

    /// Evaluates the program. `vars` must hold at least [`Program::slots`] values.
    #[inline]
    pub fn eval(&self, vars: &[f64]) -> f64 {
        assert!(
            vars.len() >= self.slots,
            "program reads {} variables, {} given",
            self.slots,
            vars.len()
        );
        if self.max_stack <= INLINE_STACK {
            let mut stack = [0.0; INLINE_STACK];
            run(&self.ops, vars, &mut stack)
        } else {
            let mut stack = vec![0.0; self.max_stack];
            run(&self.ops, vars, &mut stack)
        }
    }

    /// How many variable slots the program reads (one more than the largest slot index).
    pub fn slots(&self) -> usize {
        self.slots
    }

    /// The value, when the program reads no variables.
    pub fn as_constant(&self) -> Option<f64> {
        match self.ops.as_slice() {
            [Op::Const(c)] => Some(*c),
            _ => None,
        }
    }

    /// Number of instructions (a measure of evaluation cost).
    pub fn len(&self) -> usize {
        self.ops.len()
    }

    /// Whether the program has no instructions (never true for a compiled formula).
    pub fn is_empty(&self) -> bool {
        self.ops.is_empty()
    }
}

#[inline]
fn run(ops: &[Op], vars: &[f64], stack: &mut [f64]) -> f64 {
    let mut sp = 0usize;
    for op in ops {
        match *op {
            Op::Const(c) => {
                stack[sp] = c;
                sp += 1;
            }
            Op::Load(i) => {
                stack[sp] = vars[i];
                sp += 1;
            }
            Op::Neg => stack[sp - 1] = -stack[sp - 1],
            Op::Not => stack[sp - 1] = if stack[sp - 1] == 0.0 { 1.0 } else { 0.0 },
            Op::Square => stack[sp - 1] *= stack[sp - 1],
            Op::Cube => {
                let x = stack[sp - 1];
                stack[sp - 1] = x * x * x;
            }
            Op::Powi(n) => stack[sp - 1] = stack[sp - 1].powi(n),
            Op::Call1(f) => stack[sp - 1] = f.apply1(stack[sp - 1]),
            Op::Bin(op) => {
                sp -= 1;
                let b = stack[sp];
                let a = &mut stack[sp - 1];
                *a = match op {
                    BinOp::Add => *a + b,
                    BinOp::Sub => *a - b,
                    BinOp::Mul => *a * b,
                    BinOp::Div => *a / b,
                    other => other.apply(*a, b),
                };
            }
            Op::Call2(f) => {
                sp -= 1;
                stack[sp - 1] = f.apply2(stack[sp - 1], stack[sp]);
            }
            Op::Select => {
                sp -= 2;
                stack[sp - 1] = select(stack[sp - 1], stack[sp], stack[sp + 1]);
            }
        }
    }
    debug_assert_eq!(sp, 1);
    stack[0]
}

/// Replaces constant names by their values and evaluates constant sub-trees.
fn fold(expr: &Expr, scope: &dyn Scope) -> Result<Expr, String> {
    let folded = match expr {
        Expr::Num(x) => Expr::Num(*x),
        Expr::Var(name) => match scope.lookup(name) {
            Some(Binding::Const(c)) => Expr::Num(c),
            Some(Binding::Slot(_)) => Expr::Var(name.clone()),
            None => Expr::Num(builtin_constant(name).ok_or_else(|| name.clone())?),
        },
        Expr::Neg(a) => Expr::Neg(Box::new(fold(a, scope)?)),
        Expr::Not(a) => Expr::Not(Box::new(fold(a, scope)?)),
        Expr::Binary(op, a, b) => Expr::binary(*op, fold(a, scope)?, fold(b, scope)?),
        Expr::Call(f, args) => Expr::Call(
            *f,
            args.iter()
                .map(|a| fold(a, scope))
                .collect::<Result<_, _>>()?,
        ),
    };
    let is_const = match &folded {
        Expr::Num(_) | Expr::Var(_) => false,
        Expr::Neg(a) | Expr::Not(a) => matches!(**a, Expr::Num(_)),
        Expr::Binary(_, a, b) => matches!(**a, Expr::Num(_)) && matches!(**b, Expr::Num(_)),
        Expr::Call(_, args) => args.iter().all(|a| matches!(a, Expr::Num(_))),
    };
    if is_const {
        let value = folded
            .eval_with(&|_| None)
            .expect("a constant sub-tree has no names");
        return Ok(Expr::Num(value));
    }
    Ok(folded)
}

/// Emits stack code for a folded expression; every name left in it is a slot of `scope`.
fn emit(expr: &Expr, scope: &dyn Scope, ops: &mut Vec<Op>) {
    match expr {
        Expr::Num(x) => ops.push(Op::Const(*x)),
        Expr::Var(name) => match scope.lookup(name) {
            Some(Binding::Slot(i)) => ops.push(Op::Load(i)),
            other => unreachable!("`{name}` should have been folded, found {other:?}"),
        },
        Expr::Neg(a) => {
            emit(a, scope, ops);
            ops.push(Op::Neg);
        }
        Expr::Not(a) => {
            emit(a, scope, ops);
            ops.push(Op::Not);
        }
        Expr::Binary(BinOp::Pow, a, b) => {
            emit(a, scope, ops);
            match **b {
                Expr::Num(2.0) => ops.push(Op::Square),
                Expr::Num(3.0) => ops.push(Op::Cube),
                Expr::Num(n) if n.fract() == 0.0 && n.abs() <= 64.0 => ops.push(Op::Powi(n as i32)),
                _ => {
                    emit(b, scope, ops);
                    ops.push(Op::Bin(BinOp::Pow));
                }
            }
        }
        Expr::Binary(op, a, b) => {
            emit(a, scope, ops);
            emit(b, scope, ops);
            ops.push(Op::Bin(*op));
        }
        Expr::Call(Func::If, args) => {
            for a in args {
                emit(a, scope, ops);
            }
            ops.push(Op::Select);
        }
        Expr::Call(f @ (Func::Min | Func::Max), args) => {
            emit(&args[0], scope, ops);
            for a in &args[1..] {
                emit(a, scope, ops);
                ops.push(Op::Call2(*f));
            }
        }
        Expr::Call(f @ Func::Atan2, args) => {
            emit(&args[0], scope, ops);
            emit(&args[1], scope, ops);
            ops.push(Op::Call2(*f));
        }
        Expr::Call(f, args) => {
            emit(&args[0], scope, ops);
            ops.push(Op::Call1(*f));
        }
    }
}

fn analyse(ops: &[Op]) -> (usize, usize) {
    let (mut sp, mut max, mut slots) = (0usize, 0usize, 0usize);
    for op in ops {
        match op {
            Op::Const(_) => sp += 1,
            Op::Load(i) => {
                sp += 1;
                slots = slots.max(i + 1);
            }
            Op::Neg | Op::Not | Op::Square | Op::Cube | Op::Powi(_) | Op::Call1(_) => {}
            Op::Bin(_) | Op::Call2(_) => sp -= 1,
            Op::Select => sp -= 2,
        }
        max = max.max(sp);
    }
    (max, slots)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parser::parse;
    use crate::scope::MapScope;

    fn compile(src: &str, scope: &MapScope) -> Program {
        Program::compile(&parse(src).unwrap().expr, scope).unwrap()
    }

    #[test]
    fn constants_fold_away() {
        let scope = MapScope::new()
            .constant("g", 9.8)
            .constant("D", 4.0)
            .slot("v", 0);
        let p = compile("-g*D*v*abs(v)", &scope);
        assert_eq!(p.eval(&[-2.0]), -9.8 * 4.0 * -2.0 * 2.0);
        let c = compile("2*pi*g", &scope);
        assert_eq!(c.as_constant(), Some(2.0 * std::f64::consts::PI * 9.8));
    }

    #[test]
    fn agrees_with_the_tree_walker() {
        let scope = MapScope::new().slot("x", 0).slot("y", 1);
        for src in [
            "x^2 + y^3 - x^-2 + x^0.5",
            "if(x > y, min(x, y, 3), max(x, y))",
            "atan2(y, x) + sign(x - y) + heaviside(y)",
            "not (x < 1 or y > 2) and x != y",
            "-(x - y)/(x + y)",
        ] {
            let p = compile(src, &scope);
            let e = parse(src).unwrap().expr;
            for (x, y) in [(1.5, 0.5), (0.25, 3.0), (2.0, 2.0)] {
                let tree = e
                    .eval_with(&|n| match n {
                        "x" => Some(x),
                        "y" => Some(y),
                        _ => None,
                    })
                    .unwrap();
                let fast = p.eval(&[x, y]);
                assert!(
                    (tree - fast).abs() <= 1e-15 * tree.abs().max(1.0),
                    "{src} at ({x}, {y}): {tree} vs {fast}"
                );
            }
        }
    }

    #[test]
    fn deep_programs_fall_back_to_the_heap() {
        let scope = MapScope::new().slot("x", 0);
        let src = (0..60).map(|_| "(x+").collect::<String>() + "x" + &")".repeat(60);
        let p = compile(&src, &scope);
        assert!(p.max_stack > INLINE_STACK);
        assert_eq!(p.eval(&[1.0]), 61.0);
    }

    #[test]
    fn undefined_names_are_reported() {
        let e = Program::compile(&parse("x + q").unwrap().expr, &MapScope::new().slot("x", 0));
        assert_eq!(e.unwrap_err(), "q");
    }
}

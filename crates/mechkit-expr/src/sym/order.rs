//! The canonical order of terms and factors: numbers, then `pi` and `e`, then names
//! alphabetically (with their powers), then function calls, then sums; in sums, higher powers
//! first and numbers last (`x^2 + 2*x + 1`).

use std::cmp::Ordering;

use super::Sym;

fn rank(s: &Sym) -> u8 {
    match s {
        Sym::Num(_) => 0,
        Sym::Var(v) if v == "pi" || v == "e" => 1,
        Sym::Var(_) => 2,
        Sym::Pow(b, _) => rank(b),
        Sym::Call(..) => 4,
        Sym::Add(_) => 5,
        Sym::Mul(_) => 6,
        Sym::Cmp(..) | Sym::And(..) | Sym::Or(..) | Sym::Not(_) => 7,
    }
}

/// A base and its exponent (1 when there is no power).
pub(super) fn base_exp(s: &Sym) -> (&Sym, Option<&Sym>) {
    match s {
        Sym::Pow(b, e) => (b, Some(e)),
        other => (other, None),
    }
}

fn cmp_list(a: &[Sym], b: &[Sym]) -> Ordering {
    for (x, y) in a.iter().zip(b) {
        let c = compare(x, y);
        if c != Ordering::Equal {
            return c;
        }
    }
    a.len().cmp(&b.len())
}

/// Total order of canonical expressions, used to sort the factors of a product.
pub(super) fn compare(a: &Sym, b: &Sym) -> Ordering {
    let (ra, rb) = (rank(a), rank(b));
    if ra != rb {
        return ra.cmp(&rb);
    }
    let ((ba, ea), (bb, eb)) = (base_exp(a), base_exp(b));
    if !std::ptr::eq(ba, a) || !std::ptr::eq(bb, b) {
        // compare powers by base, then exponent (no exponent = 1 comes first)
        let c = compare_bases(ba, bb);
        if c != Ordering::Equal {
            return c;
        }
        return match (ea, eb) {
            (None, None) => Ordering::Equal,
            (None, Some(_)) => Ordering::Less,
            (Some(_), None) => Ordering::Greater,
            (Some(x), Some(y)) => compare(x, y),
        };
    }
    compare_bases(a, b)
}

fn compare_bases(a: &Sym, b: &Sym) -> Ordering {
    match (a, b) {
        (Sym::Num(x), Sym::Num(y)) => x.total_cmp(y),
        (Sym::Var(x), Sym::Var(y)) => x.cmp(y),
        (Sym::Call(f, xs), Sym::Call(g, ys)) => {
            f.name().cmp(g.name()).then_with(|| cmp_list(xs, ys))
        }
        (Sym::Add(xs), Sym::Add(ys)) | (Sym::Mul(xs), Sym::Mul(ys)) => cmp_list(xs, ys),
        (Sym::Pow(a1, b1), Sym::Pow(a2, b2)) => compare(a1, a2).then_with(|| compare(b1, b2)),
        (Sym::Cmp(o1, a1, b1), Sym::Cmp(o2, a2, b2)) => o1
            .symbol()
            .cmp(o2.symbol())
            .then_with(|| compare(a1, a2))
            .then_with(|| compare(b1, b2)),
        (Sym::And(a1, b1), Sym::And(a2, b2)) | (Sym::Or(a1, b1), Sym::Or(a2, b2)) => {
            compare(a1, a2).then_with(|| compare(b1, b2))
        }
        (Sym::Not(a1), Sym::Not(a2)) => compare(a1, a2),
        _ => rank(a)
            .cmp(&rank(b))
            .then_with(|| variant(a).cmp(&variant(b))),
    }
}

fn variant(s: &Sym) -> u8 {
    match s {
        Sym::Num(_) => 0,
        Sym::Var(_) => 1,
        Sym::Add(_) => 2,
        Sym::Mul(_) => 3,
        Sym::Pow(..) => 4,
        Sym::Call(..) => 5,
        Sym::Cmp(..) => 6,
        Sym::And(..) => 7,
        Sym::Or(..) => 8,
        Sym::Not(_) => 9,
    }
}

/// The factors of a term without its numeric coefficient.
fn monomial(t: &Sym) -> &[Sym] {
    match t {
        Sym::Mul(xs) if matches!(xs.first(), Some(Sym::Num(_))) => &xs[1..],
        Sym::Mul(xs) => xs,
        Sym::Num(_) => &[],
        other => std::slice::from_ref(other),
    }
}

/// Order of the terms of a sum: by their factors, a higher power before a lower one of the
/// same base, numbers last.
pub(super) fn compare_terms(a: &Sym, b: &Sym) -> Ordering {
    let (ma, mb) = (monomial(a), monomial(b));
    match (ma.is_empty(), mb.is_empty()) {
        (true, false) => return Ordering::Greater,
        (false, true) => return Ordering::Less,
        (true, true) => return compare(a, b),
        _ => {}
    }
    for (x, y) in ma.iter().zip(mb) {
        let ((bx, ex), (by, ey)) = (base_exp(x), base_exp(y));
        let c = compare_bases(bx, by);
        if c != Ordering::Equal {
            return c;
        }
        // higher exponent first
        let one = Sym::one();
        let c = degree_cmp(ey.unwrap_or(&one), ex.unwrap_or(&one));
        if c != Ordering::Equal {
            return c;
        }
    }
    mb.len().cmp(&ma.len()).then_with(|| compare(a, b))
}

fn degree_cmp(a: &Sym, b: &Sym) -> Ordering {
    match (a.as_num(), b.as_num()) {
        (Some(x), Some(y)) => x.total_cmp(&y),
        _ => compare(a, b),
    }
}

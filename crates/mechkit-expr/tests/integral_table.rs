//! Issue 27: a table of course integrals (`data/integrals.tsv`, exact values by SymPy from
//! `data/integrals_exact.py`). For each, the antiderivative is checked by differentiation
//! (inside `Sym::integrate`), and its definite value `F(b) - F(a)` against the exact value and
//! against an independent numerical quadrature (tanh-sinh, written here) to 1e-9 relative.

use mechkit_expr::Sym;

struct Row {
    integrand: String,
    from: f64,
    to: f64,
    /// The limits as written (exact: `1`, `1/2`, `pi`).
    ends: (Sym, Sym),
    params: Vec<(String, f64)>,
    value: f64,
}

fn number(text: &str) -> f64 {
    Sym::parse(text)
        .unwrap_or_else(|e| panic!("{text}: {e}"))
        .eval(&|_| None)
        .unwrap_or_else(|e| panic!("{text}: {e}"))
}

fn rows() -> Vec<Row> {
    include_str!("data/integrals.tsv")
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| {
            let cols: Vec<&str> = l.split('\t').collect();
            let params = cols[3]
                .split(',')
                .filter(|p| !p.is_empty())
                .map(|p| {
                    let (k, v) = p.split_once('=').expect("name=value");
                    (k.to_string(), number(v))
                })
                .collect();
            Row {
                integrand: cols[0].to_string(),
                from: number(cols[1]),
                to: number(cols[2]),
                ends: (Sym::parse(cols[1]).unwrap(), Sym::parse(cols[2]).unwrap()),
                params,
                value: cols[4].parse().expect("a decimal value"),
            }
        })
        .collect()
}

/// `f(end ± s)` as an expression in `s`, expanded, so that points next to an end are
/// evaluated without the rounding of `end ± s` (`1 - x^2` near `x = 1` is `2 s - s^2`).
fn near(f: &Sym, end: &Sym, sign: i64, params: &[(String, f64)]) -> impl Fn(f64) -> f64 {
    let at = Sym::sum(vec![
        end.clone(),
        Sym::product(vec![Sym::int(sign), Sym::var("__s")]),
    ]);
    let g = f.substitute("x", &at).expand();
    let params = params.to_vec();
    move |s| {
        g.eval(&|n| match n {
            "__s" => Some(s),
            _ => params.iter().find(|(k, _)| k == n).map(|(_, v)| *v),
        })
        .unwrap_or(f64::NAN)
    }
}

/// Tanh-sinh (double exponential) quadrature on `[a, b]`: exact to rounding for analytic
/// integrands, and for integrable singularities at the ends; points next to an end are
/// placed by their distance to it.
fn tanh_sinh(f: &Sym, ends: &(Sym, Sym), params: &[(String, f64)]) -> f64 {
    let (lo, hi) = (near(f, &ends.0, 1, params), near(f, &ends.1, -1, params));
    let value = |s: &Sym| s.eval(&|_| None).expect("a number");
    let (a, b) = (value(&ends.0), value(&ends.1));
    let half = (b - a) / 2.0;
    let mut previous = f64::NAN;
    let mut h = 0.5;
    for _ in 0..9 {
        let mut sum = 0.0;
        let n = (4.5 / h) as i64;
        for k in -n..=n {
            let t = k as f64 * h;
            let u = std::f64::consts::FRAC_PI_2 * t.sinh();
            let w = half * std::f64::consts::FRAC_PI_2 * t.cosh() / u.cosh().powi(2);
            // distance to the nearer end: half (1 - tanh|u|) = 2 half/(e^(2|u|) + 1)
            let s = 2.0 * half / ((2.0 * u.abs()).exp() + 1.0);
            if s <= 0.0 || w == 0.0 {
                continue;
            }
            let v = if t < 0.0 { lo(s) } else { hi(s) };
            if v.is_finite() {
                sum += w * v;
            }
        }
        let value = sum * h;
        if (value - previous).abs() <= 1e-14 * value.abs().max(1e-300) {
            return value;
        }
        previous = value;
        h /= 2.0;
    }
    previous
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * a.abs().max(b.abs()).max(1e-12)
}

#[test]
fn course_integral_table() {
    let rows = rows();
    assert!(rows.len() >= 100, "{} integrals", rows.len());
    let mut missing = Vec::new();
    let mut wrong = Vec::new();
    for r in &rows {
        let f = Sym::parse(&r.integrand).unwrap();
        let quad = tanh_sinh(&f, &r.ends, &r.params);
        assert!(
            close(quad, r.value),
            "{}: the test's quadrature {quad} against {}",
            r.integrand,
            r.value
        );
        let Some(anti) = f.integrate("x") else {
            missing.push(r.integrand.clone());
            continue;
        };
        let env = |v: f64| {
            let params = r.params.clone();
            move |n: &str| {
                if n == "x" {
                    Some(v)
                } else {
                    params.iter().find(|(k, _)| k == n).map(|(_, v)| *v)
                }
            }
        };
        let big_f = &anti.result;
        let closed = big_f.eval(&env(r.to)).unwrap() - big_f.eval(&env(r.from)).unwrap();
        if !(close(closed, r.value) && close(closed, quad)) {
            wrong.push(format!(
                "{}: F = {big_f}, {closed} against {} (quadrature {quad})",
                r.integrand, r.value
            ));
        }
    }
    assert!(
        wrong.is_empty(),
        "wrong definite values:\n{}",
        wrong.join("\n")
    );
    let found = rows.len() - missing.len();
    println!(
        "{found} of {} with a closed form; missing: {missing:?}",
        rows.len()
    );
    assert!(
        found * 100 >= rows.len() * 95,
        "{found} of {}: missing {missing:?}",
        rows.len()
    );
}

/// A standard table of integrals with symbolic constants (`data/calculus_table.txt`): each
/// closed form is verified by differentiation inside `Sym::integrate`; the ones left without
/// are those docs/formulas.md names.
#[test]
fn standard_table_with_symbolic_constants() {
    let rows: Vec<&str> = include_str!("data/calculus_table.txt")
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .collect();
    assert!(rows.len() >= 130, "{} integrands", rows.len());
    let mut missing = Vec::new();
    for f in &rows {
        let s = Sym::parse(f).unwrap_or_else(|e| panic!("{f}: {e}"));
        let var = if s.free_of("x") { "t" } else { "x" };
        if s.integrate(var).is_none() {
            missing.push(*f);
        }
    }
    let found = rows.len() - missing.len();
    println!("{found} of {}; missing: {missing:?}", rows.len());
    assert!(
        found >= 135,
        "{found} of {}: missing {missing:?}",
        rows.len()
    );
}

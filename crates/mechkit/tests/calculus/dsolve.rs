//! `calculus::dsolve` against a table of equations with exact solutions
//! (`dsolve_table.txt`): each answer (already verified by substitution into its equation)
//! must equal the exact solution, and a DOP853 integration of the equation at tolerance 1e-12
//! from the initial point must reproduce it to 1e-7 (the unknown function is `x` unless a
//! row names another).

use mechkit::calculus::{dsolve, parse_params};
use mechkit::expr::Sym;
use mechkit::expr::sym::dsolve::{Condition, Ode, derivative_name};
use mechkit::ode::{AdaptiveConfig, AdaptiveRk, OdeSystem, State, Tableau, Tolerance};

struct Row {
    eq: String,
    func: String,
    ic: String,
    exact: Sym,
    t_end: f64,
    set: Vec<(String, f64)>,
}

fn table() -> Vec<Row> {
    include_str!("dsolve_table.txt")
        .lines()
        .filter(|l| !l.trim().is_empty() && !l.starts_with('#'))
        .map(|l| {
            let f: Vec<&str> = l.split('|').map(str::trim).collect();
            Row {
                eq: f[0].into(),
                func: f.get(5).unwrap_or(&"x").to_string(),
                ic: f[1].into(),
                exact: Sym::parse(f[2]).unwrap(),
                t_end: f[3].parse().unwrap(),
                set: f
                    .get(4)
                    .filter(|s| !s.is_empty())
                    .map_or_else(Vec::new, |s| parse_params(s).unwrap()),
            }
        })
        .collect()
}

/// `x^(n) = f(t, x, …)` as a first-order system in `(x, x', …)`.
struct Explicit {
    rhs: Sym,
    names: Vec<String>,
}

impl OdeSystem for Explicit {
    fn dim(&self) -> usize {
        self.names.len()
    }
    fn rhs_into(&self, t: f64, y: &[f64], dydt: &mut [f64]) {
        let env = |n: &str| {
            if n == "t" {
                return Some(t);
            }
            self.names.iter().position(|m| m == n).map(|i| y[i])
        };
        let n = y.len();
        dydt[..n - 1].copy_from_slice(&y[1..]);
        dydt[n - 1] = self.rhs.eval(&env).unwrap();
    }
}

fn at(s: &Sym, t: f64) -> f64 {
    s.eval(&|n| (n == "t").then_some(t)).unwrap()
}

#[test]
fn every_equation_of_the_table_matches_its_exact_and_numerical_solution() {
    let rows = table();
    assert!(rows.len() >= 60);
    let mut symbolic = 0;
    for r in &rows {
        let s = dsolve(&r.eq, &r.func, "t", Some(&r.ic), &r.set)
            .unwrap_or_else(|e| panic!("{}: {e}", r.eq));
        assert!(s.constants.is_empty(), "{}: {:?}", r.eq, s.constants);
        if Sym::difference(s.solution.clone(), r.exact.clone())
            .expand()
            .is_zero()
        {
            symbolic += 1;
        }
        // the initial point and the numerical system
        let conds = Condition::parse_list(&r.ic, &r.func).unwrap();
        let t0 = conds[0].at.eval(&|_| None).unwrap();
        let values: Vec<(String, Sym)> = r
            .set
            .iter()
            .map(|(k, v)| (k.clone(), Sym::Num(mechkit::expr::Number::from_f64(*v))))
            .collect();
        let ode = Ode::parse(&r.eq, &r.func, "t")
            .unwrap()
            .with_values(&values);
        let sys = Explicit {
            rhs: ode.explicit().unwrap(),
            names: (0..ode.order)
                .map(|k| derivative_name(&r.func, k))
                .collect(),
        };
        let mut d = r.exact.clone();
        let mut y0 = Vec::new();
        for _ in 0..ode.order {
            y0.push(at(&d, t0));
            d = d.diff("t");
        }
        let config = AdaptiveConfig {
            rtol: Tolerance::Scalar(1e-12),
            atol: Tolerance::Scalar(1e-13),
            ..AdaptiveConfig::default()
        };
        let mut rk = AdaptiveRk::new(Tableau::dop853(), config).unwrap();
        let mut state = State::new(t0, y0);
        for j in 1..=8 {
            let tj = t0 + (r.t_end - t0) * f64::from(j) / 8.0;
            while state.t < tj {
                rk.step(&sys, &mut state, tj).unwrap();
            }
            let (got, exact) = (at(&s.solution, tj), at(&r.exact, tj));
            let scale = exact.abs().max(1.0);
            assert!(
                (got - exact).abs() <= 1e-9 * scale,
                "{}: {} vs exact {} at t = {tj}: {got} vs {exact}",
                r.eq,
                s.solution,
                r.exact
            );
            assert!(
                (state.y[0] - got).abs() <= 1e-7 * scale,
                "{}: DOP853 {} vs {got} at t = {tj}",
                r.eq,
                state.y[0]
            );
        }
    }
    println!(
        "{} equations, {symbolic} equal to the exact form symbolically",
        rows.len()
    );
}

#[test]
fn values_decide_the_damping_case() {
    let case = |set: &str| {
        let p = parse_params(set).unwrap();
        dsolve("m*x'' + c*x' + k*x = 0", "x", "t", None, &p)
            .unwrap()
            .method
    };
    assert!(case("m=1,c=1,k=4").contains("under-damped"));
    assert!(case("m=1,c=5,k=4").contains("over-damped"));
    assert!(case("m=1,c=4,k=4").contains("critically damped"));
    let s = dsolve("m*x'' = -k*x", "x", "t", None, &[]).unwrap();
    assert_eq!(s.assumptions, ["k/m > 0"]);
    assert_eq!(s.constants, ["C1", "C2"]);
}

#[test]
fn no_method_points_to_a_numerical_solution() {
    let e = dsolve("x'' + sin(x) = 0", "x", "t", None, &[])
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("no closed form") && e.contains("mechkit run"),
        "{e}"
    );
}

/// Review C-25: initial conditions where the equation is singular are refused: `x' = 1/x`
/// with `x(0) = 0` has no finite `x'` there, and both `√(2t)` and `−√(2t)` leave that point.
#[test]
fn conditions_where_the_equation_is_singular_are_refused() {
    for (eq, ic) in [("x' = 1/x", "x(0)=0"), ("x'' = 1/x", "x(0)=0, x'(0)=1")] {
        let e = dsolve(eq, "x", "t", Some(ic), &[]).unwrap_err();
        assert!(
            e.to_string().contains("is singular at the initial point"),
            "{eq}: {e}"
        );
    }
    // a regular point of the same equation is solved
    assert!(dsolve("x' = 1/x", "x", "t", Some("x(0)=1"), &[]).is_ok());
}

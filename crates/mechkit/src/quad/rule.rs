//! Fixed composite rules on `n` equal panels, the ones a course compares side by side (Burden
//! and Faires, *Numerical Analysis*, 9th ed., 2011, §4.3-4.7).
//!
//! With `h = (b − a)/n` and `x_i = a + i h`:
//!
//! | rule | formula | error |
//! |------|---------|-------|
//! | left | `h Σ_{i=0}^{n−1} f(x_i)` | `O(h)` |
//! | right | `h Σ_{i=1}^{n} f(x_i)` | `O(h)` |
//! | midpoint | `h Σ_{i=0}^{n−1} f(x_i + h/2)` | `O(h²)` |
//! | trapezoid | `h (f(x_0)/2 + Σ_{i=1}^{n−1} f(x_i) + f(x_n)/2)` | `O(h²)` |
//! | Simpson (`n` even) | `h/3 (f(x_0) + 4 Σ_{odd} f(x_i) + 2 Σ_{even} f(x_i) + f(x_n))` | `O(h⁴)` |
//! | Gauss-Legendre, `N` points per panel | `h/2 Σ_panels Σ_j w_j f(c + t_j h/2)` | `O(h^{2N})` |
//!
//! where `c` is a panel's centre and `(t_j, w_j)` come from [`gauss_legendre`].

use std::fmt;

use thiserror::Error;

use super::gauss_legendre::{MAX_GAUSS_POINTS, gauss_legendre};
use crate::Real;

/// A fixed composite quadrature rule.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Rule {
    /// Rectangles at the left end of each panel.
    Left,
    /// Rectangles at the right end of each panel.
    Right,
    /// Rectangles at the centre of each panel.
    Midpoint,
    /// Trapezoids.
    Trapezoid,
    /// Parabolas through pairs of panels (needs an even number of panels).
    Simpson,
    /// Gauss-Legendre with this many points per panel (1 to 64).
    GaussLegendre(usize),
}

impl Rule {
    /// The rules of a first course: left, right, midpoint, trapezoid, Simpson.
    pub const BASIC: [Rule; 5] = [
        Rule::Left,
        Rule::Right,
        Rule::Midpoint,
        Rule::Trapezoid,
        Rule::Simpson,
    ];

    /// Points per panel when `"gauss-legendre"` is given without a number.
    pub const DEFAULT_GAUSS_POINTS: usize = 5;

    /// The rule's name: `"left"`, `"right"`, `"midpoint"`, `"trapezoid"`, `"simpson"`,
    /// `"gauss-legendre-5"`. [`Rule::parse`] reads it back.
    pub fn name(&self) -> String {
        self.to_string()
    }

    /// Reads a rule's [name](Rule::name); `"gauss-legendre"` alone means 5 points per panel.
    /// `None` for anything else, including Gauss-Legendre with 0 or more than 64 points.
    ///
    /// # Example
    /// ```
    /// use mechkit::quad::Rule;
    /// assert_eq!(Rule::parse("simpson"), Some(Rule::Simpson));
    /// assert_eq!(Rule::parse("gauss-legendre-3"), Some(Rule::GaussLegendre(3)));
    /// assert_eq!(Rule::parse("gauss-legendre"), Some(Rule::GaussLegendre(5)));
    /// assert_eq!(Rule::parse("gauss-legendre-0"), None);
    /// ```
    pub fn parse(text: &str) -> Option<Rule> {
        let rule = match text.trim() {
            "left" => Rule::Left,
            "right" => Rule::Right,
            "midpoint" => Rule::Midpoint,
            "trapezoid" => Rule::Trapezoid,
            "simpson" => Rule::Simpson,
            "gauss-legendre" => Rule::GaussLegendre(Self::DEFAULT_GAUSS_POINTS),
            other => {
                let points: usize = other.strip_prefix("gauss-legendre-")?.parse().ok()?;
                if !(1..=MAX_GAUSS_POINTS).contains(&points) {
                    return None;
                }
                Rule::GaussLegendre(points)
            }
        };
        Some(rule)
    }

    /// Reads a list of rule names, where `"all"` stands for the [basic](Rule::BASIC) rules
    /// and Gauss-Legendre with 5 points. The error names the first unknown rule and lists the
    /// known ones.
    ///
    /// # Example
    /// ```
    /// use mechkit::quad::Rule;
    /// assert_eq!(Rule::parse_list(&["left", " simpson"]).unwrap(), [Rule::Left, Rule::Simpson]);
    /// assert_eq!(Rule::parse_list(&["all"]).unwrap().len(), 6);
    /// assert!(Rule::parse_list(&["trapezoidal"]).unwrap_err().contains("`trapezoidal`"));
    /// ```
    ///
    /// # Errors
    /// A name that is not a rule (the message says which names are).
    pub fn parse_list<S: AsRef<str>>(names: &[S]) -> Result<Vec<Rule>, String> {
        let mut rules = Vec::new();
        for name in names.iter().map(|n| n.as_ref().trim()) {
            if name == "all" {
                rules.extend(Rule::BASIC);
                rules.push(Rule::GaussLegendre(Rule::DEFAULT_GAUSS_POINTS));
                continue;
            }
            match Rule::parse(name) {
                Some(r) => rules.push(r),
                None => {
                    return Err(format!(
                        "unknown rule `{name}`; use left, right, midpoint, trapezoid, simpson, gauss-legendre-N (e.g. gauss-legendre-5) or all"
                    ));
                }
            }
        }
        Ok(rules)
    }

    /// The evaluations of the integrand the rule makes on `n` panels (saturating).
    pub fn evaluations(&self, n: usize) -> usize {
        match *self {
            Rule::Left | Rule::Right | Rule::Midpoint => n,
            Rule::Trapezoid | Rule::Simpson => n.saturating_add(1),
            Rule::GaussLegendre(points) => n.saturating_mul(points),
        }
    }

    /// The most panels the rule may have: [`MAX_EVALUATIONS`] evaluations.
    pub fn max_intervals(&self) -> usize {
        match *self {
            Rule::Left | Rule::Right | Rule::Midpoint => MAX_EVALUATIONS,
            Rule::Trapezoid | Rule::Simpson => MAX_EVALUATIONS - 2,
            Rule::GaussLegendre(points) => MAX_EVALUATIONS / points.max(1),
        }
    }

    /// Whether the rule can be applied on `n` panels: at least one, an even number for
    /// Simpson's rule, 1 to 64 points per panel for Gauss-Legendre, and at most
    /// [`MAX_EVALUATIONS`] evaluations in all. [`integrate_rule`] checks the same; a front
    /// checks it before any other work.
    ///
    /// # Errors
    /// The first of these that fails.
    pub fn check_intervals(&self, n: usize) -> Result<(), RuleError> {
        if n == 0 {
            return Err(RuleError::NoIntervals);
        }
        match *self {
            Rule::Simpson if n % 2 == 1 => return Err(RuleError::OddSimpson { n }),
            Rule::GaussLegendre(points) if !(1..=MAX_GAUSS_POINTS).contains(&points) => {
                return Err(RuleError::GaussPoints { points });
            }
            _ => {}
        }
        if n > self.max_intervals() {
            return Err(RuleError::TooManyEvaluations {
                rule: *self,
                n,
                evaluations: self.evaluations(n),
            });
        }
        Ok(())
    }

    /// Order of convergence `p` for smooth integrands: the error scales as `h^p`
    /// (1, 1, 2, 2, 4 and `2N`).
    pub fn order(&self) -> usize {
        match *self {
            Rule::Left | Rule::Right => 1,
            Rule::Midpoint | Rule::Trapezoid => 2,
            Rule::Simpson => 4,
            Rule::GaussLegendre(points) => 2 * points,
        }
    }
}

impl fmt::Display for Rule {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Rule::Left => f.write_str("left"),
            Rule::Right => f.write_str("right"),
            Rule::Midpoint => f.write_str("midpoint"),
            Rule::Trapezoid => f.write_str("trapezoid"),
            Rule::Simpson => f.write_str("simpson"),
            Rule::GaussLegendre(points) => write!(f, "gauss-legendre-{points}"),
        }
    }
}

/// The most evaluations of the integrand one fixed rule makes: 10^8, a second or two of a
/// compiled formula. `integrate --n 1e12` asked for 10^12 and ran for hours; a rule's error
/// falls as `h^p`, so more panels than this add nothing a double can hold for a smooth
/// integrand (and the adaptive quadrature serves the others).
pub const MAX_EVALUATIONS: usize = 100_000_000;

/// Why a fixed rule could not be applied.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum RuleError {
    /// `n = 0`.
    #[error("the number of intervals must be at least 1")]
    NoIntervals,
    /// Simpson's rule with an odd number of intervals.
    #[error(
        "Simpson's rule needs an even number of intervals, not {n}: use an even n such as {}",
        .n + 1
    )]
    OddSimpson {
        /// The intervals asked for.
        n: usize,
    },
    /// A Gauss-Legendre rule with 0 or more than 64 points per panel.
    #[error("Gauss-Legendre rules have 1 to 64 points per panel, not {points}")]
    GaussPoints {
        /// The points asked for.
        points: usize,
    },
    /// More evaluations than [`MAX_EVALUATIONS`].
    #[error(
        "{rule} on {n} intervals evaluates the integrand {evaluations} times, more than the {MAX_EVALUATIONS} a rule may; use at most {} intervals",
        rule.max_intervals()
    )]
    TooManyEvaluations {
        /// The rule.
        rule: Rule,
        /// The intervals asked for.
        n: usize,
        /// The evaluations they take (saturated).
        evaluations: usize,
    },
    /// A limit is infinite or NaN (use the adaptive [`integrate`](super::integrate)).
    #[error("fixed rules need finite limits, not {} and {}", crate::error::short(*a), crate::error::short(*b))]
    BadLimits {
        /// Lower limit.
        a: Real,
        /// Upper limit.
        b: Real,
    },
    /// The integrand is not finite at a node.
    #[error(
        "the integrand is {value} at x = {}: the integral may not exist there (a singularity); \
         check the interval, or integrate up to a point near it",
        super::short(*.x)
    )]
    NotFinite {
        /// Where.
        x: Real,
        /// What it was.
        value: Real,
    },
}

/// `∫_a^b f(x) dx` by `rule` on `n` equal intervals (panels).
///
/// For `b < a` the result is minus the same rule on `[b, a]` (so `Left` always samples the
/// smaller end of each panel). Every node is checked: a non-finite value is an error naming it.
///
/// # Example
/// The work of `F = −F₀ sin(2πx/b)` over a quarter period (`F₀ = b = 1`, exact `−1/2π`):
/// ```
/// use approx::assert_relative_eq;
/// use mechkit::quad::{Rule, integrate_rule};
/// let force = |x: f64| -(2.0 * std::f64::consts::PI * x).sin();
/// let w = integrate_rule(force, 0.0, 0.25, Rule::Trapezoid, 10).unwrap();
/// assert_relative_eq!(w, -0.158_828, epsilon = 1e-6);
/// let w = integrate_rule(force, 0.0, 0.25, Rule::GaussLegendre(5), 1).unwrap();
/// assert_relative_eq!(w, -0.5 / std::f64::consts::PI, epsilon = 1e-9);
/// ```
pub fn integrate_rule(
    mut f: impl FnMut(Real) -> Real,
    a: Real,
    b: Real,
    rule: Rule,
    n: usize,
) -> Result<Real, RuleError> {
    rule.check_intervals(n)?;
    if !a.is_finite() || !b.is_finite() {
        return Err(RuleError::BadLimits { a, b });
    }
    if b < a {
        return composite(&mut f, b, a, rule, n).map(|v| -v);
    }
    composite(&mut f, a, b, rule, n)
}

/// The rule on `a ≤ b`, arguments already checked.
fn composite(
    f: &mut dyn FnMut(Real) -> Real,
    a: Real,
    b: Real,
    rule: Rule,
    n: usize,
) -> Result<Real, RuleError> {
    let h = (b - a) / n as Real;
    let node = |i: usize| if i == n { b } else { a + i as Real * h };
    let mut eval = |x: Real| {
        let value = f(x);
        if value.is_finite() {
            Ok(value)
        } else {
            Err(RuleError::NotFinite { x, value })
        }
    };
    let mut sum = |range: std::ops::Range<usize>, step: usize, x: &dyn Fn(usize) -> Real| {
        range
            .step_by(step)
            .try_fold(0.0, |s, i| Ok::<_, RuleError>(s + eval(x(i))?))
    };
    let value = match rule {
        Rule::Left => h * sum(0..n, 1, &node)?,
        Rule::Right => h * sum(1..n + 1, 1, &node)?,
        Rule::Midpoint => h * sum(0..n, 1, &|i| a + (i as Real + 0.5) * h)?,
        Rule::Trapezoid => {
            let ends = sum(0..n + 1, n, &node)?; // f(x_0) + f(x_n)
            h * (0.5 * ends + sum(1..n, 1, &node)?)
        }
        Rule::Simpson => {
            let ends = sum(0..n + 1, n, &node)?;
            let odd = sum(1..n, 2, &node)?;
            let even = sum(2..n, 2, &node)?;
            h / 3.0 * (ends + 4.0 * odd + 2.0 * even)
        }
        Rule::GaussLegendre(points) => {
            let (t, w) = gauss_legendre(points);
            let half = 0.5 * h;
            let mut total = 0.0;
            for i in 0..n {
                let c = a + (i as Real + 0.5) * h;
                let mut panel = 0.0;
                for (&t, &w) in t.iter().zip(&w) {
                    panel += w * eval(c + half * t)?;
                }
                total += panel;
            }
            half * total
        }
    };
    Ok(value)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Issue 26: `integrate --n 1e12` ran for hours; a rule refuses more evaluations than
    /// [`MAX_EVALUATIONS`] before the first.
    #[test]
    fn issue_026_a_rule_refuses_panels_past_its_evaluation_bound() {
        let mut calls = 0;
        let e = integrate_rule(
            |x| {
                calls += 1;
                x
            },
            0.0,
            1.0,
            Rule::Trapezoid,
            1_000_000_000_000,
        )
        .unwrap_err();
        assert_eq!(calls, 0);
        assert!(e.to_string().contains("1000000000001 times"), "{e}");
        assert!(e.to_string().contains("at most 99999998 intervals"), "{e}");
        let e = Rule::GaussLegendre(64)
            .check_intervals(2_000_000)
            .unwrap_err();
        assert!(e.to_string().contains("at most 1562500 intervals"), "{e}");
        assert!(Rule::Midpoint.check_intervals(MAX_EVALUATIONS).is_ok());
        assert!(Rule::GaussLegendre(64).check_intervals(usize::MAX).is_err());
    }

    #[test]
    fn names_round_trip() {
        for rule in Rule::BASIC
            .into_iter()
            .chain([1, 5, 64].map(Rule::GaussLegendre))
        {
            assert_eq!(Rule::parse(&rule.name()), Some(rule));
        }
        assert_eq!(Rule::GaussLegendre(5).name(), "gauss-legendre-5");
        for bad in ["", "gauss", "gauss-legendre-65", "gauss-legendre-x", "Left"] {
            assert_eq!(Rule::parse(bad), None, "{bad:?}");
        }
        let orders: Vec<usize> = Rule::BASIC.iter().map(Rule::order).collect();
        assert_eq!(orders, [1, 1, 2, 2, 4]);
        assert_eq!(Rule::GaussLegendre(3).order(), 6);
    }

    #[test]
    fn each_rule_is_exact_where_it_should_be() {
        // constants: every rule; linear: all but left/right; cubic: Simpson and Gauss(2)
        for rule in Rule::BASIC {
            let v = integrate_rule(|_| 3.0, 1.0, 2.0, rule, 4).unwrap();
            assert!((v - 3.0).abs() < 1e-15, "{rule}");
        }
        for rule in [Rule::Midpoint, Rule::Trapezoid, Rule::Simpson] {
            let v = integrate_rule(|x| 2.0 * x, 0.0, 1.0, rule, 6).unwrap();
            assert!((v - 1.0).abs() < 1e-15, "{rule}");
        }
        for rule in [Rule::Simpson, Rule::GaussLegendre(2)] {
            let v = integrate_rule(|x| x * x * x, 0.0, 2.0, rule, 2).unwrap();
            assert!((v - 4.0).abs() < 1e-14, "{rule}");
        }
        // left and right bracket an increasing integrand: ∫0^1 x = 0.5, n = 4
        assert_eq!(integrate_rule(|x| x, 0.0, 1.0, Rule::Left, 4), Ok(0.375));
        assert_eq!(integrate_rule(|x| x, 0.0, 1.0, Rule::Right, 4), Ok(0.625));
    }

    #[test]
    fn reversed_and_empty_intervals() {
        for rule in Rule::BASIC.into_iter().chain([Rule::GaussLegendre(4)]) {
            let forward = integrate_rule(f64::exp, 0.0, 1.0, rule, 8).unwrap();
            let backward = integrate_rule(f64::exp, 1.0, 0.0, rule, 8).unwrap();
            assert_eq!(backward, -forward, "{rule}");
            assert_eq!(
                integrate_rule(f64::exp, 2.0, 2.0, rule, 8),
                Ok(0.0),
                "{rule}"
            );
        }
    }

    #[test]
    fn errors() {
        let f = |x: f64| x;
        assert_eq!(
            integrate_rule(f, 0.0, 1.0, Rule::Left, 0),
            Err(RuleError::NoIntervals)
        );
        let e = integrate_rule(f, 0.0, 1.0, Rule::Simpson, 7).unwrap_err();
        assert_eq!(e, RuleError::OddSimpson { n: 7 });
        assert!(e.to_string().contains("even n such as 8"), "{e}");
        assert_eq!(
            integrate_rule(f, 0.0, 1.0, Rule::GaussLegendre(0), 1),
            Err(RuleError::GaussPoints { points: 0 })
        );
        assert!(matches!(
            integrate_rule(f, 0.0, f64::INFINITY, Rule::Trapezoid, 4),
            Err(RuleError::BadLimits { .. })
        ));
        // 1/x at the left end: the left rule and the trapezoid touch it, the midpoint does not
        let e = integrate_rule(|x| 1.0 / x, 0.0, 1.0, Rule::Left, 4).unwrap_err();
        assert_eq!(
            e,
            RuleError::NotFinite {
                x: 0.0,
                value: f64::INFINITY
            }
        );
        assert!(e.to_string().contains("x = 0"), "{e}");
        assert!(integrate_rule(|x| 1.0 / x, 0.0, 1.0, Rule::Midpoint, 4).is_ok());
    }
}

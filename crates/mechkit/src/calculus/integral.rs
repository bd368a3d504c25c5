//! Antiderivatives from the rule table (verified by differentiation), definite integrals by
//! the closed form and by adaptive quadrature side by side, and the fixed rules of a course
//! against the exact value with their observed orders.

use mechkit_expr::sym::Antiderivative;
use mechkit_expr::{Number, Sym, parse};

use super::singular::{Singularity, show_point};
use super::{CalculusError, Params, lookup};
use crate::Real;
use crate::function::Function;
use crate::inputs::{Input, InputError};
use crate::quad::{
    QuadError, QuadResult, Rule, Tolerance, integrate as quadrature, integrate_rule,
};

/// An integral: the antiderivative when the rule table has one, and the definite value by
/// both routes when limits are given.
#[derive(Debug, Clone, PartialEq)]
pub struct Integral {
    /// The integrand, canonical.
    pub input: Sym,
    /// An antiderivative (verified by differentiation), if found.
    pub antiderivative: Option<Sym>,
    /// What it assumed.
    pub assumptions: Vec<String>,
    /// The definite integral, if limits were given.
    pub definite: Option<Definite>,
}

/// A definite integral by the closed form and by quadrature.
///
/// Serialized as `{from, to, closed_form, quadrature: {value, error, evaluations} | null,
/// quadrature_error: text | null, agree}`.
#[derive(Debug, Clone, PartialEq)]
pub struct Definite {
    /// Lower limit.
    pub from: Real,
    /// Upper limit.
    pub to: Real,
    /// `F(to) - F(from)`, when there is an antiderivative continuous on the interval and all
    /// names have values.
    pub closed_form: Option<Real>,
    /// Adaptive Gauss-Kronrod.
    pub quadrature: Result<QuadResult, String>,
    /// Whether the two agree within the quadrature's error estimate (or 1e-9 relative).
    pub agree: Option<bool>,
}

impl Definite {
    /// The value to trust: the closed form where it agrees with the quadrature, else the
    /// quadrature's value; `None` when the quadrature failed (a closed form alone may have
    /// jumped across a singularity, as `ln|x|` across 0 does). The fixed rules are measured
    /// against it.
    ///
    /// ```
    /// use mechkit::calculus::integral;
    /// let d = integral("x^2", "x", Some((0.0, 1.0)), &[]).unwrap().definite.unwrap();
    /// assert_eq!(d.value(), Some(1.0 / 3.0));
    /// // across a pole the integral diverges: refused before anything is computed (the closed
    /// // form ln|2| − ln|−1| would have been a wrong answer)
    /// assert!(integral("1/x", "x", Some((-1.0, 2.0)), &[]).is_err());
    /// ```
    pub fn value(&self) -> Option<Real> {
        match (self.closed_form, self.agree, &self.quadrature) {
            (Some(c), Some(true), _) => Some(c),
            (_, _, Ok(q)) => Some(q.value),
            _ => None,
        }
    }
}

#[cfg(feature = "serde")]
impl serde::Serialize for Definite {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeStruct;
        #[derive(serde::Serialize)]
        struct Quad {
            value: Real,
            error: Real,
            evaluations: usize,
        }
        let mut st = s.serialize_struct("Definite", 6)?;
        // an infinite limit is an input, echoed as null (JSON has no infinity): not an
        // answer, so the finiteness rule passes it
        let limit = |x: Real| x.is_finite().then_some(x);
        st.serialize_field("from", &limit(self.from))?;
        st.serialize_field("to", &limit(self.to))?;
        st.serialize_field("closed_form", &self.closed_form)?;
        st.serialize_field(
            "quadrature",
            &self.quadrature.as_ref().ok().map(|q| Quad {
                value: q.value,
                error: q.error,
                evaluations: q.evaluations,
            }),
        )?;
        st.serialize_field("quadrature_error", &self.quadrature.as_ref().err())?;
        st.serialize_field("agree", &self.agree)?;
        st.end()
    }
}

/// The integral of `text` with respect to `x`, with `params` giving values to the other names
/// (needed for the definite value).
pub fn integral(
    text: &str,
    x: &str,
    limits: Option<(Real, Real)>,
    params: &Params,
) -> Result<Integral, CalculusError> {
    super::check_variable(x, Input::Variable)?;
    super::check_not_given(params, &[x])?;
    let (input, anti) = antiderivative_for(Sym::from_expr(&parse(text)?.expr), x, params);
    let (antiderivative, assumptions) = match anti {
        Some(a) => (Some(a.result), a.assumptions),
        None => (None, Vec::new()),
    };
    // a pole in [a, b] makes the integral diverge: refused, naming the point; an integrable
    // singularity inside is a breakpoint of the quadrature (the rule never samples it)
    let breaks = match limits {
        Some((from, to)) => super::singular::integrable(&input, x, params, from, to)
            .map_err(|s| diverges(text.trim(), x, s, (from, to)))?,
        None => Vec::new(),
    };
    let definite = limits.map(|(from, to)| {
        let env = lookup(params);
        let at = |f: &Sym, v: Real| f.eval(&|n| if n == x { Some(v) } else { env(n) });
        let ends: Vec<Real> = std::iter::once(from)
            .chain(breaks.iter().copied())
            .chain(std::iter::once(to))
            .collect();
        let quad = ends
            .windows(2)
            .map(|w| {
                quadrature(
                    |v| at(&input, v).unwrap_or(Real::NAN),
                    w[0],
                    w[1],
                    Tolerance::default(),
                )
                .or_else(|e| match e {
                    // an integrable singularity at an end (1/sqrt(1 - x^2) at ±1): the double
                    // exponential rule, the integrand expanded around each end
                    QuadError::NotConverged { .. } | QuadError::NotFinite { .. } => {
                        super::singular::endpoint_singular(&input, x, &lookup(params), w[0], w[1])
                            .ok_or(e)
                    }
                    other => Err(other),
                })
            })
            .try_fold(
                QuadResult {
                    value: 0.0,
                    error: 0.0,
                    evaluations: 0,
                },
                |sum, piece| {
                    piece.map(|q| QuadResult {
                        value: sum.value + q.value,
                        error: sum.error + q.error,
                        evaluations: sum.evaluations + q.evaluations,
                    })
                },
            )
            .map_err(|e| e.to_string());
        // the closed form counts only if it is continuous on the interval: compare with the
        // quadrature's value (a jump in ln|x| across 0 would show as a disagreement)
        let closed_form = antiderivative.as_ref().and_then(|big_f| {
            let (a, b) = (at(big_f, from).ok()?, at(big_f, to).ok()?);
            let v = b - a;
            v.is_finite().then_some(v)
        });
        let agree = match (&closed_form, &quad) {
            (Some(c), Ok(q)) => {
                Some((c - q.value).abs() <= (10.0 * q.error).max(1e-9 * c.abs().max(1e-12)))
            }
            _ => None,
        };
        Definite {
            from,
            to,
            closed_form,
            quadrature: quad,
            agree,
        }
    });
    if definite
        .as_ref()
        .is_some_and(|d| d.quadrature.is_err() && d.closed_form.is_none())
    {
        let missing: Vec<String> = input
            .names()
            .into_iter()
            .filter(|n| n != x && lookup(params)(n).is_none())
            .collect();
        if let Some(first) = missing.first() {
            return Err(CalculusError::Invalid(format!(
                "a definite value needs values for {}: give them with --set, e.g. --set {first}=1",
                missing.join(", "),
            )));
        }
    }
    Ok(Integral {
        input,
        antiderivative,
        assumptions,
        definite,
    })
}

/// The integrand and an antiderivative that holds for the values `params` gives: the
/// symbolic one when it does (its assumptions decided by the values, `F' = f` checked with
/// them), else that of the integrand with the values put in, which is then the integrand
/// returned. `1/(1 + e*cos(th))` with `e = 0.5` is the ellipse's `atan` form, not the
/// logarithm the symbolic search gives assuming `e - 1 > 0`; `sin(a*x)*sin(b*x)` with
/// `a = b` is `x/2 - sin(2 a x)/(4 a)`, not a formula dividing by `a - b`.
fn antiderivative_for(input: Sym, x: &str, params: &Params) -> (Sym, Option<Antiderivative>) {
    let names = input.names();
    let values: Vec<(String, Sym)> = params
        .iter()
        .filter(|(n, _)| n != x && names.contains(n))
        .map(|(n, v)| (n.clone(), Sym::Num(Number::from_f64(*v))))
        .collect();
    let symbolic = input.integrate(x);
    if values.is_empty()
        || symbolic
            .as_ref()
            .is_some_and(|a| a.holds_for(&input, x, &values))
    {
        return (input, symbolic);
    }
    let concrete = values
        .iter()
        .fold(input, |s, (name, v)| s.substitute(name, v));
    let anti = concrete.integrate(x);
    (concrete, anti)
}

/// The refusal of a definite integral across a pole: `1/x^2` is not integrable at x = 0.
fn diverges(input: &str, x: &str, s: Singularity, (from, to): (Real, Real)) -> InputError {
    let at = show_point(s.at);
    let growth = super::singular::pole_growth(x, s);
    InputError::new(
        Input::Limits,
        format!(
            "`{input}` is not integrable at {x} = {at} in [{}, {}]: the integral diverges{growth}\n  \
             = hint: integrate up to a point before {at} (or from one after it), where the value is finite",
            show_point(from),
            show_point(to)
        ),
    )
}

/// One fixed rule's estimate of a definite integral, next to the exact value.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct RuleEstimate {
    /// The rule (its name in JSON).
    #[cfg_attr(feature = "serde", serde(serialize_with = "super::text::display"))]
    pub rule: Rule,
    /// Number of intervals.
    pub n: usize,
    /// Its value.
    pub value: Real,
    /// `value - reference`.
    pub error: Real,
    /// The convergence order measured against the previous number of intervals of the same
    /// rule, `ln(e_prev/e)/ln(n/n_prev)` (none for the first, or when an error is down at
    /// rounding level).
    pub observed_order: Option<Real>,
}

/// The estimates of `∫ text dx` over `limits` by each rule with each number of intervals, and
/// the reference they are measured against: the closed form when the rule table has one
/// (checked against adaptive quadrature), else adaptive Gauss-Kronrod quadrature.
///
/// ```
/// use mechkit::calculus::rule_estimates;
/// use mechkit::quad::Rule;
/// let (reference, rows) = rule_estimates("1/(1 + x^2)", "x", (0.0, 1.0), &[],
///     &[Rule::Trapezoid], &[10]).unwrap();
/// assert!((reference - std::f64::consts::FRAC_PI_4).abs() < 1e-15);
/// assert!((rows[0].value - 0.784_981).abs() < 1e-6);
/// let (_, rows) = rule_estimates("exp(x)", "x", (0.0, 1.0), &[], &[Rule::Simpson], &[8, 16]).unwrap();
/// assert!((rows[1].observed_order.unwrap() - 4.0).abs() < 0.05);
/// ```
pub fn rule_estimates(
    text: &str,
    x: &str,
    limits: (Real, Real),
    params: &Params,
    rules: &[Rule],
    ns: &[usize],
) -> Result<(Real, Vec<RuleEstimate>), CalculusError> {
    let f = Function::parse(text, &[x], params)?;
    let exact = integral(text, x, Some(limits), params)?
        .definite
        .and_then(|d| d.value())
        .ok_or_else(|| {
            CalculusError::Invalid(format!(
                "`{text}` could not be integrated from {} to {} to compare the rules with",
                crate::error::short(limits.0),
                crate::error::short(limits.1)
            ))
        })?;
    Ok((exact, estimates(&f, limits, exact, rules, ns)?))
}

fn estimates(
    f: &Function,
    limits: (Real, Real),
    exact: Real,
    rules: &[Rule],
    ns: &[usize],
) -> Result<Vec<RuleEstimate>, CalculusError> {
    if let Some(&bad) = ns.iter().find(|&&n| n == 0) {
        return Err(InputError::new(
            Input::Intervals,
            format!("the number of intervals must be at least 1, not {bad}"),
        )
        .into());
    }
    let mut rows = Vec::new();
    for &rule in rules {
        let mut previous: Option<(usize, Real)> = None;
        for &n in ns {
            let value = integrate_rule(|v| f.at1(v), limits.0, limits.1, rule, n)
                .map_err(|e| CalculusError::Invalid(format!("{}: {e}", rule.name())))?;
            let error = value - exact;
            // errors at the level of rounding carry no order
            let noise = 1e3 * Real::EPSILON * exact.abs().max(Real::MIN_POSITIVE);
            let observed_order = previous.and_then(|(n0, e0)| {
                let o = (e0.abs() / error.abs()).ln() / (n as Real / n0 as Real).ln();
                (o.is_finite() && n != n0 && e0.abs() > noise && error.abs() > noise).then_some(o)
            });
            previous = Some((n, error));
            rows.push(RuleEstimate {
                rule,
                n,
                value,
                error,
                observed_order,
            });
        }
    }
    Ok(rows)
}

/// The answer of `mechkit integrate`: the antiderivative, the definite value by both routes,
/// and the fixed rules against the exact value when asked.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Integration {
    /// The integrand, canonical.
    #[cfg_attr(feature = "serde", serde(serialize_with = "super::text::display"))]
    pub input: Sym,
    /// The variable of integration.
    pub var: String,
    /// An antiderivative (verified by differentiation), if the rule table has one.
    #[cfg_attr(feature = "serde", serde(serialize_with = "super::text::display_opt"))]
    pub antiderivative: Option<Sym>,
    /// What it assumed (`a > 0`).
    pub assumptions: Vec<String>,
    /// The values given to the other names (a JSON object).
    #[cfg_attr(feature = "serde", serde(serialize_with = "super::text::params"))]
    pub parameters: Vec<(String, Real)>,
    /// The definite integral, with limits.
    pub definite: Option<Definite>,
    /// The exact value the fixed rules are measured against, with rules.
    pub reference: Option<Real>,
    /// The fixed rules' estimates, with rules.
    pub rules: Option<Vec<RuleEstimate>>,
}

impl Integration {
    /// Whether nothing could be computed: no closed form, and no definite value either; or,
    /// when limits were given, no definite value (neither its closed form nor quadrature).
    pub fn found_nothing(&self) -> bool {
        match &self.definite {
            Some(d) => d.closed_form.is_none() && d.quadrature.is_err(),
            None => self.antiderivative.is_none(),
        }
    }
}

/// `∫ text dx`: the antiderivative, the definite value over `limits` (closed form and
/// quadrature), and with `rules` (given with limits) each rule's estimate with each number of
/// intervals in `ns` against the exact value.
///
/// ```
/// use mechkit::calculus::integration;
/// use mechkit::quad::Rule;
/// let i = integration("1/(a+x^2)", "x", Some((0.0, 1.0)), &[("a".into(), 1.0)],
///     &[Rule::Trapezoid], &[10, 20]).unwrap();
/// assert_eq!(i.antiderivative.unwrap().to_string(), "atan(x/sqrt(a))/sqrt(a)");
/// assert_eq!(i.definite.unwrap().agree, Some(true));
/// let order = i.rules.unwrap()[1].observed_order.unwrap();
/// assert!((order - 2.0).abs() < 0.01);
/// ```
pub fn integration(
    text: &str,
    x: &str,
    limits: Option<(Real, Real)>,
    params: &Params,
    rules: &[Rule],
    ns: &[usize],
) -> Result<Integration, CalculusError> {
    let i = integral(text, x, limits, params)?;
    let mut reference_value = None;
    let mut rows = None;
    if let (false, Some(lim)) = (rules.is_empty(), limits) {
        let f = Function::parse(text, &[x], params)?;
        let exact = i
            .definite
            .as_ref()
            .and_then(Definite::value)
            .ok_or_else(|| {
                CalculusError::Invalid(format!(
                    "`{text}` could not be integrated from {} to {} to compare the rules with",
                    crate::error::short(lim.0),
                    crate::error::short(lim.1)
                ))
            })?;
        rows = Some(estimates(&f, lim, exact, rules, ns)?);
        reference_value = Some(exact);
    }
    Ok(Integration {
        input: i.input,
        var: x.to_string(),
        antiderivative: i.antiderivative,
        assumptions: i.assumptions,
        parameters: params.to_vec(),
        definite: i.definite,
        reference: reference_value,
        rules: rows,
    })
}

#[cfg(test)]
#[path = "integral_tests.rs"]
mod tests;

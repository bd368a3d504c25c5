//! `d/dx` of a formula, simplified, and its value at a point checked against Ridders'
//! extrapolation of central differences.

use mechkit_expr::{Sym, parse};

use super::{CalculusError, Params};
use crate::Real;
use crate::deriv::Verdict;
use crate::function::Function;
use crate::inputs::{Input, InputError};

/// A derivative.
#[derive(Debug, Clone, PartialEq)]
pub struct Derivative {
    /// The formula, canonical.
    pub input: Sym,
    /// Its derivative, simplified.
    pub result: Sym,
}

/// `d/dx` of `text`.
pub fn derivative(text: &str, x: &str) -> Result<Derivative, CalculusError> {
    super::check_variable(x, Input::Variable)?;
    let input = Sym::from_expr(&parse(text)?.expr);
    let result = input.diff(x);
    Ok(Derivative { input, result })
}

/// The value of a derivative at a point by the symbolic derivative and by Ridders'
/// extrapolation of central differences, side by side.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct DerivativeCheck {
    /// Where.
    #[cfg_attr(feature = "serde", serde(rename = "x"))]
    pub at: Real,
    /// The symbolic derivative's value (`None` where it is not a finite number: outside the
    /// formula's domain, at a singularity, a vertical tangent).
    pub symbolic: Option<Real>,
    /// Ridders' estimate (`None` where it is not a finite number).
    pub numeric: Option<Real>,
    /// Its error estimate (`None` where it is not a finite number).
    pub numeric_error: Option<Real>,
    /// Whether they agree within the estimate (or 1e-9 relative), and the estimate is sure
    /// enough to say so ([`crate::deriv::confirm`]).
    pub agree: bool,
    /// Whether the derivative's formula has no value at the point while the numerical
    /// estimate is sure and nothing breaks the function there: the derivative exists and is
    /// `numeric` (a removable singularity of the formula: `2*x^3/sqrt(x^4)` at 0).
    pub estimate_only: bool,
    /// Where the formula jumps at the point (no derivative exists there): its values just
    /// left and just right of it, `[left, right]` in JSON.
    pub jump: Option<[Real; 2]>,
    /// Where the formula is continuous but has a corner or a cusp at the point (no derivative
    /// exists there): its slopes just left and just right of it, `[left, right]` in JSON.
    pub kink: Option<[Real; 2]>,
    /// Where the formula's slopes grow without bound on both sides of the point (a vertical
    /// tangent, or a cusp when they have opposite signs; no finite derivative exists there):
    /// the slopes over the smallest steps tried, `[left, right]` in JSON.
    pub vertical: Option<[Real; 2]>,
}

/// `d/dx text` at `at`, symbolically and numerically (initial step `h`, e.g. 0.1 or a tenth
/// of the scale of `x`), with `params` for the other names.
///
/// ```
/// let c = mechkit::calculus::derivative_at("x^3*sin(x)", "x", 1.2, &[], 0.1).unwrap();
/// assert!(c.agree && (c.symbolic.unwrap() - c.numeric.unwrap()).abs() < 1e-10);
/// // floor jumps at 1: no derivative there, whatever the rules say (0)
/// let c = mechkit::calculus::derivative_at("floor(x)", "x", 1.0, &[], 0.1).unwrap();
/// assert!(!c.agree && c.jump == Some([0.0, 1.0]));
/// // |x| has a corner at 0: no derivative there either (the rules say sign(0) = 0)
/// let c = mechkit::calculus::derivative_at("abs(x)", "x", 0.0, &[], 0.1).unwrap();
/// assert!(!c.agree && c.kink.is_some_and(|[l, r]| (l + 1.0).abs() < 1e-6 && (r - 1.0).abs() < 1e-6));
/// // cbrt(x) has a vertical tangent at 0: its derivative's formula gives no finite value
/// let c = mechkit::calculus::derivative_at("cbrt(x)", "x", 0.0, &[], 0.1).unwrap();
/// assert!(!c.agree && c.symbolic.is_none() && c.vertical.is_some_and(|[l, r]| l > 1e3 && r > 1e3));
/// ```
pub fn derivative_at(
    text: &str,
    x: &str,
    at: Real,
    params: &Params,
    h: Real,
) -> Result<DerivativeCheck, CalculusError> {
    let f = Function::parse(text, &[x], params)?;
    let symbolic = f.diff(x).at1(at);
    let (est, verdict) = crate::deriv::confirm(|v| f.at1(v), at, h, symbolic);
    let (mut jump, mut kink, mut vertical) = (None, None, None);
    match verdict {
        Verdict::Jump { left, right } => jump = Some([left, right]),
        Verdict::Kink { left, right } => kink = Some([left, right]),
        Verdict::Vertical { left, right } => vertical = Some([left, right]),
        Verdict::Agree | Verdict::Disagree | Verdict::EstimateOnly => {}
    }
    let finite = |v: Real| v.is_finite().then_some(v);
    Ok(DerivativeCheck {
        at,
        symbolic: finite(symbolic),
        numeric: finite(est.value),
        numeric_error: finite(est.error),
        agree: verdict == Verdict::Agree,
        estimate_only: verdict == Verdict::EstimateOnly,
        jump,
        kink,
        vertical,
    })
}

/// The answer of `mechkit diff`: the derivative, and its check at a point when asked.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Differentiation {
    /// The formula, canonical.
    #[cfg_attr(feature = "serde", serde(serialize_with = "super::text::display"))]
    pub input: Sym,
    /// The variable.
    pub var: String,
    /// The derivative, simplified.
    #[cfg_attr(feature = "serde", serde(serialize_with = "super::text::display"))]
    pub derivative: Sym,
    /// Its value at the point asked, symbolically and numerically.
    pub at: Option<DerivativeCheck>,
}

impl Differentiation {
    /// Whether the check (if any) found the two values in agreement.
    pub fn agrees(&self) -> bool {
        self.at.is_none_or(|c| c.agree)
    }
}

/// `d/dx text`, and with `at = Some((point, h))` its value at `point` checked numerically
/// from the initial step `h` (positive), with `params` for the other names.
///
/// ```
/// use mechkit::calculus::differentiate;
/// let d = differentiate("-F0*sin(2*pi*x/b)", "x", Some((0.1, 0.1)),
///     &[("F0".into(), 2.0), ("b".into(), 1.0)]).unwrap();
/// assert_eq!(d.derivative.to_string(), "-2*pi*F0*cos(2*pi*x/b)/b");
/// let exact = -2.0 * std::f64::consts::TAU * (std::f64::consts::TAU * 0.1).cos();
/// assert!((d.at.unwrap().symbolic.unwrap() - exact).abs() < 1e-12 && d.agrees());
/// ```
pub fn differentiate(
    text: &str,
    x: &str,
    at: Option<(Real, Real)>,
    params: &Params,
) -> Result<Differentiation, CalculusError> {
    let d = derivative(text, x)?;
    super::check_not_given(params, &[x])?;
    let at = match at {
        Some((point, h)) => {
            if h.is_nan() || h <= 0.0 {
                return Err(InputError::new(
                    Input::Step,
                    format!(
                        "the step of the numerical derivative must be positive, not {}",
                        crate::error::short(h)
                    ),
                )
                .into());
            }
            Some(derivative_at(text, x, point, params, h)?)
        }
        None => None,
    };
    Ok(Differentiation {
        input: d.input,
        var: x.to_string(),
        derivative: d.result,
        at,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Review C-08: at a jump there is no derivative, and the check never says the two agree.
    #[test]
    fn a_jump_has_no_derivative_and_never_agrees() {
        let d = differentiate("floor(x)", "x", Some((1.0, 0.1)), &[]).unwrap();
        let c = d.at.unwrap();
        assert!(!d.agrees() && c.jump == Some([0.0, 1.0]), "{c:?}");
        let d = differentiate("sign(x)", "x", Some((0.0, 0.1)), &[]).unwrap();
        assert!(!d.agrees() && d.at.unwrap().jump == Some([-1.0, 1.0]));
        let d = differentiate("x^3 - 3*x", "x", Some((1.0, 0.1)), &[]).unwrap();
        assert!(d.agrees() && d.at.unwrap().jump.is_none());
    }

    /// At a corner there is no derivative: `abs(x)` at 0 was "symbolic 0, numeric 0, the two
    /// agree", exit 0; `max(x, 0)` at 0 "1 against 0.5, they DISAGREE"; `abs(x - 1)` at 1 a
    /// "jump" of 1e-9 to 1e-9.
    #[test]
    fn a_corner_has_no_derivative_and_never_agrees() {
        for (f, at, slopes) in [
            ("abs(x)", 0.0, [-1.0, 1.0]),
            ("max(x, 0)", 0.0, [0.0, 1.0]),
            ("abs(x - 1)", 1.0, [-1.0, 1.0]),
            ("abs(sin(x))", 0.0, [-1.0, 1.0]),
        ] {
            let d = differentiate(f, "x", Some((at, 0.1)), &[]).unwrap();
            let c = d.at.unwrap();
            assert!(!d.agrees() && c.jump.is_none(), "{f}: {c:?}");
            let [l, r] = c.kink.unwrap_or_else(|| panic!("{f}: {c:?}"));
            assert!(
                (l - slopes[0]).abs() < 1e-6 && (r - slopes[1]).abs() < 1e-6,
                "{f}: {c:?}"
            );
        }
        let d = differentiate("abs(x)", "x", Some((0.5, 0.1)), &[]).unwrap();
        assert!(d.agrees() && d.at.unwrap().kink.is_none());
    }

    /// Review C-17: the variable cannot be given a value (it would be ignored).
    #[test]
    fn a_value_for_the_variable_is_refused() {
        let e = differentiate("x^2", "x", Some((1.0, 0.1)), &[("x".into(), 2.0)]).unwrap_err();
        assert!(matches!(
            e,
            CalculusError::Input(InputError {
                input: Input::Params,
                ..
            })
        ));
    }
}

//! The answers about force fields in 2-D and 3-D: the work along a path with the verdict on
//! whether the field is conservative (`mechkit work --field`), and the force `F = -∇U` of a
//! potential field at points (`mechkit potential --var x,y`).

use mechkit_expr::Sym;

use super::line_integral::{ForceField, Path};
use crate::Real;
use crate::calculus::{CalculusError, Params};
use crate::inputs::{Input, InputError, count};
use crate::quad::Tolerance;

/// The work of a field along a path, and whether the field is conservative.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct FieldWork {
    /// The field's components.
    #[cfg_attr(
        feature = "serde",
        serde(serialize_with = "crate::calculus::text::display_list")
    )]
    pub field: Vec<Sym>,
    /// `∫ F·dr`.
    pub work: Real,
    /// The quadrature's error estimate.
    pub error: Real,
    /// Whether the path ends where it starts.
    pub closed: bool,
    /// The path's length.
    pub length: Real,
    /// The curl (one component in 2-D, three in 3-D).
    #[cfg_attr(
        feature = "serde",
        serde(serialize_with = "crate::calculus::text::display_list")
    )]
    pub curl: Vec<Sym>,
    /// Whether the curl vanishes (null when it could not be decided).
    pub conservative: Option<bool>,
    /// A potential `U` with `F = -∇U`, when the rule table can build one.
    #[cfg_attr(
        feature = "serde",
        serde(serialize_with = "crate::calculus::text::display_opt")
    )]
    pub potential: Option<Sym>,
}

impl ForceField {
    /// The work along `path` to 1e-12 (relative and absolute), with the curl, whether the
    /// field is conservative and its potential.
    ///
    /// ```
    /// use mechkit::energy::{ForceField, Path};
    /// let g = ForceField::parse(&["0", "-m*g"], &[("m".into(), 2.0), ("g".into(), 9.81)]).unwrap();
    /// let path = Path::Polyline(vec![vec![0.0, 0.0], vec![3.0, 0.0], vec![3.0, 2.0]]);
    /// let w = g.work_report(&path).unwrap();
    /// assert!((w.work + 2.0 * 9.81 * 2.0).abs() < 1e-12);
    /// assert_eq!(w.conservative, Some(true));
    /// assert_eq!(w.potential.unwrap().to_string(), "g*m*y");
    /// ```
    pub fn work_report(&self, path: &Path) -> Result<FieldWork, CalculusError> {
        let w = self.work_along(
            path,
            Tolerance {
                abs: 1e-12,
                rel: 1e-12,
            },
        )?;
        Ok(FieldWork {
            field: self.formulas().into_iter().cloned().collect(),
            work: w.work,
            error: w.error,
            closed: w.closed,
            length: w.length,
            curl: self.curl(),
            conservative: self.is_conservative(),
            potential: self.potential(),
        })
    }
}

/// The force of a potential field at a point.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct FieldPoint {
    /// The point.
    pub r: Vec<Real>,
    /// `F(r)`.
    pub force: Vec<Real>,
}

/// The force `F = -∇U` of a potential field, and its values at points.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct FieldForce {
    /// The potential as given.
    pub potential: String,
    /// The coordinates: `x, y` or `x, y, z`.
    pub vars: Vec<String>,
    /// The components of `F`.
    #[cfg_attr(
        feature = "serde",
        serde(serialize_with = "crate::calculus::text::display_list")
    )]
    pub force: Vec<Sym>,
    /// `F` at the points asked.
    pub at: Vec<FieldPoint>,
}

/// `F = -∇U` of the potential `text` in the coordinates `vars` (`x, y` or `x, y, z`), with
/// `params` for the other names, and its values at `points`.
///
/// ```
/// let f = mechkit::energy::potential_field("k*(x^2 + y^2)/2", &["x", "y"], &[("k".into(), 2.0)],
///     &[vec![0.0, 3.0]]).unwrap();
/// assert_eq!(f.force[0].to_string(), "-k*x");
/// assert_eq!(f.at[0].force, [0.0, -6.0]);
/// ```
///
/// # Errors
/// Coordinates other than `x, y[, z]` ([`Input::Variable`]), a point with another number of
/// coordinates ([`Input::At`]), a formula that does not read.
pub fn potential_field(
    text: &str,
    vars: &[&str],
    params: &Params,
    points: &[Vec<Real>],
) -> Result<FieldForce, CalculusError> {
    let expected = &["x", "y", "z"][..vars.len().min(3)];
    if vars.len() < 2 || vars.len() > 3 || vars != expected {
        return Err(InputError::new(
            Input::Variable,
            format!(
                "the coordinates of a potential field are x,y or x,y,z, not `{}`",
                vars.join(",")
            ),
        )
        .into());
    }
    let field = ForceField::from_potential(text, vars.len(), params)?;
    let n = vars.len();
    let at = points
        .iter()
        .map(|r| {
            if r.len() != n {
                return Err(InputError::new(
                    Input::At,
                    format!(
                        "a point needs {} like the field, not {}",
                        count(n, "coordinate"),
                        r.len()
                    ),
                )
                .into());
            }
            let mut f = vec![0.0; n];
            field.at(r, &mut f);
            // -0.0 prints as 0
            Ok(FieldPoint {
                r: r.clone(),
                force: f.iter().map(|v| v + 0.0).collect(),
            })
        })
        .collect::<Result<_, CalculusError>>()?;
    Ok(FieldForce {
        potential: text.to_string(),
        vars: vars.iter().map(ToString::to_string).collect(),
        force: field.formulas().into_iter().cloned().collect(),
        at,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn coordinates_are_checked() {
        let e = potential_field("x*z", &["x", "z"], &[], &[]).unwrap_err();
        assert!(matches!(
            e,
            CalculusError::Input(InputError {
                input: Input::Variable,
                ..
            })
        ));
        let e = potential_field("x*y", &["x", "y"], &[], &[vec![1.0]]).unwrap_err();
        assert!(e.to_string().contains("2 coordinates"), "{e}");
    }
}

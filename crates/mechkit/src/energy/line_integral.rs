//! The work of a force field along a curve in 2-D or 3-D, `W = ∫ F·dr`, and whether the field
//! is conservative: its curl (symbolic), a potential `U` with `F = -∇U` when the rule table can
//! build one, and the loop integral of a closed path (zero for a conservative field).

use mechkit_expr::Sym;

use crate::Real;
use crate::calculus::{CalculusError, Params};
use crate::function::Function;
use crate::inputs::{Input, InputError, count};
use crate::quad::{QuadError, Tolerance, integrate};

const AXES: [&str; 3] = ["x", "y", "z"];

/// A force field `F(x, y[, z])`, one formula per component.
#[derive(Debug, Clone, PartialEq)]
pub struct ForceField {
    components: Vec<Function>,
}

/// A curve to integrate along.
#[derive(Debug, Clone, PartialEq)]
pub enum Path {
    /// `r(s)`, one formula per component, for `s` from `from` to `to`.
    Parametric {
        /// The components, functions of the parameter.
        components: Vec<Function>,
        /// Start of the parameter.
        from: Real,
        /// End of the parameter.
        to: Real,
    },
    /// Straight segments through the points, in order.
    Polyline(Vec<Vec<Real>>),
}

/// The work along a path.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PathWork {
    /// `∫ F·dr`.
    pub work: Real,
    /// Estimated error of the quadrature.
    pub error: Real,
    /// Whether the path ends where it starts.
    pub closed: bool,
    /// The path's length.
    pub length: Real,
}

impl Path {
    /// The curve `r(s)`: one formula per component (`"cos(s)"`, `"sin(s)"`) of the parameter
    /// `var`, with `params` for the other names, for `var` from `from` to `to`.
    ///
    /// ```
    /// use mechkit::energy::Path;
    /// let circle = Path::parametric(&["cos(s)", "sin(s)"], "s", (0.0, 1.0), &[]).unwrap();
    /// assert!(matches!(circle, Path::Parametric { .. }));
    /// ```
    pub fn parametric(
        components: &[&str],
        var: &str,
        (from, to): (Real, Real),
        params: &Params,
    ) -> Result<Self, CalculusError> {
        let components = components
            .iter()
            .map(|c| Function::parse(c, &[var], params))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Path::Parametric {
            components,
            from,
            to,
        })
    }
}

impl ForceField {
    /// Parses one formula per component (2 or 3), functions of `x`, `y` (and `z`).
    pub fn parse(components: &[&str], params: &Params) -> Result<Self, CalculusError> {
        if !(2..=3).contains(&components.len()) {
            return Err(InputError::new(
                Input::Field,
                format!(
                    "a force field has 2 or 3 components (Fx, Fy[, Fz]), not {}",
                    components.len()
                ),
            )
            .into());
        }
        let vars = &AXES[..components.len()];
        let components = components
            .iter()
            .map(|c| Function::parse(c, vars, params))
            .collect::<Result<_, _>>()?;
        Ok(Self { components })
    }

    /// The conservative field `F = -∇U` of a potential `U(x, y[, z])` in `dim` = 2 or 3
    /// dimensions, by symbolic differentiation.
    ///
    /// ```
    /// use mechkit::energy::ForceField;
    /// let params = [("m".to_string(), 2.0), ("g".to_string(), 9.81), ("k".to_string(), 5.0)];
    /// let f = ForceField::from_potential("m*g*y + k*x^2/2", 2, &params).unwrap();
    /// let names: Vec<String> = f.formulas().iter().map(|c| c.to_string()).collect();
    /// assert_eq!(names, ["-k*x", "-g*m"]);
    /// let mut force = [0.0; 2];
    /// f.at(&[0.1, 3.0], &mut force);
    /// assert_eq!(force, [-0.5, -2.0 * 9.81]);
    /// ```
    pub fn from_potential(text: &str, dim: usize, params: &Params) -> Result<Self, CalculusError> {
        if !(2..=3).contains(&dim) {
            return Err(CalculusError::Invalid(format!(
                "a potential field has 2 or 3 coordinates (x, y[, z]), not {dim}"
            )));
        }
        let vars = &AXES[..dim];
        let u = Function::parse(text, vars, params)?;
        let components = vars
            .iter()
            .map(|v| u.with_sym(Sym::negate(u.sym().diff(v))))
            .collect();
        Ok(Self { components })
    }

    /// 2 or 3.
    pub fn dim(&self) -> usize {
        self.components.len()
    }

    /// The component formulas.
    pub fn formulas(&self) -> Vec<&Sym> {
        self.components.iter().map(Function::sym).collect()
    }

    /// `F` at `r`.
    pub fn at(&self, r: &[Real], out: &mut [Real]) {
        for (o, c) in out.iter_mut().zip(&self.components) {
            *o = c.at(r);
        }
    }

    /// The curl: in 2-D the single component `∂Fy/∂x - ∂Fx/∂y`, in 3-D all three.
    pub fn curl(&self) -> Vec<Sym> {
        let d = |i: usize, axis: usize| self.components[i].sym().diff(AXES[axis]);
        let c = |i: usize, j: usize| Sym::difference(d(j, i), d(i, j));
        if self.dim() == 2 {
            vec![c(0, 1)]
        } else {
            vec![c(1, 2), c(2, 0), c(0, 1)]
        }
    }

    /// `Some(true)` when the curl simplifies to zero, `Some(false)` when it is nonzero at some
    /// sample point, `None` when neither could be shown.
    pub fn is_conservative(&self) -> Option<bool> {
        let curl = self.curl();
        if curl.iter().all(Sym::is_zero) {
            return Some(true);
        }
        let f = &self.components[0];
        let probes = [[0.31, -0.72, 0.53], [1.3, 0.4, -0.9], [-0.6, 1.7, 0.25]];
        for c in &curl {
            let g = f.with_sym(c.clone());
            for p in &probes {
                let v = g.at(&p[..self.dim()]);
                if v.is_finite() && v.abs() > 1e-9 {
                    return Some(false);
                }
            }
        }
        None
    }

    /// A potential `U` with `F = -∇U`, when the field is conservative and the rule table can
    /// integrate it (verified by taking the gradient back).
    pub fn potential(&self) -> Option<Sym> {
        let n = self.dim();
        let mut u = Sym::zero();
        for (axis, &name) in AXES.iter().enumerate().take(n) {
            // what -∂U/∂axis still lacks, which must not depend on the axes already done
            let rest = Sym::difference(
                Sym::negate(self.components[axis].sym().clone()),
                u.diff(name),
            );
            if AXES[..axis].iter().any(|k| !rest.diff(k).is_zero()) {
                return None;
            }
            let part = rest.integrate(name)?.result;
            u = Sym::sum(vec![u, part]);
        }
        let back_ok = (0..n).all(|axis| {
            Sym::sum(vec![
                u.diff(AXES[axis]),
                self.components[axis].sym().clone(),
            ])
            .is_zero()
        });
        back_ok.then_some(u)
    }

    /// `∫ F·dr` along `path` to tolerance `tol`.
    ///
    /// ```
    /// use mechkit::energy::{ForceField, Path};
    /// use mechkit::function::Function;
    /// use mechkit::quad::Tolerance;
    /// // F = (-y, x) around the unit circle: 2π, so the field is not conservative
    /// let f = ForceField::parse(&["-y", "x"], &[]).unwrap();
    /// let circle = Path::Parametric {
    ///     components: vec![Function::parse("cos(s)", &["s"], &[]).unwrap(),
    ///                      Function::parse("sin(s)", &["s"], &[]).unwrap()],
    ///     from: 0.0, to: 2.0 * std::f64::consts::PI,
    /// };
    /// let w = f.work_along(&circle, Tolerance::default()).unwrap();
    /// assert!((w.work - 2.0 * std::f64::consts::PI).abs() < 1e-12 && w.closed);
    /// assert_eq!(f.is_conservative(), Some(false));
    /// ```
    pub fn work_along(&self, path: &Path, tol: Tolerance) -> Result<PathWork, CalculusError> {
        let n = self.dim();
        let fail = |e: QuadError| CalculusError::Invalid(format!("the line integral failed: {e}"));
        let mut f = [0.0; 3];
        let mut r = [0.0; 3];
        match path {
            Path::Parametric {
                components,
                from,
                to,
            } => {
                if components.len() != n {
                    return Err(InputError::new(
                        Input::Path,
                        format!(
                            "the path has {} but the field has {n}: give the path one \
                             component per coordinate of the field, e.g. `cos(s), sin(s)` in 2-D",
                            count(components.len(), "component")
                        ),
                    )
                    .into());
                }
                let var = components[0].vars()[0].clone();
                let tangent: Vec<Function> = components.iter().map(|c| c.diff(&var)).collect();
                let mut integrand = |s: Real| {
                    for (ri, c) in r.iter_mut().zip(components) {
                        *ri = c.at1(s);
                    }
                    self.at(&r[..n], &mut f[..n]);
                    (0..n).map(|i| f[i] * tangent[i].at1(s)).sum::<Real>()
                };
                let w = integrate(&mut integrand, *from, *to, tol).map_err(fail)?;
                let speed = |s: Real| {
                    tangent
                        .iter()
                        .map(|t| t.at1(s).powi(2))
                        .sum::<Real>()
                        .sqrt()
                };
                let length = integrate(speed, *from, *to, tol).map_or(Real::NAN, |q| q.value);
                let end = |s: Real| components.iter().map(|c| c.at1(s)).collect::<Vec<_>>();
                let (a, b) = (end(*from), end(*to));
                Ok(PathWork {
                    work: w.value,
                    error: w.error,
                    closed: close(&a, &b, length),
                    length: length.abs(),
                })
            }
            Path::Polyline(points) => {
                if points.len() < 2 || points.iter().any(|p| p.len() != n) {
                    return Err(InputError::new(
                        Input::Through,
                        format!(
                            "a path of straight segments needs at least 2 points of {}",
                            count(n, "coordinate")
                        ),
                    )
                    .into());
                }
                let (mut work, mut error, mut length) = (0.0, 0.0, 0.0);
                for seg in points.windows(2) {
                    let (p, q) = (&seg[0], &seg[1]);
                    let d: Vec<Real> = (0..n).map(|i| q[i] - p[i]).collect();
                    let integrand = |s: Real| {
                        for i in 0..n {
                            r[i] = p[i] + s * d[i];
                        }
                        self.at(&r[..n], &mut f[..n]);
                        (0..n).map(|i| f[i] * d[i]).sum::<Real>()
                    };
                    let w = integrate(integrand, 0.0, 1.0, tol).map_err(fail)?;
                    work += w.value;
                    error += w.error;
                    length += d.iter().map(|v| v * v).sum::<Real>().sqrt();
                }
                let closed = close(&points[0], &points[points.len() - 1], length);
                Ok(PathWork {
                    work,
                    error,
                    closed,
                    length,
                })
            }
        }
    }
}

fn close(a: &[Real], b: &[Real], length: Real) -> bool {
    let gap: Real = a
        .iter()
        .zip(b)
        .map(|(p, q)| (p - q).powi(2))
        .sum::<Real>()
        .sqrt();
    gap <= 1e-12 * length.abs().max(1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line(points: &[[Real; 2]]) -> Path {
        Path::Polyline(points.iter().map(|p| p.to_vec()).collect())
    }

    #[test]
    fn gravity_is_conservative_and_path_independent() {
        let g =
            ForceField::parse(&["0", "-m*g"], &[("m".into(), 2.0), ("g".into(), 9.81)]).unwrap();
        assert_eq!(g.is_conservative(), Some(true));
        assert_eq!(g.potential().unwrap().to_string(), "g*m*y");
        let straight = line(&[[0.0, 0.0], [3.0, 2.0]]);
        let detour = line(&[[0.0, 0.0], [0.0, 5.0], [3.0, 5.0], [3.0, 2.0]]);
        let t = Tolerance::default();
        let (w1, w2) = (
            g.work_along(&straight, t).unwrap(),
            g.work_along(&detour, t).unwrap(),
        );
        assert!((w1.work + 2.0 * 9.81 * 2.0).abs() < 1e-12);
        assert!((w1.work - w2.work).abs() < 1e-12);
    }

    #[test]
    fn a_spring_in_3d_has_a_potential() {
        let f = ForceField::parse(&["-k*x", "-k*y", "-k*z"], &[("k".into(), 3.0)]).unwrap();
        assert_eq!(f.curl().iter().filter(|c| c.is_zero()).count(), 3);
        let u = f.potential().unwrap();
        assert_eq!(u.to_string(), "k*x^2/2 + k*y^2/2 + k*z^2/2");
        // along a helix r(s) = (cos s, sin s, s), s from 0 to π: W = -ΔU = -k π²/2
        let helix = Path::Parametric {
            components: ["cos(s)", "sin(s)", "s"]
                .iter()
                .map(|c| Function::parse(c, &["s"], &[]).unwrap())
                .collect(),
            from: 0.0,
            to: std::f64::consts::PI,
        };
        let w = f.work_along(&helix, Tolerance::default()).unwrap();
        let pi2 = std::f64::consts::PI.powi(2);
        assert!((w.work + 3.0 * pi2 / 2.0).abs() < 1e-12, "{w:?}");
        assert!((w.length - std::f64::consts::PI * 2f64.sqrt()).abs() < 1e-12);
    }

    #[test]
    fn a_swirl_is_not_conservative() {
        let f = ForceField::parse(&["y", "0"], &[]).unwrap();
        assert_eq!(f.is_conservative(), Some(false));
        assert!(f.potential().is_none());
        // around the unit square counter-clockwise: ∮ y dx = -1
        let square = line(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.0, 0.0]]);
        let w = f.work_along(&square, Tolerance::default()).unwrap();
        assert!(w.closed && (w.work + 1.0).abs() < 1e-13 && (w.length - 4.0).abs() < 1e-15);
    }
}

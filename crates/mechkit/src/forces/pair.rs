//! Pair forces given by their potential: a formula `U(r)` of the separation `r` of two bodies,
//! and the central force `F(r) = -dU/dr` along the line of centres, derived symbolically once
//! (`mechkit_expr::Sym::diff`) and compiled once.
//!
//! For a pair `(a, b)` with `d = x_a - x_b` and `r = |d|`, the force on `a` is
//! `F(r) d/r` (positive `F` pushes the bodies apart), the force on `b` its opposite (Newton's
//! third law), and the pair's potential energy is `U(r)`. With a cut-off `r_c` both vanish for
//! `r ≥ r_c`, and inside it the potential is shifted by `U(r_c)` (`U(r) - U(r_c)`), so that it is
//! continuous and the energy ledger balances when a pair crosses the cut-off; the force is not
//! shifted (it jumps by `F(r_c)` there).
//!
//! Two bodies at the same point have no line of centres: the force is then NaN, on purpose,
//! and the run stops with a diagnosis that names the force and where the bodies are.

use mechkit_expr::{Expr, MapScope, Program, Sym};
use thiserror::Error;

use super::emit::ForceEmitter;
use super::force::Force;
use crate::Real;
use crate::particles::Kinematics;

/// A pair potential that cannot be built.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum PairError {
    /// A name in the formula is neither the variable nor a given constant.
    #[error("the potential uses `{0}`, which is neither the separation nor a constant")]
    UndefinedName(String),
    /// The cut-off is not a positive finite length.
    #[error("the cut-off must be positive and finite, not {}", crate::error::short(*.0))]
    BadCutoff(Real),
    /// The potential is not finite at the cut-off (it could not be shifted).
    #[error(
        "the potential is {value} at the cut-off r = {}, not a finite number",
        crate::error::short(*cutoff)
    )]
    NotFiniteAtCutoff {
        /// The cut-off.
        cutoff: Real,
        /// `U` there.
        value: Real,
    },
}

/// `U(r)` and `F(r) = -U'(r)` of a central pair potential, compiled, with an optional cut-off.
///
/// # Example
/// ```
/// use mechkit::forces::RadialPotential;
/// use mechkit_expr::parse;
/// // Lennard-Jones in reduced units: the minimum is at r = 2^(1/6), where U = -1
/// let u = parse("4*eps*((s/r)^12 - (s/r)^6)").unwrap().expr;
/// let lj = RadialPotential::new(&u, "r", &[("eps".into(), 1.0), ("s".into(), 1.0)]).unwrap();
/// assert_eq!(lj.force_formula().to_string(), "eps*(48*s^12/r^13 - 24*s^6/r^7)");
/// let r_min = 2f64.powf(1.0 / 6.0);
/// assert!(lj.force(r_min).abs() < 1e-13);
/// assert!((lj.energy(r_min) + 1.0).abs() < 1e-14);
/// ```
#[derive(Debug, Clone)]
pub struct RadialPotential {
    potential: Program,
    force: Program,
    potential_sym: Sym,
    force_sym: Sym,
    cutoff: Option<Real>,
    shift: Real,
}

impl RadialPotential {
    /// `U` given by `u`, a formula of `var` (the separation) and of the names in `constants`
    /// (and `pi`, `e`); the force `-dU/d(var)` is derived symbolically. A constant named like
    /// the variable is hidden by it.
    pub fn new(u: &Expr, var: &str, constants: &[(String, Real)]) -> Result<Self, PairError> {
        let mut scope = MapScope::new();
        for (name, value) in constants {
            scope = scope.constant(name, *value);
        }
        let scope = scope.slot(var, 0);
        let potential_sym = Sym::from_expr(u);
        let force_sym = Sym::negate(potential_sym.diff(var));
        let potential = Program::compile(u, &scope)
            .map_err(PairError::UndefinedName)?
            .native();
        let force = Program::compile(&force_sym.to_expr(), &scope)
            .map_err(PairError::UndefinedName)?
            .native();
        Ok(Self {
            potential,
            force,
            potential_sym,
            force_sym,
            cutoff: None,
            shift: 0.0,
        })
    }

    /// The same potential cut off at `cutoff`: zero force and energy for `r ≥ cutoff`, and the
    /// energy shifted by `U(cutoff)` inside, so that it is continuous.
    pub fn with_cutoff(mut self, cutoff: Real) -> Result<Self, PairError> {
        if !(cutoff.is_finite() && cutoff > 0.0) {
            return Err(PairError::BadCutoff(cutoff));
        }
        let value = self.potential.eval(&[cutoff]);
        if !value.is_finite() {
            return Err(PairError::NotFiniteAtCutoff { cutoff, value });
        }
        self.cutoff = Some(cutoff);
        self.shift = value;
        Ok(self)
    }

    /// The potential as typed, in canonical form.
    pub fn potential_formula(&self) -> &Sym {
        &self.potential_sym
    }

    /// The force `-dU/dr`, as derived.
    pub fn force_formula(&self) -> &Sym {
        &self.force_sym
    }

    /// The cut-off, if any.
    pub fn cutoff(&self) -> Option<Real> {
        self.cutoff
    }

    /// Whether `r` is beyond the cut-off.
    #[inline]
    fn cut(&self, r: Real) -> bool {
        self.cutoff.is_some_and(|rc| r >= rc)
    }

    /// The potential energy at separation `r` (shifted when cut off; zero beyond).
    #[inline]
    pub fn energy(&self, r: Real) -> Real {
        if self.cut(r) {
            0.0
        } else {
            self.potential.eval(&[r]) - self.shift
        }
    }

    /// The force `F(r) = -dU/dr` at separation `r`: positive pushes apart; zero beyond the
    /// cut-off.
    #[inline]
    pub fn force(&self, r: Real) -> Real {
        if self.cut(r) {
            0.0
        } else {
            self.force.eval(&[r])
        }
    }

    /// `F(r)/r`, the factor of the separation vector; NaN at `r = 0`, where the line of
    /// centres is undefined.
    #[inline]
    fn force_over_r(&self, r: Real) -> Real {
        if r == 0.0 {
            Real::NAN
        } else {
            self.force(r) / r
        }
    }
}

/// A pair potential acting between pairs of bodies.
///
/// # Example
/// ```
/// use mechkit::forces::{Force, PairForce, RadialPotential};
/// use mechkit::particles::Kinematics;
/// use mechkit_expr::parse;
/// // a harmonic bond of stiffness 2 and length 1 between bodies at x = 0 and x = 1.5 (1-D)
/// let u = parse("k*(r - L)^2/2").unwrap().expr;
/// let law = RadialPotential::new(&u, "r", &[("k".into(), 2.0), ("L".into(), 1.0)]).unwrap();
/// let bond = PairForce::new("bond", vec![(0, 1)], law);
/// let k = Kinematics { t: 0.0, dim: 1, x: &[0.0, 1.5], v: &[0.0, 0.0], mass: &[1.0, 1.0] };
/// let mut f = [0.0; 2];
/// bond.add_forces(&k, &mut f);
/// assert_eq!(f, [1.0, -1.0]); // stretched: the bodies pull together
/// assert!((bond.potential(&k).unwrap() - 0.25).abs() < 1e-15);
/// ```
#[derive(Debug, Clone)]
pub struct PairForce {
    name: String,
    pairs: Vec<(usize, usize)>,
    law: RadialPotential,
}

impl PairForce {
    /// The potential `law` between each of `pairs` (distinct bodies).
    ///
    /// # Panics
    /// If a pair names one body twice.
    pub fn new(name: impl Into<String>, pairs: Vec<(usize, usize)>, law: RadialPotential) -> Self {
        assert!(
            pairs.iter().all(|(a, b)| a != b),
            "a pair force needs two distinct bodies per pair"
        );
        Self {
            name: name.into(),
            pairs,
            law,
        }
    }

    /// Every pair among `bodies`, in order: `(b0, b1), (b0, b2), …, (b1, b2), …`.
    pub fn all_pairs(bodies: &[usize]) -> Vec<(usize, usize)> {
        let mut out = Vec::new();
        for (n, &a) in bodies.iter().enumerate() {
            for &b in &bodies[n + 1..] {
                out.push((a, b));
            }
        }
        out
    }

    /// The pairs.
    pub fn pairs(&self) -> &[(usize, usize)] {
        &self.pairs
    }

    /// The potential.
    pub fn law(&self) -> &RadialPotential {
        &self.law
    }
}

/// `d = a - b`; returns `|d|`.
#[inline]
fn separation(a: &[Real], b: &[Real], d: &mut [Real; 3]) -> Real {
    let mut r2 = 0.0;
    for i in 0..a.len() {
        d[i] = a[i] - b[i];
        r2 += d[i] * d[i];
    }
    r2.sqrt()
}

impl Force for PairForce {
    fn name(&self) -> &str {
        &self.name
    }

    fn add_forces(&self, k: &Kinematics<'_>, out: &mut [Real]) {
        let dim = k.dim;
        let mut d = [0.0; 3];
        for &(a, b) in &self.pairs {
            let r = separation(k.position(a), k.position(b), &mut d);
            let s = self.law.force_over_r(r);
            for i in 0..dim {
                out[a * dim + i] += s * d[i];
                out[b * dim + i] -= s * d[i];
            }
        }
    }

    fn potential(&self, k: &Kinematics<'_>) -> Option<Real> {
        let mut d = [0.0; 3];
        Some(
            self.pairs
                .iter()
                .map(|&(a, b)| {
                    self.law
                        .energy(separation(k.position(a), k.position(b), &mut d))
                })
                .sum(),
        )
    }

    fn emit(&self, e: &mut ForceEmitter<'_>) -> bool {
        self.emit_pairs(e)
    }

    fn internal(&self) -> bool {
        true
    }

    fn local(&self) -> bool {
        true
    }

    fn bodies(&self) -> Vec<usize> {
        let mut out: Vec<usize> = self.pairs.iter().flat_map(|&(a, b)| [a, b]).collect();
        out.sort_unstable();
        out.dedup();
        out
    }
}

#[path = "pair_emit.rs"]
mod emit;

#[cfg(test)]
mod tests {
    use mechkit_expr::parse;

    use super::*;

    fn law(u: &str, constants: &[(&str, Real)]) -> RadialPotential {
        let c: Vec<(String, Real)> = constants
            .iter()
            .map(|(n, v)| ((*n).to_string(), *v))
            .collect();
        RadialPotential::new(&parse(u).unwrap().expr, "r", &c).unwrap()
    }

    /// The symbolic force against a central difference of the compiled potential, with
    /// Richardson extrapolation (error O(h⁴)), over a range of separations.
    fn agrees_with_finite_differences(p: &RadialPotential, range: (Real, Real)) {
        for j in 0..=40 {
            let r = range.0 + (range.1 - range.0) * Real::from(j) / 40.0;
            let h = 1e-3 * r;
            let d = |h: Real| (p.energy(r + h) - p.energy(r - h)) / (2.0 * h);
            let numeric = -(4.0 * d(h / 2.0) - d(h)) / 3.0;
            let exact = p.force(r);
            let scale = exact.abs().max(p.energy(r).abs() / r).max(1e-300);
            assert!(
                (numeric - exact).abs() <= 1e-7 * scale,
                "r = {r}: symbolic {exact}, finite difference {numeric}"
            );
        }
    }

    #[test]
    fn lennard_jones_force_is_minus_the_derivative() {
        let lj = law(
            "4*eps*((s/r)^12 - (s/r)^6)",
            &[("eps", 1.6e-21), ("s", 3.4e-10)],
        );
        agrees_with_finite_differences(&lj, (3.0e-10, 1.2e-9));
        // zero force at the minimum 2^(1/6) σ
        let r_min = 2f64.powf(1.0 / 6.0) * 3.4e-10;
        assert!(lj.force(r_min).abs() < 1e-12 * lj.force(3.0e-10).abs());
    }

    #[test]
    fn morse_force_is_minus_the_derivative() {
        let morse = law(
            "D*(1 - exp(-a*(r - re)))^2",
            &[("D", 4.7), ("a", 1.9), ("re", 0.74)],
        );
        agrees_with_finite_differences(&morse, (0.4, 3.0));
        // closed form: F = -2 D a e^{-a(r-re)} (1 - e^{-a(r-re)})
        for r in [0.5, 0.74, 1.3, 2.7] {
            let x: Real = (-1.9 * (r - 0.74) as Real).exp();
            let exact = -2.0 * 4.7 * 1.9 * x * (1.0 - x);
            assert!((morse.force(r) - exact).abs() < 1e-13, "r = {r}");
        }
    }

    #[test]
    fn coulomb_force_is_minus_the_derivative() {
        let coulomb = law("k/r", &[("k", 2.3e-28)]);
        agrees_with_finite_differences(&coulomb, (1e-10, 1e-8));
        assert_eq!(coulomb.force_formula().to_string(), "k/r^2");
        for r in [1e-10, 3.7e-9] {
            let exact: Real = 2.3e-28 / (r * r);
            assert!((coulomb.force(r) - exact).abs() <= 1e-15 * exact);
        }
    }

    #[test]
    fn cutoff_shifts_the_energy_and_zeroes_both_beyond() {
        let lj = law("4*((1/r)^12 - (1/r)^6)", &[]).with_cutoff(2.5).unwrap();
        let u_rc = 4.0 * (2.5_f64.powi(-12) - 2.5_f64.powi(-6));
        let r: Real = 1.3;
        assert!((lj.energy(r) - (4.0 * (r.powi(-12) - r.powi(-6)) - u_rc)).abs() < 1e-15);
        assert_eq!(lj.energy(2.5), 0.0);
        assert_eq!(lj.force(2.5), 0.0);
        assert_eq!(lj.force(7.0), 0.0);
        assert!(lj.force(2.49) < 0.0, "attractive just inside");
        assert!(matches!(
            law("1/r", &[]).with_cutoff(0.0),
            Err(PairError::BadCutoff(_))
        ));
        assert!(matches!(
            law("1/(r - 1)", &[]).with_cutoff(1.0),
            Err(PairError::NotFiniteAtCutoff { .. })
        ));
    }

    #[test]
    fn undefined_names_are_refused() {
        let u = parse("k*(r - x)^2").unwrap().expr;
        let e = RadialPotential::new(&u, "r", &[("k".into(), 1.0)]).unwrap_err();
        assert!(matches!(&e, PairError::UndefinedName(n) if n == "x"), "{e}");
    }

    #[test]
    fn forces_are_equal_and_opposite_in_three_dimensions() {
        let p = PairForce::new(
            "lj",
            PairForce::all_pairs(&[0, 1, 2]),
            law("4*((1/r)^12 - (1/r)^6)", &[]),
        );
        assert_eq!(p.pairs(), &[(0, 1), (0, 2), (1, 2)]);
        assert_eq!(p.bodies(), vec![0, 1, 2]);
        let x = [0.0, 0.0, 0.0, 1.1, 0.2, -0.1, 0.3, 1.0, 0.4];
        let k = Kinematics {
            t: 0.0,
            dim: 3,
            x: &x,
            v: &[0.0; 9],
            mass: &[1.0; 3],
        };
        let mut f = [0.0; 9];
        p.add_forces(&k, &mut f);
        for axis in 0..3 {
            let total: Real = (0..3).map(|b| f[b * 3 + axis]).sum();
            assert!(total.abs() < 1e-12, "momentum moves along axis {axis}");
        }
        // each pair's force lies along its line of centres: the torque about the origin of
        // the total is zero, as for any central force
        let mut torque = [0.0; 3];
        for b in 0..3 {
            let (r, fb) = (&x[b * 3..b * 3 + 3], &f[b * 3..b * 3 + 3]);
            torque[0] += r[1] * fb[2] - r[2] * fb[1];
            torque[1] += r[2] * fb[0] - r[0] * fb[2];
            torque[2] += r[0] * fb[1] - r[1] * fb[0];
        }
        assert!(torque.iter().all(|t| t.abs() < 1e-12), "{torque:?}");
    }

    #[test]
    fn zero_separation_gives_a_non_finite_force() {
        let p = PairForce::new("bond", vec![(0, 1)], law("(r - 1)^2", &[]));
        let k = Kinematics {
            t: 0.0,
            dim: 2,
            x: &[0.5, 0.5, 0.5, 0.5],
            v: &[0.0; 4],
            mass: &[1.0; 2],
        };
        let mut f = [0.0; 4];
        p.add_forces(&k, &mut f);
        assert!(f.iter().all(|x| x.is_nan()));
    }
}

//! Polynomials of a step's fraction computed from the components of its interpolant by sums
//! and products, with a bound on their rounding: a function of the motion that is a
//! polynomial in the state (or whose sign is that of one) enclosed as one polynomial, not
//! through interval arithmetic on the state's enclosures.
//!
//! Interval arithmetic on enclosures of the state forgets that the components move together:
//! `ω` of a body spinning about a principal axis, formed from the rotating quaternion and
//! the fixed momentum, is constant, yet its enclosure over a piece of the step is as wide
//! as the quaternion's swing, and no halving makes it narrow enough to show it constant. The
//! same function as one polynomial cancels exactly, to rounding.
//!
//! **The rounding bound.** A [`Series`] keeps, beside its coefficients, the same computation
//! on their magnitudes (the *majorant*) and the most roundings on any path from the inputs
//! (the *depth*: a sum adds one, a product of `n`-term polynomials adds `n`, one for the
//! products and `n − 1` for summing them in turn). By induction over the operations, each
//! computed coefficient is within `γ_D M_j` of the exact one, with `D` the depth, `M_j` the
//! exact majorant and `γ_D = D u / (1 − D u)` (`u` the unit roundoff); the computed
//! majorant is itself within a factor `1 − γ_D` of the exact one. The inputs, the
//! interpolant's coefficients, are exact by definition (the interpolant *is* that
//! polynomial).

use std::ops::{Add, Mul, Sub};

use mechkit_expr::interval::{Interval, Jet};

use super::polynomial::{MAX_TERMS, enclose_coefficients};
use crate::Real;
use crate::ode::StepPolynomial;

/// A polynomial `Σ_j c_j s^j` in the fraction `s` of a step, computed in floating point,
/// with what bounds its rounding.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Series {
    /// Number of coefficients; 0 when a product had more than [`MAX_TERMS`] (unknown).
    len: usize,
    coeffs: [Real; MAX_TERMS],
    /// The same computation on the magnitudes of the inputs.
    majorant: [Real; MAX_TERMS],
    /// Most roundings on any path from an input to a coefficient.
    depth: u32,
}

impl Series {
    const UNKNOWN: Series = Series {
        len: 0,
        coeffs: [0.0; MAX_TERMS],
        majorant: [0.0; MAX_TERMS],
        depth: 0,
    };

    /// Component `i` of the interpolant `poly` (exact).
    pub fn component(poly: &StepPolynomial, i: usize) -> Series {
        let c = poly.coefficients(i);
        let mut out = Series {
            len: c.len(),
            ..Series::UNKNOWN
        };
        for (j, &cj) in c.iter().enumerate() {
            out.coeffs[j] = cj;
            out.majorant[j] = cj.abs();
        }
        out
    }

    /// The constant `x` (exact).
    pub fn constant(x: Real) -> Series {
        let mut out = Series {
            len: 1,
            ..Series::UNKNOWN
        };
        out.coeffs[0] = x;
        out.majorant[0] = x.abs();
        out
    }

    /// The coefficients, lowest power first (empty when unknown).
    pub fn coefficients(&self) -> &[Real] {
        &self.coeffs[..self.len]
    }

    /// Bounds on the distance of each coefficient from the exact one.
    fn errors(&self) -> [Real; MAX_TERMS] {
        let d = Real::from(self.depth);
        let u = 0.5 * Real::EPSILON;
        let gamma = d * u / (1.0 - d * u);
        // the computed majorant may fall short of the exact one by 1 − γ; a 1 % margin
        // covers the rounding of this very bound
        let factor = gamma / (1.0 - gamma) * 1.01;
        self.majorant.map(|m| m * factor)
    }

    /// Encloses the polynomial and its time derivative over the fractions `s` of the step
    /// of `poly` (unknown when a product outgrew [`MAX_TERMS`], or anything is not finite).
    pub fn enclose(&self, poly: &StepPolynomial, s: Interval) -> Jet {
        if self.len == 0 {
            return Jet::new(Interval::ENTIRE, Interval::ENTIRE);
        }
        let errors = self.errors();
        enclose_coefficients(self.coefficients(), &errors[..self.len], s, poly.inv_h())
    }

    /// Coefficient-wise `a ± b`.
    fn sum(&self, other: &Series, sign: Real) -> Series {
        if self.len == 0 || other.len == 0 {
            return Series::UNKNOWN;
        }
        let mut out = Series {
            len: self.len.max(other.len),
            depth: self.depth.max(other.depth) + 1,
            ..Series::UNKNOWN
        };
        for j in 0..out.len {
            out.coeffs[j] = self.coeffs[j] + sign * other.coeffs[j];
            out.majorant[j] = self.majorant[j] + other.majorant[j];
        }
        out
    }
}

impl Add for Series {
    type Output = Series;
    fn add(self, other: Series) -> Series {
        self.sum(&other, 1.0)
    }
}

impl Sub for Series {
    type Output = Series;
    fn sub(self, other: Series) -> Series {
        self.sum(&other, -1.0)
    }
}

impl Mul for Series {
    type Output = Series;
    fn mul(self, other: Series) -> Series {
        if self.len == 0 || other.len == 0 || self.len + other.len - 1 > MAX_TERMS {
            return Series::UNKNOWN;
        }
        let terms = self.len.min(other.len);
        let mut out = Series {
            len: self.len + other.len - 1,
            depth: self.depth.max(other.depth) + u32::try_from(terms).unwrap_or(u32::MAX),
            ..Series::UNKNOWN
        };
        for i in 0..self.len {
            for j in 0..other.len {
                out.coeffs[i + j] += self.coeffs[i] * other.coeffs[j];
                out.majorant[i + j] += self.majorant[i] * other.majorant[j];
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn poly(components: &[&[Real]]) -> StepPolynomial {
        let mut p = StepPolynomial::default();
        let width = components.iter().map(|c| c.len()).max().unwrap();
        p.reset(0.0, 0.5, components.len(), width);
        for (i, c) in components.iter().enumerate() {
            p.coefficients_mut(i)[..c.len()].copy_from_slice(c);
        }
        p
    }

    /// The value of `(a b − c)(a + b)` along the components, at `s`, as plain numbers.
    fn direct(p: &StepPolynomial, s: Real) -> Real {
        let (a, b, c) = (p.value(0, s), p.value(1, s), p.value(2, s));
        (a * b - c) * (a + b)
    }

    #[test]
    fn a_series_holds_the_function_it_was_built_from() {
        let p = poly(&[
            &[0.3, -1.2, 0.7, 0.1, -0.02, 0.004, 1e-4, -3e-6],
            &[-2.0, 0.5, 0.25, -0.125],
            &[1.0, 1.0],
        ]);
        let (a, b, c) = (
            Series::component(&p, 0),
            Series::component(&p, 1),
            Series::component(&p, 2),
        );
        let f = (a * b - c) * (a + b);
        // every component has the width of the widest (8): 15 terms times 8
        assert_eq!(f.coefficients().len(), 15 + 8 - 1);
        for (lo, hi) in [(0.0, 1.0), (0.2, 0.3), (0.61, 0.61 + 1e-7), (0.5, 0.5)] {
            let jet = f.enclose(&p, Interval::new(lo, hi));
            for k in 0..=20 {
                let s = lo + (hi - lo) * Real::from(k) / 20.0;
                assert!(jet.v.contains(direct(&p, s)), "{s}: {jet:?}");
                let d = 1e-6;
                let slope = (direct(&p, s + d) - direct(&p, s - d)) / (2.0 * d) / 0.5;
                let tolerance = 1e-6 * (1.0 + slope.abs());
                assert!(
                    jet.d.lo() - tolerance <= slope && slope <= jet.d.hi() + tolerance,
                    "{s}: {slope} not in {jet:?}"
                );
            }
        }
    }

    /// A product that cancels (`a a − a a`) is enclosed at rounding level, while interval
    /// arithmetic on `a`'s enclosure gives the width of its swing.
    #[test]
    fn cancellation_is_kept() {
        let p = poly(&[&[0.3, -1.2, 0.7, 0.1]]);
        let a = Series::component(&p, 0);
        let zero = a * a - a * a;
        let whole = zero.enclose(&p, Interval::new(0.0, 1.0));
        assert!(whole.v.contains(0.0));
        assert!(whole.v.width() < 1e-13, "{whole:?}");
        let ja = p.enclose(0, Interval::new(0.0, 1.0));
        assert!((ja * ja - ja * ja).v.width() > 0.1);
    }

    proptest::proptest! {
        /// Random components, random scales: `(a b − c)(a + b)` evaluated directly at points
        /// of a random range lies in the series' enclosure.
        #[test]
        fn every_value_lies_in_the_enclosure(
            a in proptest::collection::vec(-1e3f64..1e3, 1..=8),
            b in proptest::collection::vec(-1e3f64..1e3, 1..=8),
            c in proptest::collection::vec(-1e3f64..1e3, 1..=8),
            scale in -12i32..6,
            (lo, w) in (0.0f64..1.0, 0.0f64..1.0),
        ) {
            let k = 10f64.powi(scale);
            let scaled = |v: &[f64]| v.iter().map(|x| x * k).collect::<Vec<_>>();
            let (a, b, c) = (scaled(&a), scaled(&b), scaled(&c));
            let p = poly(&[&a, &b, &c]);
            let f = (Series::component(&p, 0) * Series::component(&p, 1)
                - Series::component(&p, 2))
                * (Series::component(&p, 0) + Series::component(&p, 1));
            let hi = (lo + w * (1.0 - lo)).min(1.0);
            for (lo, hi) in [(lo, hi), (0.0, 1.0)] {
                let jet = f.enclose(&p, Interval::new(lo, hi));
                for j in 0..=16 {
                    let s = lo + (hi - lo) * f64::from(j) / 16.0;
                    // the direct value rounds too: allow its own rounding
                    let v = direct(&p, s);
                    let (pa, pb, pc) = (p.value(0, s), p.value(1, s), p.value(2, s));
                    let slack = 64.0 * f64::EPSILON
                        * ((pa * pb).abs() + pc.abs()) * (pa.abs() + pb.abs());
                    proptest::prop_assert!(
                        jet.v.lo() - slack <= v && v <= jet.v.hi() + slack,
                        "{} not in {}", v, jet.v
                    );
                }
            }
        }
    }

    #[test]
    fn a_product_too_long_is_unknown() {
        let p = poly(&[&[1.0; 8]]);
        let a = Series::component(&p, 0);
        let long = a * a * a * a;
        assert!(long.coefficients().is_empty());
        assert_eq!(
            long.enclose(&p, Interval::new(0.0, 1.0)).v,
            Interval::ENTIRE
        );
    }
}

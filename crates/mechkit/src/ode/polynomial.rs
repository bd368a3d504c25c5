//! The interpolant of one step as a polynomial per component, for proofs about the motion
//! inside the step.
//!
//! Every dense output in [`crate::ode`] is a polynomial in the fraction of the step
//! `s = (t - t₀)/h ∈ [0, 1]`: Hermite's cubic, Shampine's quartic for Dormand-Prince 5(4),
//! the cubic of Bogacki-Shampine, Hairer's degree-7 interpolant of DOP853. A
//! [`StepPolynomial`] holds the monomial coefficients `y_i(s) = Σ_j c_ij s^j` of each
//! component, so that the component and its time derivative can be *enclosed* over any range
//! of `s` by interval arithmetic ([`StepPolynomial::enclose`]):
//!
//! - the value by the mean-value form `y(S) ⊂ y(m) + y'(S)·(S − m)` (`m` the midpoint of `S`),
//!   intersected with Horner's scheme on `S`: the overestimate shrinks with the square of the
//!   width, so halving a range quickly gives tight bounds;
//! - the time derivative `dy/dt = y'(s)/h` the same way from `y''`.
//!
//! The coefficients are computed in floating point from the method's stages, so the
//! polynomial equals the method's dense output to rounding.

use mechkit_expr::interval::{Interval, Jet};

use crate::Real;

/// Most coefficients per component (DOP853's interpolant has degree 7).
pub const MAX_COEFFICIENTS: usize = 8;

/// Ranges of `s` at least this wide are enclosed in the power form (cheap), narrower ones in
/// the mean-value form (tight): see [`StepPolynomial::enclose`].
const POWER_FORM_WIDTH: Real = 0.25;

/// The interpolant of one step: `y_i(t₀ + s h) = Σ_j c_ij s^j` for `s ∈ [0, 1]`.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct StepPolynomial {
    /// Start of the step (s).
    t0: Real,
    /// Length of the step (s).
    h: Real,
    /// `1/h` (0 for an empty step): the enclosures' time derivatives.
    inv_h: Real,
    /// Coefficients per component (`degree + 1`).
    width: usize,
    /// `coeffs[i * width + j] = c_ij`.
    coeffs: Vec<Real>,
}

impl StepPolynomial {
    /// Makes room for `n` components of `width` coefficients (all zero) over the step from
    /// `t0` of length `h`.
    pub fn reset(&mut self, t0: Real, h: Real, n: usize, width: usize) {
        assert!(
            (1..=MAX_COEFFICIENTS).contains(&width),
            "a step polynomial has 1 to {MAX_COEFFICIENTS} coefficients, not {width}"
        );
        self.t0 = t0;
        self.h = h;
        self.inv_h = if h == 0.0 { 0.0 } else { 1.0 / h };
        self.width = width;
        self.coeffs.clear();
        self.coeffs.resize(n * width, 0.0);
    }

    /// Start of the step (s).
    pub fn t0(&self) -> Real {
        self.t0
    }

    /// Length of the step (s).
    pub fn h(&self) -> Real {
        self.h
    }

    /// `1/h` (0 for an empty step).
    pub(crate) fn inv_h(&self) -> Real {
        self.inv_h
    }

    /// Number of components.
    pub fn len(&self) -> usize {
        self.coeffs.len().checked_div(self.width).unwrap_or(0)
    }

    /// Whether it has no components.
    pub fn is_empty(&self) -> bool {
        self.coeffs.is_empty()
    }

    /// The coefficients of component `i`, lowest power first.
    pub fn coefficients(&self, i: usize) -> &[Real] {
        &self.coeffs[i * self.width..(i + 1) * self.width]
    }

    /// The coefficients of component `i`, to fill.
    pub fn coefficients_mut(&mut self, i: usize) -> &mut [Real] {
        &mut self.coeffs[i * self.width..(i + 1) * self.width]
    }

    /// Sets component `i` to the cubic Hermite interpolant with values `y0`, `y1` and time
    /// derivatives `d0`, `d1` at the ends (see [`super::hermite`]).
    pub fn set_hermite(&mut self, i: usize, (y0, d0): (Real, Real), (y1, d1): (Real, Real)) {
        let h = self.h;
        let c = self.coefficients_mut(i);
        c.fill(0.0);
        c[0] = y0;
        c[1] = h * d0;
        c[2] = -3.0 * y0 - 2.0 * h * d0 + 3.0 * y1 - h * d1;
        c[3] = 2.0 * y0 + h * d0 - 2.0 * y1 + h * d1;
    }

    /// The fraction of the step at time `t`.
    pub fn fraction(&self, t: Real) -> Real {
        if self.h == 0.0 {
            1.0
        } else {
            (t - self.t0) / self.h
        }
    }

    /// The value of component `i` at the fraction `s` of the step.
    pub fn value(&self, i: usize, s: Real) -> Real {
        self.coefficients(i)
            .iter()
            .rev()
            .fold(0.0, |acc, c| acc * s + c)
    }

    /// Encloses component `i` and its time derivative over the fractions `s` of the step.
    ///
    /// A range of at least a quarter of the step is enclosed in the power form (each term
    /// `c_j s^j` bounded by its values at the range's ends, one pass over the coefficients:
    /// the whole step is the common first test of a proof). On a narrower one the polynomial
    /// is re-expanded about the midpoint `m` of `S` (a Taylor shift, `y(m + δ) = Σ_k b_k δ^k`),
    /// so with `r` the half-width of `S` the value lies within
    /// `Σ_{k≥1} |b_k| r^k` of `b_0` and the slope within `Σ_{k≥2} k |b_k| r^(k-1)` of `b_1`:
    /// the mean-value form, whose overestimate shrinks with the square of the width. The
    /// arithmetic is plain floating point; its rounding is bounded a priori (every `b_k` is
    /// a sum of at most `n` terms each at most `|c_j| (1 + |m|)^j`, formed in at most `2n`
    /// roundings) and added to both radii, so the enclosures are rigorous.
    pub fn enclose(&self, i: usize, s: Interval) -> Jet {
        enclose_coefficients(self.coefficients(i), &[], s, self.inv_h)
    }
}

/// Encloses the polynomial `Σ_j c_j s^j` of the fraction `s` of a step whose reciprocal
/// length is `inv_h` (0: an empty step), and its time derivative, over the fractions `S`, as
/// [`StepPolynomial::enclose`] does; `errors` (empty: none) bounds how far each `c_j` may be
/// from the true coefficient (a polynomial computed in floating point, a
/// [`Series`](super::Series)), and both radii grow by what those errors can add over `S`. At
/// most [`MAX_TERMS`] coefficients.
pub(crate) fn enclose_coefficients(c: &[Real], errors: &[Real], s: Interval, inv_h: Real) -> Jet {
    let extra = remainder(errors, s);
    if s.lo() >= 0.0 && s.hi() <= 1.0 && s.hi() - s.lo() >= POWER_FORM_WIDTH {
        return power_form(c, s, inv_h, extra);
    }
    taylor_form(c, s, inv_h, extra)
}

/// Most coefficients a [`Series`](super::Series) holds and is enclosed with: the product of
/// three interpolants of [`MAX_COEFFICIENTS`] each.
pub const MAX_TERMS: usize = 3 * MAX_COEFFICIENTS - 2;

/// What coefficient errors `e_j` add over `S`: `Σ e_j σ^j` to the value and
/// `Σ j e_j σ^(j-1)` to the slope per `s`, with `σ = max |s|` (rounded up by a relative
/// margin).
fn remainder(errors: &[Real], s: Interval) -> (Real, Real) {
    if errors.is_empty() {
        return (0.0, 0.0);
    }
    let sigma = s.lo().abs().max(s.hi().abs());
    let (mut value, mut slope) = (0.0, 0.0);
    let (mut p, mut q) = (1.0, 1.0); // σ^j, σ^(j-1)
    for (j, e) in errors.iter().enumerate() {
        value += e * p;
        if j >= 1 {
            slope += j as Real * e * q;
            q *= sigma;
        }
        p *= sigma;
    }
    let margin = 1.0 + 4.0 * (errors.len() as Real + 2.0) * Real::EPSILON;
    (value * margin, slope * margin)
}

/// The enclosure of a wide range `S ⊂ [0, 1]` in the power form: on non-negative `s`
/// every `s^j` lies between `lo^j` and `hi^j`, so each term `c_j s^j` between `c_j lo^j`
/// and `c_j hi^j`, and the sum of the terms' ranges holds the value (the slope the same
/// way from `j c_j s^(j-1)`). It costs one pass over the coefficients, without the Taylor
/// shift, and for the short steps of an integration (`|c_j|` falling fast with `j`) it is
/// nearly as tight as the mean-value form over the whole step. The rounding is bounded a
/// priori: every partial result is at most `Σ j |c_j|` in size (`|s| ≤ 1`), and each
/// is formed in at most `2n + 2` roundings.
fn power_form(c: &[Real], s: Interval, inv_h: Real, extra: (Real, Real)) -> Jet {
    if s.lo() == 0.0 && s.hi() == 1.0 {
        return whole_step(c, inv_h, extra);
    }
    let n = c.len();
    let (mut p_lo, mut p_hi) = (1.0, 1.0); // lo^j, hi^j
    let (mut q_lo, mut q_hi) = (1.0, 1.0); // lo^(j-1), hi^(j-1)
    let (mut v_lo, mut v_hi, mut scale) = (0.0, 0.0, 0.0);
    let (mut d_lo, mut d_hi, mut scale_d) = (0.0, 0.0, 0.0);
    for (j, &cj) in c.iter().enumerate() {
        let (a, b) = (cj * p_lo, cj * p_hi);
        v_lo += a.min(b);
        v_hi += a.max(b);
        scale += cj.abs();
        if j >= 1 {
            let k = j as Real * cj;
            let (a, b) = (k * q_lo, k * q_hi);
            d_lo += a.min(b);
            d_hi += a.max(b);
            scale_d += k.abs();
            q_lo *= s.lo();
            q_hi *= s.hi();
        }
        p_lo *= s.lo();
        p_hi *= s.hi();
    }
    power_jet((v_lo, v_hi, scale), (d_lo, d_hi, scale_d), n, inv_h, extra)
}

/// The power form over the whole step, `S = [0, 1]`: each `s^j` (`j ≥ 1`) lies in
/// `[0, 1]`, so the value lies in `c_0 + Σ_{j≥1} [min(c_j, 0), max(c_j, 0)]` (the slope
/// the same way); the first test of every proof, so a few additions.
fn whole_step(c: &[Real], inv_h: Real, extra: (Real, Real)) -> Jet {
    let n = c.len();
    let (mut v_lo, mut v_hi, mut scale) = (c[0], c[0], c[0].abs());
    let (mut d_lo, mut d_hi, mut scale_d) = (0.0, 0.0, 0.0);
    for (j, &cj) in c.iter().enumerate().skip(1) {
        v_lo += cj.min(0.0);
        v_hi += cj.max(0.0);
        scale += cj.abs();
        let k = j as Real * cj;
        if j == 1 {
            (d_lo, d_hi) = (k, k);
        } else {
            d_lo += k.min(0.0);
            d_hi += k.max(0.0);
        }
        scale_d += k.abs();
    }
    power_jet((v_lo, v_hi, scale), (d_lo, d_hi, scale_d), n, inv_h, extra)
}

/// The jet from the power form's sums `(lo, hi, Σ|terms|)` of the value and of the slope
/// per `s` of a polynomial of `n` coefficients, widened by the rounding of `n` terms and by
/// the coefficients' own errors `extra` (value, slope per `s`).
fn power_jet(
    value: (Real, Real, Real),
    slope: (Real, Real, Real),
    n: usize,
    inv_h: Real,
    extra: (Real, Real),
) -> Jet {
    let rounding = (2 * n + 2) as Real * Real::EPSILON * 1.01;
    let (err, err_d) = (rounding * value.2 + extra.0, rounding * slope.2 + extra.1);
    let v = outward(value.0 - err, value.1 + err);
    let per_time = if inv_h == 0.0 {
        Interval::point(0.0)
    } else {
        let (a, b) = ((slope.0 - err_d) * inv_h, (slope.1 + err_d) * inv_h);
        // two roundings each (the reciprocal and the product): two ulps outwards
        outward(a.min(b).next_down(), a.max(b).next_up())
    };
    Jet::new(v, per_time)
}

/// The enclosure of `S` in the mean-value (Taylor) form, widened by the coefficients' own
/// errors `extra` (value, slope per `s`).
fn taylor_form(c: &[Real], s: Interval, inv_h: Real, extra: (Real, Real)) -> Jet {
    let n = c.len();
    let m = s.mid();
    let r = (s.hi() - m).max(m - s.lo()).next_up();
    let mut b = [0.0; MAX_TERMS];
    b[..n].copy_from_slice(&c[..n]);
    // Taylor shift to m: repeated synthetic division by (x - m)
    for k in 0..n {
        for j in (k..n - 1).rev() {
            b[j] += m * b[j + 1];
        }
    }
    // a priori bound on the rounding of every b_k
    let grow = 1.0 + m.abs();
    let mut scale = 0.0;
    let mut power = 1.0;
    for cj in c {
        scale += cj.abs() * power;
        power *= grow;
    }
    let unit = Real::EPSILON * 0.5;
    let err = 2.0 * (2 * n) as Real * unit * scale * 1.01;
    // radii of the value and of the slope (d/ds), with the rounding of each b_k
    let (mut r0, mut r1) = (0.0, 0.0);
    let mut rpow = 1.0; // r^(k-1) at the top of iteration k
    for (k, bk) in b.iter().enumerate().take(n).skip(1) {
        let bk = bk.abs() + err;
        if k >= 2 {
            r1 += k as Real * bk * rpow;
        }
        rpow *= r;
        r0 += bk * rpow;
    }
    let (e0, e1) = (err + extra.0, err + extra.1);
    // the sums themselves round: a relative margin of n ulps covers them
    let margin = 1.0 + 4.0 * (n as Real) * Real::EPSILON;
    let value = widen(b[0], (r0 + e0) * margin);
    let slope = if n > 1 { b[1] } else { 0.0 };
    let per_time = if inv_h == 0.0 {
        Interval::point(0.0)
    } else {
        // dy/dt = (dy/ds)/h: the quotient rounds once more (the margin's extra ulps)
        widen(
            slope * inv_h,
            (r1 + e1) * margin * inv_h.abs() * margin + (slope * inv_h).abs() * 4.0 * Real::EPSILON,
        )
    };
    Jet::new(value, per_time)
}

/// `[x - radius, x + radius]`, rounded outwards (unknown when anything is not finite).
fn widen(x: Real, radius: Real) -> Interval {
    outward(x - radius, x + radius)
}

/// `[lo, hi]` widened by one ulp each way (unknown when either is not finite).
fn outward(lo: Real, hi: Real) -> Interval {
    let (lo, hi) = (lo.next_down(), hi.next_up());
    if lo.is_finite() && hi.is_finite() {
        Interval::new(lo, hi)
    } else {
        Interval::ENTIRE
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hermite_coefficients_reproduce_the_interpolant() {
        let mut p = StepPolynomial::default();
        p.reset(1.0, 0.5, 1, 4);
        p.set_hermite(0, (0.3, -1.2), (0.9, 2.5));
        for s in [0.0, 0.2, 0.5, 0.77, 1.0] {
            let want = super::super::hermite(0.3, -1.2, 0.9, 2.5, 0.5, s);
            assert!((p.value(0, s) - want).abs() < 1e-15, "{s}");
        }
    }

    #[test]
    fn enclosures_hold_values_and_derivatives() {
        let mut p = StepPolynomial::default();
        p.reset(0.0, 2.0, 1, 6);
        p.coefficients_mut(0)
            .copy_from_slice(&[0.1, -3.0, 7.5, -2.0, -4.0, 1.25]);
        let exact = |s: Real| {
            0.1 - 3.0 * s + 7.5 * s * s - 2.0 * s.powi(3) - 4.0 * s.powi(4) + 1.25 * s.powi(5)
        };
        let slope =
            |s: Real| (-3.0 + 15.0 * s - 6.0 * s * s - 16.0 * s.powi(3) + 6.25 * s.powi(4)) * 0.5;
        for (a, b) in [(0.0, 1.0), (0.1, 0.3), (0.45, 0.4501), (0.9, 1.0)] {
            let jet = p.enclose(0, Interval::new(a, b));
            for k in 0..=20 {
                let s = a + (b - a) * Real::from(k) / 20.0;
                assert!(jet.v.contains(exact(s)), "{s}: {jet:?}");
                assert!(jet.d.contains(slope(s)), "{s}: {jet:?}");
            }
        }
        // tight on narrow ranges: the mean-value form
        let narrow = p.enclose(0, Interval::new(0.5, 0.5 + 1e-6));
        assert!(narrow.v.width() < 1e-5);
    }

    proptest::proptest! {
        /// Random polynomials of every degree, random ranges: every value and slope at points
        /// of the range lies in the enclosure.
        #[test]
        fn every_point_lies_in_the_enclosure(
            coeffs in proptest::collection::vec(-1e3f64..1e3, 1..=MAX_COEFFICIENTS),
            scale in -12i32..6,
            (a, w) in (0.0f64..1.0, 0.0f64..1.0),
            h in 1e-6f64..1e3,
        ) {
            let b = (a + w * (1.0 - a)).min(1.0);
            let mut p = StepPolynomial::default();
            p.reset(0.0, h, 1, coeffs.len());
            let k = 10f64.powi(scale);
            for (c, x) in p.coefficients_mut(0).iter_mut().zip(&coeffs) {
                *c = x * k;
            }
            let c = p.coefficients(0).to_vec();
            // the range drawn (the power form when wide, the mean-value form when narrow) and
            // the whole step (its own power form)
            for (a, b) in [(a, b), (0.0, 1.0)] {
                let jet = p.enclose(0, Interval::new(a, b));
                for j in 0..=16 {
                    let s = a + (b - a) * f64::from(j) / 16.0;
                    let value = p.value(0, s);
                    let slope = c.iter().enumerate().skip(1).rev()
                        .fold(0.0, |acc, (i, ci)| acc * s + i as f64 * ci) / h;
                    proptest::prop_assert!(jet.v.contains(value), "{} not in {}", value, jet.v);
                    proptest::prop_assert!(jet.d.contains(slope), "{} not in {}", slope, jet.d);
                }
            }
        }
    }
}

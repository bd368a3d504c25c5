//! The coefficients of Radau IIA of order 5 (three stages), and what its Newton iteration and
//! dense output are made of, derived from the Butcher matrix when the method is built.
//!
//! The nodes are the Radau points `c = ((4 − √6)/10, (4 + √6)/10, 1)`. The stage equations
//! `Z = h (A ⊗ I) F(Z)` (with `Zᵢ = Yᵢ − y₀`) are solved by simplified Newton in the
//! coordinates `W = (T⁻¹ ⊗ I) Z` in which `A⁻¹ = T Λ T⁻¹` is block diagonal,
//! `Λ = [[γ, 0, 0], [0, α, −β], [0, β, α]]`: one real system `(γ/h − J)` and one complex
//! system `((α + iβ)/h − J)` of the size of the state instead of one three times as large
//! (Hairer & Wanner, *Solving ODEs II*, Sec. IV.8). `T` is built here from the eigenvectors of
//! `A⁻¹` and checked against its definition in the tests.

use nalgebra::{Complex, Matrix3};

use crate::Real;

/// The derived coefficients of Radau IIA(5).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct RadauTableau {
    /// Nodes.
    pub c: [Real; 3],
    /// The real eigenvalue of `A⁻¹`.
    pub gamma: Real,
    /// The complex pair `α ± iβ` of `A⁻¹` (β > 0).
    pub alpha: Real,
    pub beta: Real,
    /// `T` and `T⁻¹` (row-major).
    pub t: [[Real; 3]; 3],
    pub ti: [[Real; 3]; 3],
    /// The error estimate's weights: `err = (γ/h − J)⁻¹ (f₀ + Σ dᵢ Zᵢ / h)`; exact for
    /// solutions of degree up to 3, so the estimate is of order 4 against the method's 5.
    pub d: [Real; 3],
    /// The collocation polynomial `y₀ + Σₖ qₖ sᵏ` (k = 1..3) through `(cᵢ, Zᵢ)`: `q = V⁻¹ Z`,
    /// `V_ik = cᵢᵏ`.
    pub v_inv: [[Real; 3]; 3],
}

impl RadauTableau {
    pub fn new() -> Self {
        let s6 = 6.0_f64.sqrt();
        let c = [(4.0 - s6) / 10.0, (4.0 + s6) / 10.0, 1.0];
        let a = Matrix3::new(
            (88.0 - 7.0 * s6) / 360.0,
            (296.0 - 169.0 * s6) / 1800.0,
            (-2.0 + 3.0 * s6) / 225.0,
            (296.0 + 169.0 * s6) / 1800.0,
            (88.0 + 7.0 * s6) / 360.0,
            (-2.0 - 3.0 * s6) / 225.0,
            (16.0 - s6) / 36.0,
            (16.0 + s6) / 36.0,
            1.0 / 9.0,
        );
        let a_inv = a.try_inverse().expect("Radau IIA's matrix is invertible");
        let eig = a_inv.complex_eigenvalues();
        let real = (0..3)
            .min_by(|&i, &j| eig[i].im.abs().total_cmp(&eig[j].im.abs()))
            .expect("three eigenvalues");
        let pair = (0..3)
            .find(|&i| i != real && eig[i].im > 0.0)
            .expect("a complex pair");
        let gamma = eig[real].re;
        let lambda = eig[pair];
        // an eigenvector of a rank-2 matrix M − λI: the cross product of two of its rows
        let null = |lambda: Complex<Real>| -> [Complex<Real>; 3] {
            let m = |r: usize, k: usize| {
                Complex::new(a_inv[(r, k)], 0.0)
                    - if r == k {
                        lambda
                    } else {
                        Complex::new(0.0, 0.0)
                    }
            };
            [
                m(0, 1) * m(1, 2) - m(0, 2) * m(1, 1),
                m(0, 2) * m(1, 0) - m(0, 0) * m(1, 2),
                m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0),
            ]
        };
        let v1 = null(Complex::new(gamma, 0.0));
        let v2 = null(lambda);
        // columns v₁, Re v₂, −Im v₂: then T⁻¹ A⁻¹ T = Λ
        let t = Matrix3::from_fn(|r, k| match k {
            0 => v1[r].re,
            1 => v2[r].re,
            _ => -v2[r].im,
        });
        let ti = t
            .try_inverse()
            .expect("eigenvectors of distinct eigenvalues");
        let v = Matrix3::from_fn(|r, k| c[r].powi(k as i32 + 1));
        let v_inv = v.try_inverse().expect("distinct nodes");
        let rows = |m: &Matrix3<Real>| -> [[Real; 3]; 3] {
            std::array::from_fn(|r| std::array::from_fn(|k| m[(r, k)]))
        };
        Self {
            c,
            gamma,
            alpha: lambda.re,
            beta: lambda.im,
            t: rows(&t),
            ti: rows(&ti),
            d: [
                -(13.0 + 7.0 * s6) / 3.0,
                (-13.0 + 7.0 * s6) / 3.0,
                -1.0 / 3.0,
            ],
            v_inv: rows(&v_inv),
        }
    }

    /// `m · x` for a row-major 3 × 3 matrix.
    #[inline]
    pub fn apply(m: &[[Real; 3]; 3], x: [Real; 3]) -> [Real; 3] {
        let row = |r: &[Real; 3]| r[0] * x[0] + r[1] * x[1] + r[2] * x[2];
        [row(&m[0]), row(&m[1]), row(&m[2])]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_transformation_block_diagonalises_the_inverse_matrix() {
        let rt = RadauTableau::new();
        // the values published with RADAU5 (Hairer & Wanner)
        assert!(
            (rt.gamma - 3.637_834_252_744_496).abs() < 1e-13,
            "{}",
            rt.gamma
        );
        assert!(
            (rt.alpha - 2.681_082_873_627_752).abs() < 1e-13,
            "{}",
            rt.alpha
        );
        assert!(
            (rt.beta - 3.050_430_199_247_41).abs() < 1e-13,
            "{}",
            rt.beta
        );
        let s6 = 6.0_f64.sqrt();
        let a = Matrix3::new(
            (88.0 - 7.0 * s6) / 360.0,
            (296.0 - 169.0 * s6) / 1800.0,
            (-2.0 + 3.0 * s6) / 225.0,
            (296.0 + 169.0 * s6) / 1800.0,
            (88.0 + 7.0 * s6) / 360.0,
            (-2.0 - 3.0 * s6) / 225.0,
            (16.0 - s6) / 36.0,
            (16.0 + s6) / 36.0,
            1.0 / 9.0,
        );
        let t = Matrix3::from_fn(|r, k| rt.t[r][k]);
        let ti = Matrix3::from_fn(|r, k| rt.ti[r][k]);
        let lambda = ti * a.try_inverse().unwrap() * t;
        let want = Matrix3::new(
            rt.gamma, 0.0, 0.0, 0.0, rt.alpha, -rt.beta, 0.0, rt.beta, rt.alpha,
        );
        assert!((lambda - want).abs().max() < 1e-12, "{lambda}");
        // the collocation polynomial interpolates the stages
        for (i, ci) in rt.c.iter().enumerate() {
            let mut z = [0.0; 3];
            z[i] = 1.0;
            let q = RadauTableau::apply(&rt.v_inv, z);
            for (j, cj) in rt.c.iter().enumerate() {
                let p = q[0] * cj + q[1] * cj * cj + q[2] * cj.powi(3);
                let want = if i == j { 1.0 } else { 0.0 };
                assert!((p - want).abs() < 1e-13, "{i} {j} {p} at {ci}");
            }
        }
        // the error weights: 1 + Σ dᵢ cᵢ = 0 and Σ dᵢ cᵢ² = 0
        let s1: Real = rt.d.iter().zip(rt.c).map(|(d, c)| d * c).sum();
        let s2: Real = rt.d.iter().zip(rt.c).map(|(d, c)| d * c * c).sum();
        assert!((1.0 + s1).abs() < 1e-14 && s2.abs() < 1e-14, "{s1} {s2}");
    }
}

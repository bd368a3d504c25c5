//! Gauss-Legendre nodes and weights on [-1, 1], computed by Newton's method on the Legendre
//! polynomial `P_N` (Press, Teukolsky, Vetterling and Flannery, *Numerical Recipes*, 3rd ed.,
//! 2007, §4.6, routine `gauleg`).
//!
//! `P_N` and its derivative come from the three-term recurrence
//! `(k+1) P_{k+1}(x) = (2k+1) x P_k(x) − k P_{k−1}(x)` and
//! `P_N'(x) = N (x P_N(x) − P_{N−1}(x)) / (x² − 1)`. The `i`-th root (descending) starts from
//! Tricomi's estimate `cos(π (i + 3/4) / (N + 1/2))` and Newton converges quadratically; the
//! weights are `w_i = 2 / ((1 − x_i²) P_N'(x_i)²)`. The rule with `N` points integrates
//! polynomials of degree `2N − 1` exactly.

use crate::Real;

/// Most points [`gauss_legendre`] computes.
pub const MAX_GAUSS_POINTS: usize = 64;

/// `(P_N(x), P_N'(x))` by the three-term recurrence.
fn legendre(n: usize, x: Real) -> (Real, Real) {
    let (mut p_prev, mut p) = (1.0, x);
    for k in 1..n {
        let k = k as Real;
        let next = ((2.0 * k + 1.0) * x * p - k * p_prev) / (k + 1.0);
        p_prev = p;
        p = next;
    }
    let dp = n as Real * (x * p - p_prev) / ((x - 1.0) * (x + 1.0));
    (p, dp)
}

/// The `n`-point Gauss-Legendre rule on [-1, 1]: `(nodes, weights)`, nodes ascending, so that
/// `∫_{-1}^{1} f(x) dx ≈ Σ w_i f(x_i)`, exactly for polynomials of degree `2n − 1`.
///
/// Against 40-digit mpmath roots, the nodes are within one ulp (1.1e-16) and the weights within
/// 1.3e-14 relative (`n` = 64; 2e-15 for `n` = 20). The rule is exactly symmetric
/// (`x_{n−1−i} = −x_i`, equal weights).
///
/// Panics if `n` is 0 or above [`MAX_GAUSS_POINTS`] (64).
///
/// # Example
/// ```
/// use approx::assert_relative_eq;
/// use mechkit::quad::gauss_legendre;
/// let (x, w) = gauss_legendre(2);
/// assert_relative_eq!(x[1], 1.0 / 3f64.sqrt(), epsilon = 1e-15);
/// assert_relative_eq!(w[0], 1.0, epsilon = 1e-15);
/// ```
pub fn gauss_legendre(n: usize) -> (Vec<Real>, Vec<Real>) {
    assert!(
        (1..=MAX_GAUSS_POINTS).contains(&n),
        "Gauss-Legendre rules have 1 to {MAX_GAUSS_POINTS} points, not {n}"
    );
    let mut nodes = vec![0.0; n];
    let mut weights = vec![0.0; n];
    // The positive roots (descending in i), mirrored onto the negative half.
    for i in 0..n.div_ceil(2) {
        let mut x = (std::f64::consts::PI * (i as Real + 0.75) / (n as Real + 0.5)).cos();
        for _ in 0..100 {
            let (p, dp) = legendre(n, x);
            let dx = p / dp;
            x -= dx;
            if dx.abs() <= 1e-16 {
                break;
            }
        }
        if 2 * i + 1 == n {
            x = 0.0; // the centre of an odd rule
        }
        // The weight at the rounded node, corrected to first order to the exact root
        // `x − δ` with `δ = P/P'` (at a root `d ln w/dx = −2x/(1 − x²)`, so one ulp in a
        // node near ±1 would otherwise cost 1e-13 relative in its weight).
        let (p, dp) = legendre(n, x);
        let one_minus_x2 = (1.0 - x) * (1.0 + x);
        let delta = p / dp;
        let w = 2.0 / (one_minus_x2 * dp * dp) * (1.0 + 2.0 * x * delta / one_minus_x2);
        nodes[n - 1 - i] = x;
        nodes[i] = -x;
        weights[n - 1 - i] = w;
        weights[i] = w;
    }
    (nodes, weights)
}

#[cfg(test)]
// Reference values keep the digits they were computed with.
#[allow(clippy::excessive_precision)]
mod tests {
    use super::*;

    #[test]
    fn two_points_are_plus_minus_one_over_root_three() {
        let (x, w) = gauss_legendre(2);
        let r = 1.0 / 3f64.sqrt();
        assert!(
            (x[0] + r).abs() < 2e-16 && (x[1] - r).abs() < 2e-16,
            "{x:?}"
        );
        assert!(
            (w[0] - 1.0).abs() < 1e-15 && (w[1] - 1.0).abs() < 1e-15,
            "{w:?}"
        );
        assert_eq!(gauss_legendre(1), (vec![0.0], vec![2.0]));
    }

    #[test]
    fn five_points_match_the_table() {
        // Abramowitz and Stegun, Table 25.4, to 20 digits by mpmath as below (x = 0: w = 128/225).
        let (x, w) = gauss_legendre(5);
        let xs = [
            -0.906_179_845_938_663_992_8,
            -0.538_469_310_105_683_091_04,
            0.0,
            0.538_469_310_105_683_091_04,
            0.906_179_845_938_663_992_8,
        ];
        let ws = [
            0.236_926_885_056_189_087_51,
            0.478_628_670_499_366_468_04,
            128.0 / 225.0,
            0.478_628_670_499_366_468_04,
            0.236_926_885_056_189_087_51,
        ];
        for i in 0..5 {
            assert!((x[i] - xs[i]).abs() < 1e-15, "x[{i}] = {}", x[i]);
            assert!((w[i] - ws[i]).abs() < 1e-15, "w[{i}] = {}", w[i]);
        }
    }

    #[test]
    fn sixty_four_points_match_mpmath() {
        // 30-digit roots of P_64 and their weights (numpy's leggauss is off by 2e-15 in w[63]):
        // python3 -c "import mpmath as m; m.mp.dps=30; P=lambda t: m.legendre(64,t);
        //   r=m.findroot(P, 0.9993); print(r, 2/((1-r**2)*m.diff(P,r)**2))"   (and from 0.0243)
        let (x, w) = gauss_legendre(64);
        assert!(
            (x[63] - 0.999_305_041_735_772_139_46).abs() < 2e-16,
            "{}",
            x[63]
        );
        assert!(
            (w[63] - 0.001_783_280_721_696_432_947_3).abs() < 5e-17,
            "{}",
            w[63]
        );
        assert!(
            (x[32] - 0.024_350_292_663_424_432_509).abs() < 1e-17,
            "{}",
            x[32]
        );
        assert!(
            (w[32] - 0.048_690_957_009_139_720_383).abs() < 1e-16,
            "{}",
            w[32]
        );
    }

    #[test]
    fn nodes_ascend_and_weights_sum_to_two() {
        for n in 1..=MAX_GAUSS_POINTS {
            let (x, w) = gauss_legendre(n);
            assert!(x.windows(2).all(|p| p[0] < p[1]), "n = {n}");
            assert!(x[0] > -1.0 && x[n - 1] < 1.0, "n = {n}");
            assert!((w.iter().sum::<Real>() - 2.0).abs() < 1e-14, "n = {n}");
        }
    }

    #[test]
    fn exact_for_polynomials_of_degree_two_n_minus_one() {
        // ∫_0^1 x^k dx = 1/(k+1), on [0, 1] so that odd powers do not vanish by symmetry.
        for n in 1..=MAX_GAUSS_POINTS {
            let (x, w) = gauss_legendre(n);
            for k in [0, n, 2 * n - 1] {
                let q: Real = x
                    .iter()
                    .zip(&w)
                    .map(|(&x, &w)| 0.5 * w * (0.5 * (x + 1.0)).powi(k as i32))
                    .sum();
                let exact = 1.0 / (k as Real + 1.0);
                assert!(
                    (q - exact).abs() < 1e-15,
                    "n = {n}, k = {k}: {q} vs {exact}"
                );
            }
            // and not beyond: x^(2n) is not integrated exactly (the error, ~ 4^-n, is visible for
            // small n)
            if n > 10 {
                continue;
            }
            let q: Real = x
                .iter()
                .zip(&w)
                .map(|(&x, &w)| w * x.powi(2 * n as i32))
                .sum();
            assert!((q - 2.0 / (2.0 * n as Real + 1.0)).abs() > 1e-12, "n = {n}");
        }
    }

    #[test]
    #[should_panic(expected = "1 to 64 points")]
    fn too_many_points_panics() {
        let _ = gauss_legendre(65);
    }
}

//! The elliptic-function reference: K(m) by the AGM, sn/cn/dn and F(φ|m) against mpmath, and the
//! Euler-Poinsot solution against Euler's equations.

use mechkit::mass::Vec3;
use mechkit::rigid::free3d::{Poinsot, complete_k, incomplete_f, jacobi};

#[test]
#[allow(clippy::excessive_precision)] // the digits mpmath printed
fn complete_k_by_agm_matches_mpmath_to_2e_16() {
    // mpmath.ellipk at 25 digits
    let cases = [
        (0.0, std::f64::consts::FRAC_PI_2),
        (0.1, 1.612_441_348_720_219_4),
        (0.5, 1.854_074_677_301_371_9),
        (0.9, 2.578_092_113_348_173_3),
        (0.99, 3.695_637_362_989_874_2),
        (0.999_999, 8.294_051_463_601_062),
    ];
    for (m, k) in cases {
        let rel = (complete_k(m) - k).abs() / k;
        assert!(rel < 4e-16, "K({m}): {} vs {k}, {rel:e}", complete_k(m));
    }
    // near m = 1 through the complement: K ≈ ln(4/√m₁)
    let k = mechkit::rigid::free3d::complete_k_complement(1e-12);
    assert!((k - 15.201_804_919_087_715).abs() < 1e-13, "{k}");
}

#[test]
#[allow(clippy::excessive_precision)] // the digits mpmath printed
fn jacobi_functions_and_their_inverse_match_mpmath() {
    let cases = [
        (0.7, 0.8, 0.612_365_484_117_245_3, 0.790_574_799_662_784_5),
        (3.0, 0.3, 0.411_422_660_634_000_65, -0.911_444_674_303_843_8),
        (
            10.0,
            0.999,
            -0.307_462_292_454_822_26,
            -0.951_560_265_415_924_9,
        ),
        (
            -1.3,
            0.5,
            -0.920_446_474_210_017_8,
            0.390_868_632_809_473_46,
        ),
    ];
    for (u, m, sn, cn) in cases {
        let (s, c, d) = jacobi(u, m);
        assert!(
            (s - sn).abs() < 1e-14 && (c - cn).abs() < 1e-14,
            "{u} {m}: {s} {c}"
        );
        assert!((d * d - (1.0 - m * sn * sn)).abs() < 1e-14);
    }
    for (phi, m, f) in [
        (1.2, 0.6, 1.381_322_687_881_858_2),
        (0.3, 0.99, 0.304_556_009_344_368_2),
        (2.5, 0.5, 3.044_408_477_487_261_3),
        (-4.0, 0.7, -5.088_975_077_596_994),
    ] {
        assert!((incomplete_f(phi, m) - f).abs() < 2e-14, "F({phi}|{m})");
    }
}

/// Euler's equations `I₁ω̇₁ = (I₂ − I₃)ω₂ω₃` (and cyclic), by central differences of the
/// elliptic solution.
fn euler_residual(moments: [f64; 3], p: &Poinsot, t: f64) -> f64 {
    let h = 1e-5;
    let dw = (p.omega(t + h) - p.omega(t - h)) / (2.0 * h);
    let w = p.omega(t);
    let i = moments;
    (0..3)
        .map(|k| {
            let (a, b) = ((k + 1) % 3, (k + 2) % 3);
            (i[k] * dw[k] - (i[a] - i[b]) * w[a] * w[b]).abs()
        })
        .fold(0.0, f64::max)
}

#[test]
fn poinsot_solution_solves_eulers_equations_in_both_regimes_and_any_axis_order() {
    for moments in [
        [1.0, 2.0, 3.0],
        [3.0, 1.0, 2.0],
        [2.0, 3.0, 1.0],
        [2.0, 1.0, 3.0],
    ] {
        for omega in [[0.3, 1.0, 0.2], [1.0, 0.4, 0.1], [0.1, 0.4, 1.0]] {
            let p = Poinsot::new(moments, Vec3::from(omega)).unwrap();
            assert!((p.omega(0.0) - Vec3::from(omega)).norm() < 1e-13);
            for t in [0.3, 1.7, 5.0, 23.0] {
                let r = euler_residual(moments, &p, t);
                assert!(r < 1e-8, "{moments:?} {omega:?} t = {t}: residual {r:e}");
            }
            let back = p.omega(p.period());
            assert!((back - Vec3::from(omega)).norm() < 1e-11, "periodic");
        }
    }
    // steady rotations and the separatrix have no period
    assert!(Poinsot::new([1.0, 2.0, 3.0], Vec3::new(0.0, 0.0, 1.0)).is_none());
    assert!(Poinsot::new([1.0, 2.0, 3.0], Vec3::new(0.0, 1.0, 0.0)).is_none());
    assert!(Poinsot::new([2.0, 2.0, 2.0], Vec3::new(0.3, 1.0, 0.0)).is_none());
}

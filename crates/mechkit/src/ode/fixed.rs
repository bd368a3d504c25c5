//! The coefficients of the most used pairs, Dormand-Prince 5(4) and DOP853, as constants:
//! with them the adaptive stepper's stage loops are unrolled with the coefficients in the code
//! ([`super::stages::Stages::compute_fixed`]). They are the same numbers as [`Tableau::dopri5`]
//! and [`Tableau::dop853`]; [`Kernel::for_tableau`] checks that, entry by entry, before using
//! them, so any other tableau (or a modified copy) takes the general path.

// The digits are kept as published.
#![allow(clippy::excessive_precision, clippy::unreadable_literal)]

use super::dop853::DOP853 as D;
use super::stages::sparse;
use super::tableau::{DenseKind, Tableau};
use crate::Real;

/// A tableau's non-zero coefficients as constants: the nodes `C`, the rows `A` (row `i`
/// gives stage `i`), the weights `B` and the error weights `E` (and DOP853's `E3`).
pub(crate) trait FixedTableau {
    const C: &'static [Real];
    const A: &'static [&'static [(usize, Real)]];
    const B: &'static [(usize, Real)];
    const E: &'static [(usize, Real)];
    const E3: &'static [(usize, Real)];

    /// Whether `tab` has exactly these coefficients.
    fn matches(tab: &Tableau) -> bool {
        let s = tab.stages();
        Self::A.len() == s
            && (0..s).all(|i| tab.c[i] == Self::C[i] && sparse(&tab.a[i]) == Self::A[i])
            && sparse(&tab.b) == Self::B
            && sparse(&tab.e) == Self::E
            && sparse(&tab.e3) == Self::E3
    }
}

/// Dormand-Prince 5(4) ([`Tableau::dopri5`]).
pub(crate) struct Dopri5;

impl FixedTableau for Dopri5 {
    const C: &'static [Real] = &[0.0, 1. / 5., 3. / 10., 4. / 5., 8. / 9., 1.0];
    const A: &'static [&'static [(usize, Real)]] = &[
        &[],
        &[(0, 1. / 5.)],
        &[(0, 3. / 40.), (1, 9. / 40.)],
        &[(0, 44. / 45.), (1, -56. / 15.), (2, 32. / 9.)],
        &[
            (0, 19372. / 6561.),
            (1, -25360. / 2187.),
            (2, 64448. / 6561.),
            (3, -212. / 729.),
        ],
        &[
            (0, 9017. / 3168.),
            (1, -355. / 33.),
            (2, 46732. / 5247.),
            (3, 49. / 176.),
            (4, -5103. / 18656.),
        ],
    ];
    const B: &'static [(usize, Real)] = &[
        (0, 35. / 384.),
        (2, 500. / 1113.),
        (3, 125. / 192.),
        (4, -2187. / 6784.),
        (5, 11. / 84.),
    ];
    const E: &'static [(usize, Real)] = &[
        (0, -71. / 57600.),
        (2, 71. / 16695.),
        (3, -71. / 1920.),
        (4, 17253. / 339_200.),
        (5, -22. / 525.),
        (6, 1. / 40.),
    ];
    const E3: &'static [(usize, Real)] = &[];
}

/// DOP853 ([`Tableau::dop853`]), from the published digits in [`super::dop853`].
pub(crate) struct Dop853;

impl FixedTableau for Dop853 {
    const C: &'static [Real] = &D.c;
    const A: &'static [&'static [(usize, Real)]] = &[
        &[],
        &[(0, D.a[1][0])],
        &[(0, D.a[2][0]), (1, D.a[2][1])],
        &[(0, D.a[3][0]), (2, D.a[3][2])],
        &[(0, D.a[4][0]), (2, D.a[4][2]), (3, D.a[4][3])],
        &[(0, D.a[5][0]), (3, D.a[5][3]), (4, D.a[5][4])],
        &[
            (0, D.a[6][0]),
            (3, D.a[6][3]),
            (4, D.a[6][4]),
            (5, D.a[6][5]),
        ],
        &[
            (0, D.a[7][0]),
            (3, D.a[7][3]),
            (4, D.a[7][4]),
            (5, D.a[7][5]),
            (6, D.a[7][6]),
        ],
        &[
            (0, D.a[8][0]),
            (3, D.a[8][3]),
            (4, D.a[8][4]),
            (5, D.a[8][5]),
            (6, D.a[8][6]),
            (7, D.a[8][7]),
        ],
        &[
            (0, D.a[9][0]),
            (3, D.a[9][3]),
            (4, D.a[9][4]),
            (5, D.a[9][5]),
            (6, D.a[9][6]),
            (7, D.a[9][7]),
            (8, D.a[9][8]),
        ],
        &[
            (0, D.a[10][0]),
            (3, D.a[10][3]),
            (4, D.a[10][4]),
            (5, D.a[10][5]),
            (6, D.a[10][6]),
            (7, D.a[10][7]),
            (8, D.a[10][8]),
            (9, D.a[10][9]),
        ],
        &[
            (0, D.a[11][0]),
            (3, D.a[11][3]),
            (4, D.a[11][4]),
            (5, D.a[11][5]),
            (6, D.a[11][6]),
            (7, D.a[11][7]),
            (8, D.a[11][8]),
            (9, D.a[11][9]),
            (10, D.a[11][10]),
        ],
    ];
    const B: &'static [(usize, Real)] = &[
        (0, D.a[12][0]),
        (5, D.a[12][5]),
        (6, D.a[12][6]),
        (7, D.a[12][7]),
        (8, D.a[12][8]),
        (9, D.a[12][9]),
        (10, D.a[12][10]),
        (11, D.a[12][11]),
    ];
    const E: &'static [(usize, Real)] = &[
        (0, D.e5[0]),
        (5, D.e5[5]),
        (6, D.e5[6]),
        (7, D.e5[7]),
        (8, D.e5[8]),
        (9, D.e5[9]),
        (10, D.e5[10]),
        (11, D.e5[11]),
    ];
    const E3: &'static [(usize, Real)] = &[
        (0, D.a[12][0] - 0.244_094_488_188_976_377_952_755_905_512),
        (5, D.a[12][5]),
        (6, D.a[12][6]),
        (7, D.a[12][7]),
        (8, D.a[12][8] - 0.733_846_688_281_611_857_341_361_741_547),
        (9, D.a[12][9]),
        (10, D.a[12][10]),
        (
            11,
            D.a[12][11] - 0.220_588_235_294_117_647_058_823_529_412e-1,
        ),
    ];
}

/// Which stage loops an adaptive stepper runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Kernel {
    /// [`Dopri5`]'s constants.
    Dopri5,
    /// [`Dop853`]'s constants (with its combined error estimate).
    Dop853,
    /// The tableau's rows as data.
    General,
}

impl Kernel {
    /// The constants' kernel when `tab` has exactly their coefficients, else the general one.
    pub fn for_tableau(tab: &Tableau) -> Kernel {
        if Dopri5::matches(tab) && tab.dense != DenseKind::Dop853 {
            Kernel::Dopri5
        } else if Dop853::matches(tab) && tab.dense == DenseKind::Dop853 {
            Kernel::Dop853
        } else {
            Kernel::General
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ode::{AdaptiveConfig, AdaptiveRk, OdeSystem, State, Tolerance};

    /// A damped, driven chain of `n` cubic oscillators, `y = [q, v]`.
    struct Chain(usize);

    impl OdeSystem for Chain {
        fn dim(&self) -> usize {
            2 * self.0
        }

        fn rhs_into(&self, t: Real, y: &[Real], dydt: &mut [Real]) {
            let n = self.0;
            let (q, v) = y.split_at(n);
            dydt[..n].copy_from_slice(v);
            for i in 0..n {
                let l = if i > 0 { q[i - 1] } else { 0.0 };
                let r = q.get(i + 1).copied().unwrap_or(0.0);
                dydt[n + i] = l - 2.0 * q[i] + r - 0.1 * v[i] - q[i].powi(3) + 0.01 * t.sin();
            }
        }
    }

    /// Steps, statistics, states and dense output of `tab` along 30 s of the chain.
    fn run(tab: &Tableau, kernel: Kernel, n: usize) -> (Vec<Real>, crate::ode::AdaptiveStats) {
        let config = AdaptiveConfig {
            rtol: Tolerance::Scalar(1e-9),
            atol: Tolerance::Scalar(1e-12),
            ..AdaptiveConfig::default()
        };
        let mut rk = AdaptiveRk::new(tab.clone(), config).expect("valid settings");
        rk.kernel = kernel;
        let sys = Chain(n);
        let mut s = State::new(
            0.0,
            (0..2 * n).map(|i| 0.3 * (i as Real + 1.0).sin()).collect(),
        );
        let mut seen = Vec::new();
        let mut out = vec![0.0; 2 * n];
        while s.t < 30.0 {
            rk.step(&sys, &mut s, 30.0).expect("a step");
            let (a, b) = rk.last_step();
            rk.dense_into(&sys, 0.3 * a + 0.7 * b, &mut out);
            seen.extend_from_slice(&out);
            seen.extend_from_slice(&s.y);
        }
        (seen, rk.stats())
    }

    #[test]
    fn the_unrolled_loops_give_the_general_paths_results_bit_for_bit() {
        // 2 components (one block, padded), 6 and 18 (several blocks, the last padded), 8
        for (tab, kernel) in [
            (Tableau::dopri5(), Kernel::Dopri5),
            (Tableau::dop853(), Kernel::Dop853),
        ] {
            for n in [1, 3, 4, 9] {
                let (fast, fast_stats) = run(&tab, kernel, n);
                let (general, general_stats) = run(&tab, Kernel::General, n);
                assert_eq!(fast_stats, general_stats, "{} n = {n}", tab.name);
                assert!(fast_stats.accepted > 20, "{} n = {n}", tab.name);
                assert!(
                    fast.iter()
                        .zip(&general)
                        .all(|(a, b)| a.to_bits() == b.to_bits()),
                    "{} n = {n}",
                    tab.name
                );
            }
        }
    }

    #[test]
    fn the_constants_are_the_tableaus() {
        assert_eq!(Kernel::for_tableau(&Tableau::dopri5()), Kernel::Dopri5);
        assert_eq!(Kernel::for_tableau(&Tableau::dop853()), Kernel::Dop853);
        assert_eq!(
            Kernel::for_tableau(&Tableau::bogacki_shampine()),
            Kernel::General
        );
        // one coefficient changed in its last bit: the general path
        let mut t = Tableau::dopri5();
        t.a[3][1] = Real::from_bits(t.a[3][1].to_bits() + 1);
        assert_eq!(Kernel::for_tableau(&t), Kernel::General);
        let mut t = Tableau::dop853();
        t.e3[8] = Real::from_bits(t.e3[8].to_bits() + 1);
        assert_eq!(Kernel::for_tableau(&t), Kernel::General);
    }
}

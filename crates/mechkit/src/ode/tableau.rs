//! Butcher tableaus as data, each citing its source, validated when built.
//!
//! A tableau gives the stages `k_i = f(t + c_i h, y + h Σ_j a_ij k_j)`, the solution
//! `y + h Σ b_i k_i`, and for embedded pairs the error estimate `h Σ e_i k_i` (with `e = b − b̂`,
//! the last entry multiplying `f(t + h, y_new)` for first-same-as-last pairs).

#![allow(clippy::excessive_precision)] // coefficients as published

use crate::Real;

/// How a method interpolates inside a step (its dense output).
#[derive(Debug, Clone, PartialEq)]
pub enum DenseKind {
    /// Cubic Hermite from the values and derivatives at both ends (3rd order).
    Hermite,
    /// `y(t + θh) = y + h Σ_i k_i Σ_j p_ij θ^(j+1)` (Dormand-Prince 5(4), Bogacki-Shampine).
    Polynomial(Vec<Vec<Real>>),
    /// DOP853's 7th-order interpolant with three extra stages (Hairer, Nørsett & Wanner).
    Dop853,
}

/// A Butcher tableau.
#[derive(Debug, Clone, PartialEq)]
pub struct Tableau {
    /// Name as in scenario files.
    pub name: &'static str,
    /// Where the coefficients come from.
    pub source: &'static str,
    /// Order of the solution.
    pub order: u32,
    /// Order of the embedded error estimator (`None` for fixed-step methods).
    pub error_order: Option<u32>,
    /// Nodes `c`.
    pub c: Vec<Real>,
    /// Coupling coefficients `a` (strictly lower triangular, row `i` has `i` entries).
    pub a: Vec<Vec<Real>>,
    /// Weights `b`.
    pub b: Vec<Real>,
    /// Error weights `e = b − b̂` (one more entry than stages when the last multiplies
    /// `f(t + h, y_new)`).
    pub e: Vec<Real>,
    /// DOP853 only: the third-order error weights used with `e` (Hairer's combined estimate).
    pub e3: Vec<Real>,
    /// Whether the last stage is evaluated at the new solution (first same as last).
    pub fsal: bool,
    /// Dense output.
    pub dense: DenseKind,
}

/// A tableau that violates a consistency condition.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("tableau {name}: {problem}")]
pub struct TableauError {
    /// Which tableau.
    pub name: String,
    /// What is wrong.
    pub problem: String,
}

fn r(n: f64, d: f64) -> Real {
    n / d
}

impl Tableau {
    /// Number of stages.
    pub fn stages(&self) -> usize {
        self.b.len()
    }

    /// Whether it has an error estimator (adaptive step size).
    pub fn is_adaptive(&self) -> bool {
        self.error_order.is_some()
    }

    /// Checks the shape, `Σ_j a_ij = c_i` and `Σ b_i = 1` (to 1e-13), and that the error
    /// weights sum to zero.
    pub fn validate(&self) -> Result<(), TableauError> {
        let err = |problem: String| {
            Err(TableauError {
                name: self.name.into(),
                problem,
            })
        };
        let s = self.stages();
        if self.c.len() != s || self.a.len() != s {
            return err(format!(
                "{s} weights but {} nodes and {} rows",
                self.c.len(),
                self.a.len()
            ));
        }
        for (i, row) in self.a.iter().enumerate() {
            if row.len() != i {
                return err(format!("row {i} of a has {} entries, not {i}", row.len()));
            }
            let sum: Real = row.iter().sum();
            if (sum - self.c[i]).abs() > 1e-13 {
                return err(format!(
                    "row {i} of a sums to {}, but c = {}",
                    crate::error::short(sum),
                    crate::error::short(self.c[i])
                ));
            }
        }
        let sb: Real = self.b.iter().sum();
        if (sb - 1.0).abs() > 1e-13 {
            return err(format!(
                "the weights sum to {}, not 1",
                crate::error::short(sb)
            ));
        }
        if self.is_adaptive() {
            let se: Real = self.e.iter().sum();
            if se.abs() > 1e-13 {
                return err(format!(
                    "the error weights sum to {}, not 0",
                    crate::error::short(se)
                ));
            }
        }
        Ok(())
    }

    /// The classical fourth-order Runge-Kutta method (Kutta, 1901).
    pub fn rk4() -> Tableau {
        Tableau {
            name: "rk4",
            source: "W. Kutta, Z. Math. Phys. 46, 435 (1901)",
            order: 4,
            error_order: None,
            c: vec![0.0, 0.5, 0.5, 1.0],
            a: vec![vec![], vec![0.5], vec![0.0, 0.5], vec![0.0, 0.0, 1.0]],
            b: vec![r(1., 6.), r(1., 3.), r(1., 3.), r(1., 6.)],
            e: vec![],
            e3: vec![],
            fsal: false,
            dense: DenseKind::Hermite,
        }
    }

    /// Heun's method (explicit trapezoid), 2nd order, with forward Euler embedded for the
    /// error (1st order).
    pub fn heun() -> Tableau {
        Tableau {
            name: "heun",
            source: "K. Heun, Z. Math. Phys. 45, 23 (1900); Hairer-Nørsett-Wanner I, Table II.1.1",
            order: 2,
            error_order: Some(1),
            c: vec![0.0, 1.0],
            a: vec![vec![], vec![1.0]],
            b: vec![0.5, 0.5],
            // b − b̂ with b̂ = (1, 0)
            e: vec![-0.5, 0.5],
            e3: vec![],
            fsal: false,
            dense: DenseKind::Hermite,
        }
    }

    /// Bogacki-Shampine 3(2), first same as last (P. Bogacki and L. F. Shampine, Appl. Math.
    /// Lett. 2, 321 (1989)); dense output by its cubic interpolant.
    pub fn bogacki_shampine() -> Tableau {
        Tableau {
            name: "bs3",
            source: "P. Bogacki, L. F. Shampine, Appl. Math. Lett. 2(4), 321-325 (1989)",
            order: 3,
            error_order: Some(2),
            c: vec![0.0, 0.5, 0.75],
            a: vec![vec![], vec![0.5], vec![0.0, 0.75]],
            b: vec![r(2., 9.), r(1., 3.), r(4., 9.)],
            e: vec![r(5., 72.), r(-1., 12.), r(-1., 9.), r(1., 8.)],
            e3: vec![],
            fsal: true,
            dense: DenseKind::Polynomial(vec![
                vec![1.0, r(-4., 3.), r(5., 9.)],
                vec![0.0, 1.0, r(-2., 3.)],
                vec![0.0, r(4., 3.), r(-8., 9.)],
                vec![0.0, -1.0, 1.0],
            ]),
        }
    }

    /// Dormand-Prince 5(4), first same as last (J. R. Dormand, P. J. Prince, J. Comput. Appl.
    /// Math. 6, 19 (1980)), with Shampine's 4th-order continuous extension (Math. Comp. 46,
    /// 135 (1986)).
    pub fn dopri5() -> Tableau {
        Tableau {
            name: "dopri5",
            source: "J. R. Dormand, P. J. Prince, J. Comput. Appl. Math. 6(1), 19-26 (1980); dense output: L. F. Shampine, Math. Comp. 46, 135-150 (1986)",
            order: 5,
            error_order: Some(4),
            c: vec![0.0, r(1., 5.), r(3., 10.), r(4., 5.), r(8., 9.), 1.0],
            a: vec![
                vec![],
                vec![r(1., 5.)],
                vec![r(3., 40.), r(9., 40.)],
                vec![r(44., 45.), r(-56., 15.), r(32., 9.)],
                vec![
                    r(19372., 6561.),
                    r(-25360., 2187.),
                    r(64448., 6561.),
                    r(-212., 729.),
                ],
                vec![
                    r(9017., 3168.),
                    r(-355., 33.),
                    r(46732., 5247.),
                    r(49., 176.),
                    r(-5103., 18656.),
                ],
            ],
            b: vec![
                r(35., 384.),
                0.0,
                r(500., 1113.),
                r(125., 192.),
                r(-2187., 6784.),
                r(11., 84.),
            ],
            e: vec![
                r(-71., 57600.),
                0.0,
                r(71., 16695.),
                r(-71., 1920.),
                r(17253., 339_200.),
                r(-22., 525.),
                r(1., 40.),
            ],
            e3: vec![],
            fsal: true,
            dense: DenseKind::Polynomial(vec![
                vec![
                    1.0,
                    r(-8_048_581_381., 2_820_520_608.),
                    r(8_663_915_743., 2_820_520_608.),
                    r(-12_715_105_075., 11_282_082_432.),
                ],
                vec![0.0, 0.0, 0.0, 0.0],
                vec![
                    0.0,
                    r(131_558_114_200., 32_700_410_799.),
                    r(-68_118_460_800., 10_900_136_933.),
                    r(87_487_479_700., 32_700_410_799.),
                ],
                vec![
                    0.0,
                    r(-1_754_552_775., 470_086_768.),
                    r(14_199_869_525., 1_410_260_304.),
                    r(-10_690_763_975., 1_880_347_072.),
                ],
                vec![
                    0.0,
                    r(127_303_824_393., 49_829_197_408.),
                    r(-318_862_633_887., 49_829_197_408.),
                    r(701_980_252_875., 199_316_789_632.),
                ],
                vec![
                    0.0,
                    r(-282_668_133., 205_662_961.),
                    r(2_019_193_451., 616_988_883.),
                    r(-1_453_857_185., 822_651_844.),
                ],
                vec![
                    0.0,
                    r(40_617_522., 29_380_423.),
                    r(-110_615_467., 29_380_423.),
                    r(69_997_945., 29_380_423.),
                ],
            ]),
        }
    }

    /// DOP853: Dormand-Prince 8(5,3) with a 7th-order dense output (E. Hairer, S. P. Nørsett,
    /// G. Wanner, *Solving Ordinary Differential Equations I*, 2nd ed., Springer 1993,
    /// Sec. II.10; coefficients of the Fortran code `dop853.f`).
    pub fn dop853() -> Tableau {
        let d = &super::dop853::DOP853;
        Tableau {
            name: "dop853",
            source: "E. Hairer, S. P. Nørsett, G. Wanner, Solving ODEs I (2nd ed., 1993), Sec. II.10, code dop853.f",
            order: 8,
            error_order: Some(7),
            c: d.c[..12].to_vec(),
            a: (0..12).map(|i| d.a[i][..i].to_vec()).collect(),
            b: d.a[12][..12].to_vec(),
            e: {
                let mut e = d.e5.to_vec();
                e.push(0.0);
                e
            },
            e3: {
                let mut e3: Vec<Real> = d.a[12][..12].to_vec();
                e3[0] -= 0.244_094_488_188_976_377_952_755_905_512;
                e3[8] -= 0.733_846_688_281_611_857_341_361_741_547;
                e3[11] -= 0.220_588_235_294_117_647_058_823_529_412e-1;
                e3.push(0.0);
                e3
            },
            fsal: true,
            dense: DenseKind::Dop853,
        }
    }

    /// Looks a tableau up by name.
    pub fn by_name(name: &str) -> Option<Tableau> {
        Some(match name {
            "rk4" => Tableau::rk4(),
            "heun" => Tableau::heun(),
            "bs3" | "bogacki-shampine" | "rk23" => Tableau::bogacki_shampine(),
            "dopri5" | "rk45" | "dormand-prince" => Tableau::dopri5(),
            "dop853" => Tableau::dop853(),
            _ => return None,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_tableau_is_consistent() {
        for t in [
            Tableau::rk4(),
            Tableau::heun(),
            Tableau::bogacki_shampine(),
            Tableau::dopri5(),
            Tableau::dop853(),
        ] {
            t.validate().unwrap_or_else(|e| panic!("{e}"));
        }
    }

    #[test]
    fn order_conditions_of_dopri5() {
        // Σ b c = 1/2, Σ b c² = 1/3, Σ b c³ = 1/4, Σ b c⁴ = 1/5
        let t = Tableau::dopri5();
        for (k, want) in [(1, 0.5), (2, 1.0 / 3.0), (3, 0.25), (4, 0.2)] {
            let s: Real = t.b.iter().zip(&t.c).map(|(b, c)| b * c.powi(k)).sum();
            assert!((s - want).abs() < 1e-14, "k = {k}: {s}");
        }
    }
}

//! The formatters of numbers shown to people: messages, summaries, `Display` of values
//! (`short_number`), and aligned columns with fixed decimals (`short_fixed`).

/// `x` with the shortest digits that read back as the same `f64`, in exponent form outside
/// `1e-4 ≤ |x| < 1e16`: `0.002`, `9.81`, `1e300`, `2.5e-7`, `-3e16`; `inf`, `-inf`, `NaN`.
///
/// Rust's `{}` of `1e300` is 301 digits; this is what every user-facing number goes through
/// instead (CSV and JSON keep their own exact formats).
///
/// ```
/// use mechkit_expr::short_number;
/// assert_eq!(short_number(1e300), "1e300");
/// assert_eq!(short_number(0.001), "0.001");
/// assert_eq!(short_number(-2.5e-7), "-2.5e-7");
/// assert_eq!(short_number(123456.5), "123456.5");
/// assert_eq!(short_number(1e16), "1e16");
/// assert_eq!(short_number(0.0), "0");
/// ```
pub fn short_number(x: f64) -> String {
    if x != 0.0 && x.is_finite() && !(1e-4..1e16).contains(&x.abs()) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

/// `x` with `decimals` digits after the point, as `{:.N}` writes it, but in exponent form
/// (`{:.Ne}`) from `1e16` up: a column of `3.1415927` stays aligned, and `1e120` is not 121
/// digits and seven zeros. Small magnitudes keep the fixed form (`0.000000`), which is short.
///
/// ```
/// use mechkit_expr::short_fixed;
/// assert_eq!(short_fixed(3.14159265, 3), "3.142");
/// assert_eq!(short_fixed(-2.5e120, 3), "-2.500e120");
/// assert_eq!(short_fixed(1e-300, 6), "0.000000");
/// assert_eq!(short_fixed(f64::INFINITY, 2), "inf");
/// ```
pub fn short_fixed(x: f64, decimals: usize) -> String {
    if x.is_finite() && x.abs() >= 1e16 {
        format!("{x:.decimals$e}")
    } else {
        format!("{x:.decimals$}")
    }
}

#[cfg(test)]
mod tests {
    use super::{short_fixed, short_number};

    #[test]
    fn every_finite_number_reads_back_and_stays_short() {
        for x in [
            1e300,
            -1e-300,
            5e-324,
            f64::MAX,
            f64::MIN_POSITIVE,
            1e-4,
            9.999e-5,
            1e16 - 2.0,
            0.1 + 0.2,
            -0.0,
        ] {
            let s = short_number(x);
            assert_eq!(s.parse::<f64>().unwrap().to_bits(), x.to_bits(), "{s}");
            assert!(s.len() <= 24, "{s}");
        }
        assert_eq!(short_number(f64::INFINITY), "inf");
        assert_eq!(short_number(f64::NAN), "NaN");
    }

    /// Fixed decimals of `1e308` were 309 digits and the decimals (`md`'s thermo rows).
    #[test]
    fn fixed_decimals_of_extreme_numbers_stay_short() {
        for x in [1e308, -1e120, f64::MAX, 1e16, 9.9e15, 1e-320, -0.0, 12.5] {
            for d in [0, 2, 7] {
                let s = short_fixed(x, d);
                assert!(s.len() <= 26, "{s}");
            }
        }
        assert_eq!(short_fixed(9.9e15, 1), "9900000000000000.0");
        assert_eq!(short_fixed(1e16, 1), "1.0e16");
    }
}

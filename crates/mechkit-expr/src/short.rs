//! The one formatter of numbers shown to people: messages, summaries, `Display` of values.

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

#[cfg(test)]
mod tests {
    use super::short_number;

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
}

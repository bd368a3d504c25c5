//! Logarithmic axes: the range, whole decades around the positive values, and the decades'
//! labels.

/// The range of a log axis showing the positive finite `values`: from the decade at or below
/// the smallest to the decade at or above the largest (at least one decade), so every label
/// is a power of ten. With no positive value, 1 to 10.
pub(super) fn log_range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| v.is_finite() && *v > 0.0)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
    if !lo.is_finite() {
        return (1.0, 10.0);
    }
    // a value a rounding error above a decade belongs to it
    let (a, mut b) = (
        (lo.log10() + 1e-9).floor() as i32,
        (hi.log10() - 1e-9).ceil() as i32,
    );
    if b <= a {
        b = a + 1;
    }
    // a hair wider, so that the end decades are inside whatever the rounding of 10^n
    (power(a) * (1.0 - 1e-9), power(b) * (1.0 + 1e-9))
}

/// 10^n, exactly where `f64` can say it.
fn power(n: i32) -> f64 {
    format!("1e{n}").parse().unwrap_or(f64::NAN)
}

/// The label of `v` on a log axis: a decade as `1e-6` (`0.01` … `1000` when `plain`), any
/// other value to three significant digits (`2e-6`, `0.05`).
pub(super) fn decade(v: f64, plain: bool) -> String {
    if !(v.is_finite() && v > 0.0) {
        return String::new();
    }
    let n = v.log10().round();
    let exact = ((v / power(n as i32)) - 1.0).abs() < 1e-6;
    if exact {
        let n = n as i32;
        if plain {
            return format!("{}", power(n));
        }
        return format!("1e{n}");
    }
    if plain {
        return super::tick(v, 1.0);
    }
    scientific(v)
}

/// `v` in scientific notation to three significant digits, trailing zeros dropped: `2.5e-7`,
/// `1.23e6`.
pub(crate) fn scientific(v: f64) -> String {
    let s = format!("{v:.2e}");
    match s.split_once('e') {
        Some((m, e)) => format!("{}e{e}", m.trim_end_matches('0').trim_end_matches('.')),
        None => s,
    }
}

#[cfg(test)]
mod tests {
    use super::{decade, log_range};

    #[test]
    fn a_log_range_spans_whole_decades_of_the_positive_values() {
        let (lo, hi) = log_range([0.0, -1.0, 2.5e-7, 3e-3, f64::NAN].into_iter());
        assert!((lo / 1e-7 - 1.0).abs() < 1e-6 && lo <= 1e-7, "{lo}");
        assert!((hi / 1e-2 - 1.0).abs() < 1e-6 && hi >= 1e-2, "{hi}");
        // a decade itself is the bottom, and one decade is the least
        let (lo, hi) = log_range([1e-3].into_iter());
        assert!(lo <= 1e-3 && (hi / 1e-2 - 1.0).abs() < 1e-6);
        assert_eq!(log_range([0.0, -2.0].into_iter()), (1.0, 10.0));
    }

    #[test]
    fn decades_are_labelled_as_powers_of_ten() {
        assert_eq!(decade(1e-6, false), "1e-6");
        assert_eq!(decade(1.000_000_000_000_1e-12, false), "1e-12");
        assert_eq!(decade(100.0, false), "1e2");
        assert_eq!(decade(100.0, true), "100");
        assert_eq!(decade(0.01, true), "0.01");
        assert_eq!(decade(2e-6, false), "2e-6");
        assert_eq!(decade(0.0, false), "");
    }
}

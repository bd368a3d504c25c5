//! Quadrature of samples against SciPy and against the rules on functions: the trapezoid rule
//! on a uniform table is the function rule, running integrals end at the integral, Simpson and
//! cumulative Simpson reproduce `scipy.integrate` (1.17.1) on an irregular grid with an even
//! and an odd number of intervals, and the edge cases (two samples, decreasing x, bad input).

use mechkit::quad::{
    Rule, SampleRule, SamplesError, cumtrapz, cumulative, integrate_rule, integrate_samples,
    simpson, trapz, trapz_uniform,
};

/// An irregular grid and values, written out so that no libm is involved.
const X: [f64; 9] = [0.0, 0.3, 0.7, 1.2, 1.5, 2.1, 2.6, 3.0, 3.2];
const Y: [f64; 9] = [1.0, 2.5, -0.5, 3.0, 4.25, 1.75, 0.0, 2.0, -1.0];

// python3 -c "import numpy as np; from scipy.integrate import simpson, cumulative_simpson;
//   x=np.array([0,0.3,0.7,1.2,1.5,2.1,2.6,3.0,3.2]); y=np.array([1.0,2.5,-0.5,3.0,4.25,1.75,0.0,2.0,-1.0]);
//   print([repr(v) for v in (simpson(y[:8],x=x[:8]), simpson(y,x=x), simpson(y[:8][::-1],x=x[:8][::-1]))]);
//   print(list(cumulative_simpson(y,x=x,initial=0))); print(list(cumulative_simpson(y[:8],x=x[:8],initial=0)))"
const SIMPSON_8: f64 = 5.500_370_370_370_372;
const SIMPSON_9: f64 = 6.101_111_111_111_112;
const SIMPSON_8_REVERSED: f64 = -4.925_357_142_857_143;
const CUMULATIVE_SIMPSON_9: [f64; 9] = [
    0.0,
    0.605_357_142_857_142_8,
    1.195_833_333_333_333,
    1.894_618_055_555_555_2,
    2.998_055_555_555_555_3,
    4.776_237_373_737_374,
    5.201_111_111_111_111,
    5.956_666_666_666_665,
    6.101_111_111_111_11,
];
const CUMULATIVE_SIMPSON_8_LAST: f64 = 5.500_370_370_370_37;

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-14 * b.abs().max(1.0)
}

#[test]
fn simpson_matches_scipy() {
    assert!(
        close(simpson(&X[..8], &Y[..8]), SIMPSON_8),
        "{}",
        simpson(&X[..8], &Y[..8])
    );
    assert!(close(simpson(&X, &Y), SIMPSON_9), "{}", simpson(&X, &Y));
    // with an odd number of intervals the pairs start at the first sample, so walking the
    // table backwards pairs other intervals: not the negated value (SciPy agrees)
    let (xr, yr): (Vec<f64>, Vec<f64>) = X[..8].iter().rev().zip(Y[..8].iter().rev()).unzip();
    assert!(
        close(simpson(&xr, &yr), SIMPSON_8_REVERSED),
        "{}",
        simpson(&xr, &yr)
    );
}

#[test]
fn cumulative_simpson_matches_scipy() {
    let c = cumulative(&X, &Y, SampleRule::Simpson).unwrap();
    for (k, (ours, scipy)) in c.iter().zip(CUMULATIVE_SIMPSON_9).enumerate() {
        assert!(close(*ours, scipy), "k = {k}: {ours} vs {scipy}");
    }
    let c = cumulative(&X[..8], &Y[..8], SampleRule::Simpson).unwrap();
    // up to the last pair the two tables pair the intervals alike
    for k in 0..7 {
        assert!(close(c[k], CUMULATIVE_SIMPSON_9[k]), "k = {k}: {}", c[k]);
    }
    assert!(close(c[7], CUMULATIVE_SIMPSON_8_LAST), "{}", c[7]);
    // the last value is the integral, here from the last three samples' parabola
    assert!(close(c[7], SIMPSON_8));
}

#[test]
fn trapezoid_on_a_table_is_the_function_rule() {
    let f = |x: f64| (3.0 * x).sin() + x * x;
    for n in [1, 2, 10, 1000] {
        let x: Vec<f64> = (0..=n).map(|i| 2.0 * f64::from(i) / f64::from(n)).collect();
        let y: Vec<f64> = x.iter().map(|&x| f(x)).collect();
        let by_rule = integrate_rule(f, 0.0, 2.0, Rule::Trapezoid, n as usize).unwrap();
        assert!(close(trapz(&x, &y), by_rule), "n = {n}");
        assert!(
            close(trapz_uniform(2.0 / f64::from(n), &y), by_rule),
            "n = {n}"
        );
        // the running integral ends at the integral (a running sum against a pairwise one)
        let c = cumtrapz(&x, &y);
        assert_eq!(c.len(), x.len());
        assert!(close(c[n as usize], trapz(&x, &y)), "n = {n}");
    }
}

#[test]
fn cumtrapz_ends_at_trapz_on_a_long_table() {
    let n = 100_000;
    let x: Vec<f64> = (0..n)
        .map(|i| (f64::from(i) / f64::from(n)).powf(1.5))
        .collect();
    let y: Vec<f64> = x.iter().map(|x| x.exp()).collect();
    let (c, t) = (cumtrapz(&x, &y), trapz(&x, &y));
    assert!(
        (c[n as usize - 1] - t).abs() < 1e-13,
        "{} vs {t}",
        c[n as usize - 1]
    );
}

#[test]
fn edge_cases() {
    // two samples: every rule that can apply is a single rectangle or trapezoid
    let (x, y) = ([0.0, 2.0], [1.0, 3.0]);
    assert_eq!(integrate_samples(&x, &y, SampleRule::Trapezoid), Ok(4.0));
    assert_eq!(integrate_samples(&x, &y, SampleRule::Simpson), Ok(4.0));
    assert_eq!(cumulative(&x, &y, SampleRule::Simpson), Ok(vec![0.0, 4.0]));
    assert_eq!(
        integrate_samples(&x, &y, SampleRule::Midpoint),
        Err(SamplesError::MidpointOddIntervals { intervals: 1 })
    );
    // decreasing x: the path walked backwards
    let (xr, yr) = ([2.0, 0.0], [3.0, 1.0]);
    assert_eq!(trapz(&xr, &yr), -4.0);
    assert_eq!(integrate_samples(&xr, &yr, SampleRule::Left), Ok(-6.0));
    assert_eq!(integrate_samples(&xr, &yr, SampleRule::Right), Ok(-2.0));
    // bad input
    assert_eq!(
        integrate_samples(&X, &Y[..8], SampleRule::Trapezoid),
        Err(SamplesError::LengthMismatch { x: 9, y: 8 })
    );
    assert_eq!(
        cumulative(&[], &[], SampleRule::Left),
        Err(SamplesError::TooFewSamples { n: 0 })
    );
}

#[test]
fn long_sums_are_the_same_bits_on_one_and_two_threads() {
    // 10^6 samples on a jittered grid: the halves are summed in parallel above 2^17 samples
    let n: usize = 1_000_003;
    let mut state = 0x9e37_79b9_7f4a_7c15_u64;
    let mut jitter = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    };
    let h = 1.0 / (n - 1) as f64;
    let x: Vec<f64> = (0..n).map(|i| (i as f64 + 0.4 * jitter()) * h).collect();
    let y: Vec<f64> = x.iter().map(|t| (3.0 * t).sin() + 0.1 * jitter()).collect();
    let on = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| [trapz(&x, &y), trapz_uniform(h, &y), simpson(&x, &y)])
    };
    let one = on(1);
    for threads in [2, 3] {
        assert_eq!(one.map(f64::to_bits), on(threads).map(f64::to_bits));
    }
    // and still the integral: ∫ sin 3t dt on [0, 1] plus noise averaging out
    assert!(
        (one[0] - (1.0 - 3f64.cos()) / 3.0).abs() < 1e-3,
        "{}",
        one[0]
    );
}

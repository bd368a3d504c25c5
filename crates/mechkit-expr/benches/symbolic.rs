//! The symbolic engine: antiderivatives (each verified by differentiating it back, as
//! `mechkit integrate` does) and derivatives, for the course's integrals and for the 40
//! slowest inputs the `calculus` fuzz target met in its corpus
//! (`benches/data/slow_integrals.txt`: fuzz-mutated products and towers of powers, each
//! taking up to 1.3 s in the fuzz build). The second group is the baseline for work on the
//! engine's speed (docs/benchmarks.md, "Symbolic engine").
//!
//! Run with `cargo bench -p mechkit-expr --bench symbolic`.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use mechkit_expr::Sym;

/// Integrals of the course: work of a spring and of a drag law, a Gaussian moment, a
/// potential's antiderivative by parts, partial fractions, an arc-tangent.
const COURSE: [&str; 8] = [
    "-k*(x - L0)",
    "x^2*exp(-x/a)",
    "x*sin(w*x)",
    "sin(x)^2",
    "1/(a + x^2)",
    "1/((x - 1)*(x + 2))",
    "F0*cos(w*x + phi)",
    "m*g*x*exp(-b*x)",
];

fn parsed(lines: impl Iterator<Item = &'static str>) -> Vec<Sym> {
    lines.filter_map(|l| Sym::parse(l).ok()).collect()
}

fn integrate_all(fs: &[Sym]) -> usize {
    fs.iter().filter(|f| f.integrate("x").is_some()).count()
}

fn differentiate_all(fs: &[Sym]) -> Vec<Sym> {
    fs.iter().map(|f| f.diff("x")).collect()
}

fn course(c: &mut Criterion) {
    let fs = parsed(COURSE.into_iter());
    assert_eq!(
        integrate_all(&fs),
        COURSE.len(),
        "every course integral has a closed form"
    );
    let mut group = c.benchmark_group("symbolic: course");
    group.bench_function("integrate 8", |b| b.iter(|| integrate_all(black_box(&fs))));
    group.bench_function("differentiate 8", |b| {
        b.iter(|| differentiate_all(black_box(&fs)));
    });
    group.finish();
}

/// The integrals issue 27 named as missing (each alone), then the whole table of course
/// integrals of `tests/data/integrals.tsv` (the time per integral is the total over its
/// length).
const ISSUE_27: [&str; 13] = [
    "sqrt(1 - x^2)",
    "sqrt(4 + x^2)",
    "exp(-x)*sin(x)",
    "exp(-a*x)*cos(w*x)",
    "sin(x)^3",
    "cos(x)^4",
    "1/cos(x)",
    "ln(x)^2",
    "x*atan(x)",
    "1/(1 + x^2)^2",
    "1/(c^2 - x^2)",
    "1/(1 + exp(x))",
    "sqrt(x^2 - 1)",
];

fn table(c: &mut Criterion) {
    let mut group = c.benchmark_group("symbolic: integral table");
    for src in ISSUE_27 {
        let f = Sym::parse(src).expect("parses");
        assert!(f.integrate("x").is_some(), "{src} has a closed form");
        group.bench_function(src, |b| b.iter(|| black_box(&f).integrate("x")));
    }
    let fs = parsed(
        include_str!("../tests/data/integrals.tsv")
            .lines()
            .filter(|l| !l.starts_with('#'))
            .filter_map(|l| l.split('\t').next()),
    );
    assert!(fs.len() >= 100, "the table parses: {}", fs.len());
    slowest_rows(&fs);
    group.bench_function(format!("integrate all {}", fs.len()), |b| {
        b.iter(|| integrate_all(black_box(&fs)));
    });
    group.finish();
}

/// Prints the five slowest integrals of the table, each the fastest of 20 runs (issue 27
/// asks for every course integral under 1 ms).
fn slowest_rows(fs: &[Sym]) {
    let mut times: Vec<(f64, String)> = fs
        .iter()
        .map(|f| {
            let best = (0..20)
                .map(|_| {
                    let start = std::time::Instant::now();
                    black_box(f.integrate("x"));
                    start.elapsed().as_secs_f64()
                })
                .fold(f64::INFINITY, f64::min);
            (best, f.to_string())
        })
        .collect();
    times.sort_by(|a, b| b.0.total_cmp(&a.0));
    for (t, f) in times.iter().take(5) {
        eprintln!("slowest of the table: {:8.1} µs  {f}", t * 1e6);
    }
}

fn slow_corpus(c: &mut Criterion) {
    let fs = parsed(include_str!("data/slow_integrals.txt").lines());
    assert!(fs.len() >= 30, "the slow inputs parse: {} of 40", fs.len());
    let mut group = c.benchmark_group("symbolic: slow fuzz inputs");
    group.sample_size(10);
    group.bench_function("integrate all", |b| {
        b.iter(|| integrate_all(black_box(&fs)));
    });
    group.bench_function("differentiate all", |b| {
        b.iter(|| differentiate_all(black_box(&fs)));
    });
    group.finish();
}

criterion_group!(benches, course, table, slow_corpus);
criterion_main!(benches);

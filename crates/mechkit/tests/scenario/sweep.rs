//! Parameter sweeps: a constant overridden is re-resolved everywhere it is used (a ball thrown
//! up at v0 rises to v0²/2g and lands at 2v0/g, exact for constant acceleration); 1,000 runs
//! give 1,000 rows in index order; the table does not depend on the thread count; shards
//! merged equal the unsharded table byte for byte; a diverging run is a row, not an abort.

use mechkit::scenario::sweep::{
    Parameter, Sampling, Shard, SweepError, SweepGrid, SweepOptions, SweepPart, merge_parts,
    run_sweep,
};

/// A ball thrown up at `vup = 2*v0/2` (a constant of a constant, so the override must
/// re-resolve it) under g = 10 m/s², velocity Verlet with 10 ms steps, landing located.
const THROW: &str = r#"
[constants]
g = "10 m/s^2"
v0 = "1 m/s"
vup = "2*v0/2"
[[body]]
name = "ball"
mass = "1 kg"
velocity = "vup"
[[force]]
name = "gravity"
kind = "uniform-gravity"
g = "g"
[integrator]
method = "verlet"
dt = "10 ms"
[stop]
when = "x < 0"
t_max = "10 s"
[observe]
t_land = "final(t)"
x_max = "max(x)"
[output]
plots = ["v(x)"]
"#;

fn grid(sets: &[&str], sampling: Sampling) -> SweepGrid {
    SweepGrid::new(
        sets.iter().map(|s| Parameter::parse(s).unwrap()).collect(),
        sampling,
    )
}

fn run(
    sets: &[&str],
    options: &SweepOptions,
) -> Result<mechkit::scenario::sweep::SweepTable, SweepError> {
    run_sweep(
        "throw.toml",
        THROW,
        &grid(sets, Sampling::Grid),
        options,
        &|| {},
    )
}

#[test]
fn thousand_runs_give_thousand_rows_with_their_values_and_exact_landings() {
    let table = run(&["v0=1 m/s:10 m/s:1000"], &SweepOptions::default()).unwrap();
    assert_eq!(table.rows.len(), 1000);
    let csv = table.to_csv();
    assert_eq!(csv.lines().count(), 1 + 1000, "header, 1,000 rows");
    assert_eq!(
        csv.lines().next().unwrap(),
        "index,v0,stop_reason,t_end,steps,t_land,x_max,K_end,U_end,E_end,work_energy_residual"
    );
    let mut worst = 0.0_f64;
    for (i, r) in table.rows.iter().enumerate() {
        assert_eq!(r.index, i);
        let v0 = 1.0 + 9.0 * i as f64 / 999.0;
        assert!((r.values[0] - v0).abs() < 1e-12, "run {i}: {}", r.values[0]);
        assert_eq!(r.stop_reason, "event");
        // Verlet and the cubic Hermite location are exact for constant acceleration: the
        // landing time is 2 v0/g to rounding (measured worst 4.9e-15 s)
        worst = worst.max((r.t_end - 2.0 * v0 / 10.0).abs());
        // the highest sample lies within g dt²/8 of the apex v0²/2g
        let apex = v0 * v0 / 20.0;
        assert!(r.observables[1] <= apex + 1e-12 && r.observables[1] > apex - 10.0 * 1e-4 / 8.0);
    }
    eprintln!("worst landing time error {worst:e} s");
    assert!(worst < 1e-12, "landing time error {worst:e} s");
}

#[test]
fn table_does_not_depend_on_the_thread_count() {
    let sets = ["v0=1:5:40", "g=9,10,11"];
    let on = |threads| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| run(&sets, &SweepOptions::default()).unwrap().to_csv())
    };
    let one = on(1);
    assert_eq!(one.lines().count(), 1 + 120);
    assert_eq!(one, on(2));
    assert_eq!(one, on(4));
}

#[test]
fn shards_merged_equal_the_unsharded_table_byte_for_byte() {
    let sets = ["v0=1:5:100"];
    let whole = run(&sets, &SweepOptions::default()).unwrap();
    let mut parts = Vec::new();
    for k in [2, 3, 1] {
        let shard = Shard { k, n: 3 };
        let part = run(
            &sets,
            &SweepOptions {
                shard: Some(shard),
                ..Default::default()
            },
        )
        .unwrap();
        assert_eq!(part.file_name(), format!("sweep.part{k}.csv"));
        assert!(part.rows.iter().all(|r| r.index % 3 == k - 1));
        assert_eq!(
            part.manifest_file_name(),
            format!("sweep.part{k}.manifest.json")
        );
        parts.push(SweepPart {
            name: part.file_name(),
            csv: part.to_csv(),
            manifest: part.manifest_json(),
        });
    }
    assert_eq!(
        merge_parts(&parts).unwrap(),
        (whole.to_csv(), whole.manifest_json())
    );

    // a missing part is named by its runs
    let err = merge_parts(&parts[..2]).unwrap_err().to_string();
    assert!(err.contains("34 of 100 runs are missing: 0, 3, 6"), "{err}");
    // a part given twice
    let twice = [parts.clone(), vec![parts[0].clone()]].concat();
    let err = merge_parts(&twice).unwrap_err().to_string();
    assert!(err.contains("runs given twice"), "{err}");
    // a part of another sweep
    let other = run(
        &["v0=1:5:99"],
        &SweepOptions {
            shard: Some(Shard { k: 1, n: 3 }),
            ..Default::default()
        },
    )
    .unwrap();
    let mixed = vec![
        parts[0].clone(),
        SweepPart {
            name: "other.csv".into(),
            csv: other.to_csv(),
            manifest: other.manifest_json(),
        },
    ];
    let err = merge_parts(&mixed).unwrap_err();
    assert!(matches!(err, SweepError::Mismatch { .. }), "{err}");
    assert!(err.to_string().contains("other.csv"), "{err}");
}

#[test]
fn grid_order_has_the_last_parameter_fastest() {
    let table = run(&["v0=1,2", "g=9,10,11"], &SweepOptions::default()).unwrap();
    let points: Vec<Vec<f64>> = table.rows.iter().map(|r| r.values.clone()).collect();
    assert_eq!(
        points,
        [
            [1., 9.],
            [1., 10.],
            [1., 11.],
            [2., 9.],
            [2., 10.],
            [2., 11.]
        ]
    );
    // g is re-read for the force too: the landing time is 2 v0/g
    for r in &table.rows {
        assert!((r.t_end - 2.0 * r.values[0] / r.values[1]).abs() < 1e-12);
    }
}

#[test]
fn random_points_are_seeded_inside_the_ranges_and_the_same_in_shards() {
    let g = grid(
        &["v0=1 m/s:5 m/s:2", "g=9,10"],
        Sampling::Random { n: 200, seed: 7 },
    );
    assert_eq!(g.len(), 200);
    let pts: Vec<Vec<f64>> = (0..200).map(|i| g.point(i)).collect();
    assert!(
        pts.iter()
            .all(|p| (1.0..=5.0).contains(&p[0]) && (p[1] == 9.0 || p[1] == 10.0))
    );
    let mean = pts.iter().map(|p| p[0]).sum::<f64>() / 200.0;
    assert!((mean - 3.0).abs() < 0.25, "mean {mean}");
    assert!(pts.iter().any(|p| p[1] == 9.0) && pts.iter().any(|p| p[1] == 10.0));
    assert_eq!(pts, (0..200).map(|i| g.point(i)).collect::<Vec<_>>());
    let other = grid(
        &["v0=1 m/s:5 m/s:2", "g=9,10"],
        Sampling::Random { n: 200, seed: 8 },
    );
    assert_ne!(pts[0], other.point(0));
}

#[test]
fn a_diverging_run_is_a_row_not_an_abort() {
    // explicit Euler on a spring grows by sqrt(1 + (ω dt)²) per step: with k = 1e6 N/m it
    // overflows long before t_max; with k = 1 N/m it runs to the end
    let text = r#"
[constants]
k = "1 N/m"
[[body]]
mass = "1 kg"
position = "1 m"
[[force]]
name = "spring"
kind = "expression"
F = "-k*x"
[integrator]
method = "euler"
dt = "1 ms"
[stop]
t_max = "10 s"
"#;
    let g = grid(&["k=1,1e6"], Sampling::Grid);
    let t = run_sweep("spring.toml", text, &g, &SweepOptions::default(), &|| {}).unwrap();
    assert_eq!(t.rows[0].stop_reason, "t_max");
    assert_eq!(t.rows[1].stop_reason, "diverged");
}

#[test]
fn overlay_has_one_curve_per_run_and_a_thinned_legend() {
    let table = run(
        &["v0=1:5:25"],
        &SweepOptions {
            plot: Some(String::new()),
            ..Default::default()
        },
    )
    .unwrap();
    let plot = table.overlay(10).unwrap();
    assert_eq!(plot.series.len(), 25);
    let labelled: Vec<&str> = plot
        .series
        .iter()
        .map(|s| s.label.as_str())
        .filter(|l| !l.is_empty())
        .collect();
    assert!(labelled.len() <= 10, "{labelled:?}");
    assert_eq!(labelled[0], "v0 = 1");
    assert_eq!(*labelled.last().unwrap(), "v0 = 5");
    // each curve starts at x = 0 with v = v0
    assert_eq!(plot.series[24].points[0], (0.0, 5.0));
}

#[test]
fn bad_parameters_are_clear_errors() {
    let err = |sets: &[&str]| {
        let params: Result<Vec<_>, _> = sets.iter().map(|s| Parameter::parse(s)).collect();
        match params {
            Err(e) => e.to_string(),
            Ok(p) => run_sweep(
                "throw.toml",
                THROW,
                &SweepGrid::new(p, Sampling::Grid),
                &SweepOptions::default(),
                &|| {},
            )
            .unwrap_err()
            .to_string(),
        }
    };
    let e = err(&["vo=1:2:3"]);
    assert!(
        e.contains("`vo` (in --set) is not a constant") && e.contains("did you mean `v0`"),
        "{e}"
    );
    assert!(e.contains("g, v0, vup"), "{e}");
    let e = err(&["v0=1 kg:2 kg:3"]);
    assert!(e.contains("kg (mass)") && e.contains("velocity"), "{e}");
    let e = err(&["v0=1:2"]);
    assert!(e.contains("START:END:COUNT"), "{e}");
    let e = err(&["v0=1:2:x"]);
    assert!(e.contains("not a whole number"), "{e}");
    let e = err(&["v0=1 m/s:2:5"]);
    assert!(e.contains("same units"), "{e}");
    let e = err(&["v0 1"]);
    assert!(e.contains("no `=`"), "{e}");
    let e = err(&["v0=1 mps"]);
    assert!(e.contains("mps"), "{e}");
    let e = err(&["v0=1", "v0=2"]);
    assert!(e.contains("gives `v0` twice"), "{e}");
    let e = err(&[]);
    assert!(e.contains("at least one --set"), "{e}");
    let e = run(
        &["v0=1"],
        &SweepOptions {
            plot: Some("w(x)".into()),
            ..Default::default()
        },
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("--plot") && e.contains("`w`"), "{e}");
}

/// Found while writing the `options` fuzz target: a range of 10^11 points asked for 800 GB at
/// once (the process aborted), and three large ranges overflowed the count of runs (a panic
/// in a debug build, a wrong count in a release build). Both are refused with the limit now.
#[test]
fn fuzz_huge_sweeps_are_refused_not_allocated() {
    use mechkit::scenario::sweep::{MAX_RUNS, Parameter, Sampling, SweepGrid};
    let err = Parameter::parse("v0=0:5:100000000000")
        .unwrap_err()
        .to_string();
    assert!(err.contains("more than a sweep runs"), "{err}");
    let big = |name: &str| Parameter::parse(&format!("{name}=0:1:100000")).unwrap();
    // 10^20 runs: past what a usize counts
    let grid = SweepGrid::new(vec![big("a"), big("b"), big("c"), big("d")], Sampling::Grid);
    assert_eq!(grid.len(), usize::MAX, "the count saturates");
    let err = grid.check().unwrap_err().to_string();
    assert!(err.contains("more than 10^19 runs"), "{err}");
    let random = SweepGrid::new(
        vec![big("a")],
        Sampling::Random {
            n: MAX_RUNS + 1,
            seed: 1,
        },
    );
    assert!(random.check().is_err());
    let largest = Parameter::parse(&format!("a=0:1:{MAX_RUNS}")).unwrap();
    assert!(
        SweepGrid::new(vec![largest], Sampling::Grid)
            .check()
            .is_ok()
    );
}

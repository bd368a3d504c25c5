//! A sweep spread over processes: each shard's table carried as bytes
//! (`SweepTable::to_bytes`) and merged in memory (`merge_tables`) equals the unsharded sweep,
//! byte for byte in `sweep.csv` and bit for bit in every number, NaN included, and draws the
//! same overlay; parts that do not make one sweep are refused as `mechkit sweep-merge`
//! refuses them.

use mechkit::scenario::sweep::{
    Parameter, Sampling, Shard, SweepError, SweepGrid, SweepOptions, SweepTable, merge_tables,
    run_sweep,
};

/// A ball thrown up at v0 into quadratic drag, its highest point and landing observed, and
/// an observable that is NaN (the final speed of a body that never moved sideways, divided
/// by itself).
const THROW: &str = r#"
[constants]
g = "9.8 m/s^2"
v0 = "1 m/s"
k = "0.1 1/m"
[[body]]
name = "ball"
mass = "1 kg"
velocity = "v0"
[[force]]
name = "gravity"
kind = "uniform-gravity"
g = "g"
[[force]]
name = "air"
kind = "expression"
on = "ball"
F = "-m*k*v*abs(v)"
[integrator]
method = "rk4"
dt = "7 ms"
[stop]
when = "x < 0"
t_max = "10 s"
[observe]
x_max = "max(x)"
nan = "final(t)*0/0"
[output]
plots = ["v(x)"]
"#;

fn sweep(sets: &[&str], sampling: Sampling, shard: Option<Shard>) -> SweepTable {
    let grid = SweepGrid::new(
        sets.iter().map(|s| Parameter::parse(s).unwrap()).collect(),
        sampling,
    );
    let options = SweepOptions {
        shard,
        plot: Some(String::new()),
        ..Default::default()
    };
    run_sweep("throw.toml", THROW, &grid, &options, &|| {}).unwrap()
}

/// The shards of a sweep of `n` parts, each carried as bytes and read back.
fn parts(sets: &[&str], sampling: Sampling, n: usize) -> Vec<SweepTable> {
    (1..=n)
        .rev()
        .map(|k| {
            let part = sweep(sets, sampling, Some(Shard { k, n }));
            SweepTable::from_bytes(&part.to_bytes()).unwrap()
        })
        .collect()
}

fn bits(t: &SweepTable) -> Vec<Vec<u64>> {
    t.rows
        .iter()
        .map(|r| {
            let mut v: Vec<f64> = r.values.clone();
            v.extend([r.t_end, r.kinetic_end, r.energy_end, r.work_energy_residual]);
            v.extend(&r.observables);
            v.extend(r.potential_end);
            v.iter().map(|x| x.to_bits()).collect()
        })
        .collect()
}

#[test]
fn shards_carried_as_bytes_and_merged_equal_the_whole_sweep() {
    let sets = ["v0=0.5:9:23", "k=0,0.1"];
    let whole = sweep(&sets, Sampling::Grid, None);
    let merged = merge_tables(parts(&sets, Sampling::Grid, 5)).unwrap();
    assert_eq!(merged.to_csv(), whole.to_csv());
    assert_eq!(merged.manifest_json(), whole.manifest_json());
    assert_eq!(bits(&merged), bits(&whole));
    assert!(whole.rows[3].observables[1].is_nan());
    assert_eq!(merged.overlay(10), whole.overlay(10));
    assert_eq!(
        (merged.rows.len(), merged.runs, merged.shard),
        (46, 46, None)
    );

    // a random sample, in shards of one run and of none
    let random = Sampling::Random { n: 3, seed: 7 };
    let whole = sweep(&sets, random, None);
    let merged = merge_tables(parts(&sets, random, 4)).unwrap();
    assert_eq!(merged.to_csv(), whole.to_csv());
    assert_eq!(bits(&merged), bits(&whole));
}

#[test]
fn parts_that_do_not_make_one_sweep_are_refused() {
    let sets = ["v0=1:5:10"];
    let mut three = parts(&sets, Sampling::Grid, 3);
    let err = merge_tables(three[1..].to_vec()).unwrap_err().to_string();
    assert!(err.contains("3 of 10 runs are missing: 2, 5, 8"), "{err}");
    let twice = [three.clone(), vec![three[0].clone()]].concat();
    let err = merge_tables(twice).unwrap_err().to_string();
    assert!(
        err.contains("run 2 is in sweep.part3.csv and sweep.part3.csv"),
        "{err}"
    );
    three[2] = sweep(&["v0=1:5:11"], Sampling::Grid, Some(Shard { k: 1, n: 3 }));
    let err = merge_tables(three).unwrap_err();
    assert!(matches!(err, SweepError::Mismatch { .. }), "{err}");
    let err = merge_tables(Vec::new()).unwrap_err().to_string();
    assert!(err.contains("no parts to merge"), "{err}");
}

#[test]
fn a_part_cut_short_is_damaged() {
    let bytes = sweep(&["v0=1,2"], Sampling::Grid, None).to_bytes();
    for cut in [bytes.len() - 1, bytes.len() / 2, 30] {
        let err = SweepTable::from_bytes(&bytes[..cut])
            .unwrap_err()
            .to_string();
        assert!(err.contains("the sweep's part is damaged"), "{err}");
    }
    let mut longer = bytes.clone();
    longer.push(0);
    let err = SweepTable::from_bytes(&longer).unwrap_err().to_string();
    assert!(err.contains("bytes after the last row"), "{err}");
}

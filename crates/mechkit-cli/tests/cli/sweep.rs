//! `mechkit sweep` and `mechkit sweep-merge`: a 1,000-run sweep writes 1,000 rows with the
//! grid's values; the table is the same on 1 and 2 threads; shards 1/3, 2/3, 3/3 merged equal
//! the unsharded table byte for byte; the overlay plot; bad --set, --shard, --threads and
//! incomplete merges exit 2 with the flag named.

use crate::util::{Dir, at, examples, num};

/// A ball thrown up at v0 under g = 10 m/s², 5 Verlet steps of 10 ms at most per run.
const THROW: &str = r#"
[constants]
g = "10 m/s^2"
v0 = "1 m/s"
[[body]]
name = "ball"
mass = "1 kg"
velocity = "v0"
[[force]]
name = "gravity"
kind = "uniform-gravity"
g = "g"
[integrator]
method = "verlet"
dt = "10 ms"
[stop]
when = "x < 0"
t_max = "1 s"
[observe]
x_max = "max(x)"
[output]
plots = ["v(x)"]
"#;

#[test]
fn thousand_runs_give_thousand_rows_and_do_not_depend_on_threads() {
    let dir = Dir::new();
    dir.create("throw.toml", THROW);
    let mut csv = Vec::new();
    for threads in ["1", "2"] {
        let out = format!("t{threads}");
        let j = dir
            .run(&[
                "sweep",
                "throw.toml",
                "--set",
                "v0=0.1:2:1000",
                "--threads",
                threads,
                "--no-plots",
                "--out",
                &out,
                "--json",
            ])
            .json();
        assert_eq!(num(&j, "/rows"), 1000.0);
        assert_eq!(num(&j, "/threads"), threads.parse::<f64>().unwrap());
        assert!(num(&j, "/runs_per_second") > 0.0);
        csv.push(dir.read(&format!("{out}/sweep.csv")));
    }
    assert_eq!(csv[0], csv[1], "1 and 2 threads give the same table");
    let lines: Vec<&str> = csv[0].lines().collect();
    assert_eq!(
        lines.len(),
        1 + 1000,
        "a plain CSV: the header, then the rows"
    );
    assert_eq!(
        lines[0],
        "index,v0,stop_reason,t_end,steps,x_max,K_end,U_end,E_end,work_energy_residual"
    );
    // the sweep's identity is in the manifest beside it
    let manifest = dir.read_json("t1/sweep.manifest.json");
    let sweep = at(&manifest, "/sweep").as_str().unwrap();
    assert!(sweep.starts_with("mechkit sweep of throw.toml"), "{sweep}");
    assert!(sweep.ends_with("; 1000 runs"), "{sweep}");
    assert_eq!(num(&manifest, "/runs"), 1000.0);
    assert!(at(&manifest, "/shard").is_null());
    for (i, line) in lines[1..].iter().enumerate() {
        let cells: Vec<&str> = line.split(',').collect();
        assert_eq!(cells[0], i.to_string());
        let v0: f64 = cells[1].parse().unwrap();
        assert!((v0 - (0.1 + 1.9 * i as f64 / 999.0)).abs() < 1e-12);
        // the landing is located exactly at 2 v0/g (constant acceleration)
        let t_end: f64 = cells[3].parse().unwrap();
        assert!((t_end - v0 / 5.0).abs() < 1e-12, "row {i}: {line}");
    }
}

#[test]
fn shards_merged_equal_the_unsharded_sweep() {
    let dir = Dir::new();
    dir.create("throw.toml", THROW);
    let sets = ["--set", "v0=1,2,3", "--set", "g=9:11:20"];
    let run = |extra: &[&str]| {
        let mut args = vec!["sweep", "throw.toml"];
        args.extend_from_slice(&sets);
        args.extend_from_slice(extra);
        dir.run(&args).assert_code(0);
    };
    run(&["--out", "whole", "-q"]);
    for k in ["3/3", "1/3", "2/3"] {
        run(&["--out", "parts", "--shard", k, "--no-plots"]);
    }
    let whole = dir.read("whole/sweep.csv");
    assert_eq!(whole.lines().count(), 1 + 60);
    let part = dir.read("parts/sweep.part2.csv");
    assert_eq!(part.lines().count(), 1 + 20);
    let part_manifest = dir.read_json("parts/sweep.part2.manifest.json");
    assert_eq!(
        (
            num(&part_manifest, "/shard/k"),
            num(&part_manifest, "/shard/n")
        ),
        (2.0, 3.0)
    );

    let j = dir.run(&["sweep-merge", "parts", "--json"]).json();
    assert_eq!(num(&j, "/rows"), 60.0);
    assert_eq!(
        dir.read("parts/sweep.csv"),
        whole,
        "merged == unsharded, byte for byte"
    );
    assert_eq!(
        dir.read("parts/sweep.manifest.json"),
        dir.read("whole/sweep.manifest.json"),
        "and so is its manifest"
    );
    // the overlay of the whole sweep has a curve per run
    let svg = dir.read("whole/sweep_v_x.svg");
    assert!(svg.contains("v0 = 1, g = 9"), "legend");

    // a missing part is an error naming the missing runs
    std::fs::remove_file(dir.path().join("parts/sweep.part1.csv")).unwrap();
    dir.run(&[
        "sweep-merge",
        "parts/sweep.part2.csv",
        "parts/sweep.part3.csv",
        "--out",
        "m.csv",
    ])
    .assert_bad_input(&["20 of 60 runs are missing: 0, 3, 6", "shard"]);
}

#[test]
fn the_example_sweep_runs() {
    let dir = Dir::new();
    let file = examples().join("sweep/throw.toml");
    let out = dir.run(&[
        "sweep",
        file.to_str().unwrap(),
        "--set",
        "v0=0 km/h:18 km/h:6",
        "--out",
        "o",
    ]);
    out.assert_code(0);
    assert!(out.stdout.contains("6 runs"), "{}", out.stdout);
    let csv = dir.read("o/sweep.csv");
    assert!(
        csv.lines().nth(6).unwrap().starts_with("5,5,event,"),
        "{csv}"
    );
    assert!(dir.path().join("o/sweep_v_x.svg").exists());
}

#[test]
fn bad_input_exits_2_naming_the_flag() {
    let dir = Dir::new();
    dir.create("throw.toml", THROW);
    let bad = |args: &[&str], needles: &[&str]| {
        dir.run_with(&["sweep", "throw.toml"], args)
            .assert_bad_input(needles);
    };
    bad(
        &["--set", "v0=1:2"],
        &["--set \"v0=1:2\"", "START:END:COUNT"],
    );
    bad(
        &["--set", "vo=1,2"],
        &["`vo` (in --set) is not a constant", "did you mean `v0`"],
    );
    bad(&["--set", "v0=1 kg,2 kg"], &["kg (mass)", "velocity"]);
    bad(
        &["--set", "v0=1,2", "--shard", "4/3"],
        &["--shard \"4/3\"", "between 1 and N"],
    );
    bad(
        &["--set", "v0=1,2", "--threads", "0"],
        &["--threads must be at least 1"],
    );
    bad(&["--set", "v0=1,2", "--plot", "w(x)"], &["--plot", "`w`"]);
    dir.run(&["sweep", "missing.toml", "--set", "v0=1"])
        .assert_bad_input(&["cannot read missing.toml"]);
    dir.run(&["sweep-merge", "."])
        .assert_bad_input(&["holds no sweep.partK.csv files"]);
}

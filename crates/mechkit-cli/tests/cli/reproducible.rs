//! The same scenario gives the same bytes: run twice, on 1 or 2 threads, with native code or
//! the interpreter, fused or not; and the summary says where it came from (provenance).

use super::util::{Dir, at, examples};

/// Runs `file` into `out` with `env` and returns (trajectory.csv, summary.json) as text.
fn outputs(dir: &Dir, file: &str, out: &str, env: &[(&str, &str)]) -> (String, serde_json::Value) {
    dir.run_with_env(&["run", file, "--out", out, "--no-plots"], env)
        .assert_code(0);
    (
        dir.read(&format!("{out}/trajectory.csv")),
        dir.read_json(&format!("{out}/summary.json")),
    )
}

#[test]
fn the_same_scenario_gives_the_same_bytes_however_it_is_run() {
    let dir = Dir::new();
    // a long fixed-step run (fused) and an adaptive run with events
    let workload = examples().join("../bench/workloads/feather_1e7.toml");
    let long = dir.create(
        "long.toml",
        &std::fs::read_to_string(workload)
            .unwrap()
            .replace("t_max = \"10 s\"", "t_max = \"0.5 s\""),
    );
    let long = long.to_str().unwrap();
    let bounce = examples().join("bouncing_ball.toml");
    let bounce = bounce.to_str().unwrap();
    for file in [long, bounce] {
        let (csv, summary) = outputs(&dir, file, "a", &[]);
        let runs = [
            outputs(&dir, file, "b", &[]),
            outputs(&dir, file, "c", &[("RAYON_NUM_THREADS", "1")]),
            outputs(&dir, file, "d", &[("RAYON_NUM_THREADS", "2")]),
            outputs(&dir, file, "e", &[("MECHKIT_JIT", "0")]),
            outputs(&dir, file, "f", &[("MECHKIT_FUSE", "0")]),
        ];
        for (i, (other_csv, other)) in runs.iter().enumerate() {
            assert!(csv == *other_csv, "{file}: trajectory of run {i} differs");
            for key in [
                "/bodies",
                "/work",
                "/t_end",
                "/steps",
                "/energy",
                "/momentum",
            ] {
                assert_eq!(at(&summary, key), at(other, key), "{file} run {i}: {key}");
            }
        }
        let p = at(&summary, "/provenance");
        assert_eq!(at(p, "/mechkit"), env!("CARGO_PKG_VERSION"));
        assert_eq!(at(p, "/scenario_fnv1a").as_str().unwrap().len(), 16);
        assert_eq!(at(p, "/threads"), 1);
        assert!(at(p, "/seed").is_null());
        assert_eq!(at(&runs[3].1, "/provenance/native_code"), false);
    }
    // the long run was fused by default and not with MECHKIT_FUSE=0
    let (_, fused) = outputs(&dir, long, "g", &[]);
    let (_, general) = outputs(&dir, long, "h", &[("MECHKIT_FUSE", "0")]);
    assert!(at(&fused, "/step_control/fused_steps").as_u64().unwrap() > 0);
    assert_eq!(at(&general, "/step_control/fused_steps"), 0);
}

//! `mechkit md` on the small gallery inputs of `examples/md/`, read with `--positions`:
//! - two LJ atoms released at rest from r = 1.5σ turn where U(r) = E: the outer turning
//!   point is the release point, the inner one the root of U(r) = U(1.5σ) in the well;
//! - a periodic ring of 16 springs started in its lowest longitudinal mode oscillates at
//!   ω = 2 √(k/m) sin(π/N) (the ring's normal modes ω_q = 2 √(k/m) |sin(πq/N)|): a
//!   quarter period later every atom is at its lattice site moving at −ω u_i(0), half a
//!   period later at −u_i(0), a period later back at u_i(0);
//! - bad particle files and flags name the flag and the line.

use crate::util::{Dir, example};

/// The frames of an extended-XYZ file: per frame, per atom, `[x, y, z, vx, vy, vz]`.
fn frames(text: &str) -> Vec<Vec<[f64; 6]>> {
    let mut lines = text.lines();
    let mut out = Vec::new();
    while let Some(count) = lines.next() {
        let n: usize = count.trim().parse().expect("atom count");
        lines.next().expect("comment line");
        let atoms = (0..n)
            .map(|_| {
                let f: Vec<f64> = lines
                    .next()
                    .expect("atom line")
                    .split_whitespace()
                    .skip(1)
                    .map(|v| v.parse().expect("number"))
                    .collect();
                std::array::from_fn(|k| f[k])
            })
            .collect();
        out.push(atoms);
    }
    out
}

#[test]
fn lj_pair_turns_where_u_equals_e() {
    let dir = Dir::new();
    let pair = example("md/lj_pair.csv");
    let out = dir
        .run(&[
            "md",
            "--positions",
            &pair,
            "--boundary",
            "open",
            "--potential",
            "lj",
            "--dt",
            "1e-4",
            "--steps",
            "40000",
            "--thermo-every",
            "1000",
            "--xyz-every",
            "5",
            "--out",
            "out",
            "--json",
        ])
        .json();
    let u = |r: f64| 4.0 * (r.powi(-12) - r.powi(-6));
    let e = u(1.5);
    let (mut lo, mut hi) = (0.9, 2f64.powf(1.0 / 6.0));
    while hi - lo > 1e-14 {
        let mid = 0.5 * (lo + hi);
        if u(mid) > e { lo = mid } else { hi = mid }
    }
    let inner = 0.5 * (lo + hi);
    let r: Vec<f64> = frames(&dir.read("out/trajectory.xyz"))
        .iter()
        .map(|f| ((0..3).map(|k| (f[1][k] - f[0][k]).powi(2)).sum::<f64>()).sqrt())
        .collect();
    let r_min = r.iter().copied().fold(f64::INFINITY, f64::min);
    // The second outer turn, after the first inner one.
    let r_max_later = r[r.len() / 3..].iter().copied().fold(0.0, f64::max);
    // Sampled every 5 steps (5e-4 τ): the turning points are missed by at most ~3e-6 σ.
    assert!((r_min - inner).abs() < 2e-5, "r_min {r_min} vs {inner}");
    assert!((r_max_later - 1.5).abs() < 2e-5, "r_max {r_max_later}");
    let total: Vec<f64> = out["thermo"]
        .as_array()
        .unwrap()
        .iter()
        .map(|t| t["total_per_atom"].as_f64().unwrap())
        .collect();
    assert!((total[0] - e / 2.0).abs() < 1e-15);
    assert!(total.iter().all(|t| (t - total[0]).abs() < 1e-6));
}

#[test]
fn spring_chain_lowest_mode_has_the_ring_frequency() {
    let dir = Dir::new();
    let chain = example("md/spring_chain.csv");
    let (n, k, m, a) = (16.0f64, 1.0f64, 1.0f64, 0.1f64);
    let omega = 2.0 * (k / m).sqrt() * (std::f64::consts::PI / n).sin();
    let period = 2.0 * std::f64::consts::PI / omega;
    let dt = format!("{:e}", period / 2000.0);
    dir.run(&[
        "md",
        "--positions",
        &chain,
        "--box",
        "16",
        "--potential",
        "spring",
        "--k",
        "1",
        "--rest-length",
        "1",
        "--cutoff",
        "1.5",
        "--dt",
        &dt,
        "--steps",
        "2000",
        "--xyz-every",
        "500",
        "--out",
        "out",
    ])
    .assert_code(0);
    let f = frames(&dir.read("out/trajectory.xyz"));
    assert_eq!(f.len(), 5); // 0, T/4, T/2, 3T/4, T
    // Displacements from the lattice sites i + 1/2 (no atom crosses the periodic edge).
    let u = |frame: &[[f64; 6]], i: usize| frame[i][0] - (i as f64 + 0.5);
    for i in 0..16 {
        let u0 = a * (2.0 * std::f64::consts::PI * i as f64 / n).sin();
        assert!((u(&f[0], i) - u0).abs() < 1e-8);
        // Verlet's phase error at dt = T/2000 is ~1e-6 rad: ~1e-7 σ here.
        assert!(u(&f[1], i).abs() < 1e-6, "atom {i} at T/4: {}", u(&f[1], i));
        assert!(
            (f[1][i][3] + omega * u0).abs() < 1e-6,
            "atom {i} velocity at T/4"
        );
        assert!((u(&f[2], i) + u0).abs() < 1e-6, "atom {i} at T/2");
        assert!((u(&f[4], i) - u0).abs() < 1e-6, "atom {i} at T");
    }
}

#[test]
fn bad_particle_files_name_the_flag_and_line() {
    let dir = Dir::new();
    dir.create("bad.csv", "x,y\n0,0\n1,oops\n");
    dir.run(&["md", "--positions", "bad.csv", "--boundary", "open"])
        .assert_bad_input(&["--positions", "bad.csv:3:", "oops"]);
    dir.create("two.csv", "0,0\n1.2,0\n");
    dir.run(&["md", "--positions", "two.csv"])
        .assert_bad_input(&["--box", "periodic"]);
    dir.run(&["md", "--positions", "two.csv", "--box", "1,2,3"])
        .assert_bad_input(&["--box", "3 lengths"]);
    dir.create("v.csv", "0,0,0\n");
    dir.run(&[
        "md",
        "--positions",
        "two.csv",
        "--boundary",
        "open",
        "--velocities",
        "v.csv",
    ])
    .assert_bad_input(&["--velocities", "1 3-D velocity for 2 2-D positions"]);
    dir.run(&["md", "--positions", "missing.csv", "--boundary", "open"])
        .assert_bad_input(&["--positions", "missing.csv"]);
    dir.run(&["md", "--potential", "morse"])
        .assert_bad_input(&["--potential", "morse"]);
    dir.run(&[
        "md",
        "--positions",
        "two.csv",
        "--boundary",
        "open",
        "--potential",
        "spring",
        "--k",
        "0",
    ])
    .assert_bad_input(&["--k"]);
}

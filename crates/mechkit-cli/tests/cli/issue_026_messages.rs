//! Issue 26, reliability (second round), messages: errors that came during a run with no
//! location, named internal placeholders, or printed numbers of 300 digits now come when the
//! file is read, located at the value, in the user's own words; and every loop whose length
//! comes from input is bounded before it starts.
//!
//! - `h_min > h_max` (and `h0 < h_min`) in `[integrator]` is refused by `check`, at `h_min`;
//! - a subnormal mass (`1e-320 kg`, whose reciprocal overflows) is refused at the mass;
//! - an `[observe]` formula mixing dimensions names the user's `max(x)`, not `_r0___`;
//! - bodies overlapping at t = 0 are located at the second body's position;
//! - a PNG of 2147483647 × 1 pixels (and a JPEG of 65535 × 65535) gets the size-limit message,
//!   not the decoder's "Memory limit exceeded";
//! - a run cut by the output limit says how many rows its CSV holds and the last time in it;
//! - `1e300` is printed `1e300`, not 301 digits;
//! - `potential --samples`, `spin --samples` and an `[output] interval` of 1e-300 s are
//!   refused before any work, with the flag or the key and the limit.

use super::util::{Csv, Dir};

/// A ball in 1-D under gravity; `integrator` and `extra` complete it.
fn ball(mass: &str, integrator: &str, extra: &str) -> String {
    format!(
        "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"{mass}\"\nposition = \"100 m\"\n[[force]]\nname = \"gravity\"\nkind = \"uniform-gravity\"\n[integrator]\n{integrator}\n[stop]\nt_max = \"1 s\"\n{extra}"
    )
}

/// The 1-based line of the first occurrence of `needle` in `text`.
fn line_of(text: &str, needle: &str) -> usize {
    text.lines()
        .position(|l| l.contains(needle))
        .expect("the needle is in the text")
        + 1
}

#[test]
fn issue_026_h_min_above_h_max_is_refused_when_the_file_is_read() {
    let dir = Dir::new();
    for (name, integrator, other) in [
        (
            "max.toml",
            "method = \"dopri5\"\nh_min = \"1 s\"\nh_max = \"1 ms\"",
            "`h_max` = 0.001 s",
        ),
        (
            "first.toml",
            "method = \"dopri5\"\nh_min = \"1 ms\"\nh0 = \"1 us\"",
            "`h0` = 1e-6 s",
        ),
    ] {
        let text = ball("1 kg", integrator, "");
        dir.create(name, &text);
        let at = format!("{name}:{}:", line_of(&text, "h_min"));
        for command in ["check", "run"] {
            dir.run(&[command, name]).assert_bad_input(&[
                &at,
                "`h_min` =",
                "is larger than",
                other,
                "hint:",
            ]);
        }
    }
}

#[test]
fn issue_026_a_subnormal_mass_is_refused_where_it_is_written() {
    let dir = Dir::new();
    let text = ball("1e-320 kg", "method = \"rk4\"\ndt = \"1 ms\"", "");
    dir.create("s.toml", &text);
    let at = format!("s.toml:{}:", line_of(&text, "mass ="));
    dir.run(&["check", "s.toml"]).assert_bad_input(&[
        &at,
        "the mass of `ball`",
        "1e-320 kg",
        "2.2e-308",
    ]);
    // the smallest normal mass is accepted
    dir.create(
        "ok.toml",
        &ball("2.3e-308 kg", "method = \"rk4\"\ndt = \"1 ms\"", ""),
    );
    dir.run(&["check", "ok.toml"]).assert_code(0);
}

#[test]
fn issue_026_an_observable_mixing_dimensions_names_the_users_reductions() {
    let dir = Dir::new();
    let text = ball(
        "1 kg",
        "method = \"rk4\"\ndt = \"1 ms\"",
        "[observe]\nbad = \"max(x) + final(v)\"\n",
    );
    dir.create("s.toml", &text);
    let out = dir.run(&["check", "s.toml"]);
    out.assert_bad_input(&["cannot add `max(x)`", "`final(v)`"]);
    assert!(!out.stderr.contains("_r0"), "{}", out.stderr);
    assert!(!out.stderr.contains("_r1"), "{}", out.stderr);
}

#[test]
fn issue_026_bodies_overlapping_at_the_start_are_located_at_the_second_body() {
    let dir = Dir::new();
    let text = "dimensions = 1\n[[body]]\nname = \"a\"\nmass = \"1 kg\"\nposition = \"0 m\"\nradius = \"1 m\"\n[[body]]\nname = \"b\"\nmass = \"1 kg\"\nposition = \"1 m\"\nradius = \"0.5 m\"\n[contact]\nrestitution = 1\n[integrator]\nmethod = \"rk4\"\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n";
    dir.create("s.toml", text);
    dir.run(&["check", "s.toml"]).assert_bad_input(&[
        "s.toml:10:12",
        "`a` and `b` overlap by 0.5 m at t = 0",
        "hint:",
    ]);
}

/// A PNG whose header claims `width` × `height` pixels (8-bit RGB), with a tiny image body.
fn png(width: u32, height: u32) -> Vec<u8> {
    fn chunk(out: &mut Vec<u8>, kind: &[u8], data: &[u8]) {
        out.extend((data.len() as u32).to_be_bytes());
        out.extend(kind);
        out.extend(data);
        out.extend([0, 0, 0, 0]); // CRC: the header is read before any check of it
    }
    let mut out = b"\x89PNG\r\n\x1a\n".to_vec();
    let mut ihdr = width.to_be_bytes().to_vec();
    ihdr.extend(height.to_be_bytes());
    ihdr.extend([8, 2, 0, 0, 0]);
    chunk(&mut out, b"IHDR", &ihdr);
    chunk(&mut out, b"IEND", &[]);
    out
}

#[test]
fn issue_026_an_image_claiming_too_many_pixels_gets_the_size_limit_message() {
    let dir = Dir::new();
    std::fs::write(dir.path().join("wide.png"), png(2_147_483_647, 1)).unwrap();
    std::fs::write(dir.path().join("tall.png"), png(1, u32::MAX)).unwrap();
    // SOI, SOF0 of 65535 × 65535 pixels, EOI
    let jpeg = [
        0xFF, 0xD8, 0xFF, 0xC0, 0, 11, 8, 0xFF, 0xFF, 0xFF, 0xFF, 1, 1, 0x11, 0, 0xFF, 0xD9,
    ];
    std::fs::write(dir.path().join("big.jpg"), jpeg).unwrap();
    for (file, size) in [
        ("wide.png", "2147483647 × 1 pixels"),
        ("tall.png", "1 × 4294967295 pixels"),
        ("big.jpg", "65535 × 65535 pixels"),
    ] {
        let out = dir.run(&["com", file]);
        out.assert_bad_input(&[size, "more than mechkit reads", "scale it down"]);
        assert!(!out.stderr.contains("Memory limit"), "{}", out.stderr);
    }
}

#[test]
fn issue_026_a_run_cut_by_the_output_limit_says_where_its_csv_ends() {
    let dir = Dir::new();
    dir.create(
        "s.toml",
        &ball("1 kg", "method = \"rk4\"\ndt = \"1 ms\"", ""),
    );
    let out = dir.run(&[
        "run",
        "s.toml",
        "--out",
        "out",
        "--no-plots",
        "--max-output",
        "20kB",
    ]);
    out.assert_code(1);
    let csv = Csv::parse(&dir.read("out/trajectory.csv"));
    let last = csv.rows.last().expect("rows")[csv.column("t")];
    let rows = csv.rows.len();
    let summary = dir.read_json("out/summary.json");
    assert_eq!(summary["files"]["trajectory_rows"], rows as u64);
    assert_eq!(summary["files"]["trajectory_last_t"].as_f64(), Some(last));
    let t_end = summary["t_end"].as_f64().expect("t_end");
    assert!(t_end > last, "the row at t_end = {t_end} did not fit");
    let said = format!("holds {rows} rows, up to t = {last} s");
    out.assert_stderr_contains(&format!("the file {said}"))
        .assert_stderr_contains(&said);
}

#[test]
fn issue_026_extreme_numbers_are_printed_short() {
    let dir = Dir::new();
    dir.create(
        "heavy.toml",
        &ball("1e300 kg", "method = \"rk4\"\ndt = \"1 ms\"", ""),
    );
    let out = dir.run(&["check", "heavy.toml"]);
    out.assert_code(0);
    assert!(out.stdout.contains("body ball: 1e300 kg"), "{}", out.stdout);
    dir.create(
        "dt.toml",
        &ball("1 kg", "method = \"rk4\"\ndt = \"-1e300 s\"", ""),
    );
    dir.run(&["check", "dt.toml"])
        .assert_bad_input(&["must be positive, not -1e300 s"]);
    for out in [
        dir.run(&["check", "heavy.toml"]),
        dir.run(&["check", "dt.toml"]),
    ] {
        for line in out.stdout.lines().chain(out.stderr.lines()) {
            assert!(
                !line.contains("0000000000000000000000000"),
                "a long number: {line}"
            );
        }
    }
}

#[test]
fn issue_026_sample_counts_are_bounded_before_any_work() {
    let dir = Dir::new();
    let too_many = "10000001";
    dir.run(&["potential", "x^2", "--range", "-1:1", "--samples", too_many])
        .assert_bad_input(&["--samples", too_many, "10000000"]);
    dir.run(&[
        "spin",
        "--moments",
        "1,2,3",
        "--omega",
        "1,0,0",
        "--t-max",
        "1",
        "--samples",
        &usize::MAX.to_string(),
    ])
    .assert_bad_input(&["--samples", "10000000"]);
}

#[test]
fn issue_026_an_output_interval_asking_for_1e300_rows_is_refused_at_the_interval() {
    let dir = Dir::new();
    let text = ball(
        "1 kg",
        "method = \"rk4\"\ndt = \"1 ms\"",
        "[output]\ninterval = \"1e-300 s\"\n",
    );
    dir.create("s.toml", &text);
    let at = format!("s.toml:{}:", line_of(&text, "interval"));
    dir.run(&["check", "s.toml"])
        .assert_bad_input(&[&at, "1e300 output times", "larger interval"]);
}

/// A body started where a force has no value (an orbit at the attracting centre, two bodies of
/// a pair force at one place) is refused when the file is read, located at the body's
/// position: it stopped at the run's first evaluation with exit 1 and no location, and
/// `check` said ok. A body off the centre by a metre still runs.
#[test]
fn issue_026_a_body_started_at_a_singular_point_of_a_force_is_refused_at_its_position() {
    let dir = Dir::new();
    let orbit = |x: &str| {
        format!(
            "dimensions = 2\n[[body]]\nname = \"probe\"\nmass = \"1 kg\"\nposition = [\"{x}\", \"0 m\"]\nvelocity = [\"0 m/s\", \"1 m/s\"]\n[[force]]\nname = \"sun\"\nkind = \"newtonian-gravity\"\nGM = \"1 m^3/s^2\"\ncenter = [\"0 m\", \"0 m\"]\n[integrator]\nmethod = \"rk4\"\ndt = \"1 ms\"\n[stop]\nt_max = \"0.1 s\"\n"
        )
    };
    dir.create("centre.toml", &orbit("0 m"));
    for args in [
        &["check", "centre.toml"][..],
        &["run", "centre.toml", "--out", "out"],
    ] {
        dir.run(args).assert_bad_input(&[
            "centre.toml:5:12",
            "at the start (t = 0) the force `sun` on `probe` is NaN",
            "probe at position (0, 0) m",
            "hint:",
            "move the body",
        ]);
    }
    dir.create("off.toml", &orbit("1 m"));
    dir.run(&["check", "off.toml"]).assert_code(0);

    let pair = "dimensions = 2\n[[body]]\nname = \"a\"\nmass = \"1 kg\"\nposition = [\"0 m\", \"0 m\"]\n[[body]]\nname = \"b\"\nmass = \"1 kg\"\nposition = [\"0 m\", \"0 m\"]\n[[force]]\nname = \"bond\"\nkind = \"pair\"\nbetween = \"all\"\nU = \"-1/r\"\n[integrator]\nmethod = \"rk4\"\ndt = \"1 ms\"\n[stop]\nt_max = \"0.1 s\"\n";
    dir.create("pair.toml", pair);
    dir.run(&["check", "pair.toml"]).assert_bad_input(&[
        "pair.toml:5:12",
        "the force `bond` on `a`",
        "the other bodies: b at (0, 0) m",
    ]);
}

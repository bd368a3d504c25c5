//! The models' commands (`rocket`, `spin`, `bead`, `roll`, `friction`, `animate`) under the
//! reliability rules: a tolerance below double precision, a fixed step count past the budget
//! and an animation speed or size out of range are refused at the flag before any work (they
//! ran for minutes, or were silently changed); extreme numbers print short; an echoed value is
//! cut; a title's control characters never reach the terminal raw.

use super::util::Dir;

/// A run of more than 24 digits in a row: a number printed with hundreds of digits.
fn long_digit_run(text: &str) -> Option<&str> {
    let mut run = 0;
    for (i, c) in text.char_indices() {
        run = if c.is_ascii_digit() { run + 1 } else { 0 };
        if run > 24 {
            let start = text[..i].rfind('\n').map_or(0, |n| n + 1);
            let end = text[i..].find('\n').map_or(text.len(), |n| i + n);
            return Some(&text[start..end]);
        }
    }
    None
}

#[test]
fn a_tolerance_below_double_precision_is_refused_at_the_flag() {
    let dir = Dir::new();
    let rocket = [
        "rocket",
        "--m0",
        "1 t",
        "--m1",
        "400 kg",
        "--mass-rate",
        "10",
        "--exhaust-speed",
        "2 km/s",
        "--g",
        "9.81",
        "--coast",
        "--rtol",
        "1e-307",
    ];
    let spin = [
        "spin",
        "--moments",
        "1, 2, 3",
        "--omega",
        "0.01, 1, 0.01",
        "--t-max",
        "100",
        "--rtol",
        "1e-100",
    ];
    let bead = [
        "bead", "--circle", "1 m", "--side", "outside", "--start", "0", "--speed", "0.1 m/s",
        "--t-max", "3 s", "--rtol", "1e-100",
    ];
    let roll = [
        "roll", "--body", "hoop", "--radius", "1", "--mass", "1", "--slope", "0.3", "--mu", "0.3",
        "--v0", "2", "--omega0", "-3", "--t-max", "3", "--rtol", "1e-100",
    ];
    for args in [&rocket[..], &spin, &bead, &roll] {
        let start = std::time::Instant::now();
        dir.run(args).assert_bad_input(&[
            "--rtol",
            "below what double precision can deliver",
            "1e-14 or more",
        ]);
        assert!(
            start.elapsed().as_secs() < 10,
            "{args:?} took {:?}",
            start.elapsed()
        );
    }
    // the library's rule, the same at a scenario's compare flag
    let scenario = super::util::example("spring_block.toml");
    dir.run(&[
        "run",
        &scenario,
        "--compare-methods",
        "rk4,dopri5",
        "--rtol",
        "1e-100",
        "-o",
        "cmp",
    ])
    .assert_bad_input(&["--rtol", "below what double precision"]);
    // 1e-14 is accepted
    let mut ok = roll;
    ok[18] = "1e-14";
    dir.run(&ok).assert_code(0);
}

#[test]
fn fixed_steps_past_the_budget_and_a_subnormal_step_are_refused_before_the_run() {
    let dir = Dir::new();
    let spin = |dt: &str, t_max: &str| {
        dir.run(&[
            "spin",
            "--moments",
            "1, 2, 3",
            "--omega",
            "0.01, 1, 0.01",
            "--t-max",
            t_max,
            "--method",
            "rk4",
            "--dt",
            dt,
        ])
    };
    let e = spin("1e-320", "10");
    e.assert_bad_input(&["--dt", "1e-320 s", "at least 2.2e-308 s"]);
    assert!(!e.stderr.contains("inf"), "{}", e.stderr);
    spin("1 ms", "1e300").assert_bad_input(&[
        "--dt",
        "1e303 fixed steps of 0.001 s",
        "more than the 1000000 a run may take",
    ]);
}

#[test]
fn extreme_numbers_print_short() {
    let dir = Dir::new();
    dir.create("subnormal.csv", "t,x\n0,0\n1e-320,1\n2e-320,2\n3e-320,3\n");
    dir.create(
        "huge.csv",
        "t,x\n0,1e308\n1,-1e308\n2,1e308\n3,-1e308\n4,1e308\n",
    );
    dir.create("far.csv", "t,x\n0,1e300\n1,2e300\n2,3e300\n3,5e300\n");
    let cases: &[&[&str]] = &[
        &["impulse", "subnormal.csv"],
        &["impulse", "huge.csv"],
        &["derive", "far.csv"],
        &[
            "collide",
            "--m1",
            "1",
            "--v1",
            "1,1",
            "--m2",
            "1",
            "--v2",
            "0,0",
            "--normal",
            "1,0",
            "-e",
            "1",
            "--friction",
            "1e308",
        ],
        &[
            "potential",
            "x^2",
            "--range",
            "-1:1",
            "--energy",
            "1e308",
            "--no-plots",
        ],
        &[
            "potential",
            "1e300*x^2",
            "--range",
            "-1:1",
            "--mass",
            "1e-300",
            "--x0",
            "0.5",
            "--no-plots",
        ],
        &["md", "--cells", "4", "--sigma", "1e10", "--steps", "10"],
        &["md", "--cells", "4", "--cutoff", "1e300", "--steps", "10"],
        &[
            "rocket",
            "--m0",
            "1 t",
            "--m1",
            "400 kg",
            "--mass-rate",
            "10",
            "--exhaust-speed",
            "1e300 m/s",
            "--g",
            "9.81",
            "--coast",
        ],
        &[
            "bead", "--curve", "sqrt(x)", "--start", "1", "--speed", "1", "--t-max", "3",
        ],
        &[
            "power", "--power", "20 kW", "--mass", "200 kg", "--at", "1e-300 s",
        ],
        &["integrate", "1e300*x", "--from", "0", "--to", "1"],
    ];
    for args in cases {
        let out = dir.run(args);
        for text in [&out.stdout, &out.stderr] {
            assert!(
                long_digit_run(text).is_none(),
                "{args:?} printed a long number: {}",
                long_digit_run(text).unwrap_or_default()
            );
        }
    }
}

#[test]
fn an_echoed_value_is_cut_like_a_source_line() {
    let dir = Dir::new();
    dir.create(
        "long.csv",
        &format!("t,x\n0,{}\n1,2\n", "1".repeat(100_000)),
    );
    let out = dir.run(&["derive", "long.csv"]);
    out.assert_bad_input(&["long.csv:2:3", "(100000 characters)"]);
    assert!(out.stderr.len() < 1000, "{} bytes", out.stderr.len());
    let flag = "2".repeat(5000) + "x";
    let out = dir.run(&[
        "spin",
        "--moments",
        &flag,
        "--omega",
        "1,1,1",
        "--t-max",
        "1",
    ]);
    out.assert_bad_input(&["--moments"]);
    assert!(out.stderr.len() < 1000, "{} bytes", out.stderr.len());
}

#[test]
fn messages_name_the_flag_given_in_its_own_terms() {
    let dir = Dir::new();
    let friction = |angle: &str| {
        dir.run(&[
            "friction", "--mass", "1", "--mu-s", "0.6", "--mu-d", "0.4", "--angle", angle,
        ])
    };
    let e = friction("100 deg");
    e.assert_bad_input(&["--angle `100 deg` is 100°", "between -90° and 90°"]);
    assert!(!e.stderr.contains("deg deg"), "{}", e.stderr);
    assert!(!friction("2 rad").stderr.contains("rad deg"));
    friction("2").assert_bad_input(&["write \"2 deg\" for degrees"]);
    dir.run(&[
        "rotation",
        "--radius",
        "6371 km",
        "--period",
        "1 d",
        "--latitude",
        "100 deg",
    ])
    .assert_bad_input(&["--latitude", "(in degrees)", "not 100"]);
    dir.run(&["rotation", "--radius", "1e-320 m", "--speed", "10 m/s"])
        .assert_bad_input(&["--radius", "at least 2.2e-308 m"]);
    let out = dir.run(&["integrate", "1/x", "--from", "1", "--to", "inf"]);
    assert!(
        out.stdout
            .contains("does not decay fast enough towards x = inf"),
        "{}",
        out.stdout
    );
    assert!(!out.stdout.contains("at x = 1:"), "{}", out.stdout);
    let out = dir.run(&[
        "power",
        "--power",
        "20 kW",
        "--mass",
        "1e-310 kg",
        "--at",
        "5 s",
        "-o",
        "p",
    ]);
    out.assert_bad_input(&["--mass", "at least 2.2e-308 kg"]);
    assert!(!dir.path().join("p").exists(), "nothing is written");
    for angle in ["0", "720 deg"] {
        dir.run(&[
            "rigid-collide",
            "--rod",
            "--mass",
            "1",
            "--length",
            "1",
            "--release-angle",
            angle,
            "--block-mass",
            "1",
            "--block-velocity",
            "0",
            "--restitution",
            "0.5",
        ])
        .assert_bad_input(&["--release-angle", "between -180° and 180° and not 0"]);
    }
}

#[test]
fn control_characters_of_a_title_are_escaped_in_human_output() {
    let dir = Dir::new();
    let text = "title = \"A \\u001b[31mred\\u0001 \\u202Eevil\"\ndimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n[integrator]\nmethod = \"rk4\"\ndt = \"0.1 s\"\n[stop]\nt_max = \"1 s\"\n";
    dir.create("t.toml", text);
    for args in [&["check", "t.toml"][..], &["run", "t.toml", "-o", "out"]] {
        let out = dir.run(args);
        out.assert_code(0);
        for c in ['\u{1b}', '\u{1}', '\u{202e}'] {
            assert!(!out.stdout.contains(c), "{args:?}: {:?}", out.stdout);
        }
        assert!(
            out.stdout.contains("A \\u{1b}[31mred\\u{1} \\u{202e}evil"),
            "{args:?}: {}",
            out.stdout
        );
    }
}

#[test]
fn an_animation_speed_or_size_out_of_range_is_refused_at_the_flag() {
    let dir = Dir::new();
    let scenario = super::util::example("spring_block.toml");
    let animate =
        |extra: &[&str]| dir.run_with(&["animate", &scenario, "-o", "an", "-f", "html"], extra);
    for speed in ["1e-300", "1e300"] {
        animate(&["--speed", speed]).assert_bad_input(&[
            "--speed",
            "choose a speed from 0.0625",
            "to 125",
        ]);
    }
    animate(&["--width", "0", "--height", "1"])
        .assert_bad_input(&["--width 0", "from 64 to 4096 pixels"]);
    animate(&["--speed", "2"]).assert_code(0);
}

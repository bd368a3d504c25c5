//! Issue 26, silent wrong answers: inputs that printed a wrong or non-finite answer with exit
//! code 0 now give exit 1 or 2 with a message that names what is wrong.
//!
//! - the finiteness rule: no command prints or writes `inf` or `NaN` as a result (`work`,
//!   `impulse`, `derive`, `collide` on values near 1e308);
//! - a definite integral across a pole is refused at the pole; an improper integral that
//!   converges keeps its value;
//! - the bounds of an integral share a dimension; a variable is a name;
//! - a number that overflows a double is refused where it is written;
//! - a fixed step longer than the run is refused at `dt`;
//! - `md` refuses a start that cannot work (a subnormal mass, atoms at one place, a step that
//!   crosses the cut-off) and stops at the first thermo value that is not finite;
//! - a title with control characters gives well-formed SVG;
//! - a sweep in which every run failed exits 1.

use super::util::{Dir, example, num};

/// Whether the file name `f` ends in `.EXT`.
fn has_extension(f: &str, ext: &str) -> bool {
    std::path::Path::new(f)
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case(ext))
}

/// The text of `examples/feather.toml`.
fn feather() -> String {
    std::fs::read_to_string(example("feather.toml")).expect("the example is readable")
}

#[test]
fn issue_026_a_definite_integral_across_a_pole_is_refused_at_the_pole() {
    let dir = Dir::new();
    // (integrand, from, to, the point named)
    for (f, a, b, at) in [
        ("1/x^2", "-1", "1", "x = 0"),
        ("1/x", "-1", "1", "x = 0"),
        ("1/x", "0", "1", "x = 0"),
        ("1/(x-1)", "0", "2", "x = 1"),
        ("tan(x)", "0", "2", "x = 1.570796327"),
        ("ln(x)/x", "0", "1", "x = 0"),
    ] {
        for extra in [&[][..], &["--json"][..], &["--method", "trapezoid"][..]] {
            let mut args = vec!["integrate", f, "--from", a, "--to", b];
            args.extend_from_slice(extra);
            let out = dir.run(&args);
            out.assert_bad_input(&[
                "--from/--to",
                &format!("`{f}` is not integrable at {at} in [{a}, {b}]"),
                "the integral diverges",
                "hint:",
            ]);
            assert!(out.stdout.is_empty(), "{f}: {}", out.stdout);
        }
    }
}

#[test]
fn issue_026_improper_integrals_that_converge_keep_their_value() {
    let dir = Dir::new();
    for (f, a, b, exact) in [
        ("1/sqrt(x)", "0", "1", 2.0),
        ("ln(x)", "0", "1", -1.0),
        ("1/sqrt(1-x^2)", "-1", "1", std::f64::consts::PI),
        ("1/sqrt(abs(x))", "-1", "1", 4.0),
        ("x^2", "-1", "1", 2.0 / 3.0),
    ] {
        let v = dir.json(&["integrate", f, "--from", a, "--to", b, "--json"]);
        let d = &v["definite"];
        let value = d["closed_form"]
            .as_f64()
            .or_else(|| d["quadrature"]["value"].as_f64())
            .unwrap_or_else(|| panic!("{f}: no value in {v}"));
        assert!((value - exact).abs() < 1e-8, "{f}: {value} for {exact}");
    }
    // an infinite limit is an input, echoed as null: not a result the finiteness rule refuses
    let v = dir.json(&[
        "integrate",
        "exp(-x)",
        "--from",
        "0",
        "--to",
        "inf",
        "--json",
    ]);
    assert!(v["definite"]["to"].is_null());
    assert!((num(&v, "/definite/quadrature/value") - 1.0).abs() < 1e-9);
}

#[test]
fn issue_026_bounds_share_a_dimension_and_a_variable_is_a_name() {
    let dir = Dir::new();
    dir.run(&["integrate", "x^2", "--from", "1 m", "--to", "2 s"])
        .assert_bad_input(&["--from `1 m` and --to `2 s` have different dimensions"]);
    dir.run(&["potential", "x^2", "--range", "1 m:2 s"])
        .assert_bad_input(&["--range", "different dimensions"]);
    // units of one dimension are converted, as before
    let v = dir.json(&["integrate", "1", "--from", "1 m", "--to", "1 km", "--json"]);
    assert!((num(&v, "/definite/closed_form") - 999.0).abs() < 1e-9);
    for args in [
        vec!["diff", "x^2", "--var", "x+y"],
        vec!["diff", "x^2", "--var", "2"],
        vec!["diff", "x^2", "--var", "pi"],
        vec!["integrate", "x^2", "--var", "sin(x)"],
        vec!["solve", "x^2 = 4", "--for", "x*y"],
    ] {
        dir.run(&args).assert_bad_input(&["is not a name"]);
    }
}

#[test]
fn issue_026_a_number_too_large_for_a_double_is_refused_where_it_is_written() {
    let dir = Dir::new();
    dir.run(&["units", "1e309 m"]).assert_bad_input(&[
        "`1e309` is too large for a double-precision number",
        "^^^^^",
    ]);
    dir.run(&["units", "1e308 km"])
        .assert_bad_input(&["`1e308 km` in SI units is too large"]);
    dir.run(&["diff", "1e309*x"])
        .assert_bad_input(&["`1e309` is too large", "(column 1)"]);
    dir.create(
        "big.toml",
        &feather().replace("position = \"2.4 m\"", "position = \"1e400 m\""),
    );
    dir.run(&["check", "big.toml"])
        .assert_bad_input(&["`1e400` is too large", "big.toml:"]);
}

#[test]
fn issue_026_a_fixed_step_longer_than_the_run_is_refused_at_dt() {
    let dir = Dir::new();
    let text = feather().replace("dt     = \"1 ms\"", "dt = \"20 s\"");
    assert!(text.contains("dt = \"20 s\""), "the example changed");
    dir.create("f.toml", &text);
    for cmd in ["check", "run"] {
        dir.run(&[cmd, "f.toml"]).assert_bad_input(&[
            "dt = 20 s is longer than the run, from t = 0 s to t_max = 10 s",
            "f.toml:",
            "hint: choose a step much shorter than the run",
        ]);
    }
}

#[test]
fn issue_026_results_that_are_not_finite_are_never_printed() {
    let dir = Dir::new();
    dir.create("f.csv", "x,F\n0,1e308\n1,1e308\n2,1e308\n");
    dir.create("j.csv", "t,F\n0,1e308\n1,1e308\n2,1e308\n");
    dir.create("x.csv", "t,x\n0,-1e308\n1,1e308\n2,-1e308\n3,1e308\n");
    for args in [
        vec!["work", "f.csv"],
        vec!["work", "f.csv", "--json"],
        vec!["work", "f.csv", "-o", "out"],
        vec!["impulse", "j.csv"],
        vec!["derive", "x.csv"],
        vec!["derive", "x.csv", "--json", "-o", "out"],
        vec![
            "collide",
            "--m1",
            "1",
            "--m2",
            "1",
            "--v1",
            "1e308",
            "--v2",
            "-1e308",
            "--restitution",
            "1",
        ],
    ] {
        let out = dir.run(&args);
        out.assert_code(1);
        assert!(out.stderr.starts_with("error:"), "{args:?}: {}", out.stderr);
        for bad in ["inf", "NaN", "null"] {
            assert!(
                !out.stdout.contains(bad),
                "{args:?} printed {bad}: {}",
                out.stdout
            );
        }
    }
    assert!(
        dir.files("out").iter().all(|f| !has_extension(f, "csv")),
        "{:?}",
        dir.files("out")
    );
    dir.run(&["work", "f.csv"])
        .assert_stderr_contains("is inf, not a finite number");
}

#[test]
fn issue_026_collisions_near_the_largest_double_are_exact() {
    let dir = Dir::new();
    // m1 + m2 overflowed: the velocities after came out 0
    let v = dir.json(&[
        "collide",
        "--m1",
        "1e308",
        "--m2",
        "1e308",
        "--v1",
        "1",
        "--v2",
        "0",
        "--restitution",
        "0",
        "--json",
    ]);
    assert_eq!(num(&v, "/v1/0"), 0.5);
    assert_eq!(num(&v, "/v2/0"), 0.5);
    assert_eq!(num(&v, "/kinetic_lost"), 2.5e307);
    // an energy that is not representable is refused, naming it
    dir.run(&[
        "collide",
        "--m1",
        "1",
        "--m2",
        "1",
        "--v1",
        "1e308",
        "--v2",
        "0",
        "--restitution",
        "1",
    ])
    .assert_code(1)
    .assert_stderr_contains("the result kinetic_before is inf, not a finite number");
}

#[test]
fn issue_026_md_refuses_a_start_that_cannot_work() {
    let dir = Dir::new();
    dir.run(&["md", "--mass", "1e-320", "--steps", "5"])
        .assert_bad_input(&["--mass", "1e-320, below 2.2e-308"]);
    for args in [
        vec!["md", "--temperature", "1e100", "--steps", "5"],
        vec!["md", "--dt", "1e308", "--steps", "5"],
    ] {
        dir.run(&args)
            .assert_bad_input(&["--dt", "more than the box's shortest edge"]);
    }
    dir.create("p.csv", "# three atoms\nx,y,z\n0,0,0\n1.5,0,0\n\n0,0,0\n");
    dir.run(&["md", "--positions", "p.csv", "--box", "10", "--steps", "5"])
        .assert_bad_input(&[
            "--positions",
            "p.csv:3 and ",
            "p.csv:6 are at the same place",
        ]);
}

#[test]
fn issue_026_md_stops_at_the_first_thermo_value_that_is_not_finite() {
    let dir = Dir::new();
    let out = dir.run(&[
        "md",
        "--cells",
        "4",
        "--dt",
        "0.4",
        "--steps",
        "200",
        "--thermo-every",
        "1",
        "-o",
        "out",
    ]);
    out.assert_code(1)
        .assert_stderr_contains("diverged at step");
    let thermo = dir.read("out/thermo.csv");
    for line in thermo.lines() {
        assert!(!line.contains("inf") && !line.contains("NaN"), "{thermo}");
    }
    assert!(thermo.lines().count() >= 2, "{thermo}");
}

#[test]
fn issue_026_titles_with_control_characters_give_well_formed_svg() {
    let dir = Dir::new();
    let text = feather();
    let title = text
        .lines()
        .find(|l| l.starts_with("title"))
        .expect("a title");
    dir.create(
        "t.toml",
        &text.replace(
            title,
            r#"title = "Feather\u0001\u000b\u001f\uFFFE <&> fall""#,
        ),
    );
    dir.run(&["run", "t.toml", "-o", "out"]).assert_code(0);
    let svgs: Vec<String> = dir
        .files("out")
        .into_iter()
        .filter(|f| has_extension(f, "svg"))
        .collect();
    assert!(!svgs.is_empty());
    for f in svgs {
        let svg = dir.read(&format!("out/{f}"));
        assert!(
            !svg.chars()
                .any(|c| (c < ' ' && !"\t\n\r".contains(c)) || c == '\u{fffe}'),
            "{f} holds a character XML forbids"
        );
        resvg::usvg::Tree::from_str(&svg, &resvg::usvg::Options::default())
            .unwrap_or_else(|e| panic!("{f} is not well-formed: {e}"));
        if f == "x_t.svg" {
            assert!(svg.contains("Feather &lt;&amp;&gt; fall"), "{svg}");
        }
    }
}

#[test]
fn issue_026_a_sweep_in_which_every_run_failed_exits_1() {
    let dir = Dir::new();
    dir.create(
        "blow.toml",
        r#"
dimensions = 1
[constants]
k = "1e6 N/m"
[[body]]
name = "ball"
mass = "1 kg"
position = "1 m"
velocity = "0 m/s"
[[force]]
name = "spring"
kind = "expression"
on = "ball"
F = "-k*x"
[integrator]
method = "euler"
dt = "10 ms"
[stop]
t_max = "5 s"
"#,
    );
    for out_args in [&["-o", "out"][..], &[][..]] {
        let mut args = vec!["sweep", "blow.toml", "--set", "k=1e6:2e6:3", "--no-plots"];
        args.extend_from_slice(out_args);
        dir.run(&args).assert_code(1).assert_stderr_contains(
            "error: every run failed (3 of 3); the first, run 0 (k=1000000), diverged",
        );
    }
    // some failed: the rows say which, and the command succeeds
    let out = dir.run(&[
        "sweep",
        "blow.toml",
        "--set",
        "k=1,1e6",
        "--no-plots",
        "-o",
        "some",
    ]);
    out.assert_code(0)
        .assert_stderr_contains("warning: 1 of 2 runs failed");
}

//! Issue 22 for the calculus and work-energy commands (`diff`, `integrate`, `solve`, `units`,
//! `potential`, `work`, `impulse`, `derive`, `power`): their results are library values, so
//! what is checked here is the behaviour the front owes on top of them.
//!
//! - `solve --set` gives values to a linear system's names (it used to ignore them), and
//!   `--set` values are formulas (`th=pi/6`);
//! - `units --to` prints each line once;
//! - nothing is written without `-o DIR`; with it, each command writes its CSV through the one
//!   writer (plain column names, a units sidecar) and plots named `<y>_<x>`;
//! - `work` prints the largest force as a magnitude;
//! - `potential` says in words where a released body goes, and labels its axes with units only
//!   where they are known; `derive` likewise, from the data file's header;
//! - counts agree with their nouns ("1 component").

use crate::util::{Csv, Dir, example, num};

#[test]
fn solve_uses_set_for_a_linear_system() {
    let dir = Dir::new();
    let out = dir.run(&[
        "solve",
        "a*x + y = 3; x - y = 1",
        "--for",
        "x,y",
        "--set",
        "a=2",
        "--json",
    ]);
    out.assert_code(0);
    let j = out.json();
    assert!((num(&j, "/numeric/x") - 4.0 / 3.0).abs() < 1e-15, "{j}");
    assert!((num(&j, "/numeric/y") - 1.0 / 3.0).abs() < 1e-15, "{j}");
    assert_eq!(j["parameters"]["a"], 2.0);
    // the symbolic solution is still there
    assert!(j["solution"]["x"].as_str().unwrap().contains('a'), "{j}");
    let out = dir.run(&[
        "solve",
        "a*x + y = 3; x - y = 1",
        "--for",
        "x,y",
        "--set",
        "a=2",
    ]);
    out.assert_code(0);
    assert!(
        out.stdout.contains("numerically with a = 2") && out.stdout.contains("x = 1.333333"),
        "{}",
        out.stdout
    );
    // singular for a = -1: no unique solution, exit 1
    let out = dir.run(&[
        "solve",
        "a*x + y = 3; x - y = 1",
        "--for",
        "x,y",
        "--set=a=-1",
    ]);
    out.assert_code(1);
    assert!(out.stdout.contains("no unique solution"), "{}", out.stdout);
}

#[test]
fn set_values_are_formulas() {
    let out = Dir::new().run(&[
        "solve",
        "N = m*g*cos(th)",
        "--for",
        "N",
        "--set",
        "m=2 kg,g=9.81,th=pi/6",
        "--json",
    ]);
    out.assert_code(0);
    let n = num(&out.json(), "/numeric/0");
    assert!(
        (n - 2.0 * 9.81 * (std::f64::consts::PI / 6.0).cos()).abs() < 1e-12,
        "{n}"
    );
    let out = Dir::new().run(&[
        "diff", "sin(k*x)", "--at", "0", "--set", "k=30 deg", "--json",
    ]);
    out.assert_code(0);
    assert!((num(&out.json(), "/at/symbolic") - std::f64::consts::PI / 6.0).abs() < 1e-12);
}

#[test]
fn units_to_si_prints_the_line_once() {
    let out = Dir::new().run(&["units", "60 km/h", "--to", "m/s"]);
    out.assert_code(0);
    assert_eq!(out.stdout.lines().count(), 1, "{}", out.stdout);
    let out = Dir::new().run(&["units", "1 AU", "--to", "km"]);
    assert_eq!(out.stdout.lines().count(), 2, "{}", out.stdout);
    assert!(out.stdout.contains("149597870.7 km"), "{}", out.stdout);
    let j = Dir::new()
        .run(&["units", "60 km/h", "--to", "m/s", "--json"])
        .json();
    assert_eq!(j["si_unit"], "m/s");
    assert_eq!(j["converted"]["unit"], "m/s");
}

#[test]
fn nothing_is_written_without_out() {
    let dir = Dir::new();
    for args in [
        vec!["potential", "x^2", "--range=-1:1"],
        vec![
            "power", "--power", "20 kW", "--mass", "200 kg", "--at", "5 s",
        ],
        vec!["derive", &example("data/fallingtennisball02.txt")],
        vec!["work", &example("data/forcedata.d")],
        vec!["impulse", &example("data/baseballforce.d")],
    ] {
        dir.run(&args).assert_code(0);
        assert_eq!(dir.files("."), Vec::<String>::new(), "{args:?}");
    }
}

#[test]
fn work_writes_its_table_and_plot_into_out() {
    let dir = Dir::new();
    let out = dir.run(&[
        "work",
        &example("data/forcedata.d"),
        "--mass",
        "1",
        "--v0",
        "0.5",
        "-o",
        "w",
        "--json",
    ]);
    out.assert_code(0);
    let j = out.json();
    assert_eq!(dir.files("w"), ["W_x.svg", "work.csv", "work.units.json"]);
    assert!(j["csv"].as_str().unwrap().ends_with("work.csv"), "{j}");
    assert!(j["plot"].as_str().unwrap().ends_with("W_x.svg"), "{j}");
    let csv = Csv::parse(&dir.read("w/work.csv"));
    assert_eq!(csv.header, ["x", "F", "W", "v"]);
    // a file without units: the sidecar says so
    let units = dir.read_json("w/work.units.json");
    assert_eq!(
        units,
        serde_json::json!({"x": null, "F": null, "W": null, "v": null})
    );
    // --format png, and --no-plots
    dir.run(&[
        "work",
        &example("data/forcedata.d"),
        "-o",
        "p",
        "--format",
        "png",
    ])
    .assert_code(0);
    assert!(dir.files("p").contains(&"W_x.png".to_string()));
    dir.run(&[
        "work",
        &example("data/forcedata.d"),
        "-o",
        "n",
        "--no-plots",
    ])
    .assert_code(0);
    assert_eq!(dir.files("n"), ["work.csv", "work.units.json"]);
}

#[test]
fn impulse_writes_impulse_csv_and_j_t() {
    let dir = Dir::new();
    dir.run(&[
        "impulse",
        &example("data/baseballforce.d"),
        "--mass",
        "0.145 kg",
        "-o",
        "j",
    ])
    .assert_code(0);
    assert_eq!(
        dir.files("j"),
        ["J_t.svg", "impulse.csv", "impulse.units.json"]
    );
    assert_eq!(
        Csv::parse(&dir.read("j/impulse.csv")).header,
        ["t", "F", "J"]
    );
}

#[test]
fn a_header_with_units_gives_the_columns_their_units() {
    let dir = Dir::new();
    dir.create("push.csv", "x [cm], F [N]\n0, 2\n50, 2\n100, 2\n");
    let j = dir.run(&["work", "push.csv", "-o", "w", "--json"]).json();
    // converted to SI: 2 N over 1 m
    assert!((num(&j, "/work") - 2.0).abs() < 1e-15, "{j}");
    assert_eq!(
        dir.read_json("w/work.units.json"),
        serde_json::json!({"x": "m", "F": "N", "W": "J"})
    );
    let svg = dir.read("w/W_x.svg");
    assert!(
        svg.contains("W [J]") && svg.contains("x [m]"),
        "axes with units"
    );
}

#[test]
fn the_largest_force_is_a_magnitude() {
    let out = Dir::new().run(&["work", &example("data/forcedata.d")]);
    out.assert_code(0);
    assert!(
        out.stdout
            .contains("largest |F| = 1 N (F = -1 at x = 0.25)"),
        "{}",
        out.stdout
    );
    let j = Dir::new()
        .run(&["work", &example("data/forcedata.d"), "--json"])
        .json();
    assert_eq!(
        (num(&j, "/peak/magnitude"), num(&j, "/peak/f")),
        (1.0, -1.0)
    );
}

#[test]
fn potential_writes_only_into_out_with_plain_axes() {
    let dir = Dir::new();
    let out = dir.run(&[
        "potential",
        "--force",
        "-F0*sin(2*pi*x/b)",
        "--range=-1:2",
        "--set",
        "F0=1,b=1",
        "--mass",
        "1",
        "--x0",
        "0",
        "--v0",
        "0.5",
        "-o",
        "d",
    ]);
    out.assert_code(0);
    assert_eq!(
        dir.files("d"),
        [
            "U_x.svg",
            "potential.csv",
            "potential.units.json",
            "v_x.svg"
        ]
    );
    assert!(!dir.path().join("out").exists());
    // no units anywhere in the input: none on the axes
    let svg = dir.read("d/U_x.svg");
    assert!(
        !svg.contains("[J]") && !svg.contains("[m]"),
        "units on unitless axes"
    );
    assert_eq!(
        Csv::parse(&dir.read("d/potential.csv")).header,
        ["x", "U", "F", "v"]
    );
    // with units: U0 in eV, the range in ångström
    let out = dir.run(&[
        "potential",
        "U0*((a/r)^12-(a/r)^6)",
        "--var",
        "r",
        "--range",
        "3 Å:10 Å",
        "--set",
        "U0=0.01 eV,a=3.4 Å",
        "-o",
        "lj",
    ]);
    out.assert_code(0);
    let svg = dir.read("lj/U_r.svg");
    assert!(
        svg.contains("U [J]") && svg.contains("r [m]"),
        "axes with units"
    );
    assert_eq!(
        dir.read_json("lj/potential.units.json"),
        serde_json::json!({"r": "m", "U": "J", "F": "N"})
    );
}

#[test]
fn potential_says_where_a_released_body_goes() {
    let dir = Dir::new();
    // a well: it oscillates
    let out = dir.run(&[
        "potential",
        "x^2",
        "--range=-2:2",
        "--mass",
        "1",
        "--x0",
        "0",
        "--v0",
        "1",
    ]);
    out.assert_code(0);
    assert!(out.stdout.contains("oscillates"), "{}", out.stdout);
    // a ramp with nothing to stop it: it leaves the range, in words a student reads
    let out = dir.run(&[
        "potential",
        "-x",
        "--range=-0.4:2",
        "--mass",
        "1",
        "--x0",
        "0",
        "--v0",
        "1",
    ]);
    out.assert_code(0);
    assert!(
        out.stdout.contains(
            "no turning point in [-0.4, 2]: the body leaves the range at x = 2 moving right"
        ),
        "{}",
        out.stdout
    );
    assert!(!out.stdout.contains("none inside"), "{}", out.stdout);
    // thrown left up the ramp: turns, then leaves on the right
    let out = dir.run(&[
        "potential",
        "-x",
        "--range=-1:2",
        "--mass",
        "1",
        "--x0",
        "0",
        "--v0=-1",
        "--json",
    ]);
    let j = out.json();
    assert_eq!(j["motion"]["left"]["kind"], "turning_point");
    assert_eq!(j["motion"]["right"]["kind"], "range_end");
    assert!((num(&j, "/motion/left_turn") + 0.5).abs() < 1e-12, "{j}");
}

#[test]
fn derive_plots_are_named_and_labelled_like_the_csv() {
    let dir = Dir::new();
    dir.create(
        "drop.csv",
        "t [s], y [m]\n0, 2\n0.1, 1.951\n0.2, 1.804\n0.3, 1.559\n0.4, 1.216\n",
    );
    dir.run(&["derive", "drop.csv", "-o", "d"]).assert_code(0);
    assert_eq!(
        dir.files("d"),
        [
            "a_t.svg",
            "derived.csv",
            "derived.units.json",
            "v_t.svg",
            "y_t.svg"
        ]
    );
    assert_eq!(
        dir.read_json("d/derived.units.json"),
        serde_json::json!({"t": "s", "y": "m", "dy_dt": "m/s", "d2y_dt2": "m/s^2"})
    );
    let svg = dir.read("d/v_t.svg");
    assert!(
        svg.contains("v [m/s]") && svg.contains("t [s]"),
        "axes with units"
    );
    // the tennis ball's file has no header: no units, on the axes either
    dir.run(&[
        "derive",
        &example("data/fallingtennisball02.txt"),
        "-o",
        "tb",
    ])
    .assert_code(0);
    assert_eq!(
        dir.read_json("tb/derived.units.json"),
        serde_json::json!({"t": null, "x": null, "dx_dt": null, "d2x_dt2": null})
    );
    assert!(!dir.read("tb/v_t.svg").contains("[m/s]"));
}

#[test]
fn power_writes_its_curves_into_out() {
    let dir = Dir::new();
    dir.run(&[
        "power", "--power", "20 kW", "--mass", "200 kg", "--at", "5 s", "-o", "p",
    ])
    .assert_code(0);
    assert_eq!(
        dir.files("p"),
        ["power.csv", "power.units.json", "v_t.svg", "x_t.svg"]
    );
    assert_eq!(
        Csv::parse(&dir.read("p/power.csv")).header,
        ["t", "v", "a", "x", "W"]
    );
}

#[test]
fn counts_agree_with_their_nouns() {
    let out = Dir::new().run(&[
        "work", "--field", "y, -x", "--path", "cos(s)", "--param", "s=0:1",
    ]);
    out.assert_code(2);
    out.assert_stderr_contains("the path has 1 component but");
    let out = Dir::new().run(&["solve", "x + y = 1", "--for", "x,y"]);
    out.assert_code(2);
    out.assert_stderr_contains("1 equation for 2 unknowns");
}

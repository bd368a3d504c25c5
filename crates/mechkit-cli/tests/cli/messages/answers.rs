//! Answers that would have been wrong or not finite (issue 26): a divergent integral, bounds
//! of two dimensions, a variable that is no name, a number too large for a double, a step
//! longer than the run, md starts that cannot work, a result that is not finite, a sweep in
//! which every run failed.

use super::case::{Case, Contents, assert_cases};

#[test]
fn answer_messages() {
    assert_cases(CASES);
}

/// A feather falling for 10 s in steps of 20 s.
const LONG_STEP: &str = r#"dimensions = 1
[[body]]
name = "feather"
mass = "1 g"
position = "2.4 m"
[[force]]
kind = "uniform-gravity"
[integrator]
method = "euler-cromer"
dt = "20 s"
[stop]
t_max = "10 s"
"#;

/// A spring so stiff that explicit Euler explodes for every `k` of the sweep.
const UNSTABLE: &str = r#"dimensions = 1
[constants]
k = "1e6 N/m"
[[body]]
name = "ball"
mass = "1 kg"
position = "1 m"
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
"#;

pub static CASES: &[Case] = &[
    Case {
        area: "answer",
        kind: "integral_across_a_pole",
        files: &[],
        args: &["integrate", "1/x^2", "--from", "-1", "--to", "1"],
        code: 2,
    },
    Case {
        area: "answer",
        kind: "bounds_of_two_dimensions",
        files: &[],
        args: &["integrate", "x", "--from", "1 m", "--to", "2 s"],
        code: 2,
    },
    Case {
        area: "answer",
        kind: "variable_not_a_name",
        files: &[],
        args: &["diff", "x^2", "--var", "x+y"],
        code: 2,
    },
    Case {
        area: "answer",
        kind: "number_too_large_in_a_quantity",
        files: &[],
        args: &["units", "1e309 m"],
        code: 2,
    },
    Case {
        area: "answer",
        kind: "quantity_too_large_in_si",
        files: &[],
        args: &["units", "1e308 km"],
        code: 2,
    },
    Case {
        area: "answer",
        kind: "number_too_large_in_a_formula",
        files: &[],
        args: &["diff", "1e309*x"],
        code: 2,
    },
    Case {
        area: "answer",
        kind: "step_longer_than_the_run",
        files: &[("s.toml", Contents::Text(LONG_STEP))],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "answer",
        kind: "md_subnormal_mass",
        files: &[],
        args: &["md", "--mass", "1e-320", "--steps", "5"],
        code: 2,
    },
    Case {
        area: "answer",
        kind: "md_step_across_the_box",
        files: &[],
        args: &["md", "--temperature", "1e100", "--steps", "5"],
        code: 2,
    },
    Case {
        area: "answer",
        kind: "md_atoms_at_one_place",
        files: &[("p.csv", Contents::Text("x,y,z\n0,0,0\n1.5,0,0\n0,0,0\n"))],
        args: &["md", "--positions", "p.csv", "--box", "10", "--steps", "5"],
        code: 2,
    },
    Case {
        area: "answer",
        kind: "result_not_finite",
        files: &[("f.csv", Contents::Text("x,F\n0,1e308\n1,1e308\n2,1e308\n"))],
        args: &["work", "f.csv"],
        code: 1,
    },
    Case {
        area: "answer",
        kind: "every_sweep_run_failed",
        files: &[("s.toml", Contents::Text(UNSTABLE))],
        args: &[
            "sweep",
            "s.toml",
            "--set",
            "k=1e6:2e6:2",
            "--no-plots",
            "-o",
            "out",
        ],
        code: 1,
    },
];

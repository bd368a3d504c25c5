//! Scenario files: values (units, dimensions, ranges), formulas and events, each located in
//! the file with a caret under the problem.

use super::case::{Case, Contents::Text, assert_cases};

#[test]
fn scenario_value_messages() {
    assert_cases(CASES);
}

/// A one-body scenario with `line` as its last `[[body]]` line.
macro_rules! body_with {
    ($line:literal) => {
        concat!(
            "dimensions = 1\n[[body]]\nname = \"ball\"\n",
            $line,
            "\n[integrator]\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n"
        )
    };
}

/// A one-body scenario with an expression force `F = "formula"`.
macro_rules! force_with {
    ($line:literal) => {
        concat!(
            "dimensions = 1\n[constants]\nk = \"10 N/m\"\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n",
            "[[force]]\nname = \"spring\"\nkind = \"expression\"\n",
            $line,
            "\n[integrator]\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n"
        )
    };
}

pub static CASES: &[Case] = &[
    Case {
        area: "scenario value",
        kind: "angular_speed_in_hertz",
        files: &[(
            "s.toml",
            Text(
                "[[rigid_body]]\nname = \"wheel\"\nomega = \"50 Hz\"\n  [[rigid_body.part]]\n  shape = \"cylinder\"\n  radius = \"25 cm\"\n  height = \"10 cm\"\n  mass = \"40 kg\"\n[stop]\nt_max = \"1 s\"\n",
            ),
        )],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "scenario value",
        kind: "bodies_at_a_pair_forces_singular_point",
        files: &[(
            "s.toml",
            Text(
                "dimensions = 2\n[constants]\nk = \"10 N/m\"\nL = \"1 m\"\n[[body]]\nname = \"a\"\nmass = \"1 kg\"\nposition = [\"0 m\", \"0 m\"]\n[[body]]\nname = \"b\"\nmass = \"1 kg\"\nposition = [\"0 m\", \"0 m\"]\n[[force]]\nname = \"bond\"\nkind = \"pair\"\nbetween = [\"a\", \"b\"]\nU = \"k*(r - L)^2/2\"\n[integrator]\nmethod = \"rk4\"\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n",
            ),
        )],
        args: &["run", "s.toml", "--out", "out", "--no-plots"],
        code: 2,
    },
    Case {
        area: "scenario value",
        kind: "negative_gravity",
        files: &[(
            "s.toml",
            Text(
                "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n[[force]]\nkind = \"uniform-gravity\"\ng = \"-9.81 m/s^2\"\n[integrator]\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n",
            ),
        )],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "scenario value",
        kind: "negative_spring_constant",
        files: &[(
            "s.toml",
            Text(
                "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\nposition = \"1 m\"\n[[force]]\nkind = \"spring\"\nk = \"-100 N/m\"\n[integrator]\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n",
            ),
        )],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "scenario value",
        kind: "negative_mass",
        files: &[("s.toml", Text(body_with!("mass = \"-2 kg\"")))],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "scenario value",
        kind: "zero_dt",
        files: &[(
            "s.toml",
            Text(
                "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n[integrator]\ndt = \"0 s\"\n[stop]\nt_max = \"1 s\"\n",
            ),
        )],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "scenario value",
        kind: "unknown_unit",
        files: &[("s.toml", Text(body_with!("mass = \"1 kgg\"")))],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "scenario value",
        kind: "unit_syntax",
        files: &[("s.toml", Text(body_with!("mass = \"1 kg^^2\"")))],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "scenario value",
        kind: "unit_in_reduced_units",
        files: &[(
            "s.toml",
            Text(concat!(
                "units = \"reduced\"\n",
                body_with!("mass = \"1 kg\"")
            )),
        )],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "scenario value",
        kind: "unknown_unit_system",
        files: &[(
            "s.toml",
            Text(concat!(
                "units = \"metric\"\n",
                body_with!("mass = \"1 kg\"")
            )),
        )],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "scenario value",
        kind: "no_number",
        files: &[("s.toml", Text(body_with!("mass = \"kg\"")))],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "scenario value",
        kind: "wrong_dimension",
        files: &[("s.toml", Text(body_with!("mass = \"3 m\"")))],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "scenario value",
        kind: "vector_length",
        files: &[(
            "s.toml",
            Text(body_with!("mass = \"1 kg\"\nposition = [\"1 m\", \"2 m\"]")),
        )],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "scenario value",
        kind: "non_finite_value",
        files: &[(
            "s.toml",
            Text(body_with!("mass = \"1 kg\"\nposition = \"1e999 m\"")),
        )],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "formula in a scenario",
        kind: "undefined_name",
        files: &[("s.toml", Text(force_with!("F = \"-k*xx\"")))],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "formula in a scenario",
        kind: "dimension_mismatch",
        files: &[("s.toml", Text(force_with!("F = \"-k*x + t\"")))],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "formula in a scenario",
        kind: "force_of_wrong_dimension",
        files: &[("s.toml", Text(force_with!("F = \"-k\"")))],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "formula in a scenario",
        kind: "unclosed_paren",
        files: &[("s.toml", Text(force_with!("F = \"-k*(x\"")))],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "formula in a scenario",
        kind: "unknown_function",
        files: &[("s.toml", Text(force_with!("F = \"-k*sinn(x)\"")))],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "formula in a scenario",
        kind: "unit_in_a_formula",
        files: &[(
            "s.toml",
            Text(
                "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n[integrator]\ndt = \"1 ms\"\n[stop]\nwhen = \"x < -1 m\"\n",
            ),
        )],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "formula in a scenario",
        kind: "event_set_unknown_component",
        files: &[(
            "s.toml",
            Text(
                "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n[integrator]\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n[[event]]\nname = \"bounce\"\nfunction = \"x\"\nset = { vy = \"-v\" }\n",
            ),
        )],
        args: &["check", "s.toml"],
        code: 2,
    },
];

//! Scenario files: TOML syntax, the schema (keys, types, kinds, names) and reading the file.

use super::case::{Case, Contents::Text, assert_cases};

#[test]
fn scenario_structure_messages() {
    assert_cases(CASES);
}

pub static CASES: &[Case] = &[
    Case {
        area: "scenario",
        kind: "toml_syntax",
        files: &[(
            "s.toml",
            Text("dimensions = 1\n[[body]]\nname = \"ball\"\nmass = = \"1 kg\"\n"),
        )],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "scenario",
        kind: "unknown_key",
        files: &[(
            "s.toml",
            Text(
                "dimensions = 1\n[[body]]\nname = \"ball\"\nmasss = \"1 kg\"\n[integrator]\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n",
            ),
        )],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "scenario",
        kind: "unknown_section",
        files: &[(
            "s.toml",
            Text(
                "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n[integrater]\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n",
            ),
        )],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "scenario",
        kind: "missing_key",
        files: &[(
            "s.toml",
            Text(
                "dimensions = 1\n[[body]]\nname = \"ball\"\nposition = \"1 m\"\n[integrator]\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n",
            ),
        )],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "scenario",
        kind: "no_body",
        files: &[(
            "s.toml",
            Text("dimensions = 1\n[integrator]\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n"),
        )],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "scenario",
        kind: "wrong_type",
        files: &[(
            "s.toml",
            Text(
                "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = true\n[integrator]\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n",
            ),
        )],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "scenario",
        kind: "dimensions_out_of_range",
        files: &[(
            "s.toml",
            Text(
                "dimensions = 4\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n[integrator]\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n",
            ),
        )],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "scenario",
        kind: "duplicate_name",
        files: &[(
            "s.toml",
            Text(
                "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n[[body]]\nname = \"ball\"\nmass = \"2 kg\"\n[integrator]\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n",
            ),
        )],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "scenario",
        kind: "unknown_force_kind",
        files: &[(
            "s.toml",
            Text(
                "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n[[force]]\nname = \"f\"\nkind = \"sprng\"\n[integrator]\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n",
            ),
        )],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "scenario",
        kind: "unknown_body_reference",
        files: &[(
            "s.toml",
            Text(
                "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n[[force]]\nname = \"push\"\nkind = \"expression\"\non = \"bal\"\nF = \"1 N\"\n[integrator]\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n",
            ),
        )],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "scenario",
        kind: "unknown_method",
        files: &[(
            "s.toml",
            Text(
                "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n[integrator]\nmethod = \"rk5\"\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n",
            ),
        )],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "scenario",
        kind: "tolerance_on_fixed_step_method",
        files: &[(
            "s.toml",
            Text(
                "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n[integrator]\nmethod = \"rk4\"\ndt = \"1 ms\"\nrtol = 1e-6\n[stop]\nt_max = \"1 s\"\n",
            ),
        )],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "scenario",
        kind: "unknown_plot",
        files: &[(
            "s.toml",
            Text(
                "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n[integrator]\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n[output]\nplots = [\"q(t)\"]\n",
            ),
        )],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "scenario",
        kind: "file_not_found",
        files: &[],
        args: &["run", "nofile.toml"],
        code: 2,
    },
    Case {
        area: "scenario",
        kind: "not_a_file",
        files: &[],
        args: &["check", "."],
        code: 2,
    },
];

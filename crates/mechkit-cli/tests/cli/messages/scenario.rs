//! Scenario files: TOML syntax, the schema (keys, types, kinds, names) and reading the file.

use super::case::{Case, Contents::Text, assert_cases};

#[test]
fn scenario_structure_messages() {
    assert_cases(CASES);
}

/// A `mechkit check s.toml` case of the area `scenario`.
macro_rules! check {
    ($kind:literal, $text:expr) => {
        Case {
            area: "scenario",
            kind: $kind,
            files: &[("s.toml", Text($text))],
            args: &["check", "s.toml"],
            code: 2,
        }
    };
}

/// One body, a step and a stop time, followed by `$rest`.
macro_rules! ball_and {
    ($rest:literal) => {
        concat!(
            "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n",
            "[integrator]\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n",
            $rest
        )
    };
}

pub static CASES: &[Case] = &[
    check!("toml_duplicate_key", "dimensions = 1\ndimensions = 2\n"),
    check!(
        "unknown_key_listing_the_keys",
        "[[rigid_body]]\nname = \"rod\"\nshape = \"rod\"\n"
    ),
    check!(
        "missing_force_parameter",
        "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n[[force]]\nname = \"s\"\nkind = \"spring\"\n[integrator]\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n"
    ),
    check!(
        "reserved_constant_name",
        "dimensions = 1\n[constants]\nz = \"0 m\"\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n[integrator]\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n"
    ),
    check!(
        "unknown_event_action",
        ball_and!("[[event]]\nname = \"e\"\nfunction = \"x\"\naction = \"halt\"\n")
    ),
    check!(
        "count_on_a_recording_event",
        ball_and!("[[event]]\nname = \"e\"\nfunction = \"x\"\ncount = 3\n")
    ),
    check!("output_every_zero", ball_and!("[output]\nevery = 0\n")),
    check!(
        "unknown_event_check",
        ball_and!("[[event]]\nname = \"e\"\nfunction = \"x\"\ncheck = \"end\"\n")
    ),
    check!(
        "pair_potential_undefined_name",
        "dimensions = 1\n[constants]\neps = \"1e-21 J\"\ns = \"0.34 nm\"\n[[body]]\nname = \"a\"\nmass = \"40 u\"\n[[body]]\nname = \"b\"\nmass = \"40 u\"\nposition = \"0.4 nm\"\n[[force]]\nkind = \"pair\"\nbetween = [\"a\", \"b\"]\nU = \"4*eps*(s/r)^12 - x\"\n[integrator]\ndt = \"1 fs\"\n[stop]\nt_max = \"1 ps\"\n"
    ),
    check!(
        "pair_potential_not_an_energy",
        "dimensions = 1\n[constants]\neps = \"1e-21 J\"\n[[body]]\nname = \"a\"\nmass = \"40 u\"\n[[body]]\nname = \"b\"\nmass = \"40 u\"\nposition = \"0.4 nm\"\n[[force]]\nkind = \"pair\"\nbetween = \"all\"\nU = \"eps/r\"\n[integrator]\ndt = \"1 fs\"\n[stop]\nt_max = \"1 ps\"\n"
    ),
    check!(
        "restitution_out_of_range",
        "dimensions = 2\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\nradius = \"1 cm\"\n[contact]\nrestitution = 1.5\n[integrator]\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n"
    ),
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
        kind: "analytic_curve_of_no_plot",
        files: &[(
            "s.toml",
            Text(
                "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n[integrator]\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n[output.analytic]\n\"v(x)\" = \"-9.8*t\"\n",
            ),
        )],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "scenario",
        kind: "analytic_curve_unknown_name",
        files: &[(
            "s.toml",
            Text(
                "dimensions = 1\n[constants]\ng = \"9.8 m/s^2\"\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n[integrator]\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n[output.analytic]\n\"v(t)\" = \"-g*t + v0\"\n",
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

//! Command-line usage: the argument parser's errors and mechkit's own checks of flag values.

use super::case::{Case, Contents::Text, assert_cases};

#[test]
fn command_line_messages() {
    assert_cases(CASES);
}

/// A case without input files.
macro_rules! flags {
    ($kind:literal $(, $arg:literal)*) => {
        Case {
            area: "command line",
            kind: $kind,
            files: &[],
            args: &[$($arg),*],
            code: 2,
        }
    };
}

pub static CASES: &[Case] = &[
    flags!("unknown_subcommand", "simulate"),
    flags!("missing_argument", "run"),
    flags!("unknown_flag", "check", "s.toml", "--verbose"),
    flags!("flag_without_value", "integrate", "x", "--from"),
    flags!("invalid_choice", "work", "f.dat", "--of", "speed"),
    flags!("not_a_number", "md", "--steps", "many"),
    Case {
        area: "command line",
        kind: "compare_unknown_method",
        files: &[(
            "s.toml",
            Text(
                "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n[integrator]\ndt = \"0.1 s\"\n[stop]\nt_max = \"1 s\"\n",
            ),
        )],
        args: &["run", "s.toml", "--compare-methods", "rk5"],
        code: 2,
    },
    Case {
        area: "command line",
        kind: "compare_dt_not_a_time",
        files: &[(
            "s.toml",
            Text(
                "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n[integrator]\ndt = \"0.1 s\"\n[stop]\nt_max = \"1 s\"\n",
            ),
        )],
        args: &["run", "s.toml", "--compare-methods", "rk4", "--dt", "1 m"],
        code: 2,
    },
    flags!("point_masses_without_positions", "com", "--mass", "1 kg"),
    flags!(
        "point_masses_mixed_dimensions",
        "com",
        "--mass",
        "1 kg@0,0",
        "--mass",
        "2 kg@1"
    ),
    flags!("point_mass_not_a_mass", "com", "--mass", "1 m@0"),
    flags!("no_bodies", "com"),
    flags!(
        "point_masses_with_mark",
        "com",
        "--mass",
        "1 kg",
        "--at",
        "0 m",
        "--mark",
        "out.png"
    ),
    flags!(
        "point_masses_with_about",
        "com",
        "--mass",
        "1 kg",
        "--at",
        "0 m",
        "--about",
        "1 m"
    ),
];

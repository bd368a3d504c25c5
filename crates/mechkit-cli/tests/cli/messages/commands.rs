//! The other commands' own checks of their flags: sweeps, rockets, friction, spin, collisions,
//! rotation, beads, power.

use super::case::{Case, Contents::Text, assert_cases};

#[test]
fn command_messages() {
    assert_cases(CASES);
}

/// A scenario with one constant, `v0`, for the sweep cases.
const THROW: &str = "dimensions = 1\n[constants]\nv0 = \"1 m/s\"\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\nvelocity = \"v0\"\n[integrator]\ndt = \"0.1 s\"\n[stop]\nt_max = \"1 s\"\n";

/// A `mechkit sweep s.toml …` case.
macro_rules! sweep {
    ($kind:literal $(, $arg:literal)*) => {
        Case {
            area: "sweep",
            kind: $kind,
            files: &[("s.toml", Text(THROW))],
            args: &["sweep", "s.toml" $(, $arg)*],
            code: 2,
        }
    };
}

/// A case of another command, without files.
macro_rules! command {
    ($kind:literal $(, $arg:literal)*) => {
        Case {
            area: "command",
            kind: $kind,
            files: &[],
            args: &[$($arg),*],
            code: 2,
        }
    };
}

pub static CASES: &[Case] = &[
    sweep!("range_syntax", "--set", "v0=0:5"),
    sweep!("unknown_constant", "--set", "vv=0:5:3"),
    sweep!("value_without_number", "--set", "v0=a:5:3"),
    sweep!("shard_out_of_range", "--set", "v0=0:5:3", "--shard", "3/2"),
    Case {
        area: "sweep",
        kind: "merge_output_is_a_part",
        files: &[
            ("sweep.part1.csv", Text("run\n0\n")),
            ("sweep.part2.csv", Text("run\n1\n")),
        ],
        args: &[
            "sweep-merge",
            "sweep.part1.csv",
            "sweep.part2.csv",
            "-o",
            "./sweep.part2.csv",
        ],
        code: 2,
    },
    Case {
        area: "sweep",
        kind: "merge_missing_part",
        files: &[],
        args: &["sweep-merge", "sweep.part1.csv"],
        code: 2,
    },
    command!(
        "rocket_burnout_above_ignition",
        "rocket",
        "--m0",
        "1000 kg",
        "--m1",
        "2000 kg",
        "--mass-rate",
        "10 kg/s",
        "--exhaust-speed",
        "2 km/s"
    ),
    command!(
        "friction_negative_mass",
        "friction",
        "--mass=-1 kg",
        "--mu-s",
        "0.6",
        "--mu-d",
        "0.4"
    ),
    command!(
        "spin_component_count",
        "spin",
        "--moments",
        "1, 2",
        "--omega",
        "0.01, 1, 0.01",
        "--t-max",
        "100"
    ),
    command!(
        "collide_restitution_out_of_range",
        "collide",
        "--m1",
        "0.2 kg",
        "--v1",
        "15 m/s",
        "--m2",
        "1.5 kg",
        "--v2",
        "0",
        "--restitution",
        "2"
    ),
    command!(
        "rotation_wrong_dimension",
        "rotation",
        "--omega0",
        "1000 rpm",
        "--omega1",
        "2000 m/s",
        "--time",
        "15 s"
    ),
    command!(
        "bead_negative_radius",
        "bead",
        "--circle=-1 m",
        "--side",
        "outside",
        "--start",
        "0",
        "--speed",
        "0.1 m/s",
        "--t-max",
        "3 s"
    ),
    command!(
        "bead_curve_with_a_step",
        "bead",
        "--curve",
        "-floor(x)",
        "--start",
        "0.5",
        "--speed",
        "1 m/s",
        "--t-max",
        "3 s",
        "--no-plots"
    ),
    command!(
        "work_path_and_field_dimensions",
        "work",
        "--field",
        "y, -x",
        "--path",
        "cos(s)",
        "--param",
        "s=0:1"
    ),
    command!(
        "work_path_without_parameter",
        "work",
        "--field",
        "y, -x",
        "--path",
        "cos(s), sin(s)"
    ),
    command!(
        "potential_range_reversed",
        "potential",
        "x^2",
        "--range",
        "2:-1"
    ),
    command!(
        "potential_range_uses_an_unknown_name",
        "potential",
        "x^2",
        "--range",
        "0:a"
    ),
    command!(
        "integrate_unknown_rule",
        "integrate",
        "x",
        "--from",
        "0",
        "--to",
        "1",
        "--method",
        "trapezoidal"
    ),
    command!(
        "integrate_zero_intervals",
        "integrate",
        "x",
        "--from",
        "0",
        "--to",
        "1",
        "--method",
        "left",
        "--n",
        "0"
    ),
    command!(
        "power_negative_mass",
        "power",
        "--power",
        "20 kW",
        "--mass=-200 kg",
        "--at",
        "5 s"
    ),
    command!(
        "collide_negative_g",
        "collide",
        "--m1",
        "1",
        "--v1",
        "1",
        "--m2",
        "2",
        "--v2",
        "0",
        "-e",
        "1",
        "--g=-9.8"
    ),
    command!("gallery_unknown_case", "gallery", "c99"),
    command!("gallery_ambiguous_case", "gallery", "c1"),
    command!("gallery_root_without_cases", "gallery", "--root", "."),
    Case {
        area: "command",
        kind: "gallery_report_without_end_marker",
        files: &[(
            "v.md",
            Text(
                "# Validation\n<!-- gallery:begin (generated by `mechkit gallery --report`; do not edit) -->\n",
            ),
        )],
        args: &["gallery", "--report", "v.md", "--no-plots"],
        code: 2,
    },
];

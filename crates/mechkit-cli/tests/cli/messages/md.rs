//! `mechkit md`: flags and particle files; each message names the flag it is about.

use super::case::{Case, Contents::Text, assert_cases};

#[test]
fn md_messages() {
    assert_cases(CASES);
}

/// A `mechkit md …` case without files.
macro_rules! md {
    ($kind:literal $(, $arg:literal)*) => {
        Case {
            area: "md",
            kind: $kind,
            files: &[],
            args: &["md" $(, $arg)*],
            code: 2,
        }
    };
}

/// A `mechkit md --positions p.csv …` case on the positions file `text`.
macro_rules! positions {
    ($kind:literal, $name:literal, $text:literal $(, $arg:literal)*) => {
        Case {
            area: "md",
            kind: $kind,
            files: &[($name, Text($text))],
            args: &["md", "--positions", $name $(, $arg)*],
            code: 2,
        }
    };
}

pub static CASES: &[Case] = &[
    md!("unknown_lattice", "--lattice", "bcc"),
    md!("no_cells", "--cells", "0"),
    md!("density_not_positive", "--density=-1"),
    md!("density_negative_without_equals", "--density", "-1"),
    md!("cells_negative", "--cells", "-1"),
    md!("time_step_not_positive", "--dt", "0"),
    md!("box_too_small", "--lattice", "square", "--cells", "2"),
    md!("unknown_potential", "--potential", "morse"),
    md!("too_few_particles", "--lattice", "chain", "--cells", "1"),
    md!("positions_file_not_found", "--positions", "nofile.csv"),
    md!("neigh_every_zero", "--neigh-every", "0"),
    md!("neigh_check_not_yes_or_no", "--neigh-check", "maybe"),
    Case {
        area: "md",
        kind: "dangerous_builds_warning",
        files: &[],
        args: &[
            "md",
            "--cells",
            "4",
            "--steps",
            "40",
            "--neigh-every",
            "20",
            "--neigh-check",
            "no",
            "-q",
        ],
        code: 0,
    },
    Case {
        area: "md",
        kind: "export_lammps_over_a_file",
        files: &[("lmp", Text("not a directory\n"))],
        args: &[
            "md",
            "--cells",
            "4",
            "--steps",
            "1",
            "--export-lammps",
            "lmp",
        ],
        code: 2,
    },
    positions!(
        "positions_not_a_number",
        "p.csv",
        "0,0,0\n1,a,1\n",
        "--box",
        "10"
    ),
    positions!(
        "positions_column_count",
        "p.csv",
        "0,0,0\n1,1\n",
        "--box",
        "10"
    ),
    positions!(
        "positions_too_many_columns",
        "p.csv",
        "0,0,0,0\n",
        "--box",
        "10"
    ),
    positions!("positions_empty", "p.csv", "# nothing\n", "--box", "10"),
    positions!(
        "xyz_count",
        "p.xyz",
        "two\ncomment\nAr 0 0 0\n",
        "--box",
        "10"
    ),
    positions!(
        "xyz_truncated",
        "p.xyz",
        "2\ncomment\nAr 0 0 0\n",
        "--box",
        "10"
    ),
    positions!(
        "xyz_short_line",
        "p.xyz",
        "1\ncomment\nAr 0 0\n",
        "--box",
        "10"
    ),
    positions!("periodic_box_needs_lengths", "p.csv", "0,0,0\n1,1,1\n"),
    positions!(
        "box_length_count",
        "p.csv",
        "0,0,0\n1,1,1\n",
        "--box",
        "1,2"
    ),
    positions!(
        "unknown_boundary",
        "p.csv",
        "0,0,0\n1,1,1\n",
        "--boundary",
        "wall"
    ),
    Case {
        area: "md",
        kind: "velocities_count",
        files: &[
            ("p.csv", Text("0,0,0\n1,1,1\n")),
            ("v.csv", Text("0,0,0\n")),
        ],
        args: &[
            "md",
            "--positions",
            "p.csv",
            "--velocities",
            "v.csv",
            "--box",
            "10",
        ],
        code: 2,
    },
];

//! Runs that end badly (exit 1, the output so far kept), warnings about how a run is bounded,
//! and output that cannot be written (exit 2).

use super::case::{
    Case,
    Contents::{Folder, Text},
    assert_cases,
};

#[test]
fn runtime_messages() {
    assert_cases(CASES);
}

pub static CASES: &[Case] = &[
    Case {
        area: "run",
        kind: "diverged",
        files: &[(
            "s.toml",
            Text(
                "dimensions = 1\n[constants]\nc = \"1 N*m\"\n[[body]]\nname = \"probe\"\nmass = \"1 kg\"\n[[body]]\nname = \"bead\"\nmass = \"1 kg\"\nposition = \"1 m\"\nvelocity = \"-1 m/s\"\n[[force]]\nname = \"repel\"\nkind = \"expression\"\non = \"probe\"\nF = \"c/bead.x\"\n[integrator]\nmethod = \"euler\"\ndt = \"0.25 s\"\n[stop]\nt_max = \"10 s\"\n",
            ),
        )],
        args: &["run", "s.toml", "--out", "out", "--no-plots"],
        code: 1,
    },
    Case {
        area: "run",
        kind: "step_too_small",
        files: &[(
            "s.toml",
            Text(
                "dimensions = 1\n[constants]\nk = \"1e12 N/m\"\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\nposition = \"1 m\"\n[[force]]\nname = \"stiff\"\nkind = \"expression\"\nF = \"-k*x\"\n[integrator]\nmethod = \"dopri5\"\nrtol = 1e-10\natol = 1e-12\nh_min = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n",
            ),
        )],
        args: &["run", "s.toml", "--out", "out", "--no-plots"],
        code: 1,
    },
    Case {
        area: "run",
        kind: "zeno",
        files: &[(
            "s.toml",
            Text(
                "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\nposition = \"1 m\"\n[[force]]\nname = \"gravity\"\nkind = \"uniform-gravity\"\ng = \"9.81 m/s^2\"\n[integrator]\nmethod = \"dopri5\"\n[[event]]\nname = \"bounce\"\nfunction = \"x\"\ndirection = \"falling\"\nset = { v = \"-0.9*v\" }\n[stop]\nt_max = \"100 s\"\n",
            ),
        )],
        args: &["run", "s.toml", "--out", "out", "--no-plots"],
        code: 1,
    },
    Case {
        area: "run",
        kind: "zeno_at_once",
        files: &[(
            "s.toml",
            Text(
                "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\nposition = \"1 m\"\n[[force]]\nname = \"gravity\"\nkind = \"uniform-gravity\"\ng = \"9.81 m/s^2\"\n[integrator]\nmethod = \"dopri5\"\n[[event]]\nname = \"bounce\"\nfunction = \"x\"\ndirection = \"falling\"\nset = { v = \"-0.5*v\" }\n[stop]\nt_max = \"100 s\"\n",
            ),
        )],
        args: &["run", "s.toml", "--out", "out", "--no-plots"],
        code: 1,
    },
    Case {
        area: "run",
        kind: "no_t_max_warning",
        files: &[(
            "s.toml",
            Text(
                "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n[[force]]\nname = \"gravity\"\nkind = \"uniform-gravity\"\ng = \"9.81 m/s^2\"\n[integrator]\ndt = \"1 ms\"\n[stop]\nwhen = \"x < -1\"\n",
            ),
        )],
        args: &["check", "s.toml"],
        code: 0,
    },
    Case {
        area: "output",
        kind: "unwritable_out",
        files: &[
            (
                "s.toml",
                Text(
                    "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n[integrator]\ndt = \"0.1 s\"\n[stop]\nt_max = \"1 s\"\n",
                ),
            ),
            ("afile", Text("a regular file, not a directory\n")),
        ],
        args: &["run", "s.toml", "--out", "afile/sub"],
        code: 2,
    },
    Case {
        area: "output",
        kind: "unwritable_md_out",
        files: &[("afile", Text("a regular file, not a directory\n"))],
        args: &[
            "md",
            "--cells",
            "4",
            "--lattice",
            "sc",
            "--density",
            "0.1",
            "--out",
            "afile/sub",
        ],
        code: 2,
    },
    Case {
        area: "output",
        kind: "output_not_a_regular_file",
        files: &[
            (
                "s.toml",
                Text(
                    "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n[integrator]\ndt = \"0.1 s\"\n[stop]\nt_max = \"1 s\"\n",
                ),
            ),
            ("out/summary.json", Folder),
        ],
        args: &["run", "s.toml", "--out", "out"],
        code: 2,
    },
    Case {
        area: "output",
        kind: "plot_not_a_regular_file",
        files: &[
            (
                "s.toml",
                Text(
                    "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n[integrator]\ndt = \"0.1 s\"\n[stop]\nt_max = \"1 s\"\n[output]\nplots = [\"x(t)\"]\n",
                ),
            ),
            ("out/x_t.svg", Folder),
        ],
        args: &["run", "s.toml", "--out", "out"],
        code: 2,
    },
];

//! Resource limits: output size, the step limit, the size of a scenario file.

use super::case::{
    Case,
    Contents::{Bytes, Text},
    assert_cases,
};

#[test]
fn limit_messages() {
    assert_cases(CASES);
}

const FALL: &str = "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\nposition = \"100 m\"\n[[force]]\nname = \"gravity\"\nkind = \"uniform-gravity\"\ng = \"9.81 m/s^2\"\n[integrator]\nmethod = \"rk4\"\ndt = \"1 ms\"\n[stop]\nt_max = \"4 s\"\n";

/// 594 bytes of JPEG claiming 361 megapixels (a fuzz finding).
fn bomb() -> Vec<u8> {
    std::fs::read(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../fuzz/regressions/image/jpeg-bomb-361-megapixels.jpg"),
    )
    .expect("the saved fuzz input")
}

fn huge() -> Vec<u8> {
    "# not a scenario\n".repeat(1_000_000).into_bytes()
}

pub static CASES: &[Case] = &[
    Case {
        area: "limits",
        kind: "output_limit",
        files: &[("s.toml", Text(FALL))],
        args: &[
            "run",
            "s.toml",
            "--out",
            "out",
            "--no-plots",
            "--max-output",
            "20kB",
        ],
        code: 1,
    },
    Case {
        area: "limits",
        kind: "md_output_limit",
        files: &[],
        args: &[
            "md",
            "--cells",
            "4",
            "--steps",
            "100",
            "--xyz-every",
            "5",
            "--out",
            "out",
            "--max-output",
            "60kB",
        ],
        code: 1,
    },
    Case {
        area: "limits",
        kind: "max_output_flag",
        files: &[("s.toml", Text(FALL))],
        args: &["run", "s.toml", "--out", "out", "--max-output", "20 kX"],
        code: 2,
    },
    Case {
        area: "limits",
        kind: "max_size_value",
        files: &[(
            "s.toml",
            Text(
                "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n[integrator]\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n[output]\nmax_size = \"lots\"\n",
            ),
        )],
        args: &["run", "s.toml", "--out", "out"],
        code: 2,
    },
    Case {
        area: "limits",
        kind: "max_size_type",
        files: &[(
            "s.toml",
            Text(
                "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n[integrator]\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n[output]\nmax_size = 1.5\n",
            ),
        )],
        args: &["run", "s.toml", "--out", "out"],
        code: 2,
    },
    Case {
        area: "limits",
        kind: "step_limit_before_t_max",
        files: &[(
            "s.toml",
            Text(
                "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n[integrator]\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\nmax_steps = 50\n",
            ),
        )],
        args: &["run", "s.toml", "--out", "out", "--no-plots"],
        code: 0,
    },
    Case {
        area: "limits",
        kind: "scenario_too_large",
        files: &[("big.toml", Bytes(huge))],
        args: &["check", "big.toml"],
        code: 2,
    },
    Case {
        area: "limits",
        kind: "sweep_range_too_long",
        files: &[("s.toml", Text(SWEEP))],
        args: &[
            "sweep",
            "s.toml",
            "--set",
            "v0=0:5:100000000000",
            "--out",
            "out",
        ],
        code: 2,
    },
    Case {
        area: "limits",
        kind: "sweep_grid_too_large",
        files: &[("s.toml", Text(SWEEP))],
        args: &[
            "sweep",
            "s.toml",
            "--set",
            "v0=0:5:10000",
            "--set",
            "g=1:2:10000",
            "--out",
            "out",
        ],
        code: 2,
    },
    Case {
        area: "limits",
        kind: "md_too_many_atoms",
        files: &[],
        args: &["md", "--cells", "2000", "--steps", "1"],
        code: 2,
    },
    Case {
        area: "limits",
        kind: "md_too_many_threads",
        files: &[],
        args: &["md", "--cells", "8", "--steps", "1", "--threads", "100000"],
        code: 2,
    },
    Case {
        area: "limits",
        kind: "sweep_too_many_threads",
        files: &[("s.toml", Text(SWEEP))],
        args: &[
            "sweep",
            "s.toml",
            "--set",
            "v0=0:5:3",
            "--threads",
            "1000",
            "--out",
            "out",
        ],
        code: 2,
    },
    Case {
        area: "limits",
        kind: "formula_too_deep",
        files: &[("s.toml", Text(FLAT_FORCE))],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "limits",
        kind: "fixed_steps_beyond_the_bound",
        files: &[("s.toml", Text(FAR_T_MAX))],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "limits",
        kind: "subnormal_dt",
        files: &[("s.toml", Text(SUBNORMAL_DT))],
        args: &["run", "s.toml", "--out", "out"],
        code: 2,
    },
    Case {
        area: "limits",
        kind: "max_steps_beyond_the_bound",
        files: &[("s.toml", Text(HUGE_MAX_STEPS))],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "limits",
        kind: "md_too_many_steps",
        files: &[],
        args: &["md", "--steps", "1000000000000000000"],
        code: 2,
    },
    Case {
        area: "limits",
        kind: "integrate_too_many_evaluations",
        files: &[],
        args: &[
            "integrate",
            "x^2",
            "--from",
            "0",
            "--to",
            "1",
            "--method",
            "trapezoid",
            "--n",
            "1000000000000",
        ],
        code: 2,
    },
    Case {
        area: "limits",
        kind: "rtol_below_double_precision",
        files: &[],
        args: &[
            "roll", "--body", "hoop", "--radius", "1", "--mass", "1", "--slope", "0.3", "--mu",
            "0.3", "--v0", "2", "--omega0", "-3", "--t-max", "3", "--rtol", "1e-100",
        ],
        code: 2,
    },
    Case {
        area: "limits",
        kind: "model_fixed_steps_beyond_the_budget",
        files: &[],
        args: &[
            "spin",
            "--moments",
            "1, 2, 3",
            "--omega",
            "0.01, 1, 0.01",
            "--t-max",
            "1e300",
            "--method",
            "rk4",
            "--dt",
            "1 ms",
        ],
        code: 2,
    },
    Case {
        area: "limits",
        kind: "animation_speed_out_of_range",
        files: &[("s.toml", Text(FALL))],
        args: &[
            "animate", "s.toml", "-o", "an", "-f", "html", "--speed", "1e-300",
        ],
        code: 2,
    },
    Case {
        area: "limits",
        kind: "image_too_large",
        files: &[("photo.jpg", Bytes(bomb))],
        args: &["com", "photo.jpg"],
        code: 2,
    },
];

const SWEEP: &str = "dimensions = 1\n[constants]\nv0 = \"1 m/s\"\ng = \"9.81 m/s^2\"\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\nvelocity = \"v0\"\n[[force]]\nname = \"gravity\"\nkind = \"uniform-gravity\"\ng = \"g\"\n[integrator]\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n";

/// A force of 300 terms: 300 levels deep.
const FLAT_FORCE: &str = "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n[[force]]\nname = \"f\"\nkind = \"expression\"\nF = \"-m*(1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5+1e-5)\"\n[integrator]\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n";

const FAR_T_MAX: &str = "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n[integrator]\nmethod = \"rk4\"\ndt = \"1 ms\"\n[stop]\nt_max = \"1e300 s\"\n";

const SUBNORMAL_DT: &str = "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n[integrator]\nmethod = \"rk4\"\ndt = \"1e-320 s\"\n[stop]\nt_max = \"1 s\"\n";

const HUGE_MAX_STEPS: &str = "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n[integrator]\nmethod = \"rk4\"\ndt = \"1 ms\"\n[stop]\nmax_steps = 9200000000000000000\n";

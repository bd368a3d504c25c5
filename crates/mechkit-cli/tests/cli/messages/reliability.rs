//! Issue 26's messages: step limits in the wrong order, a mass whose reciprocal overflows, an
//! observable mixing dimensions, bodies overlapping at the start, an image claiming billions of
//! pixels, sample counts and output intervals past their bounds.

use super::case::{
    Case,
    Contents::{Bytes, Text},
    assert_cases,
};

#[test]
fn reliability_messages() {
    assert_cases(CASES);
}

const H_MIN_ABOVE_H_MAX: &str = "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\nposition = \"1 m\"\n[[force]]\nkind = \"uniform-gravity\"\n[integrator]\nmethod = \"dopri5\"\nh_min = \"1 s\"\nh_max = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n";

const SUBNORMAL_MASS: &str = "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1e-320 kg\"\nposition = \"1 m\"\n[[force]]\nkind = \"uniform-gravity\"\n[integrator]\nmethod = \"rk4\"\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n";

const OBSERVE_MIXED: &str = "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\nposition = \"1 m\"\n[[force]]\nkind = \"uniform-gravity\"\n[integrator]\nmethod = \"rk4\"\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n[observe]\nbad = \"max(x) + final(v)\"\n";

const OVERLAP: &str = "dimensions = 1\n[[body]]\nname = \"a\"\nmass = \"1 kg\"\nposition = \"0 m\"\nradius = \"1 m\"\n[[body]]\nname = \"b\"\nmass = \"1 kg\"\nposition = \"1 m\"\nradius = \"0.5 m\"\n[contact]\nrestitution = 1\n[integrator]\nmethod = \"rk4\"\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n";

const TINY_INTERVAL: &str = "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\nposition = \"1 m\"\n[[force]]\nkind = \"uniform-gravity\"\n[integrator]\nmethod = \"rk4\"\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n[output]\ninterval = \"1e-300 s\"\n";

/// A PNG header claiming 2147483647 × 1 pixels.
fn wide_png() -> Vec<u8> {
    let mut out = b"\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR".to_vec();
    out.extend(2_147_483_647u32.to_be_bytes());
    out.extend(1u32.to_be_bytes());
    out.extend([8, 2, 0, 0, 0, 0, 0, 0, 0]);
    out
}

pub static CASES: &[Case] = &[
    Case {
        area: "reliability",
        kind: "h_min_above_h_max",
        files: &[("s.toml", Text(H_MIN_ABOVE_H_MAX))],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "reliability",
        kind: "subnormal_mass",
        files: &[("s.toml", Text(SUBNORMAL_MASS))],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "reliability",
        kind: "observe_mixed_dimensions",
        files: &[("s.toml", Text(OBSERVE_MIXED))],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "reliability",
        kind: "bodies_overlap_at_start",
        files: &[("s.toml", Text(OVERLAP))],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "reliability",
        kind: "output_interval_too_small",
        files: &[("s.toml", Text(TINY_INTERVAL))],
        args: &["check", "s.toml"],
        code: 2,
    },
    Case {
        area: "reliability",
        kind: "image_header_too_large",
        files: &[("wide.png", Bytes(wide_png))],
        args: &["com", "wide.png"],
        code: 2,
    },
    Case {
        area: "reliability",
        kind: "potential_samples_too_many",
        files: &[],
        args: &[
            "potential",
            "x^2",
            "--range",
            "-1:1",
            "--samples",
            "10000001",
        ],
        code: 2,
    },
    Case {
        area: "reliability",
        kind: "spin_samples_too_many",
        files: &[],
        args: &[
            "spin",
            "--moments",
            "1,2,3",
            "--omega",
            "1,0,0",
            "--t-max",
            "1",
            "--samples",
            "10000001",
        ],
        code: 2,
    },
];

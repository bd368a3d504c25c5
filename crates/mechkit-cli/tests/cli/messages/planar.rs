//! Mechanisms in a plane: free rigid bodies and joints (docs/scenario.md §6.2).

use super::case::{Case, Contents::Text, assert_cases};

#[test]
fn planar_messages() {
    assert_cases(CASES);
}

/// A `mechkit check s.toml` case of the area `planar`.
macro_rules! check {
    ($kind:literal, $text:expr) => {
        Case {
            area: "planar",
            kind: $kind,
            files: &[("s.toml", Text($text))],
            args: &["check", "s.toml"],
            code: 2,
        }
    };
}

/// A rod in a plane with a step and a stop time, followed by `$rest`.
macro_rules! rod_and {
    ($rest:literal) => {
        concat!(
            "dimensions = 2\n[[rigid_body]]\nname = \"rod\"\nmass = \"1 kg\"\n",
            "inertia = \"0.1 kg m^2\"\npoints = { tip = [\"0 m\", \"0.5 m\"] }\n",
            "[integrator]\ndt = \"1 ms\"\n[stop]\nt_max = \"1 s\"\n",
            $rest
        )
    };
}

pub static CASES: &[Case] = &[
    check!(
        "joint_anchor_not_a_body",
        rod_and!("[[joint]]\nkind = \"hinge\"\na = \"rdo.tip\"\n")
    ),
    check!(
        "joint_point_not_defined",
        rod_and!("[[joint]]\nkind = \"hinge\"\na = \"rod.end\"\n")
    ),
    check!(
        "joint_kind_unknown",
        rod_and!("[[joint]]\nkind = \"hing\"\na = \"rod.tip\"\n")
    ),
    check!(
        "friction_kinetic_above_static",
        rod_and!("[[joint]]\nkind = \"contact\"\non = \"rod.tip\"\nmu_s = 0.2\nmu_k = 0.5\n")
    ),
    check!(
        "joint_names_one_body_twice",
        rod_and!("[[joint]]\nkind = \"rod\"\na = \"rod.tip\"\nb = \"rod\"\n")
    ),
    check!(
        "joint_name_taken_by_a_body",
        rod_and!("[[joint]]\nname = \"rod\"\nkind = \"hinge\"\na = \"rod.tip\"\n")
    ),
    check!(
        "joint_without_a_plane",
        "dimensions = 1\n[[body]]\nname = \"ball\"\nmass = \"1 kg\"\n[[joint]]\nkind = \"rod\"\na = \"ball\"\nb = \"0 m\"\n[integrator]\ndt = \"1 ms\"\n"
    ),
    check!(
        "rigid_body_in_space_with_impossible_moments",
        "dimensions = 3\n[[rigid_body]]\nname = \"top\"\nmass = \"1 kg\"\ninertia = [\"1 kg m^2\", \"1 kg m^2\", \"3 kg m^2\"]\n[integrator]\ndt = \"1 ms\"\n"
    ),
    check!(
        "joint_violated_at_the_start",
        rod_and!(
            "[[joint]]\nkind = \"contact\"\non = \"rod.tip\"\nsurface = { point = [\"0 m\", \"1 m\"] }\n"
        )
    ),
    check!(
        "planar_rigid_body_without_inertia",
        "dimensions = 2\n[[rigid_body]]\nname = \"disk\"\nmass = \"1 kg\"\n[integrator]\ndt = \"1 ms\"\n"
    ),
];

//! Body files and meshes (`mechkit com BODYFILE`, `mechkit inertia BODYFILE`).

use super::case::{Case, Contents::Text, assert_cases};

#[test]
fn body_file_messages() {
    assert_cases(CASES);
}

/// A `mechkit com b.toml` case on the body file `text`.
macro_rules! com {
    ($kind:literal, $text:literal) => {
        Case {
            area: "body file",
            kind: $kind,
            files: &[("b.toml", Text($text))],
            args: &["com", "b.toml"],
            code: 2,
        }
    };
}

pub static CASES: &[Case] = &[
    com!("unknown_shape", "[[part]]\nshape = \"sphre\"\n"),
    com!(
        "wrong_dimension",
        "[[part]]\nshape = \"sphere\"\nradius = \"2 kg\"\nmass = 1\n"
    ),
    com!(
        "key_of_another_shape",
        "[[part]]\nshape = \"disk\"\nradius = 1\nlength = 2\nmass = 1\n"
    ),
    com!(
        "density_of_wrong_kind",
        "[[part]]\nshape = \"plate\"\nwidth = 1\nheight = 1\ndensity = \"7800 kg/m^3\"\n"
    ),
    com!(
        "no_mass_or_density",
        "[[part]]\nshape = \"box\"\nsize = [1, 1, 1]\n"
    ),
    com!(
        "holes_cancel_the_mass",
        "[[part]]\nshape = \"box\"\nsize = [1, 1, 1]\nmass = 1\n[[part]]\nshape = \"box\"\nsize = [1, 1, 1]\nmass = 1\nhole = true\n"
    ),
    com!(
        "hole_outside_the_body",
        "[[part]]\nshape = \"box\"\nsize = [\"10 cm\", \"10 cm\", \"10 cm\"]\nmass = 1\n[[part]]\nshape = \"box\"\nsize = [\"5 cm\", \"5 cm\", \"5 cm\"]\nposition = [\"20 cm\", \"20 cm\", \"20 cm\"]\nmass = 1\nhole = true\n"
    ),
    com!(
        "self_intersecting_polygon",
        "[[part]]\nshape = \"polygon\"\nvertices = [[0, 0], [1, 1], [1, 0], [0, 1]]\nmass = 1\n"
    ),
    com!(
        "degenerate_triangle",
        "[[part]]\nshape = \"triangle\"\nvertices = [[0, 0], [1, 1], [2, 2]]\nmass = 1\n"
    ),
    com!(
        "open_mesh",
        "[[part]]\nshape = \"mesh\"\nvertices = [[0,0,0],[1,0,0],[0,1,0],[0,0,1]]\nfaces = [[1,3,2],[1,2,4],[1,4,3]]\nmass = 1\n"
    ),
    com!(
        "missing_mesh_file",
        "[[part]]\nshape = \"mesh\"\nfile = \"missing.obj\"\nmass = 1\n"
    ),
    Case {
        area: "body file",
        kind: "bad_obj_line",
        files: &[
            (
                "tet.obj",
                Text("v 0 0 0\nv 1 0 0\nv 0 one 0\nv 0 0 1\nf 1 3 2\n"),
            ),
            (
                "b.toml",
                Text("[[part]]\nshape = \"mesh\"\nfile = \"tet.obj\"\nmass = 1\n"),
            ),
        ],
        args: &["com", "b.toml"],
        code: 2,
    },
    Case {
        area: "body file",
        kind: "axis_without_length",
        files: &[("b.toml", Text("[[part]]\nshape = \"point\"\nmass = 1\n"))],
        args: &["inertia", "b.toml", "--axis", "0, 0, 0"],
        code: 2,
    },
    Case {
        area: "body file",
        kind: "unit_of_wrong_kind",
        files: &[("b.toml", Text("[[part]]\nshape = \"point\"\nmass = 1\n"))],
        args: &["inertia", "b.toml", "--in", "kg"],
        code: 2,
    },
];

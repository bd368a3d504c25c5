//! Mass properties: analytic shapes against exact polygon and mesh formulas (with the
//! measured convergence order of fine discretisations), composites with holes, and the
//! properties every inertia tensor must have.

mod properties;
mod shapes;

use mechkit::mass::{MassProperties, Mat3, TriangleMesh, Vec3};

/// Largest relative difference of mass, centre of mass and inertia, scaled by the body's size.
pub fn difference(a: &MassProperties, b: &MassProperties) -> f64 {
    let size = a.inertia.norm().max(1e-300);
    let length = (size / a.mass.abs()).sqrt();
    ((a.mass - b.mass).abs() / a.mass.abs())
        .max((a.centre_of_mass - b.centre_of_mass).norm() / length)
        .max((a.inertia - b.inertia).norm() / size)
}

/// A closed mesh of a sphere of radius `r`: `rings` bands of latitude, `segments` around.
pub fn uv_sphere(r: f64, rings: usize, segments: usize) -> TriangleMesh {
    use std::f64::consts::{PI, TAU};
    let mut v = vec![Vec3::new(0.0, 0.0, r)];
    for i in 1..rings {
        let theta = PI * i as f64 / rings as f64;
        for j in 0..segments {
            let phi = TAU * j as f64 / segments as f64;
            v.push(
                r * Vec3::new(
                    theta.sin() * phi.cos(),
                    theta.sin() * phi.sin(),
                    theta.cos(),
                ),
            );
        }
    }
    v.push(Vec3::new(0.0, 0.0, -r));
    let south = v.len() - 1;
    let at = |i: usize, j: usize| 1 + (i - 1) * segments + j % segments;
    let mut f = Vec::new();
    for j in 0..segments {
        f.push([0, at(1, j), at(1, j + 1)]);
        f.push([south, at(rings - 1, j + 1), at(rings - 1, j)]);
    }
    for i in 1..rings - 1 {
        for j in 0..segments {
            f.push([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
            f.push([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
        }
    }
    TriangleMesh::new(v, f).unwrap()
}

/// A closed mesh of a box with corners `lo` and `hi`.
pub fn box_mesh(lo: Vec3, hi: Vec3) -> TriangleMesh {
    let c = |i: usize| {
        Vec3::new(
            [lo.x, hi.x][i & 1],
            [lo.y, hi.y][(i >> 1) & 1],
            [lo.z, hi.z][i >> 2],
        )
    };
    let v = (0..8).map(c).collect();
    let quads = [
        [0, 2, 3, 1],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
    ];
    let f = quads
        .iter()
        .flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]])
        .collect();
    TriangleMesh::new(v, f).unwrap()
}

/// Checks symmetric, positive semi-definite and the triangle inequality of the principal
/// moments, to `tol` relative to the trace.
pub fn assert_physical(i: &Mat3, tol: f64) {
    let scale = i.trace().abs().max(1e-300);
    assert!(
        (i - i.transpose()).norm() <= tol * scale,
        "not symmetric: {i}"
    );
    let p = mechkit::mass::principal(i);
    assert!(
        p.moments[0] >= -tol * scale,
        "negative moment: {:?}",
        p.moments
    );
    assert!(
        p.moments[0] + p.moments[1] >= p.moments[2] - tol * scale,
        "triangle inequality fails: {:?}",
        p.moments
    );
}

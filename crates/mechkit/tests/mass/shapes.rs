//! Each analytic shape against an independent computation: exact polygon and mesh formulas
//! (equal for polygons and polyhedra, converging at second order for curved shapes), limits
//! of thick shapes (thin rods, rings, shells), and composites with holes.

use std::f64::consts::PI;

use mechkit::mass::{Amount, Body, MassProperties, Part, Polygon, Shape, TriangleMesh, Vec3};
use nalgebra::Rotation3;

use super::{box_mesh, difference, uv_sphere};

fn unit(s: &Shape) -> MassProperties {
    s.unit_properties().unwrap()
}

/// Observed order from errors at n and 2n.
fn order(errors: &[f64]) -> Vec<f64> {
    errors.windows(2).map(|e| (e[0] / e[1]).log2()).collect()
}

#[test]
fn fine_polygons_converge_to_the_disk_at_second_order() {
    let disk = unit(&Shape::Disk {
        radius: 2.0,
        inner_radius: 0.0,
    });
    let errors: Vec<f64> = [64, 128, 256, 512]
        .iter()
        .map(|&n| difference(&disk, &Polygon::regular(n, 2.0).unwrap().unit_properties()))
        .collect();
    let p = order(&errors);
    assert!(
        p.iter().all(|p| (p - 2.0).abs() < 0.02),
        "orders {p:?} errors {errors:?}"
    );
    assert!(errors[3] < 1e-4);
}

#[test]
fn fine_meshes_converge_to_the_ball_at_second_order() {
    let ball = unit(&Shape::Sphere {
        radius: 1.5,
        inner_radius: 0.0,
    });
    let errors: Vec<f64> = [16, 32, 64, 128]
        .iter()
        .map(|&n| difference(&ball, &uv_sphere(1.5, n, 2 * n).unit_properties()))
        .collect();
    let p = order(&errors);
    assert!(
        p.iter().all(|p| (p - 2.0).abs() < 0.05),
        "orders {p:?} errors {errors:?}"
    );
}

#[test]
fn cone_and_cylinder_against_faceted_meshes() {
    // a pyramid with an n-gon base converges to the cone; a prism to the cylinder
    let (r, h) = (0.7, 2.0);
    let faceted = |n: usize, top_radius: f64| {
        let ring = |z: f64, rr: f64| -> Vec<Vec3> {
            (0..n)
                .map(|k| {
                    let a = 2.0 * PI * k as f64 / n as f64;
                    Vec3::new(rr * a.cos(), rr * a.sin(), z)
                })
                .collect()
        };
        let mut v = ring(-h / 2.0, r);
        let (bottom, top) = (2 * n, 2 * n + 1);
        v.extend(ring(h / 2.0, top_radius.max(1e-300)));
        v.push(Vec3::new(0.0, 0.0, -h / 2.0));
        v.push(Vec3::new(0.0, 0.0, h / 2.0));
        let mut f = Vec::new();
        for k in 0..n {
            let k1 = (k + 1) % n;
            f.push([bottom, k1, k]);
            f.push([top, n + k, n + k1]);
            f.push([k, k1, n + k1]);
            f.push([k, n + k1, n + k]);
        }
        TriangleMesh::new(v, f).unwrap().unit_properties()
    };
    let cylinder = unit(&Shape::Cylinder {
        radius: r,
        inner_radius: 0.0,
        height: h,
    });
    let e: Vec<f64> = [64, 128, 256]
        .iter()
        .map(|&n| difference(&cylinder, &faceted(n, r)))
        .collect();
    assert!(order(&e).iter().all(|p| (p - 2.0).abs() < 0.02), "{e:?}");
    // the cone's local origin is the centre of its base: shift by h/2
    let cone = unit(&Shape::Cone {
        radius: r,
        height: h,
    })
    .translated(&Vec3::new(0.0, 0.0, -h / 2.0));
    let e: Vec<f64> = [64, 128, 256]
        .iter()
        .map(|&n| difference(&cone, &faceted(n, 1e-9)))
        .collect();
    assert!(order(&e).iter().all(|p| (p - 2.0).abs() < 0.05), "{e:?}");
}

#[test]
fn polyhedra_and_polygons_equal_their_exact_formulas() {
    let size = Vec3::new(1.0, 2.0, 3.0);
    let cuboid = unit(&Shape::Cuboid { size });
    let mesh = box_mesh(-size / 2.0, size / 2.0).unit_properties();
    assert!(difference(&cuboid, &mesh) < 1e-14);
    // moved and turned: the mesh of the moved box equals the moved analytic box
    let turn = Rotation3::from_euler_angles(0.3, -0.7, 1.1);
    let offset = Vec3::new(3.0, -1.0, 0.5);
    let moved = TriangleMesh::new(
        mesh_vertices(&box_mesh(-size / 2.0, size / 2.0))
            .iter()
            .map(|v| turn * v + offset)
            .collect(),
        box_mesh(-size / 2.0, size / 2.0).faces().to_vec(),
    )
    .unwrap();
    assert!(
        difference(
            &cuboid.rotated(&turn).translated(&offset),
            &moved.unit_properties()
        ) < 1e-13
    );
    // the plate is the polygon of its rectangle and the thin limit of a box
    let plate = unit(&Shape::Plate {
        width: 3.0,
        height: 1.0,
    });
    let rect = Polygon::new(vec![[-1.5, -0.5], [1.5, -0.5], [1.5, 0.5], [-1.5, 0.5]]).unwrap();
    assert!(difference(&plate, &rect.unit_properties()) < 1e-14);
    let thin = unit(&Shape::Cuboid {
        size: Vec3::new(3.0, 1.0, 1e-6),
    })
    .scaled(1e6);
    assert!(difference(&plate, &thin) < 1e-11);
    // a triangle is a 3-gon; a tetrahedron is a 4-face mesh
    let tri = [
        Vec3::new(0.2, 0.1, 0.0),
        Vec3::new(2.0, 0.4, 0.0),
        Vec3::new(0.7, 1.9, 0.0),
    ];
    let as_polygon = Polygon::new(tri.iter().map(|v| [v.x, v.y]).collect()).unwrap();
    assert!(
        difference(
            &unit(&Shape::Triangle { vertices: tri }),
            &as_polygon.unit_properties()
        ) < 1e-14
    );
    let t = [
        Vec3::zeros(),
        Vec3::new(1.0, 0.1, 0.0),
        Vec3::new(0.2, 1.3, 0.1),
        Vec3::new(0.3, 0.2, 0.9),
    ];
    let tet_mesh =
        TriangleMesh::new(t.to_vec(), vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]).unwrap();
    assert!(
        difference(
            &unit(&Shape::Tetrahedron { vertices: t }),
            &tet_mesh.unit_properties()
        ) < 1e-14
    );
    // an L-shaped (concave) polygon is two rectangles
    let l = Polygon::new(vec![
        [0.0, 0.0],
        [2.0, 0.0],
        [2.0, 1.0],
        [1.0, 1.0],
        [1.0, 3.0],
        [0.0, 3.0],
    ])
    .unwrap();
    let parts = [
        unit(&Shape::Plate {
            width: 2.0,
            height: 1.0,
        })
        .translated(&Vec3::new(1.0, 0.5, 0.0)),
        unit(&Shape::Plate {
            width: 1.0,
            height: 2.0,
        })
        .translated(&Vec3::new(0.5, 2.0, 0.0)),
    ];
    assert!(difference(&MassProperties::sum(&parts).unwrap(), &l.unit_properties()) < 1e-14);
}

fn mesh_vertices(m: &TriangleMesh) -> Vec<Vec3> {
    m.vertices().to_vec()
}

#[test]
fn sectors_make_disks_and_follow_fine_polygons() {
    let disk = unit(&Shape::Disk {
        radius: 1.0,
        inner_radius: 0.0,
    });
    assert!(
        difference(
            &disk,
            &unit(&Shape::Sector {
                radius: 1.0,
                angle: 2.0 * PI
            })
        ) < 1e-14
    );
    // three sectors of 120° turned to fill the disk
    let third = unit(&Shape::Sector {
        radius: 1.0,
        angle: 2.0 * PI / 3.0,
    });
    let parts: Vec<_> = (0..3)
        .map(|k| {
            third.rotated(&Rotation3::from_axis_angle(
                &Vec3::z_axis(),
                2.0 * PI * f64::from(k) / 3.0,
            ))
        })
        .collect();
    assert!(difference(&disk, &MassProperties::sum(&parts).unwrap()) < 1e-14);
    // a 60° piece of pie against the polygon of its arc
    let angle = PI / 3.0;
    let sector = unit(&Shape::Sector { radius: 2.0, angle });
    let pie = |n: usize| {
        let mut v = vec![[0.0, 0.0]];
        v.extend((0..=n).map(|k| {
            let a = -angle / 2.0 + angle * k as f64 / n as f64;
            [2.0 * a.cos(), 2.0 * a.sin()]
        }));
        Polygon::new(v).unwrap().unit_properties()
    };
    let e: Vec<f64> = [32, 64, 128]
        .iter()
        .map(|&n| difference(&sector, &pie(n)))
        .collect();
    assert!(order(&e).iter().all(|p| (p - 2.0).abs() < 0.02), "{e:?}");
}

#[test]
fn thin_shapes_are_limits_of_thick_ones() {
    // per unit mass, so the density of the limit does not matter
    let per_mass = |p: MassProperties| p.scaled(1.0 / p.mass);
    let close = |a: MassProperties, b: MassProperties, tol: f64| {
        let d = difference(&per_mass(a), &per_mass(b));
        assert!(d < tol, "{d}");
    };
    let eps = 1e-7;
    close(
        unit(&Shape::Rod { length: 2.0 }),
        unit(&Shape::Cylinder {
            radius: eps,
            inner_radius: 0.0,
            height: 2.0,
        }),
        1e-12,
    );
    close(
        unit(&Shape::Ring { radius: 2.0 }),
        unit(&Shape::Disk {
            radius: 2.0,
            inner_radius: 2.0 - eps,
        }),
        1e-7,
    );
    close(
        unit(&Shape::Tube {
            radius: 1.0,
            height: 3.0,
        }),
        unit(&Shape::Cylinder {
            radius: 1.0,
            inner_radius: 1.0 - eps,
            height: 3.0,
        }),
        1e-7,
    );
    close(
        unit(&Shape::SphericalShell { radius: 1.0 }),
        unit(&Shape::Sphere {
            radius: 1.0,
            inner_radius: 1.0 - eps,
        }),
        1e-7,
    );
    close(
        unit(&Shape::Disk {
            radius: 1.0,
            inner_radius: 0.0,
        }),
        unit(&Shape::Cylinder {
            radius: 1.0,
            inner_radius: 0.0,
            height: eps,
        }),
        1e-12,
    );
    // a thick shell and a hollow cylinder are the solid minus a hole
    let hollow = unit(&Shape::Sphere {
        radius: 2.0,
        inner_radius: 1.5,
    });
    let minus = MassProperties::sum(&[
        unit(&Shape::Sphere {
            radius: 2.0,
            inner_radius: 0.0,
        }),
        unit(&Shape::Sphere {
            radius: 1.5,
            inner_radius: 0.0,
        })
        .hole(),
    ])
    .unwrap();
    assert!(difference(&hollow, &minus) < 1e-14);
    let tube = unit(&Shape::Cylinder {
        radius: 2.0,
        inner_radius: 0.5,
        height: 1.0,
    });
    let minus = MassProperties::sum(&[
        unit(&Shape::Cylinder {
            radius: 2.0,
            inner_radius: 0.0,
            height: 1.0,
        }),
        unit(&Shape::Cylinder {
            radius: 0.5,
            inner_radius: 0.0,
            height: 1.0,
        })
        .hole(),
    ])
    .unwrap();
    assert!(difference(&tube, &minus) < 1e-14);
}

#[test]
fn a_cube_with_a_cubic_hole_is_seven_small_cubes() {
    let cube = |centre: Vec3, side: f64| {
        Part::new(
            "c",
            Shape::Cuboid {
                size: Vec3::repeat(side),
            },
            Amount::Density(7850.0),
        )
        .at(centre)
    };
    let holed = Body::new(vec![
        cube(Vec3::zeros(), 2.0),
        cube(Vec3::repeat(0.5), 1.0).hole(),
    ]);
    let mut seven = Vec::new();
    for i in 0..8 {
        let c = Vec3::new(
            [-0.5, 0.5][i & 1],
            [-0.5, 0.5][(i >> 1) & 1],
            [-0.5, 0.5][i >> 2],
        );
        if i != 7 {
            seven.push(cube(c, 1.0));
        }
    }
    let a = holed.properties().unwrap();
    let b = Body::new(seven).properties().unwrap();
    assert!(difference(&a, &b) < 1e-14);
    assert!((a.mass - 7.0 * 7850.0).abs() < 1e-9);
    // the CM moves away from the hole along the diagonal: -0.5/7 in each coordinate
    assert!((a.centre_of_mass - Vec3::repeat(-0.5 / 7.0)).norm() < 1e-15);
    // a hole the size of the body leaves nothing
    let nothing = Body::new(vec![
        cube(Vec3::zeros(), 1.0),
        cube(Vec3::zeros(), 1.0).hole(),
    ]);
    assert!(nothing.properties().is_err());
}

#[test]
fn degenerate_shapes_are_refused() {
    let line = [
        Vec3::zeros(),
        Vec3::new(1.0, 1.0, 0.0),
        Vec3::new(2.0, 2.0, 0.0),
    ];
    assert!(
        Shape::Triangle { vertices: line }
            .unit_properties()
            .is_err()
    );
    assert!(
        Shape::Sphere {
            radius: 1.0,
            inner_radius: 1.0
        }
        .unit_properties()
        .is_err()
    );
    assert!(Shape::Rod { length: -1.0 }.unit_properties().is_err());
    assert!(
        Shape::Sector {
            radius: 1.0,
            angle: 7.0
        }
        .unit_properties()
        .is_err()
    );
    // a bow tie crosses itself; a polygon with a repeated vertex or 2 vertices is refused
    let bow = Polygon::new(vec![[0.0, 0.0], [2.0, 2.0], [2.0, 0.0], [0.0, 2.0]]);
    assert!(bow.unwrap_err().to_string().contains("crosses itself"));
    assert!(Polygon::new(vec![[0.0, 0.0], [1.0, 0.0]]).is_err());
    assert!(Polygon::new(vec![[0.0, 0.0], [1.0, 0.0], [1.0, 0.0], [0.0, 1.0]]).is_err());
    // a box with one face missing is open; one face turned over is inconsistently oriented
    let b = box_mesh(Vec3::zeros(), Vec3::repeat(1.0));
    let mut faces = b.faces().to_vec();
    faces.pop();
    let e = TriangleMesh::new(b.vertices().to_vec(), faces.clone()).unwrap_err();
    assert!(e.to_string().contains("not closed"), "{e}");
    faces.push([b.faces()[11][0], b.faces()[11][2], b.faces()[11][1]]);
    assert!(TriangleMesh::new(b.vertices().to_vec(), faces).is_err());
    // inward-facing faces are turned outward: same result
    let inward: Vec<[usize; 3]> = b.faces().iter().map(|f| [f[0], f[2], f[1]]).collect();
    let flipped = TriangleMesh::new(b.vertices().to_vec(), inward).unwrap();
    assert!(difference(&b.unit_properties(), &flipped.unit_properties()) < 1e-15);
}

#[test]
fn obj_files_read_into_meshes() {
    let obj = "# unit cube\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n\
               f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4/1 1/1 5/1 8/1\n";
    let m = TriangleMesh::from_obj(obj).unwrap();
    assert!((m.volume() - 1.0).abs() < 1e-15);
    let e = TriangleMesh::from_obj("v 0 0 0\nf 1 2 3\n").unwrap_err();
    assert!(e.to_string().contains("line 2"), "{e}");
}

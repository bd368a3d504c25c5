//! Properties of mass properties over random shapes, placements and cuts: inertia tensors are
//! symmetric positive semi-definite with `I₁ + I₂ ≥ I₃`; moving a shape and applying the
//! parallel-axis theorem agrees with computing it in place; a shape cut into pieces and
//! recombined gives the same mass properties; moments about an axis turn with the body.

use mechkit::mass::{MassProperties, Polygon, Shape, Vec3};
use nalgebra::Rotation3;
use proptest::prelude::*;

use super::{assert_physical, difference};

fn point() -> impl Strategy<Value = Vec3> {
    (-3.0..3.0f64, -3.0..3.0f64, -3.0..3.0f64).prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

fn rotation() -> impl Strategy<Value = Rotation3<f64>> {
    (-3.2..3.2f64, -1.6..1.6f64, -3.2..3.2f64)
        .prop_map(|(a, b, c)| Rotation3::from_euler_angles(a, b, c))
}

fn length() -> impl Strategy<Value = f64> {
    0.05..4.0f64
}

/// A polygon star-shaped about the origin: radii at increasing angles less than 180° apart
/// (simple by construction).
fn star() -> impl Strategy<Value = Polygon> {
    prop::collection::vec((0.0..1.0f64, 0.2..2.0f64), 4..12).prop_filter_map(
        "a simple polygon",
        |mut v| {
            v.sort_by(|a, b| a.0.total_cmp(&b.0));
            let n = v.len() as f64;
            let pts = v
                .iter()
                .enumerate()
                .map(|(k, (jitter, r))| {
                    let a = std::f64::consts::TAU * (k as f64 + 0.5 * jitter) / n;
                    [r * a.cos(), r * a.sin()]
                })
                .collect();
            Polygon::new(pts).ok()
        },
    )
}

fn shape() -> impl Strategy<Value = Shape> {
    prop_oneof![
        length().prop_map(|length| Shape::Rod { length }),
        (length(), 0.0..0.99f64).prop_map(|(radius, f)| Shape::Disk {
            radius,
            inner_radius: f * radius
        }),
        (length(), 0.0..0.99f64, length()).prop_map(|(radius, f, height)| Shape::Cylinder {
            radius,
            inner_radius: f * radius,
            height
        }),
        (length(), 0.0..0.99f64).prop_map(|(radius, f)| Shape::Sphere {
            radius,
            inner_radius: f * radius
        }),
        (length(), length()).prop_map(|(radius, height)| Shape::Cone { radius, height }),
        (length(), length(), length()).prop_map(|(a, b, c)| Shape::Cuboid {
            size: Vec3::new(a, b, c)
        }),
        (length(), 0.1..std::f64::consts::TAU)
            .prop_map(|(radius, angle)| Shape::Sector { radius, angle }),
        (point(), point(), point()).prop_filter_map("a triangle", |(a, b, c)| {
            let s = Shape::Triangle {
                vertices: [a, b, c],
            };
            s.unit_properties()
                .ok()
                .filter(|p| p.mass > 1e-3)
                .map(|_| s)
        }),
        (point(), point(), point(), point()).prop_filter_map("a tetrahedron", |(a, b, c, d)| {
            let s = Shape::Tetrahedron {
                vertices: [a, b, c, d],
            };
            s.unit_properties()
                .ok()
                .filter(|p| p.mass > 1e-3)
                .map(|_| s)
        }),
        star().prop_map(Shape::Polygon),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn inertia_tensors_are_physical(s in shape(), turn in rotation(), at in point(), about in point()) {
        let p = s.unit_properties().unwrap().rotated(&turn).translated(&at);
        assert_physical(&p.inertia, 1e-12);
        assert_physical(&p.inertia_about(&about), 1e-12);
    }

    #[test]
    fn moving_a_shape_is_the_parallel_axis_theorem(s in shape(), d in point(), about in point()) {
        let here = s.unit_properties().unwrap();
        let there = here.translated(&d);
        let a = there.inertia_about(&about);
        let b = here.inertia_about(&(about - d));
        prop_assert!((a - b).norm() <= 1e-12 * a.norm().max(here.inertia.norm()), "{a} vs {b}");
    }

    #[test]
    fn moments_about_an_axis_turn_with_the_body(s in shape(), turn in rotation(), axis in point(), about in point()) {
        prop_assume!(axis.norm() > 1e-3);
        let p = s.unit_properties().unwrap();
        let turned = p.rotated(&turn);
        let a = turned.moment_about_axis(&(turn * about), &(turn * axis)).unwrap();
        let b = p.moment_about_axis(&about, &axis).unwrap();
        prop_assert!((a - b).abs() <= 1e-12 * a.abs().max(p.inertia.norm()));
    }

    #[test]
    fn a_box_cut_in_two_recombines(size in (length(), length(), length()), f in 0.05..0.95f64, turn in rotation(), at in point()) {
        let size = Vec3::new(size.0, size.1, size.2);
        let whole = Shape::Cuboid { size }.unit_properties().unwrap();
        let left = Shape::Cuboid { size: Vec3::new(f * size.x, size.y, size.z) }.unit_properties().unwrap()
            .translated(&Vec3::new(-size.x / 2.0 + f * size.x / 2.0, 0.0, 0.0));
        let right = Shape::Cuboid { size: Vec3::new((1.0 - f) * size.x, size.y, size.z) }.unit_properties().unwrap()
            .translated(&Vec3::new(size.x / 2.0 - (1.0 - f) * size.x / 2.0, 0.0, 0.0));
        let place = |p: MassProperties| p.rotated(&turn).translated(&at);
        let joined = MassProperties::sum(&[place(left), place(right)]).unwrap();
        prop_assert!(difference(&place(whole), &joined) < 1e-12);
    }

    #[test]
    fn a_tetrahedron_cut_at_an_inner_point_recombines(v in (point(), point(), point(), point()), w in (0.05..1.0f64, 0.05..1.0f64, 0.05..1.0f64, 0.05..1.0f64)) {
        let v = [v.0, v.1, v.2, v.3];
        let whole = Shape::Tetrahedron { vertices: v }.unit_properties();
        prop_assume!(whole.as_ref().is_ok_and(|p| p.mass > 1e-2));
        let sum = w.0 + w.1 + w.2 + w.3;
        let inner = (w.0 * v[0] + w.1 * v[1] + w.2 * v[2] + w.3 * v[3]) / sum;
        let pieces: Vec<MassProperties> = (0..4)
            .map(|k| {
                let mut t = v;
                t[k] = inner;
                Shape::Tetrahedron { vertices: t }.unit_properties().unwrap()
            })
            .collect();
        prop_assert!(difference(&whole.unwrap(), &MassProperties::sum(&pieces).unwrap()) < 1e-10);
    }

    #[test]
    fn a_polygon_is_the_sum_of_its_fan_triangles(p in star()) {
        // star-shaped about the origin: the triangles (origin, vᵢ, vᵢ₊₁) tile it
        let v = p.vertices();
        let n = v.len();
        let tri: Vec<MassProperties> = (0..n)
            .map(|i| {
                let a = Vec3::new(v[i][0], v[i][1], 0.0);
                let b = Vec3::new(v[(i + 1) % n][0], v[(i + 1) % n][1], 0.0);
                Shape::Triangle { vertices: [Vec3::zeros(), a, b] }.unit_properties().unwrap()
            })
            .collect();
        prop_assert!(difference(&p.unit_properties(), &MassProperties::sum(&tri).unwrap()) < 1e-12);
    }
}

//! Points on a body's surface, to draw it: for each part, a few points of its shape (the ends
//! of a rod, the rim of a disk, the corners of a box) placed in the body frame. An animation
//! draws the convex hull of a part's points as seen in its plane.

use super::{Body, Shape, Vec3};
use crate::Real;

/// Points around a circle of radius `r` in the plane z = `z`.
fn circle(r: Real, z: Real, out: &mut Vec<Vec3>) {
    const N: usize = 32;
    for k in 0..N {
        let a = std::f64::consts::TAU * k as Real / N as Real;
        out.push(Vec3::new(r * a.cos(), r * a.sin(), z));
    }
}

impl Shape {
    /// Points of the shape's surface in its own frame whose convex hull, seen from any side,
    /// is close to the shape's silhouette.
    pub fn outline_points(&self) -> Vec<Vec3> {
        let mut out = Vec::new();
        match self {
            Shape::Point => out.push(Vec3::zeros()),
            Shape::Rod { length } => {
                out.push(Vec3::new(0.0, 0.0, -0.5 * length));
                out.push(Vec3::new(0.0, 0.0, 0.5 * length));
            }
            Shape::Ring { radius } | Shape::Disk { radius, .. } => circle(*radius, 0.0, &mut out),
            Shape::Cylinder { radius, height, .. } | Shape::Tube { radius, height } => {
                circle(*radius, -0.5 * height, &mut out);
                circle(*radius, 0.5 * height, &mut out);
            }
            Shape::Sphere { radius, .. } | Shape::SphericalShell { radius } => {
                circle(*radius, 0.0, &mut out);
                let n = out.len();
                for k in 0..n {
                    let p = out[k];
                    out.push(Vec3::new(p.x, 0.0, p.y));
                    out.push(Vec3::new(0.0, p.x, p.y));
                }
            }
            Shape::Cone { radius, height } => {
                circle(*radius, 0.0, &mut out);
                out.push(Vec3::new(0.0, 0.0, *height));
            }
            Shape::Cuboid { size } => {
                for k in 0..8 {
                    let s = |bit: usize| if k & bit == 0 { -0.5 } else { 0.5 };
                    out.push(Vec3::new(s(1) * size.x, s(2) * size.y, s(4) * size.z));
                }
            }
            Shape::Plate { width, height } => {
                for (x, y) in [(-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5)] {
                    out.push(Vec3::new(x * width, y * height, 0.0));
                }
            }
            Shape::Triangle { vertices } => out.extend(vertices),
            Shape::Tetrahedron { vertices } => out.extend(vertices),
            Shape::Sector { radius, angle } => {
                const ARC: usize = 24;
                out.push(Vec3::zeros());
                for k in 0..=ARC {
                    let a = angle * (k as Real / ARC as Real - 0.5);
                    out.push(Vec3::new(radius * a.cos(), radius * a.sin(), 0.0));
                }
            }
            Shape::Polygon(p) => {
                out.extend(p.vertices().iter().map(|v| Vec3::new(v[0], v[1], 0.0)));
            }
            Shape::Mesh(m) => out.extend(m.vertices()),
        }
        out
    }
}

impl Body {
    /// Each solid part's outline points ([`Shape::outline_points`]) in the body frame, moved
    /// by `shift` (the body frame's origin to the point the drawing turns about); holes are
    /// left out.
    pub fn outline(&self, shift: Vec3) -> Vec<Vec<[Real; 3]>> {
        self.parts()
            .iter()
            .filter(|p| !p.hole)
            .map(|p| {
                p.shape
                    .outline_points()
                    .into_iter()
                    .map(|v| {
                        let w = p.rotation * v + p.position - shift;
                        [w.x, w.y, w.z]
                    })
                    .collect()
            })
            .collect()
    }
}

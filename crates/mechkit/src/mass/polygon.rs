//! A thin plate bounded by a simple polygon: exact area, centroid and second moments from the
//! vertices (a fan of signed triangles, so concave polygons are exact too).

use super::shapes::simplex_second_moment;
use super::{MassError, MassProperties, Mat3, Vec3};
use crate::Real;

/// A simple polygon in the xy plane, vertices in order (either sense; no repeated closing
/// vertex needed).
#[derive(Debug, Clone, PartialEq)]
pub struct Polygon {
    vertices: Vec<[Real; 2]>,
}

/// Whether segments `p1-p2` and `q1-q2` share a point.
fn segments_meet(p1: [Real; 2], p2: [Real; 2], q1: [Real; 2], q2: [Real; 2]) -> bool {
    let cross = |o: [Real; 2], a: [Real; 2], b: [Real; 2]| {
        (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
    };
    let within = |o: [Real; 2], a: [Real; 2], b: [Real; 2]| {
        b[0] >= o[0].min(a[0])
            && b[0] <= o[0].max(a[0])
            && b[1] >= o[1].min(a[1])
            && b[1] <= o[1].max(a[1])
    };
    let d1 = cross(q1, q2, p1);
    let d2 = cross(q1, q2, p2);
    let d3 = cross(p1, p2, q1);
    let d4 = cross(p1, p2, q2);
    if ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0))
        && ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0))
    {
        return true;
    }
    (d1 == 0.0 && within(q1, q2, p1))
        || (d2 == 0.0 && within(q1, q2, p2))
        || (d3 == 0.0 && within(p1, p2, q1))
        || (d4 == 0.0 && within(p1, p2, q2))
}

impl Polygon {
    /// Checks the polygon: at least 3 finite vertices, no two consecutive ones equal, edges
    /// that meet only at their shared vertices, and a non-zero area. A closing vertex equal to
    /// the first is dropped.
    ///
    /// ```
    /// use mechkit::mass::Polygon;
    /// // an L-shaped plate: area 3, centroid (5/6, 5/6)
    /// let l = Polygon::new(vec![[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0], [1.0, 2.0], [0.0, 2.0]]).unwrap();
    /// let p = l.unit_properties();
    /// assert!((p.mass - 3.0).abs() < 1e-12 && (p.centre_of_mass.x - 5.0 / 6.0).abs() < 1e-12);
    /// assert!(Polygon::new(vec![[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]]).is_err()); // a bow tie
    /// ```
    pub fn new(mut vertices: Vec<[Real; 2]>) -> Result<Self, MassError> {
        if vertices.len() > 3 && vertices.first() == vertices.last() {
            vertices.pop();
        }
        let degenerate = |reason: String| MassError::Degenerate {
            shape: "polygon",
            reason,
        };
        if vertices.len() < 3 {
            return Err(degenerate(format!(
                "it has {} vertices; a polygon needs at least 3",
                vertices.len()
            )));
        }
        if let Some(i) = vertices
            .iter()
            .position(|v| !v.iter().all(|x| x.is_finite()))
        {
            return Err(MassError::Invalid(format!(
                "polygon vertex {} is not a finite point",
                i + 1
            )));
        }
        let n = vertices.len();
        if let Some(i) = (0..n).find(|&i| vertices[i] == vertices[(i + 1) % n]) {
            return Err(degenerate(format!(
                "vertices {} and {} are the same point",
                i + 1,
                (i + 1) % n + 1
            )));
        }
        for i in 0..n {
            for j in i + 1..n {
                // neighbouring edges share a vertex; they may only meet there
                let adjacent = j == i + 1 || (i == 0 && j == n - 1);
                let (p1, p2) = (vertices[i], vertices[(i + 1) % n]);
                let (q1, q2) = (vertices[j], vertices[(j + 1) % n]);
                let meet = if adjacent {
                    // collinear and folding back over each other
                    let shared = if j == i + 1 { p2 } else { p1 };
                    let (a, b) = if j == i + 1 { (p1, q2) } else { (p2, q1) };
                    let cross = (a[0] - shared[0]) * (b[1] - shared[1])
                        - (a[1] - shared[1]) * (b[0] - shared[0]);
                    let dot = (a[0] - shared[0]) * (b[0] - shared[0])
                        + (a[1] - shared[1]) * (b[1] - shared[1]);
                    cross == 0.0 && dot > 0.0
                } else {
                    segments_meet(p1, p2, q1, q2)
                };
                if meet {
                    return Err(MassError::SelfIntersecting {
                        first: i + 1,
                        second: j + 1,
                    });
                }
            }
        }
        let polygon = Self { vertices };
        if polygon.signed_area() == 0.0 {
            return Err(degenerate("its area is zero".into()));
        }
        Ok(polygon)
    }

    /// A regular polygon with `n` vertices on a circle of radius `r` about the origin.
    pub fn regular(n: usize, r: Real) -> Result<Self, MassError> {
        let step = std::f64::consts::TAU / n as Real;
        Self::new(
            (0..n)
                .map(|k| {
                    let (s, c) = (k as Real * step).sin_cos();
                    [r * c, r * s]
                })
                .collect(),
        )
    }

    /// The vertices.
    pub fn vertices(&self) -> &[[Real; 2]] {
        &self.vertices
    }

    /// The area, positive for counter-clockwise vertices.
    pub fn signed_area(&self) -> Real {
        let n = self.vertices.len();
        (0..n)
            .map(|i| {
                let (a, b) = (self.vertices[i], self.vertices[(i + 1) % n]);
                a[0] * b[1] - a[1] * b[0]
            })
            .sum::<Real>()
            / 2.0
    }

    /// Mass properties at unit areal density (mass = area), in the xy plane.
    pub fn unit_properties(&self) -> MassProperties {
        // measured from the first vertex, so far-away polygons lose no digits
        let o = self.vertices[0];
        let local: Vec<Vec3> = self
            .vertices
            .iter()
            .map(|v| Vec3::new(v[0] - o[0], v[1] - o[1], 0.0))
            .collect();
        let (mut area, mut first, mut second) = (0.0, Vec3::zeros(), Mat3::zeros());
        for pair in local[1..].windows(2) {
            let (a, b) = (pair[0], pair[1]);
            let signed = 0.5 * (a.x * b.y - a.y * b.x);
            area += signed;
            first += signed * (a + b) / 3.0;
            second += simplex_second_moment(&[Vec3::zeros(), a, b], signed, 12.0);
        }
        let sign = area.signum();
        MassProperties::from_moments(area * sign, &(first * sign), &(second * sign))
            .translated(&Vec3::new(o[0], o[1], 0.0))
    }
}

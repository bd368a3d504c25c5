//! Standard shapes of uniform density, each in its own frame: mass per unit density
//! (length, area or volume), centre of mass and inertia tensor about the centre of mass.
//!
//! Frames: axisymmetric shapes (rod, ring, disk, cylinder, tube, cone) have their axis along
//! local z; flat shapes (ring, disk, plate, sector, polygon) lie in the local xy plane. The
//! local origin is the shape's centre, except for the cone (the centre of its base, apex at
//! `z = height`) and the sector (its apex, symmetric about +x); triangles, tetrahedra,
//! polygons and meshes are given by their vertices in the local frame.

use std::f64::consts::PI;

use super::mesh::TriangleMesh;
use super::polygon::Polygon;
use super::{MassError, MassProperties, Mat3, Vec3};
use crate::Real;

/// What a density of the shape is per: length (kg/m), area (kg/m²) or volume (kg/m³).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Extent {
    /// A thin rod or ring: density in kg/m.
    Line,
    /// A thin plate or shell: density in kg/m².
    Surface,
    /// A solid: density in kg/m³.
    Solid,
    /// A point mass: no density, only a mass.
    Point,
}

/// A shape of uniform density.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Shape {
    /// A point mass at the origin.
    Point,
    /// A thin rod along z, centred.
    Rod {
        /// Length (m).
        length: Real,
    },
    /// A thin ring (hoop) in the xy plane.
    Ring {
        /// Radius (m).
        radius: Real,
    },
    /// A thin disk in the xy plane; with `inner_radius > 0`, an annulus (washer).
    Disk {
        /// Outer radius (m).
        radius: Real,
        /// Inner radius (m); 0 for a full disk.
        inner_radius: Real,
    },
    /// A solid cylinder along z, centred; with `inner_radius > 0`, a thick-walled tube.
    Cylinder {
        /// Outer radius (m).
        radius: Real,
        /// Inner radius (m); 0 for a solid cylinder.
        inner_radius: Real,
        /// Length along z (m).
        height: Real,
    },
    /// A thin-walled tube (the lateral surface of a cylinder) along z, centred.
    Tube {
        /// Radius (m).
        radius: Real,
        /// Length along z (m).
        height: Real,
    },
    /// A solid ball; with `inner_radius > 0`, a thick spherical shell.
    Sphere {
        /// Outer radius (m).
        radius: Real,
        /// Inner radius (m); 0 for a solid ball.
        inner_radius: Real,
    },
    /// A thin spherical shell.
    SphericalShell {
        /// Radius (m).
        radius: Real,
    },
    /// A solid right circular cone: base centred at the origin in the xy plane, apex at
    /// `z = height`.
    Cone {
        /// Base radius (m).
        radius: Real,
        /// Height (m).
        height: Real,
    },
    /// A solid rectangular box, centred, edges along the axes.
    Cuboid {
        /// Edge lengths along x, y, z (m).
        size: Vec3,
    },
    /// A thin rectangular plate in the xy plane, centred.
    Plate {
        /// Along x (m).
        width: Real,
        /// Along y (m).
        height: Real,
    },
    /// A thin triangular plate with any three vertices.
    Triangle {
        /// The vertices (m).
        vertices: [Vec3; 3],
    },
    /// A thin circular sector ("piece of pie") in the xy plane: apex at the origin,
    /// symmetric about +x.
    Sector {
        /// Radius (m).
        radius: Real,
        /// Opening angle (rad), up to 2π.
        angle: Real,
    },
    /// A solid tetrahedron with any four vertices.
    Tetrahedron {
        /// The vertices (m).
        vertices: [Vec3; 4],
    },
    /// A thin plate bounded by a simple polygon in the xy plane.
    Polygon(Polygon),
    /// A solid bounded by a closed triangle mesh.
    Mesh(TriangleMesh),
}

fn positive(shape: &'static str, what: &str, value: Real) -> Result<(), MassError> {
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(MassError::Degenerate {
            shape,
            reason: format!(
                "the {what} is {}; it must be positive",
                crate::error::short(value)
            ),
        })
    }
}

fn inner(shape: &'static str, radius: Real, inner_radius: Real) -> Result<(), MassError> {
    if inner_radius.is_finite() && (0.0..radius).contains(&inner_radius) {
        Ok(())
    } else {
        Err(MassError::Degenerate {
            shape,
            reason: format!(
                "the inner radius {} must be at least 0 and less than the radius {}",
                crate::error::short(inner_radius),
                crate::error::short(radius)
            ),
        })
    }
}

fn diagonal(x: Real, y: Real, z: Real) -> Mat3 {
    Mat3::from_diagonal(&Vec3::new(x, y, z))
}

/// `∫ r rᵀ` over a triangle (or, with `V/20`, a tetrahedron) from its vertices:
/// `measure/k (Σ vᵢ vᵢᵀ + s sᵀ)`, `s = Σ vᵢ`.
pub(crate) fn simplex_second_moment(vertices: &[Vec3], measure: Real, k: Real) -> Mat3 {
    let s: Vec3 = vertices.iter().sum();
    let sum: Mat3 = vertices.iter().map(|v| v * v.transpose()).sum();
    (sum + s * s.transpose()) * (measure / k)
}

impl Shape {
    /// A short name for messages: "rod", "sphere", …
    pub fn name(&self) -> &'static str {
        match self {
            Shape::Point => "point",
            Shape::Rod { .. } => "rod",
            Shape::Ring { .. } => "ring",
            Shape::Disk { .. } => "disk",
            Shape::Cylinder { .. } => "cylinder",
            Shape::Tube { .. } => "tube",
            Shape::Sphere { .. } => "sphere",
            Shape::SphericalShell { .. } => "spherical shell",
            Shape::Cone { .. } => "cone",
            Shape::Cuboid { .. } => "box",
            Shape::Plate { .. } => "plate",
            Shape::Triangle { .. } => "triangle",
            Shape::Sector { .. } => "sector",
            Shape::Tetrahedron { .. } => "tetrahedron",
            Shape::Polygon(_) => "polygon",
            Shape::Mesh(_) => "mesh",
        }
    }

    /// What the density is per.
    pub fn extent(&self) -> Extent {
        match self {
            Shape::Point => Extent::Point,
            Shape::Rod { .. } | Shape::Ring { .. } => Extent::Line,
            Shape::Disk { .. }
            | Shape::Tube { .. }
            | Shape::SphericalShell { .. }
            | Shape::Plate { .. }
            | Shape::Triangle { .. }
            | Shape::Sector { .. }
            | Shape::Polygon(_) => Extent::Surface,
            Shape::Cylinder { .. }
            | Shape::Sphere { .. }
            | Shape::Cone { .. }
            | Shape::Cuboid { .. }
            | Shape::Tetrahedron { .. }
            | Shape::Mesh(_) => Extent::Solid,
        }
    }

    /// The mass properties at unit density: the mass is the length, area or volume (1 for a
    /// point), in the shape's own frame.
    ///
    /// ```
    /// use mechkit::mass::{Shape, Vec3};
    /// // a solid ball of radius 2: V = 32π/3, I = (2/5) V R²
    /// let p = Shape::Sphere { radius: 2.0, inner_radius: 0.0 }.unit_properties().unwrap();
    /// let v = 32.0 * std::f64::consts::PI / 3.0;
    /// assert!((p.mass - v).abs() < 1e-12 && (p.inertia[(0, 0)] - 0.4 * v * 4.0).abs() < 1e-12);
    /// ```
    pub fn unit_properties(&self) -> Result<MassProperties, MassError> {
        let name = self.name();
        let at_origin = |m: Real, i: Mat3| MassProperties::new(m, Vec3::zeros(), i);
        Ok(match self {
            Shape::Point => MassProperties::point(1.0, Vec3::zeros()),
            &Shape::Rod { length: l } => {
                positive(name, "length", l)?;
                let t = l * l * l / 12.0;
                at_origin(l, diagonal(t, t, 0.0))
            }
            &Shape::Ring { radius: r } => {
                positive(name, "radius", r)?;
                let m = 2.0 * PI * r;
                at_origin(m, diagonal(m * r * r / 2.0, m * r * r / 2.0, m * r * r))
            }
            &Shape::Disk {
                radius: r,
                inner_radius: a,
            } => {
                positive(name, "radius", r)?;
                inner(name, r, a)?;
                let m = PI * (r * r - a * a);
                let q = m * (r * r + a * a);
                at_origin(m, diagonal(q / 4.0, q / 4.0, q / 2.0))
            }
            &Shape::Cylinder {
                radius: r,
                inner_radius: a,
                height: h,
            } => {
                positive(name, "radius", r)?;
                positive(name, "height", h)?;
                inner(name, r, a)?;
                let m = PI * (r * r - a * a) * h;
                let side = m * (3.0 * (r * r + a * a) + h * h) / 12.0;
                at_origin(m, diagonal(side, side, m * (r * r + a * a) / 2.0))
            }
            &Shape::Tube {
                radius: r,
                height: h,
            } => {
                positive(name, "radius", r)?;
                positive(name, "height", h)?;
                let m = 2.0 * PI * r * h;
                let side = m * (6.0 * r * r + h * h) / 12.0;
                at_origin(m, diagonal(side, side, m * r * r))
            }
            &Shape::Sphere {
                radius: r,
                inner_radius: a,
            } => {
                positive(name, "radius", r)?;
                inner(name, r, a)?;
                let m = 4.0 / 3.0 * PI * (r.powi(3) - a.powi(3));
                // (2/5) m (R⁵ − a⁵)/(R³ − a³), written without the cancellation
                let ratio = (r.powi(4) + r.powi(3) * a + r * r * a * a + r * a.powi(3) + a.powi(4))
                    / (r * r + r * a + a * a);
                let i = 0.4 * m * ratio;
                at_origin(m, diagonal(i, i, i))
            }
            &Shape::SphericalShell { radius: r } => {
                positive(name, "radius", r)?;
                let m = 4.0 * PI * r * r;
                let i = 2.0 / 3.0 * m * r * r;
                at_origin(m, diagonal(i, i, i))
            }
            &Shape::Cone {
                radius: r,
                height: h,
            } => {
                positive(name, "radius", r)?;
                positive(name, "height", h)?;
                let m = PI * r * r * h / 3.0;
                let side = m * (3.0 * r * r / 20.0 + 3.0 * h * h / 80.0);
                MassProperties::new(
                    m,
                    Vec3::new(0.0, 0.0, h / 4.0),
                    diagonal(side, side, 0.3 * m * r * r),
                )
            }
            &Shape::Cuboid { size } => {
                for (k, axis) in ["x", "y", "z"].iter().enumerate() {
                    positive(name, &format!("edge along {axis}"), size[k])?;
                }
                let m = size.x * size.y * size.z;
                let [a2, b2, c2] = [size.x, size.y, size.z].map(|s| s * s * m / 12.0);
                at_origin(m, diagonal(b2 + c2, a2 + c2, a2 + b2))
            }
            &Shape::Plate {
                width: a,
                height: b,
            } => {
                positive(name, "width", a)?;
                positive(name, "height", b)?;
                let m = a * b;
                let (ix, iy) = (m * b * b / 12.0, m * a * a / 12.0);
                at_origin(m, diagonal(ix, iy, ix + iy))
            }
            Shape::Triangle { vertices } => triangle(vertices)?,
            &Shape::Sector { radius: r, angle } => {
                positive(name, "radius", r)?;
                if !(angle > 0.0 && angle <= 2.0 * PI + 1e-12) {
                    return Err(MassError::Degenerate {
                        shape: name,
                        reason: format!(
                            "the opening angle is {} rad; it must be above 0 and at most 2π",
                            crate::error::short(angle)
                        ),
                    });
                }
                let h = angle / 2.0;
                let m = r * r * h;
                let (s, c) = h.sin_cos();
                let first = Vec3::new(2.0 * r.powi(3) * s / 3.0, 0.0, 0.0);
                let r4 = r.powi(4) / 4.0;
                let second = diagonal(r4 * (h + s * c), r4 * (h - s * c), 0.0);
                MassProperties::from_moments(m, &first, &second)
            }
            Shape::Tetrahedron { vertices } => tetrahedron(vertices)?,
            Shape::Polygon(p) => p.unit_properties(),
            Shape::Mesh(mesh) => mesh.unit_properties(),
        })
    }

    /// The mass properties with a density (per length, area or volume as [`Shape::extent`]
    /// says; for a point, the mass).
    pub fn with_density(&self, density: Real) -> Result<MassProperties, MassError> {
        Ok(self.unit_properties()?.scaled(density))
    }

    /// The mass properties with a total mass.
    pub fn with_mass(&self, mass: Real) -> Result<MassProperties, MassError> {
        let unit = self.unit_properties()?;
        Ok(unit.scaled(mass / unit.mass))
    }
}

fn triangle(v: &[Vec3; 3]) -> Result<MassProperties, MassError> {
    let c = (v[0] + v[1] + v[2]) / 3.0;
    let local = v.map(|p| p - c);
    let area = 0.5 * (local[1] - local[0]).cross(&(local[2] - local[0])).norm();
    let size = (local[1] - local[0])
        .norm()
        .max((local[2] - local[0]).norm());
    if area.is_nan() || area <= 1e-12 * size * size {
        return Err(MassError::Degenerate {
            shape: "triangle",
            reason: "its vertices lie on a line (zero area); give three vertices that are not on one line".into(),
        });
    }
    let second = simplex_second_moment(&local, area, 12.0);
    Ok(MassProperties::from_moments(area, &Vec3::zeros(), &second).translated(&c))
}

fn tetrahedron(v: &[Vec3; 4]) -> Result<MassProperties, MassError> {
    let c = (v[0] + v[1] + v[2] + v[3]) / 4.0;
    let local = v.map(|p| p - c);
    let a = local[1] - local[0];
    let b = local[2] - local[0];
    let d = local[3] - local[0];
    let volume = (a.dot(&b.cross(&d)) / 6.0).abs();
    let size = a.norm().max(b.norm()).max(d.norm());
    if volume.is_nan() || volume <= 1e-12 * size.powi(3) {
        return Err(MassError::Degenerate {
            shape: "tetrahedron",
            reason: "its vertices lie in a plane (zero volume); give four vertices that are not in one plane".into(),
        });
    }
    let second = simplex_second_moment(&local, volume, 20.0);
    Ok(MassProperties::from_moments(volume, &Vec3::zeros(), &second).translated(&c))
}

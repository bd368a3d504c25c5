//! A solid bounded by a closed triangle mesh: exact volume, centroid and second moments by the
//! divergence theorem (a signed tetrahedron from a reference point to each face).

use std::collections::HashMap;

use super::shapes::simplex_second_moment;
use super::{MassError, MassProperties, Mat3, Vec3};
use crate::Real;

/// A closed, consistently oriented triangle mesh (outward or inward normals; inward meshes are
/// turned outward).
#[derive(Debug, Clone, PartialEq)]
pub struct TriangleMesh {
    vertices: Vec<Vec3>,
    faces: Vec<[usize; 3]>,
}

impl TriangleMesh {
    /// Checks the mesh: indices in range, no degenerate face, every edge shared by exactly two
    /// faces that run along it in opposite senses (closed and consistently oriented), and a
    /// non-zero volume. Faces index `vertices` from 0.
    pub fn new(vertices: Vec<Vec3>, faces: Vec<[usize; 3]>) -> Result<Self, MassError> {
        let open = MassError::OpenMesh;
        if faces.len() < 4 {
            return Err(open(format!(
                "it has {} faces; a closed surface needs at least 4",
                faces.len()
            )));
        }
        if let Some(i) = vertices
            .iter()
            .position(|v| !v.iter().all(|x| x.is_finite()))
        {
            return Err(MassError::Invalid(format!(
                "mesh vertex {} is not a finite point",
                i + 1
            )));
        }
        let mut edges: HashMap<(usize, usize), usize> = HashMap::new();
        for (f, face) in faces.iter().enumerate() {
            if let Some(&bad) = face.iter().find(|&&k| k >= vertices.len()) {
                return Err(MassError::Invalid(format!(
                    "face {} uses vertex {} but the mesh has {} vertices",
                    f + 1,
                    bad + 1,
                    vertices.len()
                )));
            }
            if face[0] == face[1] || face[1] == face[2] || face[0] == face[2] {
                return Err(MassError::Degenerate {
                    shape: "mesh",
                    reason: format!("face {} repeats a vertex", f + 1),
                });
            }
            for k in 0..3 {
                let edge = (face[k], face[(k + 1) % 3]);
                if let Some(other) = edges.insert(edge, f) {
                    return Err(open(format!(
                        "faces {} and {} both run along the edge from vertex {} to {} in the same sense: the faces are not consistently oriented, or more than two faces share an edge",
                        other + 1,
                        f + 1,
                        edge.0 + 1,
                        edge.1 + 1
                    )));
                }
            }
        }
        if let Some((&(a, b), &f)) = edges
            .iter()
            .filter(|(e, _)| !edges.contains_key(&(e.1, e.0)))
            .min_by_key(|(_, f)| **f)
        {
            return Err(open(format!(
                "the edge from vertex {} to {} of face {} has no face on its other side (a hole in the surface)",
                a + 1,
                b + 1,
                f + 1
            )));
        }
        let mut mesh = Self { vertices, faces };
        let volume = mesh.signed_volume();
        let size = mesh.extent();
        if volume.is_nan() || volume.abs() <= 1e-12 * size.powi(3) {
            return Err(MassError::Degenerate {
                shape: "mesh",
                reason: "it encloses no volume".into(),
            });
        }
        if volume < 0.0 {
            for f in &mut mesh.faces {
                f.swap(1, 2);
            }
        }
        Ok(mesh)
    }

    /// Reads the vertices (`v x y z`) and faces (`f a b c …`, 1-based, negative counts from
    /// the end, `a/t/n` forms allowed; polygons are split into fans) of a Wavefront OBJ text.
    pub fn from_obj(text: &str) -> Result<Self, MassError> {
        let mut vertices = Vec::new();
        let mut faces = Vec::new();
        for (n, line) in text.lines().enumerate() {
            let mut words = line.split_whitespace();
            let at = |what: &str| MassError::Invalid(format!("OBJ line {}: {what}", n + 1));
            match words.next() {
                Some("v") => {
                    let xyz: Vec<Real> = words
                        .take(3)
                        .map(|w| {
                            w.parse::<Real>()
                                .map_err(|_| {
                                    at(&format!(
                                        "`{w}` is not a number; a vertex line is `v x y z`, e.g. `v 0 1.5 0`"
                                    ))
                                })
                        })
                        .collect::<Result<_, _>>()?;
                    if xyz.len() != 3 {
                        return Err(at("a vertex needs x, y and z"));
                    }
                    vertices.push(Vec3::new(xyz[0], xyz[1], xyz[2]));
                }
                Some("f") => {
                    let idx: Vec<usize> = words
                        .map(|w| {
                            let first = w.split('/').next().unwrap_or("");
                            let i: i64 = first
                                .parse()
                                .map_err(|_| at(&format!("`{w}` is not a vertex index")))?;
                            let count = vertices.len() as i64;
                            let k = if i < 0 { count + i } else { i - 1 };
                            if (0..count).contains(&k) {
                                Ok(k as usize)
                            } else {
                                Err(at(&format!(
                                    "vertex index {i} is out of range (there are {count} vertices so far)"
                                )))
                            }
                        })
                        .collect::<Result<_, _>>()?;
                    if idx.len() < 3 {
                        return Err(at("a face needs at least 3 vertices"));
                    }
                    for k in 1..idx.len() - 1 {
                        faces.push([idx[0], idx[k], idx[k + 1]]);
                    }
                }
                _ => {}
            }
        }
        Self::new(vertices, faces)
    }

    /// The vertices.
    pub fn vertices(&self) -> &[Vec3] {
        &self.vertices
    }

    /// The faces (0-based vertex indices, outward by the right-hand rule).
    pub fn faces(&self) -> &[[usize; 3]] {
        &self.faces
    }

    fn extent(&self) -> Real {
        let o = self.vertices[self.faces[0][0]];
        self.vertices
            .iter()
            .map(|v| (v - o).norm())
            .fold(0.0, Real::max)
    }

    fn signed_volume(&self) -> Real {
        let o = self.vertices[self.faces[0][0]];
        self.faces
            .iter()
            .map(|f| {
                let [a, b, c] = f.map(|k| self.vertices[k] - o);
                a.dot(&b.cross(&c)) / 6.0
            })
            .sum()
    }

    /// The enclosed volume.
    pub fn volume(&self) -> Real {
        self.signed_volume()
    }

    /// Mass properties at unit density (mass = volume).
    pub fn unit_properties(&self) -> MassProperties {
        let o = self.vertices[self.faces[0][0]];
        let (mut volume, mut first, mut second) = (0.0, Vec3::zeros(), Mat3::zeros());
        for f in &self.faces {
            let [a, b, c] = f.map(|k| self.vertices[k] - o);
            let v = a.dot(&b.cross(&c)) / 6.0;
            volume += v;
            first += v * (a + b + c) / 4.0;
            second += simplex_second_moment(&[Vec3::zeros(), a, b, c], v, 20.0);
        }
        MassProperties::from_moments(volume, &first, &second).translated(&o)
    }
}

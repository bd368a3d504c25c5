//! Mass properties: systems of point masses (centre of mass, momentum, the centre-of-mass
//! frame and the kinetic-energy split), and rigid bodies: mass, centre of mass and inertia
//! tensor of standard shapes, polygons and triangle meshes, composites with holes, and
//! photographs (the pixels of the body). The reports of a body ([`BodySummary`]: its centre
//! of mass, its inertia tensor, principal axes and the moment about an axis) are what
//! `mechkit com` and `mechkit inertia` print.

mod body_report;
mod composite;
mod holes;
pub mod image;
mod mesh;
mod outline;
mod points;
mod polygon;
mod properties;
mod shapes;

use thiserror::Error;

use crate::Real;

pub use body_report::{
    AxisMoment, BodyCentreOfMass, BodySummary, InertiaReport, PartSummary, PointDistance,
};
pub use composite::{Amount, Body, Part};
pub use mesh::TriangleMesh;
pub use points::{MassSummary, PointMassError, PointMassInput, PointMassReport, PointMasses};
pub use polygon::Polygon;
pub use properties::{
    MassProperties, Mat3, Principal, Vec3, inertia_from_second_moment, parallel_axis, principal,
    second_moment_from_inertia,
};
pub use shapes::{Extent, Shape};

/// Why mass properties cannot be computed.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum MassError {
    /// The parts add up to no mass (holes as large as the body), or there are no parts.
    #[error(
        "the total mass is {} kg, though the parts without their signs add up to {} kg: the holes cancel the body, or there is nothing; check which parts have `hole = true` and that each hole is smaller than the body it is cut from",
        crate::error::short(*total),
        crate::error::short(*gross)
    )]
    ZeroMass {
        /// `Σ m` with holes negative.
        total: Real,
        /// `Σ |m|`.
        gross: Real,
    },
    /// A shape without length, area or volume.
    #[error("degenerate {shape}: {reason}")]
    Degenerate {
        /// The kind of shape.
        shape: &'static str,
        /// What is wrong.
        reason: String,
    },
    /// A polygon whose edges cross.
    #[error(
        "the polygon crosses itself: edge {first} (vertices {first}-{}) meets edge {second}; list the vertices in order around the boundary",
        first + 1
    )]
    SelfIntersecting {
        /// 1-based edge from vertex `first` to `first + 1`.
        first: usize,
        /// 1-based edge.
        second: usize,
    },
    /// A triangle mesh that does not enclose a volume.
    #[error(
        "the mesh is not closed: {0}; a mesh must enclose a volume: every edge shared by exactly two faces"
    )]
    OpenMesh(String),
    /// An axis direction of zero length.
    #[error(
        "the axis direction ({}, {}, {}) has no length; give a non-zero direction, e.g. 0, 0, 1 for the z axis",
        crate::error::short(direction[0]),
        crate::error::short(direction[1]),
        crate::error::short(direction[2])
    )]
    ZeroAxis {
        /// The direction given.
        direction: [Real; 3],
    },
    /// A total mass to rescale a body to that is not positive and finite.
    #[error("the total mass is {} kg; it must be a positive mass, e.g. 2 kg", crate::error::short(*mass))]
    TotalMass {
        /// The value.
        mass: Real,
    },
    /// A hole that does not lie inside the solid parts (part `index`, 0-based, of the body).
    #[error(
        "the hole `{name}` is not inside the body: {reason}; a hole removes material the other parts have, so it must lie inside them"
    )]
    Hole {
        /// Its index among the body's parts.
        index: usize,
        /// Its name.
        name: String,
        /// What is wrong.
        reason: String,
    },
    /// Any other invalid value.
    #[error("{0}")]
    Invalid(String),
}

/// The input of a mass report that a [`MassError`] is about (the errors of a body's parts
/// are located in its file instead).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum MassInput {
    /// The direction of an axis.
    Axis,
    /// The total mass the body is rescaled to.
    TotalMass,
}

impl MassError {
    /// The input the error is about, when it is one of a report's rather than of the body.
    pub fn input(&self) -> Option<MassInput> {
        match self {
            Self::ZeroAxis { .. } => Some(MassInput::Axis),
            Self::TotalMass { .. } => Some(MassInput::TotalMass),
            _ => None,
        }
    }
}

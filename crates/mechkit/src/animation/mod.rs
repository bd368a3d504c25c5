//! Animations of a run, as data: the frames of a scene at a chosen frame rate, each a list of
//! shapes in world coordinates (metres, or the run's units), with the time, trails and the
//! energies of the moment. The library computes them ([`Animation::from_run`] for a
//! scenario's run, [`Animation::from_xyz`] for an md run's frames); drawing them (a GIF, an
//! MP4, a self-contained HTML player) is a front's job, as for plots.
//!
//! The view is fixed for the whole animation (it holds every body at every frame, with a
//! margin) and to scale: one metre is as long across as up, so spheres stay round and rods
//! keep their length.

mod build;
mod draw;
mod format;
mod scene;
mod track;
mod xyz;

pub use build::{AnimationError, AnimationOptions, Columns, DEFAULT_FPS, MAX_FRAMES};
pub use format::AnimationFormat;
pub use scene::{Attachment, Body, BodyShape, Scene, SceneItem};
pub use xyz::{MAX_ATOMS, XyzFrame, parse_xyz};

use crate::Real;

/// An animation: what a renderer needs to draw every frame.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Animation {
    /// The run's title.
    pub title: String,
    /// Frames per second of playback.
    pub fps: Real,
    /// Simulated seconds per second of playback (1 = real time).
    pub speed: Real,
    /// The world rectangle shown.
    pub view: View,
    /// The unit of the axes' lengths (`m`, or `σ` for reduced units).
    pub length_unit: String,
    /// Shapes that do not move (walls, the floor, fixed anchors), drawn under the frames.
    pub background: Vec<Shape>,
    /// The frames, in time order.
    pub frames: Vec<Frame>,
    /// The paths of the bodies with a trail: point `i` is where the body is at frame `i`; a
    /// renderer draws the points up to the current frame.
    pub trails: Vec<Trail>,
    /// The energies shown as bars beside the scene, when asked for.
    pub energy: Option<EnergyBars>,
}

/// The rectangle of the world a renderer maps onto its picture, in length units, with the
/// same scale on both axes (its aspect ratio is the picture's).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct View {
    /// The left edge.
    pub x_min: Real,
    /// The right edge.
    pub x_max: Real,
    /// The bottom edge.
    pub y_min: Real,
    /// The top edge.
    pub y_max: Real,
}

impl View {
    /// The width.
    pub fn width(&self) -> Real {
        self.x_max - self.x_min
    }

    /// The height.
    pub fn height(&self) -> Real {
        self.y_max - self.y_min
    }
}

/// One picture of the scene.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Frame {
    /// The simulated time (s).
    pub t: Real,
    /// The shapes, drawn in order (later ones on top).
    pub shapes: Vec<Shape>,
    /// The energies at this time, in the order of [`EnergyBars::labels`] (empty without bars).
    pub energy: Vec<Real>,
}

/// A shape and how it is drawn.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Shape {
    /// The geometry, in world coordinates.
    pub geometry: Geometry,
    /// Its fill colour, if filled.
    pub fill: Option<Colour>,
    /// Its outline or line colour, if stroked.
    pub stroke: Option<Colour>,
    /// The line width in pixels of the picture (not world units).
    pub line_width: Real,
}

/// The geometry of a [`Shape`].
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(tag = "kind", rename_all = "snake_case"))]
pub enum Geometry {
    /// A circle of a radius in world units.
    Circle {
        /// The centre.
        centre: [Real; 2],
        /// The radius.
        radius: Real,
    },
    /// A point body: a dot of a fixed size in pixels, whatever the scale.
    Dot {
        /// Where it is.
        centre: [Real; 2],
        /// The dot's radius in pixels.
        radius_px: Real,
    },
    /// A closed polygon.
    Polygon {
        /// The corners, in order.
        points: Vec<[Real; 2]>,
    },
    /// An open line through points (a spring's coils, a string, a wall's edge).
    Polyline {
        /// The points, in order.
        points: Vec<[Real; 2]>,
    },
}

/// An sRGB colour.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Colour(pub u8, pub u8, pub u8);

impl Colour {
    /// `#rrggbb`.
    pub fn hex(self) -> String {
        format!("#{:02x}{:02x}{:02x}", self.0, self.1, self.2)
    }
}

#[cfg(feature = "serde")]
impl serde::Serialize for Colour {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(&self.hex())
    }
}

/// A body's path.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Trail {
    /// The body's name.
    pub name: String,
    /// Its colour.
    pub colour: Colour,
    /// Where the body is at each frame.
    pub points: Vec<[Real; 2]>,
}

/// The energies drawn as bars: kinetic, potential and their sum, on one scale.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct EnergyBars {
    /// The bars' names (`K`, `U`, `E`).
    pub labels: Vec<String>,
    /// The bars' colours.
    pub colours: Vec<Colour>,
    /// The unit (`J`).
    pub unit: String,
    /// The lowest and highest value any bar reaches over the run (the scale's ends; the
    /// lowest is at most 0).
    pub range: (Real, Real),
}

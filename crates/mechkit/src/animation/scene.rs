//! What a run looks like, independent of time: the bodies (their size or outline, and
//! whether they turn), the links between them (springs, rods, strings), the walls. A model
//! describes itself ([`Scene`] from a scenario, `Force::sketch` for each force); where the
//! bodies are at a time comes from the run's columns (`ball.x`, `rod.theta`).

use crate::Real;

/// The scene of a run.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Scene {
    /// Spatial dimensions of the run (1 to 3).
    pub dim: usize,
    /// The bodies, in the model's order (a link's [`Attachment::Body`] indexes them).
    pub bodies: Vec<Body>,
    /// Links and walls.
    pub items: Vec<SceneItem>,
    /// For a 1-D run: draw the axis upright (the motion is a fall or a bounce), not across.
    pub upright: bool,
}

/// A body as drawn.
#[derive(Debug, Clone, PartialEq)]
pub struct Body {
    /// Its name: its columns are `NAME.x`, `NAME.y`, `NAME.z`, and `NAME.theta` (in a plane)
    /// or `NAME.q0`…`NAME.q3` (in space) when it turns.
    pub name: String,
    /// Its shape.
    pub shape: BodyShape,
    /// For a body turning about a fixed axis through the origin (the pivot), that axis: the
    /// body has no position columns, only `NAME.theta`, its turn from the configuration it
    /// was described in.
    pub hinge: Option<[Real; 3]>,
}

/// How a body is drawn.
#[derive(Debug, Clone, PartialEq)]
pub enum BodyShape {
    /// A point mass: a dot of a fixed size.
    Point,
    /// A ball or disk of this radius.
    Sphere {
        /// The radius.
        radius: Real,
    },
    /// A rigid body: parts in its own frame (about its centre of mass, or its pivot when
    /// hinged), turned with it; each part drawn as the convex hull of its points as seen.
    Outline {
        /// The parts, each a list of points in the body frame.
        parts: Vec<Vec<[Real; 3]>>,
    },
}

/// Where a link ends.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Attachment {
    /// A fixed point of the world.
    Fixed([Real; 3]),
    /// A point of a body: `offset` from its centre, in its own frame (turned with it).
    Body {
        /// The body (index into [`Scene::bodies`]).
        body: usize,
        /// The point, from the centre of mass, in the body frame.
        offset: [Real; 3],
    },
    /// A point beside a body that does not turn with it: `offset` from its centre, in the
    /// world's frame (where a string leaves a pulley's wheel).
    Beside {
        /// The body (index into [`Scene::bodies`]).
        body: usize,
        /// The point, from the centre of mass, in the world's frame.
        offset: [Real; 3],
    },
}

/// A thing drawn besides the bodies.
#[derive(Debug, Clone, PartialEq)]
pub enum SceneItem {
    /// A spring: drawn as a coil between its ends.
    Spring {
        /// One end.
        a: Attachment,
        /// The other.
        b: Attachment,
    },
    /// A rod or a joint's arm: a straight bar.
    Rod {
        /// One end.
        a: Attachment,
        /// The other.
        b: Attachment,
    },
    /// A string or rope: a thin line.
    String {
        /// One end.
        a: Attachment,
        /// The other.
        b: Attachment,
    },
    /// A wall or the floor: the line through `point` across `normal`, hatched on the side
    /// away from the normal.
    Wall {
        /// A point of it.
        point: [Real; 3],
        /// Its normal, towards the bodies.
        normal: [Real; 3],
    },
    /// A pulley's wheel, fixed.
    Pulley {
        /// Its axle.
        centre: [Real; 3],
        /// Its radius.
        radius: Real,
    },
}

impl Scene {
    /// The scene of a particle system: its bodies as points (a front that knows their sizes
    /// sets [`Body::shape`]), and what its forces look like ([`Force::sketch`]). A 1-D run is
    /// drawn upright.
    ///
    /// [`Force::sketch`]: crate::forces::Force::sketch
    pub fn of_system(system: &crate::particles::ParticleSystem) -> Scene {
        Scene {
            dim: system.dim(),
            bodies: system
                .bodies()
                .iter()
                .map(|b| Body {
                    name: b.name.clone(),
                    shape: BodyShape::Point,
                    hinge: None,
                })
                .collect(),
            items: system
                .forces()
                .iter()
                .flat_map(crate::forces::Force::sketch)
                .collect(),
            upright: system.dim() == 1,
        }
    }

    /// A wall through `point` with `normal` (as many components as the run has).
    pub fn wall(point: &[Real], normal: &[Real]) -> SceneItem {
        let v = |x: &[Real]| std::array::from_fn(|a| x.get(a).copied().unwrap_or(0.0));
        SceneItem::Wall {
            point: v(point),
            normal: v(normal),
        }
    }
}

//! The shapes of a frame and of the background: links under bodies (springs as coils, rods,
//! strings), balls, the convex hulls of rigid bodies' parts, walls hatched behind, anchors;
//! the view that holds them.

use super::scene::{Attachment, BodyShape, Scene, SceneItem};
use super::track::{Pose, Projection};
use super::{Colour, Geometry, Shape, View};
use crate::Real;

const INK: Colour = Colour(60, 60, 60);
const STEEL: Colour = Colour(120, 120, 130);

/// A spring's coil from `a` to `b`, `width` across.
pub(super) fn coil(a: [Real; 2], b: [Real; 2], width: Real) -> Vec<[Real; 2]> {
    pub(super) const TURNS: usize = 8;
    let d = [b[0] - a[0], b[1] - a[1]];
    let len = d[0].hypot(d[1]);
    if len <= 0.0 {
        return vec![a, b];
    }
    let (u, n) = ([d[0] / len, d[1] / len], [-d[1] / len, d[0] / len]);
    let lead = 0.1 * len;
    let mut points = vec![a, [a[0] + u[0] * lead, a[1] + u[1] * lead]];
    let body = len - 2.0 * lead;
    for k in 0..2 * TURNS {
        let along = lead + body * (k as Real + 0.5) / (2 * TURNS) as Real;
        let side = if k % 2 == 0 { 0.5 } else { -0.5 } * width;
        points.push([
            a[0] + u[0] * along + n[0] * side,
            a[1] + u[1] * along + n[1] * side,
        ]);
    }
    points.push([b[0] - u[0] * lead, b[1] - u[1] * lead]);
    points.push(b);
    points
}

pub(super) fn finite(p: [Real; 2]) -> bool {
    p[0].is_finite() && p[1].is_finite()
}

/// Bounds `[x_min, y_min, x_max, y_max]` growing to hold points.
#[derive(Clone, Copy)]
pub(super) struct Bounds([Real; 4]);

impl Bounds {
    pub(super) const EMPTY: Bounds = Bounds([
        Real::INFINITY,
        Real::INFINITY,
        Real::NEG_INFINITY,
        Real::NEG_INFINITY,
    ]);

    pub(super) fn add(&mut self, p: [Real; 2], r: Real) {
        if finite(p) && r.is_finite() {
            let b = &mut self.0;
            b[0] = b[0].min(p[0] - r);
            b[1] = b[1].min(p[1] - r);
            b[2] = b[2].max(p[0] + r);
            b[3] = b[3].max(p[1] + r);
        }
    }

    /// The view: these bounds with a margin, at least `min_size` across, centred.
    pub(super) fn view(self, min_size: Real) -> View {
        let [x0, y0, x1, y1] = if self.0[0] <= self.0[2] {
            self.0
        } else {
            [0.0, 0.0, 0.0, 0.0]
        };
        let size = (x1 - x0).max(y1 - y0).max(min_size);
        let margin = 0.08 * size;
        let half_w = 0.5 * (x1 - x0).max(0.25 * size) + margin;
        let half_h = 0.5 * (y1 - y0).max(0.25 * size) + margin;
        let (cx, cy) = (0.5 * (x0 + x1), 0.5 * (y0 + y1));
        View {
            x_min: cx - half_w,
            x_max: cx + half_w,
            y_min: cy - half_h,
            y_max: cy + half_h,
        }
    }
}

/// The segment of the line through `p` along `d` inside the rectangle `v`, if any.
pub(super) fn clip_line(p: [Real; 2], d: [Real; 2], v: &View) -> Option<[[Real; 2]; 2]> {
    let (mut lo, mut hi) = (Real::NEG_INFINITY, Real::INFINITY);
    for (a, (min, max)) in [(v.x_min, v.x_max), (v.y_min, v.y_max)]
        .into_iter()
        .enumerate()
    {
        if d[a].abs() < 1e-300 {
            if p[a] < min || p[a] > max {
                return None;
            }
        } else {
            let (t0, t1) = ((min - p[a]) / d[a], (max - p[a]) / d[a]);
            lo = lo.max(t0.min(t1));
            hi = hi.min(t0.max(t1));
        }
    }
    (lo < hi && lo.is_finite() && hi.is_finite()).then(|| {
        [
            [p[0] + lo * d[0], p[1] + lo * d[1]],
            [p[0] + hi * d[0], p[1] + hi * d[1]],
        ]
    })
}

/// The ends of a link (none for a wall or a pulley).
pub(super) fn item_ends(item: &SceneItem) -> Vec<Attachment> {
    match item {
        SceneItem::Spring { a, b } | SceneItem::Rod { a, b } | SceneItem::String { a, b } => {
            vec![*a, *b]
        }
        SceneItem::Wall { .. } | SceneItem::Pulley { .. } => Vec::new(),
    }
}

/// Where an attachment is, with the bodies at `poses`.
pub(super) fn place(end: Attachment, poses: &[Pose]) -> [Real; 3] {
    match end {
        Attachment::Fixed(p) => p,
        Attachment::Body { body, offset } => {
            poses.get(body).map_or([Real::NAN; 3], |p| p.apply(offset))
        }
        Attachment::Beside { body, offset } => poses.get(body).map_or([Real::NAN; 3], |p| {
            std::array::from_fn(|a| p.centre[a] + offset[a])
        }),
    }
}

/// The walls (a line across the view, hatched behind) and the fixed pulleys.
pub(super) fn background(
    scene: &Scene,
    project: Projection,
    view: &View,
    scale: Real,
) -> Vec<Shape> {
    let mut out = Vec::new();
    for item in &scene.items {
        match item {
            SceneItem::Wall { point, normal } => {
                let p = project.apply(*point);
                let n = project.apply(*normal);
                let len = n[0].hypot(n[1]);
                if len == 0.0 || !finite(p) {
                    continue;
                }
                let n = [n[0] / len, n[1] / len];
                let d = [-n[1], n[0]];
                let Some([a, b]) = clip_line(p, d, view) else {
                    continue;
                };
                let depth = 0.03 * scale;
                out.push(Shape {
                    geometry: Geometry::Polygon {
                        points: vec![
                            a,
                            b,
                            [b[0] - n[0] * depth, b[1] - n[1] * depth],
                            [a[0] - n[0] * depth, a[1] - n[1] * depth],
                        ],
                    },
                    fill: Some(Colour(215, 215, 215)),
                    stroke: None,
                    line_width: 0.0,
                });
                out.push(Shape {
                    geometry: Geometry::Polyline { points: vec![a, b] },
                    fill: None,
                    stroke: Some(INK),
                    line_width: 2.0,
                });
            }
            SceneItem::Pulley { centre, radius } => out.push(Shape {
                geometry: Geometry::Circle {
                    centre: project.apply(*centre),
                    radius: *radius,
                },
                fill: Some(Colour(200, 200, 205)),
                stroke: Some(STEEL),
                line_width: 2.0,
            }),
            SceneItem::Spring { a, b } | SceneItem::Rod { a, b } | SceneItem::String { a, b } => {
                for end in [a, b] {
                    if let Attachment::Fixed(p) = end {
                        out.push(anchor(project.apply(*p)));
                    }
                }
            }
        }
    }
    // the pivots of bodies turning about fixed axes
    if scene.bodies.iter().any(|b| b.hinge.is_some()) {
        out.push(anchor([0.0, 0.0]));
    }
    out
}

/// A fixed point links hang from: a dark dot.
pub(super) fn anchor(centre: [Real; 2]) -> Shape {
    Shape {
        geometry: Geometry::Dot {
            centre,
            radius_px: 3.5,
        },
        fill: Some(INK),
        stroke: None,
        line_width: 0.0,
    }
}

/// The shapes of one frame: links under bodies.
pub(super) fn frame_shapes(
    scene: &Scene,
    poses: &[Pose],
    project: Projection,
    colours: &[Colour],
    scale: Real,
) -> Vec<Shape> {
    let mut out = Vec::new();
    for item in &scene.items {
        let line = |a: &Attachment, b: &Attachment| {
            [
                project.apply(place(*a, poses)),
                project.apply(place(*b, poses)),
            ]
        };
        let (points, colour, width) = match item {
            SceneItem::Spring { a, b } => {
                let [p, q] = line(a, b);
                (coil(p, q, 0.04 * scale), STEEL, 1.5)
            }
            SceneItem::Rod { a, b } => (line(a, b).to_vec(), INK, 3.0),
            SceneItem::String { a, b } => (line(a, b).to_vec(), INK, 1.0),
            SceneItem::Wall { .. } | SceneItem::Pulley { .. } => continue,
        };
        if points.iter().all(|p| finite(*p)) {
            out.push(Shape {
                geometry: Geometry::Polyline { points },
                fill: None,
                stroke: Some(colour),
                line_width: width,
            });
        }
    }
    for ((body, pose), colour) in scene.bodies.iter().zip(poses).zip(colours) {
        let centre = project.apply(pose.centre);
        match &body.shape {
            BodyShape::Point => out.push(Shape {
                geometry: Geometry::Dot {
                    centre,
                    radius_px: 5.0,
                },
                fill: Some(*colour),
                stroke: None,
                line_width: 0.0,
            }),
            BodyShape::Sphere { radius } => {
                out.push(Shape {
                    geometry: Geometry::Circle {
                        centre,
                        radius: *radius,
                    },
                    fill: Some(*colour),
                    stroke: Some(INK),
                    line_width: 1.0,
                });
                // a mark on a turning ball shows it roll
                if !matches!(pose.rotation, [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], _]) {
                    let rim = project.apply(pose.apply([*radius, 0.0, 0.0]));
                    out.push(Shape {
                        geometry: Geometry::Polyline {
                            points: vec![centre, rim],
                        },
                        fill: None,
                        stroke: Some(Colour(255, 255, 255)),
                        line_width: 2.0,
                    });
                }
            }
            BodyShape::Outline { parts } => {
                for part in parts {
                    let points: Vec<[Real; 2]> =
                        part.iter().map(|p| project.apply(pose.apply(*p))).collect();
                    if !points.iter().all(|p| finite(*p)) {
                        continue;
                    }
                    let hull = convex_hull(points, 1e-9 * scale);
                    out.push(if hull.len() > 2 {
                        Shape {
                            geometry: Geometry::Polygon { points: hull },
                            fill: Some(*colour),
                            stroke: Some(INK),
                            line_width: 1.5,
                        }
                    } else {
                        // a rod seen from the side, or a point
                        Shape {
                            geometry: Geometry::Polyline { points: hull },
                            fill: None,
                            stroke: Some(*colour),
                            line_width: 6.0,
                        }
                    });
                }
            }
        }
    }
    out
}

/// The convex hull of `points`, counter-clockwise (Andrew's monotone chain); two points for
/// a segment (collinear points), one for a point. `tolerance` is the smallest turn counted.
pub(super) fn convex_hull(mut points: Vec<[Real; 2]>, tolerance: Real) -> Vec<[Real; 2]> {
    points.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
    points.dedup_by(|a, b| (a[0] - b[0]).abs() <= tolerance && (a[1] - b[1]).abs() <= tolerance);
    if points.len() < 3 {
        return points;
    }
    let cross = |o: [Real; 2], a: [Real; 2], b: [Real; 2]| {
        (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
    };
    let area_tolerance = tolerance * tolerance;
    let mut hull: Vec<[Real; 2]> = Vec::with_capacity(2 * points.len());
    for pass in 0..2 {
        let start = hull.len();
        let iter: Box<dyn Iterator<Item = &[Real; 2]>> = if pass == 0 {
            Box::new(points.iter())
        } else {
            Box::new(points.iter().rev())
        };
        for &p in iter {
            while hull.len() >= start + 2
                && cross(hull[hull.len() - 2], hull[hull.len() - 1], p) <= area_tolerance
            {
                hull.pop();
            }
            hull.push(p);
        }
        hull.pop();
    }
    if hull.len() < 3 {
        // collinear: the two extremes
        let (first, last) = (points[0], points[points.len() - 1]);
        return vec![first, last];
    }
    hull
}

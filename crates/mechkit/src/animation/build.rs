//! The frames of a run's animation: the scene placed at each frame's time, interpolated
//! between the run's rows (cubic Hermite on the positions and their velocities, where the run
//! has them: the same accuracy as a dense output of order 3), seen through one view that holds
//! the whole motion.

use super::scene::{Attachment, Body, BodyShape, Scene, SceneItem};
use super::{Animation, Colour, EnergyBars, Frame, Geometry, Shape, Trail, View};
use crate::Real;

/// Frames per second when none is asked for.
pub const DEFAULT_FPS: Real = 25.0;

/// The most frames an animation has (a longer one plays faster).
pub const MAX_FRAMES: usize = 2000;

/// The shortest and the longest playback, in seconds, when no speed is asked for: a run
/// shorter than the first plays slowed down, one longer than the second sped up.
const PLAYBACK: (Real, Real) = (4.0, 12.0);

/// How an animation is made.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AnimationOptions {
    /// Frames per second of playback.
    pub fps: Real,
    /// Simulated seconds per second of playback; None: real time, slowed down or sped up so
    /// that it plays for 4 to 12 s.
    pub speed: Option<Real>,
    /// Draw each body's path.
    pub trails: bool,
    /// Draw the energies (K, U, E) as bars beside the scene.
    pub energy_bars: bool,
}

impl Default for AnimationOptions {
    fn default() -> Self {
        Self {
            fps: DEFAULT_FPS,
            speed: None,
            trails: true,
            energy_bars: true,
        }
    }
}

/// The colours bodies are drawn in, in turn.
const BODY_COLOURS: [Colour; 8] = [
    Colour(31, 119, 180),
    Colour(214, 39, 40),
    Colour(44, 160, 44),
    Colour(255, 127, 14),
    Colour(148, 103, 189),
    Colour(140, 86, 75),
    Colour(227, 119, 194),
    Colour(23, 190, 207),
];

const INK: Colour = Colour(60, 60, 60);
const STEEL: Colour = Colour(120, 120, 130);

/// A table of the run's columns by name (`t`, `ball.x`, `K`).
pub trait Columns {
    /// The values of the column `name`, one per row.
    fn column(&self, name: &str) -> Option<&[Real]>;
}

#[cfg(feature = "scenario")]
impl Columns for crate::scenario::Trajectory {
    fn column(&self, name: &str) -> Option<&[Real]> {
        crate::scenario::Trajectory::column(self, name)
    }
}

/// A CSV file read back (a run directory's `trajectory.csv`): columns by their exact header
/// names.
impl Columns for crate::data::Table {
    fn column(&self, name: &str) -> Option<&[Real]> {
        let index = self.names()?.iter().position(|n| n == name)?;
        crate::data::Table::column(self, &crate::data::ColumnRef::Index(index)).ok()
    }
}

impl Columns for [(String, Vec<Real>)] {
    fn column(&self, name: &str) -> Option<&[Real]> {
        self.iter()
            .find(|(n, _)| n == name)
            .map(|(_, v)| v.as_slice())
    }
}

/// Why an animation cannot be made.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum AnimationError {
    /// The run has no time column or no rows.
    #[error("the run has no rows to animate (no `t` column, or it is empty)")]
    NoRows,
    /// A body of the scene has no position columns.
    #[error("the run has no column `{0}`: the trajectory does not hold the body's position")]
    MissingColumn(String),
    /// An option out of range.
    #[error("{0}")]
    Option(String),
}

/// Where each body is over the run: its position columns and, when it turns, its angle or
/// quaternion columns, with the velocities that go with them.
struct Track<'a> {
    position: Vec<(&'a [Real], Option<&'a [Real]>)>,
    turn: Turn<'a>,
}

enum Turn<'a> {
    None,
    Angle(&'a [Real], Option<&'a [Real]>),
    /// About a fixed axis (a hinged body).
    Axis([Real; 3], &'a [Real], Option<&'a [Real]>),
    Quaternion([&'a [Real]; 4]),
}

/// Interpolation between rows `i` and `i + 1` at fraction `s`: cubic Hermite with the
/// derivative `dv` when given, else linear; `h` is the rows' time step.
fn hermite(x: &[Real], dv: Option<&[Real]>, i: usize, s: Real, h: Real) -> Real {
    let j = (i + 1).min(x.len() - 1);
    let (x0, x1) = (x[i], x[j]);
    match dv {
        Some(v) if j > i && h > 0.0 => {
            let (s2, s3) = (s * s, s * s * s);
            (2.0 * s3 - 3.0 * s2 + 1.0) * x0
                + (s3 - 2.0 * s2 + s) * h * v[i]
                + (-2.0 * s3 + 3.0 * s2) * x1
                + (s3 - s2) * h * v[j]
        }
        _ => x0 + s * (x1 - x0),
    }
}

/// The row interval holding time `t` and the fraction of the way through it.
fn locate(times: &[Real], t: Real) -> (usize, Real, Real) {
    let n = times.len();
    if n < 2 || t <= times[0] {
        return (0, 0.0, 0.0);
    }
    // the last row at or before t
    let i = times
        .partition_point(|&x| x <= t)
        .saturating_sub(1)
        .min(n - 2);
    let h = times[i + 1] - times[i];
    if h > 0.0 {
        (i, ((t - times[i]) / h).clamp(0.0, 1.0), h)
    } else {
        (i + 1, 0.0, 0.0)
    }
}

/// Turns `r` (body frame) by the state of a body at interpolation point `(i, s, h)`.
struct Pose {
    centre: [Real; 3],
    /// Rows of the rotation matrix body → world.
    rotation: [[Real; 3]; 3],
}

impl Pose {
    fn apply(&self, r: [Real; 3]) -> [Real; 3] {
        let m = &self.rotation;
        std::array::from_fn(|a| self.centre[a] + m[a][0] * r[0] + m[a][1] * r[1] + m[a][2] * r[2])
    }
}

fn rotation_z(theta: Real) -> [[Real; 3]; 3] {
    let (s, c) = theta.sin_cos();
    [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]
}

/// The turn by `theta` about `axis` (Rodrigues).
fn rotation_axis(axis: [Real; 3], theta: Real) -> [[Real; 3]; 3] {
    let half = 0.5 * theta;
    let n = axis.iter().map(|x| x * x).sum::<Real>().sqrt();
    let (s, c) = half.sin_cos();
    if n > 0.0 {
        rotation_q([c, s * axis[0] / n, s * axis[1] / n, s * axis[2] / n])
    } else {
        rotation_z(0.0)
    }
}

fn rotation_q(q: [Real; 4]) -> [[Real; 3]; 3] {
    let n = q.iter().map(|x| x * x).sum::<Real>().sqrt();
    let [w, x, y, z] = if n > 0.0 {
        q.map(|c| c / n)
    } else {
        [1.0, 0.0, 0.0, 0.0]
    };
    [
        [
            1.0 - 2.0 * (y * y + z * z),
            2.0 * (x * y - w * z),
            2.0 * (x * z + w * y),
        ],
        [
            2.0 * (x * y + w * z),
            1.0 - 2.0 * (x * x + z * z),
            2.0 * (y * z - w * x),
        ],
        [
            2.0 * (x * z - w * y),
            2.0 * (y * z + w * x),
            1.0 - 2.0 * (x * x + y * y),
        ],
    ]
}

const AXES: [&str; 3] = ["x", "y", "z"];

impl<'a> Track<'a> {
    fn new(
        body: &Body,
        dim: usize,
        table: &'a (impl Columns + ?Sized),
    ) -> Result<Self, AnimationError> {
        if let Some(axis) = body.hinge {
            let name = format!("{}.theta", body.name);
            let theta = table
                .column(&name)
                .ok_or(AnimationError::MissingColumn(name))?;
            let omega = table.column(&format!("{}.omega", body.name));
            return Ok(Self {
                position: Vec::new(),
                turn: Turn::Axis(axis, theta, omega),
            });
        }
        let mut position = Vec::with_capacity(dim);
        for axis in &AXES[..dim] {
            let name = format!("{}.{axis}", body.name);
            let x = table
                .column(&name)
                .ok_or(AnimationError::MissingColumn(name))?;
            position.push((x, table.column(&format!("{}.v{axis}", body.name))));
        }
        let turn = if let Some(theta) = table.column(&format!("{}.theta", body.name)) {
            Turn::Angle(theta, table.column(&format!("{}.omega", body.name)))
        } else if let (Some(a), Some(b), Some(c), Some(d)) = (
            table.column(&format!("{}.q0", body.name)),
            table.column(&format!("{}.q1", body.name)),
            table.column(&format!("{}.q2", body.name)),
            table.column(&format!("{}.q3", body.name)),
        ) {
            Turn::Quaternion([a, b, c, d])
        } else {
            Turn::None
        };
        Ok(Self { position, turn })
    }

    fn pose(&self, (i, s, h): (usize, Real, Real)) -> Pose {
        let mut centre = [0.0; 3];
        for (a, (x, v)) in self.position.iter().enumerate() {
            centre[a] = hermite(x, *v, i, s, h);
        }
        let rotation = match &self.turn {
            Turn::None => rotation_z(0.0),
            Turn::Angle(theta, omega) => rotation_z(hermite(theta, *omega, i, s, h)),
            Turn::Axis(axis, theta, omega) => rotation_axis(*axis, hermite(theta, *omega, i, s, h)),
            Turn::Quaternion(q) => {
                rotation_q(std::array::from_fn(|k| hermite(q[k], None, i, s, h)))
            }
        };
        Pose { centre, rotation }
    }
}

/// How world points (3 components) become picture points (2): the two axes kept.
#[derive(Clone, Copy)]
struct Projection {
    axes: [usize; 2],
    /// A 1-D run drawn upright: its x is the picture's vertical.
    upright: bool,
}

impl Projection {
    fn apply(self, p: [Real; 3]) -> [Real; 2] {
        if self.upright {
            [0.0, p[0]]
        } else {
            [p[self.axes[0]], p[self.axes[1]]]
        }
    }
}

/// The run's frame times: from the first row to the last at `fps` frames per second of
/// playback, `speed` simulated seconds per second.
fn frame_times(
    t0: Real,
    t1: Real,
    options: &AnimationOptions,
) -> Result<(Vec<Real>, Real), AnimationError> {
    if !(options.fps.is_finite() && (1.0..=120.0).contains(&options.fps)) {
        return Err(AnimationError::Option(format!(
            "the frame rate {} is not from 1 to 120 frames per second",
            options.fps
        )));
    }
    let duration = (t1 - t0).max(0.0);
    let speed = match options.speed {
        Some(s) if s.is_finite() && s > 0.0 => s,
        Some(s) => {
            return Err(AnimationError::Option(format!(
                "the speed {s} is not a positive number of simulated seconds per second"
            )));
        }
        None if duration > 0.0 => duration / duration.clamp(PLAYBACK.0, PLAYBACK.1),
        None => 1.0,
    };
    let wanted = (duration / speed * options.fps).ceil();
    let frames = if wanted.is_finite() {
        (wanted as usize + 1).clamp(1, MAX_FRAMES)
    } else {
        MAX_FRAMES
    };
    let speed = if frames > 1 {
        duration / ((frames - 1) as Real / options.fps)
    } else {
        speed
    };
    let times = (0..frames)
        .map(|k| {
            if frames > 1 {
                t0 + duration * k as Real / (frames - 1) as Real
            } else {
                t0
            }
        })
        .collect();
    Ok((times, speed))
}

/// The axes a 3-D run is seen along: the two that move most (a top view of a conical
/// pendulum, a side view of a projectile).
fn projection(scene: &Scene, tracks: &[Track<'_>]) -> Projection {
    // bodies turning about fixed axes are seen along the first one's axis
    if let Some(axis) = scene.bodies.iter().find_map(|b| b.hinge) {
        let along = (0..3)
            .max_by(|&a, &b| axis[a].abs().total_cmp(&axis[b].abs()))
            .unwrap_or(2);
        let kept: Vec<usize> = (0..3).filter(|&a| a != along).collect();
        return Projection {
            axes: [kept[0], kept[1]],
            upright: false,
        };
    }
    if scene.dim < 3 {
        return Projection {
            axes: [0, 1],
            upright: scene.dim == 1 && scene.upright,
        };
    }
    let extent = |a: usize| {
        tracks
            .iter()
            .filter_map(|t| t.position.get(a))
            .flat_map(|p| p.0.iter().copied())
            .filter(|x| x.is_finite())
            .fold((Real::INFINITY, Real::NEG_INFINITY), |(lo, hi), x| {
                (lo.min(x), hi.max(x))
            })
    };
    let spans: Vec<Real> = (0..3)
        .map(|a| {
            let (lo, hi) = extent(a);
            if hi >= lo { hi - lo } else { 0.0 }
        })
        .collect();
    // drop the axis of least motion; ties keep x and y
    let drop = (0..3)
        .rev()
        .min_by(|&a, &b| spans[a].total_cmp(&spans[b]))
        .unwrap_or(2);
    let kept: Vec<usize> = (0..3).filter(|&a| a != drop).collect();
    Projection {
        axes: [kept[0], kept[1]],
        upright: false,
    }
}

/// A spring's coil from `a` to `b`, `width` across.
fn coil(a: [Real; 2], b: [Real; 2], width: Real) -> Vec<[Real; 2]> {
    const TURNS: usize = 8;
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

fn finite(p: [Real; 2]) -> bool {
    p[0].is_finite() && p[1].is_finite()
}

/// Bounds `[x_min, y_min, x_max, y_max]` growing to hold points.
#[derive(Clone, Copy)]
struct Bounds([Real; 4]);

impl Bounds {
    const EMPTY: Bounds = Bounds([
        Real::INFINITY,
        Real::INFINITY,
        Real::NEG_INFINITY,
        Real::NEG_INFINITY,
    ]);

    fn add(&mut self, p: [Real; 2], r: Real) {
        if finite(p) && r.is_finite() {
            let b = &mut self.0;
            b[0] = b[0].min(p[0] - r);
            b[1] = b[1].min(p[1] - r);
            b[2] = b[2].max(p[0] + r);
            b[3] = b[3].max(p[1] + r);
        }
    }

    /// The view: these bounds with a margin, at least `min_size` across, centred.
    fn view(self, min_size: Real) -> View {
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
fn clip_line(p: [Real; 2], d: [Real; 2], v: &View) -> Option<[[Real; 2]; 2]> {
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

impl Animation {
    /// The animation of a run of `scenario` from its columns: its title, its scene, lengths in
    /// metres (or the reduced unit).
    ///
    /// # Errors
    /// As [`Animation::from_run`].
    #[cfg(feature = "scenario")]
    pub fn of_scenario(
        scenario: &crate::scenario::Scenario,
        table: &(impl Columns + ?Sized),
        options: &AnimationOptions,
    ) -> Result<Animation, AnimationError> {
        let unit = match scenario.units {
            mechkit_expr::units::UnitSystem::Reduced => "1",
            mechkit_expr::units::UnitSystem::Si => "m",
        };
        Animation::from_run(&scenario.title, &scenario.scene, table, unit, options)
    }

    /// The animation of a run of `scene`, from its columns (`t`, each body's position and
    /// turning, `K`, `U`, `E`).
    ///
    /// # Errors
    /// No rows, a body without its position columns, or options out of range.
    pub fn from_run(
        title: &str,
        scene: &Scene,
        table: &(impl Columns + ?Sized),
        length_unit: &str,
        options: &AnimationOptions,
    ) -> Result<Animation, AnimationError> {
        let times = table
            .column("t")
            .filter(|t| !t.is_empty())
            .ok_or(AnimationError::NoRows)?;
        let tracks = scene
            .bodies
            .iter()
            .map(|b| Track::new(b, scene.dim.clamp(1, 3), table))
            .collect::<Result<Vec<_>, _>>()?;
        let t_first = times[0];
        let t_last = times
            .iter()
            .copied()
            .filter(|t| t.is_finite())
            .fold(t_first, Real::max);
        let (frame_t, speed) = frame_times(t_first, t_last, options)?;
        let project = projection(scene, &tracks);
        let at: Vec<(usize, Real, Real)> = frame_t.iter().map(|&t| locate(times, t)).collect();
        let poses: Vec<Vec<Pose>> = at
            .iter()
            .map(|&p| tracks.iter().map(|tr| tr.pose(p)).collect())
            .collect();

        // the view holds every body at every frame
        let mut bounds = Bounds::EMPTY;
        let mut min_size: Real = 0.0;
        for frame in &poses {
            for (body, pose) in scene.bodies.iter().zip(frame) {
                match &body.shape {
                    BodyShape::Point => bounds.add(project.apply(pose.centre), 0.0),
                    BodyShape::Sphere { radius } => {
                        bounds.add(project.apply(pose.centre), *radius);
                        min_size = min_size.max(4.0 * radius);
                    }
                    BodyShape::Outline { parts } => {
                        for p in parts.iter().flatten() {
                            bounds.add(project.apply(pose.apply(*p)), 0.0);
                        }
                    }
                }
            }
            for item in &scene.items {
                for end in item_ends(item) {
                    bounds.add(project.apply(place(end, frame)), 0.0);
                }
            }
        }
        for item in &scene.items {
            if let SceneItem::Pulley { centre, radius } = item {
                bounds.add(project.apply(*centre), *radius);
            }
        }
        if min_size == 0.0 {
            min_size = 1e-3;
        }
        let view = bounds.view(min_size);
        let scale = view.width().max(view.height());

        let background = background(scene, project, &view, scale);
        let colours: Vec<Colour> = (0..scene.bodies.len())
            .map(|i| BODY_COLOURS[i % BODY_COLOURS.len()])
            .collect();
        let energy = if options.energy_bars {
            energy_columns(table)
        } else {
            Vec::new()
        };
        let frames = frame_t
            .iter()
            .zip(&poses)
            .zip(&at)
            .map(|((&t, frame), &(i, s, h))| Frame {
                t,
                shapes: frame_shapes(scene, frame, project, &colours, scale),
                energy: energy
                    .iter()
                    .map(|(_, _, c)| hermite(c, None, i, s, h))
                    .collect(),
            })
            .collect::<Vec<_>>();
        let trails = if options.trails {
            scene
                .bodies
                .iter()
                .enumerate()
                .filter(|(_, b)| b.hinge.is_none())
                .map(|(k, b)| Trail {
                    name: b.name.clone(),
                    colour: colours[k],
                    points: poses.iter().map(|f| project.apply(f[k].centre)).collect(),
                })
                .collect()
        } else {
            Vec::new()
        };
        let energy = (!energy.is_empty()).then(|| {
            let (lo, hi) = frames
                .iter()
                .flat_map(|f| f.energy.iter().copied())
                .filter(|e| e.is_finite())
                .fold((0.0 as Real, 0.0 as Real), |(lo, hi), e| {
                    (lo.min(e), hi.max(e))
                });
            EnergyBars {
                labels: energy.iter().map(|(l, _, _)| (*l).to_string()).collect(),
                colours: energy.iter().map(|(_, c, _)| *c).collect(),
                unit: "J".into(),
                range: (lo, if hi > lo { hi } else { lo + 1.0 }),
            }
        });
        Ok(Animation {
            title: title.to_string(),
            fps: options.fps,
            speed,
            view,
            length_unit: length_unit.to_string(),
            background,
            frames,
            trails,
            energy,
        })
    }
}

/// The energy columns the run has: kinetic, potential, total.
fn energy_columns<T: Columns + ?Sized>(table: &T) -> Vec<(&'static str, Colour, &[Real])> {
    [
        ("K", Colour(31, 119, 180)),
        ("U", Colour(44, 160, 44)),
        ("E", Colour(90, 90, 90)),
    ]
    .into_iter()
    .filter_map(|(name, colour)| table.column(name).map(|c| (name, colour, c)))
    .collect()
}

/// The ends of a link (none for a wall or a pulley).
fn item_ends(item: &SceneItem) -> Vec<Attachment> {
    match item {
        SceneItem::Spring { a, b } | SceneItem::Rod { a, b } | SceneItem::String { a, b } => {
            vec![*a, *b]
        }
        SceneItem::Wall { .. } | SceneItem::Pulley { .. } => Vec::new(),
    }
}

/// Where an attachment is, with the bodies at `poses`.
fn place(end: Attachment, poses: &[Pose]) -> [Real; 3] {
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
fn background(scene: &Scene, project: Projection, view: &View, scale: Real) -> Vec<Shape> {
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
fn anchor(centre: [Real; 2]) -> Shape {
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
fn frame_shapes(
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
fn convex_hull(mut points: Vec<[Real; 2]>, tolerance: Real) -> Vec<[Real; 2]> {
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

#[cfg(test)]
mod tests {
    use super::*;

    fn circle_run(n: usize) -> Vec<(String, Vec<Real>)> {
        let t: Vec<Real> = (0..n).map(|i| i as Real * 0.1).collect();
        let col = |f: &dyn Fn(Real) -> Real| t.iter().map(|&t| f(t)).collect::<Vec<_>>();
        vec![
            ("t".into(), t.clone()),
            ("ball.x".into(), col(&|t| t.cos())),
            ("ball.y".into(), col(&|t| t.sin())),
            ("ball.vx".into(), col(&|t| -t.sin())),
            ("ball.vy".into(), col(&|t| t.cos())),
            ("K".into(), col(&|_| 0.5)),
        ]
    }

    fn scene() -> Scene {
        Scene {
            dim: 2,
            bodies: vec![Body {
                name: "ball".into(),
                shape: BodyShape::Sphere { radius: 0.1 },
                hinge: None,
            }],
            items: vec![SceneItem::Spring {
                a: Attachment::Fixed([0.0; 3]),
                b: Attachment::Body {
                    body: 0,
                    offset: [0.0; 3],
                },
            }],
            upright: false,
        }
    }

    #[test]
    fn hermite_frames_follow_the_circle_between_rows() {
        let table = circle_run(64);
        let options = AnimationOptions {
            fps: 25.0,
            speed: Some(1.0),
            ..AnimationOptions::default()
        };
        let a = Animation::from_run("circle", &scene(), table.as_slice(), "m", &options).unwrap();
        // 6.3 s at 25 frames per second
        assert_eq!(a.frames.len(), 159);
        for f in &a.frames {
            let Some(Geometry::Circle { centre, .. }) = f
                .shapes
                .iter()
                .map(|s| &s.geometry)
                .find(|g| matches!(g, Geometry::Circle { .. }))
            else {
                panic!("no ball")
            };
            // cubic Hermite on rows 0.1 s apart: error ~ h^4/384
            assert!((centre[0] - f.t.cos()).abs() < 1e-6, "{f:?}");
            assert!((centre[1] - f.t.sin()).abs() < 1e-6);
        }
        assert!(a.view.x_min < -1.1 && a.view.x_max > 1.1 && a.view.y_min < -1.1);
        assert_eq!(a.trails[0].points.len(), a.frames.len());
        assert_eq!(a.energy.as_ref().unwrap().labels, ["K"]);
    }

    #[test]
    fn hulls() {
        let square = vec![[0.0, 0.0], [1.0, 0.0], [0.5, 0.5], [1.0, 1.0], [0.0, 1.0]];
        assert_eq!(convex_hull(square, 1e-12).len(), 4);
        let rod = vec![[0.0, 0.0], [1.0, 1.0], [0.5, 0.5]];
        assert_eq!(convex_hull(rod, 1e-12), [[0.0, 0.0], [1.0, 1.0]]);
    }

    #[test]
    fn a_missing_column_is_named() {
        let mut table = circle_run(5);
        table.retain(|(n, _)| n != "ball.y");
        let e = Animation::from_run(
            "c",
            &scene(),
            table.as_slice(),
            "m",
            &AnimationOptions::default(),
        )
        .unwrap_err();
        assert!(e.to_string().contains("`ball.y`"), "{e}");
    }

    #[test]
    fn playback_is_4_to_12_seconds_unless_a_speed_is_given() {
        let o = AnimationOptions::default();
        let (t, speed) = frame_times(0.0, 100.0, &o).unwrap();
        assert_eq!(t.len(), 301);
        assert!((speed - 100.0 / 12.0).abs() < 1e-9);
        let (t, _) = frame_times(0.0, 0.01, &o).unwrap();
        assert_eq!(t.len(), 101);
        assert!(frame_times(0.0, 1.0, &AnimationOptions { fps: 0.0, ..o }).is_err());
        assert!(
            frame_times(
                0.0,
                1e300,
                &AnimationOptions {
                    speed: Some(1e-300),
                    ..o
                }
            )
            .unwrap()
            .0
            .len()
                == MAX_FRAMES
        );
    }
}

//! The frames of a run's animation: the scene placed at each frame's time, interpolated
//! between the run's rows (cubic Hermite on the positions and their velocities, where the run
//! has them: the same accuracy as a dense output of order 3), seen through one view that holds
//! the whole motion.

use super::draw::{Bounds, background, frame_shapes, item_ends, place};
use super::scene::{BodyShape, Scene, SceneItem};
use super::track::{Pose, Track, hermite, locate, projection};
use super::{Animation, Colour, EnergyBars, Frame, Trail};
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
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
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
    /// A playback speed that would give the run fewer than two frames or more than
    /// [`MAX_FRAMES`]: refused with the speeds that fit, not silently changed.
    #[error(
        "the speed {} simulated s per s is not one this run of {} s can be shown at with {} frames per second; choose a speed from {} ({MAX_FRAMES} frames) to {} (2 frames)",
        crate::error::short(*speed),
        crate::error::short(*duration),
        crate::error::short(*fps),
        crate::error::short(*slowest),
        crate::error::short(*fastest)
    )]
    Speed {
        /// The speed asked for (simulated seconds per second).
        speed: Real,
        /// The run's duration (s).
        duration: Real,
        /// The frames it would make.
        frames: Real,
        /// The frame rate.
        fps: Real,
        /// The slowest speed that fits.
        slowest: Real,
        /// The fastest speed that fits.
        fastest: Real,
    },
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
    // a speed given is kept (to the rounding of a whole number of frames) or refused
    let (slowest, fastest) = (
        duration * options.fps / (MAX_FRAMES - 1) as Real,
        duration * options.fps,
    );
    if options.speed.is_some() && duration > 0.0 && !(slowest..=fastest).contains(&speed) {
        return Err(AnimationError::Speed {
            speed,
            duration,
            frames: wanted + 1.0,
            fps: options.fps,
            slowest,
            fastest,
        });
    }
    let frames = if wanted.is_finite() && wanted < MAX_FRAMES as Real {
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

#[cfg(test)]
mod tests {
    use super::super::Geometry;
    use super::super::draw::convex_hull;
    use super::super::scene::{Attachment, Body};
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
        let with_speed = |speed| AnimationOptions {
            speed: Some(speed),
            ..o
        };
        let (t, speed) = frame_times(0.0, 5.0, &with_speed(0.5)).unwrap();
        assert_eq!((t.len(), speed), (251, 0.5));
    }

    /// `--speed 1e-300` made one frame (an overflow of the frame count, a panic in a debug
    /// build) and `--speed 1e300` silently became 125 s/s: a speed given is kept or refused.
    #[test]
    fn a_speed_that_does_not_fit_the_run_is_refused_with_the_speeds_that_do() {
        let o = AnimationOptions::default();
        for speed in [1e-300, 1e300, 0.06, 126.0] {
            let e = frame_times(
                0.0,
                5.0,
                &AnimationOptions {
                    speed: Some(speed),
                    ..o
                },
            )
            .unwrap_err();
            assert!(matches!(e, AnimationError::Speed { .. }), "{e}");
            assert!(e.to_string().contains("from 0.0625"), "{e}");
            assert!(e.to_string().contains("to 125 (2 frames)"), "{e}");
        }
        let (t, _) = frame_times(
            0.0,
            5.0,
            &AnimationOptions {
                speed: Some(125.0),
                ..o
            },
        )
        .unwrap();
        assert_eq!(t.len(), 2);
        let slowest = 5.0 * 25.0 / (MAX_FRAMES - 1) as Real;
        let (t, _) = frame_times(
            0.0,
            5.0,
            &AnimationOptions {
                speed: Some(slowest),
                ..o
            },
        )
        .unwrap();
        assert_eq!(t.len(), MAX_FRAMES);
    }
}

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
            crate::error::short(options.fps)
        )));
    }
    let duration = (t1 - t0).max(0.0);
    let speed = match options.speed {
        Some(s) if s.is_finite() && s > 0.0 => s,
        Some(s) => {
            return Err(AnimationError::Option(format!(
                "the speed {} is not a positive number of simulated seconds per second",
                crate::error::short(s)
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
#[path = "build_tests.rs"]
mod tests;

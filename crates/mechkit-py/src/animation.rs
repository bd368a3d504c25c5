//! `Run.animate()`: the run's animation (the library's `Animation::from_run`, the same value
//! `mechkit animate` draws), as a `mechkit.Animation` that Jupyter shows inline as the HTML
//! player (`_repr_html_`), and that saves itself as a GIF, an MP4 (with ffmpeg) or the HTML
//! file, drawn by the command line's renderers.

use std::path::PathBuf;

use mechkit::animation::{Animation as Frames, AnimationFormat, AnimationOptions};
use mechkit::scenario::Scenario;
use mechkit_cli::animate::Canvas;
use numpy::PyReadonlyArray1;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::errors::MechkitError;
use crate::plot::Replay;

/// A run's animation: `Run.animate()`.
///
/// ```python
/// a = mechkit.Scenario.load("examples/bouncing_ball_floor.toml").run().animate()
/// a                      # in Jupyter: the player, inline
/// a.save("ball.gif")     # or .html (self-contained), .mp4 (needs ffmpeg)
/// len(a), a.fps          # frames, frames per second
/// ```
#[pyclass(module = "mechkit", name = "Animation", frozen)]
pub struct Animation {
    frames: Frames,
    canvas: Canvas,
}

/// Builds the animation of a run from its trajectory's columns and the scenario it ran
/// (parsed again from `replay` for its shapes).
pub fn of_run(
    py: Python<'_>,
    replay: &Replay,
    trajectory: &Bound<'_, PyDict>,
    options: AnimationOptions,
    canvas: Canvas,
) -> PyResult<Animation> {
    let mut columns: Vec<(String, Vec<f64>)> = Vec::with_capacity(trajectory.len());
    for (name, values) in trajectory.iter() {
        let values: PyReadonlyArray1<'_, f64> = values.extract()?;
        columns.push((name.extract()?, values.as_array().to_vec()));
    }
    let frames = py
        .detach(|| -> Result<Frames, String> {
            let scenario = Scenario::from_str_with(&replay.name, &replay.text, &replay.overrides)
                .map_err(|e| e.to_string())?;
            Frames::of_scenario(&scenario, columns.as_slice(), &options).map_err(|e| e.to_string())
        })
        .map_err(MechkitError::new_err)?;
    Ok(Animation { frames, canvas })
}

fn error(e: &anyhow::Error) -> PyErr {
    MechkitError::new_err(format!("{e:#}"))
}

#[pymethods]
impl Animation {
    /// The self-contained HTML player (Jupyter shows it inline).
    fn _repr_html_(&self) -> String {
        mechkit_cli::animate::html(&self.frames, self.canvas)
    }

    /// The HTML player as text: one file with its data, script and styles inside.
    #[getter]
    fn html(&self) -> String {
        mechkit_cli::animate::html(&self.frames, self.canvas)
    }

    /// The animated GIF's bytes.
    fn gif(&self, py: Python<'_>) -> PyResult<Vec<u8>> {
        py.detach(|| mechkit_cli::animate::gif(&self.frames, self.canvas))
            .map_err(|e| error(&e))
    }

    /// Writes the animation to `path` in the format its extension names: `.gif`, `.html` or
    /// `.mp4` (needs ffmpeg on the PATH). Returns the path.
    fn save(&self, py: Python<'_>, path: PathBuf) -> PyResult<PathBuf> {
        let format = path
            .extension()
            .and_then(|e| AnimationFormat::parse(&e.to_string_lossy()))
            .ok_or_else(|| {
                MechkitError::new_err(format!(
                    "save: name the file .gif, .html or .mp4, not {}",
                    path.display()
                ))
            })?;
        py.detach(|| -> anyhow::Result<()> {
            match format {
                AnimationFormat::Gif => {
                    let bytes = mechkit_cli::animate::gif(&self.frames, self.canvas)?;
                    mechkit::csv::write_atomic(&path, &bytes)?;
                }
                AnimationFormat::Html => {
                    let text = mechkit_cli::animate::html(&self.frames, self.canvas);
                    mechkit::csv::write_atomic(&path, text.as_bytes())?;
                }
                AnimationFormat::Mp4 => {
                    mechkit_cli::animate::mp4(&self.frames, self.canvas, &path)?;
                }
            }
            Ok(())
        })
        .map_err(|e| error(&e))?;
        Ok(path)
    }

    /// The number of frames.
    fn __len__(&self) -> usize {
        self.frames.frames.len()
    }

    /// Frames per second of playback.
    #[getter]
    fn fps(&self) -> f64 {
        self.frames.fps
    }

    /// Simulated seconds per second of playback.
    #[getter]
    fn speed(&self) -> f64 {
        self.frames.speed
    }

    /// The time of each frame (s).
    #[getter]
    fn times(&self) -> Vec<f64> {
        self.frames.frames.iter().map(|f| f.t).collect()
    }

    fn __repr__(&self) -> String {
        format!(
            "<mechkit.Animation {} frames at {} frames/s of {:?}>",
            self.frames.frames.len(),
            self.frames.fps,
            self.frames.title
        )
    }
}

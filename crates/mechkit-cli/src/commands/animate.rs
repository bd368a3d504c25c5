//! `mechkit animate`: a run's animation (`mechkit::animation`) drawn by the renderers of
//! `crate::animate`, from a scenario (run in memory) or from a run directory (its
//! trajectory.csv read back, the shapes from the scenario its summary names). `mechkit run`
//! calls [`write_animations`] for `[output] animation`.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result, anyhow, bail};
use mechkit::animation::{
    Animation, AnimationError, AnimationFormat, AnimationOptions, Columns, Scene,
};
use mechkit::scenario::Scenario;

use super::{Outcome, report};
use crate::animate::Canvas;
use crate::args::AnimateArgs;

/// What `--json` prints: the files written.
#[derive(serde::Serialize)]
struct Written {
    frames: usize,
    fps: f64,
    speed: f64,
    files: Vec<String>,
}

pub fn animate(args: &AnimateArgs) -> Result<Outcome> {
    let formats = args
        .format
        .iter()
        .map(|f| {
            AnimationFormat::parse(f)
                .ok_or_else(|| anyhow!("--format: unknown format `{f}`; use gif, mp4 or html"))
        })
        .collect::<Result<Vec<_>>>()?;
    let options = AnimationOptions {
        fps: args.fps,
        speed: args.speed,
        trails: !args.no_trails,
        energy_bars: !args.no_energy_bars,
    };
    // the size every format draws at, refused at the flag before anything runs (an HTML
    // player of 0 x 1 pixels was accepted, a GIF refused it only after the run)
    let canvas = Canvas {
        width: args.width,
        height: args.height,
    };
    for (flag, side) in [("--width", args.width), ("--height", args.height)] {
        if !Canvas::SIDES.contains(&side) {
            bail!(
                "{flag} {side}: an animation's sides are from {} to {} pixels",
                Canvas::SIDES.start(),
                Canvas::SIDES.end()
            );
        }
    }
    let xyz = if args.input.is_dir() {
        Some(args.input.join("trajectory.xyz"))
            .filter(|p| p.is_file() && !args.input.join("trajectory.csv").exists())
    } else {
        Some(args.input.clone())
            .filter(|p| p.extension().is_some_and(|e| e.eq_ignore_ascii_case("xyz")))
    };
    let (animation, out) = if let Some(path) = xyz {
        if args.set.is_some() {
            bail!("--set changes a scenario before it runs; an XYZ file holds a finished run");
        }
        let animation = from_xyz(&path, &options).map_err(flagged)?;
        let dir = path
            .parent()
            .map_or_else(|| PathBuf::from("."), Path::to_path_buf);
        (animation, args.out.clone().unwrap_or(dir))
    } else if args.input.is_dir() {
        if args.set.is_some() {
            bail!("--set changes a scenario before it runs; a run directory has already run");
        }
        let animation = from_run_dir(&args.input, &options).map_err(flagged)?;
        (
            animation,
            args.out.clone().unwrap_or_else(|| args.input.clone()),
        )
    } else {
        let Some(out) = args.out.clone() else {
            bail!(
                "--out: give the directory to write the animation in, e.g. --out out/{}",
                args.input
                    .file_stem()
                    .map_or_else(|| "run".into(), |s| s.to_string_lossy())
            );
        };
        let scenario = super::run::load(&args.input, args.set.as_deref())?;
        let (run, trajectory) = scenario.run_with_trajectory()?;
        if run.failed() {
            eprintln!(
                "warning: the run stopped early ({}); the animation shows it up to there",
                run.report.stop_reason
            );
        }
        (
            build(&scenario, &trajectory, &options).map_err(flagged)?,
            out,
        )
    };
    let files = write(&animation, &formats, canvas, &out)?;
    let written = Written {
        frames: animation.frames.len(),
        fps: animation.fps,
        speed: animation.speed,
        files: files.iter().map(|p| p.display().to_string()).collect(),
    };
    report(args.report, &written, || {
        let mut text = format!(
            "{} frames at {} frames/s ({} simulated s per s)\n",
            written.frames,
            mechkit::expr::short_number(written.fps),
            mechkit::expr::short_fixed(written.speed, 3)
        );
        for f in &written.files {
            text.push_str("wrote ");
            text.push_str(f);
            text.push('\n');
        }
        text
    })?;
    Ok(Outcome::Success)
}

/// The animation of a scenario's run from its columns.
pub fn build(
    scenario: &Scenario,
    table: &(impl Columns + ?Sized),
    options: &AnimationOptions,
) -> Result<Animation> {
    Ok(Animation::of_scenario(scenario, table, options)?)
}

/// The animation of a run directory: its trajectory.csv, drawn with the shapes of the
/// scenario its summary.json names (points when that file is gone).
fn from_run_dir(dir: &Path, options: &AnimationOptions) -> Result<Animation> {
    let summary_path = dir.join("summary.json");
    let summary: serde_json::Value = serde_json::from_str(
        &mechkit::csv::read_bounded_text(&summary_path, mechkit::csv::MAX_DATA_BYTES)
            .with_context(|| {
                format!(
                    "{} is not a run directory: cannot read {}",
                    dir.display(),
                    summary_path.display()
                )
            })?,
    )
    .with_context(|| format!("cannot read {}", summary_path.display()))?;
    let trajectory_path = dir.join("trajectory.csv");
    let table = mechkit::data::Table::read(&trajectory_path)
        .with_context(|| format!("cannot read {}", trajectory_path.display()))?;
    let scenario_path = summary["scenario"].as_str().map(PathBuf::from);
    let title = summary["title"].as_str().unwrap_or("run").to_string();
    match scenario_path.as_deref().map(Scenario::load) {
        Some(Ok(scenario)) => {
            let hash = format!("{:016x}", scenario.source_hash);
            if summary["provenance"]["scenario_fnv1a"]
                .as_str()
                .is_some_and(|h| h != hash)
            {
                eprintln!(
                    "warning: {} has changed since the run; its shapes may not match the trajectory",
                    scenario_path
                        .as_deref()
                        .map_or_else(String::new, |p| p.display().to_string())
                );
            }
            build(&scenario, &table, options)
        }
        other => {
            let why = match other {
                Some(Err(e)) => format!("{e}"),
                _ => "summary.json names no scenario".into(),
            };
            eprintln!("warning: the bodies are drawn as points: {why}");
            let scene = points_scene(&table);
            Ok(Animation::from_run(&title, &scene, &table, "m", options)?)
        }
    }
}

/// The animation of an extended XYZ file (`mechkit md --xyz-every`'s trajectory.xyz).
fn from_xyz(path: &Path, options: &AnimationOptions) -> Result<Animation> {
    let text = mechkit::csv::read_bounded_text(path, mechkit::csv::MAX_DATA_BYTES)
        .with_context(|| format!("cannot read {}", path.display()))?;
    let frames =
        mechkit::animation::parse_xyz(&text).map_err(|e| anyhow!("{}: {e}", path.display()))?;
    let title = format!("{} atoms ({})", frames[0].positions.len(), path.display());
    Ok(Animation::from_xyz(&title, &frames, options))
}

/// The bodies of a trajectory's columns (`NAME.x`), as points.
fn points_scene(table: &mechkit::data::Table) -> Scene {
    let names = table.names().unwrap_or_default();
    let mut bodies = Vec::new();
    let mut dim = 1;
    for n in names {
        if let Some(body) = n.strip_suffix(".x") {
            bodies.push(mechkit::animation::Body {
                name: body.to_string(),
                shape: mechkit::animation::BodyShape::Point,
                hinge: None,
            });
            for (d, axis) in [(2, ".y"), (3, ".z")] {
                if names.iter().any(|m| *m == format!("{body}{axis}")) {
                    dim = dim.max(d);
                }
            }
        }
    }
    Scene {
        dim,
        bodies,
        items: Vec::new(),
        upright: dim == 1,
    }
}

/// Writes the animation in each format into `dir` (created if needed); returns the files.
pub fn write(
    animation: &Animation,
    formats: &[AnimationFormat],
    canvas: Canvas,
    dir: &Path,
) -> Result<Vec<PathBuf>> {
    std::fs::create_dir_all(dir)
        .with_context(|| format!("--out: cannot create {}", dir.display()))?;
    // a name taken by a device, a pipe or a directory is refused before any frame is drawn
    for &format in formats {
        let path = dir.join(format.file_name());
        mechkit::csv::writable_target(&path)
            .with_context(|| format!("cannot write {}", path.display()))?;
    }
    let mut files = Vec::new();
    for &format in formats {
        let path = dir.join(format.file_name());
        match format {
            AnimationFormat::Gif => {
                let bytes = crate::animate::gif(animation, canvas)?;
                mechkit::csv::write_atomic(&path, &bytes)
                    .with_context(|| format!("cannot write {}", path.display()))?;
            }
            AnimationFormat::Html => {
                let text = crate::animate::html(animation, canvas);
                mechkit::csv::write_atomic(&path, text.as_bytes())
                    .with_context(|| format!("cannot write {}", path.display()))?;
            }
            AnimationFormat::Mp4 => crate::animate::mp4(animation, canvas, &path)?,
        }
        files.push(path);
    }
    Ok(files)
}

/// `[output] animation` of a run written to `dir`: its trajectory read back and drawn in
/// each format the scenario asks for.
pub fn write_animations(scenario: &Scenario, dir: &Path) -> Result<Vec<PathBuf>> {
    if scenario.animation.is_empty() {
        return Ok(Vec::new());
    }
    let path = dir.join("trajectory.csv");
    let table = mechkit::data::Table::read(&path)
        .with_context(|| format!("cannot read {}", path.display()))?;
    let animation = build(scenario, &table, &AnimationOptions::default())?;
    write(&animation, &scenario.animation, Canvas::default(), dir)
}

/// An animation's error named by its flag (`--speed`), others as they are.
fn flagged(e: anyhow::Error) -> anyhow::Error {
    match e.downcast_ref::<AnimationError>() {
        Some(AnimationError::Speed { .. }) => anyhow!("--speed: {e}"),
        _ => e,
    }
}

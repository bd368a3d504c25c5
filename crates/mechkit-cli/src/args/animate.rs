//! `mechkit animate`: a run as a GIF, an MP4 or an HTML player.

use std::path::PathBuf;

/// `mechkit animate`.
#[derive(Debug, clap::Args)]
pub struct AnimateArgs {
    /// A scenario file (TOML: it is run first), or the output directory of `mechkit run`
    /// (its trajectory.csv, and the scenario its summary.json names, for the shapes).
    pub input: PathBuf,
    /// gif, mp4 (needs ffmpeg on the PATH) or html (one self-contained file); a list such as
    /// gif,html writes each.
    #[arg(long, short, value_delimiter = ',', default_value = "gif")]
    pub format: Vec<String>,
    /// The directory to write animation.gif (.mp4, .html) in; by default the run directory
    /// given, and required with a scenario file.
    #[arg(long, short)]
    pub out: Option<PathBuf>,
    /// Frames per second of playback (1 to 120).
    #[arg(long, default_value_t = mechkit::animation::DEFAULT_FPS, allow_hyphen_values = true)]
    pub fps: f64,
    /// Simulated seconds per second of playback (default: real time, slowed down or sped up so
    /// that the animation plays for 4 to 12 s).
    #[arg(long, allow_hyphen_values = true)]
    pub speed: Option<f64>,
    /// Do not draw the bodies' paths.
    #[arg(long)]
    pub no_trails: bool,
    /// Do not draw the energy bars beside the scene.
    #[arg(long)]
    pub no_energy_bars: bool,
    /// The picture's width in pixels.
    #[arg(long, default_value_t = 640, allow_hyphen_values = true)]
    pub width: u32,
    /// The picture's height in pixels.
    #[arg(long, default_value_t = 480, allow_hyphen_values = true)]
    pub height: u32,
    /// Give constants of the scenario other values, as `run --set` does (a scenario file only).
    #[arg(long, allow_hyphen_values = true)]
    pub set: Option<String>,
    /// `-q` prints nothing but warnings and errors; `--json` prints the files written as JSON.
    #[command(flatten)]
    pub report: super::Report,
}

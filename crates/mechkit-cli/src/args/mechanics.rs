//! Arguments of the work, energy, momentum and data commands (`work`, `derive`, `potential`,
//! `power`, `rocket`, `collide`, `impulse`, `com`).

use std::path::PathBuf;

/// `mechkit collide`.
#[derive(Debug, clap::Args)]
pub struct CollideArgs {
    /// Mass of body 1, e.g. "0.2 kg".
    #[arg(long, allow_hyphen_values = true)]
    pub m1: String,
    /// Velocity of body 1: one component in 1-D, or "vx, vy[, vz]", e.g. "15 m/s".
    #[arg(long, allow_hyphen_values = true)]
    pub v1: String,
    /// Mass of body 2 ("inf" for an immovable wall).
    #[arg(long, allow_hyphen_values = true)]
    pub m2: String,
    /// Velocity of body 2 (0 for at rest).
    #[arg(long, allow_hyphen_values = true)]
    pub v2: String,
    /// Coefficient of restitution from 0 to 1, or elastic (1) or perfectly-inelastic (0).
    #[arg(long, short = 'e', allow_hyphen_values = true)]
    pub restitution: String,
    /// Contact normal from body 1 to body 2 (2-D/3-D), e.g. "1, 0".
    #[arg(long, allow_hyphen_values = true)]
    pub normal: Option<String>,
    /// Centre of sphere 1 (the normal follows from the two centres), e.g. "0 m, 0 m".
    #[arg(long, allow_hyphen_values = true)]
    pub r1: Option<String>,
    /// Centre of sphere 2.
    #[arg(long, allow_hyphen_values = true)]
    pub r2: Option<String>,
    /// Coulomb friction coefficient along the contact plane (oblique impacts).
    #[arg(long, allow_hyphen_values = true)]
    pub friction: Option<f64>,
    /// Gravitational acceleration, e.g. "9.81 m/s^2": also report how high each body rises
    /// afterwards when its speed turns into height (a pendulum bob, a ballistic pendulum),
    /// h = v²/(2g).
    #[arg(long, allow_hyphen_values = true)]
    pub g: Option<String>,
    /// `--json` and `-q/--quiet`.
    #[command(flatten)]
    pub report: crate::args::Report,
}

/// `mechkit com`.
#[derive(Debug, clap::Args)]
pub struct ComArgs {
    /// A body file (TOML: shapes, composites, holes) or an image (PNG or JPEG) of the body.
    pub file: Option<PathBuf>,
    /// Image: a pixel is part of the body when its brightness on the channel (0-1 per
    /// channel, so 0-3 for `sum`) is below this [default: 1.5 for sum, 0.5 for r, g, b].
    #[arg(long, allow_hyphen_values = true)]
    pub threshold: Option<f64>,
    /// Image: the brightness used: sum (R+G+B), r, g or b.
    #[arg(long, default_value = "sum")]
    pub channel: String,
    /// Image: the body is the bright pixels (above the threshold) instead of the dark ones.
    #[arg(long)]
    pub invert: bool,
    /// Image: weight each selected pixel by its darkness (lightness when inverted) instead of
    /// counting it as 1: a density that follows the shade.
    #[arg(long)]
    pub density_from_darkness: bool,
    /// Image: the side of one pixel, e.g. "0.5 mm" (physical coordinates and areas).
    #[arg(long, allow_hyphen_values = true)]
    pub pixel_size: Option<String>,
    /// Image: the scale from a known length, e.g. "240 px = 12 cm".
    #[arg(long, allow_hyphen_values = true)]
    pub scale: Option<String>,
    /// Image: the pixel position of the physical origin "x, y" (column, row, from the
    /// top-left corner) [default: the bottom-left corner]; physical y points up.
    #[arg(long, allow_hyphen_values = true)]
    pub origin: Option<String>,
    /// The body's total mass, e.g. "2 kg" (image: spread over the selected pixels; body file:
    /// rescales the parts' masses).
    #[arg(long = "total-mass", allow_hyphen_values = true)]
    pub total_mass: Option<String>,
    /// Also the moment of inertia about this point, "x, y[, z]" (image: physical
    /// coordinates, or pixels without a scale).
    #[arg(long, allow_hyphen_values = true)]
    pub about: Option<String>,
    /// Image: write a PNG with the selected pixels tinted and the centre of mass marked.
    #[arg(long)]
    pub mark: Option<PathBuf>,
    /// A point mass, e.g. "5.972e24 kg" with its --at, or inline "5.972e24 kg@0,0";
    /// repeat for each body.
    #[arg(long, action = clap::ArgAction::Append, allow_hyphen_values = true)]
    pub mass: Vec<String>,
    /// The body's position: one coordinate, or "x, y[, z]", e.g. "384400 km".
    #[arg(long, action = clap::ArgAction::Append, allow_hyphen_values = true)]
    pub at: Vec<String>,
    /// The body's velocity (optional, for all bodies or none).
    #[arg(long, action = clap::ArgAction::Append, allow_hyphen_values = true)]
    pub velocity: Vec<String>,
    /// Also express the centre of mass in this length, e.g. "6371 km" (Earth radii) or "pm".
    #[arg(long = "in")]
    pub unit: Option<String>,
    /// `--json` and `-q/--quiet`.
    #[command(flatten)]
    pub report: crate::args::Report,
}

/// `mechkit impulse`.
#[derive(Debug, clap::Args)]
pub struct ImpulseArgs {
    /// Data file with a time column and a force column.
    pub file: PathBuf,
    /// The time column (name or 1-based number) [default: the first].
    #[arg(long, allow_hyphen_values = true)]
    pub t: Option<String>,
    /// The force column [default: the second].
    #[arg(long, allow_hyphen_values = true)]
    pub f: Option<String>,
    /// Quadrature rule: trapezoid, simpson, left, right or midpoint.
    #[arg(long, default_value = "trapezoid")]
    pub method: String,
    /// The mass that receives the impulse: Δv = J/m.
    #[arg(long, allow_hyphen_values = true)]
    pub mass: Option<String>,
    /// Its velocity before (default 0).
    #[arg(long, allow_hyphen_values = true)]
    pub v0: Option<String>,
    /// Output directory: impulse.csv (t, F and the running impulse J) with its units sidecar,
    /// and the plot J_t.svg (J_t.png with --format png). Nothing is written without it.
    #[arg(long, short)]
    pub out: Option<PathBuf>,
    /// Do not draw the plot.
    #[arg(long)]
    pub no_plots: bool,
    /// Plot files: `--format svg|png`, `--dpi` and `--style`.
    #[command(flatten)]
    pub plots: crate::args::PlotFormat,
    /// `--json` and `-q/--quiet`.
    #[command(flatten)]
    pub report: crate::args::Report,
}

/// `mechkit derive`.
#[derive(Debug, clap::Args)]
pub struct DeriveArgs {
    /// Data file: a time column and position columns (whitespace or comma separated; # and %
    /// start comments; an optional header line names the columns).
    pub file: PathBuf,
    /// The time column (name or 1-based number) [default: the first].
    #[arg(long, allow_hyphen_values = true)]
    pub t: Option<String>,
    /// The position columns, comma-separated [default: every other column].
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
    pub x: Option<Vec<String>>,
    /// Finite differences: central (second order), forward (the course's loop) or backward.
    #[arg(long, default_value = "central")]
    pub method: String,
    /// Savitzky-Golay smoothing for noisy data: WINDOW[:ORDER] samples, e.g. 21:2 (uniform
    /// time steps only).
    #[arg(long, allow_hyphen_values = true)]
    pub smooth: Option<String>,
    /// Output directory: derived.csv with its units sidecar, and the plots x_t, v_t and a_t.
    /// Nothing is written without it.
    #[arg(long, short)]
    pub out: Option<PathBuf>,
    /// Do not draw plots.
    #[arg(long)]
    pub no_plots: bool,
    /// Plot files: `--format svg|png`, `--dpi` and `--style`.
    #[command(flatten)]
    pub plots: crate::args::PlotFormat,
    /// `--json` and `-q/--quiet`.
    #[command(flatten)]
    pub report: crate::args::Report,
}

/// `mechkit work`.
#[derive(Debug, clap::Args)]
pub struct WorkArgs {
    /// Data file: columns of x and F (whitespace or comma separated; # and % start comments).
    pub file: Option<PathBuf>,
    /// The column of x (name or 1-based number) [default: the first].
    #[arg(long, allow_hyphen_values = true)]
    pub x: Option<String>,
    /// The column of F (name or 1-based number) [default: the second].
    #[arg(long, allow_hyphen_values = true)]
    pub f: Option<String>,
    /// Quadrature rule: trapezoid, simpson, left, right or midpoint.
    #[arg(long, default_value = "trapezoid")]
    pub method: String,
    /// What x is: position (∫F dx is a work, in J) or time (∫F dt is an impulse, in N·s)
    /// [default: time when the x column is named t or time, else position].
    #[arg(long, value_parser = ["position", "time"])]
    pub of: Option<String>,
    /// A mass: with position data, the speed v(x) from ½mv² = ½mv0² + W(x); with time data,
    /// the change of velocity J/m.
    #[arg(long, allow_hyphen_values = true)]
    pub mass: Option<String>,
    /// Start speed for v(x) (default 0).
    #[arg(long, allow_hyphen_values = true)]
    pub v0: Option<String>,
    /// Output directory: work.csv (x, F, the running work W, and v with --mass; impulse.csv
    /// for time data) with its units sidecar, and the plot W_x.svg (W_x.png with --format
    /// png). Nothing is written without it.
    #[arg(long, short)]
    pub out: Option<PathBuf>,
    /// Do not draw the plot.
    #[arg(long)]
    pub no_plots: bool,
    /// Plot files: `--format svg|png`, `--dpi` and `--style`.
    #[command(flatten)]
    pub plots: crate::args::PlotFormat,
    /// A force field instead of data: components separated by commas, functions of x, y (, z),
    /// e.g. "-k*x, -k*y".
    #[arg(long, allow_hyphen_values = true)]
    pub field: Option<String>,
    /// The curve r(s) for --field, components separated by commas, e.g. "cos(s), sin(s)".
    #[arg(long, allow_hyphen_values = true, requires = "field")]
    pub path: Option<String>,
    /// The parameter of --path and its range, e.g. "s=0:2*pi".
    #[arg(long, allow_hyphen_values = true, requires = "path")]
    pub param: Option<String>,
    /// Straight segments through points for --field, e.g. "0,0; 1,0; 1,1".
    #[arg(long, allow_hyphen_values = true, requires = "field")]
    pub through: Option<String>,
    /// Values of the other names in --field and --path, e.g. "k=2,m=1 kg".
    #[arg(long, allow_hyphen_values = true)]
    pub set: Option<String>,
    /// `--json` and `-q/--quiet`.
    #[command(flatten)]
    pub report: crate::args::Report,
}

/// `mechkit power`.
#[derive(Debug, clap::Args)]
pub struct PowerArgs {
    /// The engine's power, e.g. "20 kW".
    #[arg(long, allow_hyphen_values = true)]
    pub power: Option<String>,
    /// The mass driven, e.g. "200 kg".
    #[arg(long, allow_hyphen_values = true)]
    pub mass: Option<String>,
    /// Start speed (default 0: from rest).
    #[arg(long, allow_hyphen_values = true)]
    pub v0: Option<String>,
    /// Times to report v, a and x at, comma-separated, e.g. "5 s,10 s".
    #[arg(long, allow_hyphen_values = true)]
    pub at: Option<String>,
    /// Also report when this speed is reached.
    #[arg(long, allow_hyphen_values = true)]
    pub until_speed: Option<String>,
    /// Average power instead: the work done ...
    #[arg(long, requires = "time", allow_hyphen_values = true)]
    pub work: Option<String>,
    /// ... over this time.
    #[arg(long, requires = "work", allow_hyphen_values = true)]
    pub time: Option<String>,
    /// Output directory: power.csv (t, v, a, x, W up to the last time asked) with its units
    /// sidecar, and the plots v_t and x_t. Nothing is written without it.
    #[arg(long, short)]
    pub out: Option<PathBuf>,
    /// Do not draw plots.
    #[arg(long)]
    pub no_plots: bool,
    /// Plot files: `--format svg|png`, `--dpi` and `--style`.
    #[command(flatten)]
    pub plots: crate::args::PlotFormat,
    /// `--json` and `-q/--quiet`.
    #[command(flatten)]
    pub report: crate::args::Report,
}

/// `mechkit rocket`.
#[derive(Debug, clap::Args)]
pub struct RocketArgs {
    /// Mass at ignition, e.g. "1000 kg".
    #[arg(long, allow_hyphen_values = true)]
    pub m0: String,
    /// Mass at burnout (the rocket without its propellant), e.g. "400 kg".
    #[arg(long, allow_hyphen_values = true)]
    pub m1: String,
    /// Mass ejected per second, e.g. "10 kg/s".
    #[arg(long, allow_hyphen_values = true)]
    pub mass_rate: String,
    /// Exhaust speed relative to the rocket, e.g. "2 km/s".
    #[arg(long, allow_hyphen_values = true)]
    pub exhaust_speed: String,
    /// Uniform gravity against the thrust, e.g. "9.81 m/s^2" [default: 0, free space].
    #[arg(long, allow_hyphen_values = true)]
    pub g: Option<String>,
    /// Quadratic drag coefficient D in F = -D v|v|, e.g. "0.02 kg/m" (simulation only).
    #[arg(long, allow_hyphen_values = true)]
    pub drag: Option<String>,
    /// Also follow the coast after burnout up to the apex (needs --g).
    #[arg(long)]
    pub coast: bool,
    /// Relative tolerance of the simulation (Dormand-Prince 5(4)); atol is 1000 times smaller.
    #[arg(long, default_value_t = 1e-10, allow_hyphen_values = true)]
    pub rtol: f64,
    /// Directory for rocket.csv (t, x, v, m; with its units, rocket.units.json) and the plots
    /// v_t, x_t and m_t (nothing is written without it).
    #[arg(long, short)]
    pub out: Option<PathBuf>,
    /// Do not draw plots (with --out, only the CSV).
    #[arg(long)]
    pub no_plots: bool,
    /// Plot files: `--format svg|png` and `--dpi`.
    #[command(flatten)]
    pub plots: crate::args::PlotFormat,
    /// `--json` and `-q/--quiet`.
    #[command(flatten)]
    pub report: crate::args::Report,
}

/// `mechkit potential`.
#[derive(Debug, clap::Args)]
pub struct PotentialArgs {
    /// The potential U(x), e.g. "U0*((a/r)^12-(b/r)^6)" (or give --force instead).
    #[arg(allow_hyphen_values = true)]
    pub potential: Option<String>,
    /// Start from the force F(x) instead: U = -∫F dx (symbolic when possible).
    #[arg(long, allow_hyphen_values = true)]
    pub force: Option<String>,
    /// The variable; "x,y" or "x,y,z" for a potential in 2-D or 3-D (then only the force
    /// F = -∇U is reported, and its values at --at points).
    #[arg(long, default_value = "x")]
    pub var: String,
    /// The range A:B to analyse and plot, increasing, e.g. -1:2 (with units, e.g. "3 Å:10 Å",
    /// the axis is labelled in metres).
    #[arg(long, allow_hyphen_values = true)]
    pub range: Option<String>,
    /// Values of the other names, e.g. "U0=1 eV,a=3.4 Å" (with units, the diagram's axes show
    /// them where the formula's unit follows).
    #[arg(long, allow_hyphen_values = true)]
    pub set: Option<String>,
    /// A total energy: turning points and allowed/forbidden regions.
    #[arg(long, allow_hyphen_values = true)]
    pub energy: Option<String>,
    /// Mass of a body released at --x0 with --v0: its energy, turning points and v(x).
    #[arg(long, allow_hyphen_values = true)]
    pub mass: Option<String>,
    /// Start position of the body.
    #[arg(long, allow_hyphen_values = true)]
    pub x0: Option<String>,
    /// Start velocity of the body (default 0; its sign is the direction).
    #[arg(long, allow_hyphen_values = true)]
    pub v0: Option<String>,
    /// Also report U, F (and v) at these points, comma-separated (in 2-D/3-D: points separated
    /// by `;`, coordinates by `,`).
    #[arg(long, allow_hyphen_values = true)]
    pub at: Option<String>,
    /// Grid intervals used to find equilibria and turning points.
    #[arg(value_parser = super::whole_count, long, default_value_t = 2000, allow_hyphen_values = true)]
    pub samples: usize,
    /// Output directory: the energy diagram U_x.svg (x the variable; U_x.png with --format
    /// png), v_x.svg with a released body, and potential.csv (x, U, F and v on the grid) with
    /// its units sidecar. Nothing is written without it.
    #[arg(long, short)]
    pub out: Option<PathBuf>,
    /// Do not draw plots.
    #[arg(long)]
    pub no_plots: bool,
    /// Plot files: `--format svg|png`, `--dpi` and `--style`.
    #[command(flatten)]
    pub plots: crate::args::PlotFormat,
    /// `--json` and `-q/--quiet`.
    #[command(flatten)]
    pub report: crate::args::Report,
}

/// `mechkit inertia`.
#[derive(Debug, clap::Args)]
pub struct InertiaArgs {
    /// A body file (TOML): parts with shape, dimensions, density or mass, position,
    /// orientation, `hole = true`.
    pub file: PathBuf,
    /// The point for the inertia tensor, "x, y, z" with units [default: the origin].
    #[arg(long, allow_hyphen_values = true)]
    pub about: Option<String>,
    /// The direction of an axis through the --about point, "ax, ay, az": the moment about it.
    #[arg(long, allow_hyphen_values = true)]
    pub axis: Option<String>,
    /// Rescale the parts so the body has this total mass, e.g. "2 kg".
    #[arg(long = "total-mass", allow_hyphen_values = true)]
    pub total_mass: Option<String>,
    /// Express moments of inertia in this unit, e.g. "g*cm^2" or "u*pm^2".
    #[arg(long = "in")]
    pub unit: Option<String>,
    /// `--json` and `-q/--quiet`.
    #[command(flatten)]
    pub report: crate::args::Report,
}

//! `mechkit rigid-collide`: a hinged body struck by a block, or a free body landing on the
//! ground.

use std::path::PathBuf;

/// `mechkit rigid-collide`.
#[derive(Debug, clap::Args)]
pub struct RigidCollideArgs {
    /// The hinged body is a uniform rod (with --mass, --length, --pivot-at).
    #[arg(long, conflicts_with_all = ["inertia", "body"])]
    pub rod: bool,
    /// The hinged body's moment of inertia about the pivot, e.g. "0.333 kg m^2" (with --mass
    /// and --cm-distance).
    #[arg(long, allow_hyphen_values = true, conflicts_with = "body")]
    pub inertia: Option<String>,
    /// A body file (TOML, as for `mechkit inertia`) turning about the axis z through --pivot.
    #[arg(long)]
    pub body: Option<PathBuf>,
    /// The pivot of a body file, "x, y, z" with units, e.g. "0, 0.5 m, 0".
    #[arg(long, allow_hyphen_values = true, requires = "body")]
    pub pivot: Option<String>,
    /// Mass of the rod or of the body given by --inertia.
    #[arg(long, allow_hyphen_values = true)]
    pub mass: Option<String>,
    /// Length of the rod.
    #[arg(long, allow_hyphen_values = true, requires = "rod")]
    pub length: Option<String>,
    /// Where the rod is hinged: "end", "centre", or a distance from its top end, e.g. "0.25 m".
    #[arg(
        long,
        allow_hyphen_values = true,
        default_value = "end",
        requires = "rod"
    )]
    pub pivot_at: String,
    /// With --inertia: the distance of the centre of mass below the pivot.
    #[arg(long, allow_hyphen_values = true, requires = "inertia")]
    pub cm_distance: Option<String>,
    /// The body's angular velocity just before the impact (counter-clockwise positive; at the
    /// bottom of the swing a positive ω moves the lowest point in +x).
    #[arg(long, allow_hyphen_values = true, conflicts_with = "release_angle")]
    pub omega: Option<String>,
    /// Release the body from rest at this angle from the vertical, e.g. "90 deg": ω₀ =
    /// sqrt(2 M g d (1 − cos θ₀)/I_O) at the bottom, where it strikes.
    #[arg(long, allow_hyphen_values = true)]
    pub release_angle: Option<String>,
    /// Gravitational acceleration for --release-angle.
    #[arg(long, allow_hyphen_values = true, default_value = "9.81 m/s^2")]
    pub g: String,
    /// Where the block is struck: the distance below the pivot [default: the rod's lower end],
    /// or "x, y" relative to the pivot (y up).
    #[arg(long, allow_hyphen_values = true)]
    pub hit_at: Option<String>,
    /// Mass of the block (a free particle at the contact point).
    #[arg(long, allow_hyphen_values = true, required_unless_present = "landing")]
    pub block_mass: Option<String>,
    /// Instead of a hinged body: a free rod (--rod --mass --length) landing on its lower end
    /// on the ground, tilted by --tilt above the horizontal, its centre of mass moving at
    /// --velocity and turning at --omega.
    #[arg(long, requires = "rod", conflicts_with_all = ["block_mass", "release_angle", "hit_at"])]
    pub landing: bool,
    /// With --landing: the rod's angle above the horizontal at the touch-down (0 to 90 deg).
    #[arg(long, allow_hyphen_values = true, requires = "landing")]
    pub tilt: Option<String>,
    /// With --landing: the velocity of the rod's centre of mass before it lands, "vx, vy".
    #[arg(long, allow_hyphen_values = true, requires = "landing")]
    pub velocity: Option<String>,
    /// Velocity of the block before the impact [default: 0], "vx" or "vx, vy".
    #[arg(long, allow_hyphen_values = true, default_value = "0")]
    pub block_velocity: String,
    /// Contact normal from the body into the block [default: "1, 0", horizontal].
    #[arg(long, allow_hyphen_values = true, default_value = "1, 0")]
    pub normal: String,
    /// Coefficient of restitution from 0 to 1, or elastic (1) or perfectly-inelastic (0).
    #[arg(long, short = 'e', allow_hyphen_values = true)]
    pub restitution: String,
    /// `--json` and `-q/--quiet`.
    #[command(flatten)]
    pub report: crate::args::Report,
}

//! `mechkit rotation`: angular kinematics and circular motion.

/// `mechkit rotation`. One question per call, chosen by the flags given:
/// a formula (`--theta` or `--omega` with `--at`), uniform angular acceleration (`--omega0`,
/// `--omega1`, `--time`), circular motion (`--radius` with `--speed`, `--angular-speed`,
/// `--period` or `--centripetal`, or `--speed` with `--centripetal`), or a point of a body
/// turning in 3-D (`--omega-vector`, `--point`).
#[derive(Debug, clap::Args)]
pub struct RotationArgs {
    /// θ(t) as a formula of t, e.g. "c1*t/t1 + c2*(t/t2)^2": ω and α by symbolic derivatives.
    #[arg(long, allow_hyphen_values = true, conflicts_with = "omega")]
    pub theta: Option<String>,
    /// ω(t) as a formula of t, e.g. "w0*cos(t/T)": θ by symbolic integration (from --theta0),
    /// α by the derivative.
    #[arg(long, allow_hyphen_values = true)]
    pub omega: Option<String>,
    /// θ at t = 0 with --omega [default: 0], e.g. "90 deg".
    #[arg(long, allow_hyphen_values = true, requires = "omega")]
    pub theta0: Option<String>,
    /// Values of the formula's other names, e.g. "c1=1,t1=1 s".
    #[arg(long, allow_hyphen_values = true)]
    pub set: Option<String>,
    /// Times to evaluate θ, ω, α at, comma-separated, e.g. "1 s" or "0, pi".
    #[arg(long, allow_hyphen_values = true)]
    pub at: Option<String>,
    /// Initial angular velocity for uniform angular acceleration, e.g. "1000 rpm".
    #[arg(long, allow_hyphen_values = true, requires_all = ["omega1", "time"])]
    pub omega0: Option<String>,
    /// Final angular velocity, e.g. "2000 rpm".
    #[arg(long, allow_hyphen_values = true, requires = "omega0")]
    pub omega1: Option<String>,
    /// Duration of the uniform angular acceleration, e.g. "15 s".
    #[arg(long, allow_hyphen_values = true, requires = "omega0")]
    pub time: Option<String>,
    /// Radius of the circle (circular motion), e.g. "50 m".
    #[arg(long, allow_hyphen_values = true)]
    pub radius: Option<String>,
    /// Speed on the circle, e.g. "10 m/s" (with --radius, or with --centripetal): ω = v/R, also
    /// the rolling condition of a wheel of radius R.
    #[arg(long, allow_hyphen_values = true, conflicts_with_all = ["angular_speed", "period"])]
    pub speed: Option<String>,
    /// The centripetal acceleration, e.g. "9.81 m/s^2" or "0.1 gn" (standard gravity): with
    /// --radius, ω = √(a/R) (in rad/s and rpm), the period and v; with --speed instead of
    /// --radius, the acceleration allowed: the smallest circle is R = v²/a.
    #[arg(long, allow_hyphen_values = true, conflicts_with_all = ["angular_speed", "period"])]
    pub centripetal: Option<String>,
    /// An angle turned on the circle, e.g. "90 deg": the time it takes (θ/ω) and the arc (θR).
    #[arg(long, allow_hyphen_values = true)]
    pub turn: Option<String>,
    /// Angular velocity of the circular motion, e.g. "0.2 rad/s" or "33 rpm".
    #[arg(long, allow_hyphen_values = true, conflicts_with = "period")]
    pub angular_speed: Option<String>,
    /// Period of one turn, e.g. "86400 s" or "365.25 d" (the radius is optional: without it
    /// only ω is computed).
    #[arg(long, allow_hyphen_values = true)]
    pub period: Option<String>,
    /// Angular acceleration for the tangential acceleration a_t = αR, e.g. "2 rad/s^2".
    #[arg(long, allow_hyphen_values = true)]
    pub alpha: Option<String>,
    /// Latitude on a sphere of radius --radius turning about its axis, e.g. "60 deg": the
    /// circle there has radius R cos λ.
    #[arg(long, allow_hyphen_values = true, requires = "radius")]
    pub latitude: Option<String>,
    /// The angular-velocity vector "wx, wy, wz" (rad/s) of a body turning about the origin.
    #[arg(long, allow_hyphen_values = true, requires = "point")]
    pub omega_vector: Option<String>,
    /// The angular-acceleration vector "ax, ay, az" (rad/s²) [default: 0].
    #[arg(long, allow_hyphen_values = true, requires = "omega_vector")]
    pub alpha_vector: Option<String>,
    /// The point "x, y, z" of the body (m): v = ω × r, a = α × r + ω × (ω × r).
    #[arg(long, allow_hyphen_values = true, requires = "omega_vector")]
    pub point: Option<String>,
    /// `--json` and `-q/--quiet`.
    #[command(flatten)]
    pub report: crate::args::Report,
}

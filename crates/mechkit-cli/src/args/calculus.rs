//! `mechkit diff`, `integrate`, `solve`, `dsolve` and `units`: formulas and quantities.

use super::whole_count;

/// `mechkit diff`.
#[derive(Debug, clap::Args)]
pub struct DiffArgs {
    /// The formula, e.g. "-F0*sin(2*pi*x/b)".
    #[arg(allow_hyphen_values = true)]
    pub expr: String,
    /// The variable to differentiate with respect to.
    #[arg(long, default_value = "x")]
    pub var: String,
    /// Also evaluate the derivative at this point, symbolically and by central differences
    /// with Richardson extrapolation, and check that they agree.
    #[arg(long, allow_hyphen_values = true)]
    pub at: Option<String>,
    /// Initial step of the numerical derivative (default 0.1).
    #[arg(long, requires = "at", allow_hyphen_values = true)]
    pub step: Option<String>,
    /// Values of the other names, e.g. "F0=1,b=2" (needed with --at).
    #[arg(long, allow_hyphen_values = true)]
    pub set: Option<String>,
    /// `--json` and `-q/--quiet`.
    #[command(flatten)]
    pub report: crate::args::Report,
}

/// `mechkit integrate`.
#[derive(Debug, clap::Args)]
pub struct IntegrateArgs {
    /// The integrand, e.g. "1/(a+x^2)".
    #[arg(allow_hyphen_values = true)]
    pub expr: String,
    /// The variable of integration.
    #[arg(long, default_value = "x")]
    pub var: String,
    /// Lower limit (a number, or a quantity with units).
    #[arg(long, allow_hyphen_values = true)]
    pub from: Option<String>,
    /// Upper limit.
    #[arg(long, allow_hyphen_values = true)]
    pub to: Option<String>,
    /// Values of the other names, e.g. "a=1,b=2 m".
    #[arg(long, allow_hyphen_values = true)]
    pub set: Option<String>,
    /// Also estimate the definite integral with fixed rules, comma-separated: left, right,
    /// midpoint, trapezoid, simpson, gauss-legendre-N, or all; each is compared with the exact
    /// value.
    #[arg(long, value_delimiter = ',', requires = "from")]
    pub method: Option<Vec<String>>,
    /// Numbers of intervals for --method, comma-separated.
    #[arg(value_parser = whole_count, long, value_delimiter = ',', default_value = "10", requires = "method", allow_hyphen_values = true)]
    pub n: Vec<usize>,
    /// `--json` and `-q/--quiet`.
    #[command(flatten)]
    pub report: crate::args::Report,
}

/// `mechkit solve`.
#[derive(Debug, clap::Args)]
pub struct SolveArgs {
    /// The equation "LHS = RHS" (or an expression equal to zero); several linear equations
    /// separated by `;`.
    #[arg(allow_hyphen_values = true)]
    pub equation: String,
    /// The unknown(s), comma-separated for a linear system.
    #[arg(long = "for", default_value = "x")]
    pub unknown: String,
    /// Search interval for a numerical solution, "A:B".
    #[arg(long = "in", allow_hyphen_values = true)]
    pub interval: Option<String>,
    /// Values of the other names (numbers, quantities or formulas), e.g. "m=2,g=9.81" or
    /// "th=pi/6"; with a linear system, its solution is also evaluated with them.
    #[arg(long, allow_hyphen_values = true)]
    pub set: Option<String>,
    /// `--json` and `-q/--quiet`.
    #[command(flatten)]
    pub report: crate::args::Report,
}

/// `mechkit dsolve`.
#[derive(Debug, clap::Args)]
pub struct DsolveArgs {
    /// The differential equation with primes for the derivatives, e.g.
    /// "m*x'' + c*x' + k*x = F0*cos(w*t)".
    #[arg(allow_hyphen_values = true)]
    pub equation: String,
    /// The unknown function.
    #[arg(long, default_value = "x")]
    pub func: String,
    /// The independent variable.
    #[arg(long, default_value = "t")]
    pub var: String,
    /// Initial conditions, e.g. "x(0)=1, x'(0)=0" (the constants C1, C2 stay free without).
    #[arg(long, allow_hyphen_values = true)]
    pub ic: Option<String>,
    /// Values of the other names, e.g. "m=1,c=0.2,k=4": substituted before solving (they
    /// decide the damping case).
    #[arg(long, allow_hyphen_values = true)]
    pub set: Option<String>,
    /// `--json` and `-q/--quiet`.
    #[command(flatten)]
    pub report: crate::args::Report,
}

/// `mechkit units`.
#[derive(Debug, clap::Args)]
pub struct UnitsArgs {
    /// The quantity, e.g. "60 km/h".
    #[arg(allow_hyphen_values = true)]
    pub quantity: String,
    /// The unit to convert to, e.g. "m/s".
    #[arg(long)]
    pub to: Option<String>,
    /// `--json` and `-q/--quiet`.
    #[command(flatten)]
    pub report: crate::args::Report,
}

//! The program and its subcommands ([`Cli`], [`Command`]), with the examples and exit codes
//! that `mechkit --help` shows.

use clap::{Parser, Subcommand};

use super::{
    AnimateArgs, BeadArgs, CheckArgs, CollideArgs, ComArgs, CompletionsArgs, DeriveArgs, DiffArgs,
    DsolveArgs, FrictionArgs, GalleryArgs, ImpulseArgs, InertiaArgs, IntegrateArgs, ListArgs,
    ManArgs, MdArgs, PotentialArgs, PowerArgs, RelativeArgs, RigidCollideArgs, RocketArgs,
    RollArgs, RotationArgs, RunArgs, ServeArgs, SolveArgs, SpinArgs, SweepArgs, SweepMergeArgs,
    TerminalArgs, UnitsArgs, WorkArgs,
};

const EXAMPLES: &str = r#"Examples:
  mechkit run examples/feather.toml --out out/feather
      simulate, write out/feather/trajectory.csv, summary.json and SVG plots
  mechkit run examples/kepler.toml --json
      print the summary as JSON
  mechkit check examples/projectile_drag.toml
      validate a scenario without running it
  mechkit list-integrators
  mechkit diff "-F0*sin(2*pi*x/b)" --var x --at 0.1 --set F0=1,b=1
  mechkit integrate "1/(a+x^2)" --var x --from 0 --to 1 --set a=1
  mechkit integrate "-F0*sin(2*pi*x/b)" --from 0 --to 1/4 --set F0=1,b=1 --method left --n 10,100
  mechkit solve "x^2 - 5*x + 6 = 0" --for x
  mechkit solve "cos(x) = x" --for x --in 0:1
  mechkit dsolve "m*x'' + c*x' + k*x = 0" --ic "x(0)=1, x'(0)=0" --set m=1,c=0.4,k=4
  mechkit units "60 km/h" --to m/s
  mechkit potential "U0*((a/r)^12-(b/r)^6)" --var r --range 0.8:3 --set U0=1,a=1,b=1 --energy=-0.1
  mechkit derive examples/data/fallingtennisball02.txt --smooth 21:2
  mechkit work examples/data/forcedata.d -o out/work
  mechkit work --field "y, -x" --path "cos(s), sin(s)" --param s=0:2*pi
  mechkit collide --m1 "0.2 kg" --v1 "15 m/s" --m2 "1.5 kg" --v2 0 --restitution 0
  mechkit impulse examples/data/baseballforce.d --mass "0.145 kg"
  mechkit com --mass "12.011 u" --at "0 pm" --mass "15.999 u" --at "112.8 pm" --in pm
  mechkit power --power "20 kW" --mass "200 kg" --at "5 s"
  mechkit rocket --m0 "1 t" --m1 "400 kg" --mass-rate 10 --exhaust-speed "2 km/s" --g 9.81 --coast
  mechkit potential --force "-F0*sin(2*pi*x/b)" --range=-1:2 --set F0=1,b=1 --mass 1 --x0 0 --v0 1
  mechkit friction --mass 1 --mu-s 0.6 --mu-d 0.4 --spring-k 100 --anchor-speed 0.05 --t-max 8
  mechkit roll --body hoop --radius 1 --mass 1 --slope 0.3 --mu 0.3 --v0 2 --omega0 -3 --t-max 3
  mechkit spin --moments "1, 2, 3" --omega "0.01, 1, 0.01" --t-max 100
  mechkit rotation --omega0 "1000 rpm" --omega1 "2000 rpm" --time "15 s"
  mechkit bead --circle "1 m" --side outside --start 0 --speed "0.1 m/s" --t-max "3 s"
  mechkit sweep examples/sweep/throw.toml --set "v0=0:5:51" --plot "v(x)"
  mechkit md --lattice fcc --cells 20 --density 0.8442 --temperature 1.44 --steps 100 --threads 2
  mechkit rigid-collide --rod --mass 1 --length 1 --release-angle "90 deg" --block-mass 0.3333 -e 1

Exit codes: 0 success, 1 the computation failed (e.g. diverged), 2 bad input.
Scenario format: docs/scenario.md. Commands: docs/cli.md."#;

/// Computational classical mechanics: simulate scenario files with units and formulas, and
/// report trajectories, plots and the energy ledger.
#[derive(Debug, Parser)]
#[command(
    name = "mechkit",
    version,
    about = "Computational classical mechanics: simulate scenario files with units and formulas, and report trajectories, plots and the energy ledger.",
    after_help = EXAMPLES
)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// Subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Simulate a scenario: trajectory.csv, summary.json and plots in the output directory.
    Run(RunArgs),
    /// Check a scenario file without running it.
    Check(CheckArgs),
    /// Animate a run (a scenario file, or the output directory of `run`): a GIF, an MP4 (with
    /// ffmpeg) or one self-contained HTML player, the bodies drawn to scale in their shapes.
    Animate(AnimateArgs),
    /// The browser app on 127.0.0.1: browse the workspace's scenarios and the gallery, edit one
    /// with its errors shown as you type, run it, see its plots and animation, download its
    /// outputs.
    Serve(ServeArgs),
    /// List the integration methods.
    ListIntegrators(ListArgs),
    /// Differentiate a formula symbolically.
    Diff(DiffArgs),
    /// Integrate a formula: antiderivative, and the definite value by closed form and by
    /// quadrature.
    Integrate(IntegrateArgs),
    /// Solve an equation, or a `;`-separated linear system.
    Solve(SolveArgs),
    /// Solve a differential equation in closed form (verified by substitution).
    Dsolve(DsolveArgs),
    /// Convert a quantity to SI or to another unit, and show its dimension.
    Units(UnitsArgs),
    /// A potential U(x) (or a force F(x)): the force, equilibria and their stability, turning
    /// points for an energy, the speed by the work-energy theorem, and the energy diagram.
    Potential(PotentialArgs),
    /// Motion at constant power (v, a, x at given times), or an average power W/t.
    Power(PowerArgs),
    /// A rocket (variable mass): Δv by the rocket equation, burn time, burnout speed and height
    /// and the apex of the coast, in closed form and simulated (with optional quadratic drag),
    /// and plots of v(t), x(t) and m(t).
    Rocket(RocketArgs),
    /// Velocity and acceleration from a position-time data file (CSV and plots).
    Derive(DeriveArgs),
    /// A free rigid body in 3-D (quaternion and angular momentum; the tennis-racket flip
    /// against the elliptic-function period), or a heavy top on a pivot (nutation,
    /// precession, steady precession).
    Spin(SpinArgs),
    /// Many particles with a Lennard-Jones pair potential from a lattice (reduced units):
    /// neighbour lists, periodic box, velocity Verlet, thermo, g(r), extended XYZ.
    Md(MdArgs),
    /// Two bodies colliding with a coefficient of restitution (1-D, 2-D or 3-D): velocities
    /// after, impulse, kinetic energy lost, centre-of-mass frame.
    Collide(CollideArgs),
    /// The impulse ∫F dt of a force-time data file, the average force and Δv = J/m.
    Impulse(ImpulseArgs),
    /// The centre of mass of point masses (with velocities: momentum, centre-of-mass frame,
    /// kinetic energy split), of a body file (shapes, composites with holes), or of the body
    /// in a photo (PNG or JPEG: pixels selected by brightness).
    Com(ComArgs),
    /// Mass, centre of mass and inertia tensor of a body file: about the centre of mass and
    /// about a point, principal moments and axes, the moment about an axis.
    Inertia(InertiaArgs),
    /// Angular kinematics: ω and α from θ(t) (or θ and α from ω(t)) symbolically, uniform
    /// angular acceleration, circular motion (v = ωR, a_c = ω²R, a_t = αR, latitude), and
    /// v = ω × r, a = α × r + ω × (ω × r) for a point in 3-D.
    Rotation(RotationArgs),
    /// Relative velocity: the heading that keeps a plane or a boat on its track through a wind
    /// or a current, and its ground speed; a velocity seen from another frame (Galilean
    /// transformation, v' = v − u).
    Relative(RelativeArgs),
    /// Drag from a measured terminal velocity: D/(m g) = 1/v_T², D/m, D with the mass, C_d with
    /// the density and the area; v_T from a value, a distance in a time, or a line through
    /// position samples.
    Terminal(TerminalArgs),
    /// A body on a circle or a curve y(x) under gravity: the normal force along the way, where
    /// it leaves the curve (N = 0) and where it lands again; path.csv and path.svg.
    Bead(BeadArgs),
    /// A rigid-body impact: a hinged body (a rod, a body file, or a moment of inertia) struck
    /// by a block, with restitution: ω and velocities after, impulse and hinge impulse, energy
    /// lost, angular momentum about the pivot.
    RigidCollide(RigidCollideArgs),
    /// The work ∫F dx from a data file (x, F columns; cumulative W(x)), or of a force field
    /// along a path (--field with --path or --through).
    Work(WorkArgs),
    /// Coulomb friction on a flat or inclined surface: normal force, static and dynamic
    /// friction, marginal angle, whether a block slides; with --spring-k, the stick-slip
    /// spring-block model (a belt or a slowly pulled anchor) with CSV and plots.
    Friction(FrictionArgs),
    /// A sphere, cylinder or hoop on a slope with friction: when slipping turns into rolling
    /// (simulated and closed form), the regimes, the energy ledger, CSV and plots.
    Roll(RollArgs),
    /// Run a scenario over a grid (or a seeded random sample) of its constants in parallel:
    /// one summary row per run (sweep.csv) and the runs' plots in one figure; --shard K/N
    /// runs one slice of a sweep spread over machines.
    Sweep(SweepArgs),
    /// Join the sweep.partK.csv files of a sharded sweep into sweep.csv, checking that they
    /// are parts of one sweep and hold every run once.
    SweepMerge(SweepMergeArgs),
    /// The course's worked problems, bundled: list them, run one (its answers against the
    /// book's, its outputs and plots), or run all into the validation report.
    Gallery(GalleryArgs),
    /// Print a shell completion script: `mechkit completions bash > ~/.local/share/bash-completion/completions/mechkit`
    /// (zsh: into a directory of `$fpath` as `_mechkit`; fish: `~/.config/fish/completions/mechkit.fish`).
    Completions(CompletionsArgs),
    /// Print the manual page (roff): `mechkit man | man -l -`; with -o DIR, write `mechkit.1`
    /// and one page per command (`mechkit-run.1`, …) into DIR.
    Man(ManArgs),
}

#[cfg(test)]
mod negative_values {
    use clap::error::ErrorKind;
    use clap::{CommandFactory, Parser};

    /// Every option and positional that takes a value, as `(subcommand path, arg id, long)`.
    fn value_args() -> Vec<(Vec<String>, String, Option<String>)> {
        fn walk(
            cmd: &clap::Command,
            path: &[String],
            out: &mut Vec<(Vec<String>, String, Option<String>)>,
        ) {
            for a in cmd.get_arguments() {
                let takes = a.get_num_args().is_some_and(|n| n.takes_values())
                    || a.get_action().takes_values();
                if takes && a.get_id() != "help" && a.get_id() != "version" {
                    out.push((
                        path.to_vec(),
                        a.get_id().to_string(),
                        a.get_long().map(str::to_string),
                    ));
                }
            }
            for sub in cmd.get_subcommands() {
                let mut p = path.to_vec();
                p.push(sub.get_name().to_string());
                walk(sub, &p, out);
            }
        }
        let mut out = Vec::new();
        walk(&super::Cli::command(), &[], &mut out);
        out
    }

    /// Options and positionals whose values are paths or names, never numbers.
    const NOT_NUMBERS: &[&str] = &[
        "file",
        "out",
        "shell",
        "plot",
        "kind",
        "mark",
        "parts",
        "positions",
        "velocities",
        "body",
        "unit",
        "method",
        "compare_methods",
        "channel",
        "lattice",
        "boundary",
        "potential",
        "side",
        "frame",
        "of",
        "data",
        "law",
        "case",
        "report",
        "root",
        "input",
        "format",
        "dir",
        "host",
        "neigh_check",
        "export_lammps",
    ];

    /// Issue 11: a negative number (or a list or range starting with one) given to any
    /// numeric option must reach mechkit's own validation, never clap's "unexpected argument
    /// '-1'" (`mechkit md --density -1` used to work only as `--density=-1`).
    #[test]
    fn issue_011_negative_numbers_are_values() {
        let mut bad = Vec::new();
        for (path, id, long) in value_args() {
            if NOT_NUMBERS.contains(&id.as_str()) {
                continue;
            }
            for value in ["-1", "-1,2", "-2 m/s", "-1:2"] {
                let mut argv = vec!["mechkit".to_string()];
                argv.extend(path.iter().cloned());
                if let Some(l) = &long {
                    argv.push(format!("--{l}"));
                }
                argv.push(value.to_string());
                if let Err(e) = super::Cli::try_parse_from(&argv)
                    && e.kind() == ErrorKind::UnknownArgument
                {
                    bad.push(format!("{} {id}: {value}", path.join(" ")));
                }
            }
        }
        assert!(bad.is_empty(), "{} args: {bad:#?}", bad.len());
    }
}

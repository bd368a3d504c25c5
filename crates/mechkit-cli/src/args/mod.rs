//! Command-line arguments, parsed into plain data (no library objects are built here): the
//! program and its subcommands (`cli.rs`), the options many commands share (`shared.rs`), and
//! one file per command or family of commands.

mod animate;
mod bead;
mod calculus;
mod cli;
mod counts;
mod friction;
mod gallery;
mod md;
mod mechanics;
mod programs;
mod relative;
mod rigid_collide;
mod roll;
mod rotation;
mod run;
mod serve;
mod shared;
mod spin;
mod sweep;
mod terminal;

pub use animate::AnimateArgs;
pub use bead::BeadArgs;
pub use calculus::{DiffArgs, DsolveArgs, IntegrateArgs, SolveArgs, UnitsArgs};
pub use cli::{Cli, Command};
use counts::{whole_count, whole_u64};
pub use friction::FrictionArgs;
pub use gallery::GalleryArgs;
pub use md::MdArgs;
pub use mechanics::{
    CollideArgs, ComArgs, DeriveArgs, ImpulseArgs, InertiaArgs, PotentialArgs, PowerArgs,
    RocketArgs, WorkArgs,
};
pub use programs::{CompletionsArgs, ListArgs, ManArgs};
pub use relative::RelativeArgs;
pub use rigid_collide::RigidCollideArgs;
pub use roll::RollArgs;
pub use rotation::RotationArgs;
pub use run::{CheckArgs, RunArgs};
pub use serve::ServeArgs;
pub use shared::{PlotFormat, PlotStyle, Report};
pub use spin::SpinArgs;
pub use sweep::{SweepArgs, SweepMergeArgs};
pub use terminal::TerminalArgs;

//! `mechkit inertia BODYFILE`: mass, centre of mass, inertia tensors, principal axes.

use anyhow::{Result, bail};

use super::Outcome;
use crate::args::InertiaArgs;

pub fn inertia(args: &InertiaArgs) -> Result<Outcome> {
    bail!("{}: body files are not read yet", args.file.display())
}

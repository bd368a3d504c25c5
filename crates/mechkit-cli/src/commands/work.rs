//! `mechkit work`: the work (or impulse) from sampled force data, or of a force field along a
//! path.

use anyhow::{Result, bail};

use super::Outcome;
use super::work_field::field_work;
use crate::args::WorkArgs;

pub fn work(args: &WorkArgs) -> Result<Outcome> {
    match (&args.field, &args.file) {
        (Some(field), None) => field_work(args, field),
        (Some(_), Some(_)) => bail!("give either a data file or --field, not both"),
        (None, Some(_)) => bail!("data files are not read yet"),
        (None, None) => bail!(
            "give a data file of x and F columns (mechkit work forcedata.d), or a force field with --field and a path"
        ),
    }
}

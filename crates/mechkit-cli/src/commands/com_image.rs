//! `mechkit com IMAGE`: the centre of mass of the body in a photo.

use anyhow::{Result, bail};

use super::Outcome;
use crate::args::ComArgs;

pub fn com_image(args: &ComArgs) -> Result<Outcome> {
    bail!(
        "{}: images are not read yet",
        args.file
            .as_deref()
            .unwrap_or(std::path::Path::new("?"))
            .display()
    )
}

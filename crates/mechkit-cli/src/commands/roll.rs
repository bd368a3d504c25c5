use anyhow::Result; use super::Outcome; use crate::args::RollArgs; pub fn roll(_a: &RollArgs) -> Result<Outcome> { todo!() }

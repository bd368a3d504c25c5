//! `[output] animation`: the formats a front writes the run's animation in.

use super::doc::Table;
use super::error::{ErrorKind, ScenarioError};

/// `[output] animation`: the formats to write the run's animation in after the run (`"gif"`,
/// or a list such as `["gif", "html"]`).
pub(super) fn read_animation(
    root: &Table<'_, '_>,
) -> Result<Vec<crate::animation::AnimationFormat>, ScenarioError> {
    let Some(output) = root.table("output")? else {
        return Ok(Vec::new());
    };
    let Some(list) = super::doc::string_list(&output, "animation")? else {
        return Ok(Vec::new());
    };
    let mut formats = Vec::new();
    for (name, span) in list {
        let format = crate::animation::AnimationFormat::parse(name).ok_or_else(|| {
            root.src
                .error(
                    ErrorKind::Invalid,
                    format!("unknown animation format `{name}`"),
                    span,
                )
                .with_hint("use \"gif\", \"mp4\" (needs ffmpeg) or \"html\", or a list: [\"gif\", \"html\"]")
        })?;
        if !formats.contains(&format) {
            formats.push(format);
        }
    }
    Ok(formats)
}

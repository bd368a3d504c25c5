//! A plot's title, centred at the top: in the caption's font where it fits, else smaller
//! (down to a little above the labels' size), else on two lines.

use anyhow::{Result, anyhow};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::style::{FONT_FAMILY, Style};

/// Draws `text` at the top of `area`; returns the area below it.
pub(super) fn titled<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    text: &str,
    style: Style,
) -> Result<DrawingArea<DB, Shift>>
where
    DB::ErrorType: 'static,
{
    let width = f64::from(area.dim_in_pixel().0);
    let font = |size: f64| TextStyle::from((FONT_FAMILY, size).into_font());
    let measure = |t: &str, size: f64| -> Result<(f64, f64)> {
        let (w, h) = area
            .estimate_text_size(t, &font(size))
            .map_err(|e| anyhow!("{e}"))?;
        Ok((f64::from(w), f64::from(h)))
    };
    let full = style.caption().1;
    let least = 1.15 * style.label().1;
    let (w, _) = measure(text, full)?;
    let size = if w <= width {
        full
    } else {
        (full * width / w * 0.98).max(least)
    };
    let lines = if measure(text, size)?.0 <= width {
        vec![text.to_string()]
    } else {
        let (a, b) = split(text);
        vec![a.to_string(), b.to_string()]
    };
    let pad = style.px(4.0);
    let line_height = (size * 1.2).round() as i32;
    let centre = (width / 2.0).round() as i32;
    let anchored = font(size).pos(Pos::new(HPos::Center, VPos::Top));
    for (i, line) in lines.iter().enumerate() {
        area.draw_text(line, &anchored, (centre, pad + i as i32 * line_height))
            .map_err(|e| anyhow!("{e}"))?;
    }
    let used = pad + lines.len() as i32 * line_height + pad;
    Ok(area.margin(used, 0, 0, 0))
}

/// `text` in two lines of about equal length: after the `: ` nearest the middle if there is
/// one in its middle half, else at the space nearest the middle.
fn split(text: &str) -> (&str, &str) {
    let middle = text.len() / 2;
    let nearest = |pattern: &str| {
        text.match_indices(pattern)
            .map(|(i, _)| i)
            .min_by_key(|&i| i.abs_diff(middle))
    };
    let colon = nearest(": ").filter(|&i| i.abs_diff(middle) <= text.len() / 4);
    match colon.map(|i| i + 1).or_else(|| nearest(" ")) {
        Some(i) => (text[..i].trim_end(), text[i..].trim_start()),
        None => (text, ""),
    }
}

#[cfg(test)]
mod tests {
    use super::split;

    #[test]
    fn a_long_title_splits_after_its_colon_or_at_a_middle_space() {
        assert_eq!(
            split("Feather falling with air resistance: energy error against time"),
            (
                "Feather falling with air resistance:",
                "energy error against time"
            )
        );
        assert_eq!(split("one two three four"), ("one two", "three four"));
        assert_eq!(split("unbreakable"), ("unbreakable", ""));
    }
}

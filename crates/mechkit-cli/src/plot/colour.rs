//! Curves coloured by a value: the viridis colour map and the colour bar that names it.
//!
//! Viridis (van der Walt and Smith, matplotlib 2.0, 2015, CC0) is perceptually uniform: equal
//! steps of the value look like equal steps of colour, its lightness rises monotonically (it
//! reads in grey too), and it is legible to the common forms of colour blindness.

use anyhow::{Result, anyhow};
use mechkit::figure::ColourScale;
use plotters::coord::Shift;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::style::Style;
use super::tick;

/// Viridis at entries 0, 8, 16, …, 248 and 255 of matplotlib's 256-entry table
/// (`_viridis_data` in `matplotlib/_cm_listed.py`), as 8-bit RGB; between them the map is
/// interpolated linearly.
const VIRIDIS: [RGBColor; 33] = [
    RGBColor(68, 1, 84),
    RGBColor(70, 12, 95),
    RGBColor(71, 24, 106),
    RGBColor(72, 34, 115),
    RGBColor(71, 44, 123),
    RGBColor(69, 54, 129),
    RGBColor(66, 64, 133),
    RGBColor(62, 73, 137),
    RGBColor(58, 82, 139),
    RGBColor(54, 90, 140),
    RGBColor(50, 98, 141),
    RGBColor(47, 106, 141),
    RGBColor(44, 114, 142),
    RGBColor(40, 122, 142),
    RGBColor(38, 129, 142),
    RGBColor(35, 137, 141),
    RGBColor(32, 144, 140),
    RGBColor(30, 152, 138),
    RGBColor(30, 159, 136),
    RGBColor(33, 167, 132),
    RGBColor(40, 174, 127),
    RGBColor(50, 181, 122),
    RGBColor(62, 188, 115),
    RGBColor(77, 194, 107),
    RGBColor(94, 201, 97),
    RGBColor(112, 206, 86),
    RGBColor(131, 211, 75),
    RGBColor(151, 216, 62),
    RGBColor(173, 220, 48),
    RGBColor(194, 223, 34),
    RGBColor(215, 226, 25),
    RGBColor(236, 228, 26),
    RGBColor(253, 231, 37),
];

/// How many slices of one colour draw the bar.
const SLICES: i32 = 128;

/// The entry of matplotlib's table that anchor `i` is.
fn entry(i: usize) -> f64 {
    if i + 1 == VIRIDIS.len() {
        255.0
    } else {
        8.0 * i as f64
    }
}

/// The viridis colour at `t` in [0, 1] (clamped; NaN is the middle): dark blue-violet at 0,
/// green at 0.6, yellow at 1.
pub(super) fn viridis(t: f64) -> RGBColor {
    let t = if t.is_nan() { 0.5 } else { t.clamp(0.0, 1.0) };
    let at = t * 255.0;
    let i = (1..VIRIDIS.len())
        .find(|&i| entry(i) >= at)
        .unwrap_or(VIRIDIS.len() - 1);
    let (a, b) = (VIRIDIS[i - 1], VIRIDIS[i]);
    let f = (at - entry(i - 1)) / (entry(i) - entry(i - 1));
    let mix = |x: u8, y: u8| (f64::from(x) + f * (f64::from(y) - f64::from(x))).round() as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// The values shown on the bar: `scale`'s range, widened about a single value.
fn shown(scale: &ColourScale) -> (f64, f64) {
    let (lo, hi) = (scale.from.min(scale.to), scale.from.max(scale.to));
    super::drawable(if hi > lo {
        (lo, hi)
    } else {
        let d = if lo == 0.0 { 0.5 } else { 0.1 * lo.abs() };
        (lo - d, lo + d)
    })
}

/// The bar's ticks and their labels.
fn ticks(scale: &ColourScale) -> Vec<(f64, String)> {
    let (lo, hi) = shown(scale);
    let magnitude = lo.abs().max(hi.abs());
    let coord: RangedCoordf64 = (lo..hi).into();
    coord
        .key_points(6)
        .into_iter()
        .map(|v| (v, tick(v, magnitude)))
        .collect()
}

/// The parts of the bar, left to right, in canvas pixels.
struct Layout {
    /// From the plotting area to the bar.
    gap: i32,
    /// The bar.
    bar: i32,
    /// A tick mark.
    tick: i32,
    /// From a tick mark to its label.
    pad: i32,
    /// The widest tick label.
    labels: i32,
    /// From the labels to the bar's name.
    before_name: i32,
    /// The name's height (its font size).
    name: i32,
}

impl Layout {
    fn new<DB: DrawingBackend>(
        root: &DrawingArea<DB, Shift>,
        scale: &ColourScale,
        style: Style,
    ) -> Self {
        let font = TextStyle::from(style.label().into_font());
        let labels = ticks(scale)
            .iter()
            .filter_map(|(_, t)| root.estimate_text_size(t, &font).ok())
            .map(|(w, _)| w as i32)
            .max()
            .unwrap_or(0);
        Self {
            gap: style.text_px(18.0),
            bar: style.text_px(16.0),
            tick: style.px(5.0),
            pad: style.px(4.0),
            labels,
            before_name: style.text_px(8.0),
            name: style.axis_desc().1.round() as i32,
        }
    }

    fn width(&self) -> i32 {
        self.gap + self.bar + self.tick + self.pad + self.labels + self.before_name + self.name
    }
}

/// The width of the strip the colour bar of `scale` takes at the right of the plot, in canvas
/// pixels.
pub(super) fn bar_width<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    scale: &ColourScale,
    style: Style,
) -> i32 {
    Layout::new(root, scale, style).width()
}

/// Draws the colour bar of `scale` on `root`, starting at the canvas column `left`, beside a
/// plotting area that spans the canvas rows `rows` (top, bottom): the map from `from` (bottom)
/// to `to` (top) in a framed bar, ticks with values on its right, and the scale's label
/// beside them, reading upwards.
pub(super) fn draw_bar<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    scale: &ColourScale,
    left: i32,
    (top, bottom): (i32, i32),
    style: Style,
) -> Result<()>
where
    DB::ErrorType: 'static,
{
    let layout = Layout::new(root, scale, style);
    let (x0, x1) = (left + layout.gap, left + layout.gap + layout.bar);
    let (lo, hi) = shown(scale);
    let row = |v: f64| f64::from(bottom) - (v - lo) / (hi - lo) * f64::from(bottom - top);
    // the map in thin slices, each overlapping the next so no seam shows
    for k in 0..SLICES {
        let (a, b) = (
            f64::from(k) / f64::from(SLICES),
            f64::from(k + 1) / f64::from(SLICES),
        );
        let colour = viridis(scale.fraction(lo + a.midpoint(b) * (hi - lo)));
        let (ya, yb) = (row(lo + a * (hi - lo)), row(lo + b * (hi - lo)));
        root.draw(&Rectangle::new(
            [(x0, yb.floor() as i32), (x1, ya.ceil() as i32 + 1)],
            colour.filled(),
        ))
        .map_err(|e| anyhow!("{e}"))?;
    }
    root.draw(&Rectangle::new(
        [(x0, top), (x1, bottom)],
        BLACK.stroke_width(style.frame(1.0)),
    ))
    .map_err(|e| anyhow!("{e}"))?;
    let font = TextStyle::from(style.label().into_font()).pos(Pos::new(HPos::Left, VPos::Center));
    for (v, text) in ticks(scale) {
        let y = row(v).round() as i32;
        root.draw(&PathElement::new(
            vec![(x1, y), (x1 + layout.tick, y)],
            BLACK.stroke_width(style.frame(1.0)),
        ))
        .map_err(|e| anyhow!("{e}"))?;
        root.draw_text(&text, &font, (x1 + layout.tick + layout.pad, y))
            .map_err(|e| anyhow!("{e}"))?;
    }
    let name = TextStyle::from(style.axis_desc().into_font())
        .transform(FontTransform::Rotate270)
        .pos(Pos::new(HPos::Center, VPos::Top));
    let x = x1 + layout.tick + layout.pad + layout.labels + layout.before_name;
    root.draw_text(&scale.label, &name, (x, top.midpoint(bottom)))
        .map_err(|e| anyhow!("{e}"))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::viridis;
    use plotters::style::RGBColor;

    #[test]
    fn viridis_runs_from_violet_through_green_to_yellow() {
        assert_eq!(viridis(0.0), RGBColor(68, 1, 84));
        assert_eq!(viridis(1.0), RGBColor(253, 231, 37));
        assert_eq!(viridis(-1.0), viridis(0.0));
        // entry 128 of matplotlib's table is about (33, 144, 141)
        let RGBColor(r, g, b) = viridis(128.0 / 255.0);
        assert!(r.abs_diff(33) <= 2 && g.abs_diff(144) <= 2 && b.abs_diff(141) <= 2);
        // lightness (here the sum of the channels) rises along the map
        let light = |t: f64| {
            let RGBColor(r, g, b) = viridis(t);
            u32::from(r) + u32::from(g) + u32::from(b)
        };
        for k in 0..50 {
            let t = f64::from(k) / 50.0;
            assert!(light(t + 0.02) >= light(t), "at {t}");
        }
    }
}

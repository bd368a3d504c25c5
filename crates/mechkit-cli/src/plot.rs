//! Renders plot data to SVG with plotters, using the bundled DejaVu Sans font (no system font
//! libraries needed), and to PNG by rasterising that SVG with resvg, its text set in the same
//! bundled font: the PNG shows exactly what the SVG does.
//!
//! Plots are drawn on a canvas four times their size and written back at 900x600 with
//! fractional coordinates (`svg.rs`), in the paper or the slides style (`style.rs`): curves
//! (`chart.rs`) with linear or logarithmic vertical axes (`axes.rs`), coloured by a value
//! with a colour bar (`colour.rs`), or bars (`bars.rs`).

use std::path::Path;
use std::sync::Once;

use anyhow::{Context, Result, anyhow};
use mechkit::figure::PlotData;
use mechkit::scenario::write_atomic;
use plotters::prelude::*;
use plotters::style::FontStyle;

pub(crate) mod axes;
mod bars;
mod chart;
mod colour;
mod layout;
pub(crate) mod raster;
mod style;
mod svg;
mod title;

use raster::rasterise;
use style::{CANVAS, FONT_FAMILY, Style};

pub use crate::args::{PlotFormat, PlotStyle};

static FONT: &[u8] = include_bytes!("../assets/DejaVuSans.ttf");
static REGISTER: Once = Once::new();

/// The colour of the light grid lines every chart shares (the sizes are in `style.rs`).
const GRID: RGBColor = RGBColor(235, 235, 235);

const PALETTE: [RGBColor; 8] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(255, 127, 14),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(23, 190, 207),
];

fn register_font() {
    REGISTER.call_once(|| {
        plotters::style::register_font(FONT_FAMILY, FontStyle::Normal, FONT)
            .unwrap_or_else(|_| panic!("the bundled font is a valid TrueType file"));
    });
}

/// Range of the finite values, padded by 5 % (and widened when all values are equal).
fn range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    let span = hi - lo;
    let pad = if span > 1e-12 * hi.abs().max(lo.abs()).max(1e-300) {
        0.05 * span
    } else {
        0.1 * lo.abs().max(1.0)
    };
    (lo - pad, hi + pad)
}

/// The largest end a linear axis has: its span, tick step and ticks are then finite numbers.
const AXIS_END: f64 = f64::MAX / 4.0;

/// The narrowest span of a linear axis, relative to its larger end: a tick step of this
/// span is still many units in the last place of the ticks.
const AXIS_RESOLUTION: f64 = 1e-9;

/// A range whose ticks can be counted: ends clamped to ±[`AXIS_END`] (NaN taken as 0), and
/// a span at least [`AXIS_RESOLUTION`] of the larger end, widened about the middle when it
/// is narrower. Every linear axis is drawn on such a range. plotters counts its ticks by
/// stepping from one end to the other; its step is a power of ten near the span, so with a
/// finite span of this width the count is at most the labels asked for and the loop ends.
/// Two bodies at ±1e308 made the span infinite, the step infinite, and the loop endless (a
/// run that never finished, and ignored SIGTERM).
fn drawable((lo, hi): (f64, f64)) -> (f64, f64) {
    let end = |v: f64| {
        if v.is_nan() {
            0.0
        } else {
            v.clamp(-AXIS_END, AXIS_END)
        }
    };
    let (lo, hi) = (end(lo.min(hi)), end(hi.max(lo)));
    let least = (AXIS_RESOLUTION * lo.abs().max(hi.abs())).max(1e-300);
    if hi - lo >= least {
        return (lo, hi);
    }
    let mid = lo.midpoint(hi);
    (mid - least, mid + least)
}

/// Tick label: plain for ordinary magnitudes, `1.5e11` for very large or small ones.
fn tick(v: f64, scale: f64) -> String {
    if v == 0.0 {
        return "0".into();
    }
    if (1e-3..1e5).contains(&scale) {
        let s = format!("{v:.6}");
        let s = s.trim_end_matches('0').trim_end_matches('.');
        if s == "-0" { "0".into() } else { s.to_string() }
    } else {
        let s = format!("{v:.2e}");
        // 1.50e11 -> 1.5e11
        match s.split_once('e') {
            Some((m, e)) => format!("{}e{e}", m.trim_end_matches('0').trim_end_matches('.')),
            None => s,
        }
    }
}

/// Widens one of the ranges so that a unit has the same length on both axes.
fn equalize(x: (f64, f64), y: (f64, f64), width: f64, height: f64) -> ((f64, f64), (f64, f64)) {
    let (dx, dy) = (x.1 - x.0, y.1 - y.0);
    if dx <= 0.0 || dy <= 0.0 {
        return (x, y);
    }
    let per_px = (dx / width).max(dy / height);
    let (cx, cy) = (x.0.midpoint(x.1), y.0.midpoint(y.1));
    let (hx, hy) = (per_px * width / 2.0, per_px * height / 2.0);
    ((cx - hx, cx + hx), (cy - hy, cy + hy))
}

/// The resolutions a PNG plot may have, in dots per inch (`--dpi`).
pub const PNG_DPI: std::ops::RangeInclusive<u32> = 24..=1200;

/// Draws `plot` into the file at `path` (written atomically): PNG at `format.dpi` dots per
/// inch when its name ends in `.png`, else SVG; in `format.style`.
pub fn render(plot: &PlotData, title: &str, path: &Path, format: PlotFormat) -> Result<()> {
    let svg = svg(plot, title, format.style)?;
    let is_png = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("png"));
    let bytes = if is_png {
        rasterise(&svg, format.dpi)?
    } else {
        svg.into_bytes()
    };
    write_atomic(path, &bytes).with_context(|| format!("cannot write {}", path.display()))
}

/// The SVG text of `plot` titled `title`, in `style`: what [`render`] writes to a `.svg`.
pub fn svg(plot: &PlotData, title: &str, style: PlotStyle) -> Result<String> {
    svg_text(plot, title, Style::new(style))
}

/// The PNG of `plot` at `dpi` dots per inch (within [`PNG_DPI`]): what [`render`] writes to a
/// `.png`.
pub fn png(plot: &PlotData, title: &str, style: PlotStyle, dpi: u32) -> Result<Vec<u8>> {
    if !PNG_DPI.contains(&dpi) {
        return Err(anyhow!(
            "a PNG's resolution is from {} to {} dpi, not {dpi}",
            PNG_DPI.start(),
            PNG_DPI.end()
        ));
    }
    rasterise(&svg(plot, title, style)?, dpi)
}

/// The SVG text of `plot`: drawn on the large canvas, written at the plot's size.
fn svg_text(plot: &PlotData, title: &str, style: Style) -> Result<String> {
    register_font();
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, style.canvas()).into_drawing_area();
        root.fill(&WHITE).map_err(|e| anyhow!("{e}"))?;
        if plot.bars.is_empty() {
            chart::draw(&root, plot, title, style)?;
        } else {
            bars::draw(&root, plot, title, style)?;
        }
        root.present().map_err(|e| anyhow!("{e}"))?;
    }
    // plotters escapes `&`, `<` and `>` in text, but keeps the characters XML 1.0 forbids (a
    // title with control characters): dropped, so the file is well-formed whatever it says
    let svg = crate::xml::drop_forbidden(&svg).into_owned();
    Ok(svg::rescale(&svg, f64::from(CANVAS)))
}

/// Draws a run's plots into `dir` as `<stem>.svg` (or `.png`), lists them in its summary and
/// rewrites `summary.json` (what `mechkit run` and `mechkit gallery` write after a run).
pub fn render_run(
    scenario: &mechkit::scenario::Scenario,
    out: &mut mechkit::scenario::RunOutput,
    dir: &Path,
    format: PlotFormat,
) -> Result<()> {
    render_plots(scenario, out, dir, format, &|| false)?;
    scenario.write_summary(dir, &out.summary)?;
    Ok(())
}

/// Draws the run's plots into `dir` and lists them in its summary (which is not written);
/// stops before the next plot once `stop` says so.
pub fn render_plots(
    scenario: &mechkit::scenario::Scenario,
    out: &mut mechkit::scenario::RunOutput,
    dir: &Path,
    format: PlotFormat,
    stop: &dyn Fn() -> bool,
) -> Result<()> {
    for p in &out.plots {
        if stop() {
            break;
        }
        let name = format.file(&p.file_stem);
        render(p, &scenario.title, &dir.join(&name), format)?;
        out.summary.files.plots.push(name);
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use plotters::coord::types::RangedCoordf64;
    use plotters::prelude::Ranged;

    use super::drawable;

    /// Issue 26: an axis from -1e308 to 1e308 (two bodies that far apart) has an infinite
    /// span; plotters' tick loop never ended on it. Every range is made drawable, and its
    /// ticks come out finite and few, whatever the ends.
    #[test]
    fn issue_026_every_axis_range_has_few_finite_ticks() {
        let extremes = [
            (-1e308, 1e308),
            (f64::MIN, f64::MAX),
            (f64::NEG_INFINITY, f64::INFINITY),
            (f64::NAN, 1.0),
            (1e308, 1e308),
            (1e308, 1.000_000_000_000_000_2e308),
            (5e-324, 1e-323),
            (0.0, 0.0),
            (-0.0, 5e-324),
            (1e300, -1e300),
            (0.0, 1.0),
        ];
        for range in extremes {
            let (lo, hi) = drawable(range);
            assert!(
                lo.is_finite() && hi.is_finite() && hi > lo,
                "{range:?} -> {lo}, {hi}"
            );
            assert!((hi - lo).is_finite(), "{range:?}");
            let ticks = RangedCoordf64::from(lo..hi).key_points(12);
            assert!(ticks.len() <= 14, "{range:?}: {} ticks", ticks.len());
            assert!(ticks.iter().all(|t| t.is_finite()), "{range:?}: {ticks:?}");
        }
        // ordinary ranges are drawn as they are
        assert_eq!(drawable((-0.05, 1.05)), (-0.05, 1.05));
    }
}

//! Renders plot data to SVG with plotters, using the bundled DejaVu Sans font (no system font
//! libraries needed), and to PNG by rasterising that SVG with resvg, its text set in the same
//! bundled font: the PNG shows exactly what the SVG does.

use std::path::Path;
use std::sync::Once;

use anyhow::{Context, Result, anyhow};
use mechkit::figure::{LineStyle, MarkerShape, PlotData};
use mechkit::scenario::write_atomic;
use plotters::prelude::*;
use plotters::style::FontStyle;

mod bars;
mod layout;
mod raster;

use layout::{clip_to_band, legend_corner};
use raster::rasterise;

pub use crate::args::PlotFormat;

static FONT: &[u8] = include_bytes!("../assets/DejaVuSans.ttf");
static REGISTER: Once = Once::new();

/// The house style every chart shares: the registered font, its sizes, and the grid colour.
const FONT_FAMILY: &str = "sans-serif";
const CAPTION_SIZE: u32 = 22;
const LABEL_SIZE: u32 = 14;
const AXIS_DESC_SIZE: u32 = 16;
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

/// The size of every plot in SVG pixels (at 96 dpi).
const SIZE: (u32, u32) = (900, 600);

/// Draws `plot` into the file at `path` (written atomically): PNG at `dpi` dots per inch when
/// its name ends in `.png`, else SVG.
pub fn render(plot: &PlotData, title: &str, path: &Path, dpi: u32) -> Result<()> {
    let svg = svg_text(plot, title)?;
    let is_png = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("png"));
    let bytes = if is_png {
        rasterise(&svg, dpi)?
    } else {
        svg.into_bytes()
    };
    write_atomic(path, &bytes).with_context(|| format!("cannot write {}", path.display()))
}

/// The SVG text of `plot`.
fn svg_text(plot: &PlotData, title: &str) -> Result<String> {
    register_font();
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, SIZE).into_drawing_area();
        root.fill(&WHITE).map_err(|e| anyhow!("{e}"))?;
        if !plot.bars.is_empty() {
            bars::draw(&root, plot, title)?;
            root.present().map_err(|e| anyhow!("{e}"))?;
            drop(root);
            return Ok(svg);
        }
        let points = || plot.series.iter().flat_map(|s| s.points.iter());
        let marks = || plot.markers.iter().map(|m| m.at);
        let (mut xr, mut yr) = (
            range(points().map(|p| p.0).chain(marks().map(|p| p.0))),
            range(points().map(|p| p.1).chain(marks().map(|p| p.1))),
        );
        if let Some(limits) = plot.y_limits {
            yr = limits;
        }
        if plot.equal_aspect {
            // plotting area: 900 x 600 minus margins and label areas
            (xr, yr) = equalize(
                xr,
                yr,
                900.0 - 2.0 * 16.0 - 80.0,
                600.0 - 2.0 * 16.0 - 48.0 - 30.0,
            );
        }
        let ((x0, x1), (y0, y1)) = (xr, yr);
        let (xs, ys) = (x0.abs().max(x1.abs()), y0.abs().max(y1.abs()));
        let mut chart = ChartBuilder::on(&root)
            .caption(
                format!("{title}: {}", plot.spec),
                (FONT_FAMILY, CAPTION_SIZE),
            )
            .margin(16)
            .x_label_area_size(48)
            .y_label_area_size(80)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(|e| anyhow!("{e}"))?;
        chart
            .configure_mesh()
            .x_label_formatter(&|v| tick(*v, xs))
            .y_label_formatter(&|v| tick(*v, ys))
            .x_desc(&plot.x_label)
            .y_desc(&plot.y_label)
            .label_style((FONT_FAMILY, LABEL_SIZE))
            .axis_desc_style((FONT_FAMILY, AXIS_DESC_SIZE))
            .light_line_style(GRID)
            .draw()
            .map_err(|e| anyhow!("{e}"))?;
        let mut band_labels: Vec<&str> = Vec::new();
        for band in &plot.bands {
            let shade = RGBColor(120, 120, 120).mix(0.15);
            let anno = chart
                .draw_series(std::iter::once(Rectangle::new(
                    [(band.from.max(x0), y0), (band.to.min(x1), y1)],
                    shade.filled(),
                )))
                .map_err(|e| anyhow!("{e}"))?;
            if !band_labels.contains(&band.label.as_str()) {
                band_labels.push(&band.label);
                anno.label(band.label.clone()).legend(move |(x, y)| {
                    Rectangle::new([(x, y - 5), (x + 20, y + 5)], shade.filled())
                });
            }
        }
        for (i, s) in plot.series.iter().enumerate() {
            let color = PALETTE[i % PALETTE.len()];
            // the parts of the curve inside the shown range: a potential that leaves the chart
            // is cut at its edge, not drawn along it
            let pieces = clip_to_band(&s.points, (y0, y1));
            let inside: Vec<(f64, f64)> = pieces.iter().flatten().copied().collect();
            let stroke = color.stroke_width(2);
            let anno = match s.style {
                LineStyle::Dashed => {
                    for piece in pieces.iter().skip(1) {
                        chart
                            .draw_series(DashedLineSeries::new(piece.iter().copied(), 8, 6, stroke))
                            .map_err(|e| anyhow!("{e}"))?;
                    }
                    let first = pieces.first().cloned().unwrap_or_default();
                    chart
                        .draw_series(DashedLineSeries::new(first, 8, 6, stroke))
                        .map_err(|e| anyhow!("{e}"))?
                }
                LineStyle::Markers => chart
                    .draw_series(inside.iter().map(|&p| Circle::new(p, 3, color.filled())))
                    .map_err(|e| anyhow!("{e}"))?,
                _ => chart
                    .draw_series(
                        pieces
                            .iter()
                            .map(|piece| PathElement::new(piece.clone(), stroke)),
                    )
                    .map_err(|e| anyhow!("{e}"))?,
            };
            // an empty label keeps the curve out of the legend (a sweep's thinned legend)
            if !s.label.is_empty() {
                let markers = s.style == LineStyle::Markers;
                anno.label(s.label.clone()).legend(move |(x, y)| {
                    // a marker series shows its marker, a line its line
                    let (from, to) = if markers {
                        (x + 10, x + 10)
                    } else {
                        (x, x + 20)
                    };
                    EmptyElement::at((x, y))
                        + PathElement::new(vec![(from - x, 0), (to - x, 0)], color.stroke_width(2))
                        + Circle::new((10, 0), if markers { 3 } else { 0 }, color.filled())
                });
            }
            // the end of the curve, where it is shown
            let last = s
                .points
                .iter()
                .rev()
                .find(|(x, y)| x.is_finite() && y.is_finite())
                .filter(|(_, y)| (y0..=y1).contains(y));
            if s.style == LineStyle::Solid
                && let Some(&last) = last
            {
                chart
                    .draw_series(std::iter::once(Circle::new(last, 4, color.filled())))
                    .map_err(|e| anyhow!("{e}"))?;
            }
        }
        let mut labelled: Vec<&str> = Vec::new();
        for m in &plot.markers {
            let at = m.at;
            if !(at.0.is_finite() && at.1.is_finite()) || at.1 < y0 || at.1 > y1 {
                continue;
            }
            let red = RGBColor(214, 39, 40);
            let anno = match m.shape {
                MarkerShape::Filled => {
                    chart.draw_series(std::iter::once(Circle::new(at, 6, BLACK.filled())))
                }
                MarkerShape::Open => {
                    chart.draw_series(std::iter::once(Circle::new(at, 6, BLACK.stroke_width(2))))
                }
                MarkerShape::Cross => {
                    chart.draw_series(std::iter::once(Cross::new(at, 6, BLACK.stroke_width(2))))
                }
                _ => chart.draw_series(std::iter::once(TriangleMarker::new(at, 7, red.filled()))),
            }
            .map_err(|e| anyhow!("{e}"))?;
            if labelled.contains(&m.label.as_str()) {
                continue;
            }
            labelled.push(&m.label);
            let anno = anno.label(m.label.clone());
            match m.shape {
                MarkerShape::Filled => {
                    anno.legend(|(x, y)| Circle::new((x + 10, y), 6, BLACK.filled()));
                }
                MarkerShape::Open => {
                    anno.legend(|(x, y)| Circle::new((x + 10, y), 6, BLACK.stroke_width(2)));
                }
                MarkerShape::Cross => {
                    anno.legend(|(x, y)| Cross::new((x + 10, y), 6, BLACK.stroke_width(2)));
                }
                _ => {
                    anno.legend(move |(x, y)| TriangleMarker::new((x + 10, y), 7, red.filled()));
                }
            }
        }
        if plot.series.len() + labelled.len() + plot.bands.len() > 1 {
            chart
                .configure_series_labels()
                .background_style(WHITE.mix(0.85))
                .border_style(BLACK.mix(0.3))
                .label_font((FONT_FAMILY, LABEL_SIZE))
                .position(legend_corner(plot, &labelled, (xr, yr)))
                .draw()
                .map_err(|e| anyhow!("{e}"))?;
        }
        root.present().map_err(|e| anyhow!("{e}"))?;
    }
    Ok(svg)
}

/// Draws a run's plots into `dir` as `<stem>.svg` (or `.png`), lists them in its summary and
/// rewrites `summary.json` (what `mechkit run` and `mechkit gallery` write after a run).
pub fn render_run(
    scenario: &mechkit::scenario::Scenario,
    out: &mut mechkit::scenario::RunOutput,
    dir: &Path,
    format: PlotFormat,
) -> Result<()> {
    for p in &out.plots {
        let name = format.file(&p.file_stem);
        render(p, &scenario.title, &dir.join(&name), format.dpi)?;
        out.summary.files.plots.push(name);
    }
    scenario.write_summary(dir, &out.summary)?;
    Ok(())
}

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

/// The parts of the polyline `points` inside `y0 ≤ y ≤ y1`, each a polyline: a segment that
/// crosses a bound ends (or starts) on it, and a non-finite point breaks the line. Points are
/// never moved onto the bound (a clamped curve would show a plateau that is not in the data).
fn clip_to_band(points: &[(f64, f64)], (y0, y1): (f64, f64)) -> Vec<Vec<(f64, f64)>> {
    let mut pieces: Vec<Vec<(f64, f64)>> = Vec::new();
    let mut current: Vec<(f64, f64)> = Vec::new();
    let flush = |current: &mut Vec<(f64, f64)>, pieces: &mut Vec<Vec<(f64, f64)>>| {
        if !current.is_empty() {
            pieces.push(std::mem::take(current));
        }
    };
    let inside = |y: f64| (y0..=y1).contains(&y);
    let mut previous: Option<(f64, f64)> = None;
    for &p in points {
        if !(p.0.is_finite() && p.1.is_finite()) {
            flush(&mut current, &mut pieces);
            previous = None;
            continue;
        }
        let Some(a) = previous.replace(p) else {
            if inside(p.1) {
                current.push(p);
            }
            continue;
        };
        // the parameters t in [0, 1] of the segment a → p inside the band
        let dy = p.1 - a.1;
        let (t0, t1) = if dy == 0.0 {
            if inside(a.1) { (0.0, 1.0) } else { (1.0, 0.0) }
        } else {
            let (ta, tb) = ((y0 - a.1) / dy, (y1 - a.1) / dy);
            (ta.min(tb).max(0.0), ta.max(tb).min(1.0))
        };
        if t0 > t1 {
            flush(&mut current, &mut pieces);
            continue;
        }
        let at = |t: f64| {
            if t == 1.0 {
                p
            } else {
                (a.0 + t * (p.0 - a.0), a.1 + t * dy)
            }
        };
        if t0 > 0.0 || current.is_empty() {
            // entering the band: a new piece
            flush(&mut current, &mut pieces);
            current.push(if t0 == 0.0 { a } else { at(t0) });
        }
        current.push(at(t1));
        if t1 < 1.0 {
            flush(&mut current, &mut pieces);
        }
    }
    flush(&mut current, &mut pieces);
    pieces
}

/// The corner of the plotting area where the legend covers the least of the data: the
/// legend's box is estimated from its entries (series with a label, the `markers` labels, the
/// bands) and its longest label, and the curves' points (with their segments sampled) and the
/// markers are counted in each corner's box; upper right wins ties, then upper left, lower
/// right, lower left.
fn legend_corner(
    plot: &PlotData,
    markers: &[&str],
    ((x0, x1), (y0, y1)): ((f64, f64), (f64, f64)),
) -> SeriesLabelPosition {
    let mut labels: Vec<&str> = plot
        .series
        .iter()
        .map(|s| s.label.as_str())
        .filter(|l| !l.is_empty())
        .chain(markers.iter().copied())
        .collect();
    for b in &plot.bands {
        if !labels.contains(&b.label.as_str()) {
            labels.push(&b.label);
        }
    }
    let longest = labels.iter().map(|l| l.chars().count()).max().unwrap_or(0);
    // the plotting area is about 790 x 490 pixels; an entry is about 20 pixels high and a
    // character of the labels' font 8 wide
    let w = ((40.0 + 8.0 * longest as f64) / 790.0).min(0.9);
    let h = ((12.0 + 20.0 * labels.len() as f64) / 490.0).min(0.9);
    let (sx, sy) = (x1 - x0, y1 - y0);
    let mut points: Vec<(f64, f64)> = plot.markers.iter().map(|m| m.at).collect();
    for s in &plot.series {
        for pair in s.points.windows(2) {
            let ((ax, ay), (bx, by)) = (pair[0], pair[1]);
            for k in 0..8 {
                let t = f64::from(k) / 8.0;
                points.push((ax + t * (bx - ax), ay + t * (by - ay)));
            }
        }
        points.extend(s.points.last());
    }
    let fractions: Vec<(f64, f64)> = points
        .iter()
        .filter(|(x, y)| x.is_finite() && y.is_finite())
        .map(|(x, y)| ((x - x0) / sx, (y - y0) / sy))
        .collect();
    let corners = [
        (
            SeriesLabelPosition::UpperRight,
            (1.0 - w, 1.0),
            (1.0 - h, 1.0),
        ),
        (SeriesLabelPosition::UpperLeft, (0.0, w), (1.0 - h, 1.0)),
        (SeriesLabelPosition::LowerRight, (1.0 - w, 1.0), (0.0, h)),
        (SeriesLabelPosition::LowerLeft, (0.0, w), (0.0, h)),
    ];
    let covered = |(fx, fy): ((f64, f64), (f64, f64))| {
        fractions
            .iter()
            .filter(|(x, y)| (fx.0..=fx.1).contains(x) && (fy.0..=fy.1).contains(y))
            .count()
    };
    corners
        .into_iter()
        .min_by_key(|&(_, fx, fy)| covered((fx, fy)))
        .map_or(SeriesLabelPosition::UpperRight, |(p, _, _)| p)
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

/// The PNG of the SVG text `svg` at `dpi` dots per inch (96: one pixel per SVG pixel), on a
/// white background.
fn rasterise(svg: &str, dpi: u32) -> Result<Vec<u8>> {
    use resvg::{tiny_skia, usvg};
    let mut options = usvg::Options::default();
    options.fontdb_mut().load_font_data(FONT.to_vec());
    options.fontdb_mut().set_sans_serif_family("DejaVu Sans");
    options.font_family = "DejaVu Sans".into();
    let tree = usvg::Tree::from_str(svg, &options).context("cannot read the plot's SVG")?;
    let scale = dpi as f32 / 96.0;
    let size = tree
        .size()
        .to_int_size()
        .scale_by(scale)
        .ok_or_else(|| anyhow!("a PNG at {dpi} dpi has no pixels; use --dpi 96 or more"))?;
    let mut pixmap = tiny_skia::Pixmap::new(size.width(), size.height())
        .ok_or_else(|| anyhow!("cannot allocate a {}x{} PNG", size.width(), size.height()))?;
    pixmap.fill(tiny_skia::Color::WHITE);
    let transform = tiny_skia::Transform::from_scale(scale, scale);
    resvg::render(&tree, transform, &mut pixmap.as_mut());
    encode_rgb(&pixmap, dpi).map_err(|e| anyhow!("cannot encode the PNG: {e}"))
}

/// The opaque `pixmap` as an RGB PNG (the alpha channel is 255 throughout: a white
/// background) that records its resolution, `dpi`.
fn encode_rgb(pixmap: &resvg::tiny_skia::Pixmap, dpi: u32) -> Result<Vec<u8>, png::EncodingError> {
    let rgb: Vec<u8> = pixmap
        .data()
        .chunks_exact(4)
        .flat_map(|p| [p[0], p[1], p[2]])
        .collect();
    let mut out = Vec::new();
    let mut encoder = png::Encoder::new(&mut out, pixmap.width(), pixmap.height());
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_compression(png::Compression::High);
    let per_metre = (f64::from(dpi) / 0.0254).round() as u32;
    encoder.set_pixel_dims(Some(png::PixelDimensions {
        xppu: per_metre,
        yppu: per_metre,
        unit: png::Unit::Meter,
    }));
    let mut writer = encoder.write_header()?;
    writer.write_image_data(&rgb)?;
    writer.finish()?;
    Ok(out)
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

#[cfg(test)]
mod tests {
    use mechkit::figure::{PlotData, Series};
    use plotters::prelude::SeriesLabelPosition;

    use super::{clip_to_band, legend_corner};

    #[test]
    fn the_legend_goes_where_it_covers_no_data() {
        // two curves rising to the upper right: the upper left is free
        let rising = |k: f64| {
            (0..=50)
                .map(|i| (f64::from(i) / 50.0, k * f64::from(i) / 50.0))
                .collect()
        };
        let plot = PlotData::new("y(x)", "y_x", "x", "y")
            .with_series(Series::line("a", rising(1.0)))
            .with_series(Series::line("b", rising(0.9)));
        let corner = legend_corner(&plot, &[], ((0.0, 1.0), (0.0, 1.0)));
        assert!(
            matches!(corner, SeriesLabelPosition::UpperLeft),
            "{corner:?}"
        );
        // a decaying curve from the upper left: the upper right is free, and preferred
        let decaying = (0..=50)
            .map(|i| (f64::from(i) / 50.0, (-5.0 * f64::from(i) / 50.0).exp()))
            .collect();
        let plot = PlotData::new("y(x)", "y_x", "x", "y").with_series(Series::line("c", decaying));
        let corner = legend_corner(&plot, &["marker"], ((0.0, 1.0), (0.0, 1.0)));
        assert!(
            matches!(corner, SeriesLabelPosition::UpperRight),
            "{corner:?}"
        );
    }

    #[test]
    fn a_curve_is_cut_at_the_band_not_clamped_onto_it() {
        // up through y = 1 and back down: two pieces, the crossings on the bound
        let pts = [(0.0, 0.0), (1.0, 2.0), (2.0, 0.0), (3.0, 0.5)];
        let pieces = clip_to_band(&pts, (-1.0, 1.0));
        assert_eq!(
            pieces,
            vec![
                vec![(0.0, 0.0), (0.5, 1.0)],
                vec![(1.5, 1.0), (2.0, 0.0), (3.0, 0.5)]
            ]
        );
        // wholly outside: nothing; a NaN breaks the line
        assert!(clip_to_band(&[(0.0, 5.0), (1.0, 6.0)], (0.0, 1.0)).is_empty());
        let broken = clip_to_band(
            &[
                (0.0, 0.1),
                (1.0, 0.2),
                (2.0, f64::NAN),
                (3.0, 0.3),
                (4.0, 0.4),
            ],
            (0.0, 1.0),
        );
        assert_eq!(broken.len(), 2);
        // a segment through the whole band from above to below
        let through = clip_to_band(&[(0.0, 3.0), (4.0, -1.0)], (0.0, 2.0));
        assert_eq!(through, vec![vec![(1.0, 2.0), (3.0, 0.0)]]);
    }
}

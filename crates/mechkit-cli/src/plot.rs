//! Renders plot data to SVG with plotters, using the bundled DejaVu Sans font (no system font
//! libraries needed).

use std::path::Path;
use std::sync::Once;

use anyhow::{Context, Result, anyhow};
use mechkit::scenario::{PlotData, write_atomic};
use plotters::prelude::*;
use plotters::style::FontStyle;

static FONT: &[u8] = include_bytes!("../assets/DejaVuSans.ttf");
static REGISTER: Once = Once::new();

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
        plotters::style::register_font("sans-serif", FontStyle::Normal, FONT)
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
        s.trim_end_matches('0').trim_end_matches('.').to_string()
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

/// Draws `plot` into an SVG file at `path` (written atomically).
pub fn render_svg(plot: &PlotData, title: &str, path: &Path) -> Result<()> {
    register_font();
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (900, 600)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| anyhow!("{e}"))?;
        let points = || plot.series.iter().flat_map(|s| s.points.iter());
        let (mut xr, mut yr) = (range(points().map(|p| p.0)), range(points().map(|p| p.1)));
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
            .caption(format!("{title}: {}", plot.spec), ("sans-serif", 22))
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
            .label_style(("sans-serif", 14))
            .axis_desc_style(("sans-serif", 16))
            .light_line_style(RGBColor(235, 235, 235))
            .draw()
            .map_err(|e| anyhow!("{e}"))?;
        for (i, s) in plot.series.iter().enumerate() {
            let color = PALETTE[i % PALETTE.len()];
            let pts: Vec<(f64, f64)> = s
                .points
                .iter()
                .copied()
                .filter(|(x, y)| x.is_finite() && y.is_finite())
                .collect();
            chart
                .draw_series(LineSeries::new(pts.iter().copied(), color.stroke_width(2)))
                .map_err(|e| anyhow!("{e}"))?
                .label(s.label.clone())
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
                });
            if let Some(&last) = pts.last() {
                chart
                    .draw_series(std::iter::once(Circle::new(last, 4, color.filled())))
                    .map_err(|e| anyhow!("{e}"))?;
            }
        }
        if plot.series.len() > 1 {
            chart
                .configure_series_labels()
                .background_style(WHITE.mix(0.85))
                .border_style(BLACK.mix(0.3))
                .label_font(("sans-serif", 14))
                .position(SeriesLabelPosition::UpperRight)
                .draw()
                .map_err(|e| anyhow!("{e}"))?;
        }
        root.present().map_err(|e| anyhow!("{e}"))?;
    }
    write_atomic(path, svg.as_bytes()).with_context(|| format!("cannot write {}", path.display()))
}

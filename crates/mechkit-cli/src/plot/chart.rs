//! A chart of curves: axes (linear, or a logarithmic vertical axis with decade labels),
//! shaded bands, curves in the palette's colours or coloured by a value with a colour bar,
//! marked points and the legend. The frame it shares with the bars (title, margins, mesh) is
//! in `chart/frame.rs`.

use anyhow::{Result, anyhow};
use mechkit::figure::{LineStyle, MarkerShape, PlotData, Scale, Series};
use plotters::coord::Shift;
use plotters::coord::ranged1d::ValueFormatter;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;

mod frame;

pub(super) use frame::{draw_mesh, titled_area};

use super::axes::{decade, log_range};
use super::colour::{bar_width, draw_bar, viridis};
use super::layout::{clip_to_band, in_legend, legend_corner};
use super::style::Style;
use super::{PALETTE, drawable, equalize, range, tick};

/// The chart's frame: its style, ranges and vertical scale.
struct Frame {
    style: Style,
    x: (f64, f64),
    y: (f64, f64),
    log: bool,
}

/// Draws the curves, bands and markers of `plot` on `root`, titled `title: spec`.
pub(super) fn draw<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    plot: &PlotData,
    title: &str,
    style: Style,
) -> Result<()>
where
    DB::ErrorType: 'static,
{
    let area = titled_area(root, plot, title, style)?;
    let colour = plot
        .colour_scale
        .as_ref()
        .filter(|_| plot.series.iter().any(|s| s.value.is_some()));
    let (area, bar) = match colour {
        Some(scale) => {
            let w = area.dim_in_pixel().0 as i32 - bar_width(root, scale, style);
            let (left, right) = area.split_horizontally(w);
            (left, Some((scale, right.get_base_pixel().0)))
        }
        None => (area, None),
    };
    let (x_area, y_area) = style.label_areas();
    let right = style.px(8.0);
    let log = plot.y_scale == Scale::Log;
    let points = || plot.series.iter().flat_map(|s| s.points.iter());
    let marks = || plot.markers.iter().map(|m| m.at);
    let ys = || points().map(|p| p.1).chain(marks().map(|p| p.1));
    let mut xr = range(points().map(|p| p.0).chain(marks().map(|p| p.0)));
    let mut yr = if log { log_range(ys()) } else { range(ys()) };
    if let Some(limits) = plot.y_limits.filter(|l| !log || l.0 > 0.0) {
        yr = limits;
    }
    if plot.equal_aspect && !log {
        let (w, h) = area.dim_in_pixel();
        (xr, yr) = equalize(
            xr,
            yr,
            f64::from(w) - f64::from(y_area + right),
            f64::from(h) - f64::from(x_area),
        );
    }
    xr = drawable(xr);
    if !log {
        yr = drawable(yr);
    }
    let mut builder = ChartBuilder::on(&area);
    builder
        .x_label_area_size(x_area)
        .y_label_area_size(y_area)
        .margin_right(right);
    let frame = Frame {
        style,
        x: xr,
        y: yr,
        log,
    };
    let ((x0, x1), (y0, y1)) = (xr, yr);
    let rows = if log {
        let chart = builder
            .build_cartesian_2d(x0..x1, (y0..y1).log_scale())
            .map_err(|e| anyhow!("{e}"))?;
        curves(chart, plot, &frame)?
    } else {
        let chart = builder
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(|e| anyhow!("{e}"))?;
        curves(chart, plot, &frame)?
    };
    if let Some((scale, left)) = bar {
        draw_bar(root, scale, left, rows, style)?;
    }
    Ok(())
}

/// The colour of each curve: its value's on the colour scale, else the palette's next.
fn colours(plot: &PlotData) -> Vec<RGBColor> {
    let mut next = 0;
    plot.series
        .iter()
        .map(|s| {
            if let (Some(scale), Some(v)) = (&plot.colour_scale, s.value) {
                viridis(scale.fraction(v))
            } else {
                next += 1;
                PALETTE[(next - 1) % PALETTE.len()]
            }
        })
        .collect()
}

/// The points of `s` that can be shown: on a log axis, a point at or below zero breaks the
/// curve (it has no place on the axis).
fn showable(s: &Series, log: bool) -> Vec<(f64, f64)> {
    if log {
        s.points
            .iter()
            .map(|&(x, y)| if y > 0.0 { (x, y) } else { (x, f64::NAN) })
            .collect()
    } else {
        s.points.clone()
    }
}

/// Draws the mesh, the bands, the curves, the markers and the legend on `chart`; returns the
/// plotting area's top and bottom canvas rows.
fn curves<'a, DB, Y>(
    mut chart: ChartContext<'a, DB, Cartesian2d<RangedCoordf64, Y>>,
    plot: &PlotData,
    frame: &Frame,
) -> Result<(i32, i32)>
where
    DB: DrawingBackend + 'a,
    DB::ErrorType: 'static,
    Y: Ranged<ValueType = f64> + ValueFormatter<f64>,
{
    let style = frame.style;
    let ((x0, x1), (y0, y1)) = (frame.x, frame.y);
    let (xs, ys) = (x0.abs().max(x1.abs()), y0.abs().max(y1.abs()));
    // decades as plain numbers while all are ordinary (0.01 … 1000), else as 1e-6
    let plain = y0 >= 0.999e-2 && y1 <= 1.001e3;
    let x_fmt = |v: &f64| tick(*v, xs);
    let y_fmt = |v: &f64| {
        if frame.log {
            decade(*v, plain)
        } else {
            tick(*v, ys)
        }
    };
    let labels = style.labels();
    let y_labels = if frame.log {
        // one label per decade (plotters thins them when there are too many)
        let decades = (y1 / y0).log10().round().max(1.0) as usize;
        (decades + 1).min(12)
    } else {
        labels
    };
    let mut mesh = chart.configure_mesh();
    mesh.x_labels(labels)
        .y_labels(y_labels)
        .x_label_formatter(&x_fmt)
        .y_label_formatter(&y_fmt);
    draw_mesh(&mut mesh, plot, style)?;
    let legend_box = style.text_px(20.0);
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
            let h = legend_box / 4;
            anno.label(band.label.clone()).legend(move |(x, y)| {
                Rectangle::new([(x, y - h), (x + legend_box, y + h)], shade.filled())
            });
        }
    }
    let colours = colours(plot);
    for (s, &color) in plot.series.iter().zip(&colours) {
        // the parts of the curve inside the shown range: a potential that leaves the chart
        // is cut at its edge, not drawn along it
        let pieces = clip_to_band(&showable(s, frame.log), (y0, y1));
        let stroke = color.stroke_width(style.line(2.0));
        let anno = match s.style {
            LineStyle::Dashed => {
                let (dash, gap) = (style.dash(8.0), style.dash(6.0));
                for piece in pieces.iter().skip(1) {
                    chart
                        .draw_series(DashedLineSeries::new(
                            piece.iter().copied(),
                            dash,
                            gap,
                            stroke,
                        ))
                        .map_err(|e| anyhow!("{e}"))?;
                }
                let first = pieces.first().cloned().unwrap_or_default();
                chart
                    .draw_series(DashedLineSeries::new(first, dash, gap, stroke))
                    .map_err(|e| anyhow!("{e}"))?
            }
            LineStyle::Markers => {
                let r = style.mark(3.0);
                chart
                    .draw_series(
                        pieces
                            .iter()
                            .flatten()
                            .map(|&p| Circle::new(p, r, color.filled())),
                    )
                    .map_err(|e| anyhow!("{e}"))?
            }
            _ => chart
                .draw_series(
                    pieces
                        .iter()
                        .map(|piece| PathElement::new(piece.clone(), stroke)),
                )
                .map_err(|e| anyhow!("{e}"))?,
        };
        // an empty label keeps the curve out of the legend (a sweep's thinned legend), and so
        // does a value on the colour scale (the colour bar names it)
        if in_legend(plot, s) {
            let markers = s.style == LineStyle::Markers;
            let (r, w) = (style.mark(3.0), style.line(2.0));
            anno.label(s.label.clone()).legend(move |(x, y)| {
                // a marker series shows its marker, a line its line
                let (from, to) = if markers {
                    (legend_box / 2, legend_box / 2)
                } else {
                    (0, legend_box)
                };
                EmptyElement::at((x, y))
                    + PathElement::new(vec![(from, 0), (to, 0)], color.stroke_width(w))
                    + Circle::new(
                        (legend_box / 2, 0),
                        if markers { r } else { 0 },
                        color.filled(),
                    )
            });
        }
        // the end of the curve, where it is shown
        let last = s
            .points
            .iter()
            .rev()
            .find(|(x, y)| x.is_finite() && y.is_finite() && (!frame.log || *y > 0.0))
            .filter(|(_, y)| (y0..=y1).contains(y));
        if s.style == LineStyle::Solid
            && let Some(&last) = last
        {
            chart
                .draw_series(std::iter::once(Circle::new(
                    last,
                    style.mark(4.0),
                    color.filled(),
                )))
                .map_err(|e| anyhow!("{e}"))?;
        }
    }
    let labelled = markers(&mut chart, plot, frame)?;
    let entries = plot.series.iter().filter(|s| in_legend(plot, s)).count()
        + labelled.len()
        + band_labels.len();
    if entries > 0 && plot.series.len() + labelled.len() + plot.bands.len() > 1 {
        let (w, h) = chart.plotting_area().dim_in_pixel();
        let area = (
            f64::from(w) / f64::from(style.px(1.0)),
            f64::from(h) / f64::from(style.px(1.0)),
        );
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK.mix(0.3).stroke_width(style.frame(1.0)))
            .label_font(style.label())
            .legend_area_size(style.text_px(30.0))
            .margin(style.text_px(10.0))
            .position(legend_corner(
                plot,
                &labelled,
                (frame.x, frame.y),
                frame.log,
                (style.text_factor(), area),
            ))
            .draw()
            .map_err(|e| anyhow!("{e}"))?;
    }
    let rows = chart.plotting_area().get_pixel_range().1;
    Ok((rows.start, rows.end))
}

/// Draws the marked points of `plot`; returns their legend labels, each once.
fn markers<'a, 'p, DB, Y>(
    chart: &mut ChartContext<'a, DB, Cartesian2d<RangedCoordf64, Y>>,
    plot: &'p PlotData,
    frame: &Frame,
) -> Result<Vec<&'p str>>
where
    DB: DrawingBackend + 'a,
    DB::ErrorType: 'static,
    Y: Ranged<ValueType = f64> + ValueFormatter<f64>,
{
    let style = frame.style;
    let (y0, y1) = frame.y;
    let (size, width) = (style.mark(6.0), style.line(2.0));
    let triangle = style.mark(7.0);
    let legend_x = style.text_px(10.0);
    let red = RGBColor(214, 39, 40);
    let mut labelled: Vec<&str> = Vec::new();
    for m in &plot.markers {
        let at = m.at;
        if !(at.0.is_finite() && at.1.is_finite()) || at.1 < y0 || at.1 > y1 {
            continue;
        }
        if frame.log && at.1 <= 0.0 {
            continue;
        }
        let anno = match m.shape {
            MarkerShape::Filled => {
                chart.draw_series(std::iter::once(Circle::new(at, size, BLACK.filled())))
            }
            MarkerShape::Open => chart.draw_series(std::iter::once(Circle::new(
                at,
                size,
                BLACK.stroke_width(width),
            ))),
            MarkerShape::Cross => chart.draw_series(std::iter::once(Cross::new(
                at,
                size,
                BLACK.stroke_width(width),
            ))),
            _ => chart.draw_series(std::iter::once(TriangleMarker::new(
                at,
                triangle,
                red.filled(),
            ))),
        }
        .map_err(|e| anyhow!("{e}"))?;
        if labelled.contains(&m.label.as_str()) {
            continue;
        }
        labelled.push(&m.label);
        let anno = anno.label(m.label.clone());
        match m.shape {
            MarkerShape::Filled => {
                anno.legend(move |(x, y)| Circle::new((x + legend_x, y), size, BLACK.filled()));
            }
            MarkerShape::Open => {
                anno.legend(move |(x, y)| {
                    Circle::new((x + legend_x, y), size, BLACK.stroke_width(width))
                });
            }
            MarkerShape::Cross => {
                anno.legend(move |(x, y)| {
                    Cross::new((x + legend_x, y), size, BLACK.stroke_width(width))
                });
            }
            _ => {
                anno.legend(move |(x, y)| {
                    TriangleMarker::new((x + legend_x, y), triangle, red.filled())
                });
            }
        }
    }
    Ok(labelled)
}

#[cfg(test)]
mod tests {
    use mechkit::figure::{ColourScale, LineStyle, PlotData, Scale, Series};

    use super::super::style::Style;
    use super::super::svg_text;
    use crate::args::PlotStyle;

    fn texts(svg: &str) -> Vec<&str> {
        svg.split("<text ")
            .skip(1)
            .filter_map(|t| t.split_once(">\n").map(|(_, rest)| rest))
            .filter_map(|t| t.split_once("\n</text>").map(|(text, _)| text))
            .collect()
    }

    #[test]
    fn a_log_axis_cuts_curves_at_zero_and_negative_values_and_labels_decades() {
        // an error that starts at exactly zero, dips below zero, and spans six decades
        let error = vec![
            (0.0, 0.0),
            (1.0, 1e-9),
            (1.5, 1e-8),
            (2.0, 1e-6),
            (3.0, -1.0),
            (4.0, 1e-4),
            (4.5, 3e-4),
            (5.0, 1e-3),
            (6.0, f64::NAN),
        ];
        let plot = PlotData::new("e(t)", "e_t", "t [s]", "error [m]")
            .with_y_scale(Scale::Log)
            .with_series(Series::line("euler", error))
            .with_series(
                Series::line("dashed", vec![(0.0, 1e-7), (6.0, 1e-5)]).styled(LineStyle::Dashed),
            )
            .with_series(Series::line("zero", vec![(0.0, 0.0), (1.0, 0.0)]));
        for style in [PlotStyle::Paper, PlotStyle::Slides] {
            let svg = svg_text(&plot, "t", Style::new(style)).unwrap();
            let text = texts(&svg);
            for decade in ["1e-9", "1e-6", "1e-3"] {
                assert!(text.contains(&decade), "{decade}: {text:?}");
            }
            // the curve is cut where it is not positive: two pieces of three points (1e-9
            // to 1e-6, and 1e-4 to 1e-3; the legend's line has two)
            let solid = svg
                .lines()
                .filter(|l| l.starts_with("<polyline") && l.contains("#1F77B4"))
                .filter(|l| l.split("points=\"").nth(1).unwrap().split(' ').count() > 3)
                .count();
            assert_eq!(solid, 2, "{style:?}");
            assert!(!svg.contains("NaN") && !svg.contains("inf"));
        }
        // nothing positive at all: an empty log axis, no panic
        let empty = PlotData::new("e(t)", "e_t", "t", "e")
            .with_y_scale(Scale::Log)
            .with_series(Series::line("zero", vec![(0.0, 0.0), (1.0, -1.0)]));
        assert!(svg_text(&empty, "t", Style::new(PlotStyle::Paper)).is_ok());
    }

    #[test]
    fn valued_curves_take_the_map_s_colours_and_the_bar_replaces_their_legend() {
        let mut plot =
            PlotData::new("v(x)", "v_x", "x [m]", "v [m/s]").with_colour_scale(ColourScale {
                label: "v0 [m/s]".into(),
                from: 0.0,
                to: 1.0,
            });
        for k in 0..=10 {
            let v = f64::from(k) / 10.0;
            plot = plot.with_series(
                Series::line(format!("v0 = {v}"), vec![(0.0, v), (1.0, 2.0 * v)]).valued(v),
            );
        }
        let svg = svg_text(&plot, "t", Style::new(PlotStyle::Paper)).unwrap();
        let text = texts(&svg);
        assert!(text.contains(&"v0 [m/s]"), "{text:?}");
        assert!(!text.iter().any(|t| t.starts_with("v0 = ")), "{text:?}");
        // the ends of the map
        assert!(svg.contains("stroke=\"#440154\""));
        assert!(svg.contains("stroke=\"#FDE725\""));
    }
}

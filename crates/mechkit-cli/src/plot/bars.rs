//! Bar charts (the energy ledger's waterfall): one bar per label along the horizontal axis,
//! totals in blue, gains in green, losses in red, each with its value, and a thin line carrying
//! the running total from one bar to the next.

use anyhow::{Result, anyhow};
use mechkit::figure::{BarKind, PlotData};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::chart::{draw_mesh, titled_area};
use super::style::Style;
use super::{PALETTE, drawable, tick};

const GAIN: RGBColor = RGBColor(44, 160, 44);
const LOSS: RGBColor = RGBColor(214, 39, 40);

/// Draws the bars of `plot` into `root`.
pub(super) fn draw<DB: DrawingBackend>(
    root: &DrawingArea<DB, plotters::coord::Shift>,
    plot: &PlotData,
    title: &str,
    style: Style,
) -> Result<()>
where
    DB::ErrorType: 'static,
{
    let bars = &plot.bars;
    let n = bars.len();
    // from zero (or the lowest bar) to the highest bar, with room for the values written
    // above and below the bars
    let (lo, hi) = bars
        .iter()
        .flat_map(|b| [b.from, b.to])
        .filter(|v| v.is_finite())
        .fold((0.0, 0.0), |(lo, hi): (f64, f64), v| (lo.min(v), hi.max(v)));
    let pad = if hi > lo { 0.08 * (hi - lo) } else { 1.0 };
    let (y0, y1) = drawable((if lo < 0.0 { lo - pad } else { 0.0 }, hi + pad));
    let scale = y0.abs().max(y1.abs());
    let labels: Vec<String> = bars.iter().map(|b| b.label.clone()).collect();
    let area = titled_area(root, plot, title, style)?;
    let (x_area, y_area) = style.label_areas();
    let mut chart = ChartBuilder::on(&area)
        .x_label_area_size(x_area)
        .y_label_area_size(y_area)
        .margin_right(style.px(8.0))
        .build_cartesian_2d((0..n.saturating_sub(1)).into_segmented(), y0..y1)
        .map_err(|e| anyhow!("{e}"))?;
    let x_fmt = |v: &SegmentValue<usize>| match v {
        SegmentValue::CenterOf(i) => labels.get(*i).cloned().unwrap_or_default(),
        _ => String::new(),
    };
    let y_fmt = |v: &f64| tick(*v, scale);
    let mut mesh = chart.configure_mesh();
    mesh.disable_x_mesh()
        .x_labels(n + 1)
        .x_label_formatter(&x_fmt)
        .y_labels(style.labels())
        .y_label_formatter(&y_fmt);
    draw_mesh(&mut mesh, plot, style)?;
    if y0 < 0.0 {
        chart
            .draw_series(std::iter::once(PathElement::new(
                vec![(SegmentValue::Exact(0), 0.0), (SegmentValue::Exact(n), 0.0)],
                BLACK.stroke_width(style.frame(1.0)),
            )))
            .map_err(|e| anyhow!("{e}"))?;
    }
    // the running total, carried from the top of each bar to the next bar
    let level = |i: usize| bars[i].to;
    chart
        .draw_series((0..n.saturating_sub(1)).map(|i| {
            PathElement::new(
                vec![
                    (SegmentValue::CenterOf(i), level(i)),
                    (SegmentValue::CenterOf(i + 1), level(i)),
                ],
                RGBColor(120, 120, 120).stroke_width(style.frame(1.0)),
            )
        }))
        .map_err(|e| anyhow!("{e}"))?;
    chart
        .draw_series(bars.iter().enumerate().map(|(i, b)| {
            let color = match b.kind {
                BarKind::Change if b.to < b.from => LOSS,
                BarKind::Change => GAIN,
                _ => PALETTE[0],
            };
            let mut r = Rectangle::new(
                [
                    (SegmentValue::Exact(i), b.from),
                    (SegmentValue::Exact(i + 1), b.to),
                ],
                color.mix(0.85).filled(),
            );
            let side = style.px(14.0) as u32;
            r.set_margin(0, 0, side, side);
            r
        }))
        .map_err(|e| anyhow!("{e}"))?;
    let above =
        TextStyle::from(style.label().into_font()).pos(Pos::new(HPos::Center, VPos::Bottom));
    let below = above.pos(Pos::new(HPos::Center, VPos::Top));
    let gap = style.px(4.0);
    // the height of a value's line in the chart's units: a loss that ends closer than that
    // to the bottom has its value written above it, clear of the labels under the axis
    let (_, h) = chart.plotting_area().dim_in_pixel();
    let line = (style.label().1 * 1.2 + f64::from(gap)) * (y1 - y0) / f64::from(h.max(1));
    chart
        .draw_series(bars.iter().enumerate().map(|(i, b)| {
            let value = b.to - b.from;
            let sign = if b.kind == BarKind::Change && value >= 0.0 {
                "+"
            } else {
                ""
            };
            let text = format!("{sign}{} J", significant(value));
            // written a few pixels beyond the end the bar grows toward
            let (y, font, dy) = if b.to >= b.from {
                (b.to, above.clone(), -gap)
            } else if b.to - y0 >= line {
                (b.to, below.clone(), gap)
            } else {
                (b.from, above.clone(), -gap)
            };
            EmptyElement::at((SegmentValue::CenterOf(i), y)) + Text::new(text, (0, dy), font)
        }))
        .map_err(|e| anyhow!("{e}"))?;
    Ok(())
}

/// `v` to four significant digits: `-22.48`, `100`, `0.001235`, `1.235e8`.
fn significant(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let magnitude = v.abs().log10().floor();
    if !(-4.0..8.0).contains(&magnitude) {
        return format!("{v:.3e}");
    }
    let decimals = (3.0 - magnitude).max(0.0) as usize;
    let s = format!("{v:.decimals$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

#[cfg(test)]
mod tests {
    use super::significant;

    #[test]
    fn values_keep_four_significant_digits() {
        assert_eq!(significant(-22.482_017), "-22.48");
        assert_eq!(significant(100.0), "100");
        assert_eq!(significant(15.887_988), "15.89");
        assert_eq!(significant(0.001_234_6), "0.001235");
        assert_eq!(significant(123_456.7), "123457");
        assert_eq!(significant(1.5e9), "1.500e9");
        assert_eq!(significant(0.0), "0");
    }
}

//! The frame every chart shares, the curves' and the bars': the area inside the margins under
//! the title, and the mesh (axis descriptions, type, frame, grid and tick marks in the style's
//! sizes).

use anyhow::{Result, anyhow};
use mechkit::figure::PlotData;
use plotters::chart::MeshStyle;
use plotters::coord::Shift;
use plotters::coord::ranged1d::ValueFormatter;
use plotters::prelude::*;

use crate::plot::GRID;
use crate::plot::style::Style;
use crate::plot::title::titled;

/// The area of `root` inside its margins, under the title `title: spec` (a chart of curves or
/// of bars).
pub(in crate::plot) fn titled_area<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    plot: &PlotData,
    title: &str,
    style: Style,
) -> Result<DrawingArea<DB, Shift>>
where
    DB::ErrorType: 'static,
{
    let m = style.px(16.0);
    titled(
        &root.margin(m, m, m, m),
        &format!("{title}: {}", plot.spec),
        style,
    )
}

/// Draws `mesh`, its labels set, in the look every chart shares (curves and bars): the axis
/// descriptions of `plot`, and the type, frame, grid and tick marks of `style`.
pub(in crate::plot) fn draw_mesh<X, Y, DB>(
    mesh: &mut MeshStyle<'_, '_, X, Y, DB>,
    plot: &PlotData,
    style: Style,
) -> Result<()>
where
    X: Ranged + ValueFormatter<<X as Ranged>::ValueType>,
    Y: Ranged + ValueFormatter<<Y as Ranged>::ValueType>,
    DB: DrawingBackend,
    DB::ErrorType: 'static,
{
    mesh.x_desc(&plot.x_label)
        .y_desc(&plot.y_label)
        .label_style(style.label())
        .axis_desc_style(style.axis_desc())
        .axis_style(BLACK.stroke_width(style.frame(1.0)))
        .bold_line_style(BLACK.mix(0.2).stroke_width(style.frame(1.0)))
        .light_line_style(GRID.stroke_width(style.frame(1.0)))
        .set_all_tick_mark_size(style.px(5.0))
        .draw()
        .map_err(|e| anyhow!("{e}"))
}

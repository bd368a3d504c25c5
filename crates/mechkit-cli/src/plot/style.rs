//! The sizes of a plot's type, lines and markers, for paper or for slides, on the drawing
//! canvas.
//!
//! plotters draws in whole pixels, so a slow curve drawn at the plot's own 900x600 pixels
//! shows steps. Plots are drawn on a canvas [`CANVAS`] times larger, every length scaled with
//! it, and the SVG is written back at 900x600 with fractional coordinates
//! ([`super::svg::rescale`]): a resolution of 1/[`CANVAS`] pixel.

use crate::args::PlotStyle;

/// How many times larger than the plot the canvas is.
pub(super) const CANVAS: u32 = 4;

/// The size of every plot in SVG pixels (at 96 dpi).
pub(super) const SIZE: (u32, u32) = (900, 600);

/// The family the bundled font is registered under.
pub(super) const FONT_FAMILY: &str = "sans-serif";

/// Sizes on the canvas for one style. Lengths are given in the plot's own pixels (paper) and
/// come out in canvas pixels.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Style {
    /// Factor on type and on the room kept for it.
    text: f64,
    /// Factor on the curves' strokes.
    line: f64,
    /// Factor on the axes', the grid's and the frames' strokes.
    frame: f64,
    /// Factor on markers.
    mark: f64,
}

impl Style {
    /// The sizes of `style`.
    pub(super) fn new(style: PlotStyle) -> Self {
        match style {
            PlotStyle::Paper => Self {
                text: 1.0,
                line: 1.0,
                frame: 1.0,
                mark: 1.0,
            },
            PlotStyle::Slides => Self {
                text: 1.6,
                line: 1.75,
                frame: 1.5,
                mark: 1.6,
            },
        }
    }

    /// The canvas size (the same in every style).
    #[allow(clippy::unused_self)]
    pub(super) fn canvas(self) -> (u32, u32) {
        (SIZE.0 * CANVAS, SIZE.1 * CANVAS)
    }

    /// A length of `px` plot pixels that does not depend on the style (a margin).
    #[allow(clippy::unused_self)]
    pub(super) fn px(self, px: f64) -> i32 {
        (px * f64::from(CANVAS)).round() as i32
    }

    /// A length of `px` plot pixels on paper that holds text, so grows with the type.
    pub(super) fn text_px(self, px: f64) -> i32 {
        self.px(px * self.text)
    }

    /// A font of `size` plot pixels on paper, in the bundled family.
    pub(super) fn font(self, size: f64) -> (&'static str, f64) {
        (FONT_FAMILY, size * self.text * f64::from(CANVAS))
    }

    /// The title's font.
    pub(super) fn caption(self) -> (&'static str, f64) {
        self.font(22.0)
    }

    /// The font of tick labels, legends and values.
    pub(super) fn label(self) -> (&'static str, f64) {
        self.font(14.0)
    }

    /// The font of axis labels.
    pub(super) fn axis_desc(self) -> (&'static str, f64) {
        self.font(16.0)
    }

    /// A curve's stroke of `w` plot pixels on paper.
    pub(super) fn line(self, w: f64) -> u32 {
        (w * self.line * f64::from(CANVAS)).round() as u32
    }

    /// A length along a curve (a dash) of `px` plot pixels on paper.
    pub(super) fn dash(self, px: f64) -> u32 {
        self.line(px)
    }

    /// An axis', the grid's or a frame's stroke of `w` plot pixels on paper.
    pub(super) fn frame(self, w: f64) -> u32 {
        (w * self.frame * f64::from(CANVAS)).round() as u32
    }

    /// A marker's size (radius) of `r` plot pixels on paper.
    pub(super) fn mark(self, r: f64) -> i32 {
        (r * self.mark * f64::from(CANVAS)).round() as i32
    }

    /// The heights of the label area under the plot and the width of the one left of it,
    /// which hold the tick labels and the axis labels.
    pub(super) fn label_areas(self) -> (i32, i32) {
        (
            self.px(16.0) + self.text_px(32.0),
            self.px(30.0) + self.text_px(50.0),
        )
    }

    /// How many tick labels an axis has at most.
    pub(super) fn labels(self) -> usize {
        (11.0 / self.text.sqrt()).round() as usize
    }

    /// The factor on type (legend and layout estimates).
    pub(super) fn text_factor(self) -> f64 {
        self.text
    }
}

#[cfg(test)]
mod tests {
    use super::{CANVAS, Style};
    use crate::args::PlotStyle;

    #[test]
    fn slides_have_larger_type_and_thicker_lines_on_the_same_canvas() {
        let (paper, slides) = (Style::new(PlotStyle::Paper), Style::new(PlotStyle::Slides));
        assert_eq!(paper.canvas(), slides.canvas());
        assert_eq!(paper.canvas(), (900 * CANVAS, 600 * CANVAS));
        assert!(slides.label().1 >= 1.5 * paper.label().1);
        assert!(slides.line(2.0) > paper.line(2.0));
        assert!(slides.mark(3.0) > paper.mark(3.0));
        // a margin is the same in both
        assert_eq!(paper.px(16.0), slides.px(16.0));
        assert_eq!(paper.px(16.0), 64);
    }
}

//! Where everything goes on a picture, in pixels (y down): the scene and the map of the view
//! onto it, the header's time stamp and title, the footer's scale bar and the energy panel
//! (`panel.rs`).
//! Computed once here for the SVG and, as JSON, for the HTML player's canvas.
//!
//! The view maps to the largest rectangle of its shape inside the scene, centred: a world
//! point `(x, y)` is at `(left + (x - x_min) s, bottom - (y - y_min) s)` with `s` the pixels
//! per length unit.

use mechkit::animation::{Animation, Colour, View};
use serde::Serialize;

use super::canvas::Canvas;
use super::panel::{Panel, panel};

/// The colour of text.
pub(super) const INK: Colour = Colour(0x22, 0x22, 0x22);
/// The colour of the title and the panel's heading.
pub(super) const FAINT_INK: Colour = Colour(0x55, 0x55, 0x55);
/// The colour of the panel's axis and zero line.
const AXIS: Colour = Colour(0x88, 0x88, 0x88);
/// The colour of the energy bars' tracks and of the panel's separator.
const TRACK: Colour = Colour(0xee, 0xee, 0xee);

/// A trail's line width, in pixels.
const TRAIL_WIDTH: f64 = 1.5;
/// A trail's opacity.
const TRAIL_OPACITY: f64 = 0.7;

/// Pixel coordinates are kept within this distance of the picture: a body far off screen
/// still draws as a line leaving it.
const FAR: f64 = 1e6;

/// The layout of an animation's pictures on a canvas.
#[derive(Debug, Clone, Serialize)]
pub(super) struct Layout {
    /// The picture's width and height.
    pub size: [f64; 2],
    /// The scene: what the shapes are clipped to.
    pub scene: Rect,
    /// The map from the world to the scene.
    pub map: Map,
    /// Where the time stamp starts (its text is the frame's).
    pub time: Text,
    /// The title, shortened to fit.
    pub title: Text,
    /// The scale bar, unless the scale is not a number.
    pub scale_bar: Option<ScaleBar>,
    /// The energy bars' panel, when the animation has energies.
    pub panel: Option<Panel>,
    /// A trail's line width, in pixels.
    pub trail_width: f64,
    /// A trail's opacity.
    pub trail_opacity: f64,
    /// The colour of the scale's and the panel's lines.
    pub axis: Colour,
    /// The colour of the energy bars' tracks and of the panel's separator.
    pub track: Colour,
}

/// A rectangle of pixels.
#[derive(Debug, Clone, Copy, Serialize)]
pub(super) struct Rect {
    pub x0: f64,
    pub y0: f64,
    pub x1: f64,
    pub y1: f64,
}

/// The map from world coordinates to pixels.
#[derive(Debug, Clone, Copy, Serialize)]
pub(super) struct Map {
    pub x_min: f64,
    pub y_min: f64,
    /// The pixel column of `x_min`.
    pub left: f64,
    /// The pixel row of `y_min`.
    pub bottom: f64,
    /// Pixels per length unit.
    pub scale: f64,
}

impl Map {
    /// The pixel of the world point `p`, kept within [`FAR`] of the picture.
    pub fn px(&self, p: [f64; 2]) -> (f64, f64) {
        let x = self.left + (p[0] - self.x_min) * self.scale;
        let y = self.bottom - (p[1] - self.y_min) * self.scale;
        (x.clamp(-FAR, FAR), y.clamp(-FAR, FAR))
    }
}

/// A line of text: its anchor point (on the baseline), size in pixels, alignment, colour.
#[derive(Debug, Clone, Serialize)]
pub(super) struct Text {
    pub x: f64,
    pub y: f64,
    pub size: f64,
    pub align: Align,
    pub colour: Colour,
    pub content: String,
}

/// Which point of a text its anchor is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub(super) enum Align {
    Left,
    Center,
    Right,
}

impl Align {
    /// SVG's name for it (`text-anchor`).
    pub fn svg(self) -> &'static str {
        match self {
            Self::Left => "start",
            Self::Center => "middle",
            Self::Right => "end",
        }
    }
}

/// A scale bar: a horizontal line from `x0` to `x1` at `y` with end ticks `tick` high, its
/// lines `width` pixels wide in `colour`.
#[derive(Debug, Clone, Serialize)]
pub(super) struct ScaleBar {
    pub x0: f64,
    pub x1: f64,
    pub y: f64,
    pub tick: f64,
    pub width: f64,
    pub colour: Colour,
    pub label: Text,
}

impl Layout {
    /// The layout of `anim`'s pictures on `canvas`.
    pub fn new(anim: &Animation, canvas: Canvas) -> Self {
        let (width, height) = (f64::from(canvas.width), f64::from(canvas.height));
        // text size: 12 px on the default 640x480
        let f = (width.min(height) / 40.0).clamp(9.0, 40.0);
        let band = 2.2 * f;
        let panel_width = if anim.energy.is_some() {
            (width / 4.0).round()
        } else {
            0.0
        };
        let scene = Rect {
            x0: 0.0,
            y0: band,
            x1: width - panel_width,
            y1: height - band,
        };
        let map = map(anim.view, scene);
        let time = text(0.6 * f, 1.5 * f, f, Align::Left, INK, "");
        // room for a time stamp of 12 characters on each side of the centred title
        let room = (scene.x1 - scene.x0) - 2.0 * 8.0 * f;
        let title = text(
            scene.x0.midpoint(scene.x1),
            1.5 * f,
            0.85 * f,
            Align::Center,
            FAINT_INK,
            &shortened(&anim.title, room / (0.55 * 0.85 * f)),
        );
        let scale_bar = scale_bar(map.scale, &anim.length_unit, scene, height, f);
        let panel = anim
            .energy
            .as_ref()
            .map(|bars| panel(bars, scene, width, f));
        Self {
            size: [width, height],
            scene,
            map,
            time,
            title,
            scale_bar,
            panel,
            trail_width: TRAIL_WIDTH,
            trail_opacity: TRAIL_OPACITY,
            axis: AXIS,
            track: TRACK,
        }
    }
}

pub(super) fn text(x: f64, y: f64, size: f64, align: Align, colour: Colour, text: &str) -> Text {
    Text {
        x,
        y,
        size,
        align,
        colour,
        content: text.to_string(),
    }
}

/// The map of `view` (widened to one unit where it has no size) onto the middle of `scene`.
fn map(view: View, scene: Rect) -> Map {
    let (x_min, x_max) = span(view.x_min, view.x_max);
    let (y_min, y_max) = span(view.y_min, view.y_max);
    let (w, h) = (scene.x1 - scene.x0, scene.y1 - scene.y0);
    let scale = (w / (x_max - x_min)).min(h / (y_max - y_min));
    Map {
        x_min,
        y_min,
        left: scene.x0 + (w - (x_max - x_min) * scale) / 2.0,
        bottom: scene.y1 - (h - (y_max - y_min) * scale) / 2.0,
        scale,
    }
}

/// The interval from `lo` to `hi`, or one unit about its middle when it is empty (or too
/// small to divide by), reversed or not finite.
fn span(lo: f64, hi: f64) -> (f64, f64) {
    let size = hi - lo;
    if size.is_finite() && size > 1e-250 {
        return (lo, hi);
    }
    let middle = [lo.midpoint(hi), lo, hi]
        .into_iter()
        .find(|m| m.is_finite())
        .unwrap_or(0.0);
    (middle - 0.5, middle + 0.5)
}

/// `title` cut to at most `room` characters, ending in `…` when it is cut.
fn shortened(title: &str, room: f64) -> String {
    let room = if room.is_finite() {
        room.max(0.0) as usize
    } else {
        0
    };
    if title.chars().count() <= room {
        title.to_string()
    } else if room < 2 {
        String::new()
    } else {
        let mut s: String = title.chars().take(room - 1).collect();
        s.push('…');
        s
    }
}

/// A bar of a round length (1, 2 or 5 times a power of ten) at most 30 % of the scene's width
/// at the bottom left, labelled with the length and `unit`.
fn scale_bar(scale: f64, unit: &str, scene: Rect, height: f64, f: f64) -> Option<ScaleBar> {
    let most = 0.3 * (scene.x1 - scene.x0) / scale;
    if !(most.is_finite() && most > 0.0) {
        return None;
    }
    let (mantissa, exponent) = round_length(most);
    let length = f64::from(mantissa) * 10f64.powi(exponent);
    let (x0, y) = (0.6 * f, height - 0.9 * f);
    let x1 = x0 + length * scale;
    let label = format!("{} {unit}", length_label(mantissa, exponent));
    Some(ScaleBar {
        x0,
        x1,
        y,
        tick: 0.35 * f,
        width: 1.5,
        colour: INK,
        label: text(
            x1 + 0.4 * f,
            y + 0.3 * f,
            0.85 * f,
            Align::Left,
            INK,
            label.trim_end(),
        ),
    })
}

/// The largest `m · 10^e` with `m` 1, 2 or 5 that is at most `most` (positive and finite).
fn round_length(most: f64) -> (u32, i32) {
    let exponent = most.log10().floor() as i32;
    let leading = most / 10f64.powi(exponent);
    // `leading` is in [1, 10), give or take the rounding of the power
    match leading {
        l if l >= 5.0 => (5, exponent),
        l if l >= 2.0 => (2, exponent),
        l if l >= 1.0 => (1, exponent),
        _ => (5, exponent - 1),
    }
}

/// `m · 10^e` written out: `500`, `0.02`, `1e-9`.
fn length_label(mantissa: u32, exponent: i32) -> String {
    match exponent {
        0..=5 => format!("{}", u64::from(mantissa) * 10u64.pow(exponent as u32)),
        -5..=-1 => format!("0.{}{mantissa}", "0".repeat((-exponent - 1) as usize)),
        _ => format!("{mantissa}e{exponent}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_lengths_are_one_two_or_five_times_a_power_of_ten() {
        assert_eq!(round_length(0.7), (5, -1));
        assert_eq!(round_length(1.0), (1, 0));
        assert_eq!(round_length(3.9), (2, 0));
        assert_eq!(round_length(99.0), (5, 1));
        assert_eq!(length_label(5, -1), "0.5");
        assert_eq!(length_label(2, -3), "0.002");
        assert_eq!(length_label(1, 0), "1");
        assert_eq!(length_label(5, 2), "500");
        assert_eq!(length_label(1, -9), "1e-9");
    }

    #[test]
    fn empty_or_broken_views_are_one_unit_wide() {
        assert_eq!(span(2.0, 2.0), (1.5, 2.5));
        assert_eq!(span(3.0, 1.0), (1.5, 2.5));
        assert_eq!(span(f64::NAN, 4.0), (3.5, 4.5));
        assert_eq!(span(f64::NAN, f64::INFINITY), (-0.5, 0.5));
        assert_eq!(span(-1.0, 1.0), (-1.0, 1.0));
    }

    #[test]
    fn the_view_is_centred_to_scale() {
        let scene = Rect {
            x0: 0.0,
            y0: 20.0,
            x1: 400.0,
            y1: 220.0,
        };
        let view = View {
            x_min: -1.0,
            x_max: 1.0,
            y_min: -1.0,
            y_max: 1.0,
        };
        let m = map(view, scene);
        assert_eq!(m.scale, 100.0);
        assert_eq!(m.px([0.0, 0.0]), (200.0, 120.0));
        assert_eq!(m.px([1.0, 1.0]), (300.0, 20.0), "y up");
    }

    #[test]
    fn titles_are_shortened_to_fit() {
        assert_eq!(shortened("abcdef", 4.0), "abc…");
        assert_eq!(shortened("abc", 4.0), "abc");
        assert_eq!(shortened("abc", f64::NAN), "");
    }
}

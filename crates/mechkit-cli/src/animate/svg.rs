//! One frame as SVG, the reference drawing: a white picture; in the scene (clipped to it) the
//! background shapes, the trails up to the frame, the frame's shapes; the time stamp and the
//! title above, the scale bar below; the energy bars on the right.

use std::fmt::Write as _;

use mechkit::animation::{Animation, Colour, Frame, Geometry, Shape};

use super::canvas::Canvas;
use super::layout::{Layout, Text};
use super::panel::Panel;

/// Frame `frame` of `anim` as the SVG text of a `canvas`-sized picture (a canvas outside
/// [`Canvas::SIDES`] is brought within it). A frame past the last draws the last; an
/// animation with no frames draws its background, without a time stamp.
pub fn frame_svg(anim: &Animation, frame: usize, canvas: Canvas) -> String {
    let layout = Layout::new(anim, canvas.clamped());
    let index = frame.min(anim.frames.len().saturating_sub(1));
    let frame = anim.frames.get(index);
    let [w, h] = layout.size;
    let mut svg = String::with_capacity(8192);
    let _ = write!(
        svg,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" \
         viewBox=\"0 0 {w} {h}\" font-family=\"DejaVu Sans, sans-serif\">\n\
         <rect width=\"{w}\" height=\"{h}\" fill=\"#ffffff\"/>\n"
    );
    scene(&mut svg, anim, frame.map(|f| (index, f)), &layout);
    if let Some(frame) = frame {
        let mut time = layout.time.clone();
        time.content = time_stamp(frame.t);
        push_text(&mut svg, &time);
    }
    push_text(&mut svg, &layout.title);
    if let Some(bar) = &layout.scale_bar {
        let (x0, x1, y, t) = (n(bar.x0), n(bar.x1), n(bar.y), n(bar.y - bar.tick));
        let _ = writeln!(
            svg,
            "<polyline points=\"{x0},{t} {x0},{y} {x1},{y} {x1},{t}\" fill=\"none\" \
             stroke=\"{}\" stroke-width=\"{}\"/>",
            bar.colour.hex(),
            n(bar.width)
        );
        push_text(&mut svg, &bar.label);
    }
    if let Some(panel) = &layout.panel {
        energy(&mut svg, panel, &layout, frame.map_or(&[], |f| &f.energy));
    }
    svg.push_str("</svg>\n");
    svg
}

/// The scene, clipped to its rectangle: background, trails to frame `index`, the frame.
fn scene(svg: &mut String, anim: &Animation, frame: Option<(usize, &Frame)>, layout: &Layout) {
    let r = layout.scene;
    let _ = write!(
        svg,
        "<clipPath id=\"scene\"><rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"/></clipPath>\n\
         <g clip-path=\"url(#scene)\">\n",
        n(r.x0),
        n(r.y0),
        n(r.x1 - r.x0),
        n(r.y1 - r.y0)
    );
    for shape in &anim.background {
        push_shape(svg, shape, layout);
    }
    if let Some((index, frame)) = frame {
        for trail in &anim.trails {
            let end = (index + 1).min(trail.points.len());
            push_trail(svg, &trail.points[..end], trail.colour, layout);
        }
        for shape in &frame.shapes {
            push_shape(svg, shape, layout);
        }
    }
    svg.push_str("</g>\n");
}

/// A trail's points as lines, broken where a point is not finite.
fn push_trail(svg: &mut String, points: &[[f64; 2]], colour: Colour, layout: &Layout) {
    for run in points.split(|p| !(p[0].is_finite() && p[1].is_finite())) {
        if run.len() < 2 {
            continue;
        }
        let _ = write!(
            svg,
            "<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"{}\" stroke-opacity=\"{}\" \
             stroke-linejoin=\"round\" points=\"",
            colour.hex(),
            n(layout.trail_width),
            n(layout.trail_opacity)
        );
        push_points(svg, run, layout);
        svg.push_str("\"/>\n");
    }
}

/// A shape, unless one of its numbers is not finite or its radius is negative.
fn push_shape(svg: &mut String, shape: &Shape, layout: &Layout) {
    if !drawable(shape) {
        return;
    }
    let map = &layout.map;
    match &shape.geometry {
        Geometry::Circle { centre, .. } | Geometry::Dot { centre, .. } => {
            let (x, y) = map.px(*centre);
            let r = match shape.geometry {
                Geometry::Circle { radius, .. } => radius * map.scale,
                Geometry::Dot { radius_px, .. } => radius_px,
                _ => 0.0,
            }
            .min(1e6);
            let _ = write!(
                svg,
                "<circle cx=\"{}\" cy=\"{}\" r=\"{}\"",
                n(x),
                n(y),
                n(r)
            );
        }
        Geometry::Polygon { points } | Geometry::Polyline { points } => {
            let tag = match shape.geometry {
                Geometry::Polygon { .. } => "polygon",
                _ => "polyline",
            };
            let _ = write!(svg, "<{tag} stroke-linejoin=\"round\" points=\"");
            push_points(svg, points, layout);
            svg.push('"');
        }
    }
    let _ = write!(svg, " fill=\"{}\"", paint(shape.fill));
    if let Some(stroke) = shape.stroke {
        let width = shape.line_width.clamp(0.0, 1e3);
        let _ = write!(
            svg,
            " stroke=\"{}\" stroke-width=\"{}\" stroke-linecap=\"round\"",
            stroke.hex(),
            n(width)
        );
    }
    svg.push_str("/>\n");
}

/// Whether every number of `shape` is finite and its radius, if any, not negative: what the
/// SVG and the HTML player draw.
pub(super) fn drawable(shape: &Shape) -> bool {
    let finite = |p: &[f64; 2]| p[0].is_finite() && p[1].is_finite();
    let geometry = match &shape.geometry {
        Geometry::Circle { centre, radius } => {
            finite(centre) && radius.is_finite() && *radius >= 0.0
        }
        Geometry::Dot { centre, radius_px } => {
            finite(centre) && radius_px.is_finite() && *radius_px >= 0.0
        }
        Geometry::Polygon { points } | Geometry::Polyline { points } => {
            !points.is_empty() && points.iter().all(finite)
        }
    };
    geometry && shape.line_width.is_finite()
}

fn push_points(svg: &mut String, points: &[[f64; 2]], layout: &Layout) {
    for (i, p) in points.iter().enumerate() {
        let (x, y) = layout.map.px(*p);
        let sep = if i == 0 { "" } else { " " };
        let _ = write!(svg, "{sep}{},{}", n(x), n(y));
    }
}

fn paint(colour: Option<Colour>) -> String {
    colour.map_or_else(|| "none".into(), Colour::hex)
}

/// The energy panel: the separator, the axis and its ticks, each bar's track, value and
/// label, the zero line, the heading.
fn energy(svg: &mut String, panel: &Panel, layout: &Layout, values: &[f64]) {
    let (top, bottom, zero) = (n(panel.top), n(panel.bottom), panel.y(0.0));
    let _ = writeln!(
        svg,
        "<line x1=\"{x}\" y1=\"0\" x2=\"{x}\" y2=\"100%\" stroke=\"{}\" stroke-width=\"1\"/>",
        layout.track.hex(),
        x = n(panel.separator)
    );
    push_text(svg, &panel.heading);
    for (i, bar) in panel.bars.iter().enumerate() {
        let (x, width) = (n(bar.x0), n(bar.x1 - bar.x0));
        let _ = writeln!(
            svg,
            "<rect x=\"{x}\" y=\"{top}\" width=\"{width}\" height=\"{}\" fill=\"{}\"/>",
            n(panel.bottom - panel.top),
            layout.track.hex()
        );
        if let Some(v) = values.get(i).filter(|v| v.is_finite()) {
            let y = panel.y(*v);
            let _ = writeln!(
                svg,
                "<rect x=\"{x}\" y=\"{}\" width=\"{width}\" height=\"{}\" fill=\"{}\"/>",
                n(y.min(zero)),
                n((y - zero).abs()),
                bar.colour.hex()
            );
        }
        push_text(svg, &bar.label);
    }
    let axis = layout.axis.hex();
    let _ = writeln!(
        svg,
        "<line x1=\"{a}\" y1=\"{top}\" x2=\"{a}\" y2=\"{bottom}\" stroke=\"{axis}\" stroke-width=\"1\"/>\n\
         <line x1=\"{a}\" y1=\"{z}\" x2=\"{r}\" y2=\"{z}\" stroke=\"{axis}\" stroke-width=\"1\"/>",
        a = n(panel.axis),
        z = n(zero),
        r = n(panel.right),
    );
    for tick in &panel.ticks {
        push_text(svg, tick);
    }
}

fn push_text(svg: &mut String, text: &Text) {
    if text.content.is_empty() {
        return;
    }
    let _ = writeln!(
        svg,
        "<text x=\"{}\" y=\"{}\" font-size=\"{}\" text-anchor=\"{}\" fill=\"{}\">{}</text>",
        n(text.x),
        n(text.y),
        n(text.size),
        text.align.svg(),
        text.colour.hex(),
        escape(&text.content)
    );
}

/// `t = 1.234 s`, or `t = ? s` when `t` is not finite (as the HTML player writes it).
fn time_stamp(t: f64) -> String {
    if t.is_finite() {
        format!("t = {} s", mechkit::expr::short_fixed(t, 3))
    } else {
        "t = ? s".into()
    }
}

/// `text` with the characters XML gives a meaning escaped, and those it forbids dropped
/// ([`crate::xml::escape`], the one XML escape).
pub(super) fn escape(text: &str) -> String {
    crate::xml::escape(text)
}

/// A pixel coordinate to two decimals, without trailing zeros: `12.25`, `640`.
fn n(v: f64) -> String {
    let s = format!("{v:.2}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" { "0".into() } else { s.to_string() }
}

#[cfg(test)]
mod tests {
    use super::{escape, n};

    #[test]
    fn numbers_are_short_and_text_is_escaped() {
        assert_eq!(n(12.250_01), "12.25");
        assert_eq!(n(640.0), "640");
        assert_eq!(n(-0.001), "0");
        assert_eq!(
            escape("a <b> & \"c\"\u{1}"),
            "a &lt;b&gt; &amp; &quot;c&quot;"
        );
    }
}

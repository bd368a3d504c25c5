//! The HTML player's data: the animation as compact JSON, numbers to six significant digits.
//!
//! ```text
//! {"fps": 25, "layout": {…},                      the layout of `layout.rs`
//!  "styles": [[fill, stroke, line_width], …],      colours "#rrggbb" or null
//!  "background": [shape, …],
//!  "frames": [[t, [shape, …], [energy, …]], …],
//!  "trails": [["#rrggbb", [x0, y0, x1, y1, …]], …]}
//! shape: [style, kind, numbers…]: kind 0 a circle (x, y, radius), 1 a dot (x, y, radius in
//! pixels), 2 a polygon and 3 a polyline (x0, y0, x1, y1, …)
//! ```
//!
//! A shape with a number that is not finite is left out; any other such number (a time, an
//! energy, a trail's point, where the trail then breaks) is `null`. The text is safe inside a
//! `<script>` element: `<`, `>`, `&` and `/` appear only escaped.

use std::collections::HashMap;
use std::fmt::Write as _;

use mechkit::animation::{Animation, Colour, Geometry, Shape};

use super::gif::DEFAULT_FPS;
use super::layout::Layout;
use super::svg::drawable;

/// A style's key: fill, stroke, the line width's bits.
type StyleKey = (Option<[u8; 3]>, Option<[u8; 3]>, u64);

/// The data of `anim`, drawn with `layout`, as JSON safe inside a `<script>` element.
pub(super) fn data(anim: &Animation, layout: &Layout) -> String {
    let mut styles = Styles::default();
    let mut out = String::with_capacity(1024 + 64 * anim.frames.len());
    let fps = if anim.fps.is_finite() && anim.fps > 0.0 {
        anim.fps
    } else {
        DEFAULT_FPS
    };
    out.push_str("{\"fps\":");
    push_number(&mut out, fps);
    out.push_str(",\"layout\":");
    out.push_str(&serde_json::to_string(layout).unwrap_or_else(|_| "null".into()));
    out.push_str(",\"background\":");
    push_shapes(&mut out, &anim.background, &mut styles);
    out.push_str(",\"frames\":[");
    for (i, frame) in anim.frames.iter().enumerate() {
        out.push_str(if i == 0 { "[" } else { ",[" });
        push_number(&mut out, frame.t);
        out.push(',');
        push_shapes(&mut out, &frame.shapes, &mut styles);
        out.push(',');
        push_numbers(&mut out, frame.energy.iter().copied());
        out.push(']');
    }
    out.push_str("],\"trails\":[");
    for (i, trail) in anim.trails.iter().enumerate() {
        let _ = write!(
            out,
            "{}[\"{}\",",
            if i == 0 { "" } else { "," },
            trail.colour.hex()
        );
        push_numbers(&mut out, trail.points.iter().flatten().copied());
        out.push(']');
    }
    out.push_str("],\"styles\":[");
    for (i, (fill, stroke, width)) in styles.list.iter().enumerate() {
        let _ = write!(
            out,
            "{}[{},{},",
            if i == 0 { "" } else { "," },
            colour(*fill),
            colour(*stroke)
        );
        push_number(&mut out, *width);
        out.push(']');
    }
    out.push_str("]}");
    script_safe(&out)
}

/// The styles met so far, each once.
#[derive(Default)]
struct Styles {
    index: HashMap<StyleKey, usize>,
    list: Vec<(Option<Colour>, Option<Colour>, f64)>,
}

impl Styles {
    /// The index of `shape`'s style, added if new.
    fn of(&mut self, shape: &Shape) -> usize {
        let rgb = |c: Option<Colour>| c.map(|Colour(r, g, b)| [r, g, b]);
        let width = shape.line_width.clamp(0.0, 1e3);
        let key = (rgb(shape.fill), rgb(shape.stroke), width.to_bits());
        *self.index.entry(key).or_insert_with(|| {
            self.list.push((shape.fill, shape.stroke, width));
            self.list.len() - 1
        })
    }
}

fn push_shapes(out: &mut String, shapes: &[Shape], styles: &mut Styles) {
    out.push('[');
    let mut first = true;
    for shape in shapes.iter().filter(|s| drawable(s)) {
        let _ = write!(out, "{}[{}", if first { "" } else { "," }, styles.of(shape));
        first = false;
        let (kind, numbers): (u8, Vec<f64>) = match &shape.geometry {
            Geometry::Circle { centre, radius } => (0, vec![centre[0], centre[1], *radius]),
            Geometry::Dot { centre, radius_px } => (1, vec![centre[0], centre[1], *radius_px]),
            Geometry::Polygon { points } => (2, points.iter().flatten().copied().collect()),
            Geometry::Polyline { points } => (3, points.iter().flatten().copied().collect()),
        };
        let _ = write!(out, ",{kind}");
        for v in numbers {
            out.push(',');
            push_number(out, v);
        }
        out.push(']');
    }
    out.push(']');
}

fn push_numbers(out: &mut String, values: impl Iterator<Item = f64>) {
    out.push('[');
    for (i, v) in values.enumerate() {
        if i > 0 {
            out.push(',');
        }
        push_number(out, v);
    }
    out.push(']');
}

/// `v` to six significant digits in its shortest form (`0.333333`, `1.5e-9`), `null` when it
/// is not finite.
fn push_number(out: &mut String, v: f64) {
    if !v.is_finite() {
        out.push_str("null");
        return;
    }
    let rounded = format!("{v:.5e}").parse::<f64>().unwrap_or(v);
    mechkit::csv::push_number(out, rounded);
}

fn colour(c: Option<Colour>) -> String {
    c.map_or_else(|| "null".into(), |c| format!("\"{}\"", c.hex()))
}

/// JSON text with `<`, `>`, `&` and `/` escaped (they occur only inside strings), so that it
/// can neither end a `<script>` element nor hold a web address as written.
fn script_safe(json: &str) -> String {
    let mut out = String::with_capacity(json.len());
    for c in json.chars() {
        match c {
            '<' => out.push_str("\\u003c"),
            '>' => out.push_str("\\u003e"),
            '&' => out.push_str("\\u0026"),
            '/' => out.push_str("\\/"),
            c => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::{push_number, script_safe};

    #[test]
    fn numbers_have_six_digits_and_strings_are_script_safe() {
        let mut out = String::new();
        for v in [1.0 / 3.0, 2.0, -1.5e-9, 1_234_567.0, f64::NAN] {
            push_number(&mut out, v);
            out.push(' ');
        }
        assert_eq!(out, "0.333333 2 -1.5e-9 1234570 null ");
        let safe = script_safe("{\"title\":\"</script> & https://x\"}");
        assert_eq!(
            safe,
            "{\"title\":\"\\u003c\\/script\\u003e \\u0026 https:\\/\\/x\"}"
        );
        let back: serde_json::Value = serde_json::from_str(&safe).unwrap();
        assert_eq!(back["title"], "</script> & https://x");
    }
}

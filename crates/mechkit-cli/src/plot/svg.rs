//! The SVG drawn on the large canvas, written back at the plot's own size: every coordinate
//! and length divided by the canvas factor, so the file has fractional coordinates (a slow
//! curve is smooth, not a staircase of whole pixels) and says `width="900" height="600"`.
//!
//! plotters' SVG backend writes one element per line, its attribute values escaped (no `"`
//! or `<` inside them) and the text of a `<text>` on its own line, so the rewrite reads tags
//! and attributes and leaves everything else as it is.

/// Attributes holding lengths: one, or a list (`points="1,2 3,4 "`,
/// `viewBox="0 0 3600 2400"`).
const LENGTHS: &[&str] = &[
    "x",
    "y",
    "x1",
    "y1",
    "x2",
    "y2",
    "cx",
    "cy",
    "r",
    "width",
    "height",
    "stroke-width",
    "font-size",
    "points",
    "viewBox",
];

/// The SVG text `svg`, drawn on a canvas `k` times larger than the plot, at the plot's size.
pub(super) fn rescale(svg: &str, k: f64) -> String {
    let mut out = String::with_capacity(svg.len());
    let mut rest = svg;
    while let Some(open) = rest.find('<') {
        out.push_str(&rest[..open]);
        rest = &rest[open..];
        let Some(close) = rest.find('>') else {
            break;
        };
        tag(&rest[..=close], k, &mut out);
        rest = &rest[close + 1..];
    }
    out.push_str(rest);
    out
}

/// One tag, `<name a="v" …>` or `</name>`, its lengths rescaled.
fn tag(text: &str, k: f64, out: &mut String) {
    let mut rest = text;
    while let Some(eq) = rest.find("=\"") {
        let name_start = rest[..eq].rfind([' ', '\n', '\t']).map_or(0, |i| i + 1);
        let name = &rest[name_start..eq];
        let value_start = eq + 2;
        let Some(len) = rest[value_start..].find('"') else {
            break;
        };
        let value = &rest[value_start..value_start + len];
        out.push_str(&rest[..value_start]);
        if LENGTHS.contains(&name) {
            out.push_str(&scaled_list(value, k));
        } else if name == "transform" {
            out.push_str(&rotation(value, k));
        } else {
            out.push_str(value);
        }
        rest = &rest[value_start + len..];
    }
    out.push_str(rest);
}

/// The numbers of `value`, separated by spaces and commas, each divided by `k`; a part that
/// is not a number is kept.
fn scaled_list(value: &str, k: f64) -> String {
    let mut out = String::with_capacity(value.len());
    let mut number = String::new();
    let flush = |number: &mut String, out: &mut String| {
        if !number.is_empty() {
            match number.parse::<f64>() {
                Ok(v) => out.push_str(&short(v / k)),
                Err(_) => out.push_str(number),
            }
            number.clear();
        }
    };
    for c in value.chars() {
        if c == ' ' || c == ',' {
            flush(&mut number, &mut out);
            out.push(c);
        } else {
            number.push(c);
        }
    }
    flush(&mut number, &mut out);
    out
}

/// `rotate(A, X, Y)` with the centre (not the angle) divided by `k`.
fn rotation(value: &str, k: f64) -> String {
    let inner = value
        .strip_prefix("rotate(")
        .and_then(|v| v.strip_suffix(')'));
    let Some(inner) = inner else {
        return value.to_string();
    };
    let parts: Vec<&str> = inner.split(',').map(str::trim).collect();
    let [angle, x, y] = parts[..] else {
        return value.to_string();
    };
    match (x.parse::<f64>(), y.parse::<f64>()) {
        (Ok(x), Ok(y)) => format!("rotate({angle}, {}, {})", short(x / k), short(y / k)),
        _ => value.to_string(),
    }
}

/// `v` to three decimals, without trailing zeros: `12.25`, `900`, `17.742`.
fn short(v: f64) -> String {
    let r = (v * 1000.0).round() / 1000.0;
    if r == 0.0 { "0".into() } else { format!("{r}") }
}

#[cfg(test)]
mod tests {
    use super::rescale;

    #[test]
    fn lengths_and_points_are_divided_and_text_is_kept() {
        let svg = concat!(
            "<svg width=\"3600\" height=\"2400\" viewBox=\"0 0 3600 2400\" xmlns=\"http://www.w3.org/2000/svg\">\n",
            "<polyline fill=\"none\" opacity=\"1\" stroke=\"#1F77B4\" stroke-width=\"8\" points=\"1,2 5,1202 \"/>\n",
            "<text x=\"10\" y=\"20\" dy=\"0.76em\" text-anchor=\"middle\" font-family=\"sans-serif\" font-size=\"70.96774193548387\" opacity=\"1\" fill=\"#000000\" transform=\"rotate(270, 10, 20)\">\n",
            "x = 1, y = 2\n",
            "</text>\n",
            "<circle cx=\"6\" cy=\"7\" r=\"16\" opacity=\"0.5\" fill=\"none\"/>\n",
            "</svg>\n"
        );
        let out = rescale(svg, 4.0);
        assert!(out.starts_with(
            "<svg width=\"900\" height=\"600\" viewBox=\"0 0 900 600\" xmlns=\"http://www.w3.org/2000/svg\">\n"
        ));
        assert!(out.contains("stroke-width=\"2\" points=\"0.25,0.5 1.25,300.5 \""));
        assert!(out.contains("x=\"2.5\" y=\"5\" dy=\"0.76em\""));
        assert!(out.contains("font-size=\"17.742\""));
        assert!(out.contains("transform=\"rotate(270, 2.5, 5)\""));
        assert!(out.contains("\nx = 1, y = 2\n"), "text is not a length");
        assert!(out.contains("cx=\"1.5\" cy=\"1.75\" r=\"4\" opacity=\"0.5\""));
    }
}

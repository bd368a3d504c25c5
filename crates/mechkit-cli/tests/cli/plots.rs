//! Plots ready for slides (issue 22, item 4), through the binary: a sweep of many runs of one
//! parameter coloured by its value with a colour bar instead of a legend; the comparison of
//! methods on real log axes with decade labels; fractional SVG coordinates at the nominal
//! 900x600 size; `--style slides` with larger type; PNGs of the nominal size at 96 dpi.

use std::path::Path;

use super::util::{Dir, examples};

/// The numbers of every `attr="…"` attribute of `svg` (lists such as `points` split).
fn numbers(svg: &str, attr: &str) -> Vec<f64> {
    let key = format!(" {attr}=\"");
    svg.match_indices(&key)
        .flat_map(|(i, _)| {
            let rest = &svg[i + key.len()..];
            let value = &rest[..rest.find('"').unwrap()];
            value
                .split([' ', ','])
                .filter(|s| !s.is_empty())
                .map(|s| {
                    s.parse::<f64>()
                        .unwrap_or_else(|e| panic!("{attr}={s}: {e}"))
                })
                .collect::<Vec<_>>()
        })
        .collect()
}

/// The lines of text of `svg` (the contents of its `<text>` elements).
fn texts(svg: &str) -> Vec<&str> {
    svg.split("<text ")
        .skip(1)
        .filter_map(|t| t.split_once(">\n").map(|(_, rest)| rest))
        .filter_map(|t| t.split_once("\n</text>").map(|(text, _)| text))
        .collect()
}

/// The width and height of a PNG, after checking its signature.
fn png_size(path: &Path) -> (u32, u32) {
    let bytes = std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "{}", path.display());
    let be = |i: usize| u32::from_be_bytes(bytes[i..i + 4].try_into().unwrap());
    (be(16), be(20))
}

fn sweep(dir: &Dir, set: &str, out: &str, extra: &[&str]) {
    let file = examples().join("sweep/throw.toml");
    let head = [
        "sweep",
        file.to_str().unwrap(),
        "--set",
        set,
        "--plot",
        "v(x)",
        "--out",
        out,
    ];
    dir.run_with(&head, extra).assert_code(0);
}

#[test]
fn a_sweep_of_many_runs_is_coloured_by_its_parameter_with_a_colour_bar() {
    let dir = Dir::new();
    sweep(&dir, "v0=0:5:11", "many", &[]);
    let svg = dir.read("many/sweep_v_x.svg");
    let text = texts(&svg);
    // the bar is named after the parameter with its unit, and has ticks from 0 to 5
    assert!(text.contains(&"v0 [m/s]"), "{text:?}");
    assert!(text.contains(&"0") && text.contains(&"5"), "{text:?}");
    // no legend entry per run
    let legend: Vec<&&str> = text.iter().filter(|t| t.starts_with("v0 = ")).collect();
    assert!(legend.is_empty(), "{legend:?}");
    // curves in more than the palette's 8 colours (viridis from violet to yellow)
    let mut strokes: Vec<&str> = svg
        .lines()
        .filter(|l| l.starts_with("<polyline"))
        .filter_map(|l| l.split("stroke=\"").nth(1))
        .map(|s| &s[..7])
        .collect();
    strokes.sort_unstable();
    strokes.dedup();
    assert!(strokes.len() >= 11, "{strokes:?}");
    assert!(
        strokes.contains(&"#440154"),
        "the map starts at viridis' violet"
    );

    // a few runs keep their legend, without a bar
    sweep(&dir, "v0=1:5:5", "few", &[]);
    let svg = dir.read("few/sweep_v_x.svg");
    let text = texts(&svg);
    assert!(
        text.contains(&"v0 = 1") && text.contains(&"v0 = 5"),
        "{text:?}"
    );
    assert!(!text.contains(&"v0 [m/s]"), "{text:?}");
}

#[test]
fn the_comparison_of_methods_has_log_axes_with_decade_labels() {
    let dir = Dir::new();
    let file = examples().join("feather.toml");
    dir.run(&[
        "run",
        file.to_str().unwrap(),
        "--out",
        "cmp",
        "--compare-methods",
        "euler,rk4",
    ])
    .assert_code(0);
    for (name, label) in [
        ("cmp/compare_error.svg", "position error [m]"),
        ("cmp/compare_energy.svg", "relative energy error"),
    ] {
        let svg = dir.read(name);
        let text = texts(&svg);
        assert!(text.contains(&label), "{name}: {text:?}");
        assert!(
            !svg.contains("log10"),
            "{name}: the values, not their logarithms"
        );
        // decades: rk4's error is about 1e-11, euler's 1e-4
        let decades: Vec<&&str> = text
            .iter()
            .filter(|t| t.starts_with("1e-") && t[3..].parse::<u32>().is_ok())
            .collect();
        assert!(decades.len() >= 5, "{name}: {decades:?}");
        assert!(text.contains(&"1e-6"), "{name}: {text:?}");
    }
}

#[test]
fn svg_coordinates_are_fractional_at_the_nominal_size() {
    let dir = Dir::new();
    let file = examples().join("projectile_drag.toml");
    dir.run(&["run", file.to_str().unwrap(), "--out", "o"])
        .assert_code(0);
    let svg = dir.read("o/v_t.svg");
    assert!(
        svg.starts_with("<svg width=\"900\" height=\"600\" viewBox=\"0 0 900 600\""),
        "{}",
        &svg[..100]
    );
    let points = numbers(&svg, "points");
    assert!(points.len() > 100);
    let fractional = points.iter().filter(|v| v.fract() != 0.0).count();
    assert!(
        fractional > points.len() / 4,
        "{fractional} of {} coordinates are fractional",
        points.len()
    );
    // everything inside the nominal frame
    assert!(points.iter().all(|v| (0.0..=900.0).contains(v)));
}

#[test]
fn slides_have_larger_type_and_thicker_lines() {
    let dir = Dir::new();
    let file = examples().join("projectile_drag.toml");
    let file = file.to_str().unwrap();
    dir.run(&["run", file, "--out", "paper"]).assert_code(0);
    dir.run(&["run", file, "--out", "slides", "--style", "slides"])
        .assert_code(0);
    let largest = |v: Vec<f64>| v.into_iter().fold(0.0, f64::max);
    let smallest = |v: Vec<f64>| v.into_iter().fold(f64::INFINITY, f64::min);
    let (paper, slides) = (dir.read("paper/v_t.svg"), dir.read("slides/v_t.svg"));
    for (what, p, s) in [
        (
            "the smallest type",
            smallest(numbers(&paper, "font-size")),
            smallest(numbers(&slides, "font-size")),
        ),
        (
            "the title",
            largest(numbers(&paper, "font-size")),
            largest(numbers(&slides, "font-size")),
        ),
        (
            "the curve",
            largest(numbers(&paper, "stroke-width")),
            largest(numbers(&slides, "stroke-width")),
        ),
    ] {
        assert!(s >= 1.4 * p, "{what}: {p} on paper, {s} on slides");
    }
    // the flag is offered wherever --format is, and the default is paper
    dir.run(&["run", file, "--out", "default", "--style", "paper"])
        .assert_code(0);
    assert_eq!(dir.read("default/v_t.svg"), paper);
    dir.run(&["run", file, "--style", "poster"])
        .assert_bad_input(&["--style", "slides"]);
}

#[test]
fn pngs_at_96_dpi_have_the_nominal_size_in_both_styles() {
    let dir = Dir::new();
    for style in ["paper", "slides"] {
        sweep(
            &dir,
            "v0=0:5:9",
            style,
            &["--format", "png", "--dpi", "96", "--style", style],
        );
        let path = dir.path().join(style).join("sweep_v_x.png");
        assert_eq!(png_size(&path), (900, 600), "{style}");
    }
    let dir = Dir::new();
    dir.run(&[
        "potential",
        "4*(x^-12 - x^-6)",
        "--range",
        "0.95:3",
        "-o",
        "lj",
        "--format",
        "png",
        "--dpi",
        "96",
    ])
    .assert_code(0);
    assert_eq!(png_size(&dir.path().join("lj/U_x.png")), (900, 600));
}

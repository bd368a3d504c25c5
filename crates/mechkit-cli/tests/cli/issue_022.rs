//! Issue 22 through the binary: plots as PNG for slides (`--format png`, `--dpi`, or a
//! `--plot` path ending in `.png`), rasterised from the same SVG with the bundled font.

use std::path::Path;

use super::util::{Dir, at, examples};

/// The width, height and resolution (dots per inch, from `pHYs`) of a PNG file, after
/// checking its signature.
fn png_info(path: &Path) -> (u32, u32, u32) {
    let bytes = std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    assert_eq!(
        &bytes[..8],
        b"\x89PNG\r\n\x1a\n",
        "{} is not a PNG",
        path.display()
    );
    let be = |i: usize| u32::from_be_bytes(bytes[i..i + 4].try_into().unwrap());
    let (width, height) = (be(16), be(20));
    let mut i = 8;
    let mut dpi = 0;
    while i + 8 <= bytes.len() {
        let (len, kind) = (be(i) as usize, &bytes[i + 4..i + 8]);
        if kind == b"pHYs" {
            dpi = (f64::from(be(i + 8)) * 0.0254).round() as u32;
        }
        i += 12 + len;
    }
    (width, height, dpi)
}

/// Whether the picture has more than the background: some pixels are not white (the PNG is
/// decoded with the `png` crate the binary uses).
fn has_ink(path: &Path) -> bool {
    let decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(path).unwrap()));
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buf).unwrap();
    let pixels = &buf[..info.buffer_size()];
    let dark = pixels
        .chunks_exact(3)
        .filter(|p| p.iter().all(|&c| c < 128))
        .count();
    // text and axes, a few thousand dark pixels; not a blank or a black picture
    dark > 1000 && dark < pixels.len() / 3 / 2
}

#[test]
fn a_run_draws_its_plots_as_png_at_the_resolution_asked() {
    let dir = Dir::new();
    let file = examples().join("projectile.toml");
    let file = file.to_str().unwrap();
    dir.run(&["run", file, "--out", "hi", "--format", "png"])
        .assert_code(0);
    let summary = dir.read_json("hi/summary.json");
    let plots = at(&summary, "/files/plots").as_array().unwrap().clone();
    assert!(!plots.is_empty());
    for p in &plots {
        let name = p.as_str().unwrap();
        assert!(
            Path::new(name).extension().is_some_and(|e| e == "png"),
            "{name}"
        );
        let path = dir.path().join("hi").join(name);
        // 900 x 600 SVG pixels at the default 192 dpi
        assert_eq!(png_info(&path), (1800, 1200, 192), "{name}");
        assert!(has_ink(&path), "{name} shows nothing");
        assert!(
            !dir.path()
                .join("hi")
                .join(name.replace(".png", ".svg"))
                .exists(),
            "only the format asked for"
        );
    }
    dir.run(&["run", file, "--out", "lo", "--format", "png", "--dpi", "96"])
        .assert_code(0);
    let first = plots[0].as_str().unwrap();
    assert_eq!(png_info(&dir.path().join("lo").join(first)), (900, 600, 96));
    // SVG stays the default
    dir.run(&["run", file, "--out", "svg"]).assert_code(0);
    assert!(
        dir.path()
            .join("svg")
            .join(first.replace(".png", ".svg"))
            .exists()
    );
}

#[test]
fn a_potential_diagram_as_png() {
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
        "120",
    ])
    .assert_code(0);
    assert_eq!(png_info(&dir.path().join("lj/U_x.png")), (1125, 750, 120));
    assert!(has_ink(&dir.path().join("lj/U_x.png")));
}

#[test]
fn every_command_that_draws_plots_offers_png() {
    let dir = Dir::new();
    for cmd in [
        "run", "sweep", "spin", "friction", "roll", "bead", "power", "rocket", "derive",
    ] {
        let out = dir.run(&[cmd, "--help"]);
        out.assert_code(0);
        assert!(
            out.stdout.contains("--format") && out.stdout.contains("--dpi"),
            "{cmd} --help"
        );
    }
    for cmd in ["work", "impulse", "potential"] {
        let out = dir.run(&[cmd, "--help"]);
        assert!(
            out.stdout.contains("--dpi") && out.stdout.contains(".png"),
            "{cmd}"
        );
    }
    // a resolution that would give no pixels, or absurdly many, is refused at the flag
    dir.run(&["run", "x.toml", "--format", "png", "--dpi", "0"])
        .assert_bad_input(&["--dpi"]);
    dir.run(&["run", "x.toml", "--format", "jpeg"])
        .assert_bad_input(&["--format", "png"]);
}

#[test]
fn every_output_flag_has_the_short_form() {
    let dir = Dir::new();
    for cmd in [
        "run",
        "sweep",
        "sweep-merge",
        "md",
        "work",
        "impulse",
        "derive",
        "power",
        "rocket",
        "friction",
        "roll",
        "bead",
        "spin",
        "gallery",
    ] {
        let out = dir.run(&[cmd, "--help"]);
        out.assert_code(0);
        assert!(out.stdout.contains("-o, --out"), "{cmd} --help");
    }
}

//! PNG plots: the SVG rasterised by resvg with the bundled font, written as an RGB PNG that
//! records its resolution.

use std::sync::OnceLock;

use anyhow::{Result, anyhow};
use resvg::{tiny_skia, usvg};

use super::FONT;

/// The PNG of the SVG text `svg` at `dpi` dots per inch (96: one pixel per SVG pixel), on a
/// white background.
pub(super) fn rasterise(svg: &str, dpi: u32) -> Result<Vec<u8>> {
    let pixmap = pixmap(svg, dpi as f32 / 96.0).map_err(|e| match e {
        RasterError::NoPixels => anyhow!("a PNG at {dpi} dpi has no pixels; use --dpi 96 or more"),
        e => anyhow::Error::new(e).context("cannot read the plot's SVG"),
    })?;
    encode_rgb(&pixmap, dpi).map_err(|e| anyhow!("cannot encode the PNG: {e}"))
}

/// Why an SVG could not be rasterised.
#[derive(Debug)]
pub(crate) enum RasterError {
    /// The SVG text could not be read.
    Svg(usvg::Error),
    /// At this scale the picture is less than a pixel across.
    NoPixels,
    /// The pixels could not be allocated.
    TooLarge(u32, u32),
}

impl std::fmt::Display for RasterError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Svg(e) => write!(f, "{e}"),
            Self::NoPixels => write!(f, "the picture has no pixels at this scale"),
            Self::TooLarge(w, h) => write!(f, "cannot allocate a {w}x{h} picture"),
        }
    }
}

impl std::error::Error for RasterError {}

/// The SVG text `svg` rasterised by resvg at `scale` pixels per SVG pixel, its text set in
/// the bundled font, on a white background: an opaque premultiplied-RGBA pixmap (what the PNG
/// plots and the GIF animations are made of).
pub(crate) fn pixmap(svg: &str, scale: f32) -> Result<tiny_skia::Pixmap, RasterError> {
    let tree = usvg::Tree::from_str(svg, options()).map_err(RasterError::Svg)?;
    let size = tree
        .size()
        .to_int_size()
        .scale_by(scale)
        .ok_or(RasterError::NoPixels)?;
    let mut pixmap = tiny_skia::Pixmap::new(size.width(), size.height())
        .ok_or(RasterError::TooLarge(size.width(), size.height()))?;
    pixmap.fill(tiny_skia::Color::WHITE);
    let transform = tiny_skia::Transform::from_scale(scale, scale);
    resvg::render(&tree, transform, &mut pixmap.as_mut());
    Ok(pixmap)
}

/// usvg's options with the bundled font as the only font, the sans-serif family and the
/// default: set up once (the font's tables are read when it is loaded).
fn options() -> &'static usvg::Options<'static> {
    static OPTIONS: OnceLock<usvg::Options<'static>> = OnceLock::new();
    OPTIONS.get_or_init(|| {
        let mut options = usvg::Options::default();
        options.fontdb_mut().load_font_data(FONT.to_vec());
        options.fontdb_mut().set_sans_serif_family("DejaVu Sans");
        options.font_family = "DejaVu Sans".into();
        options
    })
}

/// The opaque `pixmap` as an RGB PNG (the alpha channel is 255 throughout: a white
/// background) that records its resolution, `dpi`.
fn encode_rgb(pixmap: &tiny_skia::Pixmap, dpi: u32) -> Result<Vec<u8>, png::EncodingError> {
    let rgb: Vec<u8> = pixmap
        .data()
        .chunks_exact(4)
        .flat_map(|p| [p[0], p[1], p[2]])
        .collect();
    let mut out = Vec::new();
    let mut encoder = png::Encoder::new(&mut out, pixmap.width(), pixmap.height());
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_compression(png::Compression::High);
    let per_metre = (f64::from(dpi) / 0.0254).round() as u32;
    encoder.set_pixel_dims(Some(png::PixelDimensions {
        xppu: per_metre,
        yppu: per_metre,
        unit: png::Unit::Meter,
    }));
    let mut writer = encoder.write_header()?;
    writer.write_image_data(&rgb)?;
    writer.finish()?;
    Ok(out)
}

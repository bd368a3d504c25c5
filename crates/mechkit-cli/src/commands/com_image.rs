//! `mechkit com IMAGE`: the centre of mass and moment of inertia of the body in a photo, by
//! the course's method (the pixels with `R+G+B < 1.5` are the body).

use std::fmt::Write as _;

use anyhow::{Context, Result, anyhow, bail};
use mechkit::csv::write_atomic;
use mechkit::expr::units::Dimension;
use mechkit::mass::image::{
    Channel, ImageError, ImageOptions, ImageReport, PixelBody, Raster, Selection, marked_png,
};

use super::input::{quantity, show, split_top_level};
use super::{Outcome, report};
use crate::args::ComArgs;

/// A number of pixels: `"240"`, `"240 px"`, `"240 pixels"`.
fn pixels(text: &str, flag: &str) -> Result<f64> {
    mechkit::values::pixels(text, flag).map_err(|e| anyhow!(e))
}

/// `"x, y"` split in two, or an error that shows what to write.
fn pair<'t>(text: &'t str, flag: &str, example: &str) -> Result<[&'t str; 2]> {
    match split_top_level(text, ',').as_slice() {
        [x, y] if !x.is_empty() && !y.is_empty() => Ok([x, y]),
        _ => {
            bail!("{flag} takes two coordinates \"x, y\", e.g. {flag} \"{example}\", not `{text}`")
        }
    }
}

/// The side of a pixel (m) from `--pixel-size` or `--scale`, or `None` to work in pixels.
fn pixel_size(args: &ComArgs) -> Result<Option<f64>> {
    let size = match (&args.pixel_size, &args.scale) {
        (Some(_), Some(_)) => bail!("give either --pixel-size or --scale, not both"),
        (None, None) => return Ok(None),
        (Some(s), None) => quantity(s, "--pixel-size", Dimension::LENGTH)?,
        (None, Some(s)) => mechkit::values::pixel_scale(s, "--scale")?,
    };
    if !(size.is_finite() && size > 0.0) {
        bail!("the pixel size must be a positive length, e.g. --pixel-size \"0.5 mm\"");
    }
    Ok(Some(size))
}

/// A physical coordinate of `--about`: a length with a scale, pixels without one.
fn coordinate(text: &str, scaled: bool) -> Result<f64> {
    mechkit::values::image_coordinate(text, "--about", scaled, "--pixel-size or --scale")
        .map_err(|e| anyhow!(e))
}

/// The image's error, with the flags that change a selection that marks nothing or all.
fn image_error(e: ImageError) -> anyhow::Error {
    match e {
        ImageError::SelectsNothing { .. } | ImageError::SelectsEverything { .. } => anyhow!(
            "{e} (--threshold; --channel sum, r, g or b; --invert for a bright body on a dark background)"
        ),
        e => anyhow!(e),
    }
}

/// Flags of point masses have no meaning with an image.
fn reject_point_mass_flags(args: &ComArgs) -> Result<()> {
    for (given, flag) in [
        (!args.mass.is_empty(), "--mass"),
        (!args.at.is_empty(), "--at"),
        (!args.velocity.is_empty(), "--velocity"),
        (args.unit.is_some(), "--in"),
    ] {
        if given {
            bail!("{flag} is for point masses; it cannot be used with an image");
        }
    }
    Ok(())
}

pub fn com_image(args: &ComArgs) -> Result<Outcome> {
    let file = args
        .file
        .as_deref()
        .ok_or_else(|| anyhow!("give the image file"))?;
    reject_point_mass_flags(args)?;
    let channel = Channel::parse(&args.channel).map_err(|e| anyhow!("--channel: {e}"))?;
    let selection = Selection::from_options(
        channel,
        args.threshold,
        args.invert,
        args.density_from_darkness,
    )
    .map_err(|e| anyhow!("--threshold: {e}, e.g. --threshold 1.5"))?;
    let size = pixel_size(args)?;
    let total_mass = match &args.total_mass {
        Some(m) => {
            let m = quantity(m, "--total-mass", Dimension::MASS)?;
            if !(m.is_finite() && m > 0.0) {
                bail!("--total-mass must be a positive mass, e.g. --total-mass \"2 kg\"");
            }
            Some(m)
        }
        None => None,
    };
    let raster = Raster::open(file)?;
    let origin = match &args.origin {
        Some(text) => {
            let [x, y] = pair(text, "--origin", "200, 400")?;
            Some([pixels(x, "--origin")?, pixels(y, "--origin")?])
        }
        None => None,
    };
    let about = match &args.about {
        Some(text) => {
            let [x, y] = pair(text, "--about", "0, 0")?;
            Some([
                coordinate(x, size.is_some())?,
                coordinate(y, size.is_some())?,
            ])
        }
        None => None,
    };
    let body = PixelBody::measure(&raster, &selection).map_err(|e| {
        let e = image_error(e);
        anyhow!("{}: {e}", file.display())
    })?;
    let options = ImageOptions {
        selection,
        pixel_size: size,
        origin,
        total_mass,
        about,
    };
    let mut result = body
        .report(&file.display().to_string(), &options)
        .map_err(|e| anyhow!("{e}"))?;
    if let Some(out) = &args.mark {
        if !out
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("png"))
        {
            bail!("--mark writes a PNG image: name the file .png, e.g. --mark marked.png");
        }
        let png = marked_png(&raster, &selection, &body).map_err(|e| anyhow!("--mark: {e}"))?;
        write_atomic(out, &png)
            .with_context(|| format!("--mark: cannot write {}", out.display()))?;
        result.mark = Some(out.display().to_string());
    }
    report(args.report, &result, || to_text(&result))?;
    Ok(Outcome::Success)
}

fn to_text(m: &ImageReport) -> String {
    let len = m.unit;
    let inertia_unit = if m.mass.is_some() {
        format!("kg·{len}²")
    } else {
        format!("{len}⁴")
    };
    let pt = |p: [f64; 2]| format!("({}, {})", show(p[0] + 0.0), show(p[1] + 0.0));
    let i = &m.inertia_cm;
    let mut out = String::new();
    let _ = writeln!(
        out,
        "{}: {} × {} pixels; the body is {}: {} pixels ({} % of the image){}",
        m.file,
        m.width,
        m.height,
        m.rule,
        m.selected_pixels,
        show((1e4 * m.fraction).round() / 100.0),
        if m.density == "darkness" {
            ", density from the shade"
        } else {
            ""
        }
    );
    let _ = writeln!(
        out,
        "centre of mass in pixels (x right, y down from the top-left corner): {}",
        pt(m.pixel_centre_of_mass)
    );
    let _ = writeln!(
        out,
        "centre of mass {} {len} (y up, origin at pixel {}{})",
        pt(m.centre_of_mass),
        pt(m.origin_pixel),
        m.pixel_size
            .map_or(String::new(), |s| format!(", pixel size {} m", show(s)))
    );
    let _ = writeln!(
        out,
        "area {} {len}²; mass {}",
        show(m.area),
        match m.mass {
            Some(mass) => format!("{} kg", show(mass)),
            None =>
                format!("not given: density 1 per {len}², so the moments below are of the area"),
        }
    );
    let _ = writeln!(
        out,
        "moment of inertia about the centre of mass, axis perpendicular to the image: I_zz = {} {inertia_unit} (radius of gyration {} {len})",
        show(i.zz),
        show(m.radius_of_gyration)
    );
    let _ = writeln!(
        out,
        "  in the plane: I_xx = {}, I_yy = {}, I_xy = {} {inertia_unit}",
        show(i.xx),
        show(i.yy),
        show(i.xy + 0.0)
    );
    if let Some(a) = &m.about {
        let _ = writeln!(
            out,
            "about {} {len}: I_zz = {} {inertia_unit}",
            pt(a.point),
            show(a.zz)
        );
    }
    if let Some(path) = &m.mark {
        let _ = writeln!(out, "marked image written to {path}");
    }
    out
}

//! `ImageReport`: what the centre of mass of a photo reports (`mechkit com IMAGE --json`): the
//! selection, the pixels, the centre of mass in pixels and in physical units, the area, the
//! inertia of the thin plate about its centre of mass and about a point, and the radius of
//! gyration.

use super::{Density, ImageError, PixelBody, PixelFrame, Selection};
use crate::Real;
use crate::mass::Vec3;

/// How a photo is measured: which pixels are the body, the physical scale and origin, the
/// mass, and a point for the moment of inertia.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ImageOptions {
    /// The rule that marks the body's pixels.
    pub selection: Selection,
    /// The side of a pixel (m), or `None` to measure in pixels.
    pub pixel_size: Option<Real>,
    /// The pixel coordinates of the physical origin, or `None` for the bottom-left corner.
    pub origin: Option<[Real; 2]>,
    /// The body's mass (kg), or `None` for an areal density of 1 per unit weight.
    pub total_mass: Option<Real>,
    /// A point (physical coordinates; pixels without a pixel size) for `I_zz` about it.
    pub about: Option<[Real; 2]>,
}

/// The inertia tensor of the plate about its centre of mass: the in-plane moments, the polar
/// one and the product.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct PlateInertia {
    /// `I_xx = ∫ y² dm`.
    pub xx: Real,
    /// `I_yy = ∫ x² dm`.
    pub yy: Real,
    /// `I_zz = I_xx + I_yy`, about the axis perpendicular to the image.
    pub zz: Real,
    /// `I_xy = −∫ x y dm`.
    pub xy: Real,
}

/// `I_zz` about a point of the image.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct PlateAbout {
    /// The point (physical coordinates, or pixels).
    pub point: [Real; 2],
    /// `I_zz` about the axis through it perpendicular to the image (Steiner).
    pub zz: Real,
}

/// The centre of mass and moments of the body in a photo. Lengths are in `unit`: metres with
/// a pixel size, pixels without; moments in kg·`unit`² with a mass, `unit`⁴ without (the
/// moments of the area).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct ImageReport {
    /// Always `image` (a body file reports `body`).
    pub source: &'static str,
    /// The image file, as given.
    pub file: String,
    /// Image width (pixels).
    pub width: usize,
    /// Image height (pixels).
    pub height: usize,
    /// The channel's name (`sum`, `r`, `g`, `b`).
    pub channel: &'static str,
    /// The threshold on the channel.
    pub threshold: Real,
    /// Whether the body is the bright pixels.
    pub inverted: bool,
    /// `uniform`, or `darkness` (a density that follows the shade).
    pub density: &'static str,
    /// The rule as text (`R+G+B < 1.5`).
    pub rule: String,
    /// The number of selected pixels.
    pub selected_pixels: usize,
    /// The fraction of the image they are.
    pub fraction: Real,
    /// Their weight `W = Σ wᵢ`.
    pub weight: Real,
    /// The centre of mass in pixel coordinates (x right, y down from the top-left corner).
    pub pixel_centre_of_mass: [Real; 2],
    /// The pixel coordinates of the physical origin.
    pub origin_pixel: [Real; 2],
    /// The side of a pixel (m), when given.
    pub pixel_size: Option<Real>,
    /// `m` with a pixel size, `px` without.
    pub unit: &'static str,
    /// The centre of mass in physical coordinates (y up).
    pub centre_of_mass: [Real; 2],
    /// The area of the selected pixels (`unit`²).
    pub area: Real,
    /// The mass (kg), when given.
    pub mass: Option<Real>,
    /// The inertia tensor about the centre of mass.
    pub inertia_cm: PlateInertia,
    /// The radius of gyration about the axis through the centre of mass perpendicular to the
    /// image, `k = √(I_zz/m)` (`unit`).
    pub radius_of_gyration: Real,
    /// `I_zz` about a point, when one was given.
    pub about: Option<PlateAbout>,
    /// The marked picture written, when a front wrote one.
    pub mark: Option<String>,
}

impl PixelBody {
    /// The radius of gyration of the plate about the axis through its centre of mass
    /// perpendicular to the image, `k = √(I_zz/m) = s √((Σ wᵢ |rᵢ − r̄|² + W/6)/W)` for pixels
    /// of side `pixel_size`: it does not depend on the mass.
    ///
    /// ```
    /// use mechkit::mass::image::{PixelBody, Raster, Selection};
    /// // a black 2 × 2 block: a square of side a = 2 has k² = a²/6
    /// let img = Raster::from_fn(6, 6, |x, y| if x < 2 && y < 2 { [0.0; 3] } else { [1.0; 3] });
    /// let body = PixelBody::measure(&img, &Selection::default()).unwrap();
    /// assert!((body.radius_of_gyration(1.0) - (4.0f64 / 6.0).sqrt()).abs() < 1e-15);
    /// ```
    pub fn radius_of_gyration(&self, pixel_size: Real) -> Real {
        pixel_size * ((self.spread[0] + self.spread[1]) / self.weight).sqrt()
    }

    /// The report of the body as measured from the image `file` with `options`. Fails when
    /// the pixel size, the origin or the mass is not valid.
    pub fn report(&self, file: &str, options: &ImageOptions) -> Result<ImageReport, ImageError> {
        let origin = options.origin.unwrap_or([0.0, self.height as Real]);
        let frame = PixelFrame::new(options.pixel_size.unwrap_or(1.0), origin)?;
        let props = self.mass_properties(&frame, options.total_mass)?;
        let i = &props.inertia;
        let selection = &options.selection;
        let about = options.about.map(|p| PlateAbout {
            point: p,
            zz: props.inertia_about(&Vec3::new(p[0], p[1], 0.0))[(2, 2)],
        });
        Ok(ImageReport {
            source: "image",
            file: file.to_string(),
            width: self.width,
            height: self.height,
            channel: selection.channel.name(),
            threshold: selection.threshold,
            inverted: selection.invert,
            density: density_name(selection),
            rule: selection.to_string(),
            selected_pixels: self.count,
            fraction: self.fraction(),
            weight: self.weight,
            pixel_centre_of_mass: self.centre,
            origin_pixel: frame.origin,
            pixel_size: options.pixel_size.map(|_| frame.pixel_size),
            unit: if options.pixel_size.is_some() {
                "m"
            } else {
                "px"
            },
            centre_of_mass: [props.centre_of_mass.x + 0.0, props.centre_of_mass.y + 0.0],
            area: self.area(frame.pixel_size),
            mass: options.total_mass.map(|_| props.mass),
            inertia_cm: PlateInertia {
                xx: i[(0, 0)],
                yy: i[(1, 1)],
                zz: i[(2, 2)],
                xy: i[(0, 1)] + 0.0,
            },
            radius_of_gyration: props
                .radius_of_gyration(&props.centre_of_mass, &Vec3::z())
                .map_err(|e| ImageError::Invalid(e.to_string()))?,
            about,
            mark: None,
        })
    }
}

fn density_name(selection: &Selection) -> &'static str {
    match selection.density {
        Density::Darkness => "darkness",
        _ => "uniform",
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mass::image::Raster;

    #[test]
    fn the_radius_of_gyration_is_that_of_the_mass_properties() {
        // a black disk of radius 40 px: k = R/√2 within the rasterisation
        let disk = Raster::from_fn(100, 100, |x, y| {
            let (dx, dy) = (x as f64 + 0.5 - 50.0, y as f64 + 0.5 - 50.0);
            if dx * dx + dy * dy < 1600.0 {
                [0.0; 3]
            } else {
                [1.0; 3]
            }
        });
        let body = PixelBody::measure(&disk, &Selection::default()).unwrap();
        let options = ImageOptions {
            pixel_size: Some(1e-3),
            total_mass: Some(2.0),
            about: Some([0.0, 0.0]),
            ..ImageOptions::default()
        };
        let r = body.report("disk.png", &options).unwrap();
        let frame = PixelFrame::bottom_left(100, 1e-3).unwrap();
        let props = body.mass_properties(&frame, Some(2.0)).unwrap();
        let k = props
            .radius_of_gyration(&props.centre_of_mass, &Vec3::z())
            .unwrap();
        assert_eq!(r.radius_of_gyration, k);
        // the image moments' own: the same to rounding
        assert!((body.radius_of_gyration(1e-3) - k).abs() < 1e-14 * k);
        assert!((r.radius_of_gyration - 0.04 / 2f64.sqrt()).abs() < 2e-4);
        assert_eq!((r.unit, r.mass, r.pixel_size), ("m", Some(2.0), Some(1e-3)));
        assert_eq!(r.centre_of_mass, [0.05, 0.05]);
        // Steiner about the corner: I_zz + m d², d² = 2 · 0.05²
        let steiner = r.inertia_cm.zz + 2.0 * 0.005;
        assert!((r.about.unwrap().zz - steiner).abs() < 1e-15);
        // in pixels without a scale, and no mass: the moments of the area
        let px = body.report("disk.png", &ImageOptions::default()).unwrap();
        assert_eq!((px.unit, px.mass, px.pixel_size), ("px", None, None));
        assert!((px.radius_of_gyration - 1e3 * r.radius_of_gyration).abs() < 1e-9);
        assert_eq!(px.rule, "R+G+B < 1.5");
    }
}

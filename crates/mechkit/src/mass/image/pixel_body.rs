//! `PixelBody`: the selected pixels of an image as a thin plate: their weight, centre of mass
//! and second moments, and its mass properties in physical units.

use super::{Brightness, Channel, ImageError, PixelFrame, Raster, Selection};
use crate::Real;
use crate::mass::{MassProperties, Mat3, Vec3};

/// The pixels a [`Selection`] marks in a [`Raster`], each a uniform square of side 1 px with
/// its weight `wᵢ` (1, or its shade), measured in pixel coordinates (x right, y down, pixel
/// centres at `+½`; see [`PixelFrame`]):
///
/// - `W = Σ wᵢ`, the centre of mass `x̄ = Σ wᵢ xᵢ / W`, `ȳ = Σ wᵢ yᵢ / W`;
/// - the central second moments of the rasterised body, each pixel's own included
///   (`∫ x² = 1/12` over a unit square): `Σ wᵢ (xᵢ − x̄)² + W/12`, the same in `y`, and
///   `Σ wᵢ (xᵢ − x̄)(yᵢ − ȳ)`.
///
/// Sums run in `f64` with coordinates taken from the image's centre, so with uniform weights
/// every sum is exact (pixel centres are multiples of ½) and a body symmetric about a point
/// has its centre of mass there to the last bit.
///
/// ```
/// use mechkit::mass::image::{PixelBody, Raster, Selection};
/// // a black 2 × 3 block in a white 10 × 10 image, columns 4-5, rows 1-3
/// let img = Raster::from_fn(10, 10, |x, y| {
///     if (4..6).contains(&x) && (1..4).contains(&y) { [0.0; 3] } else { [1.0; 3] }
/// });
/// let body = PixelBody::measure(&img, &Selection::default()).unwrap();
/// assert_eq!(body.count, 6);
/// assert_eq!(body.centre, [5.0, 2.5]);
/// // a 2 × 3 rectangle: W a²/12 and W b²/12
/// assert_eq!(body.spread, [2.0, 4.5, 0.0]);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct PixelBody {
    /// Image width (pixels).
    pub width: usize,
    /// Image height (pixels).
    pub height: usize,
    /// The number of selected pixels.
    pub count: usize,
    /// `W = Σ wᵢ` (equal to `count` for a uniform density).
    pub weight: Real,
    /// The centre of mass `(x̄, ȳ)` in pixel coordinates (x right, y down from the top-left
    /// corner).
    pub centre: [Real; 2],
    /// The central second moments `[xx, yy, xy]` of the weight (px², y down), each pixel a
    /// uniform square.
    pub spread: [Real; 3],
}

/// Weighted sums over the selected pixels, coordinates from the image's centre.
#[derive(Debug, Default)]
struct Sums {
    count: usize,
    w: Real,
    x: Real,
    y: Real,
    xx: Real,
    yy: Real,
    xy: Real,
}

impl PixelBody {
    /// Selects and measures. Fails when the selection marks no pixel or every pixel (the
    /// error reports the image's [`Brightness`] on the channel, to choose a threshold from),
    /// or when the threshold is not finite.
    pub fn measure(raster: &Raster, selection: &Selection) -> Result<Self, ImageError> {
        selection.check()?;
        let (selected, weights) = selection.table();
        let table: Vec<(Real, usize)> = weights
            .into_iter()
            .zip(selected)
            .map(|(w, s)| (w, usize::from(s)))
            .collect();
        let sums = match selection.channel {
            Channel::Sum => accumulate(raster, &table, |p| Channel::Sum.level(p)),
            Channel::Red => accumulate(raster, &table, |p| Channel::Red.level(p)),
            Channel::Green => accumulate(raster, &table, |p| Channel::Green.level(p)),
            Channel::Blue => accumulate(raster, &table, |p| Channel::Blue.level(p)),
        };
        let pixels = raster.pixels();
        if sums.count == 0 || sums.count == pixels {
            let brightness = Brightness::of(raster, selection.channel);
            let selection = selection.to_string();
            return Err(if sums.count == 0 {
                ImageError::SelectsNothing {
                    selection,
                    pixels,
                    brightness,
                }
            } else {
                ImageError::SelectsEverything {
                    selection,
                    pixels,
                    brightness,
                }
            });
        }
        let w = sums.w;
        if w <= 0.0 {
            // only reachable for a selection that weighs every pixel 0, which selects them all
            return Err(ImageError::Invalid(format!(
                "the {} selected pixels weigh nothing",
                sums.count
            )));
        }
        let (mx, my) = (sums.x / w, sums.y / w);
        let own = w / 12.0;
        Ok(Self {
            width: raster.width(),
            height: raster.height(),
            count: sums.count,
            weight: w,
            centre: [
                mx + 0.5 * raster.width() as Real,
                my + 0.5 * raster.height() as Real,
            ],
            spread: [
                sums.xx - mx * sums.x + own,
                sums.yy - my * sums.y + own,
                sums.xy - mx * sums.y,
            ],
        })
    }

    /// The fraction of the image's pixels that are selected.
    pub fn fraction(&self) -> Real {
        self.count as Real / (self.width * self.height) as Real
    }

    /// The area of the selected pixels: `count · s²` (m² for `s` in m).
    pub fn area(&self, pixel_size: Real) -> Real {
        self.count as Real * pixel_size * pixel_size
    }

    /// The mass properties of the body as a thin plate in the `xy` plane of `frame` (y up,
    /// `z` out of the image): the mass `total_mass` spread over the pixels in proportion to
    /// their weights, or, when it is `None`, an areal density of 1 per unit weight (mass =
    /// area for a uniform density, in kg for `s` in m). The inertia tensor is about the
    /// centre of mass: `I_xx = ∫ y² dm`, `I_yy = ∫ x² dm`, `I_zz = I_xx + I_yy` (the polar
    /// moment), `I_xy = −∫ x y dm`. Fails when `total_mass` is not positive and finite.
    ///
    /// ```
    /// use mechkit::mass::image::{PixelBody, PixelFrame, Raster, Selection};
    /// use mechkit::mass::Vec3;
    /// // a black 4 × 2 px bar at the bottom-left of a white image, 1 cm pixels, 2 kg
    /// let img = Raster::from_fn(6, 6, |x, y| if x < 4 && y >= 4 { [0.0; 3] } else { [1.0; 3] });
    /// let body = PixelBody::measure(&img, &Selection::default()).unwrap();
    /// let frame = PixelFrame::bottom_left(img.height(), 0.01).unwrap();
    /// let p = body.mass_properties(&frame, Some(2.0)).unwrap();
    /// assert!((p.centre_of_mass - Vec3::new(0.02, 0.01, 0.0)).norm() < 1e-15);
    /// // a 4 cm × 2 cm plate: I_zz = m (a² + b²)/12
    /// assert!((p.inertia[(2, 2)] - 2.0 * (16e-4 + 4e-4) / 12.0).abs() < 1e-15);
    /// ```
    pub fn mass_properties(
        &self,
        frame: &PixelFrame,
        total_mass: Option<Real>,
    ) -> Result<MassProperties, ImageError> {
        let s2 = frame.pixel_size * frame.pixel_size;
        let mass = match total_mass {
            None => self.weight * s2,
            Some(m) if m.is_finite() && m > 0.0 => m,
            Some(m) => {
                return Err(ImageError::Invalid(format!(
                    "the total mass {} must be positive",
                    crate::error::short(m)
                )));
            }
        };
        // mass per unit weight, times the area of a pixel: px² of weight → kg m²
        let k = mass / self.weight * s2;
        let (cxx, cyy) = (k * self.spread[0], k * self.spread[1]);
        // ∫ X Y dm changes sign with y pointing up
        let cxy = -k * self.spread[2];
        let [x, y] = frame.to_physical(self.centre);
        let inertia = Mat3::new(cyy, -cxy, 0.0, -cxy, cxx, 0.0, 0.0, 0.0, cxx + cyy);
        Ok(MassProperties::new(mass, Vec3::new(x, y, 0.0), inertia))
    }
}

/// The weighted sums, row by row: each row's `Σw`, `Σw x`, `Σw x²` in the inner loop, then
/// the row's `y` applied once. Two pixels at a time, in two sets of accumulators, so that
/// the additions of one pixel do not wait for the previous one's.
fn accumulate(raster: &Raster, table: &[(Real, usize)], level: impl Fn(&[u8]) -> usize) -> Sums {
    let x_first = 0.5 - 0.5 * raster.width() as Real;
    let y_first = 0.5 - 0.5 * raster.height() as Real;
    let mut sums = Sums::default();
    for (j, row) in raster.rows().enumerate() {
        let y = y_first + j as Real;
        let mut n = 0usize;
        let (mut s0, mut s1, mut s2) = ([0.0; 2], [0.0; 2], [0.0; 2]);
        let mut x = [x_first, x_first + 1.0];
        let pairs = row.chunks_exact(6);
        let last = pairs.remainder();
        for pair in pairs {
            for (k, px) in pair.chunks_exact(3).enumerate() {
                let (w, selected) = table[level(px)];
                n += selected;
                s0[k] += w;
                let wx = w * x[k];
                s1[k] += wx;
                s2[k] += wx * x[k];
                x[k] += 2.0;
            }
        }
        if !last.is_empty() {
            let (w, selected) = table[level(last)];
            n += selected;
            s0[0] += w;
            s1[0] += w * x[0];
            s2[0] += w * x[0] * x[0];
        }
        let (s0, s1, s2) = (s0[0] + s0[1], s1[0] + s1[1], s2[0] + s2[1]);
        sums.count += n;
        sums.w += s0;
        sums.x += s1;
        sums.y += y * s0;
        sums.xx += s2;
        sums.yy += y * y * s0;
        sums.xy += y * s1;
    }
    sums
}

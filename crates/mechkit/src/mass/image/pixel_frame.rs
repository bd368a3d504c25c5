//! `PixelFrame`: from pixel coordinates (x right, y down) to physical ones (y up).

use super::ImageError;
use crate::Real;

/// Physical coordinates on an image: the side of a pixel and the pixel position of the
/// origin. Pixel coordinates run from the top-left corner of the image, `x` along a row and
/// `y` down the rows, so pixel `(i, j)` covers `[i, i+1] × [j, j+1]` and has its centre at
/// `(i + ½, j + ½)`. Physical coordinates have `y` up:
///
/// `X = (x − x₀) s`,  `Y = (y₀ − y) s`.
///
/// ```
/// use mechkit::mass::image::PixelFrame;
/// // 0.5 mm pixels, origin at the bottom-left corner of a 100-row image
/// let f = PixelFrame::bottom_left(100, 0.5e-3).unwrap();
/// assert_eq!(f.to_physical([10.0, 90.0]), [5e-3, 5e-3]);
/// assert_eq!(f.to_pixel([5e-3, 5e-3]), [10.0, 90.0]);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PixelFrame {
    /// The side of one pixel (m; 1 to measure in pixels).
    pub pixel_size: Real,
    /// The pixel coordinates `(x₀, y₀)` of the physical origin.
    pub origin: [Real; 2],
}

impl PixelFrame {
    /// Pixels of side `pixel_size` with the origin at pixel coordinates `origin`. Fails
    /// unless the size is positive and finite and the origin finite.
    pub fn new(pixel_size: Real, origin: [Real; 2]) -> Result<Self, ImageError> {
        if !(pixel_size.is_finite() && pixel_size > 0.0) {
            return Err(ImageError::Invalid(format!(
                "the pixel size {} must be a positive length",
                crate::error::short(pixel_size)
            )));
        }
        if !origin.iter().all(|c| c.is_finite()) {
            return Err(ImageError::Invalid(format!(
                "the origin ({}, {}) must be finite pixel coordinates",
                crate::error::short(origin[0]),
                crate::error::short(origin[1])
            )));
        }
        Ok(Self { pixel_size, origin })
    }

    /// The origin at the bottom-left corner of an image of `height` rows: `(0, height)`.
    pub fn bottom_left(height: usize, pixel_size: Real) -> Result<Self, ImageError> {
        Self::new(pixel_size, [0.0, height as Real])
    }

    /// Physical coordinates (y up) of pixel coordinates (y down).
    pub fn to_physical(&self, pixel: [Real; 2]) -> [Real; 2] {
        [
            (pixel[0] - self.origin[0]) * self.pixel_size,
            (self.origin[1] - pixel[1]) * self.pixel_size,
        ]
    }

    /// Pixel coordinates of physical ones.
    pub fn to_pixel(&self, physical: [Real; 2]) -> [Real; 2] {
        [
            self.origin[0] + physical[0] / self.pixel_size,
            self.origin[1] - physical[1] / self.pixel_size,
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_and_origins_are_checked() {
        assert!(PixelFrame::new(0.0, [0.0; 2]).is_err());
        assert!(PixelFrame::new(-1.0, [0.0; 2]).is_err());
        assert!(PixelFrame::new(1.0, [Real::NAN, 0.0]).is_err());
        let f = PixelFrame::new(2.0, [3.0, 4.0]).unwrap();
        assert_eq!(f.to_pixel(f.to_physical([7.5, 1.5])), [7.5, 1.5]);
    }
}

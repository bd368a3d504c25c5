//! `Raster`: the pixels of an image, 8 bits per channel, read on a 0–1 scale.

use super::ImageError;
use crate::Real;

/// An RGB image: `width × height` pixels, row by row from the top-left corner, 8 bits per
/// channel. Channel values are read on a 0–1 scale (`byte / 255`).
///
/// ```
/// use mechkit::mass::image::Raster;
/// let r = Raster::from_fn(3, 2, |x, y| if (x, y) == (1, 0) { [0.0; 3] } else { [1.0; 3] });
/// assert_eq!((r.width(), r.height()), (3, 2));
/// assert_eq!(r.rgb(1, 0), [0.0, 0.0, 0.0]);
/// assert_eq!(r.rgb(2, 1), [1.0, 1.0, 1.0]);
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Raster {
    width: usize,
    height: usize,
    rgb: Vec<u8>,
}

impl Raster {
    /// From `3 · width · height` bytes `R, G, B, R, G, B, …`, row by row from the top. Fails
    /// when the image is empty or the length does not match.
    pub fn from_rgb8(width: usize, height: usize, rgb: Vec<u8>) -> Result<Self, ImageError> {
        if width == 0 || height == 0 {
            return Err(ImageError::Invalid(format!(
                "an image of {width} × {height} pixels has no pixels"
            )));
        }
        let expected = width.checked_mul(height).and_then(|n| n.checked_mul(3));
        if expected != Some(rgb.len()) {
            return Err(ImageError::Invalid(format!(
                "{} bytes do not make a {width} × {height} RGB image (3 bytes per pixel)",
                rgb.len()
            )));
        }
        Ok(Self { width, height, rgb })
    }

    /// From `4 · width · height` bytes `R, G, B, A, …`, row by row from the top, each pixel
    /// composed on white by its alpha (`c·a + 255·(1 − a)`, rounded): a transparent pixel is
    /// background, as on the sheet a body is photographed on. Fails as [`Raster::from_rgb8`].
    ///
    /// ```
    /// use mechkit::mass::image::Raster;
    /// // black opaque, black half transparent, black fully transparent
    /// let r = Raster::from_rgba8(3, 1, &[0, 0, 0, 255, 0, 0, 0, 128, 0, 0, 0, 0]).unwrap();
    /// assert_eq!([r.rgb8(0, 0), r.rgb8(1, 0), r.rgb8(2, 0)], [[0; 3], [127; 3], [255; 3]]);
    /// ```
    pub fn from_rgba8(width: usize, height: usize, rgba: &[u8]) -> Result<Self, ImageError> {
        let pixels = width.checked_mul(height);
        if width > 0 && height > 0 && pixels.and_then(|n| n.checked_mul(4)) != Some(rgba.len()) {
            return Err(ImageError::Invalid(format!(
                "{} bytes do not make a {width} × {height} RGBA image (4 bytes per pixel)",
                rgba.len()
            )));
        }
        let mut rgb = Vec::with_capacity(pixels.unwrap_or(0).saturating_mul(3));
        for px in rgba.chunks_exact(4) {
            let alpha = u32::from(px[3]);
            rgb.extend(
                px[..3]
                    .iter()
                    .map(|&c| ((u32::from(c) * alpha + 255 * (255 - alpha) + 127) / 255) as u8),
            );
        }
        Self::from_rgb8(width, height, rgb)
    }

    /// The 8-bit level nearest a channel value on the 0–1 scale (values outside 0–1 are
    /// clamped, NaN is 0): how [`Raster::from_fn`] stores a colour.
    ///
    /// ```
    /// use mechkit::mass::image::Raster;
    /// assert_eq!([Raster::level(0.5), Raster::level(1.2), Raster::level(f64::NAN)], [128, 255, 0]);
    /// ```
    pub fn level(value: Real) -> u8 {
        to_byte(value)
    }

    /// From a function of the pixel `(column, row)` giving `[r, g, b]` on the 0–1 scale, each
    /// rounded to the nearest 8-bit level (values outside 0–1 are clamped).
    ///
    /// # Panics
    /// When `width` or `height` is 0.
    pub fn from_fn(
        width: usize,
        height: usize,
        mut colour: impl FnMut(usize, usize) -> [Real; 3],
    ) -> Self {
        assert!(
            width > 0 && height > 0,
            "Raster::from_fn: an image of {width} × {height} pixels has no pixels"
        );
        let mut rgb = Vec::with_capacity(3 * width * height);
        for y in 0..height {
            for x in 0..width {
                rgb.extend(colour(x, y).map(to_byte));
            }
        }
        Self { width, height, rgb }
    }

    /// Pixels per row.
    pub fn width(&self) -> usize {
        self.width
    }

    /// Rows.
    pub fn height(&self) -> usize {
        self.height
    }

    /// `width · height`.
    pub fn pixels(&self) -> usize {
        self.width * self.height
    }

    /// The colour of pixel `(x, y)` (column, row from the top) on the 0–1 scale.
    ///
    /// # Panics
    /// Outside the image.
    pub fn rgb(&self, x: usize, y: usize) -> [Real; 3] {
        self.rgb8(x, y).map(|b| Real::from(b) / 255.0)
    }

    /// The 8-bit colour of pixel `(x, y)`.
    ///
    /// # Panics
    /// Outside the image.
    pub fn rgb8(&self, x: usize, y: usize) -> [u8; 3] {
        assert!(
            x < self.width && y < self.height,
            "pixel ({x}, {y}) is outside the {} × {} image",
            self.width,
            self.height
        );
        let i = 3 * (y * self.width + x);
        [self.rgb[i], self.rgb[i + 1], self.rgb[i + 2]]
    }

    /// All bytes, `R, G, B` per pixel, row by row from the top.
    pub fn as_rgb8(&self) -> &[u8] {
        &self.rgb
    }

    /// The bytes, writable (same layout as [`Raster::as_rgb8`]).
    pub(crate) fn rgb8_mut(&mut self) -> &mut [u8] {
        &mut self.rgb
    }

    /// The rows, each `3 · width` bytes, from the top.
    pub(crate) fn rows(&self) -> std::slice::ChunksExact<'_, u8> {
        self.rgb.chunks_exact(3 * self.width)
    }
}

/// A 0–1 value as the nearest 8-bit level.
fn to_byte(v: Real) -> u8 {
    (v.clamp(0.0, 1.0) * 255.0).round() as u8
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bytes_must_match_the_size() {
        assert!(Raster::from_rgb8(2, 2, vec![0; 12]).is_ok());
        let e = Raster::from_rgb8(2, 2, vec![0; 11])
            .unwrap_err()
            .to_string();
        assert!(e.contains("11 bytes"), "{e}");
        assert!(Raster::from_rgb8(0, 2, Vec::new()).is_err());
        assert!(Raster::from_rgba8(2, 2, &[0; 16]).is_ok());
        let e = Raster::from_rgba8(2, 2, &[0; 12]).unwrap_err().to_string();
        assert!(e.contains("12 bytes") && e.contains("RGBA"), "{e}");
        assert!(Raster::from_rgba8(0, 2, &[]).is_err());
    }

    #[test]
    fn levels_are_rounded_and_clamped() {
        let r = Raster::from_fn(1, 1, |_, _| [0.5, -1.0, Real::NAN]);
        assert_eq!(r.rgb8(0, 0), [128, 0, 0]);
    }
}

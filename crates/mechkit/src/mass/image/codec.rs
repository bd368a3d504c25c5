//! Reading PNG and JPEG files into a [`Raster`] and writing one as PNG (feature `image`).

use std::io::{Cursor, ErrorKind};
use std::path::Path;

use ::image::codecs::png::PngEncoder;
use ::image::{ExtendedColorType, ImageEncoder, ImageFormat, ImageReader};

use super::{FileFormat, ImageError, PixelBody, Raster, Selection};

impl Raster {
    /// Reads a PNG or JPEG file. Greyscale images become grey RGB; transparent pixels are
    /// shown on white (the usual background of a photo of a body on a sheet); 16-bit
    /// channels are rounded to 8 bits. Any other file fails with what it is (GIF, BMP,
    /// TIFF, WebP, PDF, text, …), found from its first bytes whatever its name.
    pub fn open(path: impl AsRef<Path>) -> Result<Self, ImageError> {
        let path = path.as_ref();
        let bytes =
            crate::csv::read_bounded(path, crate::csv::MAX_DATA_BYTES).map_err(|e| {
                match e.kind() {
                    ErrorKind::NotFound => ImageError::NotFound {
                        path: path.to_path_buf(),
                    },
                    _ => ImageError::Read {
                        path: path.to_path_buf(),
                        message: e.to_string(),
                    },
                }
            })?;
        Self::decode(&bytes, path)
    }

    /// Decodes the bytes of a PNG or JPEG file; `path` names it in errors. An image whose
    /// header claims more than [`MAX_PIXELS`](super::MAX_PIXELS) is refused before decoding.
    pub fn decode(bytes: &[u8], path: impl AsRef<Path>) -> Result<Self, ImageError> {
        Self::decode_at_most(bytes, path, super::MAX_PIXELS)
    }

    /// [`Raster::decode`] with a smaller pixel limit (the fuzz target decodes small images
    /// only: a large one runs the same code longer).
    pub fn decode_at_most(
        bytes: &[u8],
        path: impl AsRef<Path>,
        max_pixels: u64,
    ) -> Result<Self, ImageError> {
        let path = path.as_ref();
        let (format, name) = match FileFormat::sniff(bytes) {
            FileFormat::Png => (ImageFormat::Png, "PNG"),
            FileFormat::Jpeg => (ImageFormat::Jpeg, "JPEG"),
            other => {
                return Err(ImageError::Unsupported {
                    path: path.to_path_buf(),
                    found: other.to_string(),
                });
            }
        };
        let decode_error = |e: ::image::ImageError| ImageError::Decode {
            path: path.to_path_buf(),
            format: name,
            message: e.to_string(),
        };
        // the header first: a few hundred bytes can claim a billion pixels
        let reader = || ImageReader::with_format(Cursor::new(bytes), format);
        // read by hand, so that the decoder's own limits never answer first
        let claimed = match format {
            ImageFormat::Png => super::header::png_size(bytes),
            _ => super::header::jpeg_size(bytes),
        };
        let (width, height) = match claimed {
            Some(size) => size,
            None => reader().into_dimensions().map_err(decode_error)?,
        };
        if u64::from(width) * u64::from(height) > max_pixels.min(super::MAX_PIXELS) {
            return Err(ImageError::TooLarge {
                path: path.to_path_buf(),
                format: name,
                width,
                height,
            });
        }
        let decoded = reader().decode().map_err(decode_error)?;
        let (width, height) = (decoded.width() as usize, decoded.height() as usize);
        Self::from_rgba8(width, height, &decoded.into_rgba8().into_raw())
    }

    /// The image encoded as an 8-bit RGB PNG.
    pub fn to_png(&self) -> Result<Vec<u8>, ImageError> {
        let size = |n: usize| u32::try_from(n).map_err(|e| ImageError::Encode(e.to_string()));
        let mut out = Vec::new();
        PngEncoder::new(&mut out)
            .write_image(
                self.as_rgb8(),
                size(self.width())?,
                size(self.height())?,
                ExtendedColorType::Rgb8,
            )
            .map_err(|e| ImageError::Encode(e.to_string()))?;
        Ok(out)
    }
}

/// The PNG of `raster` with the pixels `selection` marks tinted and the centre of mass of
/// `body` marked ([`Raster::marked`]), for the user to check what was measured.
pub fn marked_png(
    raster: &Raster,
    selection: &Selection,
    body: &PixelBody,
) -> Result<Vec<u8>, ImageError> {
    raster.marked(selection, body.centre).to_png()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Fuzz finding `image/jpeg-bomb-361-megapixels.jpg`: 594 bytes of JPEG whose header
    /// claims 16396 × 22025 pixels. Decoding took 30 s and gigabytes; the header is now read
    /// first and the image refused by its size.
    #[test]
    fn fuzz_jpeg_bomb_is_refused_from_its_header() {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../fuzz/regressions/image/jpeg-bomb-361-megapixels.jpg");
        let bytes = std::fs::read(&path).expect("the saved input");
        assert!(bytes.len() < 1000);
        let e = Raster::decode(&bytes, "bomb.jpg").unwrap_err();
        assert!(
            matches!(
                e,
                ImageError::TooLarge {
                    width: 16396,
                    height: 22025,
                    ..
                }
            ),
            "{e}"
        );
        assert!(e.to_string().contains("361 megapixels"), "{e}");
    }

    #[test]
    fn png_round_trip_and_what_is_not_an_image() {
        let img = Raster::from_fn(7, 5, |x, y| [x as f64 / 6.0, y as f64 / 4.0, 0.5]);
        let png = img.to_png().unwrap();
        assert_eq!(Raster::decode(&png, "x.png").unwrap(), img);
        let e = Raster::decode(b"GIF89a\x07\x00\x05\x00", "ball.png").unwrap_err();
        let text = e.to_string();
        assert!(text.contains("ball.png: this is a GIF image"), "{text}");
        assert!(text.contains("PNG and JPEG"), "{text}");
        let e = Raster::decode(&png[..40], "cut.png")
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("cut.png: a PNG file that cannot be decoded"),
            "{e}"
        );
        let e = Raster::open("/no/such/image.png").unwrap_err().to_string();
        assert!(e.starts_with("/no/such/image.png: no such file"), "{e}");
    }

    #[test]
    fn greyscale_and_transparency() {
        // a 2 × 1 grey+alpha PNG: black opaque, black fully transparent
        let mut bytes = Vec::new();
        PngEncoder::new(&mut bytes)
            .write_image(&[0, 255, 0, 0], 2, 1, ExtendedColorType::La8)
            .unwrap();
        let img = Raster::decode(&bytes, "la.png").unwrap();
        assert_eq!(img.rgb8(0, 0), [0; 3]);
        assert_eq!(img.rgb8(1, 0), [255; 3]);
    }

    #[test]
    fn jpeg_is_read() {
        // a black square on white, through a lossy JPEG: the centre of mass survives
        let img = Raster::from_fn(64, 48, |x, y| {
            if (16..32).contains(&x) && (8..24).contains(&y) {
                [0.0; 3]
            } else {
                [1.0; 3]
            }
        });
        let mut jpeg = Vec::new();
        ::image::codecs::jpeg::JpegEncoder::new_with_quality(&mut jpeg, 90)
            .write_image(img.as_rgb8(), 64, 48, ExtendedColorType::Rgb8)
            .unwrap();
        let back = Raster::decode(&jpeg, "square.jpg").unwrap();
        assert_eq!((back.width(), back.height()), (64, 48));
        let body = PixelBody::measure(&back, &Selection::default()).unwrap();
        assert_eq!(body.count, 256);
        assert!((body.centre[0] - 24.0).abs() < 1e-9 && (body.centre[1] - 16.0).abs() < 1e-9);
    }
}

//! `FileFormat`: what a file is, from its first bytes, so an unreadable file can be named.

use std::fmt;
use std::io::Read as _;
use std::path::Path;

/// The kind of a file as its first bytes ("magic numbers") tell it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum FileFormat {
    /// PNG (`\x89PNG`): read.
    Png,
    /// JPEG (`FF D8 FF`): read.
    Jpeg,
    /// GIF (`GIF87a`, `GIF89a`).
    Gif,
    /// Windows bitmap (`BM`).
    Bmp,
    /// TIFF (`II*\0`, `MM\0*`).
    Tiff,
    /// WebP (`RIFF….WEBP`).
    WebP,
    /// HEIF/HEIC or AVIF (an ISO media `ftyp` box).
    Heif,
    /// JPEG 2000.
    Jpeg2000,
    /// Windows icon.
    Ico,
    /// PDF (`%PDF`).
    Pdf,
    /// An SVG drawing or other XML.
    Svg,
    /// A ZIP archive (also office documents).
    Zip,
    /// Nothing at all.
    Empty,
    /// Readable text.
    Text,
    /// None of these.
    Unknown,
}

impl FileFormat {
    /// The format the first bytes of a file show.
    ///
    /// ```
    /// use mechkit::mass::image::FileFormat;
    /// assert_eq!(FileFormat::sniff(b"GIF89a\x01\x00"), FileFormat::Gif);
    /// assert_eq!(FileFormat::sniff(b"x, y\n1, 2\n"), FileFormat::Text);
    /// ```
    pub fn sniff(bytes: &[u8]) -> Self {
        let starts = |magic: &[u8]| bytes.starts_with(magic);
        let at =
            |offset: usize, magic: &[u8]| bytes.get(offset..offset + magic.len()) == Some(magic);
        if bytes.is_empty() {
            FileFormat::Empty
        } else if starts(b"\x89PNG\r\n\x1a\n") {
            FileFormat::Png
        } else if starts(&[0xFF, 0xD8, 0xFF]) {
            FileFormat::Jpeg
        } else if starts(b"GIF87a") || starts(b"GIF89a") {
            FileFormat::Gif
        } else if starts(b"BM") && bytes.len() >= 14 {
            FileFormat::Bmp
        } else if starts(b"II*\0") || starts(b"MM\0*") {
            FileFormat::Tiff
        } else if starts(b"RIFF") && at(8, b"WEBP") {
            FileFormat::WebP
        } else if at(4, b"ftyp") {
            FileFormat::Heif
        } else if starts(b"\0\0\0\x0cjP  ") || starts(&[0xFF, 0x4F, 0xFF, 0x51]) {
            FileFormat::Jpeg2000
        } else if starts(&[0, 0, 1, 0]) {
            FileFormat::Ico
        } else if starts(b"%PDF") {
            FileFormat::Pdf
        } else if starts(b"PK\x03\x04") {
            FileFormat::Zip
        } else if let Ok(text) = std::str::from_utf8(&bytes[..utf8_prefix(bytes)]) {
            let head = text.trim_start().to_ascii_lowercase();
            if head.starts_with("<svg") || head.starts_with("<?xml") {
                FileFormat::Svg
            } else if text
                .chars()
                .all(|c| !c.is_control() || c.is_ascii_whitespace())
            {
                FileFormat::Text
            } else {
                FileFormat::Unknown
            }
        } else {
            FileFormat::Unknown
        }
    }

    /// Whether mechkit decodes it (PNG and JPEG).
    pub fn is_readable(self) -> bool {
        matches!(self, FileFormat::Png | FileFormat::Jpeg)
    }

    /// Whether the file at `path` is meant as an image (what `com` takes as a photo rather
    /// than a body file): by its extension, of any image format (PNG and JPEG are read, the
    /// others get an error that names their format), or, whatever its name, by the first
    /// bytes of a PNG or JPEG file. An unreadable file is not an image.
    ///
    /// ```
    /// use mechkit::mass::image::FileFormat;
    /// assert!(FileFormat::names_an_image(std::path::Path::new("photo.HEIC")));
    /// assert!(!FileFormat::names_an_image(std::path::Path::new("no/such/body.toml")));
    /// ```
    pub fn names_an_image(path: &Path) -> bool {
        let by_name = path.extension().and_then(|e| e.to_str()).is_some_and(|e| {
            matches!(
                e.to_ascii_lowercase().as_str(),
                "png" | "jpg" | "jpeg" | "gif" | "bmp" | "tif" | "tiff" | "webp" | "heic" | "avif"
            )
        });
        by_name || {
            let mut head = [0u8; 16];
            std::fs::File::open(path)
                .and_then(|mut f| f.read(&mut head))
                .is_ok_and(|n| Self::sniff(&head[..n]).is_readable())
        }
    }
}

/// The length of the first 512 bytes, shortened so a UTF-8 character cut at the end is left
/// out.
fn utf8_prefix(bytes: &[u8]) -> usize {
    let n = bytes.len().min(512);
    match std::str::from_utf8(&bytes[..n]) {
        Err(e) if e.error_len().is_none() => e.valid_up_to(),
        _ => n,
    }
}

impl fmt::Display for FileFormat {
    /// With an article: "a GIF image", "text".
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            FileFormat::Png => "a PNG image",
            FileFormat::Jpeg => "a JPEG image",
            FileFormat::Gif => "a GIF image",
            FileFormat::Bmp => "a BMP image",
            FileFormat::Tiff => "a TIFF image",
            FileFormat::WebP => "a WebP image",
            FileFormat::Heif => "a HEIC/HEIF or AVIF image",
            FileFormat::Jpeg2000 => "a JPEG 2000 image",
            FileFormat::Ico => "a Windows icon",
            FileFormat::Pdf => "a PDF document",
            FileFormat::Svg => "an SVG drawing or XML document",
            FileFormat::Zip => "a ZIP archive",
            FileFormat::Empty => "an empty file",
            FileFormat::Text => "text",
            FileFormat::Unknown => "a file of an unknown format",
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn magic_bytes() {
        let cases: [(&[u8], FileFormat); 12] = [
            (b"\x89PNG\r\n\x1a\n\0\0", FileFormat::Png),
            (&[0xFF, 0xD8, 0xFF, 0xE0], FileFormat::Jpeg),
            (b"GIF87a", FileFormat::Gif),
            (b"BM\x36\0\0\0\0\0\0\0\x36\0\0\0", FileFormat::Bmp),
            (b"MM\0*\0\0\0\x08", FileFormat::Tiff),
            (b"RIFF\0\0\0\0WEBPVP8 ", FileFormat::WebP),
            (b"\0\0\0\x18ftypheic", FileFormat::Heif),
            (b"%PDF-1.7\n", FileFormat::Pdf),
            (b"  <svg xmlns=", FileFormat::Svg),
            (b"", FileFormat::Empty),
            ("température 20 °C\n".as_bytes(), FileFormat::Text),
            (&[0, 159, 146, 150, 1], FileFormat::Unknown),
        ];
        for (bytes, format) in cases {
            assert_eq!(FileFormat::sniff(bytes), format, "{bytes:?}");
        }
        assert!(FileFormat::Jpeg.is_readable() && !FileFormat::Gif.is_readable());
        assert_eq!(FileFormat::Gif.to_string(), "a GIF image");
    }
}

//! What can go wrong between a file and a measured body.

use std::path::PathBuf;

use thiserror::Error;

use super::Brightness;

/// Why an image cannot be read, or why its selected pixels cannot be measured.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum ImageError {
    /// The file does not exist.
    #[error("{}: no such file; check the path (it is relative to the current directory)", path.display())]
    NotFound {
        /// The path as given.
        path: PathBuf,
    },
    /// The file exists but cannot be read.
    #[error("{}: cannot be read: {message}; check that it is a file you may read", path.display())]
    Read {
        /// The path as given.
        path: PathBuf,
        /// The operating system's reason.
        message: String,
    },
    /// The file is not a PNG or JPEG image.
    #[error(
        "{}: this is {found}, which mechkit cannot read: mechkit reads PNG and JPEG images (save or convert the image as PNG)",
        path.display()
    )]
    Unsupported {
        /// The path as given.
        path: PathBuf,
        /// What the first bytes say the file is ("a GIF image", "text", …).
        found: String,
    },
    /// An image with more pixels than mechkit decodes (a photo has tens of megapixels; a few
    /// hundred bytes can claim hundreds).
    #[error(
        "{}: the {format} image is {width} × {height} pixels ({:.0} megapixels), more than mechkit reads ({} megapixels); scale it down (the centre of mass does not need more)",
        path.display(),
        f64::from(*width) * f64::from(*height) / 1e6,
        super::MAX_PIXELS / 1_000_000
    )]
    TooLarge {
        /// The path as given.
        path: PathBuf,
        /// `PNG` or `JPEG`.
        format: &'static str,
        /// Width in pixels, from the file's header.
        width: u32,
        /// Height in pixels.
        height: u32,
    },
    /// A PNG or JPEG file that cannot be decoded (truncated or corrupt).
    #[error(
        "{}: a {format} file that cannot be decoded: {message}; the file is truncated or damaged: export it again as PNG",
        path.display()
    )]
    Decode {
        /// The path as given.
        path: PathBuf,
        /// `PNG` or `JPEG`.
        format: &'static str,
        /// The decoder's reason.
        message: String,
    },
    /// The threshold marks no pixel as the body.
    #[error(
        "the selection {selection} marks none of the {pixels} pixels; {brightness}: choose a threshold inside that range"
    )]
    SelectsNothing {
        /// The selection rule, e.g. `R+G+B < 1.5`.
        selection: String,
        /// Pixels in the image.
        pixels: usize,
        /// The image's brightness on the selection's channel.
        brightness: Brightness,
    },
    /// The threshold marks every pixel as the body: no background is left.
    #[error(
        "the selection {selection} marks every one of the {pixels} pixels, so nothing is background; {brightness}: choose a threshold inside that range"
    )]
    SelectsEverything {
        /// The selection rule.
        selection: String,
        /// Pixels in the image.
        pixels: usize,
        /// The image's brightness on the selection's channel.
        brightness: Brightness,
    },
    /// A value that cannot describe an image, a selection or a scale.
    #[error("{0}")]
    Invalid(String),
    /// The marked image could not be encoded.
    #[error("cannot encode the marked image as PNG: {0}")]
    Encode(String),
}

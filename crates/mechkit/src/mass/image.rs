//! The centre of mass and moment of inertia of a body in a photograph, by the course's
//! method: the pixels darker than a threshold (`R + G + B < 1.5` on a 0–1 scale per channel)
//! are the body; their average position is its centre of mass.
//!
//! - [`Raster`]: the pixels (from bytes, from a function, or `Raster::open` for PNG and
//!   JPEG files with the feature `image`; other files are named from their first bytes,
//!   [`FileFormat`]).
//! - [`Selection`]: the rule, a threshold on a [`Channel`] (the sum or one colour), possibly
//!   inverted (a bright body), with a [`Density`] (uniform, or following the shade).
//! - [`PixelBody`]: the measurement in pixel coordinates (x right, y down, pixel centres at
//!   `+½`): count, weight `W = Σ wᵢ`, centre `r̄ = Σ wᵢ rᵢ / W`, central second moments with
//!   each pixel a uniform square.
//! - [`PixelFrame`]: physical coordinates `X = (x − x₀) s`, `Y = (y₀ − y) s` (y up), and
//!   [`PixelBody::mass_properties`]: the body as a thin plate with its inertia tensor
//!   (`I_zz = Σ mᵢ (|rᵢ − r̄|² + s²/6)`, the polar moment about the axis through the centre
//!   of mass perpendicular to the image).
//! - [`PixelBody::report`] with [`ImageOptions`]: everything measured, as an [`ImageReport`]
//!   (what `mechkit com IMAGE` prints), with the radius of gyration
//!   [`PixelBody::radius_of_gyration`].
//! - [`Raster::marked`]: the selected pixels tinted and the centre of mass marked (and
//!   `marked_png` with the feature `image`).
//!
//! A selection that marks no pixel or every pixel is an error that reports the image's
//! [`Brightness`] on the channel, so a threshold can be chosen.
//!
//! ```
//! use mechkit::mass::image::{PixelBody, Raster, Selection};
//! // a black disk of radius 150 px centred at (200, 200) on a white 400 × 400 image
//! let disk = Raster::from_fn(400, 400, |x, y| {
//!     let (dx, dy) = (x as f64 + 0.5 - 200.0, y as f64 + 0.5 - 200.0);
//!     if dx * dx + dy * dy < 150.0 * 150.0 { [0.0; 3] } else { [1.0; 3] }
//! });
//! let body = PixelBody::measure(&disk, &Selection::default()).unwrap();
//! assert_eq!(body.centre, [200.0, 200.0]);
//! ```

mod brightness;
#[cfg(feature = "image")]
mod codec;
mod error;
mod file_format;
#[cfg(feature = "image")]
mod header;
mod mark;
mod pixel_body;
mod pixel_frame;
mod raster;
mod report;
mod selection;
#[cfg(test)]
mod tests;

/// The most pixels an image file may have: 100 megapixels, above any phone or camera photo
/// the method needs, far below what a decompression bomb claims.
pub const MAX_PIXELS: u64 = 100_000_000;

pub use brightness::{Brightness, PERCENTILES};
#[cfg(feature = "image")]
pub use codec::marked_png;
pub use error::ImageError;
pub use file_format::FileFormat;
pub use mark::{MARK, OUTLINE, TINT};
pub use pixel_body::PixelBody;
pub use pixel_frame::PixelFrame;
pub use raster::Raster;
pub use report::{ImageOptions, ImageReport, PlateAbout, PlateInertia};
pub use selection::{Channel, Density, Selection};

//! Draws a [`mechkit::animation::Animation`] (the library's frames of a run, as data): one
//! frame as SVG ([`frame_svg`]), every frame as a looping GIF ([`gif`]) or an MP4 made by an
//! ffmpeg found on the PATH ([`mp4`]), or a self-contained HTML player ([`html`]).
//!
//! Every picture has the same layout (`layout.rs`): the scene, the view mapped to pixels to
//! scale (letterboxed, centred, y up), between a header with the time stamp and the title and
//! a footer with a scale bar; the energy bars, when the animation has them, in a panel on the
//! right. The SVG is the reference drawing: the GIF and the MP4 rasterise it with the bundled
//! font, and the HTML player draws the same layout on a `<canvas>`.
//!
//! Odd data never panics: a shape with a non-finite number is skipped, a view of no size is
//! widened to one length unit, an animation with no frames is drawn as its background.

mod canvas;
mod gif;
mod html;
mod json;
mod layout;
mod mp4;
mod palette;
mod panel;
mod pictures;
mod svg;
#[cfg(test)]
mod tests;

pub use self::gif::gif;
pub use canvas::Canvas;
pub use html::html;
pub use mp4::{find_ffmpeg, mp4};
pub use svg::frame_svg;

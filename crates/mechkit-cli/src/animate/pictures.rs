//! Every frame rasterised, in order: [`frame_svg`](super::frame_svg)'s drawing through resvg
//! with the bundled font (`plot/raster.rs`), a few frames at a time in parallel.

use anyhow::{Result, anyhow};
use mechkit::animation::Animation;
use rayon::prelude::*;
use resvg::tiny_skia::Pixmap;

use super::canvas::Canvas;
use super::svg::frame_svg;
use crate::plot::raster::pixmap;

/// The most bytes of pictures held at once, whatever the number of threads.
const BATCH_BYTES: usize = 256 << 20;

/// The number of pictures of `anim`: one per frame, or one of the background when it has no
/// frames.
pub(super) fn count(anim: &Animation) -> usize {
    anim.frames.len().max(1)
}

/// Rasterises each picture of `anim` on `canvas`, turns it into a `T` by `convert` (in
/// parallel), and hands the `T`s to `consume` in frame order; stops at the first error.
pub(super) fn for_each<T: Send>(
    anim: &Animation,
    canvas: Canvas,
    convert: impl Fn(&Pixmap) -> T + Sync,
    mut consume: impl FnMut(T) -> Result<()>,
) -> Result<()> {
    let bytes = 4 * canvas.width as usize * canvas.height as usize;
    let batch = (2 * rayon::current_num_threads()).clamp(1, (BATCH_BYTES / bytes).max(1));
    let indices: Vec<usize> = (0..count(anim)).collect();
    for chunk in indices.chunks(batch) {
        let pictures: Vec<Result<T>> = chunk
            .par_iter()
            .map(|&i| {
                let picture = pixmap(&frame_svg(anim, i, canvas), 1.0)
                    .map_err(|e| anyhow!("cannot draw frame {i}: {e}"))?;
                Ok(convert(&picture))
            })
            .collect();
        for picture in pictures {
            consume(picture?)?;
        }
    }
    Ok(())
}

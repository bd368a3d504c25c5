//! The animation as a GIF that loops forever: every frame rasterised, its colours mapped to a
//! fixed palette (`palette.rs`), each frame after the first stored as the rectangle that
//! changed, shown for `1/fps` seconds (in hundredths, at least two: GIF players show shorter
//! delays slowly).

use std::borrow::Cow;

use ::gif::{DisposalMethod, Encoder, Frame, Repeat};
use anyhow::{Context, Result};
use mechkit::animation::Animation;
use resvg::tiny_skia::Pixmap;

use super::canvas::Canvas;
use super::{palette, pictures};

/// The frame rate of an animation whose own is not a positive number.
pub(super) const DEFAULT_FPS: f64 = 25.0;

/// The GIF of `anim`: every frame as [`frame_svg`](super::frame_svg) draws it on `canvas`, at
/// `anim.fps` frames per second, looping forever. Fails on a canvas outside
/// [`Canvas::SIDES`].
pub fn gif(anim: &Animation, canvas: Canvas) -> Result<Vec<u8>> {
    let canvas = canvas.check()?;
    let (width, height) = (canvas.width as u16, canvas.height as u16);
    let mut encoder = Encoder::new(Vec::new(), width, height, &palette::table())
        .and_then(|mut e| e.set_repeat(Repeat::Infinite).map(|()| e))
        .context("cannot start the GIF")?;
    let delays = delays(anim.fps, pictures::count(anim));
    let mut previous: Option<Vec<u8>> = None;
    let mut index = 0;
    pictures::for_each(anim, canvas, indexed, |picture| {
        let changed = match &previous {
            Some(before) => changed(before, &picture, canvas.width as usize),
            None => (0, 0, width, height),
        };
        let frame = Frame {
            delay: delays[index],
            dispose: DisposalMethod::Keep,
            left: changed.0,
            top: changed.1,
            width: changed.2,
            height: changed.3,
            buffer: Cow::Owned(crop(&picture, canvas.width as usize, changed)),
            ..Frame::default()
        };
        encoder
            .write_frame(&frame)
            .with_context(|| format!("cannot write frame {index} of the GIF"))?;
        previous = Some(picture);
        index += 1;
        Ok(())
    })?;
    encoder.into_inner().context("cannot finish the GIF")
}

/// Each of `count` frames' delay in hundredths of a second at `fps` frames per second: the
/// rounded times of the frames' ends apart, so that the GIF keeps time (at 30 fps: 3, 4, 3,
/// 3, 4, …), at least two each.
pub(super) fn delays(fps: f64, count: usize) -> Vec<u16> {
    let fps = if fps.is_finite() && fps > 0.0 {
        fps
    } else {
        DEFAULT_FPS
    };
    let end = |i: usize| (100.0 * i as f64 / fps).round();
    (0..count)
        .map(|i| (end(i + 1) - end(i)).clamp(2.0, f64::from(u16::MAX)) as u16)
        .collect()
}

/// The picture's pixels as indices into the palette (the picture is opaque: its premultiplied
/// colours are its colours).
fn indexed(picture: &Pixmap) -> Vec<u8> {
    picture
        .data()
        .chunks_exact(4)
        .map(|p| palette::nearest(p[0], p[1], p[2]))
        .collect()
}

/// The smallest rectangle `(left, top, width, height)` holding every pixel that differs
/// between the pictures `before` and `after`, `width` pixels wide; one pixel when none does.
fn changed(before: &[u8], after: &[u8], width: usize) -> (u16, u16, u16, u16) {
    let (mut x0, mut y0, mut x1, mut y1) = (usize::MAX, usize::MAX, 0, 0);
    for (y, (a, b)) in before
        .chunks_exact(width)
        .zip(after.chunks_exact(width))
        .enumerate()
    {
        let Some(first) = a.iter().zip(b).position(|(p, q)| p != q) else {
            continue;
        };
        let last = a.iter().zip(b).rposition(|(p, q)| p != q).unwrap_or(first);
        (x0, x1) = (x0.min(first), x1.max(last));
        (y0, y1) = (y0.min(y), y1.max(y));
    }
    if x0 == usize::MAX {
        return (0, 0, 1, 1);
    }
    (
        x0 as u16,
        y0 as u16,
        (x1 - x0 + 1) as u16,
        (y1 - y0 + 1) as u16,
    )
}

/// The pixels of the rectangle `(left, top, width, height)` of a picture `stride` wide.
fn crop(
    picture: &[u8],
    stride: usize,
    (left, top, width, height): (u16, u16, u16, u16),
) -> Vec<u8> {
    let (left, top, width) = (usize::from(left), usize::from(top), usize::from(width));
    picture
        .chunks_exact(stride)
        .skip(top)
        .take(usize::from(height))
        .flat_map(|row| &row[left..left + width])
        .copied()
        .collect()
}

#[cfg(test)]
mod tests {
    use super::{changed, crop, delays};

    #[test]
    fn delays_keep_time_and_are_at_least_two_hundredths() {
        assert_eq!(delays(25.0, 3), [4, 4, 4]);
        assert_eq!(delays(30.0, 6), [3, 4, 3, 3, 4, 3]);
        assert_eq!(delays(100.0, 2), [2, 2]);
        assert_eq!(delays(f64::NAN, 1), [4]);
        assert_eq!(delays(1e-9, 1), [u16::MAX]);
    }

    #[test]
    fn only_the_changed_rectangle_is_kept() {
        let before = [0u8; 12];
        let mut after = before;
        after[5] = 1; // (1, 1) in a 4x3 picture
        after[10] = 2; // (2, 2)
        assert_eq!(changed(&before, &after, 4), (1, 1, 2, 2));
        assert_eq!(crop(&after, 4, (1, 1, 2, 2)), [1, 0, 0, 2]);
        assert_eq!(changed(&before, &before, 4), (0, 0, 1, 1));
    }
}

//! The size of an animation's pictures, and its limits.

use std::ops::RangeInclusive;

use anyhow::{Result, bail};

/// The size of an animation's pictures, in pixels: 640x480 by default, each side within
/// [`Canvas::SIDES`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Canvas {
    /// The width in pixels.
    pub width: u32,
    /// The height in pixels.
    pub height: u32,
}

impl Default for Canvas {
    fn default() -> Self {
        Self {
            width: 640,
            height: 480,
        }
    }
}

impl Canvas {
    /// The sizes a side may have, in pixels.
    pub const SIDES: RangeInclusive<u32> = 64..=4096;

    /// The canvas, or an error saying which side is outside [`Canvas::SIDES`].
    pub fn check(self) -> Result<Self> {
        for (name, side) in [("width", self.width), ("height", self.height)] {
            if !Self::SIDES.contains(&side) {
                bail!(
                    "an animation's {name} is from {} to {} pixels, not {side}",
                    Self::SIDES.start(),
                    Self::SIDES.end()
                );
            }
        }
        Ok(self)
    }

    /// The canvas with each side brought within [`Canvas::SIDES`] (what the drawings that
    /// cannot fail use).
    pub(super) fn clamped(self) -> Self {
        let side = |s: u32| s.clamp(*Self::SIDES.start(), *Self::SIDES.end());
        Self {
            width: side(self.width),
            height: side(self.height),
        }
    }

    /// The canvas with odd sides made one pixel smaller (what a yuv420p video needs).
    pub(super) fn even(self) -> Self {
        Self {
            width: self.width & !1,
            height: self.height & !1,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Canvas;

    #[test]
    fn sides_outside_the_limits_are_refused_and_clamped() {
        assert!(Canvas::default().check().is_ok());
        let big = Canvas {
            width: 5000,
            height: 480,
        };
        let e = big.check().unwrap_err().to_string();
        assert!(
            e.contains("width") && e.contains("5000") && e.contains("4096"),
            "{e}"
        );
        let small = Canvas {
            width: 640,
            height: 10,
        };
        assert!(small.check().unwrap_err().to_string().contains("height"));
        assert_eq!(
            big.clamped(),
            Canvas {
                width: 4096,
                height: 480
            }
        );
        let odd = Canvas {
            width: 641,
            height: 481,
        };
        assert_eq!(odd.even(), Canvas::default());
    }
}

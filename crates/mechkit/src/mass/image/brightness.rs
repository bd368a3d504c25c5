//! `Brightness`: the range of an image's values on a channel, to choose a threshold from.

use std::fmt;

use super::{Channel, Raster};
use crate::Real;

/// The percentiles [`Brightness`] reports.
pub const PERCENTILES: [u8; 5] = [1, 10, 50, 90, 99];

/// The distribution of an image's values on one channel: the smallest, the largest and the
/// percentiles in [`PERCENTILES`] (nearest rank on the 8-bit levels).
///
/// ```
/// use mechkit::mass::image::{Brightness, Channel, Raster};
/// // a left-to-right grey ramp of 256 levels
/// let ramp = Raster::from_fn(256, 1, |x, _| [x as f64 / 255.0; 3]);
/// let b = Brightness::of(&ramp, Channel::Red);
/// assert_eq!((b.min, b.max), (0.0, 1.0));
/// assert_eq!(b.percentiles[2], (50, 127.0 / 255.0)); // the median
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Brightness {
    /// The channel the values are on.
    pub channel: Channel,
    /// The darkest value.
    pub min: Real,
    /// The brightest value.
    pub max: Real,
    /// `(p, value)`: `p` % of the pixels have at most this value.
    pub percentiles: Vec<(u8, Real)>,
}

impl Brightness {
    /// The values of every pixel of `raster` on `channel`.
    pub fn of(raster: &Raster, channel: Channel) -> Self {
        let mut histogram = vec![0usize; channel.levels()];
        for px in raster.as_rgb8().chunks_exact(3) {
            histogram[channel.level(px)] += 1;
        }
        let n = raster.pixels();
        // the value at or below which `count` pixels lie (nearest rank)
        let level_of_rank = |rank: usize| {
            let mut seen = 0;
            for (level, &h) in histogram.iter().enumerate() {
                seen += h;
                if seen >= rank {
                    return Channel::value_of_level(level);
                }
            }
            Channel::value_of_level(histogram.len() - 1)
        };
        let min = level_of_rank(1);
        let max = level_of_rank(n);
        let percentiles = PERCENTILES
            .iter()
            .map(|&p| (p, level_of_rank((usize::from(p) * n).div_ceil(100).max(1))))
            .collect();
        Self {
            channel,
            min,
            max,
            percentiles,
        }
    }
}

impl fmt::Display for Brightness {
    /// `the brightness R+G+B goes from 0.2 to 3 (1 %: 0.25, 10 %: …, 99 %: 2.98)`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "the brightness {} of the pixels goes from {} to {} (percentiles",
            self.channel.symbol(),
            round3(self.min),
            round3(self.max)
        )?;
        for (i, (p, v)) in self.percentiles.iter().enumerate() {
            let sep = if i == 0 { " " } else { ", " };
            write!(f, "{sep}{p} %: {}", round3(*v))?;
        }
        write!(f, ")")
    }
}

/// Three decimals, enough to choose a threshold (levels are 1/255 apart).
fn round3(v: Real) -> Real {
    (v * 1000.0).round() / 1000.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_two_tone_image() {
        // 90 % white, 10 % black
        let r = Raster::from_fn(10, 10, |x, _| if x == 0 { [0.0; 3] } else { [1.0; 3] });
        let b = Brightness::of(&r, Channel::Sum);
        assert_eq!((b.min, b.max), (0.0, 3.0));
        assert_eq!(b.percentiles[1], (10, 0.0));
        assert_eq!(b.percentiles[2], (50, 3.0));
        let text = b.to_string();
        assert!(
            text.contains("from 0 to 3") && text.contains("10 %: 0,"),
            "{text}"
        );
    }
}

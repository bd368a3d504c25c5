//! Which pixels are the body and how much each weighs: a threshold on a brightness channel,
//! optionally inverted, with a uniform density or one that follows the shade.

use std::fmt;

use super::ImageError;
use crate::Real;

/// The brightness a threshold is applied to, from the 0–1 channel values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[non_exhaustive]
pub enum Channel {
    /// `R + G + B`, from 0 (black) to 3 (white): the course's choice.
    #[default]
    Sum,
    /// `R`, 0 to 1.
    Red,
    /// `G`, 0 to 1.
    Green,
    /// `B`, 0 to 1.
    Blue,
}

impl Channel {
    /// Every channel.
    pub const ALL: [Channel; 4] = [Channel::Sum, Channel::Red, Channel::Green, Channel::Blue];

    /// The short name: `sum`, `r`, `g`, `b`.
    pub fn name(self) -> &'static str {
        match self {
            Channel::Sum => "sum",
            Channel::Red => "r",
            Channel::Green => "g",
            Channel::Blue => "b",
        }
    }

    /// By name: `sum`, `r`, `g`, `b` (or `red`, `green`, `blue`), any case.
    pub fn parse(text: &str) -> Result<Self, ImageError> {
        let t = text.trim().to_ascii_lowercase();
        Channel::ALL
            .into_iter()
            .find(|c| {
                c.name() == t
                    || c.symbol().eq_ignore_ascii_case(&t)
                    || c.colour_name() == Some(t.as_str())
            })
            .ok_or_else(|| {
                ImageError::Invalid(format!(
                    "unknown channel `{text}`: use sum (R+G+B), r, g or b"
                ))
            })
    }

    /// How the value is written in a rule: `R+G+B`, `R`, `G`, `B`.
    pub fn symbol(self) -> &'static str {
        match self {
            Channel::Sum => "R+G+B",
            Channel::Red => "R",
            Channel::Green => "G",
            Channel::Blue => "B",
        }
    }

    fn colour_name(self) -> Option<&'static str> {
        match self {
            Channel::Sum => None,
            Channel::Red => Some("red"),
            Channel::Green => Some("green"),
            Channel::Blue => Some("blue"),
        }
    }

    /// The value of white: 3 for the sum, 1 for one channel.
    pub fn max(self) -> Real {
        match self {
            Channel::Sum => 3.0,
            _ => 1.0,
        }
    }

    /// Half of white: 1.5 for the sum (the course's rule), 0.5 for one channel.
    pub fn default_threshold(self) -> Real {
        0.5 * self.max()
    }

    /// The number of distinct 8-bit levels: 766 for the sum, 256 for one channel.
    pub(crate) fn levels(self) -> usize {
        match self {
            Channel::Sum => 3 * 255 + 1,
            _ => 256,
        }
    }

    /// The 8-bit level of a pixel's bytes (`0..levels()`).
    #[inline]
    pub(crate) fn level(self, px: &[u8]) -> usize {
        match self {
            Channel::Sum => usize::from(px[0]) + usize::from(px[1]) + usize::from(px[2]),
            Channel::Red => usize::from(px[0]),
            Channel::Green => usize::from(px[1]),
            Channel::Blue => usize::from(px[2]),
        }
    }

    /// The value of a level on the 0–1 (per channel) scale.
    pub(crate) fn value_of_level(level: usize) -> Real {
        level as Real / 255.0
    }

    /// The value of an 8-bit colour on this channel (0–3 for the sum, 0–1 otherwise).
    pub fn value(self, rgb: [u8; 3]) -> Real {
        Self::value_of_level(self.level(&rgb))
    }
}

/// How much each selected pixel weighs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum Density {
    /// Every selected pixel weighs 1: a uniform plate.
    #[default]
    Uniform,
    /// The density follows the shade: a pixel of value `v` weighs its darkness `1 − v/max`
    /// (1 for black, 0 for white), or its lightness `v/max` when the selection is inverted
    /// (the body is bright). It does not depend on the threshold, which only selects.
    Darkness,
}

/// The rule that marks the body's pixels: `value < threshold` on a channel (the course's
/// `R + G + B < 1.5`), or `value ≥ threshold` when inverted (a bright body on a dark
/// background; exactly the pixels the plain rule leaves out), with a [`Density`].
///
/// ```
/// use mechkit::mass::image::{Channel, Density, Selection};
/// let course = Selection::default();
/// assert!(course.contains(1.2) && !course.contains(1.5));
/// let bright = Selection::new(Channel::Red).threshold(0.8).inverted(true);
/// assert!(bright.contains(0.8) && !bright.contains(0.5));
/// let shade = Selection::default().density(Density::Darkness);
/// assert_eq!(shade.weight(0.75), 0.75); // 1 - 0.75/3
/// assert_eq!(shade.weight(2.0), 0.0); // not selected
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Selection {
    /// The brightness compared.
    pub channel: Channel,
    /// The threshold, on the channel's scale.
    pub threshold: Real,
    /// Whether the body is the bright pixels (`value ≥ threshold`).
    pub invert: bool,
    /// How selected pixels are weighted.
    pub density: Density,
}

impl Default for Selection {
    /// The course's rule: `R + G + B < 1.5`, uniform density.
    fn default() -> Self {
        Self::new(Channel::Sum)
    }
}

impl Selection {
    /// Dark pixels on `channel` with its default threshold (half of white), uniform density.
    pub fn new(channel: Channel) -> Self {
        Self {
            channel,
            threshold: channel.default_threshold(),
            invert: false,
            density: Density::Uniform,
        }
    }

    /// The selection a front's options describe: a channel, a threshold (the channel's
    /// default when None), inverted or not, and a density that follows the shade or not.
    ///
    /// # Errors
    /// A threshold that is not a finite number.
    pub fn from_options(
        channel: Channel,
        threshold: Option<Real>,
        invert: bool,
        density_from_darkness: bool,
    ) -> Result<Self, ImageError> {
        let selection = Self::new(channel)
            .threshold(threshold.unwrap_or(channel.default_threshold()))
            .inverted(invert)
            .density(if density_from_darkness {
                Density::Darkness
            } else {
                Density::Uniform
            });
        selection.check()?;
        Ok(selection)
    }

    /// With another threshold.
    #[must_use]
    pub fn threshold(mut self, threshold: Real) -> Self {
        self.threshold = threshold;
        self
    }

    /// Bright pixels are the body (`true`) or dark ones (`false`).
    #[must_use]
    pub fn inverted(mut self, invert: bool) -> Self {
        self.invert = invert;
        self
    }

    /// With another density rule.
    #[must_use]
    pub fn density(mut self, density: Density) -> Self {
        self.density = density;
        self
    }

    /// Fails when the threshold is not a finite number.
    pub fn check(&self) -> Result<(), ImageError> {
        if self.threshold.is_finite() {
            Ok(())
        } else {
            Err(ImageError::Invalid(format!(
                "the threshold {} is not a finite number",
                self.threshold
            )))
        }
    }

    /// Whether a pixel of this value (on the channel's scale) is part of the body.
    pub fn contains(&self, value: Real) -> bool {
        if self.invert {
            value >= self.threshold
        } else {
            value < self.threshold
        }
    }

    /// The weight of a pixel of this value: 0 outside the body, else 1 or its shade.
    pub fn weight(&self, value: Real) -> Real {
        if !self.contains(value) {
            return 0.0;
        }
        let lightness = (value / self.channel.max()).clamp(0.0, 1.0);
        match (self.density, self.invert) {
            (Density::Uniform, _) => 1.0,
            (Density::Darkness, false) => 1.0 - lightness,
            (Density::Darkness, true) => lightness,
        }
    }

    /// Whether each 8-bit level is selected, and its weight (indexed by
    /// [`Channel::level`]).
    pub(crate) fn table(&self) -> (Vec<bool>, Vec<Real>) {
        (0..self.channel.levels())
            .map(|l| {
                let v = Channel::value_of_level(l);
                (self.contains(v), self.weight(v))
            })
            .unzip()
    }
}

impl fmt::Display for Selection {
    /// The rule as written: `R+G+B < 1.5`, `R ≥ 0.8`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let op = if self.invert { "≥" } else { "<" };
        write!(
            f,
            "{} {op} {}",
            self.channel.symbol(),
            crate::error::short(self.threshold)
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn channels_by_name() {
        for c in Channel::ALL {
            assert_eq!(Channel::parse(c.name()).unwrap(), c);
        }
        assert_eq!(Channel::parse(" Green ").unwrap(), Channel::Green);
        assert_eq!(Channel::parse("R+G+B").unwrap(), Channel::Sum);
        let e = Channel::parse("hue").unwrap_err().to_string();
        assert!(e.contains("sum (R+G+B), r, g or b"), "{e}");
    }

    #[test]
    fn inverting_selects_exactly_the_rest() {
        for c in Channel::ALL {
            let s = Selection::new(c).threshold(0.3 * c.max());
            let (plain, _) = s.table();
            let (flipped, _) = s.inverted(true).table();
            assert!(plain.iter().zip(&flipped).all(|(a, b)| a != b));
        }
    }

    #[test]
    fn darkness_weights_black_fully_and_white_not_at_all() {
        let s = Selection::new(Channel::Blue)
            .threshold(2.0)
            .density(Density::Darkness);
        assert_eq!(s.weight(0.0), 1.0);
        assert_eq!(s.weight(1.0), 0.0);
        assert_eq!(s.inverted(true).weight(1.0), 0.0); // 1 < 2: not selected
        assert_eq!(s.threshold(0.0).inverted(true).weight(0.25), 0.25);
        assert_eq!(s.to_string(), "B < 2");
        assert!(s.threshold(Real::NAN).check().is_err());
    }
}

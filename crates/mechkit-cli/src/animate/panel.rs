//! The energy panel on the right of the scene: a vertical axis over the energies' range (its
//! ends and zero labelled), one bar per energy from zero to its value, its label under it,
//! the unit in the heading.

use mechkit::animation::{Colour, EnergyBars};
use serde::Serialize;

use super::layout::{Align, FAINT_INK, INK, Rect, Text, text};

/// A bar with no colour of its own.
const GREY: Colour = Colour(0x99, 0x99, 0x99);

/// The energy panel: a vertical axis from `lo` (at `bottom`) to `hi` (at `top`) and one bar
/// per label.
#[derive(Debug, Clone, Serialize)]
pub(super) struct Panel {
    /// The pixel column of the line between the scene and the panel.
    pub separator: f64,
    pub heading: Text,
    /// The pixel column of the axis.
    pub axis: f64,
    pub top: f64,
    pub bottom: f64,
    pub lo: f64,
    pub hi: f64,
    /// The right end of the zero line.
    pub right: f64,
    pub ticks: Vec<Text>,
    pub bars: Vec<Bar>,
}

impl Panel {
    /// The pixel row of the energy `v`, kept within the axis.
    pub fn y(&self, v: f64) -> f64 {
        let v = v.clamp(self.lo, self.hi);
        self.bottom - (v - self.lo) / (self.hi - self.lo) * (self.bottom - self.top)
    }
}

/// One energy bar's column and label.
#[derive(Debug, Clone, Serialize)]
pub(super) struct Bar {
    pub x0: f64,
    pub x1: f64,
    pub colour: Colour,
    pub label: Text,
}

/// The energy panel on the right of `scene`, to the picture's right edge `width`.
pub(super) fn panel(bars: &EnergyBars, scene: Rect, width: f64, f: f64) -> Panel {
    let (lo, hi) = energy_range(bars.range);
    let left = scene.x1;
    let axis = left + 3.4 * f;
    let right = width - 0.6 * f;
    let (top, bottom) = (scene.y0 + 0.5 * f, scene.y1 - 0.5 * f);
    let heading = if bars.unit.trim().is_empty() {
        "Energy".to_string()
    } else {
        format!("Energy ({})", bars.unit)
    };
    let mut panel = Panel {
        separator: left,
        heading: text(
            left.midpoint(width),
            1.5 * f,
            0.85 * f,
            Align::Center,
            FAINT_INK,
            &heading,
        ),
        axis,
        top,
        bottom,
        lo,
        hi,
        right,
        ticks: Vec::new(),
        bars: Vec::new(),
    };
    let mut values = vec![hi, lo];
    if lo < 0.0 && (panel.y(0.0) - top).min(bottom - panel.y(0.0)) > 1.2 * f {
        values.push(0.0);
    }
    panel.ticks = values
        .into_iter()
        .map(|v| {
            let y = panel.y(v) + 0.3 * f;
            text(axis - 0.3 * f, y, 0.75 * f, Align::Right, INK, &short(v))
        })
        .collect();
    let first = axis + 0.4 * f;
    let slot = (right - first) / bars.labels.len().max(1) as f64;
    panel.bars = (bars.labels.iter().enumerate())
        .map(|(i, label)| {
            let middle = first + (i as f64 + 0.5) * slot;
            Bar {
                x0: middle - 0.3 * slot,
                x1: middle + 0.3 * slot,
                colour: bars.colours.get(i).copied().unwrap_or(GREY),
                label: text(
                    middle,
                    bottom + 1.5 * f,
                    0.85 * f,
                    Align::Center,
                    INK,
                    label,
                ),
            }
        })
        .collect();
    panel
}

/// The energy scale's ends: the range, widened to hold zero, one unit when it is empty.
fn energy_range((lo, hi): (f64, f64)) -> (f64, f64) {
    let lo = if lo.is_finite() { lo.min(0.0) } else { 0.0 };
    let hi = if hi.is_finite() { hi.max(0.0) } else { 0.0 };
    if hi - lo > 0.0 && (hi - lo).is_finite() {
        (lo, hi)
    } else if lo < 0.0 {
        (lo, lo + 1.0)
    } else {
        (0.0, 1.0)
    }
}

/// `v` to three significant digits: `12.3`, `0.00456`, `-1.5e6`.
fn short(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return if v == 0.0 { "0".into() } else { format!("{v}") };
    }
    let magnitude = v.abs().log10().floor() as i32;
    if (-3..5).contains(&magnitude) {
        let decimals = (2 - magnitude).max(0) as usize;
        let s = format!("{v:.decimals$}");
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    } else {
        crate::plot::axes::scientific(v)
    }
}

#[cfg(test)]
mod tests {
    use super::{energy_range, short};

    #[test]
    fn ticks_are_short_and_the_range_holds_zero() {
        assert_eq!(short(12.345), "12.3");
        assert_eq!(short(-0.004_567), "-0.00457");
        assert_eq!(short(1500.0), "1500");
        assert_eq!(short(2.5e6), "2.5e6");
        assert_eq!(energy_range((f64::NAN, 0.0)), (0.0, 1.0));
        assert_eq!(energy_range((-2.0, -1.0)), (-2.0, 0.0));
    }
}

//! The picture of a measurement: the selected pixels tinted and the centre of mass marked,
//! so the user sees what was measured.

use super::{Raster, Selection};
use crate::Real;

/// The tint blended half and half into the selected pixels.
pub const TINT: [u8; 3] = [255, 96, 0];
/// The colour of the centre-of-mass mark.
pub const MARK: [u8; 3] = [0, 70, 255];
/// The outline around the mark, so it shows on dark and bright pixels alike.
pub const OUTLINE: [u8; 3] = [255, 255, 255];

impl Raster {
    /// A copy with the pixels `selection` marks blended half and half with [`TINT`] (the
    /// others unchanged) and a cross in a circle at `centre` (pixel coordinates, y down) in
    /// [`MARK`] with an [`OUTLINE`]. The mark scales with the image: arms of
    /// `max(6, min(w, h)/12)` px, lines `max(1, min(w, h)/200)` px wide.
    ///
    /// ```
    /// use mechkit::mass::image::{Raster, Selection, MARK, TINT};
    /// let img = Raster::from_fn(40, 40, |x, _| if x < 20 { [0.0; 3] } else { [1.0; 3] });
    /// let marked = img.marked(&Selection::default(), [10.0, 20.0]);
    /// assert_eq!(marked.rgb8(10, 20), MARK);
    /// assert_eq!(marked.rgb8(1, 1), TINT.map(|c| c / 2)); // black, tinted
    /// assert_eq!(marked.rgb8(39, 39), [255; 3]); // background, unchanged
    /// ```
    #[must_use]
    pub fn marked(&self, selection: &Selection, centre: [Real; 2]) -> Raster {
        let (selected, _) = selection.table();
        let mut out = self.clone();
        let channel = selection.channel;
        for px in out.rgb8_mut().chunks_exact_mut(3) {
            if selected[channel.level(px)] {
                for (c, t) in px.iter_mut().zip(TINT) {
                    *c = c.midpoint(t);
                }
            }
        }
        out.draw_mark(centre);
        out
    }

    fn draw_mark(&mut self, centre: [Real; 2]) {
        let size = self.width().min(self.height()) as Real;
        let arm = (size / 12.0).max(6.0);
        let half = 0.5 * (size / 200.0).round().max(1.0);
        let radius = 0.6 * arm;
        let edge = half.max(1.0);
        let reach = arm + edge + 1.0;
        let span = |c: Real, n: usize| {
            let lo = (c - reach).floor().max(0.0) as usize;
            let hi = ((c + reach).ceil().max(0.0) as usize).min(n);
            lo..hi
        };
        for j in span(centre[1], self.height()) {
            for i in span(centre[0], self.width()) {
                let dx = i as Real + 0.5 - centre[0];
                let dy = j as Real + 0.5 - centre[1];
                let on = |w: Real, extra: Real| {
                    let cross = (dx.abs() <= w && dy.abs() <= arm + extra)
                        || (dy.abs() <= w && dx.abs() <= arm + extra);
                    cross || (dx.hypot(dy) - radius).abs() <= w
                };
                let colour = if on(half, 0.0) {
                    MARK
                } else if on(half + edge, edge) {
                    OUTLINE
                } else {
                    continue;
                };
                let k = 3 * (j * self.width() + i);
                self.rgb8_mut()[k..k + 3].copy_from_slice(&colour);
            }
        }
    }
}

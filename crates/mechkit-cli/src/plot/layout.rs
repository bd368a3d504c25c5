//! Where things go on a chart: the parts of a curve inside the shown range, and the corner
//! for the legend.

use mechkit::figure::{PlotData, Series};
use plotters::prelude::SeriesLabelPosition;

/// Whether the curve `s` of `plot` has a legend entry: it has a label, and is not named by a
/// colour bar instead (a value on the plot's colour scale).
pub(super) fn in_legend(plot: &PlotData, s: &Series) -> bool {
    !s.label.is_empty() && (plot.colour_scale.is_none() || s.value.is_none())
}

/// The parts of the polyline `points` inside `y0 ≤ y ≤ y1`, each a polyline: a segment that
/// crosses a bound ends (or starts) on it, and a non-finite point breaks the line. Points are
/// never moved onto the bound (a clamped curve would show a plateau that is not in the data).
pub(super) fn clip_to_band(points: &[(f64, f64)], (y0, y1): (f64, f64)) -> Vec<Vec<(f64, f64)>> {
    let mut pieces: Vec<Vec<(f64, f64)>> = Vec::new();
    let mut current: Vec<(f64, f64)> = Vec::new();
    let flush = |current: &mut Vec<(f64, f64)>, pieces: &mut Vec<Vec<(f64, f64)>>| {
        if !current.is_empty() {
            pieces.push(std::mem::take(current));
        }
    };
    let inside = |y: f64| (y0..=y1).contains(&y);
    let mut previous: Option<(f64, f64)> = None;
    for &p in points {
        if !(p.0.is_finite() && p.1.is_finite()) {
            flush(&mut current, &mut pieces);
            previous = None;
            continue;
        }
        let Some(a) = previous.replace(p) else {
            if inside(p.1) {
                current.push(p);
            }
            continue;
        };
        // the parameters t in [0, 1] of the segment a → p inside the band
        let dy = p.1 - a.1;
        let (t0, t1) = if dy == 0.0 {
            if inside(a.1) { (0.0, 1.0) } else { (1.0, 0.0) }
        } else {
            let (ta, tb) = ((y0 - a.1) / dy, (y1 - a.1) / dy);
            (ta.min(tb).max(0.0), ta.max(tb).min(1.0))
        };
        if t0 > t1 {
            flush(&mut current, &mut pieces);
            continue;
        }
        // a point on the segment, in the band (from −2.7e169 to −2.4e151 against a band of
        // 1e49 the crossing parameter rounds to exactly 1, and the far end is not in the band)
        let at = |t: f64| {
            if t == 1.0 && inside(p.1) {
                p
            } else {
                (a.0 + t * (p.0 - a.0), (a.1 + t * dy).clamp(y0, y1))
            }
        };
        if t0 > 0.0 || current.is_empty() {
            // entering the band: a new piece
            flush(&mut current, &mut pieces);
            current.push(if t0 == 0.0 && inside(a.1) { a } else { at(t0) });
        }
        current.push(at(t1));
        if t1 < 1.0 {
            flush(&mut current, &mut pieces);
        }
    }
    flush(&mut current, &mut pieces);
    pieces
}

/// The corner of the plotting area where the legend covers the least of the data: the
/// legend's box is estimated from its entries (series with a legend entry, the `markers`
/// labels, the bands), its longest label and the type's size (`text`, the style's factor on
/// it, in a plotting area of `area` plot pixels), and the curves' points (with their segments
/// sampled) and the markers are counted in each corner's box; upper right wins ties, then
/// upper left, lower right, lower left. On a `log` vertical axis the points are placed by
/// their logarithm.
pub(super) fn legend_corner(
    plot: &PlotData,
    markers: &[&str],
    ((x0, x1), (y0, y1)): ((f64, f64), (f64, f64)),
    log: bool,
    (text, (width, height)): (f64, (f64, f64)),
) -> SeriesLabelPosition {
    let mut labels: Vec<&str> = plot
        .series
        .iter()
        .filter(|s| in_legend(plot, s))
        .map(|s| s.label.as_str())
        .chain(markers.iter().copied())
        .collect();
    for b in &plot.bands {
        if !labels.contains(&b.label.as_str()) {
            labels.push(&b.label);
        }
    }
    let longest = labels.iter().map(|l| l.chars().count()).max().unwrap_or(0);
    // on paper an entry is about 20 pixels high and a character of the labels' font 8 wide
    let w = (text * (40.0 + 8.0 * longest as f64) / width).min(0.9);
    let h = (text * (12.0 + 20.0 * labels.len() as f64) / height).min(0.9);
    let map = |y: f64| if log { y.log10() } else { y };
    let (y0, y1) = (map(y0), map(y1));
    let (sx, sy) = (x1 - x0, y1 - y0);
    let mut points: Vec<(f64, f64)> = plot.markers.iter().map(|m| m.at).collect();
    for s in &plot.series {
        for pair in s.points.windows(2) {
            let ((ax, ay), (bx, by)) = (pair[0], pair[1]);
            for k in 0..8 {
                let t = f64::from(k) / 8.0;
                points.push((ax + t * (bx - ax), ay + t * (by - ay)));
            }
        }
        points.extend(s.points.last());
    }
    let fractions: Vec<(f64, f64)> = points
        .iter()
        .filter(|(x, y)| x.is_finite() && y.is_finite())
        .map(|&(x, y)| ((x - x0) / sx, (map(y) - y0) / sy))
        .filter(|(x, y)| x.is_finite() && y.is_finite())
        .collect();
    let corners = [
        (
            SeriesLabelPosition::UpperRight,
            (1.0 - w, 1.0),
            (1.0 - h, 1.0),
        ),
        (SeriesLabelPosition::UpperLeft, (0.0, w), (1.0 - h, 1.0)),
        (SeriesLabelPosition::LowerRight, (1.0 - w, 1.0), (0.0, h)),
        (SeriesLabelPosition::LowerLeft, (0.0, w), (0.0, h)),
    ];
    let covered = |(fx, fy): ((f64, f64), (f64, f64))| {
        fractions
            .iter()
            .filter(|(x, y)| (fx.0..=fx.1).contains(x) && (fy.0..=fy.1).contains(y))
            .count()
    };
    corners
        .into_iter()
        .min_by_key(|&(_, fx, fy)| covered((fx, fy)))
        .map_or(SeriesLabelPosition::UpperRight, |(p, _, _)| p)
}

#[cfg(test)]
mod tests {
    use mechkit::figure::{PlotData, Series};
    use plotters::prelude::SeriesLabelPosition;

    use super::{clip_to_band, legend_corner};

    /// The paper style's type in its plotting area.
    const PAPER: (f64, (f64, f64)) = (1.0, (790.0, 490.0));

    /// Found by the `command_line` target (2026-12-05): `mechkit potential
    /// "U0-((a/r)^60-(b/r)^6)"` has U = −2.7e169 at r = 0.0015 and −2.4e151 at 0.003, against
    /// a band of 1e49: the segment's crossing parameter rounds to exactly 1, and its end, far
    /// outside, was kept; plotters overflowed mapping it to a pixel (a panic with overflow
    /// checks). Every point of every piece lies in the band.
    #[test]
    fn fuzz_a_crossing_that_rounds_to_the_far_end_stays_in_the_band() {
        let band = (-1.721_630_191_351_698_3e49, 7.485_348_658_050_863e47);
        let curve = [
            (0.0015, -2.719_721_638_936_43e169),
            (0.003, -2.358_982_487_592_571_2e151),
            (0.0045, -1.0e49),
            (0.006, -1.0e40),
        ];
        let pieces = clip_to_band(&curve, band);
        assert!(!pieces.is_empty());
        for p in pieces.iter().flatten() {
            assert!((band.0..=band.1).contains(&p.1), "{p:?}");
        }
    }

    #[test]
    fn the_legend_goes_where_it_covers_no_data() {
        // two curves rising to the upper right: the upper left is free
        let rising = |k: f64| {
            (0..=50)
                .map(|i| (f64::from(i) / 50.0, k * f64::from(i) / 50.0))
                .collect()
        };
        let plot = PlotData::new("y(x)", "y_x", "x", "y")
            .with_series(Series::line("a", rising(1.0)))
            .with_series(Series::line("b", rising(0.9)));
        let corner = legend_corner(&plot, &[], ((0.0, 1.0), (0.0, 1.0)), false, PAPER);
        assert!(
            matches!(corner, SeriesLabelPosition::UpperLeft),
            "{corner:?}"
        );
        // a decaying curve from the upper left: the upper right is free, and preferred
        let decaying = (0..=50)
            .map(|i| (f64::from(i) / 50.0, (-5.0 * f64::from(i) / 50.0).exp()))
            .collect();
        let plot = PlotData::new("y(x)", "y_x", "x", "y").with_series(Series::line("c", decaying));
        let corner = legend_corner(&plot, &["marker"], ((0.0, 1.0), (0.0, 1.0)), false, PAPER);
        assert!(
            matches!(corner, SeriesLabelPosition::UpperRight),
            "{corner:?}"
        );
    }

    #[test]
    fn a_curve_is_cut_at_the_band_not_clamped_onto_it() {
        // up through y = 1 and back down: two pieces, the crossings on the bound
        let pts = [(0.0, 0.0), (1.0, 2.0), (2.0, 0.0), (3.0, 0.5)];
        let pieces = clip_to_band(&pts, (-1.0, 1.0));
        assert_eq!(
            pieces,
            vec![
                vec![(0.0, 0.0), (0.5, 1.0)],
                vec![(1.5, 1.0), (2.0, 0.0), (3.0, 0.5)]
            ]
        );
        // wholly outside: nothing; a NaN breaks the line
        assert!(clip_to_band(&[(0.0, 5.0), (1.0, 6.0)], (0.0, 1.0)).is_empty());
        let broken = clip_to_band(
            &[
                (0.0, 0.1),
                (1.0, 0.2),
                (2.0, f64::NAN),
                (3.0, 0.3),
                (4.0, 0.4),
            ],
            (0.0, 1.0),
        );
        assert_eq!(broken.len(), 2);
        // a segment through the whole band from above to below
        let through = clip_to_band(&[(0.0, 3.0), (4.0, -1.0)], (0.0, 2.0));
        assert_eq!(through, vec![vec![(1.0, 2.0), (3.0, 0.0)]]);
    }
}

//! The figures of a potential analysis: the energy diagram (`U(x)` with the energy line,
//! equilibria, turning points, forbidden regions and singular points, on a vertical range that
//! shows the wells rather than a divergence at the edge) and the speed `v(x)` of a released
//! body.

use super::analysis::{AxisUnits, PotentialAnalysis};
use super::diagram::Stability;
use crate::Real;
use crate::figure::{Band, LineStyle, Marker, MarkerShape, PlotData, Series};

impl PotentialAnalysis {
    /// The energy diagram, named `U_<var>` (the file stem): axes labelled with their units
    /// where known (`x [m]`, `U [J]`), else by their names alone.
    pub fn diagram_plot(&self) -> PlotData {
        let d = &self.diagram;
        let x = &self.var;
        // a NaN at each singular point breaks the curve there
        let mut curve: Vec<(Real, Real)> =
            d.x.iter()
                .copied()
                .zip(d.potential.iter().copied())
                .collect();
        for &s in &d.singularities {
            let k = curve.partition_point(|p| p.0 < s);
            curve.insert(k, (s, Real::NAN));
        }
        let mut plot = PlotData::new(
            "energy diagram",
            format!("U_{x}"),
            AxisUnits::label(x, self.units.x.as_deref()),
            AxisUnits::label("U", self.units.potential.as_deref()),
        )
        .with_series(Series::line(format!("U({x})"), curve));
        let (lo, hi) = (d.x[0], d.x[d.x.len() - 1]);
        for e in &d.equilibria {
            let (shape, label) = match e.stability {
                Stability::Stable => (MarkerShape::Filled, "stable equilibrium"),
                Stability::Unstable => (MarkerShape::Open, "unstable equilibrium"),
                Stability::Neutral => (MarkerShape::Cross, "neutral equilibrium"),
            };
            plot.markers.push(Marker {
                at: (e.x, e.potential),
                label: label.into(),
                shape,
            });
        }
        let mut core: Vec<Real> = d.equilibria.iter().map(|e| e.potential).collect();
        if let Some(c) = &d.energy {
            plot.series.push(
                Series::line(
                    format!("E = {}", mechkit_expr::short_fixed(c.energy, 6)),
                    vec![(lo, c.energy), (hi, c.energy)],
                )
                .styled(LineStyle::Dashed),
            );
            for &t in &c.turning_points {
                plot.markers.push(Marker {
                    at: (t, c.energy),
                    label: "turning point".into(),
                    shape: MarkerShape::Triangle,
                });
            }
            for r in c.regions.iter().filter(|r| !r.allowed) {
                plot.bands.push(Band {
                    from: r.from,
                    to: r.to,
                    label: "forbidden (U > E)".into(),
                });
            }
            core.push(c.energy);
        }
        plot.y_limits = y_limits(&d.potential, &core);
        if let Some((y0, _)) = plot.y_limits {
            for &s in &d.singularities {
                plot.markers.push(Marker {
                    at: (s, y0),
                    label: "singular point".into(),
                    shape: MarkerShape::Cross,
                });
            }
        }
        plot
    }

    /// The speed `v(x)` of the released body by the work-energy theorem, named `v_<var>`;
    /// `None` without a body.
    pub fn speed_plot(&self) -> Option<PlotData> {
        let m = self.motion.as_ref()?;
        let x = &self.var;
        Some(
            PlotData::new(
                format!(
                    "speed from the work-energy theorem, m = {}",
                    crate::error::short(m.mass)
                ),
                format!("v_{x}"),
                AxisUnits::label(x, self.units.x.as_deref()),
                AxisUnits::label("v", self.units.speed().as_deref()),
            )
            .with_series(Series::line(
                format!("v({x})"),
                m.diagram
                    .x
                    .iter()
                    .copied()
                    .zip(m.speed.iter().copied())
                    .collect(),
            )),
        )
    }
}

/// The vertical range: the equilibria and the energy line, and the bulk of the curve (its 5th
/// to 95th percentile), so that a curve running off to infinity (a 1/r^12 wall, a pole) is cut
/// instead of flattening the wells.
fn y_limits(u: &[Real], core: &[Real]) -> Option<(Real, Real)> {
    let mut finite: Vec<Real> = u.iter().copied().filter(|v| v.is_finite()).collect();
    if finite.is_empty() {
        return None;
    }
    finite.sort_by(Real::total_cmp);
    #[allow(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        clippy::cast_precision_loss
    )]
    let pick = |q: Real| finite[((finite.len() - 1) as Real * q).round() as usize];
    let (umin, umax) = (finite[0], finite[finite.len() - 1]);
    let lo = core.iter().copied().fold(pick(0.05), Real::min);
    let hi = core.iter().copied().fold(pick(0.95), Real::max);
    let span = (hi - lo)
        .max(1e-12 * hi.abs().max(lo.abs()))
        .max(Real::MIN_POSITIVE);
    Some((
        (lo - 0.15 * span).max(umin - 0.05 * span),
        (hi + 0.15 * span).min(umax + 0.05 * span),
    ))
}

#[cfg(test)]
mod tests {
    use super::super::analysis::{Given, PotentialQuestion, analyse_potential};

    #[test]
    fn axes_have_units_only_where_known() {
        let q = PotentialQuestion {
            energy: Some(-0.1),
            ..PotentialQuestion::new(Given::Potential("(1/r)^12 - (1/r)^6"), "r", (0.8, 3.0))
        };
        let a = analyse_potential(&q).unwrap();
        let p = a.diagram_plot();
        assert_eq!((p.x_label.as_str(), p.y_label.as_str()), ("r", "U"));
        assert_eq!(p.file_stem, "U_r");
        // the wall at 0.8 (U ≈ 55) does not flatten the well (U = -0.25)
        let (lo, hi) = p.y_limits.unwrap();
        assert!(lo < -0.25 && hi < 5.0, "{lo} {hi}");
        assert!(a.speed_plot().is_none());
    }
}

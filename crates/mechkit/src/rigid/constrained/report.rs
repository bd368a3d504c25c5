//! The answer of `mechkit bead` as a value ([`BeadReport`], [`BeadOnCurve::report`]): the
//! departure (N = 0) and the landing, the turning points, the energy and its drift, and,
//! when the body starts at an equilibrium of the curve (a horizontal tangent), its stability
//! and, at an unstable one, where the slightest disturbance would make it leave
//! ([`Equilibrium`], in `report/equilibrium.rs`); the table `path.csv` and the plot `path`.

mod equilibrium;

pub use equilibrium::{Equilibrium, LeavingPoint};

use super::curve::Side;
use super::error::ConstrainedError;
use super::run::{BeadOnCurve, BeadRun, BeadSample, Landing, Start, StopReason, positive};
use crate::Real;
use crate::csv::{Column, Table};
use crate::figure::{LineStyle, Marker, MarkerShape, PlotData, Series};
use crate::ode::AdaptiveConfig;
use crate::report::sample_table;
use crate::rigid::Input;

/// Where the body leaves the curve.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct DepartureReport {
    /// Time (s).
    pub t: Real,
    /// The curve coordinate (x, or φ on a circle).
    pub coordinate: Real,
    /// Position (m).
    pub position: [Real; 2],
    /// Velocity (m/s).
    pub velocity: [Real; 2],
    /// Speed (m/s).
    pub speed: Real,
    /// The normal force there (N): zero to the integration's accuracy.
    pub normal_force: Real,
    /// On a circle: the angle from the top, in (−180°, 180°].
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub angle_from_top_deg: Option<Real>,
    /// On a circle: cos φ.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub cos_angle: Option<Real>,
}

/// The files a front wrote.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct BeadFiles {
    /// `path.csv`.
    pub csv: Option<String>,
    /// The plot of the path.
    pub plot: Option<String>,
}

/// A body on a curve, simulated, as `mechkit bead` reports it.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct BeadReport {
    /// The curve, in words.
    pub curve: String,
    /// The side: `outside`/`inside` (circle), `above`/`below` (graph) or `bead`.
    pub side: &'static str,
    /// m (kg).
    pub mass: Real,
    /// g (m/s²).
    pub g: Real,
    /// The start.
    pub start: Start,
    /// ½v² + g y at the start (J/kg).
    pub energy_per_mass: Real,
    /// The largest drift of it on the curve (J/kg).
    pub energy_drift_per_mass: Real,
    /// Where it leaves the curve.
    pub departure: Option<DepartureReport>,
    /// Where it lands on it again.
    pub landing: Option<Landing>,
    /// `landed` or `time-limit`.
    pub stop_reason: &'static str,
    /// Turning points (s).
    pub turning_times: Vec<Real>,
    /// The end (s).
    pub t_end: Real,
    /// Accepted steps.
    pub steps: u64,
    /// The start is an equilibrium (a horizontal tangent): its stability and where it leaves.
    pub equilibrium: Option<Equilibrium>,
    /// The files written (set by the front).
    pub files: Option<BeadFiles>,
    /// The model.
    #[cfg_attr(feature = "serde", serde(skip))]
    pub model: BeadOnCurve,
    /// The run.
    #[cfg_attr(feature = "serde", serde(skip))]
    pub run: BeadRun,
}

impl Side {
    /// The side's name: `outside`/`inside` on a circle, `above`/`below` on a graph, `bead`.
    pub fn name(self, circle: bool) -> &'static str {
        match (self, circle) {
            (Side::Outer, true) => "outside",
            (Side::Outer, false) => "above",
            (Side::Inner, true) => "inside",
            (Side::Inner, false) => "below",
            (Side::Bead, _) => "bead",
        }
    }
}

impl Start {
    /// Released from rest `height` (m) above the start, in gravity `g`: the speed
    /// `v = √(2 g h)` towards increasing coordinate.
    ///
    /// ```
    /// use mechkit::rigid::constrained::Start;
    /// let s = Start::dropped(0.0, 2.0, 9.81)?;
    /// assert_eq!(s.speed, (2.0f64 * 9.81 * 2.0).sqrt());
    /// # Ok::<(), mechkit::rigid::constrained::ConstrainedError>(())
    /// ```
    pub fn dropped(coordinate: Real, height: Real, g: Real) -> Result<Self, ConstrainedError> {
        let h = positive((Input::DropHeight, "the drop height (m)"), height, true)?;
        let g = positive((Input::Gravity, "g"), g, true)?;
        Ok(Self {
            coordinate,
            speed: (2.0 * g * h).sqrt(),
        })
    }
}

/// An angle in degrees in (−180°, 180°].
fn wrapped_degrees(a: Real) -> Real {
    a.sin().atan2(a.cos()).to_degrees()
}

impl BeadOnCurve {
    /// Integrates from `start` to `t_max` (s) with Dormand-Prince 5(4) at relative tolerance
    /// `rtol` (atol 1000 times smaller, steps of at most `t_max`/1000) and reports it.
    ///
    /// # Errors
    /// Invalid values (the error names its input), a start where the curve is undefined, or an
    /// integration that failed.
    ///
    /// ```
    /// use mechkit::rigid::constrained::{BeadOnCurve, Curve, Side, Start};
    /// // at rest on top of a cylinder: an unstable equilibrium, left at cos φ = 2/3
    /// let top = BeadOnCurve::new(Curve::circle(1.0)?, Side::Outer, 1.0, 9.81)?;
    /// let r = top.report(Start { coordinate: 0.0, speed: 0.0 }, 2.0, 1e-10)?;
    /// assert!(r.departure.is_none());
    /// let eq = r.equilibrium.unwrap();
    /// assert_eq!((eq.stability, eq.at_rest), ("unstable", true));
    /// assert!((eq.leaves_at.unwrap().cos_angle.unwrap() - 2.0 / 3.0).abs() < 1e-12);
    /// # Ok::<(), mechkit::rigid::constrained::ConstrainedError>(())
    /// ```
    pub fn report(
        &self,
        start: Start,
        t_max: Real,
        rtol: Real,
    ) -> Result<BeadReport, ConstrainedError> {
        let config = AdaptiveConfig::from_rtol(rtol).sampled_over(t_max);
        let run = self.simulate(start, t_max, &config)?;
        Ok(BeadReport::new(self.clone(), start, run))
    }
}

impl BeadReport {
    /// The report of `run`, a simulation of `model` from `start`.
    pub fn new(model: BeadOnCurve, start: Start, run: BeadRun) -> Self {
        let circle = model.curve.radius().is_some();
        let departure = run.departure.map(|d| DepartureReport {
            t: d.t,
            coordinate: d.coordinate,
            position: d.position,
            velocity: d.velocity,
            speed: d.velocity[0].hypot(d.velocity[1]),
            normal_force: d.normal_force,
            angle_from_top_deg: circle.then(|| wrapped_degrees(d.coordinate)),
            cos_angle: circle.then(|| d.coordinate.cos()),
        });
        let equilibrium = if departure.is_none() {
            model.equilibrium(start, &run)
        } else {
            None
        };
        Self {
            curve: model.curve.describe(),
            side: model.side.name(circle),
            mass: model.mass,
            g: model.g,
            start,
            energy_per_mass: run.energy,
            energy_drift_per_mass: run.energy_drift,
            departure,
            landing: run.landing,
            stop_reason: match run.stop {
                StopReason::Landed => "landed",
                StopReason::TimeLimit => "time-limit",
            },
            turning_times: run.turning_times.clone(),
            t_end: run.samples.last().map_or(0.0, |s| s.t),
            steps: run.stats.accepted,
            equilibrium,
            files: None,
            model,
            run,
        }
    }

    /// The file name of the table and the plot, without the extension.
    pub const NAME: &'static str = "path";

    /// The samples as a table (`path.csv`): t, x, y, vx, vy, the normal force (NaN in
    /// flight) and whether it is on the curve (1) or flying (0).
    pub fn table(&self) -> Table {
        let columns = [
            Column::new("t", "s"),
            Column::new("x", "m"),
            Column::new("y", "m"),
            Column::new("vx", "m/s"),
            Column::new("vy", "m/s"),
            Column::new("normal_force", "N"),
            Column::new("on_curve", "1"),
        ];
        sample_table(columns, &self.run.samples, |s| {
            [
                s.t,
                s.position[0],
                s.position[1],
                s.velocity[0],
                s.velocity[1],
                s.normal_force.unwrap_or(Real::NAN),
                if s.normal_force.is_some() { 1.0 } else { 0.0 },
            ]
        })
    }

    /// The plot `path`: the curve dashed, the path on it and in flight, the start, the
    /// departure and the landing marked; equal scales.
    pub fn plot(&self) -> PlotData {
        let (model, run) = (&self.model, &self.run);
        let track: Vec<(Real, Real)> = if let Some(r) = model.curve.radius() {
            (0..=360)
                .map(|i| {
                    let a = Real::from(i).to_radians();
                    (r * a.sin(), r * a.cos())
                })
                .collect()
        } else {
            let (lo, hi) = run
                .samples
                .iter()
                .fold((Real::INFINITY, Real::NEG_INFINITY), |(a, b), s| {
                    (a.min(s.position[0]), b.max(s.position[0]))
                });
            let pad = 0.1 * (hi - lo).max(1e-3);
            (0..=400)
                .map(|i| {
                    let x = lo - pad + (hi - lo + 2.0 * pad) * Real::from(i) / 400.0;
                    (x, model.curve.point(x)[1])
                })
                .filter(|p| p.1.is_finite())
                .collect()
        };
        let points = |keep: fn(&BeadSample) -> bool| -> Vec<(Real, Real)> {
            run.samples
                .iter()
                .filter(|s| keep(s))
                .map(|s| (s.position[0], s.position[1]))
                .collect()
        };
        let free = points(|s| s.normal_force.is_none());
        let mut plot = PlotData::new("path", Self::NAME, "x [m]", "y [m]")
            .with_series(Series::line("curve", track).styled(LineStyle::Dashed))
            .with_series(Series::line(
                "on the curve",
                points(|s| s.normal_force.is_some()),
            ));
        if !free.is_empty() {
            plot = plot.with_series(Series::line("free flight", free));
        }
        plot.equal_aspect = true;
        let first = &run.samples[0];
        plot.markers.push(Marker {
            at: (first.position[0], first.position[1]),
            label: "start".into(),
            shape: MarkerShape::Filled,
        });
        if let Some(d) = run.departure {
            plot.markers.push(Marker {
                at: (d.position[0], d.position[1]),
                label: "leaves (N = 0)".into(),
                shape: MarkerShape::Open,
            });
        }
        if let Some(l) = run.landing {
            plot.markers.push(Marker {
                at: (l.position[0], l.position[1]),
                label: "lands".into(),
                shape: MarkerShape::Cross,
            });
        }
        plot
    }
}

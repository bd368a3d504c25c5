//! The answer of `mechkit rocket` as a value ([`RocketReport`], [`Rocket::report`]): the
//! rocket equation, the burn time, the burnout and the apex in closed form next to the
//! simulation, the run's settings; its table ([`RocketReport::table`]: t, x, v, m) and plots
//! ([`RocketReport::plots`]: `v_t`, `x_t`, `m_t`).

use super::error::RocketError;
use super::run::RocketRun;
use super::vehicle::Rocket;
use crate::Real;
use crate::csv::{Column, Table};
use crate::figure::{LineStyle, PlotData, Series};
use crate::ode::AdaptiveConfig;
use crate::report::{Comparison, SimulationInfo};

/// Burnout: at `t = T` exactly.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Burnout {
    /// T (s).
    pub t: Real,
    /// The speed (m/s).
    pub v: Comparison,
    /// The height (m).
    pub x: Comparison,
}

/// The highest point of the coast.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Apex {
    /// When (s).
    pub t: Comparison,
    /// How high (m).
    pub x: Comparison,
}

/// A rocket's flight, as `mechkit rocket` reports it. The closed forms leave drag out.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct RocketReport {
    /// m0 (kg).
    pub m0: Real,
    /// m1 (kg).
    pub m1: Real,
    /// ṁ (kg/s).
    pub mass_rate: Real,
    /// u (m/s).
    pub exhaust_speed: Real,
    /// g (m/s²).
    pub g: Real,
    /// D (kg/m), `None` without drag.
    pub drag: Option<Real>,
    /// u ṁ (N).
    pub thrust: Real,
    /// Whether the thrust exceeds the weight at ignition.
    pub lifts_off: bool,
    /// u ln(m0/m1) (m/s).
    pub delta_v: Real,
    /// T = (m0 − m1)/ṁ (s).
    pub burn_time: Real,
    /// Burnout.
    pub burnout: Burnout,
    /// The apex of the coast (`None` without a coast or in free space).
    pub apex: Option<Apex>,
    /// The simulation's settings and counters.
    pub simulation: SimulationInfo,
    /// The directory the front wrote the plots to.
    pub plots: Option<String>,
    /// The rocket.
    #[cfg_attr(feature = "serde", serde(skip))]
    pub rocket: Rocket,
    /// The run.
    #[cfg_attr(feature = "serde", serde(skip))]
    pub run: RocketRun,
}

impl Rocket {
    /// Simulates the flight with Dormand-Prince 5(4) at relative tolerance `rtol` (atol 1000
    /// times smaller), steps of at most 1/1000 of the flight (to burnout, or to the drag-free
    /// apex with `coast`) so the plots follow the curves, and reports it.
    ///
    /// # Errors
    /// Invalid values (the error names its input), or an integration that failed.
    ///
    /// ```
    /// use mechkit::rocket::Rocket;
    /// let r = Rocket::new(1000.0, 400.0, 10.0, 2000.0)?.with_gravity(9.81)?.report(1e-10, true)?;
    /// assert_eq!(r.burnout.t, 60.0);
    /// assert!(r.burnout.v.difference.abs() < 1e-8 * r.burnout.v.closed_form);
    /// assert!(r.apex.unwrap().x.difference.abs() < 1e-6);
    /// # Ok::<(), mechkit::rocket::RocketError>(())
    /// ```
    pub fn report(&self, rtol: Real, coast: bool) -> Result<RocketReport, RocketError> {
        self.validate()?;
        let flight = self.apex().map_or(self.burn_time(), |(t, _)| t);
        let config = AdaptiveConfig::from_rtol(rtol).sampled_over(flight);
        let run = self.simulate(&config, coast)?;
        Ok(RocketReport::new(*self, run, &config))
    }
}

impl RocketReport {
    /// The report of `run`, a simulation of `rocket` with `config`.
    pub fn new(rocket: Rocket, run: RocketRun, config: &AdaptiveConfig) -> Self {
        let (t1, x1, v1) = run.burnout;
        let (_, x_c, v_c) = rocket.burnout();
        let apex = match (run.apex, rocket.apex()) {
            (Some((t, x)), Some((t_c, x_c))) => Some(Apex {
                t: Comparison::of(t_c, t),
                x: Comparison::of(x_c, x),
            }),
            _ => None,
        };
        Self {
            m0: rocket.m0,
            m1: rocket.m1,
            mass_rate: rocket.mass_rate,
            exhaust_speed: rocket.exhaust_speed,
            g: rocket.g,
            drag: rocket.drag,
            thrust: rocket.thrust(),
            lifts_off: rocket.lifts_off(),
            delta_v: rocket.delta_v(),
            burn_time: rocket.burn_time(),
            burnout: Burnout {
                t: t1,
                v: Comparison::of(v_c, v1),
                x: Comparison::of(x_c, x1),
            },
            apex,
            simulation: SimulationInfo::new("dopri5", config, run.stats, run.samples.len()),
            plots: None,
            rocket,
            run,
        }
    }

    /// The simulated samples as a table: t, x, v, m.
    pub fn table(&self) -> Table {
        let mut table = Table::new([
            Column::new("t", "s"),
            Column::new("x", "m"),
            Column::new("v", "m/s"),
            Column::new("m", "kg"),
        ]);
        for &(t, x, v, m) in &self.run.samples {
            table.push(&[t, x, v, m]);
        }
        table
    }

    /// The plots `v_t`, `x_t` (simulated, with the drag-free closed forms dashed) and `m_t`.
    pub fn plots(&self) -> Vec<PlotData> {
        let rocket = &self.rocket;
        let samples = &self.run.samples;
        let t_end = samples.last().map_or(0.0, |s| s.0);
        let grid: Vec<Real> = (0..=400).map(|i| t_end * Real::from(i) / 400.0).collect();
        let closed_label = if rocket.drag.is_some() {
            "closed form, no drag"
        } else {
            "closed form"
        };
        let curve = |f: fn(&(Real, Real, Real, Real)) -> Real| -> Vec<(Real, Real)> {
            samples.iter().map(|s| (s.0, f(s))).collect()
        };
        let closed = |f: fn(&Rocket, Real) -> Real| -> Vec<(Real, Real)> {
            grid.iter().map(|&t| (t, f(rocket, t))).collect()
        };
        vec![
            PlotData::new("v(t)", "v_t", "t [s]", "v [m/s]")
                .with_series(Series::line("simulated", curve(|s| s.2)))
                .with_series(
                    Series::line(closed_label, closed(Rocket::speed)).styled(LineStyle::Dashed),
                ),
            PlotData::new("x(t)", "x_t", "t [s]", "x [m]")
                .with_series(Series::line("simulated", curve(|s| s.1)))
                .with_series(
                    Series::line(closed_label, closed(Rocket::height)).styled(LineStyle::Dashed),
                ),
            PlotData::new("m(t)", "m_t", "t [s]", "m [kg]")
                .with_series(Series::line("simulated", curve(|s| s.3))),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn free_space_reports_tsiolkovsky_and_no_apex() {
        let r = Rocket::new(1000.0, 400.0, 10.0, 2000.0)
            .unwrap()
            .report(1e-10, true)
            .unwrap();
        let dv = 2000.0 * 2.5f64.ln();
        assert!((r.delta_v - dv).abs() < 1e-12 * dv);
        assert!((r.burnout.v.simulated - dv).abs() < 1e-8 * dv);
        assert!(r.apex.is_none());
        let table = r.table();
        assert_eq!(table.len(), r.simulation.samples);
        let m_end = table.column("m").unwrap().last().copied().unwrap();
        assert!((m_end - 400.0).abs() < 1e-9, "{m_end}");
        let stems: Vec<_> = r.plots().into_iter().map(|p| p.file_stem).collect();
        assert_eq!(stems, ["v_t", "x_t", "m_t"]);
        let e = Rocket::new(1000.0, 400.0, 10.0, 2000.0)
            .unwrap()
            .report(0.0, false)
            .unwrap_err();
        assert_eq!(e.input(), Some(super::super::Input::Tolerance));
    }
}

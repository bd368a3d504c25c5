//! The answer of `mechkit friction` as a value: a block released at rest on an incline
//! ([`FrictionReport`], [`Incline::report`]) and, for the stick-slip model, its run
//! ([`StickSlipReport`], [`SpringBlock::report`]: every phase with its closed-form end, the
//! energy ledger, the run's settings, the table `stick_slip.csv` and the plots).

use super::coulomb::Incline;
use super::error::FrictionError;
use super::spring_block::SpringBlock;
use super::stick_slip::{Phase, PhaseEnd, Regime, StickSlipRun, StickSlipSample};
use crate::Real;
use crate::csv::{Column, Table};
use crate::figure::{LineStyle, PlotData, Series};
use crate::ode::AdaptiveConfig;
use crate::report::{Files, SimulationInfo, sample_table, shade};

pub use crate::report::StartEnd;

/// A block released at rest on a flat or inclined surface (forces down the slope positive),
/// and the stick-slip run when one was asked for.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct FrictionReport {
    /// m (kg).
    pub mass: Real,
    /// g (m/s²).
    pub g: Real,
    /// The incline (degrees).
    pub angle_deg: Real,
    /// μs.
    pub mu_static: Real,
    /// μd.
    pub mu_dynamic: Real,
    /// Warnings about the set-up (μs < μd).
    pub warnings: Vec<String>,
    /// N = m g cos α + the extra normal load (N).
    pub normal_force: Real,
    /// The pull along the slope without friction (N).
    pub driving_force: Real,
    /// μs N (N).
    pub max_static_friction: Real,
    /// μd N (N).
    pub dynamic_friction: Real,
    /// atan μs (degrees).
    pub marginal_angle_deg: Real,
    /// Whether the block slides from rest.
    pub slides: bool,
    /// The friction on it (N).
    pub friction: Real,
    /// Its acceleration (m/s²).
    pub acceleration: Real,
    /// The stick-slip run, when asked for.
    pub stick_slip: Option<StickSlipReport>,
    /// The block.
    #[cfg_attr(feature = "serde", serde(skip))]
    pub incline: Incline,
}

impl Incline {
    /// The block released at rest, as a report (without a stick-slip run).
    ///
    /// ```
    /// use mechkit::rigid::friction::{Coulomb, Incline};
    /// let r = Incline::new(2.0, 30f64.to_radians(), Coulomb::new(0.5, 0.3)?)?.report()?;
    /// assert!(r.slides && r.stick_slip.is_none());
    /// assert!((r.marginal_angle_deg - 0.5f64.atan().to_degrees()).abs() < 1e-12);
    /// # Ok::<(), mechkit::rigid::friction::FrictionError>(())
    /// ```
    pub fn report(&self) -> Result<FrictionReport, FrictionError> {
        let r = self.at_rest()?;
        let c = self.friction;
        Ok(FrictionReport {
            mass: self.mass,
            g: self.g,
            angle_deg: self.angle.to_degrees(),
            mu_static: c.mu_static,
            mu_dynamic: c.mu_dynamic,
            warnings: c.warning().map(|w| vec![w.to_string()]).unwrap_or_default(),
            normal_force: r.normal,
            driving_force: r.driving,
            max_static_friction: r.max_static,
            dynamic_friction: r.dynamic,
            marginal_angle_deg: r.marginal_angle.to_degrees(),
            slides: r.slides,
            friction: r.friction,
            acceleration: r.acceleration,
            stick_slip: None,
            incline: *self,
        })
    }
}

/// One stick or slip phase, with the closed form of its end.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct PhaseReport {
    /// `stick`, `slip+` (faster than the surface) or `slip-`.
    pub regime: &'static str,
    /// Start (s).
    pub t_start: Real,
    /// End (s).
    pub t_end: Real,
    /// x at the start (m).
    pub x_start: Real,
    /// x at the end (m).
    pub x_end: Real,
    /// `switch` or `t_max`.
    pub ended_by: &'static str,
    /// The closed-form end of a phase that ended at a switch (s).
    pub t_end_closed_form: Option<Real>,
    /// The distance slid relative to the surface (m).
    pub slip_distance: Real,
}

/// The energy ledger of a stick-slip run (J).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct StickSlipEnergy {
    /// ½ m v².
    pub kinetic: StartEnd,
    /// The spring's ½ k (x − w t)².
    pub spring: StartEnd,
    /// The heat Q = ∫ μd N |v − u| dt.
    pub heat: Real,
    /// The work of friction on the block, W_belt − Q.
    pub work_friction: Real,
    /// The work of the belt.
    pub work_belt: Real,
    /// The work of the anchor.
    pub work_anchor: Real,
    /// K + U + Q − W_belt − W_anchor − (K₀ + U₀).
    pub residual: Real,
}

/// A stick-slip run of the spring-block model.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct StickSlipReport {
    /// k (N/m).
    pub spring_k: Real,
    /// u (m/s).
    pub belt_speed: Real,
    /// w (m/s).
    pub anchor_speed: Real,
    /// x₀ (m).
    pub x0: Real,
    /// v₀ (m/s).
    pub v0: Real,
    /// Ω = √(k/m) (rad/s).
    pub omega: Real,
    /// μs N (N): sticking lasts while |k (x − w t)| stays below it.
    pub stick_bound: Real,
    /// μd N (N).
    pub dynamic_friction: Real,
    /// The phases in order.
    pub phases: Vec<PhaseReport>,
    /// How many stick phases.
    pub stick_phases: usize,
    /// How many slip phases.
    pub slip_phases: usize,
    /// The energy ledger.
    pub energy: StickSlipEnergy,
    /// The simulation's settings and counters.
    pub simulation: SimulationInfo,
    /// The files written (set by the front).
    pub files: Option<Files>,
    /// The model.
    #[cfg_attr(feature = "serde", serde(skip))]
    pub block: SpringBlock,
    /// The run.
    #[cfg_attr(feature = "serde", serde(skip))]
    pub run: StickSlipRun,
}

/// The name of a regime: `stick`, `slip+` or `slip-`.
pub fn regime_name(r: Regime) -> &'static str {
    match r {
        Regime::Stick => "stick",
        Regime::Slip { direction } if direction > 0.0 => "slip+",
        Regime::Slip { .. } => "slip-",
    }
}

impl SpringBlock {
    /// The closed-form end of `phase` (s): [`SpringBlock::exact_stick_end`] or
    /// [`SpringBlock::exact_slip_end`] from its start.
    pub fn closed_end(&self, phase: &Phase) -> Option<Real> {
        match phase.regime {
            Regime::Stick => self.exact_stick_end(phase.start.0, phase.start.1),
            Regime::Slip { direction } => self.exact_slip_end(phase.start, direction),
        }
    }

    /// Simulates to `t_max` (s) with DOP853 at relative tolerance `rtol` (atol 1000 times
    /// smaller, steps of at most `t_max`/1000) and reports it.
    ///
    /// # Errors
    /// Invalid values (the error names its input), too many phases, or an integration that
    /// failed.
    pub fn report(&self, t_max: Real, rtol: Real) -> Result<StickSlipReport, FrictionError> {
        let config = AdaptiveConfig::from_rtol(rtol).sampled_over(t_max);
        let run = self.simulate(t_max, &config)?;
        Ok(StickSlipReport::new(*self, run, &config))
    }
}

impl StickSlipReport {
    /// The report of `run`, a simulation of `block` with `config`.
    pub fn new(block: SpringBlock, run: StickSlipRun, config: &AdaptiveConfig) -> Self {
        let phases: Vec<PhaseReport> = run
            .phases
            .iter()
            .map(|p| {
                let switched = p.ended == PhaseEnd::Switch;
                PhaseReport {
                    regime: regime_name(p.regime),
                    t_start: p.start.0,
                    t_end: p.end.0,
                    x_start: p.start.1,
                    x_end: p.end.1,
                    ended_by: if switched { "switch" } else { "t_max" },
                    t_end_closed_form: if switched { block.closed_end(p) } else { None },
                    slip_distance: p.slip_distance,
                }
            })
            .collect();
        let b = &run.balance;
        let spring = b.potential.as_ref().expect("the spring has a potential");
        let stick_phases = run
            .phases
            .iter()
            .filter(|p| p.regime == Regime::Stick)
            .count();
        Self {
            spring_k: block.k,
            belt_speed: block.belt_speed,
            anchor_speed: block.anchor_speed,
            x0: block.x0,
            v0: block.v0,
            omega: block.omega(),
            stick_bound: block.stick_bound(),
            dynamic_friction: block.friction.dynamic(block.normal()),
            stick_phases,
            slip_phases: phases.len() - stick_phases,
            phases,
            energy: StickSlipEnergy {
                kinetic: StartEnd::new(b.kinetic.start, b.kinetic.end),
                spring: StartEnd::new(spring.start, spring.end),
                heat: run.heat(),
                work_friction: run.work_friction(),
                work_belt: run.work_belt(),
                work_anchor: run.work_anchor(),
                residual: b.residual(),
            },
            simulation: SimulationInfo::new("dop853", config, run.stats, run.samples.len()),
            files: None,
            block,
            run,
        }
    }

    /// The file name of the table, without `.csv`.
    pub const TABLE: &'static str = "stick_slip";

    /// The samples as a table (`stick_slip.csv`): t, x, v, the anchor's position, the
    /// spring's force, friction, whether it sticks (1) or slips (0), the heat and the works
    /// of the belt and the anchor.
    pub fn table(&self) -> Table {
        let columns = [
            Column::new("t", "s"),
            Column::new("x", "m"),
            Column::new("v", "m/s"),
            Column::new("anchor", "m"),
            Column::new("spring_force", "N"),
            Column::new("friction", "N"),
            Column::new("stuck", "1"),
            Column::new("heat", "J"),
            Column::new("work_belt", "J"),
            Column::new("work_anchor", "J"),
        ];
        sample_table(columns, &self.run.samples, |s| {
            [
                s.t,
                s.x,
                s.v,
                self.block.anchor(s.t),
                s.spring_force,
                s.friction,
                if s.stuck { 1.0 } else { 0.0 },
                s.heat,
                s.work_belt,
                s.work_anchor,
            ]
        })
    }

    /// The plots `x_t` (block and anchor), `v_t` (block and belt) and `forces_t` (spring,
    /// friction and ±μs N), the stick intervals shaded.
    pub fn plots(&self) -> Vec<PlotData> {
        let (block, run) = (&self.block, &self.run);
        let curve = |f: &dyn Fn(&StickSlipSample) -> Real| -> Vec<(Real, Real)> {
            run.samples.iter().map(|s| (s.t, f(s))).collect()
        };
        let t_end = run.samples.last().map_or(0.0, |s| s.t);
        let flat = |y: Real| vec![(0.0, y), (t_end, y)];
        let bound = block.stick_bound();
        let mut plots = vec![
            PlotData::new("x(t)", "x_t", "t [s]", "x [m]")
                .with_series(Series::line("block", curve(&|s| s.x)))
                .with_series(
                    Series::line("anchor", curve(&|s| block.anchor(s.t))).styled(LineStyle::Dashed),
                ),
            PlotData::new("v(t)", "v_t", "t [s]", "v [m/s]")
                .with_series(Series::line("block", curve(&|s| s.v)))
                .with_series(
                    Series::line("belt", flat(block.belt_speed)).styled(LineStyle::Dashed),
                ),
            PlotData::new("forces(t)", "forces_t", "t [s]", "F [N]")
                .with_series(Series::line("spring", curve(&|s| s.spring_force)))
                .with_series(Series::line("friction", curve(&|s| s.friction)))
                .with_series(Series::line("±μs N", flat(bound)).styled(LineStyle::Dashed))
                .with_series(Series::line("±μs N", flat(-bound)).styled(LineStyle::Dashed)),
        ];
        let sticks = run.phases.iter().filter(|p| p.regime == Regime::Stick);
        shade(&mut plots, "stick", sticks.map(|p| (p.start.0, p.end.0)));
        plots
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rigid::friction::Coulomb;

    /// The earthquake model: the first stick ends at μs N/(k w), every switch at its closed
    /// form; the table has a unit for every column and the phases add up.
    #[test]
    fn a_stick_slip_report_carries_its_phases_table_and_plots() {
        let block = SpringBlock::new(1.0, 100.0, Coulomb::new(0.6, 0.4).unwrap())
            .unwrap()
            .driven(0.05);
        let r = block.report(8.0, 1e-10).unwrap();
        assert!((r.phases[0].t_end - 0.6 * 9.81 / (100.0 * 0.05)).abs() < 1e-12);
        for p in r.phases.iter().filter(|p| p.ended_by == "switch") {
            let closed = p.t_end_closed_form.unwrap();
            assert!((p.t_end - closed).abs() < 1e-11, "{p:?}");
        }
        assert_eq!(r.stick_phases + r.slip_phases, r.phases.len());
        let table = r.table();
        assert!(table.columns().iter().all(|c| c.unit.is_some()));
        assert_eq!(table.len(), r.simulation.samples);
        let stems: Vec<_> = r.plots().into_iter().map(|p| p.file_stem).collect();
        assert_eq!(stems, ["x_t", "v_t", "forces_t"]);
    }

    #[test]
    fn a_bad_stick_slip_input_names_itself() {
        let block = SpringBlock::new(1.0, 100.0, Coulomb::single(0.5).unwrap()).unwrap();
        let e = block.report(-1.0, 1e-10).unwrap_err();
        assert_eq!(e.input(), Some(crate::rigid::Input::Duration));
        let e = block.driven(f64::NAN).report(1.0, 1e-10).unwrap_err();
        assert_eq!(e.input(), Some(crate::rigid::Input::AnchorSpeed));
    }
}

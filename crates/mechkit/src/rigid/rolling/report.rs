//! The answer of `mechkit roll` as a value ([`RollReport`], [`RollingMotion::report`]): the
//! set-up, the slipping phase and the rolling phase each with its accelerations, the start of
//! rolling simulated next to its closed form, the regimes, the energy ledger, the run's
//! settings; its table ([`RollReport::table`], `roll.csv`) and plots ([`RollReport::plots`]).
//!
//! Signs as in [`RollingMotion`]: x and v down the slope, ω forward. While slipping in
//! direction s = sign(v − ωR), friction is f = −s μd N, so
//! a = g sin α − s μd g cos α and α_ω = s μd m g cos α R/I; while rolling
//! a = g sin α/(1 + k) and α_ω = a/R.

use super::error::RollingError;
use super::motion::RollingMotion;
use super::run::{Contact, RollSample, RollingRun};
use crate::Real;
use crate::csv::{Column, Table};
use crate::figure::{LineStyle, PlotData, Series};
use crate::ode::AdaptiveConfig;
use crate::report::{Comparison, Files, SimulationInfo, sample_table, shade};

pub use crate::report::StartEnd;

/// The body's numbers.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct BodyNumbers {
    /// k = I/(m R²).
    pub k: Real,
    /// m (kg).
    pub mass: Real,
    /// R (m).
    pub radius: Real,
    /// I = k m R² (kg m²).
    pub moment_of_inertia: Real,
}

/// The accelerations and the friction of one regime (x down the slope, ω forward).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct PhaseMotion {
    /// `rolling`, `slipping forward` (the contact point slides down the slope) or
    /// `slipping backward`.
    pub regime: &'static str,
    /// The friction on the body (N).
    pub friction: Real,
    /// dv/dt (m/s²).
    pub acceleration: Real,
    /// dω/dt (rad/s²).
    pub angular_acceleration: Real,
}

/// When rolling starts: the simulation next to the closed form.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct RollStart {
    /// The time (s).
    pub t: Comparison<Option<Real>>,
    /// The speed (m/s).
    pub v: Comparison<Option<Real>>,
    /// ω then (rad/s), simulated.
    pub omega: Option<Real>,
    /// x then (m), simulated.
    pub x: Option<Real>,
}

/// One interval of the run in one regime.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct PhaseReport {
    /// The regime, as [`PhaseMotion::regime`].
    pub regime: &'static str,
    /// Start (s).
    pub t_start: Real,
    /// End (s).
    pub t_end: Real,
    /// v at the end (m/s).
    pub v_end: Real,
    /// ω at the end (rad/s).
    pub omega_end: Real,
    /// `switch` or `t_max`.
    pub ended_by: &'static str,
    /// dv/dt in the phase (m/s²).
    pub acceleration: Real,
    /// dω/dt in the phase (rad/s²).
    pub angular_acceleration: Real,
    /// The friction in the phase (N).
    pub friction: Real,
}

/// The energy ledger of a roll.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct RollEnergy {
    /// ½ m v².
    pub translational: StartEnd,
    /// ½ I ω².
    pub rotational: StartEnd,
    /// −m g x sin α.
    pub potential: StartEnd,
    /// The work of friction, ∫ f (v − ωR) dt.
    pub work_friction: Option<Real>,
    /// K + U − E₀ − W_friction at the end.
    pub residual: Real,
}

/// A rolling body on a slope, simulated, as `mechkit roll` reports it.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct RollReport {
    /// The body.
    pub body: BodyNumbers,
    /// The slope (degrees).
    pub slope_deg: Real,
    /// g (m/s²).
    pub g: Real,
    /// μs.
    pub mu_static: Real,
    /// μd.
    pub mu_dynamic: Real,
    /// Warnings about the set-up (μs < μd).
    pub warnings: Vec<String>,
    /// Launch speed (m/s).
    pub v0: Real,
    /// Launch spin (rad/s).
    pub omega0: Real,
    /// v0 − ω0 R (m/s).
    pub slip_velocity0: Real,
    /// N = m g cos α (N).
    pub normal_force: Real,
    /// Whether rolling can last on this slope.
    pub can_roll: bool,
    /// The steepest slope it can roll on (degrees).
    pub steepest_rolling_angle_deg: Real,
    /// The acceleration while rolling, g sin α/(1 + k) (m/s²).
    pub rolling_acceleration: Real,
    /// The slipping phase from the launch (`None` when it starts rolling).
    pub slipping: Option<PhaseMotion>,
    /// The rolling phase (`None` on a slope too steep to roll on).
    pub rolling: Option<PhaseMotion>,
    /// When rolling starts.
    pub roll_start: RollStart,
    /// The friction while rolling (N).
    pub rolling_friction: Comparison<Option<Real>>,
    /// On a flat floor, the rolling speed from any launch, (v0 + k R ω0)/(1 + k) (m/s).
    pub flat_floor_rolling_speed: Option<Real>,
    /// The regimes in order.
    pub phases: Vec<PhaseReport>,
    /// The energy ledger.
    pub energy: RollEnergy,
    /// The simulation's settings and counters.
    pub simulation: SimulationInfo,
    /// The files written (set by the front).
    pub files: Option<Files>,
    /// The set-up.
    #[cfg_attr(feature = "serde", serde(skip))]
    pub motion: RollingMotion,
    /// The run.
    #[cfg_attr(feature = "serde", serde(skip))]
    pub run: RollingRun,
}

/// The name of a regime.
pub fn regime_name(c: Contact) -> &'static str {
    match c {
        Contact::Rolling => "rolling",
        Contact::Slipping { direction } if direction > 0.0 => "slipping forward",
        Contact::Slipping { .. } => "slipping backward",
    }
}

impl RollingMotion {
    /// The accelerations and the friction in a regime.
    pub fn phase_motion(&self, contact: Contact) -> PhaseMotion {
        let (friction, acceleration, angular_acceleration) = match contact {
            Contact::Rolling => {
                let a = self.rolling_acceleration();
                (self.rolling_friction(), a, a / self.body.radius)
            }
            Contact::Slipping { direction } => {
                let (a, alpha) = self.slip_accelerations(direction);
                (self.slip_friction(direction), a, alpha)
            }
        };
        PhaseMotion {
            regime: regime_name(contact),
            friction,
            acceleration,
            angular_acceleration,
        }
    }

    /// The regime at the launch: slipping in the direction of `v0 − ω0 R`, or, without slip,
    /// rolling if it can last and else slipping down the slope.
    pub fn launch_contact(&self) -> Contact {
        let vc0 = self.slip_velocity(self.v0, self.omega0);
        if vc0 != 0.0 {
            Contact::Slipping {
                direction: vc0.signum(),
            }
        } else if self.can_roll() {
            Contact::Rolling
        } else {
            Contact::Slipping {
                direction: self.breakaway_direction(),
            }
        }
    }

    /// Simulates to `t_max` (s) with DOP853 at relative tolerance `rtol` (atol 1000 times
    /// smaller, steps of at most `t_max`/1000: [`AdaptiveConfig::sampled_over`]) and reports
    /// it.
    ///
    /// # Errors
    /// Invalid values (the error names its input), or an integration that failed
    /// ([`RollingError::Integrate`]).
    ///
    /// ```
    /// use mechkit::rigid::friction::Coulomb;
    /// use mechkit::rigid::rolling::{RollingBody, RollingMotion};
    /// let ball = RollingBody::sphere(0.45, 0.11)?;
    /// let slope = 20f64.to_radians();
    /// let r = RollingMotion::new(ball, slope, Coulomb::single(0.3)?)
    ///     .launched(2.0, -30.0)
    ///     .report(3.0, 1e-10)?;
    /// // backspin: the contact point slides forward, friction acts up the slope
    /// let slip = r.slipping.unwrap();
    /// assert_eq!(slip.regime, "slipping forward");
    /// assert!((slip.acceleration - 9.81 * (slope.sin() - 0.3 * slope.cos())).abs() < 1e-12);
    /// assert_eq!(r.phases.len(), 2);
    /// # Ok::<(), mechkit::rigid::rolling::RollingError>(())
    /// ```
    pub fn report(&self, t_max: Real, rtol: Real) -> Result<RollReport, RollingError> {
        let config = AdaptiveConfig::from_rtol(rtol).sampled_over(t_max);
        let run = self.simulate(t_max, &config)?;
        Ok(RollReport::new(*self, run, &config))
    }
}

impl RollReport {
    /// The report of `run`, a simulation of `motion` with `config`.
    pub fn new(motion: RollingMotion, run: RollingRun, config: &AdaptiveConfig) -> Self {
        let m = &motion;
        let b = m.body;
        let closed = m.roll_start();
        let sim = run.roll_start;
        let balance = &run.balance;
        let part = |name| {
            let p = balance.kinetic.part(name).expect("rolling splits K");
            StartEnd::new(p.start, p.end)
        };
        let u = balance.potential.as_ref().expect("gravity has a potential");
        let launch = m.launch_contact();
        let phases = run
            .phases
            .iter()
            .map(|p| {
                let motion = m.phase_motion(p.contact);
                PhaseReport {
                    regime: motion.regime,
                    t_start: p.start.0,
                    t_end: p.end.0,
                    v_end: p.end.2,
                    omega_end: p.end.3,
                    ended_by: if p.switched { "switch" } else { "t_max" },
                    acceleration: motion.acceleration,
                    angular_acceleration: motion.angular_acceleration,
                    friction: motion.friction,
                }
            })
            .collect();
        Self {
            body: BodyNumbers {
                k: b.k,
                mass: b.mass,
                radius: b.radius,
                moment_of_inertia: b.moment_of_inertia(),
            },
            slope_deg: m.angle.to_degrees(),
            g: m.g,
            mu_static: m.friction.mu_static,
            mu_dynamic: m.friction.mu_dynamic,
            warnings: m
                .friction
                .warning()
                .map(|w| vec![w.to_string()])
                .unwrap_or_default(),
            v0: m.v0,
            omega0: m.omega0,
            slip_velocity0: m.slip_velocity(m.v0, m.omega0),
            normal_force: m.normal(),
            can_roll: m.can_roll(),
            steepest_rolling_angle_deg: m.steepest_rolling_angle().to_degrees(),
            rolling_acceleration: m.rolling_acceleration(),
            slipping: (launch != Contact::Rolling).then(|| m.phase_motion(launch)),
            rolling: m.can_roll().then(|| m.phase_motion(Contact::Rolling)),
            roll_start: RollStart {
                t: Comparison::of_options(closed.map(|c| c.0), sim.map(|s| s.0)),
                v: Comparison::of_options(closed.map(|c| c.1), sim.map(|s| s.2)),
                omega: sim.map(|s| s.3),
                x: sim.map(|s| s.1),
            },
            rolling_friction: Comparison::of_options(
                m.can_roll().then(|| m.rolling_friction()),
                run.rolling_friction,
            ),
            flat_floor_rolling_speed: (m.angle == 0.0).then(|| m.flat_floor_rolling_speed()),
            phases,
            energy: RollEnergy {
                translational: part("translational"),
                rotational: part("rotational"),
                potential: StartEnd::new(u.start, u.end),
                work_friction: balance.work_of("friction"),
                residual: balance.residual(),
            },
            simulation: SimulationInfo::new("dop853", config, run.stats, run.samples.len()),
            files: None,
            motion,
            run,
        }
    }

    /// The file name of the table, without `.csv`.
    pub const TABLE: &'static str = "roll";

    /// The samples as a table (`roll.csv`): t, x, v, θ, ω, ωR, the slip velocity, the
    /// friction, whether it rolls (1) or slips (0), the work of friction and the energies.
    pub fn table(&self) -> Table {
        let m = &self.motion;
        let r = m.body.radius;
        let columns = [
            Column::new("t", "s"),
            Column::new("x", "m"),
            Column::new("v", "m/s"),
            Column::new("theta", "rad"),
            Column::new("omega", "rad/s"),
            Column::new("omega_R", "m/s"),
            Column::new("slip_velocity", "m/s"),
            Column::new("friction", "N"),
            Column::new("rolling", "1"),
            Column::new("work_friction", "J"),
            Column::new("K_trans", "J"),
            Column::new("K_rot", "J"),
            Column::new("U", "J"),
        ];
        sample_table(columns, &self.run.samples, |s| {
            let (kt, kr) = m.kinetic(s.v, s.omega);
            [
                s.t,
                s.x,
                s.v,
                s.theta,
                s.omega,
                s.omega * r,
                s.slip_velocity,
                s.friction,
                if s.rolling { 1.0 } else { 0.0 },
                s.work_friction,
                kt,
                kr,
                m.potential(s.x),
            ]
        })
    }

    /// The plots: `v_t` (v and ωR, meeting where rolling starts) and `energy_t` (the
    /// energies and E₀ + W_friction), the rolling intervals shaded.
    pub fn plots(&self) -> Vec<PlotData> {
        let m = &self.motion;
        let run = &self.run;
        let r = m.body.radius;
        let energies = |s: &RollSample| {
            let (kt, kr) = m.kinetic(s.v, s.omega);
            (kt, kr, m.potential(s.x))
        };
        let curve = |f: &dyn Fn(&RollSample) -> Real| -> Vec<(Real, Real)> {
            run.samples.iter().map(|s| (s.t, f(s))).collect()
        };
        let e0 = run.balance.energy().0;
        let mut plots = vec![
            PlotData::new("v and ωR", "v_t", "t [s]", "[m/s]")
                .with_series(Series::line("v", curve(&|s| s.v)))
                .with_series(
                    Series::line("ω R", curve(&|s| s.omega * r)).styled(LineStyle::Dashed),
                ),
            PlotData::new("energy", "energy_t", "t [s]", "E [J]")
                .with_series(Series::line("K_trans", curve(&|s| energies(s).0)))
                .with_series(Series::line("K_rot", curve(&|s| energies(s).1)))
                .with_series(Series::line("U", curve(&|s| energies(s).2)))
                .with_series(Series::line(
                    "K + U",
                    curve(&|s| {
                        let (kt, kr, u) = energies(s);
                        kt + kr + u
                    }),
                ))
                .with_series(
                    Series::line("E0 + W_friction", curve(&|s| e0 + s.work_friction))
                        .styled(LineStyle::Dashed),
                ),
        ];
        let rolls = run.phases.iter().filter(|p| p.contact == Contact::Rolling);
        shade(&mut plots, "rolling", rolls.map(|p| (p.start.0, p.end.0)));
        plots
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rigid::friction::Coulomb;
    use crate::rigid::rolling::RollingBody;

    /// Backspin on a slope: the slipping phase decelerates at g (sin α − μ cos α) with the
    /// spin growing at μ m g cos α R/I, then rolling at g sin α/(1 + k); the phases carry
    /// these, and the table's v agrees with them.
    #[test]
    fn both_phases_carry_their_own_accelerations() {
        let (m, r, mu, slope) = (0.45, 0.11, 0.3, 20f64.to_radians());
        let ball = RollingBody::sphere(m, r).unwrap();
        let rep = RollingMotion::new(ball, slope, Coulomb::single(mu).unwrap())
            .launched(2.0, -30.0)
            .report(3.0, 1e-10)
            .unwrap();
        let g = 9.81;
        let slip = rep.slipping.expect("it slips at the launch");
        assert!((slip.acceleration - g * (slope.sin() - mu * slope.cos())).abs() < 1e-12);
        let i = 0.4 * m * r * r;
        let alpha = mu * m * g * slope.cos() * r / i;
        assert!((slip.angular_acceleration - alpha).abs() < 1e-10 * alpha);
        let roll = rep.rolling.expect("it can roll");
        assert!((roll.acceleration - g * slope.sin() / 1.4).abs() < 1e-12);
        assert!((roll.angular_acceleration - roll.acceleration / r).abs() < 1e-12);
        assert_eq!(rep.phases[0].acceleration, slip.acceleration);
        assert_eq!(rep.phases[1].acceleration, roll.acceleration);
        // the table: v grows at the slipping rate, then at the rolling one
        let table = rep.table();
        let (t, v) = (table.column("t").unwrap(), table.column("v").unwrap());
        let t_roll = rep.roll_start.t.simulated.unwrap();
        for k in 1..t.len() {
            if t[k] > t[k - 1] && t[k] <= t_roll {
                let a = (v[k] - v[k - 1]) / (t[k] - t[k - 1]);
                assert!((a - slip.acceleration).abs() < 1e-6, "{a}");
            }
        }
        assert_eq!(table.columns()[8].unit.as_deref(), Some("1"));
        let stems: Vec<_> = rep.plots().iter().map(|p| p.file_stem.clone()).collect();
        assert_eq!(stems, ["v_t", "energy_t"]);
    }

    #[test]
    fn a_ball_that_starts_rolling_has_no_slipping_phase() {
        let ball = RollingBody::cylinder(1.0, 0.2).unwrap();
        let motion =
            RollingMotion::new(ball, 0.1, Coulomb::single(0.5).unwrap()).launched(1.0, 5.0);
        let rep = motion.report(1.0, 1e-9).unwrap();
        assert!(rep.slipping.is_none());
        assert_eq!(rep.phases.len(), 1);
        assert_eq!(rep.phases[0].regime, "rolling");
    }
}

//! The answer of `mechkit spin` as a value ([`SpinReport`], [`SpinningBody::report`]): the
//! conservation of |L| and E (for a top E, L_z, L₃), for a free body the period of ω about
//! the intermediate axis from its zeros next to the exact 4K(m)/λ ([`Poinsot`]), for a top
//! the nutation range and the precession rate next to the steady-precession and fast-top
//! rates; the table `spin.csv` and the plots.

use super::body::SpinningBody;
use super::error::Free3dError;
use super::poinsot::Poinsot;
use super::run::{Conservation, SpinIntegrator, SpinOptions, SpinRun, SpinSample};
use crate::Real;
use crate::csv::{Column, Table};
use crate::figure::{LineStyle, PlotData, Series};
use crate::mass::{Mat3, Vec3};
use crate::report::Files;

/// The step setting of the integrator: tolerances (adaptive) or a fixed step.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize), serde(untagged))]
pub enum StepSetting {
    /// An adaptive pair's tolerances.
    Adaptive {
        /// Relative tolerance.
        rtol: Option<Real>,
        /// Absolute tolerance.
        atol: Option<Real>,
    },
    /// A fixed step (s).
    Fixed {
        /// The step.
        dt: Real,
    },
}

/// How the run was integrated.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct IntegratorInfo {
    /// `dop853`, `dopri5`, `rk4` or `splitting`.
    pub method: &'static str,
    /// The frame of L in the state: `world` or `body`.
    pub frame: &'static str,
    /// Tolerances or the step.
    pub step: StepSetting,
    /// Accepted steps.
    pub steps: u64,
    /// Rejected steps.
    pub rejected: u64,
    /// Right-hand-side evaluations.
    pub evaluations: u64,
}

/// The angular momentum about the rotation point, world frame (kg m²/s).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct AngularMomentum {
    /// At the start.
    pub start: [Real; 3],
    /// At the end.
    pub end: [Real; 3],
    /// |L| at the start.
    pub norm: Real,
}

/// The energy (J).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SpinEnergy {
    /// T + U at the start.
    pub start: Real,
    /// T + U at the end.
    pub end: Real,
    /// T at the start.
    pub kinetic_start: Real,
}

/// The period of the flip: from the zeros and exact.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct FlipPeriod {
    /// 2 (t_last − t_first)/(n − 1) from the located zeros (s).
    pub simulated: Option<Real>,
    /// 4K(m)/λ (s).
    pub elliptic: Option<Real>,
    /// (simulated − elliptic)/elliptic.
    pub relative_difference: Option<Real>,
}

/// A free body's ω about its intermediate axis (the tennis-racket flip).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Flip {
    /// The intermediate axis, 1 to 3.
    pub axis: usize,
    /// How many zeros of ω about it were located.
    pub zeros: usize,
    /// When (s).
    pub zero_times: Vec<Real>,
    /// The period.
    pub period: FlipPeriod,
    /// The elliptic parameter m.
    pub parameter_m: Option<Real>,
    /// 1 − m.
    pub one_minus_m: Option<Real>,
    /// The largest |ω − ω_exact| over the samples (rad/s).
    pub omega_max_deviation: Option<Real>,
    /// Steps in which the zeros could not be proven ([`SpinRun::unproven_steps`]).
    pub unproven_steps: u64,
}

/// The nutation angle θ (degrees).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Nutation {
    /// At the start.
    pub start: Real,
    /// The least.
    pub min: Real,
    /// The largest.
    pub max: Real,
}

/// Below this `|sin θ|` the top's symmetry axis is vertical to rounding: its precession angle
/// φ has no value there, and no mean precession rate is reported (a top started upright drifts
/// off the vertical by about 1e-8 rad through rounding alone, and φ's wandering there gave
/// rates of tens of rad/s).
pub const VERTICAL_SIN: Real = 1e-9;

/// Precession rates (rad/s).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct PrecessionRate {
    /// The mean over the run, Δφ/Δt; `None` when the symmetry axis is vertical at a sample
    /// (`sin θ` below [`VERTICAL_SIN`]), where the precession angle φ has no value: a top
    /// started upright or hanging straight down.
    pub mean: Option<Real>,
    /// The slow root of steady precession at the start's tilt and spin.
    pub steady_slow: Option<Real>,
    /// The fast root.
    pub steady_fast: Option<Real>,
    /// The fast-top approximation m g ℓ/(J₃ ω₃).
    pub fast_top: Option<Real>,
}

/// A heavy top's nutation and precession.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Top {
    /// The vector from the pivot to the centre of mass, body frame (m).
    pub cm_offset: [Real; 3],
    /// g (m/s²).
    pub g: Real,
    /// The inertia tensor about the pivot, body frame (kg m²).
    pub inertia_about_pivot: [[Real; 3]; 3],
    /// The nutation.
    pub nutation_deg: Nutation,
    /// The precession.
    pub precession_rate: PrecessionRate,
}

/// A free rigid body or a heavy top, simulated, as `mechkit spin` reports it.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SpinReport {
    /// The principal moments about the centre of mass (kg m²).
    pub moments: [Real; 3],
    /// The mass (kg).
    pub mass: Real,
    /// ω at the start, principal frame (rad/s).
    pub omega0: [Real; 3],
    /// The duration (s).
    pub t_max: Real,
    /// The integration.
    pub integrator: IntegratorInfo,
    /// The angular momentum.
    pub angular_momentum: AngularMomentum,
    /// The energy.
    pub energy: SpinEnergy,
    /// The largest relative deviations of the conserved quantities.
    pub conservation: Conservation,
    /// A free body's flip.
    pub flip: Option<Flip>,
    /// A top's nutation and precession.
    pub top: Option<Top>,
    /// The files written (set by the front).
    pub files: Option<Files>,
    /// The body.
    #[cfg_attr(feature = "serde", serde(skip))]
    pub body: SpinningBody,
    /// The run.
    #[cfg_attr(feature = "serde", serde(skip))]
    pub run: SpinRun,
}

/// The components of `v`, with −0 written as 0.
fn components(v: &Vec3) -> [Real; 3] {
    [v.x + 0.0, v.y + 0.0, v.z + 0.0]
}

fn rows(m: &Mat3) -> [[Real; 3]; 3] {
    std::array::from_fn(|r| std::array::from_fn(|c| m[(r, c)] + 0.0))
}

impl SpinningBody {
    /// Integrates from `start` over `[0, t_max]` with `options` ([`SpinningBody::simulate`])
    /// and reports it.
    ///
    /// # Errors
    /// Invalid values (the error names its input), or an integration that failed.
    ///
    /// ```
    /// use mechkit::mass::Vec3;
    /// use mechkit::rigid::free3d::{FreeBody, SpinOptions, SpinningBody};
    /// use nalgebra::UnitQuaternion;
    /// let body = SpinningBody::free(FreeBody::new([1.0, 2.0, 3.0], 1.0)?);
    /// let start = body.attitude(UnitQuaternion::identity(), Vec3::new(0.01, 1.0, 0.01))?;
    /// let r = body.report(&start, 160.0, &SpinOptions::default())?;
    /// let flip = r.flip.as_ref().unwrap();
    /// assert_eq!(flip.axis, 2);
    /// assert!(flip.period.relative_difference.unwrap().abs() < 1e-6);
    /// # Ok::<(), mechkit::rigid::free3d::Free3dError>(())
    /// ```
    pub fn report(
        &self,
        start: &super::body::Attitude,
        t_max: Real,
        options: &SpinOptions,
    ) -> Result<SpinReport, Free3dError> {
        let run = self.simulate(start, t_max, options)?;
        Ok(SpinReport::new(self.clone(), run, options, t_max))
    }
}

impl SpinReport {
    /// The report of `run`, a simulation of `body` with `options` over `[0, t_max]`.
    pub fn new(body: SpinningBody, run: SpinRun, options: &SpinOptions, t_max: Real) -> Self {
        let first = run.samples[0];
        let last = run.samples[run.samples.len() - 1];
        let flip = body.pivot().is_none().then(|| {
            let exact = Poinsot::new(body.body().moments(), first.omega_body);
            let measured = run.crossing_period();
            let reference = exact.map(|p| p.period());
            Flip {
                axis: body.body().intermediate_axis() + 1,
                zeros: run.crossings.len(),
                zero_times: run.crossings.iter().map(|z| z.t).collect(),
                period: FlipPeriod {
                    simulated: measured,
                    elliptic: reference,
                    relative_difference: measured.zip(reference).map(|(m, r)| (m - r) / r),
                },
                parameter_m: exact.map(|p| p.parameter()),
                one_minus_m: exact.map(|p| p.complementary_parameter()),
                omega_max_deviation: exact.map(|p| {
                    run.samples
                        .iter()
                        .map(|s| (s.omega_body - p.omega(s.t)).norm())
                        .fold(0.0, Real::max)
                }),
                unproven_steps: run.unproven_steps,
            }
        });
        let top = body.pivot().map(|(d, g)| {
            let thetas: Vec<Real> = run
                .samples
                .iter()
                .map(|s| s.attitude.euler_angles().1)
                .collect();
            let (lo, hi) = thetas
                .iter()
                .fold((Real::INFINITY, Real::NEG_INFINITY), |(a, b), &t| {
                    (a.min(t), b.max(t))
                });
            let (theta0, spin) = (thetas[0], first.omega_body.z);
            let steady = body.steady_precession(theta0, spin);
            let vertical = thetas.iter().any(|t| t.sin().abs() < VERTICAL_SIN);
            Top {
                cm_offset: components(&d),
                g,
                inertia_about_pivot: rows(body.inertia()),
                nutation_deg: Nutation {
                    start: theta0.to_degrees(),
                    min: lo.to_degrees(),
                    max: hi.to_degrees(),
                },
                precession_rate: PrecessionRate {
                    mean: (!vertical)
                        .then(|| (last.precession - first.precession) / (last.t - first.t)),
                    steady_slow: steady.map(|s| s.0),
                    steady_fast: steady.map(|s| s.1),
                    fast_top: body.fast_top_precession(spin),
                },
            }
        });
        let step = match &options.integrator {
            SpinIntegrator::Adaptive { config, .. } => StepSetting::Adaptive {
                rtol: config.rtol.as_scalar(),
                atol: config.atol.as_scalar(),
            },
            SpinIntegrator::Fixed { dt, .. } | SpinIntegrator::Splitting { dt } => {
                StepSetting::Fixed { dt: *dt }
            }
        };
        let b = body.body();
        Self {
            moments: b.moments(),
            mass: b.mass(),
            omega0: components(&first.omega_body),
            t_max,
            integrator: IntegratorInfo {
                method: options.integrator.name(),
                frame: options.formulation.name(),
                step,
                steps: run.steps,
                rejected: run.rejected,
                evaluations: run.evaluations,
            },
            angular_momentum: AngularMomentum {
                start: components(&first.attitude.l),
                end: components(&run.end.l),
                norm: first.attitude.l.norm(),
            },
            energy: SpinEnergy {
                start: first.kinetic + first.potential,
                end: last.kinetic + last.potential,
                kinetic_start: first.kinetic,
            },
            conservation: run.conservation,
            flip,
            top,
            files: None,
            body,
            run,
        }
    }

    /// The file name of the table, without `.csv`.
    pub const TABLE: &'static str = "spin";

    /// The samples as a table (`spin.csv`): t, the quaternion (body → world), ω in the body
    /// frame, L in the world frame and |L|, T, U, E, and for a top θ and φ.
    pub fn table(&self) -> Table {
        let top = self.body.pivot().is_some();
        let l_unit = "kg*m^2/s";
        let mut columns = vec![
            Column::new("t", "s"),
            Column::new("qw", "1"),
            Column::new("qx", "1"),
            Column::new("qy", "1"),
            Column::new("qz", "1"),
            Column::new("w1", "rad/s"),
            Column::new("w2", "rad/s"),
            Column::new("w3", "rad/s"),
            Column::new("Lx", l_unit),
            Column::new("Ly", l_unit),
            Column::new("Lz", l_unit),
            Column::new("L", l_unit),
            Column::new("T", "J"),
            Column::new("U", "J"),
            Column::new("E", "J"),
        ];
        if top {
            columns.extend([Column::new("theta", "rad"), Column::new("phi", "rad")]);
        }
        let mut table = Table::new(columns);
        let mut row = Vec::with_capacity(17);
        for s in &self.run.samples {
            let q = s.attitude.q.quaternion();
            let l = s.attitude.l;
            row.clear();
            row.extend([s.t, q.w, q.i, q.j, q.k]);
            row.extend(s.omega_body.iter());
            row.extend([
                l.x,
                l.y,
                l.z,
                l.norm(),
                s.kinetic,
                s.potential,
                s.kinetic + s.potential,
            ]);
            if top {
                row.extend([s.attitude.euler_angles().1, s.precession]);
            }
            table.push(&row);
        }
        table
    }

    /// The plots: `omega_t` (ω in the body frame, with the exact ω about the intermediate
    /// axis dashed for a free body), and for a top `nutation_t` and `precession_t`.
    pub fn plots(&self) -> Vec<PlotData> {
        let run = &self.run;
        let series = |f: &dyn Fn(&SpinSample) -> Real| -> Vec<(Real, Real)> {
            run.samples.iter().map(|s| (s.t, f(s))).collect()
        };
        let top = self.body.pivot().is_some();
        let mut omega = PlotData::new("ω in the body frame", "omega_t", "t [s]", "ω [rad/s]");
        for k in 0..3 {
            omega = omega.with_series(Series::line(
                format!("ω{}", k + 1),
                series(&|s| s.omega_body[k]),
            ));
        }
        let exact = Poinsot::new(self.moments, run.samples[0].omega_body).filter(|_| !top);
        if let Some(exact) = exact {
            let axis = self.body.body().intermediate_axis();
            omega = omega.with_series(
                Series::line(
                    format!("ω{} elliptic", axis + 1),
                    series(&|s| exact.omega(s.t)[axis]),
                )
                .styled(LineStyle::Dashed),
            );
        }
        let mut plots = vec![omega];
        if top {
            plots.push(
                PlotData::new("nutation", "nutation_t", "t [s]", "θ [deg]").with_series(
                    Series::line("θ", series(&|s| s.attitude.euler_angles().1.to_degrees())),
                ),
            );
            plots.push(
                PlotData::new("precession", "precession_t", "t [s]", "φ [deg]")
                    .with_series(Series::line("φ", series(&|s| s.precession.to_degrees()))),
            );
        }
        plots
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rigid::free3d::FreeBody;
    use nalgebra::UnitQuaternion;

    #[test]
    fn a_top_reports_its_nutation_and_its_table_has_theta_and_phi() {
        let free = FreeBody::new([3e-3, 3e-3, 4e-3], 0.5).unwrap();
        let top = SpinningBody::on_pivot(free, Vec3::new(0.0, 0.0, 0.05), 9.81).unwrap();
        let tilt = 30f64.to_radians();
        let (slow, _) = top.steady_precession(tilt, 50.0).unwrap();
        let start = top.tilted(tilt, 50.0, slow);
        let options = SpinOptions {
            samples: 200,
            ..SpinOptions::default()
        };
        let r = top.report(&start, 1.0, &options).unwrap();
        assert!(r.flip.is_none());
        let t = r.top.unwrap();
        assert!(
            (t.nutation_deg.min - 30.0).abs() < 1e-6 && (t.nutation_deg.max - 30.0).abs() < 1e-6
        );
        assert!((t.precession_rate.mean.unwrap() - slow).abs() < 1e-8 * slow.abs());
        let table = r.table();
        assert_eq!(table.columns().len(), 17);
        assert_eq!(table.len(), 201);
        assert_eq!(table.columns()[16].name, "phi");
        let stems: Vec<_> = r.plots().into_iter().map(|p| p.file_stem).collect();
        assert_eq!(stems, ["omega_t", "nutation_t", "precession_t"]);
        let free = SpinningBody::free(FreeBody::new([1.0, 2.0, 3.0], 1.0).unwrap());
        let start = free
            .attitude(UnitQuaternion::identity(), Vec3::new(0.01, 1.0, 0.01))
            .unwrap();
        let r = free.report(&start, 10.0, &options).unwrap();
        assert_eq!(r.table().columns().len(), 15);
        assert!(matches!(r.integrator.step, StepSetting::Adaptive { .. }));
    }
}

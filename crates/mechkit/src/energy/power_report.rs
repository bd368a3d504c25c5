//! The answers of `mechkit power`: motion at constant power ([`ConstantPower`]) at chosen
//! times, the time to reach a speed, the curves `v(t)` and `x(t)` as a table and plots; or
//! the average power of a work done over a time.

use super::constant_power::ConstantPower;
use crate::Real;
use crate::csv::{Column, Table};
use crate::figure::{PlotData, Series};
use crate::inputs::{Input, InputError};

/// The average power `W/t`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct AveragePower {
    /// The work done (J).
    pub work: Real,
    /// Over this time (s).
    pub time: Real,
    /// `W/t` (W).
    pub average_power: Real,
}

/// The average power of `work` done over `time`.
///
/// ```
/// let p = mechkit::energy::average_power(70.53e3, 86400.0).unwrap();
/// assert!((p.average_power - 70530.0 / 86400.0).abs() < 1e-15);
/// assert!(mechkit::energy::average_power(1.0, 0.0).is_err());
/// ```
///
/// # Errors
/// A time that is not positive ([`Input::Time`]).
pub fn average_power(work: Real, time: Real) -> Result<AveragePower, InputError> {
    if time.is_nan() || time <= 0.0 {
        return Err(InputError::new(
            Input::Time,
            format!(
                "the time must be positive, not {} s",
                crate::error::short(time)
            ),
        ));
    }
    Ok(AveragePower {
        work,
        time,
        average_power: work / time,
    })
}

/// The state at a time.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct PowerSample {
    /// The time (s).
    pub t: Real,
    /// The speed (m/s).
    pub v: Real,
    /// The acceleration (m/s²).
    pub a: Real,
    /// The distance covered (m).
    pub x: Real,
    /// The work done, `P t` (J).
    pub work: Real,
}

/// When a speed is reached.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SpeedReached {
    /// The speed (m/s).
    pub v: Real,
    /// When (s).
    pub t: Real,
    /// Where (m).
    pub x: Real,
}

/// Motion at constant power at the times asked. Its serde shape is the JSON of `mechkit
/// power`; `plots` is the directory a front wrote the plots to (set by the front).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct PowerMotion {
    /// The power (W).
    pub power: Real,
    /// The mass (kg).
    pub mass: Real,
    /// The start speed (m/s).
    pub v0: Real,
    /// The state at each time asked.
    pub at: Vec<PowerSample>,
    /// When the speed asked is reached.
    pub until_speed: Option<SpeedReached>,
    /// Where a front wrote the table and plots.
    pub plots: Option<String>,
    /// The model.
    #[cfg_attr(feature = "serde", serde(skip))]
    pub model: ConstantPower,
}

/// What `mechkit power` answers: an average power, or motion at constant power.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(untagged))]
#[non_exhaustive]
pub enum PowerAnswer {
    /// `W/t`.
    Average(AveragePower),
    /// `v`, `a`, `x` at constant power.
    Motion(PowerMotion),
}

/// Motion at constant `power` of a body of `mass` starting at speed `v0`: the state at each
/// of `times` and when `until_speed` is reached.
///
/// ```
/// let m = mechkit::energy::constant_power_motion(20e3, 200.0, 0.0, &[5.0], Some(40.0)).unwrap();
/// assert!((m.at[0].v - 1000f64.sqrt()).abs() < 1e-12);
/// assert!((m.until_speed.unwrap().t - 200.0 * 1600.0 / 40e3).abs() < 1e-12);
/// assert_eq!(m.table(10).len(), 11);
/// ```
///
/// # Errors
/// A power or mass that is not positive, a negative start speed, a negative time, a speed
/// below the start speed, each naming its [`Input`].
pub fn constant_power_motion(
    power: Real,
    mass: Real,
    v0: Real,
    times: &[Real],
    until_speed: Option<Real>,
) -> Result<PowerMotion, InputError> {
    let short = crate::error::short;
    let got = format!(
        "(got P = {} W, m = {} kg, v0 = {} m/s)",
        short(power),
        short(mass),
        short(v0)
    );
    let positive = |v: Real| v.is_finite() && v > 0.0;
    if !positive(power) {
        return Err(InputError::new(
            Input::Power,
            format!("the power must be positive {got}"),
        ));
    }
    // a = P/(m v) divides by the mass: a subnormal one is refused as a scenario refuses it
    if !crate::invertible(mass) {
        return Err(InputError::new(
            Input::Mass,
            format!(
                "the mass must be positive, finite and at least 2.2e-308 kg (its reciprocal must be finite) {got}"
            ),
        ));
    }
    let model = ConstantPower::new(power, mass, v0, 0.0).ok_or_else(|| {
        InputError::new(
            Input::StartSpeed,
            format!("the start speed must not be negative {got}"),
        )
    })?;
    if let Some(t) = times.iter().find(|t| t.is_nan() || **t < 0.0) {
        return Err(InputError::new(
            Input::At,
            format!(
                "times must not be negative, not {} s",
                crate::error::short(*t)
            ),
        ));
    }
    let until_speed = until_speed
        .map(|v| {
            let t = model.time_to_speed(v).ok_or_else(|| {
                InputError::new(
                    Input::TargetSpeed,
                    format!(
                        "{} m/s is below the start speed {} m/s",
                        short(v),
                        short(v0)
                    ),
                )
            })?;
            Ok(SpeedReached {
                v,
                t,
                x: model.position(t),
            })
        })
        .transpose()?;
    Ok(PowerMotion {
        power,
        mass,
        v0,
        at: times.iter().map(|&t| model.sample(t)).collect(),
        until_speed,
        plots: None,
        model,
    })
}

impl ConstantPower {
    /// The state at `t`.
    pub fn sample(&self, t: Real) -> PowerSample {
        PowerSample {
            t,
            v: self.speed(t),
            a: self.acceleration(t),
            x: self.position(t),
            work: self.work(t),
        }
    }
}

impl PowerMotion {
    /// The last time of interest: the latest time asked, or when the speed is reached (0
    /// when nothing was asked).
    pub fn t_end(&self) -> Real {
        self.at
            .iter()
            .map(|s| s.t)
            .chain(self.until_speed.map(|s| s.t))
            .fold(0.0, Real::max)
    }

    fn times(&self, intervals: usize) -> impl Iterator<Item = Real> + '_ {
        let t_end = self.t_end();
        let n = intervals.max(1);
        (0..=n).map(move |i| t_end * i as Real / n as Real)
    }

    /// The curves from 0 to [`t_end`](Self::t_end) on `intervals` equal steps: `t, v, a, x,
    /// W` in SI (the acceleration is infinite at the start from rest).
    pub fn table(&self, intervals: usize) -> Table {
        let mut t = Table::new([
            Column::new("t", "s"),
            Column::new("v", "m/s"),
            Column::new("a", "m/s^2"),
            Column::new("x", "m"),
            Column::new("W", "J"),
        ]);
        for time in self.times(intervals) {
            let s = self.model.sample(time);
            t.push(&[s.t, s.v, s.a, s.x, s.work]);
        }
        t
    }

    /// The plots `v_t` and `x_t` from 0 to [`t_end`](Self::t_end) (400 steps); none when
    /// nothing was asked (`t_end` is 0).
    pub fn plots(&self) -> Vec<PlotData> {
        if self.t_end() <= 0.0 {
            return Vec::new();
        }
        let curve = |f: &dyn Fn(Real) -> Real| -> Vec<(Real, Real)> {
            self.times(400).map(|t| (t, f(t))).collect()
        };
        vec![
            PlotData::new("v(t)", "v_t", "t [s]", "v [m/s]")
                .with_series(Series::line("v(t)", curve(&|t| self.model.speed(t)))),
            PlotData::new("x(t)", "x_t", "t [s]", "x [m]")
                .with_series(Series::line("x(t)", curve(&|t| self.model.position(t)))),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inputs_are_named() {
        let input = |r: Result<PowerMotion, InputError>| r.unwrap_err().input;
        assert_eq!(
            input(constant_power_motion(-1.0, 1.0, 0.0, &[], None)),
            Input::Power
        );
        assert_eq!(
            input(constant_power_motion(1.0, -200.0, 0.0, &[], None)),
            Input::Mass
        );
        assert_eq!(
            input(constant_power_motion(1.0, 1.0, -1.0, &[], None)),
            Input::StartSpeed
        );
        assert_eq!(
            input(constant_power_motion(1.0, 1.0, 0.0, &[-1.0], None)),
            Input::At
        );
        assert_eq!(
            input(constant_power_motion(1.0, 1.0, 2.0, &[], Some(1.0))),
            Input::TargetSpeed
        );
        let nothing = constant_power_motion(1.0, 1.0, 0.0, &[], None).unwrap();
        assert!(nothing.plots().is_empty());
        let m = constant_power_motion(1.0, 1.0, 0.0, &[2.0], None).unwrap();
        let names: Vec<_> = m.plots().iter().map(|p| p.file_stem.clone()).collect();
        assert_eq!(names, ["v_t", "x_t"]);
    }
}

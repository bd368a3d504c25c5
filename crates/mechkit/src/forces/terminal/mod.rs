//! Drag from a terminal velocity: a body falling steadily at `v_T` has its weight balanced by
//! the drag, `m g = b v_T` (linear) or `m g = D v_T²` (quadratic). A measured `v_T` therefore
//! gives `b/(m g) = 1/v_T` or `D/(m g) = 1/v_T²`, and with the mass the coefficient itself;
//! with the fluid's density and the body's frontal area, the dimensionless drag coefficient
//! `C_d = 2 D/(ρ A)`.
//!
//! `v_T` comes from a distance fallen at steady speed in a time, or from position samples by a
//! least-squares line through the part of the fall where the speed is steady.
//! ```
//! use mechkit::forces::terminal::{DragLaw, TerminalDrag};
//! // a feather falls 2.4 m in 4.8 s at terminal speed
//! let d = TerminalDrag::new(2.4 / 4.8, DragLaw::Quadratic).unwrap();
//! assert!((d.per_weight - 4.0).abs() < 1e-12); // D/(m g) in s²/m²
//! ```

use thiserror::Error;

use crate::Real;

mod fit;

pub use fit::{SteadyFit, steady_fit, steady_fit_from};

/// How the drag grows with speed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DragLaw {
    /// `F = −b v`.
    Linear,
    /// `F = −D |v| v`.
    Quadratic,
}

impl DragLaw {
    /// The coefficient's symbol: `D` (quadratic) or `b` (linear).
    pub fn symbol(self) -> &'static str {
        match self {
            DragLaw::Linear => "b",
            DragLaw::Quadratic => "D",
        }
    }

    /// The units of the drag per unit weight, per unit mass, and of the coefficient:
    /// `(s^2/m^2, 1/m, kg/m)` quadratic, `(s/m, 1/s, kg/s)` linear.
    pub fn units(self) -> (&'static str, &'static str, &'static str) {
        match self {
            DragLaw::Quadratic => ("s^2/m^2", "1/m", "kg/m"),
            DragLaw::Linear => ("s/m", "1/s", "kg/s"),
        }
    }

    /// Parses `linear` or `quadratic`.
    pub fn parse(text: &str) -> Option<DragLaw> {
        match text {
            "linear" => Some(DragLaw::Linear),
            "quadratic" => Some(DragLaw::Quadratic),
            _ => None,
        }
    }

    /// The name, as parsed.
    pub fn name(self) -> &'static str {
        match self {
            DragLaw::Linear => "linear",
            DragLaw::Quadratic => "quadratic",
        }
    }
}

/// Why no drag could be found.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum TerminalError {
    /// The terminal speed is not positive and finite.
    #[error("the terminal speed must be positive and finite, not {} m/s", crate::error::short(*.0))]
    Speed(Real),
    /// A quantity that must be positive is not.
    #[error("{what} must be positive and finite, not {}", crate::error::short(*value))]
    NotPositive {
        /// Which quantity.
        what: &'static str,
        /// Its value.
        value: Real,
    },
    /// A result is too small or too large for a double (`1/v_T²` of a terminal speed of
    /// 1e300 m/s underflows to 0).
    #[error(
        "{what} would be {} for these inputs, past what a double holds: give values nearer to 1 in their units (a terminal speed between 1e-150 and 1e150 m/s)",
        crate::error::short(*value)
    )]
    OutOfRange {
        /// Which quantity.
        what: &'static str,
        /// What it came to (0 when it underflowed, infinite when it overflowed).
        value: Real,
    },
    /// Too few samples for a line.
    #[error("{0} samples in the steady part: a line needs at least 3")]
    TooFewSamples(usize),
    /// The times do not increase.
    #[error("the times must increase (sample {0})")]
    Unordered(usize),
    /// No sample at or after the time the fit should start from.
    #[error(
        "no sample at or after t = {} s (the data end at t = {} s)",
        crate::error::short(*from),
        crate::error::short(*last)
    )]
    NothingAfter {
        /// The time asked for (s).
        from: Real,
        /// The last sample's time (s).
        last: Real,
    },
}

/// The drag that balances the weight at a terminal speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TerminalDrag {
    /// The law.
    pub law: DragLaw,
    /// The terminal speed `v_T` (m/s).
    pub terminal_speed: Real,
    /// The drag per unit weight: `b/(m g) = 1/v_T` (s/m) or `D/(m g) = 1/v_T²` (s²/m²).
    pub per_weight: Real,
}

impl TerminalDrag {
    /// The drag for a terminal speed (its sign is ignored: falling is negative in `y`).
    pub fn new(terminal_speed: Real, law: DragLaw) -> Result<Self, TerminalError> {
        let v = terminal_speed.abs();
        if !(v > 0.0 && v.is_finite()) {
            return Err(TerminalError::Speed(terminal_speed));
        }
        let (per_weight, what) = match law {
            DragLaw::Linear => (1.0 / v, "b/(m g) = 1/v_T"),
            DragLaw::Quadratic => (1.0 / (v * v), "D/(m g) = 1/v_T^2"),
        };
        representable(what, per_weight)?;
        Ok(Self {
            law,
            terminal_speed: v,
            per_weight,
        })
    }

    /// From a distance fallen at steady speed in a time.
    pub fn from_fall(distance: Real, time: Real, law: DragLaw) -> Result<Self, TerminalError> {
        positive("the time", time)?;
        positive("the distance", distance.abs())?;
        Self::new(distance / time, law)
    }

    /// The coefficient `b` (kg/s) or `D` (kg/m) for a body of `mass` in gravity `g`.
    pub fn coefficient(&self, mass: Real, g: Real) -> Result<Real, TerminalError> {
        positive("the mass", mass)?;
        positive("g", g)?;
        let c = self.per_weight * mass * g;
        representable("the drag coefficient", c)?;
        Ok(c)
    }

    /// The drag coefficient `C_d = 2 D/(ρ A)` of quadratic drag, for a body of `mass` in
    /// gravity `g`, in a fluid of `density`, with frontal `area`; `None` for linear drag.
    pub fn drag_coefficient(
        &self,
        mass: Real,
        g: Real,
        density: Real,
        area: Real,
    ) -> Result<Option<Real>, TerminalError> {
        positive("the density", density)?;
        positive("the area", area)?;
        let d = self.coefficient(mass, g)?;
        if self.law != DragLaw::Quadratic {
            return Ok(None);
        }
        let cd = 2.0 * d / (density * area);
        representable("C_d = 2 D/(rho A)", cd)?;
        Ok(Some(cd))
    }
}

/// A positive result that neither underflowed nor overflowed (nor lost its precision to the
/// subnormal range).
fn representable(what: &'static str, value: Real) -> Result<(), TerminalError> {
    if value.is_normal() {
        Ok(())
    } else {
        Err(TerminalError::OutOfRange { what, value })
    }
}

fn positive(what: &'static str, value: Real) -> Result<(), TerminalError> {
    if value > 0.0 && value.is_finite() {
        Ok(())
    } else {
        Err(TerminalError::NotPositive { what, value })
    }
}

/// The frontal area of a body: given, or of a round body of a radius (π r²).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Area {
    /// The area (m²).
    Given(Real),
    /// The radius of a round body (m).
    Radius(Real),
}

impl Area {
    /// The area (m²).
    pub fn value(self) -> Real {
        match self {
            Area::Given(a) => a,
            Area::Radius(r) => std::f64::consts::PI * r * r,
        }
    }
}

/// The drag that balances the weight at a terminal speed, as `mechkit terminal` reports it.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct TerminalReport {
    /// `quadratic` or `linear`.
    pub law: &'static str,
    /// v_T (m/s).
    pub terminal_speed: Real,
    /// D/(m g) = 1/v_T² or b/(m g) = 1/v_T.
    pub per_weight: Real,
    /// Its unit.
    pub per_weight_unit: &'static str,
    /// D/m or b/m: the course's constant in a = −g − (D/m) v|v|.
    pub per_mass: Real,
    /// Its unit.
    pub per_mass_unit: &'static str,
    /// g (m/s²).
    pub g: Real,
    /// D (kg/m) or b (kg/s), with the mass.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub coefficient: Option<Real>,
    /// Its unit.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub coefficient_unit: Option<&'static str>,
    /// C_d = 2D/(ρA), with the mass, the density and the area (quadratic drag).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub drag_coefficient: Option<Real>,
    /// The line fitted through position samples, when v_T came from one.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub fit: Option<SteadyFit>,
    /// Why the fit's speed is not steady.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub warning: Option<String>,
    /// The law.
    #[cfg_attr(feature = "serde", serde(skip))]
    pub drag_law: DragLaw,
}

impl TerminalDrag {
    /// The report in gravity `g`: with `mass` the coefficient, with the fluid's `density` and
    /// the body's `area` too the drag coefficient; `fit` the line v_T came from, if any.
    ///
    /// ```
    /// use mechkit::forces::terminal::{Area, DragLaw, TerminalDrag};
    /// let d = TerminalDrag::new(20.0, DragLaw::Quadratic).unwrap();
    /// let r = d.report(9.81, Some(0.057), Some((1.2, Area::Radius(0.033))), None).unwrap();
    /// let a = std::f64::consts::PI * 0.033f64.powi(2);
    /// let cd = 2.0 * 0.057 * 9.81 / (1.2 * a * 400.0);
    /// assert!((r.drag_coefficient.unwrap() - cd).abs() < 1e-12 * cd);
    /// assert_eq!(r.coefficient_unit, Some("kg/m"));
    /// ```
    pub fn report(
        &self,
        g: Real,
        mass: Option<Real>,
        fluid: Option<(Real, Area)>,
        fit: Option<SteadyFit>,
    ) -> Result<TerminalReport, TerminalError> {
        positive("g", g)?;
        let per_mass = self.per_weight * g;
        representable("the drag per unit mass", per_mass)?;
        let coefficient = mass.map(|m| self.coefficient(m, g)).transpose()?;
        let drag_coefficient = match (mass, fluid) {
            (Some(m), Some((rho, area))) => self.drag_coefficient(m, g, rho, area.value())?,
            _ => None,
        };
        let (per_weight_unit, per_mass_unit, coefficient_unit) = self.law.units();
        Ok(TerminalReport {
            law: self.law.name(),
            terminal_speed: self.terminal_speed,
            per_weight: self.per_weight,
            per_weight_unit,
            per_mass,
            per_mass_unit,
            g,
            coefficient,
            coefficient_unit: coefficient.map(|_| coefficient_unit),
            drag_coefficient,
            warning: fit.and_then(|f| f.unsteady_warning()),
            fit,
            drag_law: self.law,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_weight_balances_the_drag_at_the_terminal_speed() {
        let (m, g) = (0.057, 9.81);
        for law in [DragLaw::Linear, DragLaw::Quadratic] {
            let d = TerminalDrag::new(-12.5, law).expect("valid");
            let c = d.coefficient(m, g).expect("valid");
            let drag = match law {
                DragLaw::Linear => c * 12.5,
                DragLaw::Quadratic => c * 12.5 * 12.5,
            };
            assert!((drag - m * g).abs() < 1e-15);
        }
        let d = TerminalDrag::from_fall(2.4, 4.8, DragLaw::Quadratic).expect("valid");
        assert_eq!(d.per_weight, 4.0);
        // C_d of a sphere of radius 3.3 cm: 2 m g/(ρ A v_T²)
        let cd = d
            .drag_coefficient(0.057, 9.81, 1.2, std::f64::consts::PI * 0.033f64.powi(2))
            .expect("valid")
            .expect("quadratic");
        let want = 2.0 * 0.057 * 9.81 / (1.2 * std::f64::consts::PI * 0.033f64.powi(2) * 0.25);
        assert!((cd - want).abs() < 1e-12 * want);
        assert!(TerminalDrag::new(0.0, DragLaw::Linear).is_err());
        assert!(TerminalDrag::from_fall(1.0, 0.0, DragLaw::Linear).is_err());
    }

    /// Results past what a double holds are refused, not printed as 0 or inf: a terminal
    /// speed of 1e300 m/s gave `D/(m g) = 0` with exit 0.
    #[test]
    fn results_past_a_double_are_refused() {
        let out_of_range =
            |r: Result<Real, TerminalError>| matches!(r, Err(TerminalError::OutOfRange { .. }));
        for v in [-1e300, 1e-300, 1e160] {
            let r = TerminalDrag::new(v, DragLaw::Quadratic).map(|d| d.per_weight);
            assert!(out_of_range(r), "{v}");
        }
        assert!(TerminalDrag::new(1e300, DragLaw::Linear).is_ok());
        let d = TerminalDrag::new(1e150, DragLaw::Quadratic).expect("1e-300 is a double");
        assert!(out_of_range(d.coefficient(1e-30, 9.81)));
        let r = d.report(1e-300, None, None, None);
        assert!(matches!(r, Err(TerminalError::OutOfRange { .. })), "{r:?}");
        let big = TerminalDrag::new(5.0, DragLaw::Quadratic).expect("valid");
        let cd = big.drag_coefficient(1e300, 9.81, 1e-300, 1e-10);
        assert!(
            matches!(cd, Err(TerminalError::OutOfRange { .. })),
            "{cd:?}"
        );
    }

    #[test]
    fn a_fit_from_a_time_warns_when_the_fall_is_not_steady() {
        let (g, d): (Real, Real) = (9.81, 0.5);
        let t: Vec<Real> = (0..600).map(|i| Real::from(i) * 0.01).collect();
        let y: Vec<Real> = t
            .iter()
            .map(|&t| 100.0 - ((g * d).sqrt() * t).cosh().ln() / d)
            .collect();
        let late = steady_fit_from(&t, &y, Some(3.0)).expect("fit");
        assert_eq!(late.samples, 300);
        assert!(late.unsteady_warning().is_none());
        let early = steady_fit_from(&t[..100], &y[..100], Some(0.0)).expect("fit");
        assert!(early.unsteady_warning().unwrap().contains("not steady"));
        assert!(matches!(
            steady_fit_from(&t, &y, Some(10.0)),
            Err(TerminalError::NothingAfter { .. })
        ));
        let drag = TerminalDrag::new(late.velocity, DragLaw::Quadratic).unwrap();
        let r = drag.report(g, None, None, Some(late)).unwrap();
        assert!((r.per_mass - d).abs() < 1e-6);
        assert!(r.coefficient.is_none() && r.warning.is_none());
    }

    #[test]
    fn a_line_through_a_steady_fall_gives_its_speed() {
        // y(t) = y0 − ln(cosh(√(gD) t))/D: nearly a line after a few time constants
        let (g, d): (Real, Real) = (9.81, 0.5);
        let vt = (g / d).sqrt();
        let t: Vec<Real> = (0..800).map(|i| Real::from(i) * 0.01).collect();
        let y: Vec<Real> = t
            .iter()
            .map(|&t| 10.0 - ((g * d).sqrt() * t).cosh().ln() / d)
            .collect();
        let fit = steady_fit(&t, &y, 400).expect("fit");
        assert!(
            (fit.velocity + vt).abs() < 1e-6 * vt,
            "{} vs {vt}",
            fit.velocity
        );
        assert!((fit.half_slopes.0 - fit.half_slopes.1).abs() < 1e-6);
        // the whole fall, from rest, is not steady: the halves disagree
        let all = steady_fit(&t[..200], &y[..200], 0).expect("fit");
        assert!((all.half_slopes.0 - all.half_slopes.1).abs() > 0.1 * vt);
        assert!(matches!(
            steady_fit(&t, &y, 798),
            Err(TerminalError::TooFewSamples(2))
        ));
    }
}

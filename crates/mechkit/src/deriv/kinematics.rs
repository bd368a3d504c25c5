//! Velocity and acceleration from positions sampled in time: the "motion from data" tool of
//! the course (a falling tennis ball from motion capture, a probe's orbit from its positions).

use super::difference::{Difference, differentiate, second_derivative};
use super::error::DerivError;
use super::savitzky_golay::SavitzkyGolay;
use crate::Real;

/// How to differentiate.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Derivation {
    /// Finite differences: `v` by the scheme; `a` by the three-point second derivative for
    /// central differences, or by applying the scheme twice (as the course's loops do).
    Differences(Difference),
    /// Savitzky-Golay derivatives of the local polynomial fits (uniform time steps only).
    SavitzkyGolay(SavitzkyGolay),
}

impl Derivation {
    /// The method in words: the scheme's name (`central`), or `savitzky-golay window 21 order
    /// 2`.
    ///
    /// ```
    /// use mechkit::deriv::{Derivation, Difference, SavitzkyGolay};
    /// assert_eq!(Derivation::Differences(Difference::Forward).describe(), "forward");
    /// let sg = Derivation::SavitzkyGolay(SavitzkyGolay::new(21, 2).unwrap());
    /// assert_eq!(sg.describe(), "savitzky-golay window 21 order 2");
    /// ```
    pub fn describe(&self) -> String {
        match self {
            Derivation::Differences(d) => d.name().to_string(),
            Derivation::SavitzkyGolay(f) => {
                format!("savitzky-golay window {} order {}", f.window(), f.order())
            }
        }
    }
}

/// `v(t)` and `a(t)` at the sample times.
#[derive(Debug, Clone, PartialEq)]
pub struct Kinematics {
    /// Velocity at each sample.
    pub velocity: Vec<Real>,
    /// Acceleration at each sample.
    pub acceleration: Vec<Real>,
}

/// `v = dx/dt` and `a = d²x/dt²` of samples `x(tᵢ)`.
///
/// ```
/// use mechkit::deriv::{Derivation, Difference, kinematics};
/// let t: Vec<f64> = (0..=100).map(|i| f64::from(i) * 0.01).collect();
/// let x: Vec<f64> = t.iter().map(|t| 2.0 - 4.9 * t * t).collect();
/// let k = kinematics(&t, &x, Derivation::Differences(Difference::Central)).unwrap();
/// assert!((k.velocity[50] + 9.8 * 0.5).abs() < 1e-12);
/// assert!(k.acceleration.iter().all(|a| (a + 9.8).abs() < 1e-9));
/// ```
pub fn kinematics(t: &[Real], x: &[Real], how: Derivation) -> Result<Kinematics, DerivError> {
    match how {
        Derivation::Differences(scheme) => {
            let velocity = differentiate(t, x, scheme)?;
            let acceleration = match scheme {
                Difference::Central => second_derivative(t, x)?,
                other => differentiate(t, &velocity, other)?,
            };
            Ok(Kinematics {
                velocity,
                acceleration,
            })
        }
        Derivation::SavitzkyGolay(filter) => Ok(Kinematics {
            velocity: filter.differentiate(t, x, 1)?,
            acceleration: filter.differentiate(t, x, 2)?,
        }),
    }
}

//! The crate-level error, wrapping each module's.

use thiserror::Error;

use crate::Real;

/// Whether `x` reads shorter in exponent form: `3.04e-300` rather than the 300 digits of `{}`
/// (nonzero finite numbers outside 1e-4..1e16).
pub(crate) fn in_exponent_form(x: Real) -> bool {
    x != 0.0 && x.is_finite() && !(1e-4..1e16).contains(&x.abs())
}

/// A number for a message: `0.002`, `2e-15`.
pub(crate) fn short(x: Real) -> String {
    mechkit_expr::short_number(x)
}

/// Numbers for a message as a tuple: `(1, 0, 2e-15)`.
pub(crate) fn short_tuple(xs: &[Real]) -> String {
    let parts: Vec<String> = xs.iter().map(|x| short(*x)).collect();
    format!("({})", parts.join(", "))
}

/// Whether `x` can be divided by: positive, finite and normal, so that `1/x` is finite too.
///
/// The rule for every amount a model inverts (a mass, a moment of inertia): a subnormal mass
/// such as `1e-320 kg` is positive and finite, yet its reciprocal overflows to infinity and
/// the run fails at its first step.
pub fn invertible(x: Real) -> bool {
    x.is_normal() && x > 0.0
}

/// Any error of this crate.
#[derive(Debug, Error)]
#[non_exhaustive]
pub enum Error {
    /// An invalid particle system.
    #[error(transparent)]
    System(#[from] crate::particles::SystemError),
    /// An invalid contact force.
    #[error(transparent)]
    Contact(#[from] crate::forces::ContactError),
    /// A stepper failed.
    #[error(transparent)]
    Integrate(#[from] crate::ode::IntegrateError),
    /// A simulation could not run.
    #[error(transparent)]
    Simulate(#[from] crate::simulate::SimulateError),
    /// An invalid rocket, or its simulation failed.
    #[error(transparent)]
    Rocket(#[from] crate::rocket::RocketError),
    /// An invalid many-particle system, or its run diverged.
    #[error(transparent)]
    Md(#[from] crate::md::MdError),
    /// A data file could not be read, or lacks a column.
    #[error(transparent)]
    Data(#[from] crate::data::DataError),
    /// Samples that cannot be differentiated.
    #[error(transparent)]
    Deriv(#[from] crate::deriv::DerivError),
    /// Adaptive quadrature failed.
    #[error(transparent)]
    Quad(#[from] crate::quad::QuadError),
    /// A fixed quadrature rule cannot be applied.
    #[error(transparent)]
    Rule(#[from] crate::quad::RuleError),
    /// Samples that cannot be integrated.
    #[error(transparent)]
    Samples(#[from] crate::quad::SamplesError),
    /// A formula, unit or question of the calculus tools is invalid.
    #[error(transparent)]
    Calculus(#[from] crate::calculus::CalculusError),
    /// A scenario file is invalid or its run failed.
    #[cfg(feature = "scenario")]
    #[error(transparent)]
    Scenario(#[from] crate::scenario::ScenarioError),
}

#[cfg(test)]
mod tests {
    use super::invertible;
    use crate::particles::{ParticleSystem, SystemError};

    /// Issue 26: a subnormal mass (1e-320 kg) is positive and finite, but 1/m overflows and
    /// the run failed at its first step; every inverted amount must be [`invertible`].
    #[test]
    fn issue_026_a_subnormal_mass_is_not_invertible_and_is_refused() {
        for bad in [0.0, -1.0, 1e-320, f64::INFINITY, f64::NAN] {
            assert!(!invertible(bad), "{bad}");
        }
        for good in [f64::MIN_POSITIVE, 1e-300, 1.0, f64::MAX] {
            assert!(invertible(good) && (1.0 / good).is_finite(), "{good}");
        }
        let e = ParticleSystem::builder(1)
            .body("dust", 1e-320)
            .build()
            .expect_err("a subnormal mass");
        assert!(matches!(e, SystemError::BadMass { .. }));
        assert!(e.to_string().contains("not 1e-320 kg"), "{e}");
        let e = crate::rigid::free3d::FreeBody::new([1.0, 1.0, 1.0], 1e-320)
            .expect_err("a subnormal mass");
        assert!(e.to_string().contains("1e-320 kg"), "{e}");
    }
}

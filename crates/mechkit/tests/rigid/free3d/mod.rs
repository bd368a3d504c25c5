//! Free rigid bodies in 3-D: a torque-free body keeps `L` (world frame) and its kinetic energy;
//! its body-frame ω(t) is the Euler-Poinsot solution in Jacobi's elliptic functions, whose
//! period `4K(m)/λ` is the tennis racket's flip period; an axisymmetric body's ω⊥ turns at
//! `Ω = (I₃ − I₁)ω₃/I₁` in the body; rotation about a principal axis is steady. A heavy
//! symmetric top keeps `E`, `L_z` and `L₃`, precesses steadily at the root of
//! `J₁ cos θ Ω² − J₃ ω₃ Ω + m g ℓ = 0`, and a fast top at about `m g ℓ/(J₃ ω₃)`.

mod elliptic;
mod inputs;
mod top;
mod torque_free;

use mechkit::mass::Vec3;
use mechkit::ode::{AdaptiveConfig, Tableau, Tolerance};
use mechkit::rigid::free3d::{
    Attitude, Formulation, FreeBody, SpinIntegrator, SpinOptions, SpinningBody,
};
use nalgebra::UnitQuaternion;

pub(super) fn racket() -> SpinningBody {
    SpinningBody::free(FreeBody::new([1.0, 2.0, 3.0], 1.0).unwrap())
}

pub(super) fn start(body: &SpinningBody, omega: [f64; 3]) -> Attitude {
    body.attitude(UnitQuaternion::identity(), Vec3::from(omega))
        .unwrap()
}

pub(super) fn options(
    integrator: SpinIntegrator,
    formulation: Formulation,
    samples: usize,
) -> SpinOptions {
    SpinOptions {
        integrator,
        formulation,
        renormalise: true,
        samples,
    }
}

pub(super) fn adaptive(tableau: Tableau, rtol: f64) -> SpinIntegrator {
    SpinIntegrator::Adaptive {
        tableau,
        config: AdaptiveConfig {
            rtol: Tolerance::Scalar(rtol),
            atol: Tolerance::Scalar(rtol * 1e-3),
            ..AdaptiveConfig::default()
        },
    }
}

//! The symmetric heavy top: steady precession and the fast-top approximation.
//!
//! A top with `J₁ = J₂` about its pivot, its centre of mass at distance `ℓ` on the symmetry
//! axis, spinning at `ω₃` about that axis and tilted by `θ` from the vertical, precesses
//! steadily at `Ω` (without nutation) when gravity's torque `m g ℓ sin θ` turns the horizontal
//! part of `L` (Goldstein, *Classical Mechanics*, §5.7):
//!
//! `J₁ cos θ Ω² − J₃ ω₃ Ω + m g ℓ = 0`,
//!
//! with a slow root `Ω ≈ m g ℓ / (J₃ ω₃)` (the fast-top approximation) and a fast one
//! `Ω ≈ J₃ ω₃ / (J₁ cos θ)`; no steady precession exists when the discriminant is negative
//! (a top spinning too slowly to stay up).

use nalgebra::{UnitQuaternion, Vector3};

use super::body::{Attitude, SpinningBody};
use crate::Real;
use crate::mass::Vec3;

/// Parameters of a symmetric top: `(J₁, J₃, m g ℓ)`.
fn symmetric(body: &SpinningBody) -> Option<(Real, Real, Real)> {
    let (d, g) = body.pivot()?;
    let j = body.inertia();
    let symmetric = (j[(0, 0)] - j[(1, 1)]).abs() <= 1e-12 * j[(0, 0)];
    (symmetric && d.x == 0.0 && d.y == 0.0)
        .then(|| (j[(0, 0)], j[(2, 2)], body.body().mass() * g * d.z))
}

impl SpinningBody {
    /// The precession rates `(slow, fast)` of steady precession at tilt `theta` from the
    /// vertical with spin `spin = ω₃` (rad/s): the roots of `J₁ cos θ Ω² − J₃ ω₃ Ω + m g ℓ = 0`
    /// (the slow one alone, twice, at `θ = 90°`). `None` for a body that is not a symmetric top
    /// on its axis, or when no steady precession exists.
    ///
    /// ```
    /// use mechkit::mass::Vec3;
    /// use mechkit::rigid::free3d::{FreeBody, SpinningBody};
    /// let top = SpinningBody::on_pivot(FreeBody::new([2e-4, 2e-4, 3e-4], 0.2)?, Vec3::new(0.0, 0.0, 0.04), 9.81)?;
    /// let (slow, fast) = top.steady_precession(0.3, 200.0).unwrap();
    /// // the slow root is near m g ℓ / (J₃ ω₃)
    /// assert!((slow / top.fast_top_precession(200.0).unwrap() - 1.0).abs() < 0.05);
    /// assert!(fast > 50.0 * slow);
    /// # Ok::<(), mechkit::rigid::free3d::Free3dError>(())
    /// ```
    pub fn steady_precession(&self, theta: Real, spin: Real) -> Option<(Real, Real)> {
        let (j1, j3, mgl) = symmetric(self)?;
        let a = j1 * theta.cos();
        let b = j3 * spin;
        if a.abs() <= 1e-15 * j1 {
            let slow = mgl / b;
            return slow.is_finite().then_some((slow, slow));
        }
        let disc = b * b - 4.0 * a * mgl;
        if disc < 0.0 || b == 0.0 {
            return None;
        }
        // the stable pair of roots: q = (b + sign(b)√disc)/2, Ω = mgl/q and q/a
        let q = 0.5 * (b + b.signum() * disc.sqrt());
        Some((mgl / q, q / a))
    }

    /// The fast-top approximation of the precession rate, `m g ℓ / (J₃ ω₃)`.
    pub fn fast_top_precession(&self, spin: Real) -> Option<Real> {
        let (_, j3, mgl) = symmetric(self)?;
        Some(mgl / (j3 * spin))
    }

    /// The attitude of a top tilted by `theta` about the world x axis (its symmetry axis in
    /// the y-z plane), spinning at `spin = ω₃` about that axis and precessing at `precession`
    /// about the vertical: `ω = Ω ẑ + (ω₃ − Ω cos θ) ê₃`.
    pub fn tilted(&self, theta: Real, spin: Real, precession: Real) -> Attitude {
        let q = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), theta);
        let e3 = q * Vec3::z();
        let omega_world = precession * Vec3::z() + (spin - precession * theta.cos()) * e3;
        let omega_body = q.inverse_transform_vector(&omega_world);
        Attitude {
            q,
            l: q * (self.inertia() * omega_body),
        }
    }
}

//! The equations of motion as a first-order system for [`crate::ode`]: the state is
//! `y = [w, x, y, z, L₁, L₂, L₃]`, a quaternion (body → world) and the angular momentum about
//! the rotation point, in the world frame or in the body frame ([`Formulation`]).
//!
//! - `ω = J⁻¹ L_body` with `L_body = Rᵀ L_world`;
//! - `dq/dt = ½ q ⊗ (0, ω)`;
//! - world frame: `dL/dt = τ_world`, so a torque-free `L` is constant step by step (bit for
//!   bit: every stage of a Runge-Kutta step adds `h · 0`);
//! - body frame (Euler's equations): `dL_body/dt = L_body × ω + Rᵀ τ_world`, whose `|L|` is
//!   conserved only as well as the integrator keeps it.
//!
//! The rotation `R` is computed from `q/|q|`, so `dq/dt` is homogeneous of degree 1 in `q`
//! and every observable depends on the direction of `q` only.

use nalgebra::{Quaternion, UnitQuaternion};

use super::body::{Attitude, SpinningBody};
use crate::Real;
use crate::interval::Jet;
use crate::mass::Vec3;
use crate::ode::{OdeSystem, Series, StepPolynomial};

/// Which angular momentum the state carries.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Formulation {
    /// `L` in the world frame: `dL/dt = τ` (torque-free: constant by construction).
    #[default]
    World,
    /// `L` in the body frame: Euler's equations `dL/dt = L × ω + τ_body`.
    Body,
}

impl Formulation {
    /// The name (`world`, `body`).
    pub fn name(self) -> &'static str {
        match self {
            Formulation::World => "world",
            Formulation::Body => "body",
        }
    }

    /// The state vector of an attitude.
    pub fn to_state(self, a: &Attitude) -> Vec<Real> {
        let q = a.q.quaternion();
        let l = match self {
            Formulation::World => a.l,
            Formulation::Body => a.l_body(),
        };
        vec![q.w, q.i, q.j, q.k, l.x, l.y, l.z]
    }

    /// The attitude of a state vector (the quaternion normalised).
    pub fn attitude(self, y: &[Real]) -> Attitude {
        let q = UnitQuaternion::from_quaternion(Quaternion::new(y[0], y[1], y[2], y[3]));
        let l = Vec3::new(y[4], y[5], y[6]);
        let l = match self {
            Formulation::World => l,
            Formulation::Body => q * l,
        };
        Attitude { q, l }
    }
}

/// A 3×3 matrix as rows of plain numbers (the hot loop avoids generic matrix code, which is
/// slow in unoptimised builds).
pub(super) type Rows = [[Real; 3]; 3];

/// What the rotation's polynomial parts ([`rotation_parts`]) and the matrix products compute
/// with: plain numbers, [`Jet`]s (the enclosures of a piece of a step, with the same
/// operations in the same order), or [`Series`] (polynomials of the step's fraction).
pub(super) trait Ring:
    Copy + std::ops::Add<Output = Self> + std::ops::Sub<Output = Self> + std::ops::Mul<Output = Self>
{
    /// A constant.
    fn c(x: Real) -> Self;
}

/// A [`Ring`] that divides too: what [`rotation`] computes with.
pub(super) trait Scalar: Ring + std::ops::Div<Output = Self> {}

impl Ring for Real {
    #[inline]
    fn c(x: Real) -> Self {
        x
    }
}

impl Scalar for Real {}

impl Ring for Jet {
    #[inline]
    fn c(x: Real) -> Self {
        Jet::constant(x)
    }
}

impl Scalar for Jet {}

impl Ring for Series {
    fn c(x: Real) -> Self {
        Series::constant(x)
    }
}

/// `R(q/|q|) = 1 + (2/N) K` of a quaternion `(w, x, y, z)`, as its polynomial parts: the
/// squared norm `N = |q|²` and the rows of `K`.
pub(super) fn rotation_parts<T: Ring>(y: &[T]) -> (T, [[T; 3]; 3]) {
    let (w, x, yy, z) = (y[0], y[1], y[2], y[3]);
    let zero = T::c(0.0);
    let n = w * w + x * x + yy * yy + z * z;
    let k = [
        [zero - (yy * yy + z * z), x * yy - w * z, x * z + w * yy],
        [x * yy + w * z, zero - (x * x + z * z), yy * z - w * x],
        [x * z - w * yy, yy * z + w * x, zero - (x * x + yy * yy)],
    ];
    (n, k)
}

/// `R(q/|q|)` of a quaternion `(w, x, y, z)`, as rows.
#[inline]
pub(super) fn rotation<T: Scalar>(y: &[T]) -> [[T; 3]; 3] {
    let (n, k) = rotation_parts(y);
    let one = T::c(1.0);
    let s = T::c(2.0) / n;
    let mut r = k;
    for (i, row) in r.iter_mut().enumerate() {
        for (j, e) in row.iter_mut().enumerate() {
            *e = if i == j { one + s * *e } else { s * *e };
        }
    }
    r
}

/// `M v`.
pub(super) fn mul<T: Ring>(m: &[[T; 3]; 3], v: [T; 3]) -> [T; 3] {
    m.map(|r| r[0] * v[0] + r[1] * v[1] + r[2] * v[2])
}

/// `Mᵀ v`.
pub(super) fn mul_t<T: Ring>(m: &[[T; 3]; 3], v: [T; 3]) -> [T; 3] {
    [0, 1, 2].map(|c| m[0][c] * v[0] + m[1][c] * v[1] + m[2][c] * v[2])
}

fn cross(a: [Real; 3], b: [Real; 3]) -> [Real; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// The ODE of a [`SpinningBody`] in a [`Formulation`].
#[derive(Debug, Clone, Copy)]
pub struct SpinEquations<'a> {
    body: &'a SpinningBody,
    formulation: Formulation,
    /// `J⁻¹` (body frame).
    inverse: Rows,
    /// The pivot-to-CM vector (body frame) and the weight `m g` (zero for a free body).
    offset: [Real; 3],
    weight: Real,
}

impl<'a> SpinEquations<'a> {
    /// The equations of `body` with `L` in the frame of `formulation`.
    pub fn new(body: &'a SpinningBody, formulation: Formulation) -> Self {
        let inv = body.inverse_inertia();
        let (offset, weight) = body
            .pivot()
            .map_or(([0.0; 3], 0.0), |(d, g)| (d.into(), body.body().mass() * g));
        Self {
            body,
            formulation,
            inverse: [0, 1, 2].map(|r| [0, 1, 2].map(|c| inv[(r, c)])),
            offset,
            weight,
        }
    }

    /// The body.
    pub fn body(&self) -> &'a SpinningBody {
        self.body
    }

    /// The frame of `L` in the state.
    pub fn formulation(&self) -> Formulation {
        self.formulation
    }

    /// `L` in the body frame at the state `y`, given `R`.
    fn l_body(&self, r: &Rows, y: &[Real]) -> [Real; 3] {
        let l = [y[4], y[5], y[6]];
        match self.formulation {
            Formulation::World => mul_t(r, l),
            Formulation::Body => l,
        }
    }

    /// Encloses `ω` in the body frame (and its time derivative) over a piece of a step, from
    /// the enclosures of the state's components there.
    pub(super) fn omega_body_jet(&self, y: &[Jet]) -> [Jet; 3] {
        let r = rotation(y);
        let l = [y[4], y[5], y[6]];
        let lb = match self.formulation {
            Formulation::World => mul_t(&r, l),
            Formulation::Body => l,
        };
        let inverse = self.inverse.map(|row| row.map(Jet::constant));
        mul(&inverse, lb)
    }

    /// `ω` about `axis` (body frame) times `N = |q|²`, and `N`, as polynomials of the step
    /// whose interpolant is `poly`: `N ω = J⁻¹ (N L + 2 Kᵀ L)` in the world frame (`R = 1 +
    /// (2/N) K`, see [`rotation_parts`]), `J⁻¹ L` with `N = 1` in the body frame. Where `N >
    /// 0`, the first has the sign of `ω` about the axis, and it is a polynomial: it keeps the
    /// cancellations that interval arithmetic on the state loses.
    pub(super) fn omega_numerator(&self, poly: &StepPolynomial, axis: usize) -> (Series, Series) {
        let y: [Series; 7] = std::array::from_fn(|i| Series::component(poly, i));
        let l = [y[4], y[5], y[6]];
        let (n, lb) = match self.formulation {
            Formulation::World => {
                let (n, k) = rotation_parts(&y);
                let kl = mul_t(&k, l);
                let two = Series::constant(2.0);
                (n, [0, 1, 2].map(|j| n * l[j] + two * kl[j]))
            }
            Formulation::Body => (Series::constant(1.0), l),
        };
        let row = self.inverse[axis].map(Series::constant);
        (row[0] * lb[0] + row[1] * lb[1] + row[2] * lb[2], n)
    }

    /// `ω` in the body frame at the state `y`.
    pub fn omega_body(&self, y: &[Real]) -> Vec3 {
        let lb = self.l_body(&rotation(y), y);
        Vec3::from(mul(&self.inverse, lb))
    }

    /// The world torque `(R d) × (0, 0, −m g)`.
    fn torque(&self, r: &Rows) -> [Real; 3] {
        if self.weight == 0.0 {
            return [0.0; 3];
        }
        let rc = mul(r, self.offset);
        [-rc[1] * self.weight, rc[0] * self.weight, 0.0]
    }

    /// What the run loop checks at every step end, from the state `y`:
    /// `(|L|, L_z (world), L₃ (body), T + U, φ)`, with `φ` the precession angle.
    pub(super) fn invariants(&self, y: &[Real]) -> [Real; 5] {
        let r = rotation(y);
        let lb = self.l_body(&r, y);
        let lw = match self.formulation {
            Formulation::World => [y[4], y[5], y[6]],
            Formulation::Body => mul(&r, lb),
        };
        let w = mul(&self.inverse, lb);
        let kinetic = 0.5 * (lb[0] * w[0] + lb[1] * w[1] + lb[2] * w[2]);
        let z_cm = mul(&r, self.offset)[2];
        let norm = (lb[0] * lb[0] + lb[1] * lb[1] + lb[2] * lb[2]).sqrt();
        let phi = r[0][2].atan2(-r[1][2]);
        [norm, lw[2], lb[2], kinetic + self.weight * z_cm, phi]
    }
}

impl OdeSystem for SpinEquations<'_> {
    fn dim(&self) -> usize {
        7
    }

    fn rhs_into(&self, _t: Real, y: &[Real], dydt: &mut [Real]) {
        let r = rotation(y);
        let lb = self.l_body(&r, y);
        let w = mul(&self.inverse, lb);
        let (qw, qv) = (y[0], [y[1], y[2], y[3]]);
        // q ⊗ (0, ω) = (−v·ω, w ω + v × ω)
        let c = cross(qv, w);
        dydt[0] = -0.5 * (qv[0] * w[0] + qv[1] * w[1] + qv[2] * w[2]);
        for k in 0..3 {
            dydt[1 + k] = 0.5 * (qw * w[k] + c[k]);
        }
        let tau = self.torque(&r);
        let dl = match self.formulation {
            Formulation::World => tau,
            Formulation::Body => {
                let lw = cross(lb, w);
                let tb = mul_t(&r, tau);
                [lw[0] + tb[0], lw[1] + tb[1], lw[2] + tb[2]]
            }
        };
        dydt[4..7].copy_from_slice(&dl);
    }
}

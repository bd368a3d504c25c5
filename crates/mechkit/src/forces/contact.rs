//! Contact forces: a stiff repulsion that acts only while two bodies (spheres of given radii)
//! overlap, or a body overlaps a fixed wall, the continuous alternative to an instantaneous
//! collision with a coefficient of restitution ([`crate::collisions`]).
//!
//! For a pair of bodies the overlap is `δ = R_a + R_b - |x_b - x_a|` and the normal
//! `n̂ = (x_b - x_a)/|x_b - x_a|` (in 1-D the sign of `x_b - x_a`; at coincident centres `+x`);
//! `b` is pushed along `+n̂` and `a` along `-n̂` with equal force (Newton's third law). For a
//! wall through `p` with unit normal `n̂`, `δ = R - (x - p)·n̂` and the body is pushed along
//! `n̂`. The normal force is the law's elastic force plus the damping (see
//! [`ContactLaw`] and [`ContactDamping`]), `F = F_e(δ) + F_d(δ, δ̇)`, for `δ > 0` only, clamped
//! at `F ≥ 0` unless attraction is allowed.
//!
//! # Two forces for the energy ledger
//!
//! The energy ledger ([`crate::energy::EnergyLedger`]) treats every force that reports a
//! potential as conservative: `E = K + ΣU` sums those potentials, and only the work of forces
//! *without* a potential counts as non-conservative work, the work `ΔE` must equal
//! (`non_conservative_work`, and the run summary's `relative_drift`). A single damped contact
//! force reporting its elastic energy would book the damper's loss as the method's energy
//! error. So a contact is two forces:
//!
//! - [`ContactForce`], the elastic part: position-dependent only, potential `Σ U(δ)` over the
//!   overlapping contacts; its work over a whole contact is zero;
//! - [`ContactDamper`] (from [`ContactForce::damper`], named `<name>_damping`), the rest of the
//!   normal force, `F - F_e`: velocity-dependent, no potential; its work is the energy the
//!   contact dissipated, and equals `ΔE` when no other force dissipates.
//!
//! Add both to the system, [`ContactForce::into_forces`] gives them boxed. During a contact
//! the ledger then shows kinetic energy turning into elastic energy and back, minus what the
//! damper took.
//!
//! # Numerical notes
//!
//! - The linear dashpot's force jumps by `c v` when a contact starts, so fixed-step methods
//!   are only first order through it (the Hunt-Crossley force is continuous). Adaptive methods
//!   shrink the step there.
//! - Adaptive runs integrate the work of each force with the motion, but outside the error
//!   control. When the clamp is active at the end of a contact the elastic and damping forces
//!   cancel while the overlap runs out, so the kink of their powers at `δ = 0` is invisible to
//!   the step control: their sum (and the work-energy residual) stays exact, but the split of
//!   the work between them may be off by up to ~1e-3 of the energy. Put the work under error
//!   control ([`crate::ode::AdaptiveConfig::error_components`] = number of state components +
//!   number of forces) when the split matters.

use super::contact_builder::{ContactForceBuilder, ContactPair, ContactWall};
use super::contact_damper::ContactDamper;
use super::contact_emit::emit_law_force;
use super::contact_law::{ContactDamping, ContactLaw};
use super::emit::ForceEmitter;
use super::force::Force;
use crate::Real;
use crate::particles::Kinematics;

/// The elastic contact force of spheres with each other and with walls, and the description
/// of the whole contact (law, damping, geometry).
///
/// As a [`Force`] it is the elastic part only; add [`ContactForce::damper`] too for a damped
/// contact (the module doc says why), or use [`ContactForce::into_forces`].
///
/// # Example
/// ```
/// use mechkit::forces::{ContactDamping, ContactForce, ContactLaw, linear_restitution_clamped};
/// use mechkit::ode::{AdaptiveConfig, Method, State, Tolerance};
/// use mechkit::particles::ParticleSystem;
/// use mechkit::simulate::Simulation;
/// // a ball (m = 1 kg, R = 0.1 m) thrown at the wall x = 0 at 2 m/s
/// let (k, c, m) = (1e4, 40.0, 1.0);
/// let contact = ContactForce::builder(1)
///     .law(ContactLaw::linear(k))
///     .damping(ContactDamping::Linear { c })
///     .wall(&[0.0], &[1.0], &[(0, 0.1)])
///     .build()
///     .unwrap();
/// let mut sys = ParticleSystem::builder(1).body("ball", m);
/// for f in contact.into_forces() {
///     sys = sys.boxed_force(f);
/// }
/// let sys = sys.build().unwrap();
/// // the state (2 components) and the work of both forces under error control
/// let config = AdaptiveConfig {
///     rtol: Tolerance::Scalar(1e-10),
///     error_components: Some(4),
///     ..AdaptiveConfig::default()
/// };
/// let report = Simulation::adaptive(&sys, Method::Dop853, config)
///     .t_max(0.2)
///     .run(State::from_qv(0.0, &[0.2], &[-2.0]), &mut [])
///     .unwrap();
/// let e = report.final_state.y[1] / 2.0;
/// assert!((e - linear_restitution_clamped(k, c, m)).abs() < 1e-6);
/// // the damper's work is the kinetic energy lost, the elastic force's is zero
/// let l = &report.ledger;
/// let lost = l.kinetic_end() - l.kinetic_start();
/// assert!((l.work_of("contact_damping").unwrap() - lost).abs() < 1e-8);
/// assert!(l.work_of("contact").unwrap().abs() < 1e-8);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct ContactForce {
    pub(super) name: String,
    pub(super) dim: usize,
    pub(super) law: ContactLaw,
    pub(super) damping: ContactDamping,
    pub(super) attraction: bool,
    pub(super) pairs: Vec<ContactPair>,
    pub(super) walls: Vec<ContactWall>,
}

/// One overlapping contact at an instant: `b` is pushed along `n`, `a` (if a body) against it.
pub(super) struct Touch {
    a: Option<usize>,
    b: usize,
    n: [Real; 3],
    /// The overlap `δ > 0`.
    pub(super) delta: Real,
    /// Its rate `δ̇`.
    pub(super) rate: Real,
}

impl Touch {
    /// Adds the force `magnitude n̂` on `b` (and `-magnitude n̂` on `a`) into `out`.
    #[inline]
    pub(super) fn apply(&self, magnitude: Real, dim: usize, out: &mut [Real]) {
        for i in 0..dim {
            let f = magnitude * self.n[i];
            out[self.b * dim + i] += f;
            if let Some(a) = self.a {
                out[a * dim + i] -= f;
            }
        }
    }
}

impl ContactForce {
    /// Starts a contact force in `dim` dimensions.
    pub fn builder(dim: usize) -> ContactForceBuilder {
        ContactForceBuilder::new(dim)
    }

    /// Spatial dimensions.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// The elastic law.
    pub fn law(&self) -> ContactLaw {
        self.law
    }

    /// The damping.
    pub fn damping(&self) -> ContactDamping {
        self.damping
    }

    /// Whether the total normal force may pull (not clamped at zero).
    pub fn allows_attraction(&self) -> bool {
        self.attraction
    }

    /// The pairs of bodies.
    pub fn pairs(&self) -> &[ContactPair] {
        &self.pairs
    }

    /// The body-wall contacts (normals of unit length).
    pub fn walls(&self) -> &[ContactWall] {
        &self.walls
    }

    /// The total normal force of one contact at overlap `δ` growing at rate `δ̇`: elastic plus
    /// damping, clamped at zero unless attraction is allowed; zero when `δ ≤ 0`.
    pub fn normal_force(&self, delta: Real, rate: Real) -> Real {
        if delta <= 0.0 {
            return 0.0;
        }
        let f = self.law.force(delta) + self.damping.force(self.law, delta, rate);
        if self.attraction { f } else { f.max(0.0) }
    }

    /// The overlap `δ` of every contact (pairs first, then walls; negative is a gap) at the
    /// positions `q` (`dim` per body), into `out`.
    pub fn overlaps_into(&self, q: &[Real], out: &mut Vec<Real>) {
        let dim = self.dim;
        let x = |b: usize| &q[b * dim..(b + 1) * dim];
        out.clear();
        out.extend(self.pairs.iter().map(|p| {
            let r2: Real = x(p.a)
                .iter()
                .zip(x(p.b))
                .map(|(a, b)| (b - a) * (b - a))
                .sum();
            p.reach - r2.sqrt()
        }));
        out.extend(self.walls.iter().map(|w| {
            let d: Real = (0..dim)
                .map(|i| (x(w.body)[i] - w.point[i]) * w.normal[i])
                .sum();
            w.radius - d
        }));
    }

    /// The overlaps of [`ContactForce::overlaps_into`], as a new vector.
    pub fn overlaps(&self, q: &[Real]) -> Vec<Real> {
        let mut out = Vec::with_capacity(self.pairs.len() + self.walls.len());
        self.overlaps_into(q, &mut out);
        out
    }

    /// The damping part as a force of its own, named `<name>_damping`; `None` when the contact
    /// is not damped.
    pub fn damper(&self) -> Option<ContactDamper> {
        self.damping
            .is_active()
            .then(|| ContactDamper::new(format!("{}_damping", self.name), self.clone()))
    }

    /// The elastic force and, if damped, the damper, boxed for
    /// [`crate::particles::ParticleSystemBuilder::boxed_force`].
    pub fn into_forces(self) -> Vec<Box<dyn Force>> {
        let damper = self.damper();
        let mut forces: Vec<Box<dyn Force>> = vec![Box::new(self)];
        if let Some(d) = damper {
            forces.push(Box::new(d));
        }
        forces
    }

    /// Calls `f` with every overlapping contact.
    pub(super) fn for_each_touch(&self, k: &Kinematics<'_>, mut f: impl FnMut(&Touch)) {
        let dim = self.dim;
        assert_eq!(
            k.dim, dim,
            "the contact `{}` is {dim}-D but the system is {}-D",
            self.name, k.dim
        );
        for p in &self.pairs {
            let (xa, xb) = (k.position(p.a), k.position(p.b));
            let mut n = [0.0; 3];
            let mut r2 = 0.0;
            for i in 0..dim {
                n[i] = xb[i] - xa[i];
                r2 += n[i] * n[i];
            }
            if r2 >= p.reach * p.reach {
                continue;
            }
            let r = r2.sqrt();
            if r > 0.0 {
                for c in &mut n[..dim] {
                    *c /= r;
                }
            } else {
                n = [1.0, 0.0, 0.0];
            }
            let (va, vb) = (k.velocity(p.a), k.velocity(p.b));
            let rate = (0..dim).map(|i| (va[i] - vb[i]) * n[i]).sum();
            f(&Touch {
                a: Some(p.a),
                b: p.b,
                n,
                delta: p.reach - r,
                rate,
            });
        }
        for w in &self.walls {
            let x = k.position(w.body);
            let d: Real = (0..dim).map(|i| (x[i] - w.point[i]) * w.normal[i]).sum();
            let delta = w.radius - d;
            if delta <= 0.0 {
                continue;
            }
            let mut n = [0.0; 3];
            n[..dim].copy_from_slice(&w.normal);
            let v = k.velocity(w.body);
            let rate = -(0..dim).map(|i| v[i] * n[i]).sum::<Real>();
            f(&Touch {
                a: None,
                b: w.body,
                n,
                delta,
                rate,
            });
        }
    }

    pub(super) fn body_list(&self) -> Vec<usize> {
        let mut b: Vec<usize> = self.pairs.iter().flat_map(|p| [p.a, p.b]).collect();
        b.extend(self.walls.iter().map(|w| w.body));
        b.sort_unstable();
        b.dedup();
        b
    }
}

impl Force for ContactForce {
    fn name(&self) -> &str {
        &self.name
    }

    /// The elastic force `F_e(δ) n̂` of every overlapping contact.
    fn add_forces(&self, k: &Kinematics<'_>, out: &mut [Real]) {
        self.for_each_touch(k, |t| t.apply(self.law.force(t.delta), self.dim, out));
    }

    fn emit(&self, e: &mut ForceEmitter<'_>) -> bool {
        self.emit_touches(e, |e, t| emit_law_force(e, self.law, t.delta))
    }

    /// The elastic energy `Σ U(δ)` stored in the overlapping contacts (zero when none
    /// overlaps).
    fn potential(&self, k: &Kinematics<'_>) -> Option<Real> {
        let mut u = 0.0;
        self.for_each_touch(k, |t| u += self.law.energy(t.delta));
        Some(u)
    }

    fn internal(&self) -> bool {
        self.walls.is_empty()
    }

    fn bodies(&self) -> Vec<usize> {
        self.body_list()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kin<'a>(dim: usize, x: &'a [Real], v: &'a [Real], m: &'a [Real]) -> Kinematics<'a> {
        Kinematics {
            t: 0.0,
            dim,
            x,
            v,
            mass: m,
        }
    }

    fn forces(f: &dyn Force, k: &Kinematics<'_>) -> Vec<Real> {
        let mut out = vec![0.0; k.x.len()];
        f.add_forces(k, &mut out);
        out
    }

    #[test]
    fn pairs_push_apart_equally_in_every_dimension() {
        for dim in 1..=3 {
            let c = ContactForce::builder(dim)
                .law(ContactLaw::hertz(1e5))
                .damping(ContactDamping::HuntCrossley { alpha: 0.3 })
                .pair(0, 1, 0.5)
                .build()
                .unwrap();
            // b at distance 0.4 from a along (1, 2, 2)/3, approaching
            let dir = [1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0];
            let unit: Vec<Real> = if dim == 1 {
                vec![-1.0]
            } else {
                dir[..dim].to_vec()
            };
            let norm = unit.iter().map(|u| u * u).sum::<Real>().sqrt();
            let mut x = vec![0.5; dim];
            x.extend(unit.iter().map(|u| 0.5 + 0.4 * u / norm));
            let mut v = vec![0.0; dim];
            v.extend(unit.iter().map(|u| -u / norm));
            let k = kin(dim, &x, &v, &[1.0, 1.0]);
            let fe = forces(&c, &k);
            let fd = forces(&c.damper().unwrap(), &k);
            let expected = 1e5 * 0.1f64.powf(1.5);
            for i in 0..dim {
                let n = unit[i] / norm;
                assert!((fe[dim + i] - expected * n).abs() < 1e-9, "dim {dim}");
                assert_eq!(fe[i], -fe[dim + i]);
                // approaching at δ̇ = 1: F_d = α F_e
                assert!((fd[dim + i] - 0.3 * expected * n).abs() < 1e-9);
                assert_eq!(fd[i], -fd[dim + i]);
            }
            assert!((c.potential(&k).unwrap() - 0.4 * 1e5 * 0.1f64.powf(2.5)).abs() < 1e-9);
        }
    }

    #[test]
    fn the_force_is_minus_the_gradient_of_the_potential() {
        let c = ContactForce::builder(2)
            .law(ContactLaw::linear(50.0))
            .spheres(&[(0, 0.3), (1, 0.2)])
            .wall(&[0.0, -1.0], &[1.0, 1.0], &[(0, 0.3), (1, 0.2)])
            .build()
            .unwrap();
        let x = [0.0, -0.6, 0.35, -0.7];
        let v = [0.0; 4];
        let m = [1.0, 1.0];
        let f = forces(&c, &kin(2, &x, &v, &m));
        let u = |x: &[Real]| c.potential(&kin(2, x, &v, &m)).unwrap();
        assert!(u(&x) > 0.0);
        for i in 0..4 {
            let (mut xp, mut xm) = (x, x);
            xp[i] += 1e-6;
            xm[i] -= 1e-6;
            let grad = (u(&xp) - u(&xm)) / 2e-6;
            assert!(
                (f[i] + grad).abs() < 1e-6,
                "component {i}: {} vs {}",
                f[i],
                -grad
            );
        }
        // the pair and ball 0 overlap, ball 1 is clear of the wall
        let d = c.overlaps(&x);
        assert_eq!(d.len(), 3);
        assert!(d[0] > 0.0 && d[1] > 0.0 && d[2] < 0.0, "{d:?}");
    }

    #[test]
    fn walls_push_along_their_normal_and_nothing_acts_apart() {
        let c = ContactForce::builder(1)
            .law(ContactLaw::linear(10.0))
            .damping(ContactDamping::Linear { c: 4.0 })
            .wall(&[1.0], &[-5.0], &[(0, 0.5)])
            .build()
            .unwrap();
        let m = [1.0];
        // 0.2 into the wall at x = 1 from the left, receding fast: clamped to zero in total
        let k = kin(1, &[0.7], &[-1.0], &m);
        let (fe, fd) = (forces(&c, &k)[0], forces(&c.damper().unwrap(), &k)[0]);
        assert!((fe + 2.0).abs() < 1e-12);
        assert!((fe + fd).abs() < 1e-12);
        // approaching: the damper adds c v
        let k = kin(1, &[0.7], &[0.25], &m);
        assert!((forces(&c.damper().unwrap(), &k)[0] + 1.0).abs() < 1e-12);
        // apart: nothing
        let k = kin(1, &[0.4], &[3.0], &m);
        assert_eq!(forces(&c, &k)[0] + forces(&c.damper().unwrap(), &k)[0], 0.0);
        assert_eq!(c.potential(&k), Some(0.0));
        assert_eq!(c.bodies(), vec![0]);
    }
}

//! Symplectic splitting methods for `q'' = a(t, q)`: compositions of drifts
//! (`q += c_i h v`) and kicks (`v += d_i h a(q)`), with the coefficients as data, each citing
//! its source.
//!
//! A step is `drift(c_0) kick(d_0) drift(c_1) kick(d_1) … kick(d_{m-1}) drift(c_m)`. Every
//! drift and kick is the exact flow of a part of the Hamiltonian `H = T(v) + V(q)`, so the
//! composition is symplectic and time-symmetric when the coefficients are palindromic: the
//! energy error then oscillates with bounded amplitude instead of drifting. When the first and
//! last drifts are zero (kick-drift-kick form), the last kick's acceleration is the next step's
//! first, so an `m`-kick method costs `m − 1` evaluations per step.
//!
//! The splitting needs forces of position (and time) only; a system whose acceleration depends
//! on the velocity is refused with [`IntegrateError::NeedsPositionForces`].

#![allow(clippy::excessive_precision)] // coefficients as published

use super::state::State;
use super::stepper::{IntegrateError, Provided, StepInfo, Stepper};
use super::system::SecondOrderSystem;
use crate::Real;

/// The coefficients of a drift-kick composition.
#[derive(Debug, Clone, PartialEq)]
pub struct Composition {
    /// Name as in scenario files.
    pub name: &'static str,
    /// Where the coefficients come from.
    pub source: &'static str,
    /// Global order.
    pub order: u32,
    /// Drift coefficients `c_0 … c_m` (one more than the kicks).
    pub drifts: Vec<Real>,
    /// Kick coefficients `d_0 … d_{m-1}`.
    pub kicks: Vec<Real>,
}

/// Triple-jump weights `(w_1, w_0)` of Yoshida/Suzuki/Creutz-Gocksch: `w_1 = 1/(2 − 2^(1/3))`,
/// `w_0 = 1 − 2 w_1`.
fn triple_jump() -> (Real, Real) {
    let w1 = 1.0 / (2.0 - Real::cbrt(2.0));
    (w1, 1.0 - 2.0 * w1)
}

/// The kick-drift-kick form of a composition of velocity-Verlet substeps with weights `w`.
fn verlet_composition(w: &[Real]) -> (Vec<Real>, Vec<Real>) {
    let mut drifts = vec![0.0];
    let mut kicks = vec![0.5 * w[0]];
    for (i, wi) in w.iter().enumerate() {
        drifts.push(*wi);
        let next = w.get(i + 1).copied().unwrap_or(0.0);
        kicks.push(0.5 * (wi + next));
    }
    // drifts [0, w_0, …, w_{k-1}, 0], kicks [w_0/2, (w_0+w_1)/2, …, w_{k-1}/2]
    drifts.push(0.0);
    (drifts, kicks)
}

impl Composition {
    /// Velocity Verlet (leapfrog) in kick-drift-kick form, 2nd order, one evaluation a step.
    pub fn leapfrog() -> Composition {
        Composition {
            name: "leapfrog",
            source: "L. Verlet, Phys. Rev. 159, 98 (1967); Swope et al., J. Chem. Phys. 76, 637 (1982)",
            order: 2,
            drifts: vec![0.0, 1.0, 0.0],
            kicks: vec![0.5, 0.5],
        }
    }

    /// Yoshida's 4th-order triple jump of velocity Verlet (H. Yoshida, Phys. Lett. A 150, 262
    /// (1990)), three evaluations a step.
    pub fn yoshida4() -> Composition {
        let (w1, w0) = triple_jump();
        let (drifts, kicks) = verlet_composition(&[w1, w0, w1]);
        Composition {
            name: "yoshida4",
            source: "H. Yoshida, Phys. Lett. A 150, 262-268 (1990), eq. (4.6)",
            order: 4,
            drifts,
            kicks,
        }
    }

    /// Forest and Ruth's 4th-order method, the triple jump in drift-kick-drift form (E. Forest,
    /// R. D. Ruth, Physica D 43, 105 (1990)), three evaluations a step.
    pub fn forest_ruth() -> Composition {
        let (w1, w0) = triple_jump();
        Composition {
            name: "forest-ruth",
            source: "E. Forest, R. D. Ruth, Physica D 43, 105-117 (1990)",
            order: 4,
            drifts: vec![0.5 * w1, 0.5 * (w1 + w0), 0.5 * (w1 + w0), 0.5 * w1],
            kicks: vec![w1, w0, w1],
        }
    }

    /// PEFRL, the position-extended Forest-Ruth-like method optimised for a small error
    /// constant (I. P. Omelyan, I. M. Mryglod, R. Folk, Comput. Phys. Commun. 146, 188 (2002),
    /// eq. 20): four evaluations a step but an error about 100 times smaller than Forest-Ruth's.
    pub fn pefrl() -> Composition {
        let xi = 0.178_617_895_844_809_1;
        let lambda = -0.212_341_831_062_605_4;
        let chi = -0.066_264_582_669_818_49;
        Composition {
            name: "pefrl",
            source: "I. P. Omelyan, I. M. Mryglod, R. Folk, Comput. Phys. Commun. 146, 188-202 (2002), eq. (20)",
            order: 4,
            drifts: vec![xi, chi, 1.0 - 2.0 * (chi + xi), chi, xi],
            kicks: vec![
                0.5 * (1.0 - 2.0 * lambda),
                lambda,
                lambda,
                0.5 * (1.0 - 2.0 * lambda),
            ],
        }
    }

    /// Yoshida's 6th-order composition of seven velocity-Verlet substeps (solution A of H.
    /// Yoshida, Phys. Lett. A 150, 262 (1990), Table 1), seven evaluations a step.
    pub fn yoshida6() -> Composition {
        let w1 = -1.177_679_984_178_87;
        let w2 = 0.235_573_213_359_357;
        let w3 = 0.784_513_610_477_560;
        let w0 = 1.0 - 2.0 * (w1 + w2 + w3);
        let (drifts, kicks) = verlet_composition(&[w3, w2, w1, w0, w1, w2, w3]);
        Composition {
            name: "yoshida6",
            source: "H. Yoshida, Phys. Lett. A 150, 262-268 (1990), Table 1, solution A",
            order: 6,
            drifts,
            kicks,
        }
    }

    /// Every composition, for listings.
    pub fn all() -> Vec<Composition> {
        vec![
            Composition::leapfrog(),
            Composition::yoshida4(),
            Composition::forest_ruth(),
            Composition::pefrl(),
            Composition::yoshida6(),
        ]
    }

    /// Looks a composition up by name.
    pub fn by_name(name: &str) -> Option<Composition> {
        let norm = name.trim().to_ascii_lowercase().replace(['_', ' '], "-");
        Some(match norm.as_str() {
            "leapfrog" | "kdk" => Composition::leapfrog(),
            "yoshida4" | "yoshida" | "triple-jump" => Composition::yoshida4(),
            "forest-ruth" | "forestruth" => Composition::forest_ruth(),
            "pefrl" => Composition::pefrl(),
            "yoshida6" => Composition::yoshida6(),
            _ => return None,
        })
    }

    /// Evaluations of the acceleration per step (after the first).
    pub fn evaluations_per_step(&self) -> usize {
        let reused = self.drifts[0] == 0.0 && *self.drifts.last().expect("drifts") == 0.0;
        self.kicks.iter().filter(|d| **d != 0.0).count() - usize::from(reused)
    }

    /// Checks that the drifts and the kicks each sum to 1 (consistency) to 1e-13.
    pub fn check(&self) -> Result<(), String> {
        if self.drifts.len() != self.kicks.len() + 1 {
            return Err(format!(
                "{}: {} drifts for {} kicks (need one more drift)",
                self.name,
                self.drifts.len(),
                self.kicks.len()
            ));
        }
        let (sc, sd) = (
            self.drifts.iter().sum::<Real>(),
            self.kicks.iter().sum::<Real>(),
        );
        if (sc - 1.0).abs() > 1e-13 || (sd - 1.0).abs() > 1e-13 {
            return Err(format!(
                "{}: drifts sum to {}, kicks to {}; both must be 1",
                self.name,
                crate::error::short(sc),
                crate::error::short(sd)
            ));
        }
        Ok(())
    }
}

/// A fixed-step symplectic integrator from a [`Composition`].
///
/// # Example
/// ```
/// use mechkit::ode::{Composition, State, Stepper, Symplectic};
/// use mechkit::ode::reference::Oscillator;
/// let osc = Oscillator { omega: 1.0 };
/// let mut s = State::from_qv(0.0, &[1.0], &[0.0]);
/// Symplectic::new(Composition::yoshida4()).integrate(&osc, &mut s, 1.0, 0.01).unwrap();
/// assert!((s.y[0] - 1f64.cos()).abs() < 1e-9);
/// ```
#[derive(Debug, Clone)]
pub struct Symplectic {
    composition: Composition,
    acc: Vec<Real>,
    /// `acc` holds the acceleration at this time (the state unchanged since).
    cached_t: Option<Real>,
    provided: Provided,
}

impl Symplectic {
    /// A stepper for `composition` (which must pass [`Composition::check`]).
    pub fn new(composition: Composition) -> Self {
        composition.check().unwrap_or_else(|e| panic!("{e}"));
        Self {
            composition,
            acc: Vec::new(),
            cached_t: None,
            provided: Provided::default(),
        }
    }

    /// The coefficients.
    pub fn composition(&self) -> &Composition {
        &self.composition
    }
}

impl<S: SecondOrderSystem + ?Sized> Stepper<S> for Symplectic {
    fn name(&self) -> &'static str {
        self.composition.name
    }

    fn order(&self) -> u32 {
        self.composition.order
    }

    fn reset(&mut self) {
        self.cached_t = None;
        self.provided.clear();
    }

    fn provide_derivative(&mut self, t: Real, dydt: &[Real]) {
        self.provided.set(t, dydt);
    }

    fn step(&mut self, sys: &S, state: &mut State, h: Real) -> Result<StepInfo, IntegrateError> {
        if sys.velocity_dependent() {
            return Err(IntegrateError::NeedsPositionForces {
                method: self.composition.name,
            });
        }
        let n = sys.dof();
        self.acc.resize(n, 0.0);
        let t0 = state.t;
        let (q, v) = state.qv_mut();
        let c = &self.composition;
        let mut evaluations = 0;
        let mut tau = 0.0;
        let mut cached = if self.provided.take(t0) {
            self.acc.copy_from_slice(&self.provided.dydt[n..]);
            true
        } else {
            self.cached_t == Some(t0)
        };
        for (i, d) in c.kicks.iter().enumerate() {
            let ci = c.drifts[i];
            if ci != 0.0 {
                for (qi, vi) in q.iter_mut().zip(v.iter()) {
                    *qi += ci * h * vi;
                }
                tau += ci;
                cached = false;
            }
            if *d == 0.0 {
                continue;
            }
            if !cached {
                sys.accel_into(t0 + tau * h, q, v, &mut self.acc);
                evaluations += 1;
            }
            cached = false;
            for (vi, a) in v.iter_mut().zip(&self.acc) {
                *vi += d * h * a;
            }
        }
        let last = *c.drifts.last().expect("drifts");
        if last != 0.0 {
            for (qi, vi) in q.iter_mut().zip(v.iter()) {
                *qi += last * h * vi;
            }
        }
        state.t = t0 + h;
        // the last kick's acceleration is the next step's first when no drift follows it
        self.cached_t = (last == 0.0).then_some(state.t);
        Ok(StepInfo { evaluations })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_composition_is_consistent_and_symmetric() {
        for c in Composition::all() {
            c.check().unwrap();
            let rev: Vec<Real> = c.drifts.iter().rev().copied().collect();
            assert!(
                rev.iter()
                    .zip(&c.drifts)
                    .all(|(a, b)| (a - b).abs() < 1e-15),
                "{}",
                c.name
            );
            let rev: Vec<Real> = c.kicks.iter().rev().copied().collect();
            assert!(
                rev.iter().zip(&c.kicks).all(|(a, b)| (a - b).abs() < 1e-15),
                "{}",
                c.name
            );
        }
    }

    #[test]
    fn evaluation_counts() {
        let counts: Vec<usize> = Composition::all()
            .iter()
            .map(Composition::evaluations_per_step)
            .collect();
        assert_eq!(counts, [1, 3, 3, 4, 7]);
    }
}

//! Where events can fire inside a step, proven: the times at which the scan must look so that
//! no sign change of an event function along the step's interpolant is missed.
//!
//! For an event whose function `g` can be enclosed ([`Condition::enclose`]), the step is cut
//! into pieces proven sign-definite, monotone or at rounding level ([`StepProof`]); the ends of
//! every piece that is not sign-definite become sample points of the scan ([`super::scan`]),
//! which sees every sign change between consecutive points and locates it by Brent's method.
//! So every sign change of odd multiplicity of `g` along the interpolant is found, in time
//! order, however short the excursion, and however many per step. A zero of even
//! multiplicity (a touch) is no sign change: it does not fire.
//!
//! Functions that read the forces (accelerations, potential energy, power, and the work in
//! fixed-step runs) cannot be enclosed: they are sampled at evenly spaced points, as is a
//! step that would need more than [`MAX_BOUNDS`] enclosures for one event (with a warning).
//!
//! [`Condition::enclose`]: super::Condition::enclose

use super::event::Event;
use crate::Real;
use crate::ode::{MAX_BOUNDS, ProofOutcome, StepPolynomial, StepProof};
use crate::particles::{ParticleSystem, StateJets};

/// Evenly spaced interior samples of an event that ran out of enclosures in a step.
pub const FALLBACK_SAMPLES: usize = 64;

/// Reused buffers of the proofs, and which events were told to have fallen back to sampling.
#[derive(Debug, Default)]
pub(crate) struct Prover {
    /// The step's interpolant.
    pub poly: StepPolynomial,
    proof: StepProof,
    fractions: Vec<Real>,
    warned: Vec<bool>,
}

/// What the proof needs of the run.
pub(crate) struct Proving<'a> {
    pub events: &'a [Event],
    pub enabled: &'a [bool],
    pub sys: &'a ParticleSystem,
    /// Whether the interpolant carries the work of each force (adaptive runs).
    pub work: bool,
    /// Interior samples of an event that cannot be enclosed.
    pub default_interior: usize,
    /// The states `[q, v]` at the step's start and end (for the samples an unproven event
    /// asks for: [`Event::samples_needed`]).
    pub ends: (&'a [Real], &'a [Real]),
}

/// Most interior samples an unproven event may ask for in one step.
const MAX_INTERIOR: usize = 100_000;

impl Prover {
    /// Fills `points` with the sorted times strictly inside the step of [`Prover::poly`] at
    /// which the event functions must be sampled: the ends of the pieces that are not
    /// sign-definite for the events that can be enclosed, evenly spaced samples for the
    /// others (at least as many as they ask for: [`Event::samples_needed`]).
    pub fn points(&mut self, p: &Proving<'_>, points: &mut Vec<Real>, warnings: &mut Vec<String>) {
        points.clear();
        self.fractions.clear();
        self.warned.resize(p.events.len(), false);
        let (t0, h) = (self.poly.t0, self.poly.h);
        let asked = |e: &Event| e.samples_needed(p.ends.0, p.ends.1, h).min(MAX_INTERIOR);
        let mut uniform = 0;
        for (i, event) in p.events.iter().enumerate() {
            if !p.enabled[i] {
                continue;
            }
            let condition = event.condition();
            let outcome = if condition.is_provable() {
                let poly = &self.poly;
                let (dim, mass) = (p.sys.dim(), p.sys.masses());
                self.proof.cut(t0, h, &mut |s| {
                    condition.enclose(&StateJets::new(poly, s, dim, mass, p.work), p.sys)
                })
            } else {
                ProofOutcome::NotBounded
            };
            match outcome {
                ProofOutcome::Proven => self.proof.sample_fractions_into(&mut self.fractions),
                ProofOutcome::OutOfBounds => {
                    if !self.warned[i] {
                        self.warned[i] = true;
                        warnings.push(format!(
                            "the event `{}` could not be bounded in the step at t = {t0} s (it needed more than {MAX_BOUNDS} bounds, or its value is not a number there); there it is sampled at {FALLBACK_SAMPLES} points, so a sign change between two samples may be missed; smaller steps (dt, or h_max) make the bounds tighter",
                            event.name()
                        ));
                    }
                    uniform = uniform.max(FALLBACK_SAMPLES).max(asked(event));
                }
                ProofOutcome::NotBounded => {
                    uniform = uniform.max(p.default_interior).max(asked(event));
                }
            }
        }
        for j in 1..=uniform {
            self.fractions.push(j as Real / (uniform + 1) as Real);
        }
        let t1 = t0 + h;
        points.extend(self.fractions.iter().map(|s| t0 + s * h));
        points.retain(|t| *t > t0 && *t < t1);
        points.sort_by(Real::total_cmp);
        points.dedup();
    }
}

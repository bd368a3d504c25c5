//! Proven pieces of a step: where a function of the motion cannot change sign, or can change
//! sign at most once, inside one step. The ground of the event guarantee.
//!
//! Given an enclosure `G(S)` of a function `g` and of its time derivative over any range `S`
//! of the fraction `s ∈ [0, 1]` of a step (from interval arithmetic on the step's
//! [`StepPolynomial`](super::StepPolynomial) and on the function's formula), the step is
//! halved into pieces until each is
//!
//! - **sign-definite**: `G(S)` excludes 0, so `g` has no zero there;
//! - **monotone**: the enclosure of `dg/dt` excludes 0, so `g` has at most one zero there,
//!   and it changes sign between the piece's ends exactly when it has one; or
//! - **at rounding level**: the piece cannot be halved in floating point, or its enclosure is
//!   no wider than the rounding of `g` at one point; or
//! - **at noise level**: `G(S)` lies within `±ε`, a level below which the caller counts no
//!   change of sign (both samples of a change within it: jitter, not a crossing), so that
//!   cutting the piece further could not show a change the caller would count.
//!
//! Sampling `g` at the ends of every piece that is not sign-definite then shows every sign
//! change of odd multiplicity of `g` along the interpolant as a sign change between two
//! consecutive samples, however short the excursion and however many per step.

use mechkit_expr::interval::{Interval, Jet};

use crate::Real;

/// Most enclosures of one function in one step before the proof gives up.
pub const MAX_BOUNDS: usize = 2_000;

/// Pieces whose enclosure is unknown (a value that may be NaN or unbounded) before the proof
/// gives up: halving isolates a pole or a jump in one such piece per level (about 55 in all),
/// while a function that is NaN over the whole step would double them at every level.
const MAX_UNKNOWN: usize = 128;

/// Halvings after which a piece is tested for being at rounding level (the whole step is
/// tested too).
const ROUNDING_DEPTH: u32 = 30;

/// What a piece of the step was proven to be.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Piece {
    /// `g > 0` (`true`) or `g < 0` (`false`) throughout.
    Definite(bool),
    /// Monotone, or at rounding or noise level: its ends must be sampled.
    Open,
}

/// How a proof ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ProofOutcome {
    /// The step is cut into proven pieces.
    Proven,
    /// More than [`MAX_BOUNDS`] enclosures were needed, or more than a few pieces had
    /// unknown values (NaN possible): sample the function instead.
    OutOfBounds,
    /// The function cannot be enclosed (it reads something the interpolant does not carry).
    NotBounded,
}

/// The pieces of one step for one function, with reused buffers.
#[derive(Debug, Clone, Default)]
pub struct StepProof {
    stack: Vec<(Real, Real, u32)>,
    /// `(s_start, s_end, piece)`, in time order, covering `[0, 1]`.
    pieces: Vec<(Real, Real, Piece)>,
}

impl StepProof {
    /// Cuts the step from `t0` of length `h` into proven pieces of the function that
    /// `enclose(S)` bounds over the fractions `S` of the step (`None`: it cannot); pieces
    /// enclosed within `±noise` are not cut (0: none but a function exactly zero).
    pub fn cut(
        &mut self,
        t0: Real,
        h: Real,
        noise: Real,
        enclose: &mut dyn FnMut(Interval) -> Option<Jet>,
    ) -> ProofOutcome {
        self.pieces.clear();
        self.stack.clear();
        self.stack.push((0.0, 1.0, 0));
        let mut bounds = 0;
        let mut unknown = 0;
        while let Some((a, b, depth)) = self.stack.pop() {
            bounds += 1;
            if bounds > MAX_BOUNDS {
                return ProofOutcome::OutOfBounds;
            }
            let Some(jet) = enclose(Interval::new(a, b)) else {
                return ProofOutcome::NotBounded;
            };
            if jet.v.is_entire() {
                unknown += 1;
                if unknown > MAX_UNKNOWN {
                    return ProofOutcome::OutOfBounds;
                }
            }
            let piece = if jet.v.is_positive() {
                Piece::Definite(true)
            } else if jet.v.is_negative() {
                Piece::Definite(false)
            } else if jet.is_increasing()
                || jet.is_decreasing()
                || (jet.v.lo() >= -noise && jet.v.hi() <= noise)
            {
                Piece::Open
            } else {
                let mid = 0.5 * (a + b);
                let (ta, tm, tb) = (t0 + a * h, t0 + mid * h, t0 + b * h);
                let unsplittable = !(ta < tm && tm < tb) || mid <= a || mid >= b;
                // tested at once too: a function constant to rounding over the whole step
                // (two bodies resting in contact, their gap zero) is never sign-definite, and
                // halving it would spend every bound
                let at_rounding = (depth == 0 || depth >= ROUNDING_DEPTH) && {
                    bounds += 1;
                    enclose(Interval::point(mid)).is_some_and(|point| {
                        let width = jet.v.width();
                        width.is_finite() && width <= 4.0 * point.v.width()
                    })
                };
                if unsplittable || at_rounding {
                    Piece::Open
                } else {
                    self.stack.push((mid, b, depth + 1));
                    self.stack.push((a, mid, depth + 1));
                    continue;
                }
            };
            self.pieces.push((a, b, piece));
        }
        ProofOutcome::Proven
    }

    /// The pieces of the last proof, in time order.
    pub fn pieces(&self) -> &[(Real, Real, Piece)] {
        &self.pieces
    }

    /// Appends the fractions of the step strictly inside it at which the function must be
    /// sampled: the boundaries next to a piece that is not sign-definite (or between
    /// sign-definite pieces of opposite signs, where the function jumps).
    pub fn sample_fractions_into(&self, out: &mut Vec<Real>) {
        for w in self.pieces.windows(2) {
            let keep = match (w[0].2, w[1].2) {
                (Piece::Definite(a), Piece::Definite(b)) => a != b,
                _ => true,
            };
            if keep {
                out.push(w[0].1);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `g(s) = (s - 0.3)(s - 0.3 - 1e-9)(s - 0.8)` as a jet over `S` (time = fraction).
    fn cubic(s: Interval) -> Jet {
        let x = Jet::variable(s);
        let f = |r: Real| x - Jet::constant(r);
        f(0.3) * f(0.3 + 1e-9) * f(0.8)
    }

    /// Two bodies resting in contact: their gap `(x_b - x_a) - (R_a + R_b)` is zero over the
    /// whole step, enclosed to rounding. It is never sign-definite; it once took every bound
    /// (`OutOfBounds`, and a warning on every step of Newton's cradle).
    #[test]
    fn a_function_constant_to_rounding_is_proven_at_once() {
        let mut proof = StepProof::default();
        let mut bounds = 0;
        let gap = |s: Interval| {
            let x = Jet::variable(s) * Jet::constant(0.0);
            (Jet::constant(0.05) + x) - Jet::constant(0.03) - Jet::constant(0.02)
        };
        assert_eq!(
            proof.cut(0.0, 1.0, 0.0, &mut |s| {
                bounds += 1;
                Some(gap(s))
            }),
            ProofOutcome::Proven
        );
        assert!(bounds <= 2, "{bounds} bounds");
        assert_eq!(proof.pieces().len(), 1);
    }

    /// A function that wiggles about zero within the caller's noise level (a steady spin's
    /// ω about an axis it does not turn about) is one open piece at once with that level;
    /// without it, the proof cuts the step to separate its three zeros.
    #[test]
    fn a_function_within_the_noise_level_is_not_cut() {
        let wiggle = |s: Interval| {
            let x = Jet::variable(s);
            let f = |r: Real| x - Jet::constant(r);
            (f(0.2) * f(0.5) * f(0.7)) * Jet::constant(1e-13)
        };
        let mut proof = StepProof::default();
        let mut bounds = 0;
        let outcome = proof.cut(0.0, 1.0, 1e-12, &mut |s| {
            bounds += 1;
            Some(wiggle(s))
        });
        assert_eq!((outcome, bounds), (ProofOutcome::Proven, 1));
        assert_eq!(proof.pieces(), &[(0.0, 1.0, Piece::Open)]);
        // without the level, its three zeros are separated
        assert_eq!(
            proof.cut(0.0, 1.0, 0.0, &mut |s| Some(wiggle(s))),
            ProofOutcome::Proven
        );
        assert!(proof.pieces().len() > 3);
    }

    #[test]
    fn roots_a_billionth_apart_are_separated() {
        let mut proof = StepProof::default();
        assert_eq!(
            proof.cut(0.0, 1.0, 0.0, &mut |s| Some(cubic(s))),
            ProofOutcome::Proven
        );
        let mut s = Vec::new();
        proof.sample_fractions_into(&mut s);
        let g = |s: Real| (s - 0.3) * (s - 0.3 - 1e-9) * (s - 0.8);
        let mut points = vec![0.0];
        points.extend(&s);
        points.push(1.0);
        let changes = points
            .windows(2)
            .filter(|w| g(w[0]) * g(w[1]) < 0.0)
            .count();
        assert_eq!(changes, 3, "{points:?}");
    }

    #[test]
    fn a_function_without_bounds_is_reported() {
        let mut proof = StepProof::default();
        assert_eq!(
            proof.cut(0.0, 1.0, 0.0, &mut |_| None),
            ProofOutcome::NotBounded
        );
        assert_eq!(
            proof.cut(0.0, 1.0, 0.0, &mut |s| Some(if s.hi() < 0.5 {
                Jet::constant(-1.0)
            } else if s.lo() > 0.5 {
                Jet::constant(1.0)
            } else {
                Jet::step(Interval::new(-1.0, 1.0))
            })),
            ProofOutcome::Proven,
            "a jump at rounding level ends the halving"
        );
        let unknown = |_: Interval| Jet::ENTIRE;
        assert_eq!(
            proof.cut(0.0, 1.0, 0.0, &mut |s| Some(unknown(s))),
            ProofOutcome::OutOfBounds
        );
        let pole = |s: Interval| Jet::constant(1.0) / (Jet::variable(s) - Jet::constant(0.3));
        assert_eq!(
            proof.cut(0.0, 1.0, 0.0, &mut |s| Some(pole(s))),
            ProofOutcome::Proven,
            "a pole is isolated to rounding"
        );
        let wild = |s: Interval| Jet::variable(s * Interval::point(1e5)).sin();
        assert_eq!(
            proof.cut(0.0, 1.0, 0.0, &mut |s| Some(wild(s))),
            ProofOutcome::OutOfBounds
        );
    }
}

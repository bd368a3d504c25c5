//! The scaling that keeps a collision's arithmetic in range: velocities divided by a power of
//! two `V` and masses by a power of two `M`, so that each is at most 1 in size (exact: only
//! the exponent changes), and the results multiplied back: velocities by `V`, impulses by
//! `M·V`, energies by `M·V²`. The collision is linear in its velocities and its masses enter
//! only through their ratios, impulses and energies, so the answer is the same as unscaled
//! wherever the unscaled arithmetic does not overflow.

use super::{Collision, Outcome};
use crate::Real;

/// The two scales.
#[derive(Debug, Clone, Copy)]
pub(super) struct Scales {
    pub velocity: Real,
    pub mass: Real,
}

/// The power of two at or above `x` (> 0, finite); 1 for 0.
fn power_of_two(x: Real) -> Real {
    if x == 0.0 || !x.is_finite() {
        return 1.0;
    }
    let e = x.log2().ceil().clamp(-1000.0, 1023.0);
    // exact: a power of two in range
    let p = 2f64.powi(e as i32);
    // at 2^1023 a value above it is scaled to at most 2, which is as good
    if p < x && e < 1023.0 { p * 2.0 } else { p }
}

/// `c` with its velocities and finite masses scaled to at most 1, and the scales.
pub(super) fn scaled(c: &Collision) -> (Collision, Scales) {
    let v =
        c.v1.iter()
            .chain(&c.v2)
            .fold(0.0, |m: Real, x| m.max(x.abs()));
    let m = [c.m1, c.m2]
        .into_iter()
        .filter(|m| m.is_finite())
        .fold(0.0, Real::max);
    let k = Scales {
        velocity: power_of_two(v),
        mass: power_of_two(m),
    };
    let mut s = c.clone();
    for x in s.v1.iter_mut().chain(s.v2.iter_mut()) {
        *x /= k.velocity;
    }
    s.m1 /= k.mass;
    s.m2 /= k.mass;
    (s, k)
}

/// The outcome of the scaled collision as the original's: its inputs as given, the results
/// scaled back.
pub(super) fn unscale(out: &mut Outcome, c: &Collision, k: Scales) {
    let (v, impulse) = (k.velocity, k.mass * k.velocity);
    let scale = |xs: &mut Vec<Real>, by: Real| xs.iter_mut().for_each(|x| *x *= by);
    out.m1 = c.m1;
    out.m2 = c.m2;
    out.v1_before.clone_from(&c.v1);
    out.v2_before.clone_from(&c.v2);
    for xs in [
        &mut out.v1,
        &mut out.v2,
        &mut out.v_cm,
        &mut out.cm_frame.before.v1,
        &mut out.cm_frame.before.v2,
        &mut out.cm_frame.after.v1,
        &mut out.cm_frame.after.v2,
    ] {
        scale(xs, v);
    }
    scale(&mut out.impulse, impulse);
    out.normal_impulse *= impulse;
    out.tangential_impulse *= impulse;
    out.approach_speed *= v;
    out.separation_speed *= v;
    // energies: M·V² as (E·V)·(M·V), which overflows only when the energy does
    for e in [
        &mut out.kinetic_before,
        &mut out.kinetic_after,
        &mut out.kinetic_lost,
    ] {
        *e = (*e * v) * (k.mass * v);
    }
}

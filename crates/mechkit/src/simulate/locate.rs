//! Locating a stop condition inside a step: on the cubic Hermite interpolant of the step
//! (positions from positions and velocities, velocities from velocities and accelerations),
//! by Brent's method.

use super::condition::Condition;
use super::run::sample_of;
use crate::Real;
use crate::energy::EnergyLedger;
use crate::ode::{State, hermite};
use crate::particles::{Evaluation, ParticleSystem};
use crate::roots::brent_with_values;

/// Finds the crossing of `c` inside the step from `lo` to `hi` on the cubic Hermite
/// interpolant; leaves the interpolated state in `out` and returns its time and the force
/// evaluations used.
#[allow(clippy::too_many_arguments)]
pub(crate) fn locate(
    c: &Condition,
    sys: &ParticleSystem,
    ledger: &EnergyLedger,
    lo: (Real, &[Real], &Evaluation, Real),
    hi: (Real, &[Real], &Evaluation, Real),
    eval_buf: &mut Evaluation,
    out: &mut State,
    scratch: &mut Vec<Real>,
) -> (Real, u64) {
    let (t0, y0, e0, g0) = lo;
    let (t1, y1, e1, g1) = hi;
    let h = t1 - t0;
    let n = y0.len() / 2;
    let mut work = Vec::new();
    let mut evaluations = 0;
    let interpolate = |s: Real, out: &mut State| {
        for i in 0..n {
            out.y[i] = hermite(y0[i], y0[n + i], y1[i], y1[n + i], h, s);
            out.y[n + i] = hermite(y0[n + i], e0.a[i], y1[n + i], e1.a[i], h, s);
        }
        out.t = t0 + s * h;
    };
    let tol = (4.0 * Real::EPSILON * t1.abs().max(h) / h).max(1e-15);
    let g_prev = if g0.is_nan() { -1.0 } else { g0 };
    let s = brent_with_values(
        |s| {
            interpolate(s, out);
            if c.needs_forces() {
                let (q, v) = out.qv();
                sys.evaluate(out.t, q, v, eval_buf, scratch);
                ledger.preview_into(out.t, &eval_buf.power, &mut work);
                evaluations += 1;
            } else {
                work.clear();
                work.extend_from_slice(ledger.work());
            }
            c.value(&sample_of(0, out, eval_buf, &work), sys)
        },
        0.0,
        1.0,
        Some((g_prev.min(0.0), g1)),
        tol,
    )
    .unwrap_or(1.0);
    interpolate(s, out);
    (out.t, evaluations)
}

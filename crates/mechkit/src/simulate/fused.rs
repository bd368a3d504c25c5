//! The fused fixed-step kernel: the steps of a run that no observer looks at, compiled as one
//! loop.
//!
//! A fixed-step run of Euler or Euler-Cromer without events or output times spends most of
//! its steps producing nothing anyone reads: the CSV keeps every n-th row. For those steps the
//! general loop's work (a virtual call per force, the ledger's bookkeeping, a sample for the
//! observers) is replaced by one compiled body ([`mechkit_expr::Kernel`]): the update, every
//! force ([`Force::emit`](crate::forces::Force::emit)), the accelerations, each force's power
//! and net force, and the trapezoids of the energy and momentum ledger, with the state in
//! registers. The step the observers want, and the last step before `t_max`, stay with the
//! general loop, which also re-evaluates the system at the end of each chunk.
//!
//! The kernel performs the general loop's operations in its order, so the two agree bit for
//! bit (up to the sign of an exact zero, see [`crate::forces::ForceEmitter`]); the tests run
//! both on the same scenarios and compare the bits. A chunk that ends with a non-finite value
//! is discarded and its steps rerun by the general loop, which diagnoses the failing step.

use mechkit_expr::{Kernel, KernelBuilder, Val};

use crate::Real;
use crate::energy::EnergyLedger;
use crate::forces::ForceEmitter;
use crate::ode::{Method, State};
use crate::particles::{Coordinates, ParticleSystem};

use super::observe::Observer;
use super::run::Simulation;
use super::stepping::Stepping;

/// Below this many planned steps a run does not compile a kernel (compiling costs about a
/// millisecond; a run this short takes about as long in the general loop).
pub(super) const FUSE_MIN_STEPS: u64 = 20_000;

/// At most this many steps per chunk, so that a raised [`Cancel`](super::Cancel) (Ctrl-C) is
/// seen within tens of milliseconds.
pub(super) const MAX_CHUNK: u64 = 1 << 22;

/// Fewer silent steps than this before the next wanted sample are left to the general loop.
pub(super) const MIN_CHUNK: u64 = 8;

/// Slot layout: time, the step counter since the origin, the smallest and largest step, then
/// positions, velocities, accelerations, each force's power, net force, work and impulse.
const T: usize = 0;
const K: usize = 1;
const H_MIN: usize = 2;
const H_MAX: usize = 3;
const X: usize = 4;

/// A compiled step loop for one run.
pub(super) struct Fused {
    kernel: Kernel,
    n: usize,
    nf: usize,
    dim: usize,
    slots: Vec<Real>,
}

impl Fused {
    /// The kernel for a run's silent steps, when it can have one: fixed steps of Euler or
    /// Euler-Cromer, no events, no output times (`grid`), every force compilable, and fusing
    /// wanted (by [`Simulation::fuse`], else for runs of at least [`FUSE_MIN_STEPS`] steps
    /// unless `MECHKIT_FUSE=0`).
    pub(super) fn for_run(
        sim: &Simulation<'_>,
        stepping: &Stepping,
        t0: Real,
        expected_steps: u64,
        grid: bool,
    ) -> Option<Fused> {
        let Stepping::Fixed { method, dt } = stepping else {
            return None;
        };
        let wanted = match sim.fuse {
            Some(on) => on,
            None => {
                expected_steps >= FUSE_MIN_STEPS
                    && std::env::var("MECHKIT_FUSE").map_or(true, |v| v != "0")
            }
        };
        if !wanted || !sim.events.is_empty() || grid {
            return None;
        }
        Fused::build(sim.system, *method, *dt, t0)
    }

    /// The kernel of `method` with steps `dt` counted from `origin`, or `None` when the method
    /// or a force cannot be fused.
    pub(super) fn build(
        sys: &ParticleSystem,
        method: Method,
        dt: Real,
        origin: Real,
    ) -> Option<Fused> {
        if !matches!(method, Method::Euler | Method::EulerCromer)
            || sys.coordinates() != Coordinates::Cartesian
            || !sys.spinners().is_empty()
        {
            return None;
        }
        let dim = sys.dim();
        let n = dim * sys.masses().len();
        let nf = sys.forces().len();
        let layout = Layout { n, nf, dim };
        let mut b = KernelBuilder::new(layout.total());
        // t_next = origin + (k + 1) dt, h = t_next - t (fixed_next and the loop's h)
        let (t, k) = (b.get(T), b.get(K));
        let one = b.constant(1.0);
        let k1 = b.add(k, one);
        let dt_c = b.constant(dt);
        let origin_c = b.constant(origin);
        let kdt = b.mul(k1, dt_c);
        let t1 = b.add(origin_c, kdt);
        let h = b.sub(t1, t);
        let (x1, v1) = step(&mut b, &layout, method, h);
        let (accel, power, net) = evaluation(&mut b, sys, t1, &x1, &v1)?;
        ledger(&mut b, &layout, h, &power, &net);
        // the step range, branch-free (steps are positive)
        let (h_min, h_max) = (b.get(H_MIN), b.get(H_MAX));
        let h_min = b.min_nonnegative(h, h_min);
        let h_max = b.max_nonnegative(h, h_max);
        b.set(H_MIN, h_min);
        b.set(H_MAX, h_max);
        b.set(T, t1);
        b.set(K, k1);
        for i in 0..n {
            b.set(layout.x(i), x1[i]);
            b.set(layout.v(i), v1[i]);
            b.set(layout.a(i), accel[i]);
        }
        let kernel = b.finish().native();
        Some(Fused {
            kernel,
            n,
            nf,
            dim,
            slots: vec![0.0; layout.total()],
        })
    }

    /// Advances `state` by `steps` steps, its ledger and step counters with it, starting from
    /// the acceleration `a` of the current state. Returns `false`, changing nothing, when a
    /// value became non-finite on the way.
    pub(super) fn advance(
        &mut self,
        state: &mut State,
        fixed_k: &mut u64,
        a: &[Real],
        ledger: &mut EnergyLedger,
        step_range: &mut (Real, Real),
        steps: u64,
    ) -> bool {
        let layout = Layout {
            n: self.n,
            nf: self.nf,
            dim: self.dim,
        };
        let s = &mut self.slots;
        let parts = ledger.trapezoids();
        s[T] = state.t;
        s[K] = *fixed_k as Real;
        s[H_MIN] = step_range.0;
        s[H_MAX] = step_range.1;
        let n = self.n;
        s[X..X + 2 * n].copy_from_slice(&state.y);
        s[layout.a(0)..layout.a(0) + n].copy_from_slice(a);
        s[layout.power(0)..layout.power(0) + self.nf].copy_from_slice(parts.power);
        s[layout.work(0)..layout.work(0) + self.nf].copy_from_slice(parts.work);
        let nd = self.nf * self.dim;
        s[layout.net(0)..layout.net(0) + nd].copy_from_slice(parts.net);
        s[layout.impulse(0)..layout.impulse(0) + nd].copy_from_slice(parts.impulse);
        self.kernel.run(s, steps);
        if !s.iter().all(|x| x.is_finite()) {
            return false;
        }
        *step_range = (s[H_MIN], s[H_MAX]);
        state.t = s[T];
        *fixed_k = s[K] as u64;
        state.y.copy_from_slice(&s[X..X + 2 * n]);
        parts
            .power
            .copy_from_slice(&s[layout.power(0)..layout.power(0) + self.nf]);
        parts
            .work
            .copy_from_slice(&s[layout.work(0)..layout.work(0) + self.nf]);
        parts
            .net
            .copy_from_slice(&s[layout.net(0)..layout.net(0) + nd]);
        parts
            .impulse
            .copy_from_slice(&s[layout.impulse(0)..layout.impulse(0) + nd]);
        *parts.last_t = state.t;
        true
    }
}

/// How many steps after `steps` can run fused: up to the step before the first one an
/// observer wants, the last step before `t_max` (`planned` steps from the origin, `fixed_k`
/// taken) and the last allowed (`limit`) stay with the general loop; at most [`MAX_CHUNK`].
pub(super) fn chunk_len(
    observers: &[&mut dyn Observer],
    steps: u64,
    limit: u64,
    planned: Option<u64>,
    fixed_k: u64,
) -> u64 {
    let wanted = observers
        .iter()
        .filter_map(|o| o.next_step(steps))
        .min()
        .unwrap_or(u64::MAX);
    let mut chunk = wanted.saturating_sub(steps + 1).min(MAX_CHUNK);
    chunk = chunk.min(limit.saturating_sub(steps + 1));
    if let Some(p) = planned {
        chunk = chunk.min(p.saturating_sub(fixed_k + 1));
    }
    chunk
}

/// Slot indices of a kernel over `n` coordinates, `nf` forces in `dim` dimensions.
struct Layout {
    n: usize,
    nf: usize,
    dim: usize,
}

impl Layout {
    fn x(&self, i: usize) -> usize {
        debug_assert!(i < self.n);
        X + i
    }
    fn v(&self, i: usize) -> usize {
        X + self.n + i
    }
    fn a(&self, i: usize) -> usize {
        X + 2 * self.n + i
    }
    fn power(&self, f: usize) -> usize {
        X + 3 * self.n + f
    }
    fn work(&self, f: usize) -> usize {
        X + 3 * self.n + self.nf + f
    }
    fn net(&self, c: usize) -> usize {
        X + 3 * self.n + 2 * self.nf + c
    }
    fn impulse(&self, c: usize) -> usize {
        X + 3 * self.n + 2 * self.nf + self.nf * self.dim + c
    }
    fn total(&self) -> usize {
        X + 3 * self.n + 2 * self.nf + 2 * self.nf * self.dim
    }
}

/// `acc + s` where `None` is an exact zero that adds nothing.
fn add(b: &mut KernelBuilder, acc: Option<Val>, s: Option<Val>) -> Option<Val> {
    match (acc, s) {
        (Some(a), Some(s)) => Some(b.add(a, s)),
        (a, None) => a,
        (None, s) => s,
    }
}

/// `Σ s·v` over the terms present (`Iterator::sum` starts from `-0.0`, which adds nothing;
/// absent terms are `0·v`), or zero.
fn sum(b: &mut KernelBuilder, terms: impl Iterator<Item = Option<(Val, Val)>>) -> Val {
    let mut acc = None;
    for (s, v) in terms.flatten() {
        let p = b.mul(s, v);
        acc = add(b, acc, Some(p));
    }
    acc.unwrap_or_else(|| b.constant(0.0))
}

/// One Euler or Euler-Cromer step of `h` in the kernel: the new positions and velocities.
fn step(b: &mut KernelBuilder, layout: &Layout, method: Method, h: Val) -> (Vec<Val>, Vec<Val>) {
    let n = layout.n;
    let x: Vec<Val> = (0..n).map(|i| b.get(layout.x(i))).collect();
    let v: Vec<Val> = (0..n).map(|i| b.get(layout.v(i))).collect();
    let a: Vec<Val> = (0..n).map(|i| b.get(layout.a(i))).collect();
    let mut x1 = Vec::with_capacity(n);
    let mut v1 = Vec::with_capacity(n);
    for i in 0..n {
        let dv = b.mul(h, a[i]);
        if method == Method::EulerCromer {
            // v += h a; q += h v (the new v)
            let vi = b.add(v[i], dv);
            let dx = b.mul(h, vi);
            x1.push(b.add(x[i], dx));
            v1.push(vi);
        } else {
            // y += h y': q += h v (the old v); v += h a
            let dx = b.mul(h, v[i]);
            x1.push(b.add(x[i], dx));
            v1.push(b.add(v[i], dv));
        }
    }
    (x1, v1)
}

/// The evaluation at the step's end in the kernel (`ParticleSystem::evaluate`, `ForceSet`'s
/// order): the accelerations, each force's power and its net force per component; `None`
/// when a force cannot be emitted.
#[allow(clippy::type_complexity)]
fn evaluation(
    b: &mut KernelBuilder,
    sys: &ParticleSystem,
    t1: Val,
    x1: &[Val],
    v1: &[Val],
) -> Option<(Vec<Val>, Vec<Val>, Vec<Val>)> {
    let dim = sys.dim();
    let nf = sys.forces().len();
    let mut total: Vec<Option<Val>> = vec![None; x1.len()];
    let mut power = Vec::with_capacity(nf);
    let mut net = Vec::with_capacity(nf * dim);
    for f in sys.forces().iter() {
        let mut e = ForceEmitter::new(b, dim, t1, x1, v1, sys.masses());
        if !f.emit(&mut e) {
            return None;
        }
        let scratch = e.into_forces();
        power.push(sum(
            b,
            scratch.iter().zip(v1).map(|(s, v)| s.map(|s| (s, *v))),
        ));
        for (o, s) in total.iter_mut().zip(&scratch) {
            *o = add(b, *o, *s);
        }
        for c in 0..dim {
            let mut acc = None;
            for body in scratch.chunks_exact(dim) {
                acc = add(b, acc, body[c]);
            }
            net.push(acc.unwrap_or_else(|| b.constant(0.0)));
        }
    }
    let accel: Vec<Val> = total
        .iter()
        .zip(sys.inverse_masses())
        .map(|(f, w)| {
            let f = f.unwrap_or_else(|| b.constant(0.0));
            let w = b.constant(*w);
            b.mul(f, w)
        })
        .collect();
    Some((accel, power, net))
}

/// The ledger in the kernel: trapezoids of each force's power and net force over the step.
fn ledger(b: &mut KernelBuilder, layout: &Layout, h: Val, power: &[Val], net: &[Val]) {
    let half = b.constant(0.5);
    let half_h = b.mul(half, h);
    let trapezoid = |b: &mut KernelBuilder, acc: usize, last: usize, now: Val| {
        let (sum_slot, last_val) = (b.get(acc), b.get(last));
        let s = b.add(last_val, now);
        let inc = b.mul(half_h, s);
        let new = b.add(sum_slot, inc);
        b.set(acc, new);
        b.set(last, now);
    };
    for (i, p) in power.iter().enumerate() {
        trapezoid(b, layout.work(i), layout.power(i), *p);
    }
    for (i, f) in net.iter().enumerate() {
        trapezoid(b, layout.impulse(i), layout.net(i), *f);
    }
}

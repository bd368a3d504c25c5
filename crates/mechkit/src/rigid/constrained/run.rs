//! The motion on the curve, the departure where the normal force reaches zero, and the free
//! flight to the landing.

use super::curve::{Curve, Geometry, Side};
use super::error::ConstrainedError;
use crate::Real;
use crate::ode::{AdaptiveConfig, AdaptiveRk, AdaptiveStats, OdeSystem, State, Tableau};
use crate::roots::{brent, brent_with_values};

/// A body on a curve: the curve, the side it is on, its mass and gravity.
#[derive(Debug, Clone, PartialEq)]
pub struct BeadOnCurve {
    /// The curve.
    pub curve: Curve,
    /// Which side of it the body is on.
    pub side: Side,
    /// Mass (kg): only the normal force depends on it.
    pub mass: Real,
    /// Gravitational acceleration (m/s², pointing in −y).
    pub g: Real,
}

/// Where the body starts: the coordinate (x for a graph, the angle φ from the top, clockwise,
/// for a circle) and the speed along the curve, positive in the direction of increasing
/// coordinate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Start {
    /// x (m) or φ (rad).
    pub coordinate: Real,
    /// Signed speed along the curve (m/s).
    pub speed: Real,
}

/// One sample of the motion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BeadSample {
    /// Time (s).
    pub t: Real,
    /// Position (m).
    pub position: [Real; 2],
    /// Velocity (m/s).
    pub velocity: [Real; 2],
    /// The normal force (N) along the allowed direction (for a threaded bead: along n) while
    /// on the curve; `None` in free flight.
    pub normal_force: Option<Real>,
}

/// The body leaves the curve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Departure {
    /// Time (s).
    pub t: Real,
    /// The curve coordinate there (x or φ).
    pub coordinate: Real,
    /// Position (m).
    pub position: [Real; 2],
    /// Velocity (m/s).
    pub velocity: [Real; 2],
    /// The normal force there (N): zero to the integration's accuracy.
    pub normal_force: Real,
}

/// The free body meets the curve again.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Landing {
    /// Time (s).
    pub t: Real,
    /// The curve coordinate there.
    pub coordinate: Real,
    /// Position (m).
    pub position: [Real; 2],
    /// Velocity (m/s).
    pub velocity: [Real; 2],
    /// The velocity component along the curve's tangent (m/s).
    pub tangential_speed: Real,
    /// The velocity component into the curve (m/s, positive).
    pub normal_speed: Real,
}

/// Why the run ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum StopReason {
    /// `t_max` reached.
    TimeLimit,
    /// The body left the curve and landed on it again.
    Landed,
}

/// A run ([`BeadOnCurve::simulate`]).
#[derive(Debug, Clone, PartialEq)]
pub struct BeadRun {
    /// Samples: the start, the end of every accepted step on the curve, the departure, then
    /// the flight.
    pub samples: Vec<BeadSample>,
    /// Where the body left the curve, if it did.
    pub departure: Option<Departure>,
    /// Where it met the curve again, if it did before `t_max`.
    pub landing: Option<Landing>,
    /// Times at which the speed along the curve changes sign (turning points), located by
    /// Brent's method on the dense output.
    pub turning_times: Vec<Real>,
    /// The energy per unit mass at the start, ½v² + g y (J/kg).
    pub energy: Real,
    /// The largest |E − E₀| per unit mass on the curve (J/kg).
    pub energy_drift: Real,
    /// Why it ended.
    pub stop: StopReason,
    /// The integrator's counters.
    pub stats: AdaptiveStats,
}

struct System<'a> {
    curve: &'a Curve,
    g: Real,
}

impl OdeSystem for System<'_> {
    fn dim(&self) -> usize {
        2
    }

    fn rhs_into(&self, _t: Real, y: &[Real], dydt: &mut [Real]) {
        dydt[0] = y[1];
        dydt[1] = self.curve.geometry(y[0]).accel(y[1], self.g);
    }
}

fn positive(what: &'static str, value: Real, zero_ok: bool) -> Result<Real, ConstrainedError> {
    if value.is_finite() && (value > 0.0 || (zero_ok && value == 0.0)) {
        Ok(value)
    } else {
        Err(ConstrainedError::Value {
            what,
            value,
            must_be: if zero_ok {
                "zero or positive, and finite"
            } else {
                "positive and finite"
            },
        })
    }
}

impl BeadOnCurve {
    /// A checked model: `mass` > 0, `g` ≥ 0.
    pub fn new(curve: Curve, side: Side, mass: Real, g: Real) -> Result<Self, ConstrainedError> {
        Ok(Self {
            curve,
            side,
            mass: positive("the mass", mass, false)?,
            g: positive("g", g, true)?,
        })
    }

    /// The normal force (N) along the allowed direction at `(q, q̇)` (along n for a bead).
    pub fn normal_force(&self, q: Real, qd: Real) -> Real {
        let n = self.curve.geometry(q).normal_force(qd, self.g) * self.mass;
        match self.side {
            Side::Bead => n,
            side => side.sign() * n,
        }
    }

    fn sample(&self, t: Real, y: &[Real]) -> BeadSample {
        let geo = self.curve.geometry(y[0]);
        BeadSample {
            t,
            position: geo.r,
            velocity: [geo.d1[0] * y[1], geo.d1[1] * y[1]],
            normal_force: Some(self.normal_force(y[0], y[1])),
        }
    }

    fn energy(&self, geo: &Geometry, qd: Real) -> Real {
        let v2 = (geo.d1[0] * geo.d1[0] + geo.d1[1] * geo.d1[1]) * qd * qd;
        0.5 * v2 + self.g * geo.r[1]
    }

    /// Integrates from `start` to `t_max` (s) with Dormand-Prince 5(4) at the tolerances of
    /// `config`. A body on one side of the curve leaves it where the normal force reaches zero
    /// (located inside the step by Brent's method on the dense output, then integrated to),
    /// and flies freely until it meets the curve again or `t_max`.
    pub fn simulate(
        &self,
        start: Start,
        t_max: Real,
        config: &AdaptiveConfig,
    ) -> Result<BeadRun, ConstrainedError> {
        positive("t_max", t_max, false)?;
        if !(start.coordinate.is_finite() && start.speed.is_finite()) {
            return Err(ConstrainedError::Start(format!(
                "the start ({}, {}) must be finite",
                start.coordinate, start.speed
            )));
        }
        config.validate(2)?;
        let sys = System {
            curve: &self.curve,
            g: self.g,
        };
        let geo0 = self.curve.check_at(start.coordinate)?;
        let qd0 = start.speed / geo0.speed_factor();
        let energy = self.energy(&geo0, qd0);
        let mut rk = AdaptiveRk::new(Tableau::dopri5(), config.clone())?;
        let mut state = State::new(0.0, vec![start.coordinate, qd0]);
        let mut samples = vec![self.sample(0.0, &state.y)];
        let (mut turning_times, mut drift) = (Vec::new(), 0.0_f64);
        let leaves = self.side != Side::Bead;
        let mut departure = None;
        if leaves && self.normal_force(state.y[0], state.y[1]) < 0.0 {
            departure = Some(self.departure(&state));
        }
        let mut dense = [0.0; 2];
        while departure.is_none() && state.t < t_max {
            let before = state.clone();
            rk.step(&sys, &mut state, t_max)?;
            self.curve.check_at(state.y[0])?;
            let (a, b) = rk.last_step();
            if before.y[1] * state.y[1] < 0.0 {
                let mut qd = |t: Real| {
                    rk.dense_into(&sys, t, &mut dense);
                    dense[1]
                };
                if let Some(t) = brent_with_values(
                    &mut qd,
                    a,
                    b,
                    Some((before.y[1], state.y[1])),
                    4.0 * Real::EPSILON * b.abs(),
                ) {
                    turning_times.push(t);
                }
            }
            if leaves && let Some(t_leave) = self.leaving_in_step(&mut rk, &sys, &before, b) {
                // the interpolant is less accurate than the steps: integrate to the root
                let mut top = before;
                rk.reset();
                while top.t < t_leave {
                    rk.step(&sys, &mut top, t_leave)?;
                }
                let geo = self.curve.geometry(top.y[0]);
                drift = drift.max((self.energy(&geo, top.y[1]) - energy).abs());
                samples.push(self.sample(top.t, &top.y));
                departure = Some(self.departure(&top));
                break;
            }
            let geo = self.curve.geometry(state.y[0]);
            drift = drift.max((self.energy(&geo, state.y[1]) - energy).abs());
            samples.push(self.sample(state.t, &state.y));
        }
        let landing = departure.and_then(|d| self.fly(&d, t_max, &mut samples));
        Ok(BeadRun {
            samples,
            departure,
            landing,
            turning_times,
            energy,
            energy_drift: drift,
            stop: if landing.is_some() {
                StopReason::Landed
            } else {
                StopReason::TimeLimit
            },
            stats: rk.stats(),
        })
    }

    /// The first time in the last step where the normal force falls through zero: sampled at
    /// interior points of the dense output (two crossings inside one step are not missed),
    /// with every interior local minimum of the samples refined by golden-section search (a
    /// dip below zero narrower than the sampling, as at the top of a loop barely completed,
    /// is not missed either), then the crossing refined by Brent's method.
    fn leaving_in_step(
        &self,
        rk: &mut AdaptiveRk,
        sys: &System<'_>,
        before: &State,
        b: Real,
    ) -> Option<Real> {
        const PARTS: usize = 8;
        let a = before.t;
        let mut dense = [0.0; 2];
        let mut force = |t: Real| {
            rk.dense_into(sys, t, &mut dense);
            self.normal_force(dense[0], dense[1])
        };
        let mut ts = [0.0; PARTS + 1];
        let mut fs = [0.0; PARTS + 1];
        for (i, (t, f)) in ts.iter_mut().zip(fs.iter_mut()).enumerate() {
            *t = if i == PARTS {
                b
            } else {
                a + (b - a) * (i as Real) / (PARTS as Real)
            };
            *f = if i == 0 {
                self.normal_force(before.y[0], before.y[1])
            } else {
                force(*t)
            };
        }
        let tol = |t: Real| 4.0 * Real::EPSILON * t.abs().max(1e-300);
        for i in 1..=PARTS {
            if fs[i - 1] >= 0.0 && fs[i] < 0.0 {
                return brent_with_values(
                    &mut force,
                    ts[i - 1],
                    ts[i],
                    Some((fs[i - 1], fs[i])),
                    tol(ts[i]),
                );
            }
            let interior_min =
                i < PARTS && fs[i] >= 0.0 && fs[i] <= fs[i - 1] && fs[i] <= fs[i + 1];
            let edge_min = i == 1 && fs[0] >= 0.0 && fs[0] < fs[1];
            if interior_min || edge_min {
                let (lo, hi) = if edge_min && !interior_min {
                    (ts[0], ts[1])
                } else {
                    (ts[i - 1], ts[i + 1])
                };
                let (t_min, f_min) = golden_min(&mut force, lo, hi);
                if f_min < 0.0 {
                    let f_lo = if lo == a { fs[0] } else { force(lo) };
                    return brent_with_values(
                        &mut force,
                        lo,
                        t_min,
                        Some((f_lo, f_min)),
                        tol(t_min),
                    );
                }
            }
        }
        None
    }

    fn departure(&self, s: &State) -> Departure {
        let sample = self.sample(s.t, &s.y);
        Departure {
            t: s.t,
            coordinate: s.y[0],
            position: sample.position,
            velocity: sample.velocity,
            normal_force: self.normal_force(s.y[0], s.y[1]),
        }
    }

    /// The free flight from the departure to the landing (or `t_max`), appending samples.
    fn fly(&self, d: &Departure, t_max: Real, samples: &mut Vec<BeadSample>) -> Option<Landing> {
        let (p, v, g) = (d.position, d.velocity, self.g);
        let at = |tau: Real| {
            (
                [p[0] + v[0] * tau, p[1] + v[1] * tau - 0.5 * g * tau * tau],
                [v[0], v[1] - g * tau],
            )
        };
        let gap = |tau: Real| self.curve.gap(at(tau).0, self.side);
        let span = t_max - d.t;
        let scale = self.curve.scale();
        let speed = v[0].hypot(v[1]);
        let time_scale = (scale / g).sqrt().min(scale / speed);
        let mut dtau = if time_scale.is_finite() {
            (2e-3 * time_scale).min(span)
        } else {
            span
        };
        dtau = dtau.max(span / 200_000.0);
        // the gap grows like τ³ from a tangential departure: wait until it is clearly open
        let open = 1e-12 * scale;
        let mut armed = false;
        let mut k = 1u32;
        let mut landing_tau = None;
        while Real::from(k - 1) * dtau < span {
            let tau = (Real::from(k) * dtau).min(span);
            let gv = gap(tau);
            if armed && gv < 0.0 {
                landing_tau = brent(gap, tau - dtau, tau, 4.0 * Real::EPSILON * (d.t + tau));
                break;
            }
            armed |= gv > open;
            k += 1;
        }
        let end = landing_tau.unwrap_or(span);
        for i in 1..=400u32 {
            let tau = end * Real::from(i) / 400.0;
            let (position, velocity) = at(tau);
            samples.push(BeadSample {
                t: d.t + tau,
                position,
                velocity,
                normal_force: None,
            });
        }
        let tau = landing_tau?;
        let (position, velocity) = at(tau);
        let q = self.curve.coordinate_of(position);
        let (tangent, normal) = self.curve.frame(q);
        let dot = |a: [Real; 2], b: [Real; 2]| a[0] * b[0] + a[1] * b[1];
        Some(Landing {
            t: d.t + tau,
            coordinate: q,
            position,
            velocity,
            tangential_speed: dot(velocity, tangent),
            normal_speed: (-self.side.sign() * dot(velocity, normal)).max(0.0),
        })
    }
}

/// The minimum of `f` on `[a, b]` by golden-section search (to rounding): `(t, f(t))`.
fn golden_min(f: &mut impl FnMut(Real) -> Real, a: Real, b: Real) -> (Real, Real) {
    let r = 0.5 * (5.0_f64.sqrt() - 1.0);
    let (mut a, mut b) = (a, b);
    let (mut c, mut d) = (b - r * (b - a), a + r * (b - a));
    let (mut fc, mut fd) = (f(c), f(d));
    for _ in 0..200 {
        if (b - a).abs() <= 4.0 * Real::EPSILON * b.abs().max(a.abs()) {
            break;
        }
        if fc < fd {
            (b, d, fd) = (d, c, fc);
            c = b - r * (b - a);
            fc = f(c);
        } else {
            (a, c, fc) = (c, d, fd);
            d = a + r * (b - a);
            fd = f(d);
        }
    }
    if fc < fd { (c, fc) } else { (d, fd) }
}

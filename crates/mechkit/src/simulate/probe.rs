//! States between steps: the interpolated probe, the step it is read from, and the output
//! times still to come.

use super::event::Event;
use super::observe::Observer;
use super::report::SimulateError;
use super::run::{Simulation, sample_of};
use super::stepping::{Engine, StepEnds, WorkSystem};
use crate::Real;
use crate::energy::EnergyLedger;
use crate::error::short;
use crate::ode::State;
use crate::particles::{Evaluation, ParticleSystem, Sample, SampleKind};

/// A state between steps with what follows from it.
pub(super) struct Probe {
    pub state: State,
    pub eval: Evaluation,
    pub work: Vec<Real>,
    pub scratch: Vec<Real>,
}

/// Everything the loop needs to interpolate inside the current step.
pub(super) struct Step<'r, 'a> {
    pub sys: &'a ParticleSystem,
    pub ws: &'r WorkSystem<'a>,
    pub engine: &'r mut Engine,
    pub ends: &'r StepEnds,
    pub ledger: &'r EnergyLedger,
}

impl Probe {
    /// Buffers for `n2` state components and `nf` forces.
    pub fn new(t0: Real, n2: usize, nf: usize) -> Self {
        Self {
            state: State::new(t0, vec![0.0; n2]),
            eval: Evaluation::default(),
            work: vec![0.0; nf],
            scratch: Vec::new(),
        }
    }
}

impl Step<'_, '_> {
    /// Fills `p` with the state at `t` (and the forces there when `forces`).
    pub fn probe(&mut self, p: &mut Probe, t: Real, forces: bool, evaluations: &mut u64) {
        p.state.t = t;
        let have_work = self
            .engine
            .interpolate(self.ws, self.ends, t, &mut p.state.y, &mut p.work);
        if forces {
            let (q, v) = p.state.qv();
            self.sys.evaluate(t, q, v, &mut p.eval, &mut p.scratch);
            *evaluations += 1;
            if !have_work {
                self.ledger.preview_into(t, &p.eval.power, &mut p.work);
            }
        } else if !have_work {
            p.work.clear();
            p.work.extend_from_slice(self.ledger.work());
        }
    }
}

pub(super) fn event_values(
    events: &[Event],
    s: &Sample<'_>,
    sys: &ParticleSystem,
    out: &mut [Real],
) {
    for (o, e) in out.iter_mut().zip(events) {
        *o = e.condition().value(s, sys);
    }
}

pub(super) fn emit(
    observers: &mut [&mut dyn Observer],
    s: &Sample<'_>,
) -> Result<(), SimulateError> {
    for o in observers.iter_mut() {
        o.observe(s)?;
    }
    Ok(())
}

/// The output times still to come: every `dt` from `t0`, or a list.
pub(super) struct Grid {
    pub t0: Real,
    pub dt: Real,
    pub list: Option<Vec<Real>>,
    pub k: u64,
    pub t_max: Option<Real>,
    /// With no end (no `t_max`), the last output time's index (see [`MAX_UNENDED_OUTPUTS`]).
    pub last_k: Option<u64>,
}

/// Output times of a run with an output interval and no `t_max`: the step budget bounds the
/// steps, but not the times in them (a free fall's adaptive steps grow without bound, and one
/// step of 10^10 s held 5·10^12 output times of 2 ms).
pub const MAX_UNENDED_OUTPUTS: u64 = super::DEFAULT_MAX_STEPS;

impl Grid {
    /// The output times a run asked for (`None`: just the steps).
    pub fn of(sim: &Simulation<'_>, t0: Real, warnings: &mut Vec<String>) -> Option<Grid> {
        match (&sim.times, sim.interval) {
            (Some(list), _) => Some(Grid {
                t0,
                dt: Real::NAN,
                list: Some(list.iter().copied().filter(|t| *t > t0).collect()),
                k: 0,
                t_max: sim.t_max,
                last_k: None,
            }),
            (None, Some(dt)) => {
                let last_k = match sim.t_max {
                    None => {
                        let n = sim.max_outputs.map_or(MAX_UNENDED_OUTPUTS, |m| m.min(MAX_UNENDED_OUTPUTS));
                        warnings.push(format!(
                            "the output every {} s ends after {n} output times (t = {} s), as the run has no t_max; set t_max to choose the end",
                            short(dt),
                            short(t0 + n as Real * dt)
                        ));
                        Some(n)
                    }
                    Some(tm) => sim.max_outputs.filter(|&n| (tm - t0) / dt > n as Real).inspect(|&n| {
                        warnings.push(format!(
                            "the output every {} s up to t_max = {} s asks for {:.3e} output times, more than the {n} allowed: the output ends at t = {} s; choose a larger output interval, or raise the output limit (`[output] max_size`, `--max-output`)",
                            short(dt),
                            short(tm),
                            (tm - t0) / dt,
                            short(t0 + n as Real * dt)
                        ));
                    }),
                };
                Some(Grid {
                    t0,
                    dt,
                    list: None,
                    k: 1,
                    t_max: sim.t_max,
                    last_k,
                })
            }
            (None, None) => None,
        }
    }

    /// The next output time.
    pub fn next(&self) -> Option<Real> {
        if self.last_k.is_some_and(|last| self.k > last) {
            return None;
        }
        let t = match &self.list {
            Some(list) => *list.get(usize::try_from(self.k).ok()?)?,
            None => self.t0 + self.k as Real * self.dt,
        };
        match self.t_max {
            Some(tm) if t > tm * (1.0 + 1e-12) + 1e-300 => None,
            _ => Some(t),
        }
    }
}

impl Grid {
    /// Passes the observers the state at every output time before `limit` (up to and including
    /// it when `inclusive`), interpolated in `step`.
    #[allow(clippy::too_many_arguments)]
    pub fn emit_until(
        &mut self,
        step: &mut Step<'_, '_>,
        probe: &mut Probe,
        limit: Real,
        inclusive: bool,
        step_index: u64,
        evaluations: &mut u64,
        observers: &mut [&mut dyn Observer],
    ) -> Result<(), SimulateError> {
        while let Some(t) = self
            .next()
            .filter(|t| *t < limit || inclusive && *t == limit)
        {
            step.probe(probe, t, true, evaluations);
            let s = sample_of(
                step_index,
                &probe.state,
                &probe.eval,
                &probe.work,
                SampleKind::Grid,
            );
            emit(observers, &s)?;
            self.k += 1;
        }
        Ok(())
    }
}

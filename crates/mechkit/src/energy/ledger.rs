//! The energy ledger of a run.
//!
//! The work of force `i` is the time integral of its power, `W_i = ∫ F_i·v dt`, accumulated
//! with the trapezoidal rule over the steps actually taken (the power evaluated at each step's
//! end state). It is an independent measurement along the computed path, not a consequence of
//! the update formula, so the work-energy residual `Σ W_i - ΔK` measures how consistent the
//! trajectory is: it shrinks as `h` shrinks (as `h²` for second-order and higher methods, as
//! `h` for Euler and Euler-Cromer). For conservative forces `W_i = -ΔU_i` is a second check,
//! and `ΔE = Δ(K + U)` is the energy drift of the method.
//!
//! Adaptive runs integrate the work as part of the ODE instead (`W_i' = F_i·v`, to the method's
//! order and tolerance) and hand the values over with [`EnergyLedger::set`]. State changes by
//! events (a bounce reversing a velocity) change `K` and `U` without any force doing work; they
//! are booked separately ([`EnergyLedger::jump`]) so the residual still measures the trajectory.

use super::balance::{EnergyBalance, EnergyPart, EnergyTerm, ForceWork};
use crate::Real;
use crate::particles::Evaluation;

/// Work, kinetic and potential energy of a run.
#[derive(Debug, Clone, PartialEq)]
pub struct EnergyLedger {
    names: Vec<String>,
    work: Vec<Real>,
    last_power: Vec<Real>,
    last_t: Real,
    kinetic_start: Real,
    kinetic_end: Real,
    potential_start: Option<Real>,
    potential_end: Option<Real>,
    potential_each_start: Vec<Real>,
    potential_each_end: Vec<Real>,
    jump_kinetic: Real,
    jump_potential: Real,
    impulse: Vec<Real>,
    last_net: Vec<Real>,
    momentum_start: Vec<Real>,
    momentum_end: Vec<Real>,
    jump_momentum: Vec<Real>,
}

impl EnergyLedger {
    /// Opens the ledger at time `t` with the evaluation of the initial state.
    pub fn start(names: Vec<String>, t: Real, eval: &Evaluation) -> Self {
        let n = names.len();
        assert_eq!(eval.power.len(), n, "one power value per force");
        Self {
            names,
            work: vec![0.0; n],
            last_power: eval.power.clone(),
            last_t: t,
            kinetic_start: eval.kinetic,
            kinetic_end: eval.kinetic,
            potential_start: eval.potential_total,
            potential_end: eval.potential_total,
            potential_each_start: eval.potential.clone(),
            potential_each_end: eval.potential.clone(),
            jump_kinetic: 0.0,
            jump_potential: 0.0,
            impulse: vec![0.0; eval.net.len()],
            last_net: eval.net.clone(),
            momentum_start: eval.momentum.clone(),
            momentum_end: eval.momentum.clone(),
            jump_momentum: vec![0.0; eval.momentum.len()],
        }
    }

    /// Adds the trapezoid of each force's net force from the last recorded time to `t`.
    fn add_impulse(&mut self, t: Real, eval: &Evaluation) {
        let h = t - self.last_t;
        for ((j, f0), f1) in self
            .impulse
            .iter_mut()
            .zip(&mut self.last_net)
            .zip(&eval.net)
        {
            *j += 0.5 * h * (*f0 + f1);
            *f0 = *f1;
        }
        self.momentum_end.clone_from(&eval.momentum);
    }

    /// Records the state reached at time `t` with the work of each force integrated elsewhere
    /// (adaptive runs carry it in the ODE).
    pub fn set(&mut self, t: Real, eval: &Evaluation, work: &[Real]) {
        self.add_impulse(t, eval);
        self.work.copy_from_slice(work);
        self.last_power.clone_from(&eval.power);
        self.last_t = t;
        self.kinetic_end = eval.kinetic;
        self.potential_end = eval.potential_total;
        self.potential_each_end.clone_from(&eval.potential);
    }

    /// Records a sudden change of the state at the current time (an event's action), `eval`
    /// being the evaluation after it: the changes of `K` and `U` are booked as jumps, not work.
    pub fn jump(&mut self, eval: &Evaluation) {
        for ((j, p1), p0) in self
            .jump_momentum
            .iter_mut()
            .zip(&eval.momentum)
            .zip(&self.momentum_end)
        {
            *j += p1 - p0;
        }
        self.momentum_end.clone_from(&eval.momentum);
        self.last_net.clone_from(&eval.net);
        self.jump_kinetic += eval.kinetic - self.kinetic_end;
        if let (Some(u1), Some(u0)) = (eval.potential_total, self.potential_end) {
            self.jump_potential += u1 - u0;
        }
        self.last_power.clone_from(&eval.power);
        self.kinetic_end = eval.kinetic;
        self.potential_end = eval.potential_total;
        self.potential_each_end.clone_from(&eval.potential);
    }

    /// Change of the kinetic energy by state changes of events (J).
    pub fn jump_kinetic(&self) -> Real {
        self.jump_kinetic
    }

    /// Change of the mechanical energy `K + U` by state changes of events (J).
    pub fn jump_energy(&self) -> Real {
        self.jump_kinetic + self.jump_potential
    }

    /// Records the state reached at time `t`.
    pub fn advance(&mut self, t: Real, eval: &Evaluation) {
        self.add_impulse(t, eval);
        let h = t - self.last_t;
        for ((w, p0), p1) in self
            .work
            .iter_mut()
            .zip(&mut self.last_power)
            .zip(&eval.power)
        {
            *w += 0.5 * h * (*p0 + p1);
            *p0 = *p1;
        }
        self.last_t = t;
        self.kinetic_end = eval.kinetic;
        self.potential_end = eval.potential_total;
        self.potential_each_end.clone_from(&eval.potential);
    }

    /// The running sums of the trapezoids and their last values, for a fused kernel that
    /// advances them itself; [`EnergyLedger::end_at`] then records the end state.
    pub(crate) fn trapezoids(&mut self) -> Trapezoids<'_> {
        Trapezoids {
            work: &mut self.work,
            power: &mut self.last_power,
            impulse: &mut self.impulse,
            net: &mut self.last_net,
            last_t: &mut self.last_t,
        }
    }

    /// Records the energies and momentum of the state a fused kernel reached.
    pub(crate) fn end_at(&mut self, eval: &Evaluation) {
        self.momentum_end.clone_from(&eval.momentum);
        self.kinetic_end = eval.kinetic;
        self.potential_end = eval.potential_total;
        self.potential_each_end.clone_from(&eval.potential);
    }

    /// The work each force would have done had the run reached time `t` with power `power`
    /// there (without recording it), into `out`.
    pub fn preview_into(&self, t: Real, power: &[Real], out: &mut Vec<Real>) {
        let h = t - self.last_t;
        out.clear();
        out.extend(
            self.work
                .iter()
                .zip(&self.last_power)
                .zip(power)
                .map(|((w, p0), p1)| w + 0.5 * h * (p0 + p1)),
        );
    }

    /// Force names, in ledger order.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// Work done by each force so far (J).
    pub fn work(&self) -> &[Real] {
        &self.work
    }

    /// Work done by the force named `name`.
    pub fn work_of(&self, name: &str) -> Option<Real> {
        self.names
            .iter()
            .position(|n| n == name)
            .map(|i| self.work[i])
    }

    /// Sum of the work of all forces.
    pub fn net_work(&self) -> Real {
        self.work.iter().sum()
    }

    /// Kinetic energy at the start.
    pub fn kinetic_start(&self) -> Real {
        self.kinetic_start
    }

    /// Kinetic energy now.
    pub fn kinetic_end(&self) -> Real {
        self.kinetic_end
    }

    /// Potential energy at the start (`None` when no force has a potential).
    pub fn potential_start(&self) -> Option<Real> {
        self.potential_start
    }

    /// Potential energy now.
    pub fn potential_end(&self) -> Option<Real> {
        self.potential_end
    }

    /// Change of the potential energy of force `i` (`None` if it has none).
    pub fn potential_change(&self, i: usize) -> Option<Real> {
        let d = self.potential_each_end[i] - self.potential_each_start[i];
        (!self.potential_each_start[i].is_nan()).then_some(d)
    }

    /// `W_net - (ΔK - ΔK_events)`: zero for an exact trajectory (the kinetic energy changed by
    /// events' state changes is not the work of any force).
    pub fn work_energy_residual(&self) -> Real {
        self.net_work() - (self.kinetic_end - self.kinetic_start - self.jump_kinetic)
    }

    /// Mechanical energy `K + U` at the start and now (`U = 0` without potentials).
    pub fn energy(&self) -> (Real, Real) {
        (
            self.kinetic_start + self.potential_start.unwrap_or(0.0),
            self.kinetic_end + self.potential_end.unwrap_or(0.0),
        )
    }

    /// `ΔE = Δ(K + U)`: the energy the method gained or lost, plus the work of the
    /// non-conservative forces (which is its exact value when only those act).
    pub fn energy_change(&self) -> Real {
        let (e0, e1) = self.energy();
        e1 - e0
    }

    /// Impulse `∫F dt` of force `i` so far, its net force summed over the bodies it acts on
    /// (trapezoidal rule over the steps), `dim` components; zero for an internal force.
    pub fn impulse(&self, i: usize) -> &[Real] {
        let d = self.momentum_start.len();
        &self.impulse[i * d..(i + 1) * d]
    }

    /// Total momentum at the start.
    pub fn momentum_start(&self) -> &[Real] {
        &self.momentum_start
    }

    /// Total momentum now.
    pub fn momentum_end(&self) -> &[Real] {
        &self.momentum_end
    }

    /// Momentum changed by events' state changes (impacts on walls; impacts between bodies
    /// change nothing).
    pub fn jump_momentum(&self) -> &[Real] {
        &self.jump_momentum
    }

    /// `Δp - Σ J - Δp_events` per component: zero for an exact trajectory (the impulse-
    /// momentum theorem as a check, like the work-energy residual).
    pub fn momentum_residual(&self) -> Vec<Real> {
        let d = self.momentum_start.len();
        (0..d)
            .map(|k| {
                let dp = self.momentum_end[k] - self.momentum_start[k];
                let j: Real = (0..self.names.len()).map(|i| self.impulse[i * d + k]).sum();
                dp - j - self.jump_momentum[k]
            })
            .collect()
    }

    /// Work of the forces without a potential (drag, formulas): equals `ΔE` exactly.
    pub fn non_conservative_work(&self) -> Real {
        (0..self.work.len())
            .filter(|&i| self.potential_each_start[i].is_nan())
            .map(|i| self.work[i])
            .sum()
    }

    /// The run's [`EnergyBalance`]: `K` and `U` at the start and now (`U` split by force,
    /// `None` when no force has a potential), the work of every force (those with a potential
    /// marked conservative) and the energy changed by events ([`EnergyLedger::jump_energy`]).
    /// Its residual is `ΔE − W_nc − ΔE_events`, the energy form of the check
    /// (`work_energy_residual` is the kinetic form).
    pub fn balance(&self) -> EnergyBalance {
        let conservative = |i: usize| !self.potential_each_start[i].is_nan();
        let potential = self
            .potential_start
            .zip(self.potential_end)
            .map(|(start, end)| EnergyTerm {
                start,
                end,
                parts: (0..self.names.len())
                    .filter(|&i| conservative(i))
                    .map(|i| EnergyPart {
                        name: self.names[i].clone(),
                        start: self.potential_each_start[i],
                        end: self.potential_each_end[i],
                    })
                    .collect(),
            });
        EnergyBalance {
            kinetic: EnergyTerm::new(self.kinetic_start, self.kinetic_end),
            potential,
            work: self
                .names
                .iter()
                .zip(&self.work)
                .enumerate()
                .map(|(i, (name, &work))| ForceWork {
                    name: name.clone(),
                    work,
                    conservative: conservative(i),
                })
                .collect(),
            events: self.jump_energy(),
        }
    }
}

/// The ledger's running trapezoids, lent to a fused step kernel.
pub(crate) struct Trapezoids<'a> {
    pub work: &'a mut [Real],
    pub power: &'a mut [Real],
    pub impulse: &'a mut [Real],
    pub net: &'a mut [Real],
    pub last_t: &'a mut Real,
}

//! The scenario's equations of motion at given states, for the loops students write
//! themselves: the accelerations, and each force's value, power and potential, at many
//! `(t, q, v)` at once, computed by the same forces, units and formulas as a run.

use super::Scenario;
use super::error::{ErrorKind, ScenarioError};
use crate::Real;
use crate::particles::Kinematics;

/// What the model gives at `n` states of `dof` coordinates and `forces` forces, row-major:
/// state `s`'s acceleration is `accel[s*dof..(s+1)*dof]`, force `i`'s generalized force at it
/// `force[(s*forces + i)*dof..]`, its power `power[s*forces + i]` (W) and its potential
/// `potential[s*forces + i]` (J; NaN for a force without one).
#[derive(Debug, Clone, PartialEq)]
pub struct ModelValues {
    /// Number of states.
    pub states: usize,
    /// Coordinates per state.
    pub dof: usize,
    /// The forces' names, in order.
    pub forces: Vec<String>,
    /// Accelerations of every coordinate.
    pub accel: Vec<Real>,
    /// Each force's generalized force: N per position component, N m per angle; on the four
    /// orientation coordinates of a body in space, `2 (0, τ) ⊗ q` (its power is `τ·ω`).
    pub force: Vec<Real>,
    /// Each force's power.
    pub power: Vec<Real>,
    /// Each force's potential energy.
    pub potential: Vec<Real>,
}

impl Scenario {
    /// The number of coordinates of the state (`dim` per body, then the rigid bodies' angles
    /// or orientation quaternions and the joints' modes).
    pub fn dof(&self) -> usize {
        crate::ode::SecondOrderSystem::dof(&self.system)
    }

    /// The names of the coordinates, as the trajectory names positions (`ball.x`) and the
    /// extras by their own names (`ladder`, `top.q0`, `wall.touching`).
    pub fn coordinate_names(&self) -> Vec<String> {
        let axes = self.system.coordinates().component_names(self.system.dim())[0].clone();
        let mut names: Vec<String> = self
            .system
            .bodies()
            .iter()
            .flat_map(|b| axes.iter().map(move |a| format!("{}.{a}", b.name)))
            .collect();
        names.extend(self.system.extras().iter().map(|e| e.name.clone()));
        names
    }

    /// Evaluates the model at the states `(t[s], q[s*dof..], v[s*dof..])`.
    ///
    /// # Errors
    /// When `q` or `v` does not hold `t.len()` states of [`Scenario::dof`] numbers.
    pub fn evaluate_model(
        &self,
        t: &[Real],
        q: &[Real],
        v: &[Real],
    ) -> Result<ModelValues, ScenarioError> {
        let dof = self.dof();
        let states = t.len();
        for (what, x) in [("positions", q), ("velocities", v)] {
            if x.len() != states * dof {
                return Err(ScenarioError::new(
                    ErrorKind::Invalid,
                    format!(
                        "{states} times need {states} rows of {dof} {what} ({}), not {} numbers",
                        self.coordinate_names().join(", "),
                        x.len()
                    ),
                ));
            }
        }
        let sys = &self.system;
        let nf = sys.forces().len();
        let mut out = ModelValues {
            states,
            dof,
            forces: sys.forces().iter().map(|f| f.name().to_string()).collect(),
            accel: vec![0.0; states * dof],
            force: vec![0.0; states * nf * dof],
            power: vec![0.0; states * nf],
            potential: vec![Real::NAN; states * nf],
        };
        let mut total = vec![0.0; dof];
        let mut masses = Vec::new();
        for (s, &ts) in t.iter().enumerate() {
            let (qs, vs) = (&q[s * dof..(s + 1) * dof], &v[s * dof..(s + 1) * dof]);
            crate::ode::SecondOrderSystem::accel_into(
                sys,
                ts,
                qs,
                vs,
                &mut out.accel[s * dof..(s + 1) * dof],
            );
            sys.masses_at(qs, &mut masses);
            let k = Kinematics {
                t: ts,
                dim: sys.dim(),
                x: qs,
                v: vs,
                mass: &masses,
            };
            let each = &mut out.force[s * nf * dof..(s + 1) * nf * dof];
            sys.forces().each_into(&k, &mut total, each);
            for (i, f) in sys.forces().iter().enumerate() {
                let own = &each[i * dof..(i + 1) * dof];
                out.power[s * nf + i] =
                    own.iter().zip(vs).map(|(a, b)| a * b).sum::<Real>() + f.extra_power(&k);
                if let Some(u) = f.potential(&k) {
                    out.potential[s * nf + i] = u;
                }
            }
        }
        Ok(out)
    }
}

//! The names formulas use for the state: `t`, `x`, `vy`, `v`, `r`, `m`, `feather.x`, `K`,
//! `work.air`, … and formulas compiled against them.
//!
//! | name | meaning | unit |
//! |---|---|---|
//! | `t` | time | s |
//! | `x`, `y`, `z` | position components (as many as dimensions) | m |
//! | `vx`, `vy`, `vz` | velocity components | m/s |
//! | `v` | velocity in 1-D (signed); speed in 2-D/3-D | m/s |
//! | `speed` | speed `|v|` | m/s |
//! | `r` | distance from the origin | m |
//! | `m` | mass | kg |
//! | `ax`, `ay`, `az`, `a` | acceleration (`a`: signed in 1-D, magnitude otherwise)¹ | m/s² |
//! | `K` (per body: `name.K`) | kinetic energy¹ | J |
//! | `U`, `E` | potential energy of the conservative forces, `K + U`¹ | J |
//! | `work.F`, `power.F` | work done so far and power of the force named `F`¹ | J, W |
//!
//! Body quantities are written `name.x`; a bare `x` means the body a force acts on, or the only
//! body of a one-body scenario. ¹ Not available inside forces (they would depend on forces).

use mechkit_expr::units::Dimension;
use mechkit_expr::{Binding, Dim, ExprError, Formula, Program, Scope};

use super::kinematics::{Kinematics, dot, norm};
use super::sample::Sample;
use crate::Real;

/// Which body a name refers to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BodyRef {
    /// The body the formula is being evaluated for (a force's target).
    Local,
    /// A specific body.
    Index(usize),
}

/// A quantity of the state, by meaning.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum StateVar {
    /// Time.
    Time,
    /// Position component.
    Position(BodyRef, usize),
    /// Velocity component.
    Velocity(BodyRef, usize),
    /// Speed.
    Speed(BodyRef),
    /// Distance from the origin.
    Distance(BodyRef),
    /// Mass.
    Mass(BodyRef),
    /// Acceleration component.
    Acceleration(BodyRef, usize),
    /// Magnitude of the acceleration.
    AccelerationMagnitude(BodyRef),
    /// Kinetic energy of one body.
    BodyKinetic(BodyRef),
    /// Total kinetic energy.
    Kinetic,
    /// Total potential energy of the conservative forces.
    Potential,
    /// `K + U`.
    Energy,
    /// Work done by force `i` so far.
    Work(usize),
    /// Power of force `i`.
    Power(usize),
}

/// Which names a formula may use.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum VarLevel {
    /// Time, positions, velocities, masses: what a force may depend on.
    Kinematic,
    /// Also accelerations, energies, work and power: for conditions, observables and plots.
    Derived,
}

const AXES: [&str; 3] = ["x", "y", "z"];
const VAXES: [&str; 3] = ["vx", "vy", "vz"];
const AAXES: [&str; 3] = ["ax", "ay", "az"];

impl StateVar {
    /// Whether a force may depend on it.
    pub fn is_kinematic(self) -> bool {
        matches!(
            self,
            StateVar::Time
                | StateVar::Position(..)
                | StateVar::Velocity(..)
                | StateVar::Speed(_)
                | StateVar::Distance(_)
                | StateVar::Mass(_)
        )
    }

    /// Its dimension.
    pub fn dimension(self) -> Dimension {
        match self {
            StateVar::Time => Dimension::TIME,
            StateVar::Position(..) | StateVar::Distance(_) => Dimension::LENGTH,
            StateVar::Velocity(..) | StateVar::Speed(_) => Dimension::VELOCITY,
            StateVar::Mass(_) => Dimension::MASS,
            StateVar::Acceleration(..) | StateVar::AccelerationMagnitude(_) => {
                Dimension::ACCELERATION
            }
            StateVar::BodyKinetic(_)
            | StateVar::Kinetic
            | StateVar::Potential
            | StateVar::Energy
            | StateVar::Work(_) => Dimension::ENERGY,
            StateVar::Power(_) => Dimension::POWER,
        }
    }

    /// The SI unit to label it with.
    pub fn unit(self) -> &'static str {
        match self {
            StateVar::Time => "s",
            StateVar::Position(..) | StateVar::Distance(_) => "m",
            StateVar::Velocity(..) | StateVar::Speed(_) => "m/s",
            StateVar::Mass(_) => "kg",
            StateVar::Acceleration(..) | StateVar::AccelerationMagnitude(_) => "m/s²",
            StateVar::Power(_) => "W",
            _ => "J",
        }
    }

    fn body(self, local: Option<usize>) -> usize {
        let (StateVar::Position(r, _)
        | StateVar::Velocity(r, _)
        | StateVar::Speed(r)
        | StateVar::Distance(r)
        | StateVar::Mass(r)
        | StateVar::Acceleration(r, _)
        | StateVar::AccelerationMagnitude(r)
        | StateVar::BodyKinetic(r)) = self
        else {
            return 0;
        };
        match r {
            BodyRef::Index(i) => i,
            BodyRef::Local => local.expect("a formula with body-local names needs a body"),
        }
    }

    /// Value from the kinematics (only for [`StateVar::is_kinematic`] quantities).
    #[inline]
    pub fn value_kinematic(self, k: &Kinematics<'_>, local: Option<usize>) -> Real {
        let d = k.dim;
        match self {
            StateVar::Time => k.t,
            StateVar::Position(_, i) => k.x[self.body(local) * d + i],
            StateVar::Velocity(_, i) => k.v[self.body(local) * d + i],
            StateVar::Speed(_) => norm(k.velocity(self.body(local))),
            StateVar::Distance(_) => norm(k.position(self.body(local))),
            StateVar::Mass(_) => k.mass[self.body(local)],
            other => panic!("{other:?} is not a kinematic quantity"),
        }
    }

    /// Value in a sample of a system with `dim` dimensions and body masses `mass`.
    pub fn value(self, s: &Sample<'_>, dim: usize, mass: &[Real], local: Option<usize>) -> Real {
        let b = self.body(local);
        match self {
            StateVar::Acceleration(_, i) => s.eval.a[b * dim + i],
            StateVar::AccelerationMagnitude(_) => norm(&s.eval.a[b * dim..(b + 1) * dim]),
            StateVar::BodyKinetic(_) => {
                let v = &s.v[b * dim..(b + 1) * dim];
                0.5 * mass[b] * dot(v, v)
            }
            StateVar::Kinetic => s.eval.kinetic,
            StateVar::Potential => s.eval.potential_total.unwrap_or(Real::NAN),
            StateVar::Energy => s.energy(),
            StateVar::Work(i) => s.work[i],
            StateVar::Power(i) => s.eval.power[i],
            kin => kin.value_kinematic(
                &Kinematics {
                    t: s.t,
                    dim,
                    x: s.q,
                    v: s.v,
                    mass,
                },
                local,
            ),
        }
    }
}

/// What names mean where a formula is used: the system's bodies and forces, the constants,
/// whether bare names refer to a local body, and how much of the state may be used.
#[derive(Debug, Clone)]
pub struct NameContext<'a> {
    /// Spatial dimensions.
    pub dim: usize,
    /// Body names, by index.
    pub bodies: &'a [String],
    /// Force names, by index (for `work.F`, `power.F`).
    pub forces: &'a [String],
    /// Constants: name, value (SI), dimension.
    pub constants: &'a [(String, Real, Dim)],
    /// The body bare names refer to, if any: `Local` inside a force, the only body in a
    /// one-body scenario, or none.
    pub bare: Option<BodyRef>,
    /// How much of the state may be used.
    pub level: VarLevel,
}

impl NameContext<'_> {
    /// Resolves a state name (not a constant).
    pub fn resolve(&self, name: &str) -> Option<StateVar> {
        if name == "t" {
            return Some(StateVar::Time);
        }
        let derived = self.level == VarLevel::Derived;
        if derived {
            match name {
                "K" => return Some(StateVar::Kinetic),
                "U" => return Some(StateVar::Potential),
                "E" => return Some(StateVar::Energy),
                _ => {}
            }
            for (prefix, power) in [("work.", false), ("power.", true)] {
                if let Some(force) = name.strip_prefix(prefix) {
                    let i = self.forces.iter().position(|f| f == force)?;
                    return Some(if power {
                        StateVar::Power(i)
                    } else {
                        StateVar::Work(i)
                    });
                }
            }
        }
        let (body, field) = match name.rsplit_once('.') {
            Some((body, field)) => {
                let i = self.bodies.iter().position(|b| b == body)?;
                (BodyRef::Index(i), field)
            }
            None => (self.bare?, name),
        };
        self.body_field(body, field, derived)
    }

    fn body_field(&self, b: BodyRef, field: &str, derived: bool) -> Option<StateVar> {
        let d = self.dim;
        let axis = |names: &[&str; 3]| names[..d].iter().position(|n| *n == field);
        if let Some(i) = axis(&AXES) {
            return Some(StateVar::Position(b, i));
        }
        if let Some(i) = axis(&VAXES) {
            return Some(StateVar::Velocity(b, i));
        }
        let kinematic = match field {
            "v" if d == 1 => Some(StateVar::Velocity(b, 0)),
            "v" | "speed" => Some(StateVar::Speed(b)),
            "r" => Some(StateVar::Distance(b)),
            "m" => Some(StateVar::Mass(b)),
            _ => None,
        };
        if kinematic.is_some() || !derived {
            return kinematic;
        }
        if let Some(i) = axis(&AAXES) {
            return Some(StateVar::Acceleration(b, i));
        }
        match field {
            "a" if d == 1 => Some(StateVar::Acceleration(b, 0)),
            "a" => Some(StateVar::AccelerationMagnitude(b)),
            "K" => Some(StateVar::BodyKinetic(b)),
            _ => None,
        }
    }

    /// Every name valid here (for suggestions and help).
    pub fn all_names(&self) -> Vec<String> {
        let d = self.dim;
        let derived = self.level == VarLevel::Derived;
        let mut fields: Vec<&str> = Vec::new();
        fields.extend(&AXES[..d]);
        fields.extend(&VAXES[..d]);
        fields.extend(["v", "r", "m"]);
        if d > 1 {
            fields.push("speed");
        }
        if derived {
            fields.extend(&AAXES[..d]);
            fields.extend(["a", "K"]);
        }
        let mut out = vec!["t".to_string()];
        if self.bare.is_some() {
            out.extend(fields.iter().map(|f| (*f).to_string()));
        }
        for body in self.bodies {
            out.extend(fields.iter().map(|f| format!("{body}.{f}")));
        }
        if derived {
            out.extend(["K", "U", "E"].map(String::from));
            for f in self.forces {
                out.push(format!("work.{f}"));
                out.push(format!("power.{f}"));
            }
        }
        out.extend(self.constants.iter().map(|(n, _, _)| n.clone()));
        out
    }

    fn describe(&self) -> String {
        let d = self.dim;
        let axes = AXES[..d].join(", ");
        let v = VAXES[..d].join(", ");
        let mut s = match (self.bare, self.bodies.first()) {
            (Some(_), _) => format!("names here: t, {axes}, {v}, v, r, m"),
            (None, Some(b)) => format!("names here: t and body quantities such as {b}.x, {b}.v"),
            (None, None) => "names here: t".to_string(),
        };
        if self.level == VarLevel::Derived {
            s.push_str(", K, U, E, work.<force>, power.<force>");
        } else {
            s.push_str(" (forces cannot use accelerations or energies)");
        }
        if !self.constants.is_empty() {
            s.push_str(" and the constants");
        }
        s
    }

    /// Value of a constant.
    pub fn constant(&self, name: &str) -> Option<Real> {
        self.constants
            .iter()
            .find(|(n, _, _)| n == name)
            .map(|(_, v, _)| *v)
    }

    /// Dimension of a name as a formula sees it: constants first, then state names.
    pub fn dim_of(&self, name: &str) -> Dim {
        if let Some((_, _, d)) = self.constants.iter().find(|(n, _, _)| n == name) {
            return *d;
        }
        self.resolve(name)
            .map_or(Dim::Unknown, |v| Dim::Known(v.dimension()))
    }

    /// Compiles `formula`: constants are folded, state names become slots.
    pub fn compile(&self, formula: &Formula) -> Result<StateExpr, ExprError> {
        let mut vars: Vec<StateVar> = Vec::new();
        let mut scope = ContextScope {
            ctx: self,
            slots: Vec::new(),
        };
        for name in formula.names() {
            if self.constants.iter().any(|(n, _, _)| n == name) {
                continue;
            }
            if let Some(var) = self.resolve(name) {
                let slot = vars.iter().position(|v| *v == var).unwrap_or_else(|| {
                    vars.push(var);
                    vars.len() - 1
                });
                scope.slots.push((name.to_string(), slot));
            }
        }
        let program = formula.compile(&scope)?;
        formula.dimension_with(&|n| self.dim_of(n), &|n| self.constant(n))?;
        Ok(StateExpr {
            source: formula.source().to_string(),
            program,
            vars,
        })
    }
}

struct ContextScope<'a, 'b> {
    ctx: &'a NameContext<'b>,
    slots: Vec<(String, usize)>,
}

impl Scope for ContextScope<'_, '_> {
    fn lookup(&self, name: &str) -> Option<Binding> {
        if let Some((_, v, _)) = self.ctx.constants.iter().find(|(n, _, _)| n == name) {
            return Some(Binding::Const(*v));
        }
        self.slots
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, s)| Binding::Slot(*s))
    }

    fn candidates(&self) -> Vec<String> {
        self.ctx.all_names()
    }

    fn describe(&self) -> Option<String> {
        Some(self.ctx.describe())
    }
}

/// Most distinct state names one formula may use before evaluation allocates.
const INLINE_VARS: usize = 16;

/// A formula compiled against the state names: evaluate it on kinematics (in forces) or on a
/// sample (conditions, observables).
#[derive(Debug, Clone)]
pub struct StateExpr {
    source: String,
    program: Program,
    vars: Vec<StateVar>,
}

impl StateExpr {
    /// The formula as written.
    pub fn source(&self) -> &str {
        &self.source
    }

    /// The state quantities it reads.
    pub fn vars(&self) -> &[StateVar] {
        &self.vars
    }

    /// Whether it reads only time, positions, velocities and masses.
    pub fn is_kinematic(&self) -> bool {
        self.vars.iter().all(|v| v.is_kinematic())
    }

    /// Whether it reads velocities.
    pub fn reads_velocity(&self) -> bool {
        self.vars
            .iter()
            .any(|v| matches!(v, StateVar::Velocity(..) | StateVar::Speed(_)))
    }

    /// The value, if it reads no state at all.
    pub fn as_constant(&self) -> Option<Real> {
        self.program.as_constant()
    }

    #[inline]
    fn eval_with(&self, fill: impl Fn(StateVar) -> Real) -> Real {
        let n = self.vars.len();
        if n <= INLINE_VARS {
            let mut slots = [0.0; INLINE_VARS];
            for (s, v) in slots.iter_mut().zip(&self.vars) {
                *s = fill(*v);
            }
            self.program.eval(&slots[..n])
        } else {
            let slots: Vec<Real> = self.vars.iter().map(|v| fill(*v)).collect();
            self.program.eval(&slots)
        }
    }

    /// Evaluates on kinematics, bare names meaning body `local`.
    #[inline]
    pub fn eval_kinematic(&self, k: &Kinematics<'_>, local: Option<usize>) -> Real {
        self.eval_with(|v| v.value_kinematic(k, local))
    }

    /// Evaluates on a sample.
    pub fn eval_sample(
        &self,
        s: &Sample<'_>,
        dim: usize,
        mass: &[Real],
        local: Option<usize>,
    ) -> Real {
        self.eval_with(|v| v.value(s, dim, mass, local))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ctx<'a>(
        bodies: &'a [String],
        forces: &'a [String],
        constants: &'a [(String, Real, Dim)],
        level: VarLevel,
    ) -> NameContext<'a> {
        NameContext {
            dim: 2,
            bodies,
            forces,
            constants,
            bare: Some(BodyRef::Local),
            level,
        }
    }

    #[test]
    fn resolves_names() {
        let bodies = vec!["ball".to_string(), "moon".to_string()];
        let forces = vec!["air".to_string()];
        let c = ctx(&bodies, &forces, &[], VarLevel::Derived);
        assert_eq!(c.resolve("y"), Some(StateVar::Position(BodyRef::Local, 1)));
        assert_eq!(c.resolve("z"), None);
        assert_eq!(
            c.resolve("moon.vx"),
            Some(StateVar::Velocity(BodyRef::Index(1), 0))
        );
        assert_eq!(c.resolve("v"), Some(StateVar::Speed(BodyRef::Local)));
        assert_eq!(c.resolve("work.air"), Some(StateVar::Work(0)));
        assert_eq!(c.resolve("work.wind"), None);
        assert_eq!(
            c.resolve("ball.K"),
            Some(StateVar::BodyKinetic(BodyRef::Index(0)))
        );
        let k = ctx(&bodies, &forces, &[], VarLevel::Kinematic);
        assert_eq!(k.resolve("ax"), None);
        assert_eq!(k.resolve("K"), None);
    }

    #[test]
    fn compiles_and_evaluates_with_constants() {
        let bodies = vec!["ball".to_string()];
        let constants = vec![("D".to_string(), 0.5, Dim::Known(Dimension::QUADRATIC_DRAG))];
        let c = ctx(&bodies, &[], &constants, VarLevel::Kinematic);
        let e = c.compile(&Formula::parse("-D*v*vx").unwrap()).unwrap();
        let k = Kinematics {
            t: 0.0,
            dim: 2,
            x: &[0.0, 1.0],
            v: &[3.0, 4.0],
            mass: &[1.0],
        };
        assert_eq!(e.eval_kinematic(&k, Some(0)), -0.5 * 5.0 * 3.0);
        assert!(e.reads_velocity());
    }

    #[test]
    fn errors_suggest_and_describe() {
        let bodies = vec!["ball".to_string()];
        let c = ctx(&bodies, &[], &[], VarLevel::Kinematic);
        let err = c
            .compile(&Formula::parse("-ball.vxx").unwrap())
            .unwrap_err();
        let text = err.to_string();
        assert!(text.contains("did you mean `ball.vx`"), "{text}");
        let err = c.compile(&Formula::parse("K").unwrap()).unwrap_err();
        assert!(err.to_string().contains("forces cannot use"), "{err}");
        let err = c.compile(&Formula::parse("x + t").unwrap()).unwrap_err();
        assert!(err.to_string().contains("cannot add"), "{err}");
    }
}

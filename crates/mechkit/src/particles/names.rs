//! Name resolution: what `x`, `feather.v`, `K` or `work.air` mean where a formula is used, and
//! compiling formulas against those meanings.

use mechkit_expr::units::UnitSystem;
use mechkit_expr::{Binding, Dim, ExprError, Formula, Scope};

use super::body_refs::{PointRef, SpinField, SpinRef};
use super::state_expr::StateExpr;
use super::vars::{AAXES, ANGLE, AXES, BodyRef, Coordinates, StateVar, VAXES, VarLevel};
use crate::Real;

/// The names a planar mechanism adds: the rigid bodies' angles and points, the joints.
#[derive(Debug, Clone, Default)]
pub struct PlanarNames {
    /// The rigid bodies.
    pub rigid: Vec<RigidName>,
    /// Each joint's name and the index of its force in the system.
    pub joints: Vec<(String, usize)>,
    /// Number of coordinates after the bodies' positions (angles, modes).
    pub extras: usize,
    /// `(body, index in q)` of the bodies whose mass varies (`rocket.m` reads the coordinate).
    pub masses: Vec<(usize, usize)>,
    /// The joints' mode coordinates by name (`wall.touching`, `rope.taut`, `foot.sliding`)
    /// and their index in `q`.
    pub modes: Vec<(String, usize)>,
}

/// No rigid bodies, no joints.
pub static NO_PLANAR: PlanarNames = PlanarNames {
    rigid: Vec::new(),
    joints: Vec::new(),
    extras: 0,
    modes: Vec::new(),
    masses: Vec::new(),
};

/// A rigid body of a planar mechanism, as formulas name it.
#[derive(Debug, Clone)]
pub struct RigidName {
    /// Body index.
    pub body: usize,
    /// Index of its angle in `q`.
    pub angle: usize,
    /// Moment of inertia about the centre of mass (kg m²).
    pub inertia: Real,
    /// Named points, body frame, from the centre of mass (`z` is 0 in a plane).
    pub points: Vec<(String, [Real; 3])>,
    /// For a body turning in space: its orientation coordinates and inertia tensor (`angle`
    /// is then the index of its first quaternion component, `inertia` unused).
    pub spin: Option<SpinRef>,
}

const RIGID_FIELDS: [&str; 3] = ["theta", "omega", "I"];
const POINT_FIELDS: [&str; 4] = ["x", "y", "vx", "vy"];
const SPACE_POINT_FIELDS: [&str; 6] = ["x", "y", "z", "vx", "vy", "vz"];

/// The names of a rigid body turning in space, with what they are, kinematic ones first.
pub(crate) const SPIN_FIELDS: [(&str, SpinField); 19] = [
    ("wx", SpinField::Omega(0)),
    ("wy", SpinField::Omega(1)),
    ("wz", SpinField::Omega(2)),
    ("omega", SpinField::Speed),
    ("w1", SpinField::OmegaBody(0)),
    ("w2", SpinField::OmegaBody(1)),
    ("w3", SpinField::OmegaBody(2)),
    ("q0", SpinField::Quaternion(0)),
    ("q1", SpinField::Quaternion(1)),
    ("q2", SpinField::Quaternion(2)),
    ("q3", SpinField::Quaternion(3)),
    ("Lx", SpinField::Momentum(0)),
    ("Ly", SpinField::Momentum(1)),
    ("Lz", SpinField::Momentum(2)),
    ("L", SpinField::MomentumMagnitude),
    ("alphax", SpinField::Alpha(0)),
    ("alphay", SpinField::Alpha(1)),
    ("alphaz", SpinField::Alpha(2)),
    ("K", SpinField::Kinetic),
];

/// How many of [`SPIN_FIELDS`] a force may read (the rest need accelerations or energies).
const SPIN_KINEMATIC: usize = 15;

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
    /// What the bodies' coordinates are (positions, or angles about fixed axes).
    pub coordinates: Coordinates,
    /// The units of the scenario: in reduced units state names have no dimension to check.
    pub units: UnitSystem,
    /// Rigid bodies and joints of a planar mechanism.
    pub planar: &'a PlanarNames,
}

impl NameContext<'_> {
    /// Resolves a state name (not a constant).
    pub fn resolve(&self, name: &str) -> Option<StateVar> {
        if name == "t" {
            return Some(StateVar::Time);
        }
        let derived = self.level == VarLevel::Derived;
        if let Some((_, i)) = self.planar.modes.iter().find(|(m, _)| m == name) {
            return Some(StateVar::Coordinate(*i));
        }
        if derived {
            match name {
                "K" => return Some(StateVar::Kinetic),
                "U" => return Some(StateVar::Potential),
                "E" => return Some(StateVar::Energy),
                "K_rot" if !self.planar.rigid.is_empty() => {
                    return Some(StateVar::KineticRotation);
                }
                _ => {}
            }
            if let Some((joint, field)) = name.rsplit_once('.')
                && let Some((_, force)) = self.planar.joints.iter().find(|(j, _)| j == joint)
            {
                let k = crate::rigid::mechanism::REPORT_FIELDS
                    .iter()
                    .position(|f| *f == field)
                    .or((field == "T").then_some(2))?;
                return Some(StateVar::Constraint(*force, k));
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
            Some((body, field)) => match self.bodies.iter().position(|b| b == body) {
                Some(i) => (BodyRef::Index(i), field),
                None => return self.point(body, field),
            },
            None => (self.bare?, name),
        };
        self.body_field(body, field, derived)
    }

    /// `body.point.x`: a named point of a rigid body.
    fn point(&self, body_point: &str, field: &str) -> Option<StateVar> {
        let (body, point) = body_point.split_once('.')?;
        let i = self.bodies.iter().position(|b| b == body)?;
        let rigid = self.planar.rigid.iter().find(|r| r.body == i)?;
        let r = rigid.points.iter().find(|(n, _)| n == point)?.1;
        if rigid.spin.is_some() {
            let p = PointRef::spatial(i, rigid.angle, r);
            let k = SPACE_POINT_FIELDS.iter().position(|f| *f == field)?;
            return Some(if k < 3 {
                StateVar::PointPosition(p, k)
            } else {
                StateVar::PointVelocity(p, k - 3)
            });
        }
        let p = PointRef::new(i, rigid.angle, [r[0], r[1]]);
        let k = POINT_FIELDS.iter().position(|f| *f == field)?;
        Some(if k < 2 {
            StateVar::PointPosition(p, k)
        } else {
            StateVar::PointVelocity(p, k - 2)
        })
    }

    fn body_field(&self, b: BodyRef, field: &str, derived: bool) -> Option<StateVar> {
        let body = match b {
            BodyRef::Index(i) => Some(i),
            BodyRef::Local => None,
        };
        if let Some(&(b, i)) = self.planar.masses.iter().find(|(b, _)| Some(*b) == body) {
            match field {
                "m" => return Some(StateVar::VariableMass(i)),
                "K" if derived => return Some(StateVar::VariableKinetic(b, i)),
                _ => {}
            }
        }
        if let Some(rigid) = self.planar.rigid.iter().find(|r| Some(r.body) == body) {
            if let Some(spin) = rigid.spin {
                let n = if derived {
                    SPIN_FIELDS.len()
                } else {
                    SPIN_KINEMATIC
                };
                if let Some((_, f)) = SPIN_FIELDS[..n].iter().find(|(n, _)| *n == field) {
                    return Some(StateVar::Spin(spin, *f));
                }
            }
            match field {
                "theta" => return Some(StateVar::Coordinate(rigid.angle)),
                "omega" => return Some(StateVar::CoordinateRate(rigid.angle)),
                "alpha" if derived => return Some(StateVar::CoordinateAccel(rigid.angle)),
                "K" if derived => {
                    return Some(StateVar::RigidKinetic(PointRef::new(
                        rigid.body,
                        rigid.angle,
                        [rigid.inertia, 0.0],
                    )));
                }
                _ => {}
            }
        }
        if self.coordinates == Coordinates::Angle {
            return match field {
                "theta" => Some(StateVar::Position(b, 0)),
                "omega" => Some(StateVar::Velocity(b, 0)),
                "I" => Some(StateVar::Mass(b)),
                "alpha" if derived => Some(StateVar::Acceleration(b, 0)),
                "K" if derived => Some(StateVar::BodyKinetic(b)),
                _ => None,
            };
        }
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
        if self.coordinates == Coordinates::Angle {
            fields.extend(["theta", "omega", "I"]);
            if derived {
                fields.extend(["alpha", "K"]);
            }
        } else {
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
        }
        let mut out = vec!["t".to_string()];
        if self.bare.is_some() {
            out.extend(fields.iter().map(|f| (*f).to_string()));
        }
        for body in self.bodies {
            out.extend(fields.iter().map(|f| format!("{body}.{f}")));
        }
        for rigid in &self.planar.rigid {
            let body = &self.bodies[rigid.body];
            if rigid.spin.is_some() {
                let n = if derived {
                    SPIN_FIELDS.len()
                } else {
                    SPIN_KINEMATIC
                };
                out.extend(SPIN_FIELDS[..n].iter().map(|(f, _)| format!("{body}.{f}")));
                for (p, _) in &rigid.points {
                    out.extend(SPACE_POINT_FIELDS.iter().map(|f| format!("{body}.{p}.{f}")));
                }
                continue;
            }
            out.extend(RIGID_FIELDS[..2].iter().map(|f| format!("{body}.{f}")));
            if derived {
                out.push(format!("{body}.alpha"));
            }
            for (p, _) in &rigid.points {
                out.extend(POINT_FIELDS.iter().map(|f| format!("{body}.{p}.{f}")));
            }
        }
        out.extend(self.planar.modes.iter().map(|(m, _)| m.clone()));
        if derived {
            for (j, _) in &self.planar.joints {
                out.extend(
                    crate::rigid::mechanism::REPORT_FIELDS
                        .iter()
                        .map(|f| format!("{j}.{f}")),
                );
            }
            if !self.planar.rigid.is_empty() {
                out.push("K_rot".into());
            }
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
        let angle = self.coordinates == Coordinates::Angle;
        let mut s = match (self.bare, self.bodies.first()) {
            (Some(_), _) if angle => format!("names here: t, {}, {}, I", ANGLE[0], ANGLE[1]),
            (Some(_), _) => format!("names here: t, {axes}, {v}, v, r, m"),
            (None, Some(b)) if angle => {
                format!("names here: t and body quantities such as {b}.theta, {b}.omega")
            }
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
            .map_or(Dim::Unknown, |v| self.coordinates.dim_in(v, self.units))
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
        // state formulas run in the hot loop: native code where available
        let program = formula.compile(&scope)?.native();
        formula.dimension_with(&|n| self.dim_of(n), &|n| self.constant(n))?;
        Ok(StateExpr::new(formula.source().to_string(), program, vars))
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

#[cfg(test)]
#[path = "names_tests.rs"]
mod tests;

//! Two free rigid bodies in the plane (or one and the immovable ground) colliding at a point.

use super::error::ImpactError;
use super::{Contact, cross, spin};
use crate::Real;
use crate::rigid::Input;

/// A rigid body moving freely in the plane.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlanarBody {
    /// Mass (kg); infinite for an immovable body.
    pub mass: Real,
    /// Moment of inertia about the centre of mass, axis z (kg m²); zero for a point mass,
    /// infinite for an immovable body.
    pub inertia: Real,
    /// Centre of mass (m).
    pub position: [Real; 2],
    /// Velocity of the centre of mass (m/s).
    pub velocity: [Real; 2],
    /// Angular velocity (rad/s, counter-clockwise positive).
    pub omega: Real,
}

impl PlanarBody {
    /// A checked body: mass > 0, inertia ≥ 0, finite state.
    pub fn new(
        mass: Real,
        inertia: Real,
        position: [Real; 2],
        velocity: [Real; 2],
        omega: Real,
    ) -> Result<Self, ImpactError> {
        if !(mass > 0.0 && mass.is_finite()) {
            return Err(ImpactError::Value {
                input: Input::Mass,
                what: "a body's mass",
                value: mass,
                must_be: "positive and finite",
            });
        }
        if !(inertia >= 0.0 && inertia.is_finite()) {
            return Err(ImpactError::Value {
                input: Input::Inertia,
                what: "a body's moment of inertia",
                value: inertia,
                must_be: "zero (a point) or positive, and finite",
            });
        }
        let state = [position[0], position[1], velocity[0], velocity[1], omega];
        if let Some(bad) = state.iter().find(|v| !v.is_finite()) {
            return Err(ImpactError::Value {
                input: Input::Velocity,
                what: "a body's position, velocity or ω",
                value: *bad,
                must_be: "finite",
            });
        }
        Ok(Self {
            mass,
            inertia,
            position,
            velocity,
            omega,
        })
    }

    /// The immovable ground (or a wall): infinite mass and inertia, at rest.
    pub fn fixed(position: [Real; 2]) -> Self {
        Self {
            mass: Real::INFINITY,
            inertia: Real::INFINITY,
            position,
            velocity: [0.0; 2],
            omega: 0.0,
        }
    }

    /// Whether it is immovable.
    pub fn is_fixed(&self) -> bool {
        self.mass.is_infinite()
    }

    /// The velocity of its material point at `p`: v + ω × (p − x).
    pub fn velocity_at(&self, p: [Real; 2]) -> [Real; 2] {
        let w = spin(
            self.omega,
            [p[0] - self.position[0], p[1] - self.position[1]],
        );
        [self.velocity[0] + w[0], self.velocity[1] + w[1]]
    }

    /// Kinetic energy ½ m v² + ½ I ω² (zero for an immovable body).
    pub fn kinetic_energy(&self) -> Real {
        if self.is_fixed() {
            return 0.0;
        }
        let v = self.velocity;
        0.5 * self.mass * (v[0] * v[0] + v[1] * v[1]) + 0.5 * self.inertia * self.omega * self.omega
    }

    /// Linear momentum (zero for an immovable body: it is not counted).
    pub fn momentum(&self) -> [Real; 2] {
        if self.is_fixed() {
            return [0.0; 2];
        }
        [self.mass * self.velocity[0], self.mass * self.velocity[1]]
    }

    /// Angular momentum about the point `q`: I ω + (x − q) × m v (zero for an immovable
    /// body).
    pub fn angular_momentum(&self, q: [Real; 2]) -> Real {
        if self.is_fixed() {
            return 0.0;
        }
        let r = [self.position[0] - q[0], self.position[1] - q[1]];
        self.inertia * self.omega + cross(r, self.momentum())
    }

    /// 1/m and 1/I for the impulse response at arm `arm` (r × n), checking zero inertia.
    fn inverses(&self, arm: Real, which: &'static str) -> Result<(Real, Real), ImpactError> {
        if self.is_fixed() {
            return Ok((0.0, 0.0));
        }
        if self.inertia == 0.0 {
            if arm.abs() > 1e-12 * (1.0 + self.position[0].hypot(self.position[1])) {
                return Err(ImpactError::ZeroInertia { which });
            }
            return Ok((1.0 / self.mass, 0.0));
        }
        Ok((1.0 / self.mass, 1.0 / self.inertia))
    }
}

/// The result of [`impact()`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FreeImpact {
    /// The first body after.
    pub a: PlanarBody,
    /// The second body after.
    pub b: PlanarBody,
    /// The impulse on the second body along the normal, J (N s); the first receives −J n.
    pub impulse: Real,
    /// The effective mass along the normal (kg).
    pub effective_mass: Real,
    /// The normal relative velocity (v_B − v_A)·n at the contact before (negative) and after.
    pub normal_speed: (Real, Real),
    /// Kinetic energy before and after (J).
    pub kinetic: (Real, Real),
    /// The closed-form change, −½ (1 − e²) m_eff u² (J).
    pub kinetic_change_exact: Real,
    /// Total linear momentum of the movable bodies before and after (kg m/s).
    pub momentum: ([Real; 2], [Real; 2]),
    /// Total angular momentum about the origin before and after (kg m²/s).
    pub angular_momentum_origin: (Real, Real),
    /// Total angular momentum about the contact point before and after (kg m²/s): conserved
    /// even against the ground.
    pub angular_momentum_contact: (Real, Real),
}

/// Body `a` and body `b` collide at `contact` (the normal from `a` into `b`), frictionless.
///
/// ```
/// use mechkit::rigid::impact::{Contact, PlanarBody, impact};
/// // a rod (m, L) falling flat at speed v lands on one end (e = 0): ω = 3v/(2L), the centre
/// // of mass keeps 3v/4
/// let (m, l, v) = (2.0, 1.0, 4.0);
/// let rod = PlanarBody::new(m, m * l * l / 12.0, [0.0, 0.0], [0.0, -v], 0.0).unwrap();
/// let ground = PlanarBody::fixed([-0.5, -1.0]);
/// let end = Contact { point: [-0.5, 0.0], normal: [0.0, 1.0], restitution: 0.0 };
/// let r = impact(&ground, &rod, &end).unwrap();
/// assert!((r.b.omega - (-1.5 * v / l)).abs() < 1e-14);
/// assert!((r.b.velocity[1] + 0.75 * v).abs() < 1e-14);
/// ```
pub fn impact(
    a: &PlanarBody,
    b: &PlanarBody,
    contact: &Contact,
) -> Result<FreeImpact, ImpactError> {
    let c = contact.checked()?;
    if a.is_fixed() && b.is_fixed() {
        return Err(ImpactError::BothFixed);
    }
    let (p, n) = (c.point, c.normal);
    let ra = [p[0] - a.position[0], p[1] - a.position[1]];
    let rb = [p[0] - b.position[0], p[1] - b.position[1]];
    let (arm_a, arm_b) = (cross(ra, n), cross(rb, n));
    let (ima, iia) = a.inverses(arm_a, "the first body")?;
    let (imb, iib) = b.inverses(arm_b, "the second body")?;
    let m_eff = 1.0 / (ima + imb + arm_a * arm_a * iia + arm_b * arm_b * iib);
    let rel = |a: &PlanarBody, b: &PlanarBody| {
        let (va, vb) = (a.velocity_at(p), b.velocity_at(p));
        (vb[0] - va[0]) * n[0] + (vb[1] - va[1]) * n[1]
    };
    let u = rel(a, b);
    if u >= 0.0 {
        return Err(ImpactError::Separating { normal_speed: u });
    }
    let j = -(1.0 + c.restitution) * m_eff * u;
    let kick = |body: &PlanarBody, s: Real, im: Real, ii: Real, arm: Real| PlanarBody {
        velocity: [
            body.velocity[0] + s * j * n[0] * im,
            body.velocity[1] + s * j * n[1] * im,
        ],
        omega: body.omega + s * j * arm * ii,
        ..*body
    };
    let a1 = kick(a, -1.0, ima, iia, arm_a);
    let b1 = kick(b, 1.0, imb, iib, arm_b);
    let sum = |x: [Real; 2], y: [Real; 2]| [x[0] + y[0], x[1] + y[1]];
    let ang = |x: &PlanarBody, y: &PlanarBody, q: [Real; 2]| {
        x.angular_momentum(q) + y.angular_momentum(q)
    };
    Ok(FreeImpact {
        a: a1,
        b: b1,
        impulse: j,
        effective_mass: m_eff,
        normal_speed: (u, rel(&a1, &b1)),
        kinetic: (
            a.kinetic_energy() + b.kinetic_energy(),
            a1.kinetic_energy() + b1.kinetic_energy(),
        ),
        kinetic_change_exact: -0.5 * (1.0 - c.restitution * c.restitution) * m_eff * u * u,
        momentum: (
            sum(a.momentum(), b.momentum()),
            sum(a1.momentum(), b1.momentum()),
        ),
        angular_momentum_origin: (ang(a, b, [0.0; 2]), ang(&a1, &b1, [0.0; 2])),
        angular_momentum_contact: (ang(a, b, p), ang(&a1, &b1, p)),
    })
}

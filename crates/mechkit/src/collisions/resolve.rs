//! Resolving one collision of two bodies by an impulse along the contact normal, with a
//! coefficient of restitution and, optionally, Coulomb friction along the contact plane.
//!
//! Body 1 meets body 2 along the unit normal `n` pointing from 1 to 2. With the relative
//! velocity `u = v1 - v2`, they approach when `u_n = u·n > 0`. The normal impulse on body 2 is
//! `J_n = (1 + e) μ u_n` (and `-J_n` on body 1), `μ = m1 m2/(m1 + m2)` the reduced mass (`m1`
//! when body 2 is immovable, `m2 = ∞`): it reverses the normal approach speed times `e`,
//! exactly, which is what the textbook's `v' = -e v` says. With friction coefficient `μ_f`, the
//! tangential impulse that would stop the sliding is `μ |u_t|`; if it is at most `μ_f J_n` the
//! contact sticks (tangential relative velocity zero), else it slides with `μ_f J_n` against
//! the sliding. The bodies are particles (no spin); rolling spheres belong to rigid bodies.
//!
//! The coefficient of restitution is checked by [`Restitution`] (`resolve/restitution.rs`);
//! what cannot be resolved is a [`CollisionError`] (`resolve/error.rs`).

mod error;
mod restitution;
mod scale;

pub use error::CollisionError;
pub use restitution::Restitution;

use super::{CmFrame, Collided, VelocityPair};
use crate::Real;

/// Two bodies about to collide.
#[derive(Debug, Clone, PartialEq)]
pub struct Collision {
    /// Mass of body 1 (kg).
    pub m1: Real,
    /// Mass of body 2 (kg; `inf` for a wall).
    pub m2: Real,
    /// Velocity of body 1 (1 to 3 components).
    pub v1: Vec<Real>,
    /// Velocity of body 2.
    pub v2: Vec<Real>,
    /// Contact normal from body 1 to body 2 (normalised here).
    pub normal: Vec<Real>,
    /// Coefficient of restitution.
    pub restitution: Restitution,
    /// Coulomb friction coefficient along the contact plane (0: frictionless).
    pub friction: Real,
}

/// What a resolved collision did: the same value as the report's [`Collided`] (the collision
/// it resolved, the velocities, impulse and energies after, the centre-of-mass frame), without
/// a rise until [`Collided::with_rise`] adds one.
pub type Outcome = Collided;

/// The result: resolved, or no collision because the bodies already separate.
#[derive(Debug, Clone, PartialEq)]
pub enum Resolution {
    /// They approached; the impulse was applied.
    Collided(Box<Outcome>),
    /// They do not approach along the normal (`u·n ≤ 0`): nothing happens.
    Separating {
        /// `u·n`, the (non-positive) approach speed.
        approach_speed: Real,
    },
}

fn dot(a: &[Real], b: &[Real]) -> Real {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

impl Collision {
    /// A head-on collision in 1-D (body 2 ahead of body 1 along +x).
    pub fn head_on(m1: Real, v1: Real, m2: Real, v2: Real, e: Restitution) -> Self {
        Self {
            m1,
            m2,
            v1: vec![v1],
            v2: vec![v2],
            normal: vec![1.0],
            restitution: e,
            friction: 0.0,
        }
    }

    /// The normal of two spheres at `r1` and `r2`: `(r2 - r1)/|r2 - r1|`.
    pub fn normal_between(r1: &[Real], r2: &[Real]) -> Result<Vec<Real>, CollisionError> {
        if r1.len() != r2.len() {
            return Err(CollisionError::Dimension);
        }
        let d: Vec<Real> = r2.iter().zip(r1).map(|(a, b)| a - b).collect();
        let len = dot(&d, &d).sqrt();
        if !(len > 0.0 && len.is_finite()) {
            return Err(CollisionError::ZeroNormal);
        }
        Ok(d.iter().map(|x| x / len).collect())
    }

    /// Applies the impulse.
    ///
    /// ```
    /// use mechkit::collisions::{Collision, Resolution, Restitution};
    /// // a 0.2 kg ball at 15 m/s into a 1.5 kg block at rest, sticking together
    /// let c = Collision::head_on(0.2, 15.0, 1.5, 0.0, Restitution::PERFECTLY_INELASTIC);
    /// let Resolution::Collided(out) = c.resolve().unwrap() else { unreachable!() };
    /// assert!((out.v1[0] - 3.0 / 1.7).abs() < 1e-15 && (out.v2[0] - 3.0 / 1.7).abs() < 1e-15);
    /// assert!((out.normal_impulse - 1.5 * 3.0 / 1.7).abs() < 1e-14);
    /// ```
    ///
    /// The arithmetic is done on velocities and masses scaled by powers of two to at most 1
    /// (exact), and the results scaled back: velocities near ±1e308 give their exact answer
    /// instead of an overflow in `v1 − v2` or `m·v`; a result that is not representable (the
    /// kinetic energy of 1 kg at 1e200 m/s) is infinite, which the front refuses.
    pub fn resolve(&self) -> Result<Resolution, CollisionError> {
        self.check()?;
        let (scaled, k) = scale::scaled(self);
        Ok(match scaled.resolve_scaled()? {
            Resolution::Collided(mut out) => {
                scale::unscale(&mut out, self, k);
                Resolution::Collided(out)
            }
            Resolution::Separating { approach_speed } => Resolution::Separating {
                approach_speed: approach_speed * k.velocity,
            },
        })
    }

    /// The checks of the input that [`Collision::resolve`] makes before anything is computed.
    fn check(&self) -> Result<(), CollisionError> {
        let d = self.normal.len();
        if !(1..=3).contains(&d) || self.v1.len() != d || self.v2.len() != d {
            return Err(CollisionError::Dimension);
        }
        for (which, m) in [(1, self.m1), (2, self.m2)] {
            if m.is_nan() || m <= 0.0 {
                return Err(CollisionError::Mass { which, mass: m });
            }
        }
        if self.m1.is_infinite() && self.m2.is_infinite() {
            return Err(CollisionError::BothImmovable);
        }
        if self.friction.is_nan() || self.friction < 0.0 {
            return Err(CollisionError::Friction { mu: self.friction });
        }
        if !self
            .v1
            .iter()
            .chain(&self.v2)
            .chain(&self.normal)
            .all(|x| x.is_finite())
        {
            return Err(CollisionError::NotFinite);
        }
        Ok(())
    }

    /// [`Collision::resolve`] on velocities and masses of order 1 at most.
    fn resolve_scaled(&self) -> Result<Resolution, CollisionError> {
        let d = self.normal.len();
        if !(1..=3).contains(&d) || self.v1.len() != d || self.v2.len() != d {
            return Err(CollisionError::Dimension);
        }
        for (which, m) in [(1, self.m1), (2, self.m2)] {
            if m.is_nan() || m <= 0.0 {
                return Err(CollisionError::Mass { which, mass: m });
            }
        }
        if self.m1.is_infinite() && self.m2.is_infinite() {
            return Err(CollisionError::BothImmovable);
        }
        if self.friction.is_nan() || self.friction < 0.0 {
            return Err(CollisionError::Friction { mu: self.friction });
        }
        if !self
            .v1
            .iter()
            .chain(&self.v2)
            .chain(&self.normal)
            .all(|x| x.is_finite())
        {
            return Err(CollisionError::NotFinite);
        }
        // the normal's length, scaled so that its square neither overflows nor underflows
        let big = self.normal.iter().fold(0.0, |m: Real, x| m.max(x.abs()));
        if big == 0.0 {
            return Err(CollisionError::ZeroNormal);
        }
        let unit: Vec<Real> = self.normal.iter().map(|x| x / big).collect();
        let len = dot(&unit, &unit).sqrt();
        let n: Vec<Real> = unit.iter().map(|x| x / len).collect();
        let u: Vec<Real> = self.v1.iter().zip(&self.v2).map(|(a, b)| a - b).collect();
        let un = dot(&u, &n);
        if un <= 0.0 {
            return Ok(Resolution::Separating { approach_speed: un });
        }
        let (w1, w2) = (1.0 / self.m1, 1.0 / self.m2); // 0 for an immovable body
        let reduced = 1.0 / (w1 + w2);
        let e = self.restitution.value();
        let jn = (1.0 + e) * reduced * un;
        // tangential relative velocity and the friction impulse against it
        let ut: Vec<Real> = u.iter().zip(&n).map(|(ui, ni)| ui - un * ni).collect();
        let ut_len = dot(&ut, &ut).sqrt();
        let (jt, sticks) = if self.friction > 0.0 && ut_len > 0.0 {
            let stop = reduced * ut_len;
            let limit = self.friction * jn;
            if stop <= limit {
                (stop, Some(true))
            } else {
                (limit, Some(false))
            }
        } else {
            (0.0, None)
        };
        // Normal velocities after, from the centre of mass: v' = v_cm - e (v - v_cm) along n.
        // Written this way, e = 0 leaves exactly equal normal velocities.
        let (v1n, v2n) = (dot(&self.v1, &n), dot(&self.v2, &n));
        let cm_n = if self.m2.is_infinite() {
            v2n
        } else if self.m1.is_infinite() {
            v1n
        } else {
            (self.m1 * v1n + self.m2 * v2n) / (self.m1 + self.m2)
        };
        let after_n = |vn: Real, w: Real| if w == 0.0 { vn } else { cm_n - e * (vn - cm_n) };
        let (v1n_after, v2n_after) = (after_n(v1n, w1), after_n(v2n, w2));
        let t: Vec<Real> = ut
            .iter()
            .map(|x| if ut_len > 0.0 { x / ut_len } else { 0.0 })
            .collect();
        let v1: Vec<Real> = (0..d)
            .map(|i| (self.v1[i] - v1n * n[i]) + v1n_after * n[i] - w1 * jt * t[i])
            .collect();
        let v2: Vec<Real> = (0..d)
            .map(|i| (self.v2[i] - v2n * n[i]) + v2n_after * n[i] + w2 * jt * t[i])
            .collect();
        // the impulse on body 2: along n, and along the sliding of 1 relative to 2
        let impulse: Vec<Real> = (0..d).map(|i| jn * n[i] + jt * t[i]).collect();
        let kinetic = |m: Real, v: &[Real]| {
            if m.is_infinite() {
                0.0
            } else {
                0.5 * m * dot(v, v)
            }
        };
        let v_cm: Vec<Real> = (0..d)
            .map(|i| {
                if self.m2.is_infinite() {
                    self.v2[i]
                } else if self.m1.is_infinite() {
                    self.v1[i]
                } else {
                    (self.m1 * self.v1[i] + self.m2 * self.v2[i]) / (self.m1 + self.m2)
                }
            })
            .collect();
        let rel = |v: &[Real]| v.iter().zip(&v_cm).map(|(a, c)| a - c).collect::<Vec<_>>();
        let separation = -dot(
            &v1.iter().zip(&v2).map(|(a, b)| a - b).collect::<Vec<_>>(),
            &n,
        );
        // with an immovable body the energies are those in its frame (the centre-of-mass
        // frame), where it does no work; in another frame it would do work on the other body
        // (a moving wall speeds a ball up) and the ledger would not balance
        let (kinetic_before, kinetic_after) = if self.m1.is_infinite() || self.m2.is_infinite() {
            (
                kinetic(self.m1, &rel(&self.v1)) + kinetic(self.m2, &rel(&self.v2)),
                kinetic(self.m1, &rel(&v1)) + kinetic(self.m2, &rel(&v2)),
            )
        } else {
            (
                kinetic(self.m1, &self.v1) + kinetic(self.m2, &self.v2),
                kinetic(self.m1, &v1) + kinetic(self.m2, &v2),
            )
        };
        Ok(Resolution::Collided(Box::new(Collided {
            collided: true,
            m1: self.m1,
            m2: self.m2,
            restitution: e,
            friction: self.friction,
            v1_before: self.v1.clone(),
            v2_before: self.v2.clone(),
            cm_frame: CmFrame {
                before: VelocityPair {
                    v1: rel(&self.v1),
                    v2: rel(&self.v2),
                },
                after: VelocityPair {
                    v1: rel(&v1),
                    v2: rel(&v2),
                },
            },
            v1,
            v2,
            impulse,
            normal_impulse: jn,
            tangential_impulse: jt,
            sticks,
            approach_speed: un,
            separation_speed: separation,
            kinetic_before,
            kinetic_after,
            kinetic_lost: kinetic_before - kinetic_after,
            v_cm,
            rise: None,
        })))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn collided(c: &Collision) -> Outcome {
        match c.resolve().unwrap() {
            Resolution::Collided(o) => *o,
            Resolution::Separating { .. } => panic!("expected a collision"),
        }
    }

    #[test]
    fn elastic_head_on_textbook_formulas() {
        // v1' = (m1 - m2)/(m1 + m2) v1, v2' = 2 m1/(m1 + m2) v1 for v2 = 0
        let (m1, m2, v) = (1.0, 2.0, 3.0);
        let o = collided(&Collision::head_on(m1, v, m2, 0.0, Restitution::ELASTIC));
        assert!((o.v1[0] - (m1 - m2) / (m1 + m2) * v).abs() < 1e-15);
        assert!((o.v2[0] - 2.0 * m1 / (m1 + m2) * v).abs() < 1e-15);
        assert!(o.kinetic_lost.abs() < 1e-15);
        // in the CM frame each velocity is reversed
        let (before, after) = (&o.cm_frame.before, &o.cm_frame.after);
        assert!((after.v1[0] + before.v1[0]).abs() < 1e-15);
        assert!((after.v2[0] + before.v2[0]).abs() < 1e-15);
    }

    #[test]
    fn a_wall_reverses_the_normal_velocity_times_e() {
        let e = Restitution::new(0.8).unwrap();
        let c = Collision {
            m1: 0.5,
            m2: Real::INFINITY,
            v1: vec![3.0, -4.0],
            v2: vec![0.0, 0.0],
            normal: vec![0.0, -1.0],
            restitution: e,
            friction: 0.0,
        };
        let o = collided(&c);
        assert_eq!(o.v1, vec![3.0, 0.8 * 4.0]);
        assert_eq!(o.v2, vec![0.0, 0.0]);
        assert!((o.separation_speed - 0.8 * o.approach_speed).abs() < 1e-15);
    }

    #[test]
    fn a_moving_immovable_body_books_the_energy_in_its_own_frame() {
        // a wall at 15 m/s hits a ball at rest elastically: the ball leaves at 30 m/s; in the
        // wall's frame it comes at 15 m/s and leaves at 15 m/s, so nothing is lost
        let o = collided(&Collision::head_on(
            Real::INFINITY,
            15.0,
            1.0,
            0.0,
            Restitution::ELASTIC,
        ));
        assert_eq!(o.v2, vec![30.0]);
        assert_eq!((o.kinetic_before, o.kinetic_after), (112.5, 112.5));
        assert_eq!(o.kinetic_lost, 0.0);
        // half elastic: 112.5 J -> 28.125 J in the wall's frame
        let o = collided(&Collision::head_on(
            1.0,
            0.0,
            Real::INFINITY,
            -15.0,
            Restitution::new(0.5).unwrap(),
        ));
        assert_eq!(o.kinetic_lost, 112.5 - 28.125);
    }

    #[test]
    fn separating_bodies_do_not_collide() {
        let c = Collision::head_on(1.0, -1.0, 1.0, 1.0, Restitution::ELASTIC);
        assert_eq!(
            c.resolve().unwrap(),
            Resolution::Separating {
                approach_speed: -2.0
            }
        );
    }

    #[test]
    fn friction_sticks_or_slides() {
        let base = Collision {
            m1: 1.0,
            m2: Real::INFINITY,
            v1: vec![1.0, -1.0],
            v2: vec![0.0, 0.0],
            normal: vec![0.0, -1.0],
            restitution: Restitution::new(0.5).unwrap(),
            friction: 1.0,
        };
        // J_n = 1.5, stopping the 1 m/s slide takes 1 ≤ μ J_n: sticks
        let o = collided(&base);
        assert_eq!(o.sticks, Some(true));
        assert!(o.v1[0].abs() < 1e-15 && (o.v1[1] - 0.5).abs() < 1e-15);
        // μ = 0.2: slides, losing μ J_n = 0.3 of its tangential speed
        let o = collided(&Collision {
            friction: 0.2,
            ..base
        });
        assert_eq!(o.sticks, Some(false));
        assert!((o.v1[0] - 0.7).abs() < 1e-15);
    }

    /// Issue 26: at ±1e308 the relative velocity and the momenta overflowed, and the
    /// velocities after came out 0 or NaN. They are exact now; the energies, which are not
    /// representable, are infinite (refused by the fronts' finiteness rule).
    #[test]
    fn issue_026_velocities_near_the_largest_double_are_resolved_exactly() {
        let big = 1e308;
        let o = collided(&Collision::head_on(
            1.0,
            big,
            1.0,
            -big,
            Restitution::ELASTIC,
        ));
        assert_eq!((o.v1[0], o.v2[0]), (-big, big));
        // 2e308 is not a double: an answer the fronts refuse, not a wrong one
        assert!(o.approach_speed.is_infinite());
        let o = collided(&Collision::head_on(
            2.0,
            big,
            2.0,
            0.0,
            Restitution::ELASTIC,
        ));
        assert_eq!((o.v1[0], o.v2[0]), (0.0, big));
        assert_eq!(o.normal_impulse, 2.0 * big);
        assert!(o.kinetic_before.is_infinite());
        // huge masses: the velocities are those of equal masses
        let o = collided(&Collision::head_on(
            1e308,
            1.0,
            1e308,
            0.0,
            Restitution::ELASTIC,
        ));
        assert_eq!((o.v1[0], o.v2[0]), (0.0, 1.0));
        assert_eq!(o.kinetic_before, 0.5e308);
        // tiny values are kept too
        let o = collided(&Collision::head_on(
            1.0,
            1e-300,
            1.0,
            0.0,
            Restitution::ELASTIC,
        ));
        assert_eq!((o.v1[0], o.v2[0]), (0.0, 1e-300));
        // the same answers as before for ordinary values
        let o = collided(&Collision::head_on(
            0.2,
            15.0,
            1.5,
            0.0,
            Restitution::PERFECTLY_INELASTIC,
        ));
        assert!((o.v1[0] - 3.0 / 1.7).abs() < 1e-15);
    }

    #[test]
    fn bad_input() {
        assert!(Restitution::new(1.2).is_err() && Restitution::new(-0.1).is_err());
        assert!(Restitution::parse("inelastic").is_err());
        assert_eq!(Restitution::parse("plastic").unwrap().value(), 0.0);
        let mut c = Collision::head_on(0.0, 1.0, 1.0, 0.0, Restitution::ELASTIC);
        assert!(matches!(
            c.resolve(),
            Err(CollisionError::Mass { which: 1, .. })
        ));
        c.m1 = 1.0;
        c.normal = vec![0.0];
        assert_eq!(c.resolve(), Err(CollisionError::ZeroNormal));
        assert!(Collision::normal_between(&[1.0, 1.0], &[1.0, 1.0]).is_err());
    }
}

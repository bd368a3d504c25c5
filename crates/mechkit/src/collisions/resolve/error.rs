//! Why a collision cannot be resolved ([`CollisionError`]), each error naming the input at
//! fault ([`CollisionError::input`]) so that a front can point at its own field.

use thiserror::Error;

use crate::Real;
use crate::collisions::CollisionInput;

/// Why a collision cannot be resolved.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum CollisionError {
    /// A mass that is not positive (or NaN).
    #[error(
        "mass {which} is {}; masses must be positive (use `inf` for an immovable wall)",
        crate::error::short(*mass)
    )]
    Mass {
        /// 1 or 2.
        which: usize,
        /// The value.
        mass: Real,
    },
    /// Both masses infinite.
    #[error("both bodies are immovable (infinite mass); at least one must have a finite mass")]
    BothImmovable,
    /// `e` outside `[0, 1]`.
    #[error(
        "the coefficient of restitution is {}; it must be between 0 (perfectly inelastic) and 1 (elastic)",
        crate::error::short(*e)
    )]
    Restitution {
        /// The value.
        e: Real,
    },
    /// Not a number or a preset.
    #[error(
        "`{text}` is not a coefficient of restitution: give a number from 0 to 1, or elastic (1) or perfectly-inelastic (0); an inelastic collision needs its e, e.g. 0.5"
    )]
    RestitutionName {
        /// What was given.
        text: String,
    },
    /// A negative or NaN friction coefficient.
    #[error("the friction coefficient is {}; it must be zero or positive", crate::error::short(*mu))]
    Friction {
        /// The value.
        mu: Real,
    },
    /// The normal has zero length, or the bodies are at the same point.
    #[error("the contact normal has zero length (or the two centres coincide); give a direction")]
    ZeroNormal,
    /// Velocities and normal of different dimensions, or not 1 to 3.
    #[error("the velocities and the normal must all have 1, 2 or 3 components, the same number")]
    Dimension,
    /// A value is not finite.
    #[error("a velocity or normal component is not a finite number")]
    NotFinite,
    /// A vector with another number of components than the velocities.
    #[error("{}", components(*input, *got, *expected))]
    Components {
        /// The vector.
        input: CollisionInput,
        /// Its number of components.
        got: usize,
        /// The number wanted (that of the other vector).
        expected: usize,
    },
    /// A collision in 2-D or 3-D without its normal.
    #[error(
        "in {dim}-D the contact normal is needed: give the direction from body 1 to body 2, or the centres of the two spheres"
    )]
    NormalNeeded {
        /// The dimension of the velocities.
        dim: usize,
    },
    /// The two sphere centres are the same point.
    #[error(
        "the two centres coincide, so they give no direction from body 1 to body 2; give two different points"
    )]
    SameCentres,
    /// Sphere centres with different numbers of components.
    #[error(
        "the centre of sphere 1 has {} but that of sphere 2 has {}; give both with the same number",
        count(*r1),
        count(*r2)
    )]
    CentresDiffer {
        /// Components of the centre of sphere 1.
        r1: usize,
        /// Components of the centre of sphere 2.
        r2: usize,
    },
    /// A gravitational acceleration that is not positive.
    #[error(
        "the gravitational acceleration is {}; it must be positive, e.g. 9.81 m/s^2",
        crate::error::short(*g)
    )]
    Gravity {
        /// The value.
        g: Real,
    },
}

/// `1 component`, `2 components`.
fn count(n: usize) -> String {
    format!("{n} component{}", if n == 1 { "" } else { "s" })
}

/// The message of [`CollisionError::Components`].
fn components(input: CollisionInput, got: usize, expected: usize) -> String {
    if got == 0 || got > 3 {
        return format!("{input} has {}; give 1, 2 or 3", count(got));
    }
    match input {
        CollisionInput::Velocity1 | CollisionInput::Velocity2 => {
            let other = if input == CollisionInput::Velocity1 {
                CollisionInput::Velocity2
            } else {
                CollisionInput::Velocity1
            };
            format!(
                "{input} has {} but {other} has {expected}; give both with the same number of components (a single 0 is at rest)",
                count(got)
            )
        }
        _ => format!(
            "{input} has {} but the velocities have {expected}; give as many as they have",
            count(got)
        ),
    }
}

impl CollisionError {
    /// The input the error is about, when it is about one.
    pub fn input(&self) -> Option<CollisionInput> {
        Some(match self {
            Self::Mass { which: 1, .. } => CollisionInput::Mass1,
            Self::Mass { .. } | Self::BothImmovable => CollisionInput::Mass2,
            Self::Restitution { .. } | Self::RestitutionName { .. } => CollisionInput::Restitution,
            Self::Friction { .. } => CollisionInput::Friction,
            Self::ZeroNormal | Self::NormalNeeded { .. } => CollisionInput::Normal,
            Self::SameCentres | Self::CentresDiffer { .. } => CollisionInput::Centres,
            Self::Components { input, .. } => *input,
            Self::Gravity { .. } => CollisionInput::Gravity,
            Self::Dimension | Self::NotFinite => return None,
        })
    }
}

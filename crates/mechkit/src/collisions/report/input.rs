//! The inputs of a collision, as errors name them ([`CollisionInput`]): a front maps each to
//! its own flag or field.

/// The input of a collision that a [`CollisionError`](crate::collisions::CollisionError) is
/// about ([`CollisionError::input`](crate::collisions::CollisionError::input)),
/// so that a front can name its own field for it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum CollisionInput {
    /// The mass of body 1.
    Mass1,
    /// The mass of body 2.
    Mass2,
    /// The velocity of body 1.
    Velocity1,
    /// The velocity of body 2.
    Velocity2,
    /// The coefficient of restitution.
    Restitution,
    /// The contact normal.
    Normal,
    /// The centres of the two spheres (the normal from one to the other).
    Centres,
    /// The friction coefficient.
    Friction,
    /// The gravitational acceleration (for the rise after the collision).
    Gravity,
}

impl CollisionInput {
    /// The input as messages name it.
    pub fn name(self) -> &'static str {
        match self {
            Self::Mass1 => "the mass of body 1",
            Self::Mass2 => "the mass of body 2",
            Self::Velocity1 => "the velocity of body 1",
            Self::Velocity2 => "the velocity of body 2",
            Self::Restitution => "the coefficient of restitution",
            Self::Normal => "the normal",
            Self::Centres => "the centres of the spheres",
            Self::Friction => "the friction coefficient",
            Self::Gravity => "the gravitational acceleration",
        }
    }
}

impl std::fmt::Display for CollisionInput {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

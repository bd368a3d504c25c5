//! The inputs of the rotation and rigid-body models, named so that an error can say which
//! input caused it without a front searching its message (as [`crate::inputs::Input`] does
//! for the one-question calculations): the command line maps an [`Input`] to its flag
//! (`Input::Radius` → `--radius`, or `--circle` for a bead), a Python front to its keyword.
//!
//! ```
//! use mechkit::rigid::Input;
//! use mechkit::rigid::kinematics::CircularMotion;
//! let e = CircularMotion::from_speed(10.0, -1.0).unwrap_err();
//! assert_eq!(e.input(), Some(Input::Radius));
//! ```

/// An input of a rigid-body or rotation model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize),
    serde(rename_all = "snake_case")
)]
#[non_exhaustive]
pub enum Input {
    /// A mass (of a body, a block, a rod).
    Mass,
    /// A radius (of a circle, a rolling body).
    Radius,
    /// A length (of a rod).
    Length,
    /// The angle of an incline or a slope.
    Angle,
    /// Gravity.
    Gravity,
    /// The static friction coefficient.
    StaticFriction,
    /// The dynamic friction coefficient.
    DynamicFriction,
    /// An extra load pressing into a surface.
    NormalLoad,
    /// An extra load along a surface.
    Push,
    /// A spring constant.
    SpringConstant,
    /// The speed of a belt under a block.
    BeltSpeed,
    /// The speed of a spring's anchor.
    AnchorSpeed,
    /// A start position (or coordinate on a curve).
    StartPosition,
    /// A start speed.
    StartSpeed,
    /// A start angular velocity (spin).
    StartSpin,
    /// A height fallen from rest.
    DropHeight,
    /// How long to simulate.
    Duration,
    /// The integrator's tolerance.
    Tolerance,
    /// The integrator's fixed step.
    Step,
    /// The integration method.
    Method,
    /// An orientation.
    Orientation,
    /// The shape of a body (a preset name or an inertia factor).
    Body,
    /// A formula of a curve.
    Curve,
    /// The period of a circular motion.
    Period,
    /// A speed on a circle.
    Speed,
    /// An angular speed.
    AngularSpeed,
    /// A centripetal acceleration.
    Centripetal,
    /// An angular acceleration.
    AngularAcceleration,
    /// A latitude.
    Latitude,
    /// An angle to turn through.
    Turn,
    /// The angular velocity at the start of a uniform acceleration.
    InitialAngularVelocity,
    /// The angular velocity at its end.
    FinalAngularVelocity,
    /// The duration of a uniform acceleration.
    Time,
    /// θ at t = 0.
    InitialAngle,
    /// A moment of inertia.
    Inertia,
    /// Where a body is pivoted.
    Pivot,
    /// A centre of mass.
    CentreOfMass,
    /// An angular velocity before an impact.
    AngularVelocity,
    /// The angle a hinged body is released from.
    ReleaseAngle,
    /// The contact point of an impact.
    ContactPoint,
    /// The mass of the block (particle) struck.
    BlockMass,
    /// The velocity of the block before an impact.
    BlockVelocity,
    /// The velocity of a body's centre of mass before an impact.
    Velocity,
    /// The tilt of a body above the horizontal.
    Tilt,
    /// The contact normal of an impact.
    Normal,
    /// The coefficient of restitution.
    Restitution,
    /// The number of samples of an output grid ([`crate::sample_bound`]).
    Samples,
}

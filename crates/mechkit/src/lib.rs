//! # mechkit: computational classical mechanics
//!
//! Forces, integrators, energy ledgers and scenario files for the computational side of a
//! university mechanics course. All quantities are SI (m, kg, s, N, J).
//!
//! ## Quick start
//!
//! A feather falling with quadratic air resistance, stopped when it reaches the floor:
//!
//! ```
//! use mechkit::prelude::*;
//!
//! let (g, dmg, m) = (9.8, 4.0, 1e-3);
//! let system = ParticleSystem::builder(1)
//!     .body("feather", m)
//!     .force(UniformGravity::new("gravity", vec![0], g))
//!     .force(QuadraticDrag::new("air", vec![Target::new(0, m * g * dmg)]))
//!     .build()
//!     .unwrap();
//! let report = Simulation::new(&system, Method::EulerCromer, 1e-3)
//!     .t_max(10.0)
//!     .stop_when(Condition::below(0, 0, 0.0)) // feather.x < 0
//!     .run(State::from_qv(0.0, &[2.4], &[0.0]), &mut [])
//!     .unwrap();
//! let landing = report.event.as_ref().unwrap();
//! assert!((landing.t - 4.8354).abs() < 1e-3);       // exact: 4.8354 s
//! assert!((landing.last_step.t - 4.834).abs() < 1e-9); // the textbook loop's last step
//! // The work of gravity and of the air, measured along the path, add up to ΔK:
//! let gravity = report.ledger.work_of("gravity").unwrap();
//! assert!(report.ledger.work_energy_residual().abs() < 1e-4 * gravity);
//! ```
//!
//! ## Modules
//! - [`ode`]: systems, states, and the fixed-step methods (Euler, Euler-Cromer, velocity
//!   Verlet, RK4).
//! - [`particles`]: bodies in 1-3 dimensions, the names formulas use for their state.
//! - [`forces`]: gravity, springs, drag with wind, constant and formula forces, contact
//!   forces of overlapping spheres and walls.
//! - [`collisions`]: two bodies colliding with restitution and friction.
//! - [`rocket`]: variable mass: the rocket equation (Tsiolkovsky's Δv, burn and coast in
//!   uniform gravity in closed form) and a simulation with quadratic drag.
//! - [`energy`]: the energy ledger (work of each force, kinetic and potential energy);
//!   potentials, energy diagrams, equilibria and turning points; line integrals of force
//!   fields; constant-power motion.
//! - [`elliptic`]: complete and incomplete elliptic integrals of the first kind and Jacobi's
//!   elliptic functions (the AGM, Landen, Carlson): the exact pendulum and free-body periods.
//! - [`figure`]: plot data (curves, markers, bands) for the command line to draw.
//! - [`mass`]: point-mass systems (centre of mass, momentum, the centre-of-mass frame), and
//!   rigid bodies: mass, centre of mass and inertia tensor of shapes, polygons, triangle
//!   meshes, composites with holes, and the body in a photo ([`mass::image`]).
//! - [`md`]: many-particle molecular dynamics: Lennard-Jones and other cut-off pair
//!   potentials, cell and neighbour lists, periodic boxes, lattices, velocity Verlet on threads.
//! - [`rigid`]: rotation and rigid bodies: angular kinematics and circular motion, Coulomb
//!   friction and stick-slip, a body on a curve leaving it where the normal force vanishes,
//!   bodies hinged to the world (the physical pendulum, the Atwood machine with a massive
//!   pulley, flywheels; `[[rigid_body]]` in scenarios), rolling and slipping on a slope, rigid
//!   impacts, and free 3-D bodies and tops (quaternions, Euler's equations).
//! - [`function`]: a formula with parameter values, evaluated as a function.
//! - [`inputs`]: the inputs of the one-question calculations, named in their errors.
//! - [`simulate`]: the run loop: stop conditions located between steps, observers, divergence
//!   diagnosis.
//! - [`roots`]: Brent's method; every root on an interval.
//! - [`calculus`]: derivatives, integrals (closed form and quadrature), equations, units.
//! - [`quad`]: quadrature of functions (adaptive Gauss-Kronrod; the fixed rules of a course,
//!   Gauss-Legendre) and of sampled data (trapezoid, Simpson, running integrals).
//! - [`data`]: measured data files (columns of numbers, optional header) with line numbers in
//!   every error.
//! - [`deriv`]: derivatives of sampled data (finite differences, Savitzky-Golay) and of
//!   functions (Ridders' extrapolation).
//! - [`scenario`] (feature `scenario`): TOML scenario files → model → run → summary.
//! - [`units`]: re-export of the unit system of `mechkit-expr`.

pub mod animation;
pub mod calculus;
pub mod collisions;
pub mod csv;
pub mod data;
pub mod deriv;
pub mod elliptic;
pub mod energy;
mod error;
pub mod figure;
#[cfg(feature = "serde")]
pub mod finite;
pub mod forces;
pub mod function;
pub mod inputs;
pub mod mass;
pub mod md;
pub mod ode;
pub mod particles;
pub mod quad;
pub mod relative;
pub mod report;
pub mod rigid;
pub mod rocket;
pub mod roots;
pub mod sample_bound;
#[cfg(feature = "scenario")]
pub mod scenario;
pub mod simulate;
pub mod values;

pub use error::{Error, invertible};
pub use mechkit_expr as expr;
pub use mechkit_expr::interval;
pub use mechkit_expr::units;

/// The real number type used throughout.
pub type Real = f64;

/// The names most programs need.
pub mod prelude {
    pub use crate::Real;
    pub use crate::forces::{
        ConstantForce, ExpressionForce, Force, LinearDrag, NewtonianGravity, QuadraticDrag, Spring,
        SpringEnds, Target, UniformGravity, Wind,
    };
    pub use crate::ode::{AdaptiveConfig, Method, MethodKind, State, Tolerance};
    pub use crate::particles::ParticleSystem;
    pub use crate::simulate::{Condition, Direction, Event, Simulation, Stepping, StopReason};
}

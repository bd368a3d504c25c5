//! Elastic disks in a walled box, the collision tests' workload: shared by the `lib` target's
//! collision tests and the `billiards` target (a release-build acceptance run).

use mechkit::collisions::{Impacts, Restitution, Wall};
use mechkit::ode::State;
use mechkit::particles::{ParticleSystem, Sample};
use mechkit::prelude::*;
use mechkit::simulate::{Observer, ObserverError};

/// The smallest gap between two disks, relative to the radius, over every sample.
struct GapWatch {
    radius: f64,
    worst: f64,
}

impl Observer for GapWatch {
    fn observe(&mut self, s: &Sample<'_>) -> Result<(), ObserverError> {
        let n = s.q.len() / 2;
        for a in 0..n {
            for b in a + 1..n {
                let d = ((s.q[2 * a] - s.q[2 * b]).powi(2)
                    + (s.q[2 * a + 1] - s.q[2 * b + 1]).powi(2))
                .sqrt();
                self.worst = self.worst.min((d - 2.0 * self.radius) / self.radius);
            }
        }
        Ok(())
    }
}

/// `side × side` disks of `radius` on a grid in the unit box with its four walls, masses
/// cycling through `masses`, and pseudo-random velocities up to `speed`/2 per component.
pub struct Box2d {
    sys: ParticleSystem,
    impacts: Impacts,
    q: Vec<f64>,
    v: Vec<f64>,
}

pub fn disks_in_a_box(side: usize, radius: f64, masses: &[f64], speed: f64, seed: u64) -> Box2d {
    let n = side * side;
    let mut builder = ParticleSystem::builder(2);
    let (mut q, mut v) = (Vec::new(), Vec::new());
    let mut seed = seed;
    let mut rnd = || {
        seed = seed
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    };
    let cell = 1.0 / side as f64;
    for i in 0..n {
        builder = builder.body(format!("d{i}"), masses[i % masses.len()]);
        q.extend([
            cell * (0.5 + (i % side) as f64),
            cell * (0.5 + (i / side) as f64),
        ]);
        v.extend([speed * rnd(), speed * rnd()]);
    }
    let sys = builder.build().unwrap();
    let names = (0..n).map(|i| format!("d{i}")).collect();
    let mut impacts = Impacts::new(2, names, sys.masses().to_vec(), vec![Some(radius); n]);
    for (name, p, nrm) in [
        ("left", [0.0, 0.0], [1.0, 0.0]),
        ("right", [1.0, 0.0], [-1.0, 0.0]),
        ("bottom", [0.0, 0.0], [0.0, 1.0]),
        ("top", [0.0, 1.0], [0.0, -1.0]),
    ] {
        impacts = impacts
            .with_wall(Wall::new(name, p.to_vec(), &nrm, Restitution::ELASTIC, 0.0).unwrap());
    }
    Box2d { sys, impacts, q, v }
}

impl Box2d {
    /// Runs with velocity Verlet steps of `dt` to `t_max`, checks that the kinetic energy is
    /// kept to 1e-9 and that no two disks overlap by more than 1e-9 of their radius at any
    /// sample, and returns the number of impacts.
    pub fn run_elastic(self, radius: f64, dt: f64, t_max: f64) -> usize {
        let mut sim = Simulation::new(&self.sys, Method::VelocityVerlet, dt).t_max(t_max);
        for e in self.impacts.events() {
            sim = sim.event(e);
        }
        let mut watch = GapWatch {
            radius,
            worst: f64::INFINITY,
        };
        let report = sim
            .run(State::from_qv(0.0, &self.q, &self.v), &mut [&mut watch])
            .unwrap();
        let (k0, k1) = (report.ledger.kinetic_start(), report.ledger.kinetic_end());
        assert!((k1 - k0).abs() <= 1e-9 * k0, "K {k0} -> {k1}");
        assert!(
            watch.worst >= -1e-9,
            "overlap {:e} of the radius",
            watch.worst
        );
        report.events.len()
    }
}

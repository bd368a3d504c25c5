use super::*;
use crate::forces::{
    ContactDamping, ContactForceBuilder, ContactLaw, NewtonianGravity, PairForce, QuadraticDrag,
    RadialPotential, Spring, SpringEnds, Target, UniformGravity,
};
use crate::ode::SecondOrderSystem;

/// Three bodies in a plane: a spring between two, one tied to an anchor, mutual gravity,
/// uniform gravity and quadratic drag.
fn system() -> ParticleSystem {
    ParticleSystem::builder(2)
        .body("a", 2.0)
        .body("b", 0.5)
        .body("c", 1.5)
        .force(Spring::new("ab", 300.0, 0.4, SpringEnds::Pair(0, 1)))
        .force(Spring::new(
            "anchor",
            50.0,
            0.2,
            SpringEnds::Anchor {
                bodies: vec![2],
                anchor: vec![0.1, -0.3],
            },
        ))
        .force(NewtonianGravity::mutual("grav", vec![0, 1, 2], 0.7))
        .force(UniformGravity::new("g", vec![0, 1, 2], 9.81))
        .force(QuadraticDrag::new(
            "air",
            vec![Target::new(0, 0.3), Target::new(2, 0.1)],
        ))
        .build()
        .unwrap()
}

/// `∂a/∂q` and `∂a/∂v` of `sys` at `(q, v)`, compiled, against central differences of
/// its accelerations with step `h`: within `tol` of the largest entry of each row.
fn matches_differences(sys: &ParticleSystem, q: &[f64], v: &[f64], h: f64, tol: f64) {
    let n = q.len();
    let jac = CompiledJacobian::build(sys).expect("every force emits");
    let (mut dq, mut dv) = (vec![0.0; n * n], vec![0.0; n * n]);
    assert!(jac.eval_into(0.4, q, v, &mut dq, &mut dv));
    let accel = |q: &[f64], v: &[f64]| {
        let mut a = vec![0.0; n];
        sys.accel_into(0.4, q, v, &mut a);
        a
    };
    for (block, exact) in [(0, &dq), (1, &dv)] {
        let mut fd = vec![0.0; n * n];
        for j in 0..n {
            let (mut qp, mut qm, mut vp, mut vm) = (q.to_vec(), q.to_vec(), v.to_vec(), v.to_vec());
            if block == 0 {
                qp[j] += h;
                qm[j] -= h;
            } else {
                vp[j] += h;
                vm[j] -= h;
            }
            let (ap, am) = (accel(&qp, &vp), accel(&qm, &vm));
            for i in 0..n {
                fd[i * n + j] = (ap[i] - am[i]) / (2.0 * h);
            }
        }
        for i in 0..n {
            let row = &fd[i * n..(i + 1) * n];
            let scale = row.iter().fold(1.0_f64, |m, x| m.max(x.abs()));
            for j in 0..n {
                let e = exact[i * n + j];
                assert!(
                    (e - row[j]).abs() < tol * scale,
                    "block {block}, ∂a{i}/∂{j} at q = {q:?}, v = {v:?}: {e} vs {}",
                    row[j]
                );
            }
        }
    }
    // the system hands it to the implicit methods
    let (mut dq2, mut dv2) = (vec![0.0; n * n], vec![0.0; n * n]);
    assert!(sys.accel_jacobian_into(0.4, q, v, &mut dq2, &mut dv2));
    assert_eq!((dq, dv), (dq2, dv2));
}

#[test]
fn the_compiled_jacobian_matches_central_differences() {
    let q = [0.3, 0.9, -0.2, 0.4, 1.1, -0.7];
    let v = [0.5, -1.2, 0.8, 0.1, -0.3, 2.0];
    matches_differences(&system(), &q, &v, 1e-6, 1e-6);
}

/// Three balls in a plane on a floor: Hertz contacts (pairs and the floor) with
/// Hunt-Crossley damping, a Lennard-Jones pair potential with a cut-off, gravity.
fn contact_system(law: ContactLaw, damping: ContactDamping) -> ParticleSystem {
    let contact = ContactForceBuilder::new(2)
        .law(law)
        .damping(damping)
        .spheres(&[(0, 0.25), (1, 0.375), (2, 0.25)])
        .wall(
            &[0.0, -1.0],
            &[0.2, 1.0],
            &[(0, 0.25), (1, 0.375), (2, 0.25)],
        )
        .build()
        .unwrap();
    let lj = RadialPotential::new(
        &mechkit_expr::parse("4*e*((s/r)^12 - (s/r)^6)")
            .unwrap()
            .expr,
        "r",
        &[("e".into(), 0.01), ("s".into(), 0.5)],
    )
    .unwrap()
    .with_cutoff(1.0)
    .unwrap();
    let mut b = ParticleSystem::builder(2)
        .body("a", 2.0)
        .body("b", 0.5)
        .body("c", 1.5)
        .force(UniformGravity::new("g", vec![0, 1, 2], 9.81))
        .force(PairForce::new("lj", PairForce::all_pairs(&[0, 1, 2]), lj));
    for f in contact.clone().into_forces() {
        b = b.boxed_force(f);
    }
    b.build().unwrap()
}

#[test]
fn contact_laws_and_pair_potentials_get_their_exact_jacobian() {
    let mut seed = 0x2545_F491_4F6C_DD1D_u64;
    let mut uniform = |lo: f64, hi: f64| {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        lo + (hi - lo) * ((seed >> 11) as f64 / (1u64 << 53) as f64)
    };
    for (law, damping) in [
        (
            ContactLaw::hertz(1e5),
            ContactDamping::HuntCrossley { alpha: 0.3 },
        ),
        (ContactLaw::linear(1e4), ContactDamping::Linear { c: 20.0 }),
    ] {
        let sys = contact_system(law, damping);
        let contact = ContactForceBuilder::new(2)
            .law(law)
            .spheres(&[(0, 0.25), (1, 0.375), (2, 0.25)])
            .wall(
                &[0.0, -1.0],
                &[0.2, 1.0],
                &[(0, 0.25), (1, 0.375), (2, 0.25)],
            )
            .build()
            .unwrap();
        let mut touching = 0;
        let mut tried = 0;
        while touching < 40 {
            tried += 1;
            let q: Vec<f64> = (0..6)
                .map(|i| uniform(-0.6, 0.6) - 0.2 * f64::from(i % 2))
                .collect();
            let v: Vec<f64> = (0..6).map(|_| uniform(-1.0, 1.0)).collect();
            let overlaps = contact.overlaps(&q);
            // differences need every contact clearly in or clearly apart, the clamp of the
            // damped total clearly on one side, and no pair at the cut-off
            if overlaps.iter().any(|d| d.abs() < 2e-3) {
                continue;
            }
            let far = (0..3).all(|a| {
                (a + 1..3).all(|b| {
                    let r = ((q[2 * a] - q[2 * b]).powi(2) + (q[2 * a + 1] - q[2 * b + 1]).powi(2))
                        .sqrt();
                    (r - 1.0).abs() > 1e-3 && r > 0.3
                })
            });
            let clamps = contact_clamps(&sys, &q, &v);
            if !far || clamps {
                continue;
            }
            touching += usize::from(overlaps.iter().any(|d| *d > 0.0));
            matches_differences(&sys, &q, &v, 1e-7, 1e-5);
        }
        assert!(tried < 5000);
    }
}

/// Whether the damped total of some touching contact is within a few percent of zero (the
/// kink of the clamp, where differences straddle it).
fn contact_clamps(sys: &ParticleSystem, q: &[f64], v: &[f64]) -> bool {
    let k = crate::particles::Kinematics {
        t: 0.0,
        dim: 2,
        x: q,
        v,
        mass: &[2.0, 0.5, 1.5],
    };
    let mut elastic = vec![0.0; 6];
    let mut damper = vec![0.0; 6];
    let forces: Vec<_> = sys.forces().iter().collect();
    forces[2].add_forces(&k, &mut elastic);
    forces[3].add_forces(&k, &mut damper);
    elastic
        .iter()
        .zip(&damper)
        .any(|(e, d)| e.abs() > 0.0 && (e + d).abs() < 0.05 * e.abs())
}

/// A force that cannot write itself into a kernel.
#[derive(Debug)]
struct Opaque;

impl crate::forces::Force for Opaque {
    fn name(&self) -> &'static str {
        "opaque"
    }

    fn add_forces(&self, k: &crate::particles::Kinematics<'_>, out: &mut [f64]) {
        out[k.dim - 1] -= k.x[k.dim - 1];
    }

    fn bodies(&self) -> Vec<usize> {
        vec![0]
    }
}

#[test]
fn a_force_that_cannot_be_compiled_leaves_the_differences() {
    let sys = ParticleSystem::builder(2)
        .body("a", 1.0)
        .force(UniformGravity::new("g", vec![0], 9.81))
        .force(Opaque)
        .build()
        .unwrap();
    assert!(CompiledJacobian::build(&sys).is_none());
    let mut d = vec![0.0; 4];
    let mut e = vec![0.0; 4];
    assert!(!sys.accel_jacobian_into(0.0, &[0.0, 0.5], &[0.0, 0.0], &mut d, &mut e));
}

/// A 1-D chain of twelve bodies on springs, the first tied to a wall: each acceleration
/// depends on its neighbours only, which the compiled Jacobian's structural zeros say, and
/// radau5 factors the chain's Newton matrices as band matrices.
/// A 1-D chain of `n` 1 kg bodies on springs of 10⁶ N/m, the first tied to a wall.
fn spring_chain(n: usize) -> ParticleSystem {
    let mut b = ParticleSystem::builder(1);
    for i in 0..n {
        b = b.body(format!("m{i}"), 1.0);
    }
    b = b.force(Spring::new(
        "wall",
        1e6,
        1.0,
        SpringEnds::Anchor {
            bodies: vec![0],
            anchor: vec![0.0],
        },
    ));
    for i in 1..n {
        b = b.force(Spring::new(
            format!("s{i}"),
            1e6,
            1.0,
            SpringEnds::Pair(i - 1, i),
        ));
    }
    b.build().unwrap()
}

#[test]
fn a_chain_of_springs_has_a_tridiagonal_pattern_and_is_solved_banded() {
    let n = 12;
    let sys = spring_chain(n);
    let pattern = sys.accel_pattern().expect("springs compile");
    for i in 0..n {
        for j in 0..n {
            assert_eq!(pattern.contains(i, j), i.abs_diff(j) <= 1, "({i}, {j})");
        }
    }
    let q0: Vec<f64> = (0..n)
        .map(|i| (i + 1) as f64 + 0.01 * (i as f64).sin())
        .collect();
    let mut state = crate::ode::State::new(0.0, [q0, vec![0.0; n]].concat());
    let mut radau = crate::ode::Radau5::new(crate::ode::AdaptiveConfig::default());
    radau.step(&sys, &mut state, 1e-3).unwrap();
    assert!(
        radau.band().is_some_and(|(kl, ku)| kl + ku < 8),
        "{:?}",
        radau.band()
    );
    // mutual gravity couples every coordinate of the three bodies: dense
    let full = system().accel_pattern().unwrap();
    assert_eq!(full.len(), 36);
}

/// Past 96 coordinates the Jacobian is still compiled, with only the entries that are not
/// structurally zero as outputs: a chain of 300 bodies has 898 of 180,000, exact against
/// central differences, and its pattern is the chain's.
#[test]
fn a_long_chain_gets_a_sparse_compiled_jacobian() {
    let n = 300;
    let sys = spring_chain(n);
    let jac = CompiledJacobian::build(&sys).expect("springs compile past 96 coordinates");
    let pattern = jac.pattern();
    assert_eq!(pattern.len(), 3 * n - 2);
    assert!(pattern.entries().all(|(i, j)| i.abs_diff(j) <= 1));
    let q: Vec<f64> = (0..n)
        .map(|i| (i + 1) as f64 + 0.01 * (i as f64).sin())
        .collect();
    let v: Vec<f64> = (0..n).map(|i| 0.1 * (i as f64).cos()).collect();
    matches_differences(&sys, &q, &v, 1e-6, 1e-6);
    // too large to compile at once: interpreted, then native after use, the same bits
    let mut jac = jac;
    assert!(jac.kernel.len() > NATIVE_AT_ONCE && !jac.kernel.is_native());
    jac.native_after = 3 * jac.kernel.len() as u64;
    let mut seen = Vec::new();
    for _ in 0..4 {
        let (mut dq, mut dv) = (vec![0.0; n * n], vec![0.0; n * n]);
        assert!(jac.eval_into(0.4, &q, &v, &mut dq, &mut dv));
        seen.push((dq, dv));
    }
    assert!(jac.native.get().is_some());
    assert!(seen.windows(2).all(|w| w[0] == w[1]));
}

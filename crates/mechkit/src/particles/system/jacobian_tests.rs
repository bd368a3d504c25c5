use super::*;
use crate::forces::{
    ContactForceBuilder, NewtonianGravity, QuadraticDrag, Spring, SpringEnds, Target,
    UniformGravity,
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

#[test]
fn the_compiled_jacobian_matches_central_differences() {
    let sys = system();
    let jac = CompiledJacobian::build(&sys).expect("every force emits");
    let n = 6;
    let q = [0.3, 0.9, -0.2, 0.4, 1.1, -0.7];
    let v = [0.5, -1.2, 0.8, 0.1, -0.3, 2.0];
    let (mut dq, mut dv) = (vec![0.0; n * n], vec![0.0; n * n]);
    assert!(jac.eval_into(0.4, &q, &v, &mut dq, &mut dv));
    let accel = |q: &[f64], v: &[f64]| {
        let mut a = vec![0.0; n];
        sys.accel_into(0.4, q, v, &mut a);
        a
    };
    let h = 1e-6;
    for j in 0..n {
        for (block, exact) in [(0, &dq), (1, &dv)] {
            let (mut qp, mut qm, mut vp, mut vm) = (q, q, v, v);
            if block == 0 {
                qp[j] += h;
                qm[j] -= h;
            } else {
                vp[j] += h;
                vm[j] -= h;
            }
            let (ap, am) = (accel(&qp, &vp), accel(&qm, &vm));
            for i in 0..n {
                let fd = (ap[i] - am[i]) / (2.0 * h);
                let e = exact[i * n + j];
                assert!(
                    (e - fd).abs() < 1e-6 * (1.0 + fd.abs()),
                    "block {block}, ∂a{i}/∂{j}: {e} vs {fd}"
                );
            }
        }
    }
    // the system hands it to the implicit methods
    let (mut dq2, mut dv2) = (vec![0.0; n * n], vec![0.0; n * n]);
    assert!(sys.accel_jacobian_into(0.4, &q, &v, &mut dq2, &mut dv2));
    assert_eq!((dq, dv), (dq2, dv2));
}

#[test]
fn a_force_that_cannot_be_compiled_leaves_the_differences() {
    let contact = ContactForceBuilder::new(2)
        .name("floor")
        .law(crate::forces::ContactLaw::Hertz { k: 1e10 })
        .wall(&[0.0, 0.0], &[0.0, 1.0], &[(0, 0.1)])
        .build()
        .unwrap();
    let sys = ParticleSystem::builder(2)
        .body("a", 1.0)
        .force(contact)
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
#[test]
fn a_chain_of_springs_has_a_tridiagonal_pattern_and_is_solved_banded() {
    let n = 12;
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
    let sys = b.build().unwrap();
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

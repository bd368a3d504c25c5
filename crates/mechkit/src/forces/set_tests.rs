use super::*;
use crate::forces::{
    ConstantForce, NewtonianGravity, PairForce, QuadraticDrag, RadialPotential, Spring, SpringEnds,
    Target, UniformGravity,
};

/// A force that promises nothing: it writes into every coordinate.
#[derive(Debug)]
struct Everywhere;

impl Force for Everywhere {
    fn name(&self) -> &'static str {
        "everywhere"
    }
    fn add_forces(&self, k: &Kinematics<'_>, out: &mut [Real]) {
        for (i, o) in out.iter_mut().enumerate() {
            *o += 0.25 * i as Real - k.x[i % k.x.len()];
        }
    }
    fn bodies(&self) -> Vec<usize> {
        vec![0]
    }
}

fn forces() -> ForceSet {
    let u = mechkit_expr::parse("k*(r - L)^2/2").unwrap().expr;
    let bond = RadialPotential::new(&u, "r", &[("k".into(), 40.0), ("L".into(), 0.7)]).unwrap();
    let mut set = ForceSet::new();
    set.push(Box::new(Spring::new(
        "s",
        30.0,
        0.5,
        SpringEnds::Pair(3, 1),
    )));
    set.push(Box::new(Spring::new(
        "anchor",
        12.0,
        0.2,
        SpringEnds::Anchor {
            bodies: vec![4, 0, 4],
            anchor: vec![0.1, -0.2],
        },
    )));
    set.push(Box::new(Everywhere));
    set.push(Box::new(UniformGravity::new("g", vec![2, 4], 9.81)));
    set.push(Box::new(NewtonianGravity::mutual(
        "grav",
        vec![0, 1, 2],
        0.7,
    )));
    set.push(Box::new(PairForce::new("bond", vec![(2, 3), (0, 4)], bond)));
    set.push(Box::new(QuadraticDrag::new(
        "air",
        vec![Target::new(1, 0.3), Target::new(4, 0.1)],
    )));
    set.push(Box::new(ConstantForce::new("push", vec![3], &[1.5, -0.5])));
    set
}

/// Every force that says it is local writes only its bodies' coordinates, and the ledger
/// that visits only those gives what the ledger over every coordinate gives: the total,
/// each force's power and net force, with a force that writes everywhere in between.
#[test]
fn the_ledger_of_local_forces_visits_only_their_bodies() {
    let set = forces();
    let (d, n) = (2, 5);
    let x: Vec<Real> = (0..d * n).map(|i| (i as Real * 1.7).sin() * 2.0).collect();
    let v: Vec<Real> = (0..d * n).map(|i| (i as Real * 0.9).cos()).collect();
    let mass = [1.0, 2.0, 0.5, 1.5, 3.0];
    let k = Kinematics {
        t: 0.3,
        dim: d,
        x: &x,
        v: &v,
        mass: &mass,
    };
    for (i, f) in set.iter().enumerate() {
        if !f.local() {
            continue;
        }
        let mut out = vec![0.0; d * n];
        f.add_forces(&k, &mut out);
        let bodies = set.reach[i].as_ref().unwrap();
        for (c, o) in out.iter().enumerate() {
            assert!(
                *o == 0.0 || bodies.contains(&(c / d)),
                "{} wrote coordinate {c}",
                f.name()
            );
        }
    }
    let m = set.len();
    let (mut out, mut power, mut net, mut scratch) = (
        vec![0.0; d * n],
        vec![0.0; m],
        vec![0.0; m * d],
        vec![7.0; d * n],
    );
    set.total_and_power_into(&k, &mut out, &mut power, &mut net, &mut scratch);
    let mut each = vec![0.0; m * d * n];
    let mut total = vec![0.0; d * n];
    set.each_into(&k, &mut total, &mut each);
    assert_eq!(out, total);
    for (i, own) in each.chunks_exact(d * n).enumerate() {
        assert_eq!(power[i], dot(own, &v), "power of {}", set.get(i).name());
        for a in 0..d {
            let sum: Real = own.iter().skip(a).step_by(d).sum();
            assert_eq!(net[i * d + a], sum, "net force of {}", set.get(i).name());
        }
        assert!(power[i] != 0.0);
    }
}

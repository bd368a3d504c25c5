//! The contact laws and pair potentials written into a kernel give the forces of their
//! `add_forces`, bit for bit (up to the sign of an exact zero), in the interpreter and in
//! native code, at random states in contact and apart, and at the contacts' edges.

use mechkit_expr::{Kernel, KernelBuilder, parse};

use crate::Real;
use crate::forces::{
    ContactDamping, ContactForce, ContactLaw, Force, ForceEmitter, PairForce, RadialPotential,
};
use crate::particles::Kinematics;

/// A small deterministic generator (xorshift64*), uniform in `[lo, hi)`.
struct Rng(u64);

impl Rng {
    fn uniform(&mut self, lo: Real, hi: Real) -> Real {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let bits = self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11;
        lo + (hi - lo) * (bits as Real / (1u64 << 53) as Real)
    }
}

/// The force's kernel over slots `[t, x (n), v (n), F (n)]`.
fn kernel(f: &dyn Force, dim: usize, mass: &[Real]) -> Kernel {
    let n = dim * mass.len();
    let mut b = KernelBuilder::new(1 + 3 * n);
    let t = b.get(0);
    let x: Vec<_> = (0..n).map(|i| b.get(1 + i)).collect();
    let v: Vec<_> = (0..n).map(|i| b.get(1 + n + i)).collect();
    let mut e = ForceEmitter::new(&mut b, dim, t, &x, &v, mass);
    assert!(f.emit(&mut e), "{} emits", f.name());
    let out = e.into_forces();
    let zero = b.constant(0.0);
    for (i, o) in out.into_iter().enumerate() {
        b.set(1 + 2 * n + i, o.unwrap_or(zero));
    }
    b.finish()
}

/// The same number, NaN for NaN, either sign of zero.
fn same(a: Real, b: Real) -> bool {
    a == b || (a.is_nan() && b.is_nan())
}

/// Compares the kernel (interpreted and native) with `add_forces` at `(x, v)`.
fn agrees(
    f: &dyn Force,
    k: &Kernel,
    native: &Kernel,
    dim: usize,
    mass: &[Real],
    x: &[Real],
    v: &[Real],
) {
    let n = x.len();
    let kin = Kinematics {
        t: 0.3,
        dim,
        x,
        v,
        mass,
    };
    let mut expected = vec![0.0; n];
    f.add_forces(&kin, &mut expected);
    let mut slots = vec![0.0; 1 + 3 * n];
    slots[0] = 0.3;
    slots[1..=n].copy_from_slice(x);
    slots[1 + n..=2 * n].copy_from_slice(v);
    let mut s2 = slots.clone();
    k.run_interpreted(&mut slots, 1);
    native.run(&mut s2, 1);
    for i in 0..n {
        let (a, b) = (slots[1 + 2 * n + i], s2[1 + 2 * n + i]);
        assert!(
            same(a, expected[i]) && same(b, expected[i]),
            "{}: component {i} at x = {x:?}, v = {v:?}: kernel {a} / native {b}, loop {}",
            f.name(),
            expected[i]
        );
    }
}

/// Random states of three bodies in a box of side 1 (about half the contacts touch), and
/// the edges: bodies 0 and 1 exactly at their reach `r01` along the first axis, body 2
/// exactly touching the floor `x_last = -1`, coincident centres.
fn states(dim: usize, r01: Real, r2: Real, count: usize) -> Vec<(Vec<Real>, Vec<Real>)> {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15 ^ dim as u64);
    let mut out = Vec::new();
    for _ in 0..count {
        let x: Vec<Real> = (0..3 * dim).map(|_| rng.uniform(-0.5, 0.5)).collect();
        let v: Vec<Real> = (0..3 * dim).map(|_| rng.uniform(-2.0, 2.0)).collect();
        out.push((x, v));
    }
    for speed in [-1.0, 0.0, 1.0] {
        let mut x = vec![0.0; 3 * dim];
        x[dim] = r01;
        x[3 * dim - 1] = -1.0 + r2;
        let v: Vec<Real> = (0..3 * dim).map(|i| speed * (i as Real - 1.5)).collect();
        out.push((x.clone(), v.clone()));
        // coincident centres of 0 and 1
        x[dim] = 0.0;
        out.push((x, v));
    }
    out
}

fn contact(dim: usize, law: ContactLaw, damping: ContactDamping, attraction: bool) -> ContactForce {
    let mut floor = vec![0.0; dim];
    let mut up = vec![0.0; dim];
    floor[dim - 1] = -1.0;
    up[dim - 1] = 1.0;
    let slanted: Vec<Real> = (0..dim).map(|i| 1.0 + i as Real).collect();
    ContactForce::builder(dim)
        .law(law)
        .damping(damping)
        .allow_attraction(attraction)
        .spheres(&[(0, 0.25), (1, 0.375), (2, 0.25)])
        .wall(&floor, &up, &[(2, 0.25)])
        .wall(&[0.1; 3][..dim], &slanted, &[(0, 0.25), (1, 0.375)])
        .build()
        .unwrap()
}

#[test]
fn contact_laws_and_dampers_emit_the_forces_of_the_general_loop() {
    let mass = [1.0, 2.0, 0.5];
    for dim in 1..=3 {
        for law in [ContactLaw::linear(1e4), ContactLaw::hertz(1e10)] {
            for (damping, attraction) in [
                (ContactDamping::None, false),
                (ContactDamping::Linear { c: 30.0 }, false),
                (ContactDamping::Linear { c: 30.0 }, true),
                (ContactDamping::HuntCrossley { alpha: 0.4 }, false),
            ] {
                let c = contact(dim, law, damping, attraction);
                let mut forces: Vec<Box<dyn Force>> = vec![Box::new(c.clone())];
                if let Some(d) = c.damper() {
                    forces.push(Box::new(d));
                }
                for f in &forces {
                    let k = kernel(f.as_ref(), dim, &mass);
                    let native = k.clone().native();
                    let mut touching = 0;
                    for (x, v) in states(dim, 0.625, 0.25, 300) {
                        touching += usize::from(c.overlaps(&x).iter().any(|d| *d > 0.0));
                        agrees(f.as_ref(), &k, &native, dim, &mass, &x, &v);
                    }
                    assert!(touching > 100, "{touching} states touch");
                }
            }
        }
    }
}

#[test]
fn pair_potentials_emit_the_forces_of_the_general_loop() {
    let mass = [1.0, 2.0, 0.5];
    let lj = RadialPotential::new(
        &parse("4*((s/r)^12 - (s/r)^6)").unwrap().expr,
        "r",
        &[("s".into(), 0.3)],
    )
    .unwrap()
    .with_cutoff(0.625)
    .unwrap();
    let morse = RadialPotential::new(
        &parse("D*(1 - exp(-a*(r - re)))^2").unwrap().expr,
        "r",
        &[("D".into(), 4.7), ("a".into(), 1.9), ("re".into(), 0.4)],
    )
    .unwrap();
    for dim in 1..=3 {
        for law in [lj.clone(), morse.clone()] {
            let p = PairForce::new("pair", PairForce::all_pairs(&[0, 1, 2]), law);
            let k = kernel(&p, dim, &mass);
            let native = k.clone().native();
            // r01 = 0.625: exactly at the cut-off
            for (x, v) in states(dim, 0.625, 0.25, 300) {
                agrees(&p, &k, &native, dim, &mass, &x, &v);
            }
        }
    }
}

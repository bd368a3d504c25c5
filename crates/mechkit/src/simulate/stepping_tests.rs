//! The augmented system of a run with works: its Jacobian pattern.

use super::*;
use crate::forces::{Spring, SpringEnds};

/// The works' rows and columns are empty: a chain of springs with its works is still
/// factored banded, reduced to its coordinates.
#[test]
fn the_works_keep_a_chain_banded() {
    let mut b = ParticleSystem::builder(1);
    for i in 0..8 {
        b = b.body(format!("m{i}"), 1.0);
    }
    for i in 1..8 {
        b = b.force(Spring::new(
            format!("s{i}"),
            1e6,
            1.0,
            SpringEnds::Pair(i - 1, i),
        ));
    }
    let sys = b.build().unwrap();
    let work = WorkSystem::new(&sys);
    assert_eq!(work.jacobian_pattern().map(|p| p.dim()), Some(work.dim()));
    let y0: Vec<Real> = (0..work.dim())
        .map(|i| if i < 8 { i as Real } else { 0.0 })
        .collect();
    let mut state = State::new(0.0, y0);
    let mut radau = crate::ode::Radau5::new(crate::ode::AdaptiveConfig::default());
    radau.step(&work, &mut state, 1e-3).unwrap();
    assert!(radau.band().is_some(), "dense");
    // and its Newton systems are solved in the 8 coordinates: a tridiagonal band
    assert_eq!(radau.reduced_to(), Some(8));
    assert_eq!(radau.band(), Some((1, 1)));
}

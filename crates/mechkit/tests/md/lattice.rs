//! Lattices fill their box at the requested density with the right count and nearest
//! neighbour distance; Maxwell-Boltzmann velocities have zero momentum and the exact
//! temperature, reproducibly from a seed; bad input is an error, not a panic.

use mechkit::md::{Lattice, LennardJones, Md, MdConfig, MdError, maxwell_boltzmann};

#[test]
fn lattices_have_the_right_count_density_and_spacing() {
    for (lattice, cells, count, nearest) in [
        (
            Lattice::Fcc,
            20,
            32_000,
            (4.0 / 0.8442f64).cbrt() / 2f64.sqrt(),
        ),
        (Lattice::SimpleCubic, 5, 125, (1.0 / 0.8442f64).cbrt()),
        (Lattice::Square, 6, 36, (1.0 / 0.8442f64).sqrt()),
        (
            Lattice::Hexagonal,
            4,
            32,
            (2.0 / (3f64.sqrt() * 0.8442)).sqrt(),
        ),
        (Lattice::Chain, 10, 10, 1.0 / 0.8442),
    ] {
        let (b, x) = lattice.build(cells, 0.8442).unwrap();
        assert_eq!(x.len(), count, "{lattice:?}");
        assert!(
            (x.len() as f64 / b.volume() - 0.8442).abs() < 1e-12,
            "{lattice:?}"
        );
        // Nearest-neighbour distance from atom 0 (minimum image).
        let d = x[1..]
            .iter()
            .map(|p| {
                b.separation(&x[0], p)
                    .iter()
                    .map(|c| c * c)
                    .sum::<f64>()
                    .sqrt()
            })
            .fold(f64::INFINITY, f64::min);
        assert!((d - nearest).abs() < 1e-12, "{lattice:?}: {d} vs {nearest}");
    }
}

#[test]
fn maxwell_boltzmann_has_zero_momentum_exact_temperature_and_is_seeded() {
    for dim in 1..=3 {
        let v = maxwell_boltzmann(2.5, 1.7, dim, 1000, 42).unwrap();
        let p: [f64; 3] = std::array::from_fn(|k| v.iter().map(|v| 1.7 * v[k]).sum());
        assert!(p.iter().all(|p| p.abs() < 1e-11), "{p:?}");
        let k: f64 = v
            .iter()
            .map(|v| 0.5 * 1.7 * v.iter().map(|c| c * c).sum::<f64>())
            .sum();
        let t = 2.0 * k / (dim as f64 * 999.0);
        assert!((t - 2.5).abs() < 1e-12, "T = {t}");
        assert!(v.iter().all(|v| v[dim..].iter().all(|c| *c == 0.0)));
        assert_eq!(v, maxwell_boltzmann(2.5, 1.7, dim, 1000, 42).unwrap());
        assert_ne!(v, maxwell_boltzmann(2.5, 1.7, dim, 1000, 43).unwrap());
    }
    // at 0 K all at rest (a crystal that should stay put); it was refused as not positive
    assert_eq!(
        maxwell_boltzmann(0.0, 1.7, 3, 10, 42).unwrap(),
        vec![[0.0; 3]; 10]
    );
    assert!(maxwell_boltzmann(-1.0, 1.7, 3, 10, 42).is_err());
    // The components' distribution: ⟨v⁴⟩ / ⟨v²⟩² = 3 for a Gaussian.
    let v = maxwell_boltzmann(1.0, 1.0, 3, 100_000, 1).unwrap();
    let m2 = v.iter().map(|v| v[0] * v[0]).sum::<f64>() / 1e5;
    let m4 = v.iter().map(|v| v[0].powi(4)).sum::<f64>() / 1e5;
    assert!(
        (m4 / (m2 * m2) - 3.0).abs() < 0.05,
        "kurtosis {}",
        m4 / (m2 * m2)
    );
}

#[test]
fn bad_input_is_an_error() {
    assert!(matches!(
        Lattice::Fcc.build(0, 0.8),
        Err(MdError::NoCells { .. })
    ));
    assert!(matches!(
        Lattice::Fcc.build(3, -1.0),
        Err(MdError::NotPositive { .. })
    ));
    assert!(maxwell_boltzmann(1.0, 1.0, 4, 10, 1).is_err());
    assert!(maxwell_boltzmann(1.0, 1.0, 3, 1, 1).is_err());
    // 2 fcc cells at 0.8442 are 3.36σ across: too small for r_c + skin = 2.8σ.
    let (b, x) = Lattice::Fcc.build(2, 0.8442).unwrap();
    let v = vec![[0.0; 3]; x.len()];
    let err = Md::new(
        b,
        LennardJones::reduced(2.5).unwrap(),
        x,
        v,
        MdConfig::default(),
    );
    assert!(matches!(err, Err(MdError::BoxTooSmall { axis: 0, .. })));
    assert!(LennardJones::new(1.0, 0.0, 2.5, false).is_err());
}

//! Maxwell-Boltzmann initial velocities with zero total momentum at an exact temperature.
//!
//! Each component is drawn from N(0, k_B T / m) with the seeded [`Xoshiro256`]; the mean
//! velocity is subtracted (total momentum zero, equal masses) and the velocities are scaled
//! so that the kinetic temperature 2K / (d (N − 1)) is exactly T: the d (N − 1) degrees of
//! freedom left once the momentum is fixed, as LAMMPS counts them.

use crate::Real;

use super::{MdError, MdInput, Xoshiro256};

/// `n` velocities in `dim` dimensions for particles of mass `mass` at temperature `kt`
/// (k_B T in energy units: T itself in reduced LJ units), from `seed`; all at rest at `kt = 0`.
///
/// # Example
/// ```
/// use mechkit::md::maxwell_boltzmann;
/// let v = maxwell_boltzmann(1.44, 1.0, 3, 500, 87287).unwrap();
/// let p: f64 = v.iter().map(|v| v[0]).sum();
/// let k: f64 = v.iter().map(|v| 0.5 * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2])).sum();
/// assert!(p.abs() < 1e-12);
/// assert!((2.0 * k / (3.0 * 499.0) - 1.44).abs() < 1e-12);
/// ```
pub fn maxwell_boltzmann(
    kt: Real,
    mass: Real,
    dim: usize,
    n: usize,
    seed: u64,
) -> Result<Vec<[Real; 3]>, MdError> {
    if !(1..=3).contains(&dim) {
        return Err(MdError::Dimension { dim });
    }
    if n < 2 {
        return Err(MdError::TooFewParticles { n });
    }
    if !(mass.is_finite() && mass > 0.0) {
        return Err(MdError::NotPositive {
            input: MdInput::Mass,
            value: mass,
        });
    }
    if kt == 0.0 {
        // a crystal at 0 K: at rest
        return Ok(vec![[0.0; 3]; n]);
    }
    if !(kt.is_finite() && kt > 0.0) {
        return Err(MdError::NotPositive {
            input: MdInput::Temperature,
            value: kt,
        });
    }
    let mut rng = Xoshiro256::seed(seed);
    let sd = (kt / mass).sqrt();
    let mut v = vec![[0.0; 3]; n];
    for vi in &mut v {
        for c in vi.iter_mut().take(dim) {
            *c = sd * rng.normal();
        }
    }
    let mut mean = [0.0; 3];
    for vi in &v {
        for a in 0..3 {
            mean[a] += vi[a] / n as Real;
        }
    }
    let mut k = 0.0;
    for vi in &mut v {
        for a in 0..3 {
            vi[a] -= mean[a];
            k += 0.5 * mass * vi[a] * vi[a];
        }
    }
    let t_now = 2.0 * k / ((dim * (n - 1)) as Real);
    let scale = (kt / t_now).sqrt();
    v.iter_mut().flatten().for_each(|c| *c *= scale);
    Ok(v)
}

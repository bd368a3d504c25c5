//! Systems of point masses: total mass, centre of mass and its velocity, total momentum
//! `P = M V_cm`, velocities in the centre-of-mass frame, and the partition of the kinetic
//! energy `K = ½ M V_cm² + K_internal` (König's theorem).

use thiserror::Error;

use crate::Real;

/// The input of a set of point masses that a [`PointMassError`] is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum PointMassInput {
    /// The masses.
    Mass,
    /// The positions.
    Position,
    /// The velocities.
    Velocity,
}

impl PointMassInput {
    /// The plural noun of the input (`positions`).
    pub fn plural(self) -> &'static str {
        match self {
            Self::Mass => "masses",
            Self::Position => "positions",
            Self::Velocity => "velocities",
        }
    }
}

/// Why a set of point masses is not valid.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum PointMassError {
    /// No bodies.
    #[error("no point masses were given")]
    Empty,
    /// A mass that is not positive and finite.
    #[error("mass {index} is {}; masses must be positive", crate::error::short(*mass))]
    Mass {
        /// 1-based index.
        index: usize,
        /// The value.
        mass: Real,
    },
    /// Coordinates that do not come in groups of `dim`, or a dimension outside 1 to 3.
    #[error("{}: expected {expected} numbers ({dim} per body), got {got}", input.plural())]
    Shape {
        /// Positions or velocities.
        input: PointMassInput,
        /// Spatial dimensions.
        dim: usize,
        /// Numbers expected.
        expected: usize,
        /// Numbers given.
        got: usize,
    },
    /// A body whose position or velocity has another number of components than the first
    /// body's position, or a number outside 1 to 3.
    #[error(
        "body {index} has {} but body 1's position has {expected}; every position and velocity needs the same number of coordinates, 1 to 3 (e.g. \"1 m, 2 m\")",
        coordinates(*input, *got)
    )]
    Coordinates {
        /// Positions or velocities.
        input: PointMassInput,
        /// 1-based index of the body.
        index: usize,
        /// Its number of components.
        got: usize,
        /// The first position's.
        expected: usize,
    },
    /// Another number of positions or velocities than of masses.
    #[error("{got} {} for {expected} {}; give one per body", if *got == 1 { singular(*input) } else { input.plural() }, if *expected == 1 { "mass" } else { "masses" })]
    Count {
        /// Positions or velocities.
        input: PointMassInput,
        /// How many were given.
        got: usize,
        /// The number of masses.
        expected: usize,
    },
}

fn singular(input: PointMassInput) -> &'static str {
    match input {
        PointMassInput::Mass => "mass",
        PointMassInput::Position => "position",
        PointMassInput::Velocity => "velocity",
    }
}

/// `a position of 1 coordinate`, `a velocity of 3 coordinates`.
fn coordinates(input: PointMassInput, n: usize) -> String {
    format!(
        "a {} of {n} coordinate{}",
        singular(input),
        if n == 1 { "" } else { "s" }
    )
}

impl PointMassError {
    /// The input the error is about, when it is about one.
    pub fn input(&self) -> Option<PointMassInput> {
        match self {
            Self::Empty | Self::Mass { .. } => Some(PointMassInput::Mass),
            Self::Shape { input, .. }
            | Self::Coordinates { input, .. }
            | Self::Count { input, .. } => Some(*input),
        }
    }
}

/// Point masses in 1-3 dimensions, positions (and optionally velocities) `dim` per body.
#[derive(Debug, Clone, PartialEq)]
pub struct PointMasses {
    dim: usize,
    masses: Vec<Real>,
    positions: Vec<Real>,
    velocities: Option<Vec<Real>>,
}

/// The mass properties of a set of point masses.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct MassSummary {
    /// `M = Σ m`.
    pub total_mass: Real,
    /// `R = Σ m r / M`.
    pub centre_of_mass: Vec<Real>,
    /// `V = Σ m v / M` (when velocities were given).
    pub cm_velocity: Option<Vec<Real>>,
    /// `P = Σ m v = M V`.
    pub momentum: Option<Vec<Real>>,
    /// Each body's velocity relative to the centre of mass, `dim` per body.
    pub cm_frame_velocities: Option<Vec<Real>>,
    /// `K = Σ ½ m v²`.
    pub kinetic: Option<Real>,
    /// `½ M V²`, the kinetic energy of the centre of mass.
    pub kinetic_cm: Option<Real>,
    /// `Σ ½ m |v - V|²`, the kinetic energy relative to the centre of mass.
    pub kinetic_internal: Option<Real>,
}

/// [`MassSummary`] with the centre of mass also in a chosen length unit.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct PointMassReport {
    /// `M = Σ m` (kg).
    pub total_mass: Real,
    /// `R = Σ m r / M` (m).
    pub centre_of_mass: Vec<Real>,
    /// `R` in `unit`.
    pub centre_of_mass_in_unit: Vec<Real>,
    /// The length unit of `centre_of_mass_in_unit` (`m` when none was chosen).
    pub unit: String,
    /// `V = Σ m v / M` (m/s, when velocities were given).
    pub cm_velocity: Option<Vec<Real>>,
    /// `P = Σ m v = M V` (kg·m/s).
    pub momentum: Option<Vec<Real>>,
    /// Each body's velocity relative to the centre of mass, `dim` per body (m/s).
    pub cm_frame_velocities: Option<Vec<Real>>,
    /// `K = Σ ½ m v²` (J).
    pub kinetic: Option<Real>,
    /// `½ M V²` (J).
    pub kinetic_cm: Option<Real>,
    /// `Σ ½ m |v − V|²` (J).
    pub kinetic_internal: Option<Real>,
}

impl PointMasses {
    /// Checks and stores the bodies.
    ///
    /// ```
    /// use mechkit::mass::PointMasses;
    /// // Earth and Moon on a line, 384,400 km apart
    /// let em = PointMasses::new(1, vec![5.972e24, 7.342e22], vec![0.0, 3.844e8], None).unwrap();
    /// let s = em.summary();
    /// assert!((s.centre_of_mass[0] - 4.6686e6).abs() < 1e3);
    /// ```
    pub fn new(
        dim: usize,
        masses: Vec<Real>,
        positions: Vec<Real>,
        velocities: Option<Vec<Real>>,
    ) -> Result<Self, PointMassError> {
        if masses.is_empty() {
            return Err(PointMassError::Empty);
        }
        if let Some((i, &m)) = masses
            .iter()
            .enumerate()
            .find(|(_, m)| !(m.is_finite() && **m > 0.0))
        {
            return Err(PointMassError::Mass {
                index: i + 1,
                mass: m,
            });
        }
        let expected = masses.len() * dim;
        let shape = |input, got: usize| PointMassError::Shape {
            input,
            dim,
            expected,
            got,
        };
        if !(1..=3).contains(&dim) || positions.len() != expected {
            return Err(shape(PointMassInput::Position, positions.len()));
        }
        if let Some(v) = &velocities
            && v.len() != expected
        {
            return Err(shape(PointMassInput::Velocity, v.len()));
        }
        Ok(Self {
            dim,
            masses,
            positions,
            velocities,
        })
    }

    /// Checks and stores bodies given one by one: a mass, a position and optionally a
    /// velocity each, all positions and velocities with the same number of components (1 to
    /// 3).
    ///
    /// ```
    /// use mechkit::mass::{PointMassInput, PointMasses};
    /// let p = PointMasses::from_bodies(&[1.0, 3.0], &[vec![0.0, 0.0], vec![1.0, 2.0]], None).unwrap();
    /// assert_eq!(p.summary().centre_of_mass, [0.75, 1.5]);
    /// let e = PointMasses::from_bodies(&[1.0, 1.0], &[vec![0.0], vec![1.0, 2.0]], None).unwrap_err();
    /// assert_eq!(e.input(), Some(PointMassInput::Position));
    /// ```
    pub fn from_bodies(
        masses: &[Real],
        positions: &[Vec<Real>],
        velocities: Option<&[Vec<Real>]>,
    ) -> Result<Self, PointMassError> {
        let n = masses.len();
        let dim = positions.first().map_or(0, Vec::len);
        let check = |input, vectors: &[Vec<Real>]| {
            if vectors.len() != n {
                return Err(PointMassError::Count {
                    input,
                    got: vectors.len(),
                    expected: n,
                });
            }
            match vectors
                .iter()
                .position(|v| v.len() != dim || !(1..=3).contains(&v.len()))
            {
                Some(k) => Err(PointMassError::Coordinates {
                    input,
                    index: k + 1,
                    got: vectors[k].len(),
                    expected: dim,
                }),
                None => Ok(vectors.concat()),
            }
        };
        if n == 0 {
            return Err(PointMassError::Empty);
        }
        let positions = check(PointMassInput::Position, positions)?;
        let velocities = velocities
            .map(|v| check(PointMassInput::Velocity, v))
            .transpose()?;
        Self::new(dim, masses.to_vec(), positions, velocities)
    }

    /// The summary with the centre of mass also in a length unit of `size` metres named
    /// `unit` (what `mechkit com --mass … --json` prints).
    pub fn report(&self, unit: &str, size: Real) -> PointMassReport {
        let s = self.summary();
        PointMassReport {
            total_mass: s.total_mass,
            centre_of_mass_in_unit: s.centre_of_mass.iter().map(|x| x / size).collect(),
            centre_of_mass: s.centre_of_mass,
            unit: unit.to_string(),
            cm_velocity: s.cm_velocity,
            momentum: s.momentum,
            cm_frame_velocities: s.cm_frame_velocities,
            kinetic: s.kinetic,
            kinetic_cm: s.kinetic_cm,
            kinetic_internal: s.kinetic_internal,
        }
    }

    /// Spatial dimensions.
    pub fn dim(&self) -> usize {
        self.dim
    }

    fn weighted_mean(&self, values: &[Real]) -> Vec<Real> {
        let total: Real = self.masses.iter().sum();
        let mut out = vec![0.0; self.dim];
        for (m, body) in self.masses.iter().zip(values.chunks_exact(self.dim)) {
            for (o, x) in out.iter_mut().zip(body) {
                *o += m * x;
            }
        }
        out.iter().map(|x| x / total).collect()
    }

    /// Total mass, centre of mass, and with velocities the momentum, the centre-of-mass frame
    /// and the kinetic energy split.
    pub fn summary(&self) -> MassSummary {
        let total_mass: Real = self.masses.iter().sum();
        let centre_of_mass = self.weighted_mean(&self.positions);
        let (mut cm_velocity, mut momentum, mut frame) = (None, None, None);
        let (mut kinetic, mut kinetic_cm, mut kinetic_internal) = (None, None, None);
        if let Some(v) = &self.velocities {
            let vc = self.weighted_mean(v);
            let rel: Vec<Real> = v
                .chunks_exact(self.dim)
                .flat_map(|body| body.iter().zip(&vc).map(|(a, c)| a - c))
                .collect();
            let half_mv2 = |values: &[Real]| -> Real {
                self.masses
                    .iter()
                    .zip(values.chunks_exact(self.dim))
                    .map(|(m, b)| 0.5 * m * b.iter().map(|x| x * x).sum::<Real>())
                    .sum()
            };
            kinetic = Some(half_mv2(v));
            kinetic_internal = Some(half_mv2(&rel));
            kinetic_cm = Some(0.5 * total_mass * vc.iter().map(|x| x * x).sum::<Real>());
            momentum = Some(vc.iter().map(|x| total_mass * x).collect());
            cm_velocity = Some(vc);
            frame = Some(rel);
        }
        MassSummary {
            total_mass,
            centre_of_mass,
            cm_velocity,
            momentum,
            cm_frame_velocities: frame,
            kinetic,
            kinetic_cm,
            kinetic_internal,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn carbon_monoxide_and_koenig() {
        // C (12.011 u) at 0, O (15.999 u) at 112.8 pm: the CM is 48.37 pm from the oxygen
        let co = PointMasses::new(1, vec![12.011, 15.999], vec![0.0, 112.8], None).unwrap();
        let cm = co.summary().centre_of_mass[0];
        assert!((112.8 - cm - 48.370).abs() < 5e-4, "{cm}");
        // König: K = ½ M V² + K_internal, and P = M V
        let p = PointMasses::new(
            2,
            vec![1.0, 3.0],
            vec![0.0, 0.0, 1.0, 2.0],
            Some(vec![2.0, -1.0, 0.5, 4.0]),
        )
        .unwrap();
        let s = p.summary();
        let (k, kc, ki) = (
            s.kinetic.unwrap(),
            s.kinetic_cm.unwrap(),
            s.kinetic_internal.unwrap(),
        );
        assert!((k - (kc + ki)).abs() < 1e-14 * k);
        let m = s.momentum.unwrap();
        assert!((m[0] - 3.5).abs() < 1e-15 && (m[1] - 11.0).abs() < 1e-15);
        // in the CM frame the momenta add up to zero
        let rel = s.cm_frame_velocities.unwrap();
        assert!((1.0 * rel[0] + 3.0 * rel[2]).abs() < 1e-15);
        assert!(PointMasses::new(1, vec![1.0, -1.0], vec![0.0, 1.0], None).is_err());
        assert!(PointMasses::new(2, vec![1.0], vec![0.0], None).is_err());
    }
}

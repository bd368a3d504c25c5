//! The points of a sweep: the grid of all combinations (the last `--set` varies fastest), or a
//! seeded random sample; and the slice of them one shard runs.

use super::param::MAX_RUNS;
use super::{Parameter, SweepError};
use crate::Real;

/// How points are chosen.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Sampling {
    /// Every combination of the parameters' values.
    Grid,
    /// `n` points, each parameter drawn uniformly: between a range's bounds, or among a
    /// list's values. Point `i` depends only on `seed` and `i`.
    Random {
        /// How many points.
        n: usize,
        /// The seed.
        seed: u64,
    },
}

/// The parameters of a sweep and how their points are chosen.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepGrid {
    /// The swept constants.
    pub params: Vec<Parameter>,
    /// Grid or random sample.
    pub sampling: Sampling,
}

impl SweepGrid {
    /// A sweep over `params`.
    pub fn new(params: Vec<Parameter>, sampling: Sampling) -> Self {
        Self { params, sampling }
    }

    /// Checks the parameters: at least one, no name twice.
    pub fn check(&self) -> Result<(), SweepError> {
        if self.params.is_empty() {
            return Err(SweepError::Options(
                "a sweep needs at least one --set\n  = hint: e.g. --set \"v0=0:5:51\"".into(),
            ));
        }
        for (i, p) in self.params.iter().enumerate() {
            if self.params[..i].iter().any(|q| q.name == p.name) {
                return Err(SweepError::Duplicate {
                    name: p.name.clone(),
                });
            }
        }
        if let Sampling::Random { n: 0, .. } = self.sampling {
            return Err(SweepError::Options(
                "--random needs at least 1 point\n  = hint: e.g. --random 1000 --seed 1".into(),
            ));
        }
        if self.len() > MAX_RUNS {
            let counts: Vec<String> = self
                .params
                .iter()
                .map(|p| format!("{} {}", p.values.len(), p.name))
                .collect();
            let hint = match self.sampling {
                Sampling::Grid => format!(
                    "use fewer points ({}), or --random N for a sample of the space",
                    counts.join(" × ")
                ),
                Sampling::Random { .. } => format!("ask for at most {MAX_RUNS} with --random"),
            };
            let runs = if self.len() == usize::MAX {
                "more than 10^19".to_string()
            } else {
                self.len().to_string()
            };
            return Err(SweepError::Options(format!(
                "the sweep would make {runs} runs, more than the {MAX_RUNS} a sweep runs\n  = hint: {hint}"
            )));
        }
        Ok(())
    }

    /// The number of runs.
    pub fn len(&self) -> usize {
        match self.sampling {
            // saturating: a grid too large to count is refused by `check`
            Sampling::Grid => self
                .params
                .iter()
                .try_fold(1usize, |n, p| n.checked_mul(p.values.len()))
                .unwrap_or(usize::MAX),
            Sampling::Random { n, .. } => n,
        }
    }

    /// Whether there are no runs.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The parameter values (SI) of run `index`.
    ///
    /// # Example
    /// ```
    /// use mechkit::scenario::sweep::{Parameter, Sampling, SweepGrid};
    /// let g = SweepGrid::new(
    ///     vec![Parameter::parse("a=1,2").unwrap(), Parameter::parse("b=10,20,30").unwrap()],
    ///     Sampling::Grid,
    /// );
    /// assert_eq!(g.len(), 6);
    /// assert_eq!(g.point(4), vec![2.0, 20.0]);
    /// ```
    pub fn point(&self, index: usize) -> Vec<Real> {
        match self.sampling {
            Sampling::Grid => {
                let mut rest = index;
                let mut out = vec![0.0; self.params.len()];
                for (slot, p) in out.iter_mut().zip(&self.params).rev() {
                    *slot = p.values[rest % p.values.len()];
                    rest /= p.values.len();
                }
                out
            }
            Sampling::Random { seed, .. } => {
                let mut rng = SplitMix64(
                    seed ^ (index as u64)
                        .wrapping_add(1)
                        .wrapping_mul(0xD6E8_FEB8_6659_FD93),
                );
                self.params
                    .iter()
                    .map(|p| {
                        let u = rng.uniform();
                        match p.range {
                            Some((a, b)) => a + (b - a) * u,
                            None => {
                                p.values[((u * p.values.len() as Real) as usize)
                                    .min(p.values.len() - 1)]
                            }
                        }
                    })
                    .collect()
            }
        }
    }

    /// The manifest line of the sweep's table: what makes two tables parts of one sweep.
    pub fn describe(&self) -> String {
        let sets: Vec<String> = self
            .params
            .iter()
            .map(|p| format!("--set \"{}\"", p.text))
            .collect();
        let sampling = match self.sampling {
            Sampling::Grid => "grid".to_string(),
            Sampling::Random { n, seed } => format!("random {n} seed {seed}"),
        };
        format!("{} {sampling}", sets.join(" "))
    }
}

/// Steele, Lea and Flood's SplitMix64 (2014): a small, well-mixed generator; enough for
/// choosing parameter values.
struct SplitMix64(u64);

impl SplitMix64 {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    fn uniform(&mut self) -> Real {
        (self.next() >> 11) as Real * (1.0 / (1u64 << 53) as Real)
    }
}

/// The `k`-th of `n` slices of a sweep (1-based): the runs with `index % n == k - 1`, so
/// every shard gets a share of the cheap and the expensive corners of the grid.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    /// Which slice, 1..=n.
    pub k: usize,
    /// How many slices.
    pub n: usize,
}

impl Shard {
    /// Parses `K/N`.
    ///
    /// # Example
    /// ```
    /// use mechkit::scenario::sweep::Shard;
    /// let s = Shard::parse("2/3").unwrap();
    /// assert_eq!(s.indices(7), vec![1, 4]);
    /// assert!(Shard::parse("4/3").is_err());
    /// ```
    pub fn parse(text: &str) -> Result<Shard, SweepError> {
        let bad = |reason: &str| SweepError::BadShard {
            text: text.to_string(),
            reason: reason.to_string(),
        };
        let (k, n) = text.trim().split_once('/').ok_or_else(|| bad("no `/`"))?;
        let k: usize = k
            .trim()
            .parse()
            .map_err(|_| bad("K is not a whole number"))?;
        let n: usize = n
            .trim()
            .parse()
            .map_err(|_| bad("N is not a whole number"))?;
        if n == 0 || k == 0 || k > n {
            return Err(bad("K must be between 1 and N"));
        }
        Ok(Shard { k, n })
    }

    /// The run indices of this shard among `len` runs.
    pub fn indices(&self, len: usize) -> Vec<usize> {
        (self.k - 1..len).step_by(self.n).collect()
    }
}

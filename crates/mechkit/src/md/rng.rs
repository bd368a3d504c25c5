//! A small seeded random number generator: xoshiro256** seeded by splitmix64.
//!
//! Blackman and Vigna, "Scrambled linear pseudorandom number generators", ACM TOMS 47 (2021).
//! Written here (30 lines) so runs are reproducible from a seed without a dependency; the
//! same seed gives the same sequence on every platform.

use crate::Real;

/// xoshiro256** (period 2²⁵⁶ − 1), its state filled by splitmix64 from a 64-bit seed.
#[derive(Debug, Clone)]
pub struct Xoshiro256 {
    s: [u64; 4],
}

/// One step of splitmix64 (Steele, Lea and Flood 2014), used to spread a seed over the state.
fn splitmix64(x: &mut u64) -> u64 {
    *x = x.wrapping_add(0x9e37_79b9_7f4a_7c15);
    let mut z = *x;
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

impl Xoshiro256 {
    /// A generator seeded from `seed` through splitmix64 (never the all-zero state).
    pub fn seed(seed: u64) -> Self {
        let mut x = seed;
        Self {
            s: [
                splitmix64(&mut x),
                splitmix64(&mut x),
                splitmix64(&mut x),
                splitmix64(&mut x),
            ],
        }
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        let result = self.s[1].wrapping_mul(5).rotate_left(7).wrapping_mul(9);
        let t = self.s[1] << 17;
        self.s[2] ^= self.s[0];
        self.s[3] ^= self.s[1];
        self.s[1] ^= self.s[2];
        self.s[0] ^= self.s[3];
        self.s[2] ^= t;
        self.s[3] = self.s[3].rotate_left(45);
        result
    }

    /// Uniform on [0, 1) with 53 random bits.
    pub fn uniform(&mut self) -> Real {
        (self.next_u64() >> 11) as Real * (1.0 / (1u64 << 53) as Real)
    }

    /// Standard normal by the Box-Muller transform.
    pub fn normal(&mut self) -> Real {
        let u1 = 1.0 - self.uniform(); // (0, 1]
        let u2 = self.uniform();
        (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn same_seed_same_sequence_and_uniform_mean() {
        let (mut a, mut b) = (Xoshiro256::seed(7), Xoshiro256::seed(7));
        assert!((0..100).all(|_| a.next_u64() == b.next_u64()));
        let mut r = Xoshiro256::seed(1);
        let n = 100_000u32;
        let mean = (0..n).map(|_| r.uniform()).sum::<Real>() / Real::from(n);
        assert!((mean - 0.5).abs() < 5e-3, "mean {mean}");
        let var = (0..n).map(|_| r.normal().powi(2)).sum::<Real>() / Real::from(n);
        assert!((var - 1.0).abs() < 2e-2, "variance {var}");
    }
}

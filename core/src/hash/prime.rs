//! A multiplicative corner hash for simplex noise: `(s ⊕ x·P₀ ⊕ y·P₁ ⊕ …) · M`, read from its
//! top bits.
//!
//! The axes are hashed independently (one product per axis, each a prime), combined by `xor`
//! with a mix of the seed, and the sum is multiplied once by an odd constant, whose top bits
//! depend on every bit below them: the gradient index is read there. This is the form
//! FastNoise Lite and FastNoise2 use (their primes and multiplier); unlike a permutation
//! chain (`p[p[x] + y]`), it needs no table and no dependent loads, so a batch computes it
//! for 4 lanes per vector instruction, and it repeats only every 2³² cells.
//!
//! The gradient index's statistics (uniform choices, independent neighbours) are tested
//! below. Cellular noise keys its cells' [`CellRng`](super::CellRng) by this hash (the
//! generator's draw mixes every bit of it; `tests/tests/cellular.rs` measures the points'
//! statistics). Integer operations only: the same bits on every target.

use super::cell::mix;

/// A multiplicative hash of lattice points (module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct PrimeHash {
    seed: u32,
}

impl PrimeHash {
    /// One prime per axis (FastNoise Lite's `PrimeX` … `PrimeW`).
    pub(crate) const PRIMES: [u32; 4] = [501_125_321, 1_136_930_381, 1_720_413_743, 1_066_037_191];
    /// The final multiplier (FastNoise Lite's `0x27d4eb2d`).
    pub(crate) const MULTIPLIER: u32 = 0x27D4_EB2D;

    /// The hash for `seed` (mixed, so that seeds 0, 1, 2, … are unrelated).
    pub(crate) const fn new(seed: u32) -> Self {
        Self {
            seed: mix(seed ^ 0x5BD1_E995),
        }
    }

    /// The hash's start: the mixed seed, into which each axis's `c·Pₐ` is folded by `xor`.
    #[inline(always)]
    pub(crate) fn start(&self) -> u32 {
        self.seed
    }

    /// Axis `a`'s term for coordinate `c`: `c·Pₐ` (wrapping).
    #[inline(always)]
    pub(crate) fn axis(a: usize, c: i32) -> u32 {
        (c as u32).wrapping_mul(Self::PRIMES[a & 3])
    }

    /// The hash from the folded terms: the product with the multiplier, whose top bits are
    /// the best mixed (read them with `>>`).
    #[inline(always)]
    pub(crate) fn finish(folded: u32) -> u32 {
        folded.wrapping_mul(Self::MULTIPLIER)
    }

    /// The hash of `cell` (the bodies compute the same from the axes' terms).
    #[inline]
    pub(crate) fn hash<const D: usize>(&self, cell: [i32; D]) -> u32 {
        let mut h = self.start();
        for (a, c) in cell.into_iter().enumerate() {
            h ^= Self::axis(a, c);
        }
        Self::finish(h)
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::PrimeHash;
    use crate::testing::chi2;
    use std::println;

    /// The gradient index a simplex corner reads (the top 4 bits) is uniform over cells, and
    /// independent of its neighbours' along each axis and the diagonal, in 2D and 3D and for
    /// several seeds: χ² of the 16 values (15 degrees of freedom) and of the 256 pairs (255)
    /// below their 10⁻⁶ quantiles (52 and 375). A hash that ignores an axis fails it.
    #[test]
    fn top_bits_are_uniform_and_independent() {
        fn check(dims: usize, hash: impl Fn([i32; 3]) -> u32) -> (f64, f64) {
            let top = |c: [i32; 3]| (hash(c) >> 28) as usize;
            let (n, depth) = if dims == 3 { (40, 40) } else { (250, 1) };
            let mut single = [0u32; 16];
            let mut worst_pair = 0.0f64;
            let steps = [[1, 0, 0], [0, 1, 0], [1, 1, 0], [0, 0, 1], [1, 1, 1]];
            for (k, step) in steps
                .into_iter()
                .enumerate()
                .take(if dims == 3 { 5 } else { 3 })
            {
                let mut pairs = [0u32; 256];
                for x in 0..n {
                    for y in 0..n {
                        for z in 0..depth {
                            let c = [x * 7 - 300, y * 5 + 11, z * 3 - 50];
                            let next = [c[0] + step[0], c[1] + step[1], c[2] + step[2]];
                            if k == 0 {
                                single[top(c)] += 1;
                            }
                            pairs[top(c) * 16 + top(next)] += 1;
                        }
                    }
                }
                worst_pair = worst_pair.max(chi2(&pairs));
            }
            (chi2(&single), worst_pair)
        }
        for seed in [0, 1, 2, 1234, u32::MAX] {
            let h = PrimeHash::new(seed);
            let (single, pair) = check(3, |c| h.hash(c));
            println!("3D seed {seed}: χ² {single:.1}, pairs {pair:.1}");
            assert!(
                single < 52.0 && pair < 375.0,
                "3D seed {seed}: {single} {pair}"
            );
            let (single, pair) = check(2, |[x, y, _]| h.hash([x, y]));
            println!("2D seed {seed}: χ² {single:.1}, pairs {pair:.1}");
            assert!(
                single < 52.0 && pair < 375.0,
                "2D seed {seed}: {single} {pair}"
            );
        }
        let h = PrimeHash::new(0);
        let (_, pair) = check(3, |[x, y, _]| h.hash([x, y]));
        assert!(pair > 375.0, "an ignored axis passes: {pair}");
    }
}

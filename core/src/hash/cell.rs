//! A well-mixed 32-bit hash of integer cells, for the noises that need more than the 8 bits of
//! a permutation per cell: feature points (Worley 1996), impulse positions and weights (Lewis
//! 1989, Gabor noise), random offsets.
//!
//! Each axis is folded into the hash with one round of Wellons' `lowbias32` integer mixer
//! (<https://nullprogram.com/blog/2018/07/31/>, two multiply–xorshift rounds, bias 0.17 of his
//! measure), starting from a mix of the seed: `h = mix(…mix(mix(s ^ x) ^ y)…)`. Integer
//! operations only, so the hash is the same on every target.

use super::chain::{self, ChainHash, Order};
use crate::Real;

/// The multipliers of [`mix`] (vector kernels compute it too).
pub(crate) const MIX: [u32; 2] = [0x7FEB_352D, 0x846C_A68B];

/// Wellons' `lowbias32`: a bijection of `u32` in which each input bit flips each output bit
/// with probability close to ½.
#[inline]
#[must_use]
pub(crate) const fn mix(mut x: u32) -> u32 {
    x ^= x >> 16;
    x = x.wrapping_mul(MIX[0]);
    x ^= x >> 15;
    x = x.wrapping_mul(MIX[1]);
    x ^= x >> 16;
    x
}

/// A well-mixed 32-bit hash of an integer cell and a seed.
///
/// Tested in `tests/tests/hash.rs`: over 10⁶ random cells each input bit (of the cell and of
/// the seed) flips each output bit with probability within 0.5 ± 0.02 (strict avalanche), and
/// the hashes of neighbouring cells are uncorrelated.
///
/// # Examples
///
/// ```
/// use bandnoise::hash::CellHash;
///
/// let h = CellHash::new(7);
/// assert_ne!(h.hash([0, 0]), h.hash([1, 0]));
/// assert_ne!(h.hash([0, 0]), CellHash::new(8).hash([0, 0]));
/// // Every target computes the same bits.
/// assert_eq!(CellHash::new(0).hash([1, 2, 3]), CellHash::new(0).hash([1, 2, 3]));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct CellHash {
    start: u32,
}

impl CellHash {
    /// The hash for `seed`.
    #[must_use]
    pub const fn new(seed: u32) -> Self {
        // Mixing the seed (and a constant) first keeps seeds 0, 1, 2, … from giving related
        // first steps.
        Self {
            start: mix(seed ^ 0x9E37_79B9),
        }
    }

    /// The chain's first value, into which the first axis is folded by
    /// [`ChainHash::step`] (walks that share prefixes start from it).
    #[inline]
    pub(crate) fn start(&self) -> u32 {
        self.start
    }

    /// The hash of `cell` (1 to 4 or more dimensions).
    #[inline]
    #[must_use]
    pub fn hash<const D: usize>(&self, cell: [i32; D]) -> u32 {
        chain::cell(Order::XFirst, self.start, cell.map(|c| c as u32), |h, c| {
            self.step(h, c)
        })
    }
}

impl CellHash {
    /// Calls `visit(digits, hash, d²)` for each cell of a box around a point that is within
    /// `reach` of it (`d²`: its squared distance), in a fixed order: the box is `N` cells along each axis, axis `a`'s `k`th
    /// being `cells[a][k]` at squared distance `gaps[a][k]` from the point along that axis; a
    /// cell is within reach when the sum of its axes' squared distances is below `reach`.
    ///
    /// The cells are visited as an odometer over the axes, the first axis slowest, so the
    /// hash's chain (first axis folded first) shares its prefixes, and a prefix of axes whose
    /// distances alone reach `reach` skips all the cells beyond it at once.
    #[inline]
    pub(crate) fn near<R: Real, const D: usize, const N: usize>(
        &self,
        cells: &[[u32; N]; D],
        gaps: &[[R; N]; D],
        reach: R,
        mut visit: impl FnMut(&[usize; D], u32, R),
    ) {
        // `digit[a]` is axis a's box index; `chain[a]` and `gap[a]` are the hash and the
        // squared distance over axes 0..=a; axes from `from` on need recomputing.
        let mut digit = [0usize; D];
        let mut chain = [0u32; D];
        let mut gap = [R::ZERO; D];
        let mut from = 0;
        loop {
            let mut reached = true;
            for a in from..D {
                let (h, g) = if a == 0 {
                    (self.start, R::ZERO)
                } else {
                    (chain[a - 1], gap[a - 1])
                };
                // `min` says the digit is in the box to the compiler (no bounds check).
                let o = digit[a].min(N - 1);
                gap[a] = g + gaps[a][o];
                if gap[a] >= reach {
                    // Every cell with this prefix is out of reach: skip them all.
                    for d in digit.iter_mut().skip(a + 1) {
                        *d = N - 1;
                    }
                    reached = false;
                    break;
                }
                chain[a] = self.step(h, cells[a][o]);
            }
            if reached {
                visit(&digit, chain[D - 1], gap[D - 1]);
            }
            // The next cell: the last axis fastest.
            let mut a = D;
            loop {
                if a == 0 {
                    return;
                }
                a -= 1;
                digit[a] += 1;
                if digit[a] < N {
                    break;
                }
                digit[a] = 0;
            }
            from = a;
        }
    }
}

impl ChainHash for CellHash {
    /// Coordinates are used whole: the period is 2³² (`u32::MAX` stands for it).
    const PERIOD: u32 = u32::MAX;
    #[inline]
    fn reduce(c: i32) -> u32 {
        c as u32
    }
    #[inline]
    fn step(&self, h: u32, c: u32) -> u32 {
        mix(h ^ c)
    }
}

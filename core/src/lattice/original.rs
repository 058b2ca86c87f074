//! Perlin's original noise (Perlin 1985, "An Image Synthesizer"): gradient noise with the cubic
//! fade `3t² − 2t³` and a table of random gradient vectors indexed by a permutation hash.
//!
//! The gradient tables are generated at compile time by a `const fn` (rejection sampling of the
//! unit ball, normalised, from SplitMix64), stored as `i16` with 14 fraction bits so every number
//! type starts from the same gradients.

use super::kernel::{Cubic, MAX_CORNERS};
use super::periodic::WrapCorners;
use super::{Lattice, gradient_corners, lattice_noise_impls};
use crate::Real;
use crate::hash::chain::{self, ChainHash, Order, Wrap};
use crate::hash::{Permutation, seed::splitmix64};

/// Fraction bits of the stored gradients.
const Q: u32 = 14;

/// `sqrt` for `const` evaluation: Newton's iteration from a good start, for `x` in `[1e-4, 1]`.
const fn const_sqrt(x: f64) -> f64 {
    let mut r = 1.0;
    let mut i = 0;
    while i < 40 {
        r = 0.5 * (r + x / r);
        i += 1;
    }
    r
}

/// 256 gradients in `D` dimensions: uniform directions (unit length) for `D ≥ 2`, uniform in
/// `[-1, 1]` for `D = 1` as in Perlin's 1985 code, in Q1.14. Components are rounded toward zero,
/// so no stored vector is longer than 1.
const fn gradient_table<const D: usize>(seed: u64) -> [[i16; D]; 256] {
    let mut out = [[0i16; D]; 256];
    let mut state = seed;
    let mut i = 0;
    while i < 256 {
        let mut v = [0.0f64; D];
        let mut len2 = 0.0;
        let mut a = 0;
        while a < D {
            let (s, r) = splitmix64(state);
            state = s;
            v[a] = (r >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0;
            len2 += v[a] * v[a];
            a += 1;
        }
        if D == 1 || (len2 <= 1.0 && len2 >= 1e-4) {
            let scale = if D == 1 { 1.0 } else { 1.0 / const_sqrt(len2) };
            let mut a = 0;
            while a < D {
                out[i][a] = (v[a] * scale * (1 << Q) as f64) as i16; // truncates toward 0
                a += 1;
            }
            i += 1;
        }
    }
    out
}

static GRAD1: [[i16; 1]; 256] = gradient_table::<1>(0x1985_0001);
static GRAD2: [[i16; 2]; 256] = gradient_table::<2>(0x1985_0002);
static GRAD3: [[i16; 3]; 256] = gradient_table::<3>(0x1985_0003);
static GRAD4: [[i16; 4]; 256] = gradient_table::<4>(0x1985_0004);

/// Perlin's original 1985 noise in 1 to 4 dimensions.
///
/// * **Hash**: the seed's [`Permutation`], x innermost (as [`Perlin`](super::Perlin)).
/// * **Gradients**: a compile-time table of 256 random unit vectors per dimension (`[-1, 1]`
///   slopes in 1D), indexed by the hash; the seed changes the permutation, not the table.
/// * **Fade**: cubic `3t² − 2t³`, so the noise is C¹ (its second derivative jumps at cell faces:
///   the artifact Perlin's 2002 quintic removed).
/// * **Range**: `|n| ≤ √D/2` (unit gradients; module docs of [`lattice`](super)).
///
/// # Examples
///
/// ```
/// use bandnoise::{Noise, lattice::OriginalPerlin};
///
/// let n: f32 = OriginalPerlin::new(1).sample([0.5, 0.5, 0.5]);
/// assert!(n.abs() <= 3f32.sqrt() / 2.0);
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct OriginalPerlin {
    perm: Permutation,
}

impl OriginalPerlin {
    /// Original noise for `seed`.
    #[must_use]
    pub const fn new(seed: u32) -> Self {
        Self {
            perm: Permutation::new(seed),
        }
    }
}

impl Default for OriginalPerlin {
    fn default() -> Self {
        Self::new(0)
    }
}

/// The gradient table for each dimension.
trait Table<const D: usize> {
    fn table() -> &'static [[i16; D]; 256];
}
impl Table<1> for OriginalPerlin {
    fn table() -> &'static [[i16; 1]; 256] {
        &GRAD1
    }
}
impl Table<2> for OriginalPerlin {
    fn table() -> &'static [[i16; 2]; 256] {
        &GRAD2
    }
}
impl Table<3> for OriginalPerlin {
    fn table() -> &'static [[i16; 3]; 256] {
        &GRAD3
    }
}
impl Table<4> for OriginalPerlin {
    fn table() -> &'static [[i16; 4]; 256] {
        &GRAD4
    }
}

impl<const D: usize> Lattice<D> for OriginalPerlin
where
    OriginalPerlin: Table<D>,
{
    type Fade = Cubic;
    #[inline]
    fn corner_hashes(&self, cell: [i32; D]) -> [u32; MAX_CORNERS] {
        let (lower, upper) = chain::natural::<Permutation, D>(cell);
        chain::corners(Order::XFirst, 0, lower, upper, |h, c| self.perm.step(h, c))
    }
    gradient_corners!(D, mul_rn);
    #[inline]
    fn gradient<R: Real>(&self, h: u32) -> [R; D] {
        <Self as Table<D>>::table()[(h & 255) as usize].map(|g| R::from_ratio(g as i32, Q))
    }
}

fn sqrt_dims_half(dims: usize) -> f32 {
    libm::sqrtf(dims as f32) * 0.5 + super::ROUNDING
}

lattice_noise_impls!(OriginalPerlin, [], |_, d| sqrt_dims_half(d));
crate::noise::inherent_amplitude_bound!(OriginalPerlin, []);

impl<const D: usize> WrapCorners<D> for OriginalPerlin {
    #[inline]
    fn corner_hashes_wrapped(&self, cell: [i32; D], wrap: &Wrap<D>) -> [u32; MAX_CORNERS] {
        wrap.corner_hashes(&self.perm, Order::XFirst, 0, cell, [0; D])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gradients_are_unit_or_shorter() {
        fn check<const D: usize>(t: &[[i16; D]; 256]) {
            for g in t {
                let len2: f64 = g.iter().map(|&c| (c as f64 / 16384.0).powi(2)).sum();
                assert!(len2 <= 1.0 + 1e-12);
                if D > 1 {
                    assert!(len2 > 0.999, "{len2}");
                }
            }
        }
        check(&GRAD1);
        check(&GRAD2);
        check(&GRAD3);
        check(&GRAD4);
    }
}

//! Value noise (pbrt §10.6 introduction; Lewis 1989 §2 "lattice noise"): a pseudo-random value
//! at every lattice point, blended across the cell with the quintic fade.
//!
//! Cheap and easy, but not band-limited: interpolated white noise keeps much low-frequency energy
//! and visible grid structure (Lewis 1989 §2; Olano 2005 §2). It is here as the baseline the
//! better noises are compared against.

use super::kernel::{MAX_CORNERS, Quintic};
use super::periodic::WrapCorners;
use super::{Lattice, lattice_noise_impls};
use crate::Real;
use crate::hash::Permutation;
use crate::hash::chain::{self, ChainHash, Order, Wrap};

/// Value noise in 1 to 4 dimensions.
///
/// * **Hash**: the seed's [`Permutation`], x innermost, cells mod 256.
/// * **Lattice values**: `(2h − 255)/256` for the hash `h`, i.e. 256 evenly spaced values in
///   `[-255/256, 255/256]` (exact in every number type).
/// * **Range**: `|n| ≤ 255/256` (a convex blend of lattice values), plus 2⁻¹⁰ for rounding.
///
/// # Examples
///
/// ```
/// use bandnoise::{Noise, hash::PERLIN_2002, lattice::ValueNoise};
///
/// let v = ValueNoise::new(0);
/// // On the lattice it is the lattice value of the hash p[p[0] + 0].
/// let h = PERLIN_2002[PERLIN_2002[0] as usize] as f64;
/// assert_eq!(v.sample([0.0f64, 0.0]), (2.0 * h - 255.0) / 256.0);
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ValueNoise {
    perm: Permutation,
}

impl ValueNoise {
    /// Value noise for `seed`.
    #[must_use]
    pub const fn new(seed: u32) -> Self {
        Self {
            perm: Permutation::new(seed),
        }
    }
}

impl Default for ValueNoise {
    fn default() -> Self {
        Self::new(0)
    }
}

/// A value lattice: a corner contributes its value wherever the point is, and the gradient
/// of a contribution is zero (the noise's gradient comes from the fade alone).
impl<const D: usize> Lattice<D> for ValueNoise {
    type Fade = Quintic;
    type Corner<R: Real> = R;
    /// Perlin's chain, axis 0 innermost.
    #[inline]
    fn corner_hashes(&self, cell: [i32; D]) -> [u32; MAX_CORNERS] {
        let (lower, upper) = chain::natural::<Permutation, D>(cell);
        chain::corners(Order::XFirst, 0, lower, upper, |h, c| self.perm.step(h, c))
    }
    #[inline]
    fn corner<R: Real>(&self, h: u32) -> R {
        R::from_ratio(2 * h as i32 - 255, 8)
    }
    #[inline]
    fn contribution<R: Real>(&self, value: &R, _: &[R; D]) -> R {
        *value
    }
    #[inline]
    fn gradient<R: Real>(&self, _: u32) -> [R; D] {
        [R::ZERO; D]
    }
}

lattice_noise_impls!(ValueNoise, [], |_, _| 255.0 / 256.0 + super::ROUNDING);
crate::noise::inherent_amplitude_bound!(ValueNoise, []);

impl<const D: usize> WrapCorners<D> for ValueNoise {
    #[inline]
    fn corner_hashes_wrapped(&self, cell: [i32; D], wrap: &Wrap<D>) -> [u32; MAX_CORNERS] {
        wrap.corner_hashes(&self.perm, Order::XFirst, 0, cell, [0; D])
    }
}

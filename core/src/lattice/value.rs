//! Value noise (pbrt §10.6 introduction; Lewis 1989 §2 "lattice noise"): a pseudo-random value
//! at every lattice point, blended across the cell with the quintic fade.
//!
//! Cheap and easy, but not band-limited: interpolated white noise keeps much low-frequency energy
//! and visible grid structure (Lewis 1989 §2; Olano 2005 §2). It is here as the baseline the
//! better noises are compared against.

use super::kernel::{
    Fade, MAX_CORNERS, Quintic, fade_all, hash_corners_x_first, interpolate, split_point,
};
use super::{interpolate_lanes, split_lanes};
use crate::batch::{LANES, lane};
use crate::hash::Permutation;
use crate::{Noise, Real};

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

impl<R: Real, const D: usize> Noise<R, D> for ValueNoise {
    #[inline]
    fn sample(&self, p: [R; D]) -> R {
        let (cell, f) = split_point(p);
        let cells = cell.map(|c| (c & 255) as u32);
        let h = hash_corners_x_first(cells, 0, |h, c| self.perm.get(h + c));
        let mut v = [R::ZERO; MAX_CORNERS];
        for m in 0..(1 << D) {
            v[m] = R::from_ratio(2 * h[m] as i32 - 255, 8);
        }
        interpolate(v, &fade_all::<Quintic, R, D>(f)).canonical()
    }

    fn amplitude_bound(&self) -> f32 {
        255.0 / 256.0 + super::ROUNDING
    }

    #[inline]
    #[allow(
        clippy::needless_range_loop,
        reason = "the lane index transposes: it addresses cells and corner values alike"
    )]
    fn sample_lanes(&self, p: &[[R; LANES]; D], out: &mut [R; LANES]) {
        let (cell, f) = split_lanes(p);
        let mut v = [[R::ZERO; LANES]; MAX_CORNERS];
        for l in 0..LANES {
            let cells = lane(&cell, l).map(|c| (c & 255) as u32);
            let h = hash_corners_x_first(cells, 0, |h, c| self.perm.get(h + c));
            for m in 0..(1 << D) {
                v[m][l] = R::from_ratio(2 * h[m] as i32 - 255, 8);
            }
        }
        interpolate_lanes(&mut v, &f.map(|fa| fa.map(Quintic::fade)));
        *out = v[0].map(R::canonical);
    }
}

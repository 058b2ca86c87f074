//! Value noise (pbrt §10.6 introduction; Lewis 1989 §2 "lattice noise"): a pseudo-random value
//! at every lattice point, blended across the cell with the quintic fade.
//!
//! Cheap and easy, but not band-limited: interpolated white noise keeps much low-frequency energy
//! and visible grid structure (Lewis 1989 §2; Olano 2005 §2). It is here as the baseline the
//! better noises are compared against.

use super::kernel::{
    Fade, MAX_CORNERS, Quintic, fade_all, interpolate, interpolate_with_gradient, split_point,
};
use super::periodic::WrapCorners;
use super::{interpolate_lanes, split_lanes};
use crate::batch::{LANES, lane};
use crate::hash::Permutation;
use crate::hash::chain::{self, ChainHash, Order, Wrap};
use crate::{Noise, NoiseGradient, Real};

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

impl ValueNoise {
    /// The lattice values' hashes at the corners of `cell` (Perlin's chain, axis 0 innermost).
    #[inline]
    fn corners<const D: usize>(&self, cell: [i32; D]) -> [u32; MAX_CORNERS] {
        let (lower, upper) = chain::natural::<Permutation, D>(cell);
        chain::corners(Order::XFirst, 0, lower, upper, |h, c| self.perm.step(h, c))
    }

    /// The noise at `p` with the corners hashed by `corners` (the plain chain, or a wrapped
    /// one for [`Periodic`](super::Periodic)).
    #[inline]
    pub(super) fn sample_corners<R: Real, const D: usize>(
        &self,
        p: [R; D],
        corners: impl Fn([i32; D]) -> [u32; MAX_CORNERS],
    ) -> R {
        let (cell, f) = split_point(p);
        let h = corners(cell);
        let mut v = [R::ZERO; MAX_CORNERS];
        for m in 0..(1 << D) {
            v[m] = R::from_ratio(2 * h[m] as i32 - 255, 8);
        }
        interpolate(v, &fade_all::<Quintic, R, D>(f)).canonical()
    }

    /// [`sample_corners`](Self::sample_corners) and its analytic gradient: the lattice values
    /// are constants, so `∂n/∂x_a = Σ_c ∂W_c/∂x_a v_c` (the fade's derivative). The value is the
    /// same expression as `sample_corners`'.
    #[inline]
    pub(super) fn sample_corners_with_gradient<R: Real, const D: usize>(
        &self,
        p: [R; D],
        corners: impl Fn([i32; D]) -> [u32; MAX_CORNERS],
    ) -> (R, [R; D]) {
        let (cell, f) = split_point(p);
        let h = corners(cell);
        let mut v = [R::ZERO; MAX_CORNERS];
        for m in 0..(1 << D) {
            v[m] = R::from_ratio(2 * h[m] as i32 - 255, 8);
        }
        let s = fade_all::<Quintic, R, D>(f);
        let ds = f.map(Quintic::fade_derivative);
        interpolate_with_gradient(v, &[[R::ZERO; D]; MAX_CORNERS], &s, &ds)
    }

    /// [`sample_corners`](Self::sample_corners) over [`LANES`] points, bit-identical to it.
    #[inline]
    #[allow(
        clippy::needless_range_loop,
        reason = "the lane index transposes: it addresses cells and corner values alike"
    )]
    pub(super) fn sample_corners_lanes<R: Real, const D: usize>(
        &self,
        p: &[[R; LANES]; D],
        out: &mut [R; LANES],
        corners: impl Fn([i32; D]) -> [u32; MAX_CORNERS],
    ) {
        let (cell, f) = split_lanes(p);
        let mut v = [[R::ZERO; LANES]; MAX_CORNERS];
        for l in 0..LANES {
            let h = corners(lane(&cell, l));
            for m in 0..(1 << D) {
                v[m][l] = R::from_ratio(2 * h[m] as i32 - 255, 8);
            }
        }
        interpolate_lanes(&mut v, &f.map(|fa| fa.map(Quintic::fade)));
        *out = v[0].map(R::canonical);
    }
}

impl<R: Real, const D: usize> Noise<R, D> for ValueNoise {
    #[inline]
    fn sample(&self, p: [R; D]) -> R {
        self.sample_corners(p, |cell| self.corners(cell))
    }

    fn amplitude_bound(&self) -> f32 {
        255.0 / 256.0 + super::ROUNDING
    }

    #[inline]
    fn sample_lanes(&self, p: &[[R; LANES]; D], out: &mut [R; LANES]) {
        self.sample_corners_lanes(p, out, |cell| self.corners(cell));
    }
}

impl<R: Real, const D: usize> NoiseGradient<R, D> for ValueNoise {
    #[inline]
    fn sample_with_gradient(&self, p: [R; D]) -> (R, [R; D]) {
        self.sample_corners_with_gradient(p, |cell| self.corners(cell))
    }
}

crate::noise::inherent_amplitude_bound!(ValueNoise, []);

impl<const D: usize> WrapCorners<D> for ValueNoise {
    #[inline]
    fn corner_hashes_wrapped(&self, cell: [i32; D], wrap: &Wrap<D>) -> [u32; MAX_CORNERS] {
        wrap.corner_hashes(&self.perm, Order::XFirst, 0, cell, [0; D])
    }
}

//! Olano's corner-gradient noises (Olano 2005, "Modified Noise for Evaluation on Graphics
//! Hardware", §3.2–3.3): cNoise and mNoise.
//!
//! Both take gradients on the corners of the cube, `(±1, ±1, ±1)`, one sign per hash bit, so the
//! gradient's dot product in D dimensions is the same sum as in D+1 dimensions with the extra
//! offset 0 (§3.2). With a hash chained last-axis-innermost, `hash(x + hash(y + hash(z)))`, the
//! 3D hash at `z = 0` is the 2D hash too, which makes the noise *dimension reducible*:
//! `noise3(x, y, 0) == noise2(x, y)`, bit for bit.

use super::kernel::{MAX_CORNERS, Quintic};
use super::periodic::WrapCorners;
use super::{Lattice, gradient_corners, half_dims, lattice_noise_impls, signed};
use crate::Real;
use crate::batch::LANES;
use crate::hash::chain::{self, ChainHash, Order, Wrap};
use crate::hash::{Bbs, Permutation, seed::splitmix64};

/// `Σ_a ±d_a` with the sign of axis `a` from bit `a` of `h`.
#[inline]
pub(super) fn corner_dot<R: Real, const D: usize>(h: u32, d: &[R; D]) -> R {
    let mut sum = signed(h, 0, d[0]);
    for (a, x) in d.iter().enumerate().skip(1) {
        sum = sum + signed(h, a as u32, *x);
    }
    sum
}

#[inline]
pub(super) fn corner_gradient<R: Real, const D: usize>(h: u32) -> [R; D] {
    let mut g = [R::ZERO; D];
    for (a, ga) in g.iter_mut().enumerate() {
        *ga = signed(h, a as u32, R::ONE);
    }
    g
}

/// Olano's **mNoise**: corner gradients and the Blum-Blum-Shub hash `x² mod M`, no tables at all.
///
/// * **Hash**: `hash(x + hash(y + hash(z + hash(w))))` with `hash(x) = x² mod M`
///   ([`Bbs`]), every cell reduced mod `M`, so the noise is periodic with period `M` on every
///   axis (`noise(x + M, y) == noise(x, y)`, bit for bit in fixed point).
/// * **Gradient**: `(±1, …, ±1)`, the sign of axis `a` from bit `a` of the hash.
/// * **Seed**: the seed picks a translation `o ∈ [0, M)⁴` of the lattice and a sign mask for
///   the gradient axes, both from SplitMix64 of the seed; seed 0 is Olano's noise unchanged
///   (no translation, no flips). A lower dimension is the slice at 0 of the 4D noise of the same
///   seed, so dimension reducibility holds for every seed. With `M = 61` there are at most
///   `61^D · 2^D` distinct seeded noises per dimension: seeds are cheap, not unlimited. In 2D
///   there are exactly 61² · 4 = 14884 (counted over 300 000 seeds), so two random seeds give
///   the same 2D noise with probability 1/14884, and seeds whose translations lie within about
///   a cell of each other (mod `M`) give correlated noises: about 1% of random seed pairs
///   correlate at 0.1 or more in 2D (`tests/tests/properties.rs`). Use `MNoise<4093>` when
///   many independent seeds matter.
/// * **Range**: `|n| ≤ D/2` (module docs of [`lattice`](super)). A cell whose corner
///   gradients all point outward would reach it at its centre, but the BBS hash does not
///   produce one beyond 2D: over every cell centre of `MNoise<61>` (one period, `61^D` cells,
///   any seed) the largest `|n|` is 0.5, 1, 1.375 and 1.375 in 1D–4D (test
///   `mnoise_maxima_over_cell_centres`), and over random points 0.500, 1.000, 1.271 and 1.302
///   (`statistics.rs`).
///
/// # Examples
///
/// ```
/// use bandnoise::{I16F16, Noise, lattice::MNoise};
///
/// let m = MNoise::<61>::new(9);
/// let x = I16F16::from_num(12.375);
/// let y = I16F16::from_num(-3.5);
/// let z = I16F16::ZERO;
/// // Dimension reducible and periodic, bit for bit.
/// assert_eq!(m.sample([x, y, z]), m.sample([x, y]));
/// assert_eq!(m.sample([x + I16F16::from_num(61), y]), m.sample([x, y]));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MNoise<const M: u32 = 61> {
    pub(super) offset: [u32; 4],
    pub(super) flip: u32,
    pub(super) inner: [u32; 4],
}

impl MNoise {
    /// Olano's mNoise, with his modulus `M = 61`, for `seed` (0: his noise). For another
    /// modulus, [`MNoise::<M>::seeded`](MNoise::seeded).
    ///
    /// ```
    /// use bandnoise::{Noise, lattice::MNoise};
    ///
    /// let m = MNoise::new(7);
    /// assert_eq!(m, MNoise::<61>::seeded(7));
    /// let v: f32 = m.sample([0.5, 0.25]);
    /// # let _ = v;
    /// ```
    #[must_use]
    pub const fn new(seed: u32) -> Self {
        Self::seeded(seed)
    }
}

impl<const M: u32> MNoise<M> {
    /// mNoise with modulus `M` for `seed` (0: Olano's noise): `MNoise::<4093>::seeded(7)`.
    /// (`new` is the common case, `M = 61`: a default type parameter does not apply where the
    /// type is inferred, so `MNoise::new` is defined for 61 only.)
    #[must_use]
    pub const fn seeded(seed: u32) -> Self {
        let (offset, flip) = if seed == 0 {
            ([0; 4], 0)
        } else {
            let (_, r) = splitmix64(seed as u64);
            let mut o = [0u32; 4];
            let mut a = 0;
            while a < 4 {
                o[a] = ((r >> (12 * a)) & 0xFFF) as u32 % M;
                a += 1;
            }
            (o, (r >> 60) as u32)
        };
        // inner[D-1]: fold of the missing axes D..4 at cell 0, last axis innermost.
        let mut inner = [0u32; 4];
        let mut h = 0u32;
        let mut a = 3;
        while a > 0 {
            h = Bbs::<M>::step(h + offset[a]);
            inner[a - 1] = h;
            a -= 1;
        }
        Self {
            offset,
            flip,
            inner,
        }
    }

    /// The period on every axis.
    pub const PERIOD: u32 = M;
}

impl<const M: u32> Default for MNoise<M> {
    fn default() -> Self {
        Self::seeded(0)
    }
}

impl<const M: u32, const D: usize> Lattice<D> for MNoise<M> {
    type Fade = Quintic;
    #[inline]
    fn corner_hashes(&self, cell: [i32; D]) -> [u32; MAX_CORNERS] {
        // In 0..M, so `c + 1 + h` in the chain stays within 2M.
        let cells: [u32; D] =
            core::array::from_fn(|a| Bbs::<M>::reduce_offset(cell[a], self.offset[a]));
        let upper = cells.map(|c| c + 1);
        chain::corners(Order::LastFirst, self.inner[D - 1], cells, upper, |h, c| {
            Bbs::<M>.step(h, c)
        })
    }
    #[inline]
    fn corner_hashes_lanes(&self, cell: &[[i32; LANES]; D]) -> [[u32; LANES]; MAX_CORNERS] {
        let cells: [[u32; LANES]; D] = core::array::from_fn(|a| {
            let r = Bbs::<M>::reduce_lanes(&cell[a]);
            r.map(|r| {
                let c = r + self.offset[a];
                if c >= M { c - M } else { c }
            })
        });
        let upper = cells.map(|c| c.map(|c| c + 1));
        chain::corners(
            Order::LastFirst,
            [self.inner[D - 1]; LANES],
            cells,
            upper,
            |h, c| core::array::from_fn(|l| Bbs::<M>.step(h[l], c[l])),
        )
    }
    gradient_corners!(D, mul_rn);
    #[inline]
    fn dot<R: Real>(&self, h: u32, d: &[R; D]) -> R {
        corner_dot(h ^ self.flip, d)
    }
    #[inline]
    fn gradient<R: Real>(&self, h: u32) -> [R; D] {
        corner_gradient(h ^ self.flip)
    }
}

lattice_noise_impls!(MNoise<M>, [const M: u32], |_, d| half_dims(d));
crate::noise::inherent_amplitude_bound!(MNoise<M>, [const M: u32]);

impl<const M: u32, const D: usize> WrapCorners<D> for MNoise<M> {
    /// The seed's translation moves the lattice within the period, so a period of `M` is the
    /// noise itself.
    #[inline]
    fn corner_hashes_wrapped(&self, cell: [i32; D], wrap: &Wrap<D>) -> [u32; MAX_CORNERS] {
        let shift = core::array::from_fn(|a| self.offset[a]);
        wrap.corner_hashes(&Bbs::<M>, Order::LastFirst, self.inner[D - 1], cell, shift)
    }
}

/// Olano's **cNoise**: corner gradients with a permutation hash.
///
/// * **Hash**: the seed's [`Permutation`] (seed 0: Perlin's 2002 table), chained last axis
///   innermost, `p[(x + p[(y + p[(z + p[w]) & 255]) & 255]) & 255]`, cells mod 256 (period 256).
///   As for [`MNoise`], a lower dimension is the slice at 0 of the higher one, bit for bit (Olano
///   notes the plain permutation chain reduces only up to an offset `permute⁻¹(0)`; starting each
///   dimension's chain from the folded missing axes removes that offset).
/// * **Gradient**: `(±1, …, ±1)` from the low bits of the hash.
/// * **Range**: `|n| ≤ D/2`.
///
/// # Examples
///
/// ```
/// use bandnoise::{Noise, lattice::CNoise};
///
/// let c = CNoise::new(0);
/// assert_eq!(c.sample([0.3f32, 0.6, 0.0, 0.0]), c.sample([0.3f32, 0.6]));
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CNoise {
    perm: Permutation,
    inner: [u32; 4],
}

impl CNoise {
    /// cNoise for `seed`.
    #[must_use]
    pub const fn new(seed: u32) -> Self {
        let perm = Permutation::new(seed);
        let mut inner = [0u32; 4];
        let mut h = 0u32;
        let mut a = 3;
        while a > 0 {
            h = perm.get(h);
            inner[a - 1] = h;
            a -= 1;
        }
        Self { perm, inner }
    }
}

impl Default for CNoise {
    fn default() -> Self {
        Self::new(0)
    }
}

impl<const D: usize> Lattice<D> for CNoise {
    type Fade = Quintic;
    #[inline]
    fn corner_hashes(&self, cell: [i32; D]) -> [u32; MAX_CORNERS] {
        let (lower, upper) = chain::natural::<Permutation, D>(cell);
        chain::corners(Order::LastFirst, self.inner[D - 1], lower, upper, |h, c| {
            self.perm.step(h, c)
        })
    }
    gradient_corners!(D, mul_rn);
    #[inline]
    fn dot<R: Real>(&self, h: u32, d: &[R; D]) -> R {
        corner_dot(h, d)
    }
    #[inline]
    fn gradient<R: Real>(&self, h: u32) -> [R; D] {
        corner_gradient(h)
    }
}

lattice_noise_impls!(CNoise, [], |_, d| half_dims(d));
crate::noise::inherent_amplitude_bound!(CNoise, []);

impl<const D: usize> WrapCorners<D> for CNoise {
    #[inline]
    fn corner_hashes_wrapped(&self, cell: [i32; D], wrap: &Wrap<D>) -> [u32; MAX_CORNERS] {
        wrap.corner_hashes(
            &self.perm,
            Order::LastFirst,
            self.inner[D - 1],
            cell,
            [0; D],
        )
    }
}

//! Evaluation of one noise band (Cook & DeRose 2005, §3.6 and Appendix 2, with erratum 6), and
//! tile repetition with hashed orientations (§4.3).
//!
//! `N(p) = Σ_c n_c B(p − c)`: the quadratic B-spline through the tile's coefficients, 3 per axis
//! (3ᵈ in all). Coefficient `c` sits at integer position `c` of the coefficient grid.
//!
//! **Seams.** With [`Tiling::Varied`], each tile-sized block of the coefficient grid reads the
//! tile in one of its 48 orientations (6 axis permutations × 8 reflections; 8 in 2D), chosen by
//! a hash of the block coordinate and the seed. A coefficient's value depends only on its global
//! index, so `N` stays a quadratic B-spline of one coefficient grid: continuous with a continuous
//! gradient across block borders, with no blending and hence none of the variance loss that
//! §4.3's overlap blending must correct. What a border costs is band-limitedness: the two blocks'
//! coefficients are unrelated there. The spectrum test (`tests/tests/wavelet.rs`) measures that
//! leak and finds it small (the figures are printed there).

use crate::batch::{LANES, lane};
use crate::{Noise, Real};

use super::tile::{Tile2, Tile3};

/// Coefficient storage a wavelet noise reads: the `f32` tiles and the quantized tiles, or a
/// user's own.
///
/// Any coefficients are accepted: the weighted sums saturate in fixed point (a plain band's
/// weights sum to 1, but rounding can overshoot a coefficient at the end of I16F16's range by
/// an ulp; projected weights sum to up to 3), so an extreme tile gives ±`I16F16::MAX`, never a
/// wrapped value. For the bounds to hold, `max_abs` must be the largest `|coefficient|`.
pub trait TileData<const D: usize> {
    /// The side of the tile.
    const SIZE: usize;
    /// The coefficient at an in-range index (each component below `SIZE`; index 0 is x).
    fn get<R: Real>(&self, index: [usize; D]) -> R;
    /// The coefficient at flat index `x + SIZE·y (+ SIZE²·z)`, below `SIZE^D`.
    fn flat<R: Real>(&self, index: usize) -> R;
    /// The largest `|coefficient|`.
    fn max_abs(&self) -> f32;
}

impl<const N: usize> TileData<2> for Tile2<N> {
    const SIZE: usize = N;
    #[inline]
    fn get<R: Real>(&self, [x, y]: [usize; 2]) -> R {
        self.flat(x + N * y)
    }
    #[inline]
    fn flat<R: Real>(&self, index: usize) -> R {
        // In range by construction; `get` keeps sampling provably panic-free.
        R::from_f32(self.data.as_flattened().get(index).copied().unwrap_or(0.0))
    }
    fn max_abs(&self) -> f32 {
        self.max_abs
    }
}

impl<const N: usize> TileData<3> for Tile3<N> {
    const SIZE: usize = N;
    #[inline]
    fn get<R: Real>(&self, [x, y, z]: [usize; 3]) -> R {
        self.flat(x + N * (y + N * z))
    }
    #[inline]
    fn flat<R: Real>(&self, index: usize) -> R {
        // In range by construction; `get` keeps sampling provably panic-free.
        let coefficients = self.data.as_flattened().as_flattened();
        R::from_f32(coefficients.get(index).copied().unwrap_or(0.0))
    }
    fn max_abs(&self) -> f32 {
        self.max_abs
    }
}

/// How the tile repeats over space.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Tiling {
    /// The tile repeats unchanged: the noise is periodic with the tile's size in coefficients.
    Periodic,
    /// Each tile-sized block uses one of the tile's 48 orientations (8 in 2D), chosen by a hash
    /// of the block and the seed (§4.3): no visible repetition, and still continuous.
    #[default]
    Varied,
}

/// One band of wavelet noise over a tile `T`, in 2D or 3D (the tile's dimension).
///
/// Sampling follows the [`Noise`] contract: never panics; NaN and ±∞ coordinates are 0; cells
/// beyond `i32` wrap; the result is finite, never `-0.0`, and within
/// [`amplitude_bound`](Noise::amplitude_bound) (the tile's largest coefficient).
///
/// # Examples
///
/// ```
/// use bandnoise::{Noise, wavelet::{Tile3, Wavelet}};
///
/// static TILE: Tile3<16> = Tile3::generate(1);
/// let band = Wavelet::new(42, &TILE);
/// let v: f32 = band.sample([0.5, 1.25, -3.0]);
/// assert!(v.is_finite());
/// ```
#[derive(Debug)]
pub struct Wavelet<'t, T> {
    tile: &'t T,
    seed: u32,
    tiling: Tiling,
}

// By hand: derived impls would demand `T: Clone`, but only a reference is copied.
impl<T> Clone for Wavelet<'_, T> {
    fn clone(&self) -> Self {
        *self
    }
}
impl<T> Copy for Wavelet<'_, T> {}

/// Equal seed, tiling and tile (compared by value; the same tile by address first).
impl<T: PartialEq> PartialEq for Wavelet<'_, T> {
    fn eq(&self, other: &Self) -> bool {
        self.seed == other.seed
            && self.tiling == other.tiling
            && (core::ptr::eq(self.tile, other.tile) || self.tile == other.tile)
    }
}

impl<'t, T> Wavelet<'t, T> {
    /// A band over `tile`, with hashed orientations ([`Tiling::Varied`]) chosen by `seed`
    /// (the seed first, as in every noise's constructor).
    #[must_use]
    pub const fn new(seed: u32, tile: &'t T) -> Self {
        Self {
            tile,
            seed,
            tiling: Tiling::Varied,
        }
    }

    /// The same band with another tiling.
    #[must_use]
    pub const fn with_tiling(mut self, tiling: Tiling) -> Self {
        self.tiling = tiling;
        self
    }

    /// The tile.
    #[must_use]
    pub const fn tile(&self) -> &'t T {
        self.tile
    }

    /// The tiling.
    #[must_use]
    pub const fn tiling(&self) -> Tiling {
        self.tiling
    }

    /// The seed.
    #[must_use]
    pub const fn seed(&self) -> u32 {
        self.seed
    }
}

/// Quadratic B-spline weights along one axis: the first of the three coefficients and their
/// weights `((1−f)²/2, 1 − …, f²/2)`, with `f` the fraction of `x − ½` (Appendix 2).
#[inline]
pub(crate) fn bspline3<R: Real>(x: R) -> (i32, [R; 3]) {
    let (first, f) = bspline3_fraction(x);
    (first, bspline3_weights(f))
}

/// The first coefficient and the fraction `f` of `x − ½` behind [`bspline3`].
#[inline]
fn bspline3_fraction<R: Real>(x: R) -> (i32, R) {
    let half = R::from_ratio(1, 1);
    let (cell, frac) = x.split();
    // x − ½ without computing it (it could overflow fixed point at its minimum).
    if frac >= half {
        (cell, frac - half)
    } else {
        (cell.wrapping_sub(1), frac + half)
    }
}

/// The three weights at fraction `f`.
#[inline]
fn bspline3_weights<R: Real>(f: R) -> [R; 3] {
    let half = R::from_ratio(1, 1);
    let g = R::ONE - f;
    // Every factor is in [0, 1]: `mul_fraction` (see `Real`) is exact without saturating.
    let w0 = g.mul_fraction(g).mul_fraction(half);
    let w2 = f.mul_fraction(f).mul_fraction(half);
    [w0, R::ONE - w0 - w2, w2]
}

/// The weights' derivatives along the axis: `(−(1−f), (1−f) − f, f)`.
#[inline]
fn bspline3_derivatives<R: Real>(f: R) -> [R; 3] {
    let g = R::ONE - f;
    [-g, g - f, f]
}

/// The orientation of a block of the coefficient grid: 48 in 3D, 8 in 2D.
#[inline]
pub(crate) fn block_variant<const D: usize>(seed: u32, block: [i32; D]) -> u32 {
    orientation(seed, block, if D == 3 { 48 } else { 8 })
}

/// A 32-bit hash of a block coordinate and seed (murmur3's finaliser per component), mapped
/// onto `0..count`.
#[inline]
fn orientation<const D: usize>(seed: u32, block: [i32; D], count: u32) -> u32 {
    let mut h = seed ^ 0x9E37_79B9;
    for b in block {
        h ^= b as u32;
        h = h.wrapping_mul(0x85EB_CA6B);
        h ^= h >> 13;
        h = h.wrapping_mul(0xC2B2_AE35);
        h ^= h >> 16;
    }
    ((h as u64 * count as u64) >> 32) as u32
}

/// Axis permutations of 3 axes (output axis → tile axis).
const PERMUTATIONS3: [[usize; 3]; 6] = [
    [0, 1, 2],
    [0, 2, 1],
    [1, 0, 2],
    [1, 2, 0],
    [2, 0, 1],
    [2, 1, 0],
];

/// Maps a local index in block orientation `v` to the tile index.
#[inline]
pub(crate) fn orient<const D: usize>(local: [usize; D], v: u32, n: usize) -> [usize; D] {
    let perms = D as u32 * (D as u32 - 1).max(1); // 6 in 3D, 2 in 2D
    let (p, flips) = (v % perms, v / perms);
    let mut out = [0usize; D];
    for a in 0..D {
        let target = if D == 3 {
            PERMUTATIONS3[p as usize][a]
        } else {
            a ^ p as usize
        };
        let l = local[a];
        out[target] = if flips >> a & 1 == 1 { n - 1 - l } else { l };
    }
    out
}

/// How block orientation `v` maps output axis `a`: the tile axis it reads and whether it runs
/// backwards.
#[inline]
fn axis_map<const D: usize>(v: u32, a: usize) -> (usize, bool) {
    let perms = if D == 3 { 6 } else { 2 };
    let (p, flips) = (v % perms, v / perms);
    let target = if D == 3 {
        PERMUTATIONS3[p as usize][a]
    } else {
        a ^ p as usize
    };
    (target, flips >> a & 1 == 1)
}

/// The flat-index contribution of coefficient `j` along each axis, per lane, in block
/// orientation `v`: `local0[a][l] + j` (wrapped into the next block past `n`), reflected where
/// `v` flips the axis, times the stride of the tile axis it reads. (A function, not a closure:
/// the closure stayed out of line in 3D, 6% more instructions per x86-64 sample.)
/// Written in place: returned by value, the 16-lane array is copied.
#[inline]
fn axis_offsets<const D: usize, const L: usize>(
    offset: &mut [[[usize; L]; 3]; D],
    v: u32,
    local0: &[[usize; L]; D],
    n: usize,
) {
    for a in 0..D {
        let (target, flip) = axis_map::<D>(v, a);
        let stride = [1, n, n * n][target];
        for (j, oj) in offset[a].iter_mut().enumerate() {
            for (o, &l0) in oj.iter_mut().zip(&local0[a]) {
                let l = l0 + j;
                let l = if l >= n { l - n } else { l };
                *o = (if flip { n - 1 - l } else { l }) * stride;
            }
        }
    }
}

impl<'t, T> Wavelet<'t, T> {
    /// `Σ_c w(c) n_c` over the 3ᵈ coefficients around `p`.
    #[inline]
    fn evaluate<R: Real, const D: usize>(&self, p: [R; D]) -> R
    where
        T: TileData<D>,
    {
        let mut first = [0i32; D];
        let mut weights = [[[R::ZERO; 1]; 3]; D];
        for a in 0..D {
            let (c, w) = bspline3(p[a]);
            first[a] = c;
            weights[a] = w.map(|wj| [wj]);
        }
        let [v] = self.block_sums(first, &[weights]);
        v.canonical()
    }

    /// [`evaluate`](Self::evaluate) and its gradient: set 0 of the block sums takes the
    /// weights, set `1 + a` takes axis `a`'s weights replaced by their derivatives.
    #[inline]
    fn evaluate_with_gradient<R: Real, const D: usize>(&self, p: [R; D]) -> (R, [R; D])
    where
        T: TileData<D>,
    {
        let mut first = [0i32; D];
        let mut weights = [[[R::ZERO; 1]; 3]; D];
        let mut derivatives = [[[R::ZERO; 1]; 3]; D];
        for a in 0..D {
            let (c, f) = bspline3_fraction(p[a]);
            first[a] = c;
            weights[a] = bspline3_weights(f).map(|wj| [wj]);
            derivatives[a] = bspline3_derivatives(f).map(|dj| [dj]);
        }
        // Sets for up to 3 axes (a 2D band leaves the last one unused).
        let sets: [[[[R; 1]; 3]; D]; 4] = core::array::from_fn(|k| {
            let mut w = weights;
            if k >= 1 && k <= D {
                w[k - 1] = derivatives[k - 1];
            }
            w
        });
        let sums = self.block_sums(first, &sets);
        let gradient = core::array::from_fn(|a| sums[a + 1].canonical());
        (sums[0].canonical(), gradient)
    }

    /// `K` sums `Σ_c w_k(c) n_c` over the 3ᵈ coefficients from `first` along each axis, one per
    /// set of weights.
    ///
    /// For each block the 3ᵈ coefficients touch (usually one; at most 2ᵈ), the block's
    /// orientation is resolved once into per-axis offsets of the tile's flat index, so each
    /// coefficient costs D additions and a load.
    #[inline]
    fn block_sums<R: Real, const D: usize, const K: usize>(
        &self,
        first: [i32; D],
        sets: &[[[[R; 1]; 3]; D]; K],
    ) -> [R; K]
    where
        T: TileData<D>,
    {
        const { assert!(D == 2 || D == 3, "wavelet tiles are 2D or 3D") };
        let n = T::SIZE;
        let mut block = [0i32; D];
        let mut local0 = [0usize; D];
        let mut crossing = 0usize; // axes whose three coefficients reach the next block
        for a in 0..D {
            block[a] = first[a].div_euclid(n as i32);
            local0[a] = first[a].rem_euclid(n as i32) as usize;
            if local0[a] + 2 >= n {
                crossing |= 1 << a;
            }
        }
        let variant = |m: usize| match self.tiling {
            Tiling::Periodic => 0,
            Tiling::Varied => {
                let mut b = block;
                for (a, ba) in b.iter_mut().enumerate() {
                    *ba = ba.wrapping_add((m >> a & 1) as i32);
                }
                block_variant(self.seed, b)
            }
        };
        // The flat-index contribution of coefficient j along each axis, read in orientation v.
        let local0 = local0.map(|l| [l]);
        let mut sums = [[R::ZERO]; K];
        if crossing == 0 && D == 2 {
            // The common case in 2D (15 samples in 16 with 64-wide tiles): one block, every
            // coefficient the sample's, summed without the block loop and its per-coefficient
            // tests (a quarter of a Cortex-M0 sample's instructions, 30% on x86-64). In 3D
            // the 27 coefficients dominate (x86-64: the same count either way), and a second
            // copy of their sum would cost the demo's wasm budget about 3 KB.
            let mut off = [[[0usize; 1]; 3]; D];
            axis_offsets(&mut off, variant(0), &local0, n);
            for (sum, weights) in sums.iter_mut().zip(sets) {
                self.add_block(sum, weights, &off, |_, _| true);
            }
            return sums.map(|[s]| s);
        }
        // Along each axis, coefficients j < split[a] lie in the block, the rest in the next.
        let mut split = [3usize; D];
        for a in 0..D {
            split[a] = (n - local0[a][0]).min(3);
        }
        // Sum block by block: each block's coefficients form a separable sub-range. The
        // summing is `add_block` with one lane, so the batch path shares it.
        let mut m = crossing;
        loop {
            let mut off = [[[0usize; 1]; 3]; D];
            axis_offsets(&mut off, variant(m), &local0, n);
            // Coefficient j along axis a belongs to this block when it is on the block's side
            // of the split (loops run over 0..3 so every index is provably in range).
            let mine = |a: usize, j: usize| (m >> a & 1 == 1) == (j >= split[a]);
            for (sum, weights) in sums.iter_mut().zip(sets) {
                self.add_block(sum, weights, &off, mine);
            }
            if m == 0 {
                break;
            }
            m = (m - 1) & crossing; // the next subset of the crossing axes
        }
        sums.map(|[s]| s)
    }
}

impl<T> Wavelet<'_, T> {
    /// [`evaluate`](Self::evaluate) for [`LANES`] points, bit-identical to it. When the lanes
    /// agree on the blocks their coefficients touch (all lanes in the same block along each
    /// axis, and along an axis where coefficients reach into the next block, all lanes at the
    /// same coefficient: a row of a grid, along its constant axes), each block's orientation is
    /// resolved once for all lanes and every lane sums its coefficients in `evaluate`'s order.
    /// Otherwise every lane takes `evaluate`.
    #[inline]
    fn evaluate_lanes<R: Real, const D: usize>(&self, p: &[[R; LANES]; D], out: &mut [R; LANES])
    where
        T: TileData<D>,
    {
        const { assert!(D == 2 || D == 3, "wavelet tiles are 2D or 3D") };
        let n = T::SIZE;
        let mut weights = [[[R::ZERO; LANES]; 3]; D];
        let mut local0 = [[0usize; LANES]; D];
        let mut block = [0i32; D];
        let mut crossing = 0usize;
        let mut uniform = true;
        for a in 0..D {
            for l in 0..LANES {
                let (first, w) = bspline3(p[a][l]);
                for (wj, w) in weights[a].iter_mut().zip(w) {
                    wj[l] = w;
                }
                let b = first.div_euclid(n as i32);
                local0[a][l] = first.rem_euclid(n as i32) as usize;
                if l == 0 {
                    block[a] = b;
                }
                uniform &= b == block[a];
            }
            if local0[a].iter().any(|&l0| l0 + 2 >= n) {
                crossing |= 1 << a;
                uniform &= local0[a].iter().all(|&l0| l0 == local0[a][0]);
            }
        }
        if !uniform {
            for (l, o) in out.iter_mut().enumerate() {
                *o = self.evaluate(lane(p, l));
            }
            return;
        }
        // As in `evaluate`: along axis a, coefficients j < split[a] lie in the block, the rest
        // in the next (the same for every lane where any lane crosses).
        let split: [usize; D] = core::array::from_fn(|a| (n - local0[a][0]).min(3));
        let mut sum = [R::ZERO; LANES];
        let mut offset = [[[0usize; LANES]; 3]; D];
        let mut m = crossing;
        loop {
            let v = match self.tiling {
                Tiling::Periodic => 0,
                Tiling::Varied => {
                    let mut b = block;
                    for (a, ba) in b.iter_mut().enumerate() {
                        *ba = ba.wrapping_add((m >> a & 1) as i32);
                    }
                    block_variant(self.seed, b)
                }
            };
            axis_offsets(&mut offset, v, &local0, n);
            // Coefficient j along axis a belongs to this block when it is on the block's side
            // of the split; without crossing axes, every coefficient does (a separate
            // instantiation, without the tests).
            let mine = |a: usize, j: usize| (m >> a & 1 == 1) == (j >= split[a]);
            if crossing == 0 {
                self.add_block(&mut sum, &weights, &offset, |_, _| true);
            } else {
                self.add_block(&mut sum, &weights, &offset, mine);
            }
            if m == 0 {
                break;
            }
            m = (m - 1) & crossing;
        }
        for (o, s) in out.iter_mut().zip(sum) {
            *o = s.canonical();
        }
    }
}

impl<T> Wavelet<'_, T> {
    /// Adds each of `L` lanes' coefficients of one block (those `mine(axis, j)` selects),
    /// weighted, to `sum`: rows along x, then planes along y, then z. `evaluate` is this with
    /// one lane, so the batch path (16 lanes) sums in the same order by construction.
    #[inline]
    fn add_block<R: Real, const D: usize, const L: usize>(
        &self,
        sum: &mut [R; L],
        weights: &[[[R; L]; 3]; D],
        offset: &[[[usize; L]; 3]; D],
        mine: impl Fn(usize, usize) -> bool,
    ) where
        T: TileData<D>,
    {
        let planes = if D == 3 { 3 } else { 1 };
        for (l, s) in sum.iter_mut().enumerate() {
            for jz in 0..planes {
                if D == 3 && !mine(D - 1, jz) {
                    continue;
                }
                let zoff = if D == 3 { offset[D - 1][jz][l] } else { 0 };
                let mut plane = R::ZERO;
                for jy in 0..3 {
                    if !mine(1, jy) {
                        continue;
                    }
                    let base = zoff + offset[1][jy][l];
                    let mut row = R::ZERO;
                    for jx in 0..3 {
                        if mine(0, jx) {
                            let c = self.tile.flat(base + offset[0][jx][l]);
                            // Weights lie in [0, 1], so no product exceeds its other factor.
                            row = row.saturating_add(weights[0][jx][l].mul_fraction(c));
                        }
                    }
                    plane = plane.saturating_add(weights[1][jy][l].mul_fraction(row));
                }
                *s = s.saturating_add(if D == 3 {
                    weights[D - 1][jz][l].mul_fraction(plane)
                } else {
                    plane
                });
            }
        }
    }
}

crate::noise::inherent_amplitude_bound!(Wavelet<'_, T>, [T]);

/// The analytic gradient: each axis's quadratic B-spline weights differentiated, `(−(1−f),
/// (1−f) − f, f)` for the fraction `f` (a band is C¹: its gradient is continuous, its second
/// derivative jumps at coefficient half-integers).
impl<R: Real, T: TileData<D>, const D: usize> crate::NoiseGradient<R, D> for Wavelet<'_, T> {
    #[inline]
    fn sample_with_gradient(&self, p: [R; D]) -> (R, [R; D]) {
        self.evaluate_with_gradient(p)
    }
}

impl<R: Real, T: TileData<D>, const D: usize> Noise<R, D> for Wavelet<'_, T> {
    #[inline]
    fn sample(&self, p: [R; D]) -> R {
        self.evaluate(p)
    }

    #[inline]
    fn sample_lanes(&self, p: &[[R; LANES]; D], out: &mut [R; LANES]) {
        self.evaluate_lanes(p, out);
    }

    /// `|Σ_c w(c) n_c| ≤ max |n_c|`: the weights are non-negative and sum to 1. Plus 2⁻¹⁰ for
    /// rounding, as for the lattice noises.
    fn amplitude_bound(&self) -> f32 {
        self.tile.max_abs() * (1.0 + 1e-6) + crate::lattice::ROUNDING
    }
}

//! Evaluation of one noise band (Cook & DeRose 2005, §3.6 and Appendix 2, with erratum 6), and
//! tile repetition with hashed orientations (§4.3).
//!
//! `N(p) = Σ_c n_c B(p − c)`: the quadratic B-spline through the tile's coefficients, 3 per axis
//! (3ᵈ in all). Coefficient `c` sits at integer position `c` of the coefficient grid.
//!
//! **Seams.** A tile repeats over tile-sized blocks of the coefficient grid; [`Tiling`] says how.
//!
//! * [`Tiling::Periodic`] repeats it unchanged: band-limited, seamless, and periodic.
//! * [`Tiling::Varied`] reads the tile in one of its 48 orientations (6 axis
//!   permutations × 8 reflections; 8 in 2D) per block, chosen by a hash of the block and the
//!   seed. A coefficient's value depends only on its global index, so `N` stays a quadratic
//!   B-spline of one coefficient grid, continuous with a continuous gradient. But the blocks
//!   abut: their coefficients are unrelated across a border, which leaks power below the band,
//!   and a border between two orientations that are mirror images of each other along it shows
//!   as a symmetric streak.
//! * [`Tiling::Blended`] (the default) is §4.3's tile meshing made seamless. Each block reads the tile in a
//!   hashed orientation *and* cyclically shifted by a hashed amount per axis (so no two blocks'
//!   borders line up with the tile's content), and reaches 4 coefficients past each of its
//!   borders. Where two blocks overlap (a zone 8 coefficients wide around every border), a
//!   coefficient is the sum of both blocks' coefficients weighted by `sin θ` and `cos θ`, θ
//!   rising linearly across the zone (a table of 8 exact dyadic weights, the same in every
//!   number type). The squares of the weights sum to 1, so the variance of independent
//!   coefficients is kept without the paper's correction pass; the zone is wide against the
//!   band's wavelength, so the weights vary slowly and the band limit is kept. Tiles smaller
//!   than 11 coefficients have no room for a zone: they are shifted and oriented, unblended.
//!
//! The figures measured for each tiling are in [`Tiling`]'s docs.

use crate::batch::{Grid, LANES, for_each_rows, lane};
use crate::hash::{CellHash, mix};
use crate::{Error, Noise, Real};

mod fixed;
mod row;
pub(crate) use row::GROUP;

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
    /// What [`flat_with`](Self::flat_with) needs that is the same for every read, computed
    /// once for a loop of reads (a quantized tile's scale). The default: nothing (`R::ONE`).
    #[inline]
    fn unit<R: Real>(&self) -> R {
        R::ONE
    }
    /// [`flat`](Self::flat)`(index)`, the same value, given `unit == self.unit()`. The
    /// default reads `flat`.
    #[inline]
    fn flat_with<R: Real>(&self, index: usize, unit: R) -> R {
        let _ = unit;
        self.flat(index)
    }
    /// The largest `|coefficient|`.
    fn max_abs(&self) -> f32;
    /// `Some(s)` if every coefficient is an `i16` integer `q` ([`raw`](Self::raw)) times
    /// `2^−s`, read exactly by [`flat`](Self::flat) in every number type: fixed-point
    /// samples then sum the integers in 32-bit arithmetic, with the same bits as through
    /// `flat` (the quantized tiles, which need it on cores without a long multiply). The
    /// default: `None`.
    #[inline]
    fn quantized_shift(&self) -> Option<u32> {
        None
    }
    /// The integer `q` of the coefficient at flat index `index` (below `SIZE^D`), whose
    /// value is `q · 2^−s` for the `s` of [`quantized_shift`](Self::quantized_shift); read
    /// only where that is `Some`. The default: 0.
    #[inline]
    fn raw(&self, index: usize) -> i16 {
        let _ = index;
        0
    }
    /// The coefficients along x at tile indices `y`, `z` (a 3D tile, each below `SIZE`), if
    /// the storage holds them as a run of `SIZE` `f32`s: lets a band projected along an axis
    /// read runs of coefficients several at a time. The run must hold the values
    /// [`get`](Self::get) reads at `[0..SIZE, y, z]`; coefficients past the end of a shorter
    /// run read as 0. The default: `None` (read one by one).
    #[inline]
    fn row(&self, y: usize, z: usize) -> Option<&[f32]> {
        let _ = (y, z);
        None
    }
    /// The 3 × 3 × 3 coefficients of a 3D tile at indices `(x[i], y[j], z[k])` (each below
    /// `SIZE`), as `[k][j][i]`, given `unit == self.unit()`: one block's reads in a point sample
    /// of a 3D band, which storage kept as nested arrays can make with one addition per line
    /// of three instead of a flat index per coefficient. Only 3D bands call it (`D = 3`). The
    /// default reads [`flat_with`](Self::flat_with) at `x[i] + SIZE·(y[j] + SIZE·z[k])`.
    #[inline]
    fn cube<R: Real>(&self, [x, y, z]: [[usize; 3]; 3], unit: R) -> [[[R; 3]; 3]; 3] {
        let n = Self::SIZE;
        z.map(|z| y.map(|y| x.map(|x| self.flat_with(x + n * (y + n * z), unit))))
    }
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
        let coefficients = self.data.as_flattened();
        R::from_f32(
            coefficients
                .get(within(index, coefficients.len()))
                .copied()
                .unwrap_or(0.0),
        )
    }
    fn max_abs(&self) -> f32 {
        self.max_abs
    }
}

impl<const N: usize> TileData<3> for Tile3<N> {
    const SIZE: usize = N;
    #[inline]
    fn row(&self, y: usize, z: usize) -> Option<&[f32]> {
        let plane = self.data.get(within(z, N))?;
        Some(plane.get(within(y, N))?.as_slice())
    }
    #[inline]
    fn get<R: Real>(&self, [x, y, z]: [usize; 3]) -> R {
        self.flat(x + N * (y + N * z))
    }
    #[inline]
    fn cube<R: Real>(&self, [x, y, z]: [[usize; 3]; 3], _unit: R) -> [[[R; 3]; 3]; 3] {
        // In range by construction; masked where `N` is a power of two (every default tile),
        // so that the reads need no bounds checks, and read as 0 otherwise (never a panic).
        let (x, y) = (x.map(|i| within(i, N)), y.map(|i| within(i, N)));
        z.map(|z| {
            let plane = self.data.get(within(z, N));
            y.map(|y| {
                let row = plane.and_then(|plane| plane.get(y));
                x.map(|x| R::from_f32(row.and_then(|row| row.get(x)).copied().unwrap_or(0.0)))
            })
        })
    }
    #[inline]
    fn flat<R: Real>(&self, index: usize) -> R {
        // In range by construction; `get` keeps sampling provably panic-free.
        let coefficients = self.data.as_flattened().as_flattened();
        R::from_f32(
            coefficients
                .get(within(index, coefficients.len()))
                .copied()
                .unwrap_or(0.0),
        )
    }
    fn max_abs(&self) -> f32 {
        self.max_abs
    }
}

/// `index`, below `len` by construction, masked to `len`'s range where `len` is a power of two
/// (every default tile): the same index, and the optimiser then sees the read in range and
/// drops its bounds check, a compare and a branch per coefficient.
#[inline(always)]
pub(crate) const fn within(index: usize, len: usize) -> usize {
    if len.is_power_of_two() {
        index & (len - 1)
    } else {
        index
    }
}

/// How the tile repeats over space (the module docs of `band.rs` explain each).
///
/// Measured by `tests/tests/seams.rs` (1024² samples from an origin off the lattice, four
/// tiles, noise seeds 0 and 7; Hann-windowed spectra), `Blended` against `Varied`:
///
/// | one band | `Blended` | `Varied` | `Periodic` |
/// |---|---|---|---|
/// | 2D power below 1/8 cycle per coefficient | 0.005–0.006% | 0.27–0.47% | 0.0016% |
/// | 3D projected along z, power below 1/8 (mean of 8 planes) | 0.77–0.78% | 1.8% | 0.5% |
/// | 2D power at the tile's harmonics (0.39% if nothing repeats) | 0.44–0.50% | 10–14% | 100% |
/// | variance near a block border against the interior, 2D / 3D | within ±2.3% / ±1.4% | up to +63% / +23% | — |
/// | worst mirror correlation across a 2D border | 0.24 | 1.00 | — |
///
/// `Blended`, the default, is the only tiling without repetition or seams. Its zones cost time:
/// a sample within 4 coefficients of a border sums two blocks per axis (four at a 2D corner),
/// about 1.5× `Varied`'s instructions on average over a 64² tile on a Cortex-M0 and more on
/// x86-64 (`bench/README.md`). `Varied` is the faster choice where its borders do not matter.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Tiling {
    /// The tile repeats unchanged: the noise is periodic with the tile's size in coefficients.
    Periodic,
    /// Each tile-sized block uses one of the tile's 48 orientations (8 in 2D), chosen by a hash
    /// of the block and the seed (§4.3): continuous, but the blocks abut, so their borders
    /// show (see the module docs for what they cost). Spec text `tiling=varied`.
    Varied,
    /// Each block reads the tile cyclically shifted and in one of its orientations, both
    /// hashed, and neighbouring blocks blend their coefficients over 8 coefficients around
    /// each border with weights whose squares sum to 1 (§4.3's tile meshing): no repetition,
    /// no seams, and the band limit kept (figures in the module docs). Slower than `Varied`
    /// near block borders. The default; spec text `tiling=blended`.
    #[default]
    Blended,
}

/// One band of wavelet noise over a tile `T`, in 2D or 3D (the tile's dimension).
///
/// Sampling follows the [`Noise`] contract: never panics; NaN and ±∞ coordinates are 0; cells
/// beyond `i32` wrap; the result is finite, never `-0.0`, and within
/// [`amplitude_bound`](Noise::amplitude_bound) (the largest coefficient of the blended grid).
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
    /// The seed's cell hash, which places each block (orientation and shift).
    hash: CellHash,
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
    /// A band over `tile`, with blocks placed and blended ([`Tiling::Blended`], the default)
    /// as `seed` chooses (the seed first, as in every noise's constructor).
    #[must_use]
    pub const fn new(seed: u32, tile: &'t T) -> Self {
        Self {
            tile,
            seed,
            hash: CellHash::new(seed),
            tiling: Tiling::Blended,
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

/// [`bspline3`] of each lane: the first coefficients into `first`, the weights into
/// `weights[j]`, bit for bit (through [`Real::split_lanes`], written so the compiler can
/// vectorise it).
#[inline]
pub(crate) fn bspline3_lanes<R: Real>(
    x: &[R; LANES],
    first: &mut [i32; LANES],
    weights: &mut [[R; LANES]; 3],
) {
    let mut frac = [R::ZERO; LANES];
    R::split_lanes(x, first, &mut frac);
    for (first, frac) in first.iter_mut().zip(&mut frac) {
        (*first, *frac) = minus_half(*first, *frac);
    }
    for l in 0..LANES {
        let [w0, w1, w2] = bspline3_weights(frac[l]);
        (weights[0][l], weights[1][l], weights[2][l]) = (w0, w1, w2);
    }
}

/// The first coefficient and the fraction `f` of `x − ½` behind [`bspline3`].
#[inline]
fn bspline3_fraction<R: Real>(x: R) -> (i32, R) {
    let (cell, frac) = x.split();
    minus_half(cell, frac)
}

/// The cell and fraction of `x − ½` from those of `x`, without computing `x − ½` (it could
/// overflow fixed point at its minimum).
#[inline]
fn minus_half<R: Real>(cell: i32, frac: R) -> (i32, R) {
    let half = R::from_ratio(1, 1);
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

/// Half the width, in coefficients, of the zone around a block border where the two blocks'
/// coefficients blend (§4.3).
pub(crate) const BLEND: usize = 4;

/// `RAMP[k] = sin(π/2 · (k + ½) / (2·BLEND))` in units of 2⁻¹⁶ (rounded to nearest; every
/// number type gets the same weights): at the `k`-th coefficient of a blend zone, the weight of
/// the block the zone leads into. The block it leaves weighs `RAMP[2·BLEND − 1 − k]` (the
/// cosine), so the squared weights sum to 1 within 2⁻¹⁵ and the coefficients keep their
/// variance (§4.3's correction, folded into the weights).
const RAMP: [i32; 2 * BLEND] = [6424, 19024, 30893, 41576, 50660, 57798, 62714, 65220];

/// The most a blend zone's two weights sum to, `max_k RAMP[k] + RAMP[2·BLEND − 1 − k]`
/// (`√2 · cos(π/(8·BLEND))`, 1.407): a blended coefficient is at most this many times the
/// tile's largest (per axis), and so is the sum of a sample's weights along an axis.
const BLEND_GAIN: f32 = {
    let mut gain = 0;
    let mut k = 0;
    while k < 2 * BLEND {
        let pair = RAMP[k] + RAMP[2 * BLEND - 1 - k];
        if pair > gain {
            gain = pair;
        }
        k += 1;
    }
    gain as f32 / 65536.0
};

/// How one block of the coefficient grid reads the tile: orientation `variant` (48 in 3D, 8 in
/// 2D) after a cyclic shift of the tile by `shift` coefficients along each output axis.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Placement<const D: usize> {
    variant: u32,
    shift: [usize; D],
}

/// The blocks one axis of a sample reads: the first block, the local index of the sample's
/// first coefficient in it (in `[h, n + h)`, `h` the blend half-width), and whether its three
/// coefficients reach the next block too (in that block's blend zone, or past its border).
#[inline]
fn axis_span(first: i32, n: usize, h: usize) -> (i32, usize, bool) {
    let (n, h) = (n as i32, h as i32);
    // Block q owns coefficients [qn − h, qn + n + h): u = c + h puts its start at qn.
    let u = first.wrapping_add(h);
    let (q, r) = if n.count_ones() == 1 {
        // A power of two (every default tile): the floor's shift and mask, which the
        // optimiser does not derive from `div_euclid` on the Cortex-M0 (8 more instructions).
        (u >> n.trailing_zeros(), u & (n - 1))
    } else {
        (u.div_euclid(n), u.rem_euclid(n))
    };
    if r < 2 * h {
        // The first coefficient is in the zone where block q − 1 fades into q.
        (q.wrapping_sub(1), (r - h + n) as usize, true)
    } else {
        (q, (r - h) as usize, r + 2 >= n)
    }
}

/// The weight of local coefficient `l` (`l + n` is passed, so it is not negative) of a block:
/// 0 outside the block's reach `[−h, n + h)`, 1 inside `[h, n − h)`, the ramp between.
#[inline]
pub(crate) fn blend_weight<R: Real>(l_plus_n: usize, n: usize, h: usize) -> R {
    if l_plus_n + h < n || l_plus_n >= 2 * n + h {
        R::ZERO
    } else if l_plus_n < n + h {
        R::from_ratio(RAMP[(l_plus_n + h - n) % (2 * BLEND)], 16)
    } else if l_plus_n >= 2 * n - h {
        R::from_ratio(RAMP[(2 * n + h - 1 - l_plus_n) % (2 * BLEND)], 16)
    } else {
        R::ONE
    }
}

/// Axis permutations of 3 axes (output axis → tile axis).
pub(crate) const PERMUTATIONS3: [[usize; 3]; 6] = [
    [0, 1, 2],
    [0, 2, 1],
    [1, 0, 2],
    [1, 2, 0],
    [2, 0, 1],
    [2, 1, 0],
];

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

/// The tile's flat index of local coefficient `local` (each component in `[−h, n + h)`, passed
/// plus `n`) of a block placed by `place`.
#[inline]
pub(crate) fn tile_index<const D: usize>(
    local_plus_n: [usize; D],
    place: &Placement<D>,
    n: usize,
) -> usize {
    let mut index = 0;
    for (a, &l) in local_plus_n.iter().enumerate() {
        index += place.axis(a, n).offset(l, n);
    }
    index
}

/// How one output axis of a block reads the tile ([`Placement::axis`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct AxisMap {
    /// The stride of the tile axis it reads.
    stride: usize,
    /// Whether it runs backwards.
    flip: bool,
    /// Its cyclic shift.
    shift: usize,
}

impl AxisMap {
    /// The part of the tile's flat index of local index `l` (in `[−h, n + h)`, passed plus
    /// `n`): its [`coordinate`](Self::coordinate) times the stride.
    #[inline]
    pub(crate) fn offset(&self, l_plus_n: usize, n: usize) -> usize {
        self.coordinate(l_plus_n, n) * self.stride
    }

    /// The index along the tile axis it reads of local index `l` (passed plus `n`, or plus
    /// any multiple of `n`): `(l + shift) mod n`, reversed if the axis runs backwards.
    #[inline]
    pub(crate) fn coordinate(&self, l_plus_n: usize, n: usize) -> usize {
        oriented(l_plus_n + self.shift, n, self.flip)
    }
}

/// The tile index, along the tile axis it reads, of a coefficient at `u` (its local index
/// plus the block's shift, plus a multiple of `n`): `u mod n`, reversed if the axis runs
/// backwards.
#[inline]
fn oriented(u: usize, n: usize, flip: bool) -> usize {
    let t = u % n;
    if flip { n - 1 - t } else { t }
}

/// What [`oriented`] takes added to a local index of the first block along output axis `a`,
/// read by the block `m` steps (one bit per axis) past it: the block's shift, plus `2n`, less
/// `n` if the block is the next one along `a` (a local index ≥ −h − n past the first block,
/// h < n, so the sum is never negative).
#[inline]
fn block_start<const D: usize>(place: &Placement<D>, a: usize, m: usize, n: usize) -> usize {
    place.shift[a] + if m >> a & 1 == 1 { n } else { 2 * n }
}

impl<const D: usize> Placement<D> {
    /// The tile as it is: no shift, the first orientation (a filler for arrays of
    /// placements).
    pub(crate) const UNSHIFTED: Self = Placement {
        variant: 0,
        shift: [0; D],
    };

    /// The index in [`PERMUTATIONS3`] of the tile axes a 3D block's output axes read.
    #[inline]
    pub(crate) fn permutation(&self) -> usize {
        (self.variant % 6) as usize
    }

    /// How output axis `a` reads the tile in this placement.
    #[inline]
    pub(crate) fn axis(&self, a: usize, n: usize) -> AxisMap {
        let (target, flip) = axis_map::<D>(self.variant, a);
        // A match, not `[1, n, n²][target]`: the optimiser cannot see that a target read
        // from `PERMUTATIONS3` is below 3, and the index would keep a panic path.
        let stride = match target {
            0 => 1,
            1 => n,
            _ => n * n,
        };
        AxisMap {
            stride,
            flip,
            shift: self.shift[a],
        }
    }
}

/// The first block that reaches global coefficient `g` (block `q` reaches `[qn − h,
/// qn + n + h)`), `g`'s local index in it plus `n` (in `[n + h, 2n + h)`), and whether the
/// next block reaches `g` too (the blend zone where the first fades into the next).
#[inline]
pub(crate) fn first_block(g: i32, n: usize, h: usize) -> (i32, usize, bool) {
    // u = g + h puts block q's start at qn; the zone is r < 2h.
    let u = g.wrapping_add(h as i32);
    let (q, r) = (u.div_euclid(n as i32), u.rem_euclid(n as i32) as usize);
    if r < 2 * h {
        (q.wrapping_sub(1), r + 2 * n - h, true)
    } else {
        (q, r + n - h, false)
    }
}

/// The tile's flat-index parts along output axis `a` of the `K` coefficients from local
/// index `l0` (in the first block) read by the block `m` steps (one bit per axis) past the
/// first, placed by `place`: [`AxisMap::offset`]'s values. For a tile whose side is a power
/// of two (every default tile) by masks, which vectorise: `u mod n` is `u & (n − 1)`,
/// reversed it is `^ (n − 1)`, and the block's step of `n` ([`block_start`]) vanishes
/// modulo `n`; the stride is a shift.
#[inline(always)]
pub(crate) fn offset_run<const D: usize, const K: usize>(
    place: &Placement<D>,
    a: usize,
    m: usize,
    l0: usize,
    n: usize,
) -> [usize; K] {
    if n.is_power_of_two() {
        let (target, flip) = axis_map::<D>(place.variant, a);
        let (mask, log) = (n - 1, n.trailing_zeros());
        let u = l0 + place.shift[a];
        let reverse = if flip { mask } else { 0 };
        // The stride as a shift chosen by a match, not `target · log`: each part then lies
        // in its own bits of the flat index, which the optimiser sees (see `fixed::join`).
        core::array::from_fn(|j| {
            let t = ((u + j) & mask) ^ reverse;
            match target {
                0 => t,
                1 => t << log,
                _ => t << (2 * log),
            }
        })
    } else {
        // `AxisMap::offset` adds the block's shift; `block_start` less it is `n` or `2n`.
        let (map, u) = (
            place.axis(a, n),
            l0 + block_start(place, a, m, n) - place.shift[a],
        );
        core::array::from_fn(|j| map.offset(u + j, n))
    }
}

/// The flat-index contribution of coefficient `j` along each axis, per lane, in the block
/// `m` steps (one bit per axis) past the first: local index `local0[a][l] + j − n·m_a`, shifted
/// and oriented by `place`, times the stride of the tile axis it reads. (A function, not a
/// closure: the closure stayed out of line in 3D, 6% more instructions per x86-64 sample.)
/// Written in place: returned by value, the 16-lane array is copied.
#[inline]
fn axis_offsets<const D: usize, const L: usize>(
    offset: &mut [[[usize; L]; 3]; D],
    place: &Placement<D>,
    m: usize,
    local0: &[[usize; L]; D],
    n: usize,
) {
    for a in 0..D {
        let (target, flip) = axis_map::<D>(place.variant, a);
        let stride = [1, n, n * n][target];
        let add = block_start(place, a, m, n);
        for (j, oj) in offset[a].iter_mut().enumerate() {
            for (o, &l0) in oj.iter_mut().zip(&local0[a]) {
                *o = oriented(l0 + j + add, n, flip) * stride;
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
        if fixed::QUANTIZED
            && !R::FLOAT
            && let Some(shift) = self.tile.quantized_shift()
            && (fixed::MIN_SHIFT..=16).contains(&shift)
        {
            // I16F16 on a quantized tile: the same bits in 32-bit integer operations.
            let bits = self.evaluate_quantized(p.map(|x| x.fixed_bits()), shift);
            return R::from_ratio(bits, 16);
        }
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
    /// placement is resolved once into per-axis offsets of the tile's flat index, so each
    /// coefficient costs D additions and a load; in a blend zone, the axis's weights are
    /// multiplied by the block's blend weights first.
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
        let (n, h) = (T::SIZE, self.half_width::<D>());
        let mut block = [0i32; D];
        let mut local0 = [[0usize; 1]; D];
        let mut crossing = 0usize; // axes whose three coefficients read a second block
        for a in 0..D {
            let (b, l0, two) = axis_span(first[a], n, h);
            block[a] = b;
            local0[a] = [l0];
            crossing |= (two as usize) << a;
        }
        let mut sums = [[R::ZERO]; K];
        let mut off = [[[0usize; 1]; 3]; D];
        if crossing == 0 && D == 2 {
            // The common case (most samples with 64-wide tiles): one block, every coefficient
            // weighing its B-spline weight alone. (In 3D the loop below does the same with one
            // block; a second copy of the 27-coefficient sum would cost the demo 3 KB.)
            axis_offsets(&mut off, &self.placement(block), 0, &local0, n);
            for (sum, weights) in sums.iter_mut().zip(sets) {
                self.add_block(sum, &weights.each_ref(), &off, every);
            }
            return sums.map(|[s]| s);
        }
        // Sum block by block, each block's coefficients weighted by the B-spline times the
        // block's blend weights (0 beyond its reach; with abutting blocks, 1 or 0): the
        // summing is `add_block` with one lane, so the batch path shares it.
        let mut sided: [_; K] = core::array::from_fn(|k| self.sided(&sets[k], crossing, &local0));
        // A coefficient beyond its block's reach is skipped where multiplying costs more than
        // a branch (no float unit: ARMv6-M, which has no 64-bit product either, and RV32
        // without F; and wasm32, whose engines keep the branches cheap), and elsewhere weighs
        // 0: adding the `±0` it gives leaves a sum's bits as they are ([`exclude`]).
        // The same bits either way; which is faster where was measured (bench/README.md,
        // "wavelet sums in columns"). In blend zones (`h > 0`) the blend weights are already
        // 0 beyond a block's reach, so only skipping needs the members.
        let skip = cfg!(any(
            bandnoise_armv6m,
            all(target_arch = "riscv32", not(target_feature = "f")),
            target_arch = "wasm32"
        ));
        let members = if crossing == 0 || !skip && h > 0 {
            [[0b111; D]; 2] // every coefficient of each block read
        } else {
            self.members(crossing, &local0)
        };
        if !skip && h == 0 && crossing != 0 {
            sided.iter_mut().for_each(|sides| exclude(sides, members));
        }
        if CUBE && D == 3 {
            // `skip` is false on these targets: every coefficient is read.
            self.add_cubes(&mut sums, &sided, block, crossing, &local0);
            return sums.map(|[s]| s);
        }
        // Every subset of the crossing axes, largest first.
        for m in (0..=crossing).rev().filter(|m| m & !crossing == 0) {
            let place = self.placement(self.step(block, m));
            axis_offsets(&mut off, &place, m, &local0, n);
            let mine = |a: usize, j: usize| !skip || members[m >> a & 1][a] >> j & 1 == 1;
            for (sum, sides) in sums.iter_mut().zip(&sided) {
                let weights = core::array::from_fn(|a| &sides[m >> a & 1][a]);
                self.add_block(sum, &weights, &off, mine);
            }
        }
        sums.map(|[s]| s)
    }

    /// The largest `|coefficient|` of the blended coefficient grid: the tile's, times
    /// [`BLEND_GAIN`] per axis where blocks blend.
    pub(crate) fn coefficient_bound<const D: usize>(&self) -> f32
    where
        T: TileData<D>,
    {
        let gain = if self.half_width::<D>() > 0 {
            BLEND_GAIN
        } else {
            1.0
        };
        let mut bound = self.tile.max_abs();
        for _ in 0..D {
            bound *= gain;
        }
        bound
    }

    /// The blend half-width: [`BLEND`] with [`Tiling::Blended`] on a tile wide enough for two
    /// zones and a sample between them, else 0 (blocks abut).
    #[inline]
    pub(crate) fn half_width<const D: usize>(&self) -> usize
    where
        T: TileData<D>,
    {
        match self.tiling {
            Tiling::Blended if T::SIZE >= 2 * BLEND + 3 => BLEND,
            _ => 0,
        }
    }

    /// `block` moved one block along each axis whose bit is set in `m`.
    #[inline]
    fn step<const D: usize>(&self, mut block: [i32; D], m: usize) -> [i32; D] {
        for (a, b) in block.iter_mut().enumerate() {
            *b = b.wrapping_add((m >> a & 1) as i32);
        }
        block
    }

    /// Each axis's weights in the first block (`[0]`) and the next (`[1]`): along a crossing
    /// axis, times each block's blend weights (the lanes share their coefficients there);
    /// along other axes, unchanged (only the first block is read).
    #[inline]
    fn sided<R: Real, const D: usize, const L: usize>(
        &self,
        weights: &[[[R; L]; 3]; D],
        crossing: usize,
        local0: &[[usize; L]; D],
    ) -> [[[[R; L]; 3]; D]; 2]
    where
        T: TileData<D>,
    {
        let (n, h) = (T::SIZE, self.half_width::<D>());
        let mut sides = [*weights; 2];
        if h == 0 {
            // Abutting blocks: every coefficient of a block weighs 1 (the others are skipped).
            return sides;
        }
        for (s, side) in sides.iter_mut().enumerate() {
            for (a, axis) in side.iter_mut().enumerate() {
                if crossing >> a & 1 == 1 {
                    blend_axis(axis, s, zone_at(local0[a][0], n, h));
                }
            }
        }
        sides
    }

    /// Which of the three coefficients along each axis lie within the reach of the first
    /// block (`[0]`) and the next (`[1]`), as bits: all three along axes that do not cross.
    #[inline]
    fn members<const D: usize, const L: usize>(
        &self,
        crossing: usize,
        local0: &[[usize; L]; D],
    ) -> [[u8; D]; 2]
    where
        T: TileData<D>,
    {
        members(
            crossing,
            core::array::from_fn(|a| local0[a][0]),
            T::SIZE,
            self.half_width::<D>(),
        )
    }

    /// How the block at `block` reads the tile: identity when periodic; with
    /// [`Tiling::Varied`], an orientation from [`orientation`]'s hash; with
    /// [`Tiling::Blended`], [`blended_placement`].
    // Out of line in wasm, where the demo's size budget counts each inlined copy (1.5 KB);
    // inline elsewhere, where the call would cost the Cortex-M0 3% per sample.
    #[cfg_attr(target_arch = "wasm32", inline(never))]
    #[cfg_attr(not(target_arch = "wasm32"), inline)]
    pub(crate) fn placement<const D: usize>(&self, block: [i32; D]) -> Placement<D>
    where
        T: TileData<D>,
    {
        let n = T::SIZE;
        let count = if D == 3 { 48 } else { 8 };
        match self.tiling {
            Tiling::Periodic => Placement {
                variant: 0,
                shift: [0; D],
            },
            Tiling::Varied => Placement {
                variant: orientation(self.seed, block, count),
                shift: [0; D],
            },
            Tiling::Blended => blended_placement(&self.hash, block, n, count),
        }
    }
}

/// [`Tiling::Blended`]'s placement of `block`: a [`CellHash`] of the block picks the
/// orientation (its top 10 bits) and, mixed once more, a shift along each axis (10 bits each,
/// scaled to `0..n`). Inline on x86-64 and AArch64, where it saves a band's point sample 7–10%
/// of its instructions; out of line elsewhere: in wasm for the demo's size budget, and on the
/// firmware cores, where its copies in every block loop change how the compiler inlines the
/// other noises sampled in the same program (`bench/README.md` has the counts).
#[cfg_attr(any(target_arch = "x86_64", target_arch = "aarch64"), inline)]
#[cfg_attr(
    not(any(target_arch = "x86_64", target_arch = "aarch64")),
    inline(never)
)]
fn blended_placement<const D: usize>(
    hash: &CellHash,
    block: [i32; D],
    n: usize,
    count: u32,
) -> Placement<D> {
    let h = hash.hash(block);
    let s = mix(h);
    Placement {
        variant: ((h >> 22) * count) >> 10,
        shift: core::array::from_fn(|a| (((s >> (10 * a)) as usize & 1023) * n) >> 10),
    }
}

/// The blend weights of the coefficients around a zone, in units of 2⁻¹⁶: `ZONE[0][z + 2]`
/// is the weight, in the block the zone leaves, of the coefficient `z` places past the zone's
/// start (`z` in `[−2, 2·BLEND + 2)`: 1 before the zone, the falling ramp, 0 past it), and
/// `ZONE[1][z + 2]` its weight in the block the zone leads into (0, the rising ramp, 1):
/// [`blend_weight`]'s values at those places (a unit test compares them), read without its
/// four-way branch. Padded to 16 entries, so that an index masked to 4 bits is in range:
/// [`CROSSING`]'s blended weights from `z = −2`.
const ZONE: [[i32; 16]; 2] = {
    let mut zone = [[0; 16]; 2];
    let mut i = 0;
    while i < 16 {
        (zone[0][i], zone[1][i]) = (CROSSING[1][0][i + 6], CROSSING[1][1][i + 6]);
        i += 1;
    }
    zone
};

/// [`ZONE`] for the supports and windows of a projected band, which cross from one block into
/// the next: `CROSSING[b][side][z + 8]`, with `b` 1 for the blended tiling (`h = BLEND`) and 0
/// for the others (`h = 0`), is the weight in the block the zone leaves (`side` 0) or leads
/// into (1) of the coefficient `z` places past the zone's start (local index `n − h`), for `z`
/// in `[−8, 2h + 8)`: a run of up to 8 offsets that reaches the zone starts at most 7 places
/// before it and ends at most 7 past it. [`blend_weight`]'s values there (a unit test compares
/// them), without its branches. Padded to 32 entries, so that an index masked to 5 bits is in
/// range.
pub(crate) const CROSSING: [[[i32; 32]; 2]; 2] = {
    let mut crossing = [[[0; 32]; 2]; 2];
    let mut b = 0;
    while b < 2 {
        let h = b * BLEND;
        let mut i = 0;
        while i < 32 {
            let z = i as isize - 8;
            (crossing[b][0][i], crossing[b][1][i]) = if z < 0 {
                (1 << 16, 0)
            } else if z < 2 * h as isize {
                (RAMP[2 * BLEND - 1 - z as usize], RAMP[z as usize])
            } else {
                (0, 1 << 16)
            };
            i += 1;
        }
        b += 1;
    }
    crossing
};

/// Multiplies the weights of the three coefficients of one axis (every lane's) by their blend
/// weights in the block on `side` of a zone (0: the block it leaves, 1: the one it leads
/// into), the first coefficient `at − 2` places past the zone's start ([`ZONE`]; `at` in
/// `[0, 2·BLEND + 2)`). The same products as [`blend_weight`]'s weights give, 1 and 0
/// included.
#[inline]
fn blend_axis<R: Real, const L: usize>(axis: &mut [[R; L]; 3], side: usize, at: usize) {
    for (j, wj) in axis.iter_mut().enumerate() {
        let b = R::from_ratio(ZONE[side & 1][(at + j) & 15], 16);
        for x in wj.iter_mut() {
            *x = x.mul_fraction(b);
        }
    }
}

/// `at` of [`blend_axis`] for a crossing axis whose first coefficient has local index `l0` in
/// the first block ([`axis_span`]: `l0` in `[n − h − 2, n + h)`, the zone starting at `n −
/// h`), with `h` > 0.
#[inline]
fn zone_at(l0: usize, n: usize, h: usize) -> usize {
    (l0 + h + 2).wrapping_sub(n)
}

/// Sets to 0 the weight of each coefficient outside its block's reach: `sides[s][a][j]` is
/// the weight in block side `s` (the first block or the next) along axis `a` of coefficient
/// `j`, `members[s][a]` its bits as [`members`] gives them.
///
/// `add_block` with a `mine` that skips such a coefficient gives the same bits: a zero
/// weight adds `±0`, and every sum starts at `+0`, adding anything to `+0` never gives `−0`
/// (`+0 + −0 = +0`), so a sum is never `−0` and adding `±0` to it changes nothing (fixed
/// point: adding 0 is exact). The coefficients it multiplies are the tile's, finite.
#[inline]
fn exclude<R: Real, const D: usize>(sides: &mut [[[[R; 1]; 3]; D]; 2], members: [[u8; D]; 2]) {
    for (side, bits) in sides.iter_mut().zip(members) {
        for (axis, bits) in side.iter_mut().zip(bits) {
            for (j, w) in axis.iter_mut().enumerate() {
                if bits >> j & 1 == 0 {
                    *w = [R::ZERO];
                }
            }
        }
    }
}

/// [`Wavelet::members`] from the first lane's local indices. The first block reaches local
/// index `n + h`, so coefficient `j` (local `l0 + j`) is in it while `j < n + h − l0`; the next
/// block starts at local `n − h` of the first, so it holds `j ≥ n − h − l0`.
#[inline(never)]
fn members<const D: usize>(
    crossing: usize,
    local0: [usize; D],
    n: usize,
    h: usize,
) -> [[u8; D]; 2] {
    let mut bits = [[0b111u8; D]; 2];
    for (a, &l0) in local0.iter().enumerate() {
        if crossing >> a & 1 == 1 {
            bits[0][a] = (1u8 << (n + h - l0).min(3)) - 1;
            bits[1][a] = 0b111 & !((1u8 << (n - h).saturating_sub(l0).min(3)) - 1);
        }
    }
    bits
}

/// A 32-bit hash of a block coordinate and seed (murmur3's finaliser per component), mapped
/// onto `0..count`: [`Tiling::Varied`]'s orientations.
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

impl<T> Wavelet<'_, T> {
    /// [`evaluate`](Self::evaluate) for [`LANES`] points, bit-identical to it. When the lanes
    /// agree on the blocks their coefficients touch (all lanes in the same blocks along each
    /// axis, and along an axis where coefficients reach a second block, all lanes at the same
    /// coefficient: a row of a grid, along its constant axes), each block's placement is
    /// resolved once for all lanes and every lane sums its coefficients in `evaluate`'s order.
    /// Otherwise every lane takes `evaluate`.
    #[inline]
    fn evaluate_lanes<R: Real, const D: usize>(&self, p: &[[R; LANES]; D], out: &mut [R; LANES])
    where
        T: TileData<D>,
    {
        const { assert!(D == 2 || D == 3, "wavelet tiles are 2D or 3D") };
        let (n, h) = (T::SIZE, self.half_width::<D>());
        let mut weights = [[[R::ZERO; LANES]; 3]; D];
        let mut local0 = [[0usize; LANES]; D];
        let mut block = [0i32; D];
        let mut crossing = 0usize;
        let mut uniform = true;
        for a in 0..D {
            let mut two = [false; LANES];
            for l in 0..LANES {
                let (first, w) = bspline3(p[a][l]);
                for (wj, w) in weights[a].iter_mut().zip(w) {
                    wj[l] = w;
                }
                let (b, l0, t) = axis_span(first, n, h);
                local0[a][l] = l0;
                two[l] = t;
                if l == 0 {
                    block[a] = b;
                }
                uniform &= b == block[a];
            }
            if two.iter().any(|&t| t) {
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
        let mut sum = [R::ZERO; LANES];
        let mut offset = [[[0usize; LANES]; 3]; D];
        if crossing == 0 {
            // One block, every coefficient weighing its B-spline weight alone.
            axis_offsets(&mut offset, &self.placement(block), 0, &local0, n);
            self.add_block(&mut sum, &weights.each_ref(), &offset, every);
        } else {
            // As in `block_sums`, but without copying 16 lanes of weights where blocks abut.
            let blended;
            let sides: [[&[[R; LANES]; 3]; D]; 2] = if h > 0 {
                blended = self.sided(&weights, crossing, &local0);
                blended.each_ref().map(|side| side.each_ref())
            } else {
                [weights.each_ref(); 2]
            };
            let members = self.members(crossing, &local0);
            for m in (0..=crossing).rev().filter(|m| m & !crossing == 0) {
                let place = self.placement(self.step(block, m));
                axis_offsets(&mut offset, &place, m, &local0, n);
                let mine = |a: usize, j: usize| members[m >> a & 1][a] >> j & 1 == 1;
                let weights = core::array::from_fn(|a| sides[m >> a & 1][a]);
                self.add_block(&mut sum, &weights, &offset, mine);
            }
        }
        for (o, s) in out.iter_mut().zip(sum) {
            *o = s.canonical();
        }
    }
}

impl<T> Wavelet<'_, T> {
    /// Adds each of `L` lanes' coefficients of one block (those `mine(axis, j)` selects),
    /// weighted, to `sum`: for each x index, its column (lines along z, then along y) weighted
    /// by its x weight. `evaluate` is this with one lane, so the batch path (16 lanes) sums in
    /// the same order by construction; x comes last so that a grid's row, along which only x
    /// changes, can sum each column once for all its samples (`row.rs`).
    #[inline]
    fn add_block<R: Real, const D: usize, const L: usize>(
        &self,
        sum: &mut [R; L],
        weights: &[&[[R; L]; 3]; D],
        offset: &[[[usize; L]; 3]; D],
        mine: impl Fn(usize, usize) -> bool,
    ) where
        T: TileData<D>,
    {
        let planes = if D == 3 { 3 } else { 1 };
        let unit = self.tile.unit::<R>();
        for (l, s) in sum.iter_mut().enumerate() {
            for jx in 0..3 {
                if !mine(0, jx) {
                    continue;
                }
                let mut column = R::ZERO;
                for jy in 0..3 {
                    if !mine(1, jy) {
                        continue;
                    }
                    let base = offset[0][jx][l] + offset[1][jy][l];
                    let line = if D == 3 {
                        let mut line = R::ZERO;
                        for jz in 0..planes {
                            if mine(D - 1, jz) {
                                let c = self.tile.flat_with(base + offset[D - 1][jz][l], unit);
                                line = line.saturating_add(weights[D - 1][jz][l].mul_fraction(c));
                            }
                        }
                        line
                    } else {
                        self.tile.flat_with(base, unit)
                    };
                    // Weights lie in [0, 1], so no product exceeds its other factor.
                    column = column.saturating_add(weights[1][jy][l].mul_fraction(line));
                }
                *s = s.saturating_add(weights[0][jx][l].mul_fraction(column));
            }
        }
    }
}

/// Whether a 3D point sample reads each block as a [`TileData::cube`] summed by
/// [`Wavelet::add_cube`] (x86-64 and AArch64), rather than coefficient by coefficient through
/// flat indices ([`Wavelet::add_block`]), and a band projected along an axis sums each block
/// by a copy per axis permutation (`permuted_sums` in `projected.rs`): the same values in the
/// same order, so the same bits. Not on the firmware cores and wasm, whose code size the six
/// copies (one per axis permutation) would cost.
pub(crate) const CUBE: bool = cfg!(any(target_arch = "x86_64", target_arch = "aarch64"));

impl<T> Wavelet<'_, T> {
    /// [`block_sums`](Self::block_sums)' loop over the blocks where a block is summed by
    /// [`add_cube`](Self::add_cube): every subset `m` of the crossing axes, largest first (the
    /// order `add_block`'s loop takes), each block's placement found before any block is
    /// summed. Each block's sum is chosen by its axis permutation, a jump no predictor
    /// foresees, whose misprediction costs least when its target is known as the jump is
    /// reached (found in the loop, the placements cost a 3D sample an eighth more time:
    /// `bench/README.md`).
    #[inline]
    fn add_cubes<R: Real, const D: usize, const K: usize>(
        &self,
        sums: &mut [[R; 1]; K],
        sided: &[[[[[R; 1]; 3]; D]; 2]; K],
        block: [i32; D],
        crossing: usize,
        local0: &[[usize; 1]; D],
    ) where
        T: TileData<D>,
    {
        let mut places = [(0, Placement::UNSHIFTED); 8];
        let (mut m, mut count) = (crossing, 0);
        loop {
            places[count % 8] = (m, self.placement(self.step(block, m)));
            count += 1;
            if m == 0 {
                break;
            }
            m = (m - 1) & crossing; // the next smaller subset
        }
        for &(m, ref place) in places.iter().take(count) {
            let weights = sided
                .each_ref()
                .map(|sides| core::array::from_fn(|a| &sides[m >> a & 1][a]));
            self.add_cube(sums, &weights, place, m, local0);
        }
    }

    /// [`add_block`](Self::add_block) for a 3D point sample (one lane), each of the `K` sums
    /// with its weights, every coefficient of the block placed by `place` read: the block's
    /// 27 coefficients read at once by [`TileData::cube`] along the tile's axes, then summed in
    /// `add_block`'s order. The sum is written once per axis permutation, so that which cube
    /// entry each output coefficient is, is known at compile time.
    #[inline]
    fn add_cube<R: Real, const D: usize, const K: usize>(
        &self,
        sums: &mut [[R; 1]; K],
        weights: &[[&[[R; 1]; 3]; D]; K],
        place: &Placement<D>,
        m: usize,
        local0: &[[usize; 1]; D],
    ) where
        T: TileData<D>,
    {
        match place.permutation() {
            0 => self.add_cube_as::<R, D, K, 0>(sums, weights, place, m, local0),
            1 => self.add_cube_as::<R, D, K, 1>(sums, weights, place, m, local0),
            2 => self.add_cube_as::<R, D, K, 2>(sums, weights, place, m, local0),
            3 => self.add_cube_as::<R, D, K, 3>(sums, weights, place, m, local0),
            4 => self.add_cube_as::<R, D, K, 4>(sums, weights, place, m, local0),
            _ => self.add_cube_as::<R, D, K, 5>(sums, weights, place, m, local0),
        }
    }

    /// [`add_cube`](Self::add_cube) for the blocks whose output axis `a` reads tile axis
    /// `PERMUTATIONS3[P][a]`. Only called with `D = 3`; the indices taken `% D` keep the
    /// 2D instantiation, which nothing calls, free of out-of-range indexing.
    #[inline]
    fn add_cube_as<R: Real, const D: usize, const K: usize, const P: usize>(
        &self,
        sums: &mut [[R; 1]; K],
        weights: &[[&[[R; 1]; 3]; D]; K],
        place: &Placement<D>,
        m: usize,
        local0: &[[usize; 1]; D],
    ) where
        T: TileData<D>,
    {
        let n = T::SIZE;
        let perm = PERMUTATIONS3[P];
        let flips = place.variant / 6;
        // The tile index along each tile axis of the three coefficients of the output axis
        // that reads it, as `axis_offsets` computes them (before the strides).
        let mut index = [[0usize; 3]; 3];
        for (a, &target) in perm.iter().enumerate() {
            let add = block_start(place, a % D, m, n);
            for (j, i) in index[target].iter_mut().enumerate() {
                *i = oriented(local0[a % D][0] + j + add, n, flips >> a & 1 == 1);
            }
        }
        let cube = self.tile.cube::<R>(index, self.tile.unit::<R>());
        for (sum, w) in sums.iter_mut().zip(weights) {
            let [s] = sum;
            for jx in 0..3 {
                let mut column = R::ZERO;
                for jy in 0..3 {
                    let mut line = R::ZERO;
                    for (jz, &[wz]) in w[2 % D].iter().enumerate() {
                        // Tile axis `perm[a]` is at output axis a's coefficient `j[a]`.
                        let mut k = [0; 3];
                        for (&target, j) in perm.iter().zip([jx, jy, jz]) {
                            k[target] = j;
                        }
                        let c = cube[k[2]][k[1]][k[0]];
                        line = line.saturating_add(wz.mul_fraction(c));
                    }
                    column = column.saturating_add(w[1][jy][0].mul_fraction(line));
                }
                *s = s.saturating_add(w[0][jx][0].mul_fraction(column));
            }
        }
    }
}

/// Every coefficient of a block (for [`Wavelet::add_block`]; one function, so one
/// instantiation wherever it is passed).
#[inline]
fn every(_axis: usize, _j: usize) -> bool {
    true
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

    /// Row by row, each column of coefficients the row's samples share summed once, rows
    /// that share their y/z coefficients together (`band/row.rs`).
    fn fill_grid(&self, grid: &Grid<R, D>, out: &mut [R]) -> Result<(), Error> {
        for_each_rows::<R, D, GROUP>(grid, out, |starts, values| {
            self.fill_rows(starts, |first| grid.lanes(0, first), values, |o, v| *o = v);
        })
    }

    /// `|Σ_c w(c) n_c| ≤ max |n_c|`: the weights are non-negative and sum to 1, and a
    /// blended coefficient is at most `(√2·cos(π/32))^D` (1.41ᴰ) times the tile's largest.
    /// Plus 2⁻¹⁰ for rounding, as for the lattice noises.
    fn amplitude_bound(&self) -> f32 {
        self.coefficient_bound::<D>() * (1.0 + 1e-6) + crate::lattice::ROUNDING
    }
}

#[cfg(test)]
mod tests {
    use super::{BLEND, ZONE, blend_axis, blend_weight, zone_at};
    use crate::{I16F16, Real};

    /// The zone table gives [`blend_weight`]'s weights at every place a crossing axis's
    /// coefficients can take, in both blocks, for several tile sizes and number types.
    fn zone_is_blend_weight<R: Real + core::fmt::Debug>() {
        let h = BLEND;
        for n in [11, 16, 32, 64] {
            for l0 in n - h - 2..n + h {
                for side in 0..2 {
                    let mut axis = [[R::from_f32(0.75)]; 3];
                    blend_axis(&mut axis, side, zone_at(l0, n, h));
                    for (j, [w]) in axis.into_iter().enumerate() {
                        let b: R = blend_weight(l0 + j + n - side * n, n, h);
                        assert_eq!(
                            w,
                            R::from_f32(0.75).mul_fraction(b),
                            "n {n} l0 {l0} side {side}"
                        );
                    }
                }
            }
        }
        // Both ends of each side's table are the weights of a whole block and of none.
        assert_eq!((ZONE[0][0], ZONE[0][2 * BLEND + 3]), (1 << 16, 0));
        assert_eq!((ZONE[1][0], ZONE[1][2 * BLEND + 3]), (0, 1 << 16));
    }

    #[test]
    fn zone_table_is_blend_weight() {
        zone_is_blend_weight::<f32>();
        zone_is_blend_weight::<f64>();
        zone_is_blend_weight::<I16F16>();
    }
}

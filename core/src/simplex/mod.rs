//! Simplex noise (Perlin 2001, "Noise hardware", and his patent US 6,867,776, expired in
//! January 2022; as explained by Gustavson, "Simplex noise demystified", 2005).
//!
//! Gradient noise on the simplicial lattice: `D + 1` corners per sample instead of `2ᴰ`, each
//! contributing a radially symmetric kernel `(r² − |d|²)⁴ (g·d)` that vanishes beyond `r`, with
//! no interpolation between corners. The lattice is the integer lattice *skewed* along the main
//! diagonal (`x_a + F·Σx`, `F = (√(D+1) − 1)/D`): a skewed unit cube splits into `D!`
//! simplices, and the one holding the point follows from the order of its fractions
//! (Gustavson's "rank" method). Offsets are *unskewed* by `G = (1 − 1/√(D+1))/D` from the
//! fractions. The skew itself splits each coordinate into its cell and fraction first and
//! skews the cells in integers, so every computation in the number type works with numbers
//! below 4 whatever the coordinate: fixed point cannot overflow, and `f32` keeps its fraction
//! bits far from the origin.
//!
//! **The falloff radius is the one that makes the noise continuous.** Gustavson's reference
//! code uses `r² = 0.6` in 3D and 4D, wider than the distance from some simplex faces to the
//! opposite corner, so a corner's kernel is cut while it is still non-zero and the noise jumps
//! across those faces (Gustavson's own correction, simplex-noise.js #9; webgl-noise narrowed
//! its 4D radius in 2025 for the same reason). bandnoise uses `r² = ½` in 2D–4D, the height of
//! the 2D simplex, and the kernel reaches zero with its first three derivatives at `r`, so the
//! noise is C² everywhere. `tests/tests/simplex.rs` measures the largest jump across simplex
//! faces for both radii. In 1D the "simplices" are the unit cells and `r = 1`, Gustavson's 1D
//! noise.
//!
//! **Batches** ([`Noise::fill_grid`](crate::Noise::fill_grid), `fill_points`) run the same
//! body over 16 points at once, each step a loop over the points, so that the arithmetic
//! vectorises: the same operations on the same numbers as a point sample, bit for bit.
//!
//! **Hash**: a corner `c` hashes to `(s ⊕ c₀·P₀ ⊕ c₁·P₁ ⊕ …) · M` in wrapping 32-bit
//! integers, `s` a mix of the seed, `Pₐ` a prime per axis and `M` an odd multiplier
//! (FastNoise Lite's primes and multiplier), and the gradient is chosen by the product's top
//! bits, the best mixed. No table and no chain of dependent loads (a permutation chain such
//! as [`Perlin`](crate::lattice::Perlin)'s `p[p[x] + y]` must be looked up lane by lane and
//! repeats every 256 cells): a batch hashes 4 lanes per vector instruction, and the noise
//! repeats only every 2³² cells. The top bits' statistics are tested (uniform, independent
//! of the neighbours').
//!
//! **Gradients** are Perlin's sets: 1D slopes `±¼ … ±1` (3 bits), the 12 cube edges in 3D
//! (Perlin's `grad`, as Gustavson's `grad3`; 4 bits), their projections onto the plane in 2D,
//! the 32 tesseract edges in 4D (Gustavson's `grad4`; 5 bits). Dot products with gradient
//! components in `{−1, 0, 1}` are additions: a point sample reads the gradient's row from a
//! table, a batch picks the signed offsets by selects (the same values).
//!
//! **No periodic variant**: the simplicial lattice's periods lie along the skewed axes, not
//! along x and y, so a rectangle of simplex noise cannot be tiled seamlessly by wrapping the
//! cells as [`Periodic`](crate::lattice::Periodic) does; periodic simplex noise needs another
//! lattice (Gustavson & McEwan 2022, psrdnoise: a stretched hexagonal lattice in 2D).
//!
//! # Examples
//!
//! ```
//! use bandnoise::{I16F16, Noise, NoiseGradient, simplex::Simplex};
//!
//! let noise = Simplex::new(7);
//! let v: f32 = noise.sample([0.3, 4.7]);
//! assert!(v.abs() <= noise.amplitude_bound::<2>());
//! // The gradient comes with the same value, bit for bit.
//! let (w, g): (f32, [f32; 2]) = noise.sample_with_gradient([0.3, 4.7]);
//! assert_eq!(v.to_bits(), w.to_bits());
//! // Fixed point follows f32 closely.
//! let q: I16F16 = noise.sample([I16F16::from_num(0.3), I16F16::from_num(4.7)]);
//! assert!((q.to_num::<f32>() - v).abs() < 1e-3);
//! # let _ = g;
//! ```

mod flow;
mod open;

pub use flow::{Flow, FlowSum};
pub use open::{Improve, OpenSimplex2, OpenSimplex2S};

use crate::batch::LANES;
use crate::hash::prime::PrimeHash;
use crate::lattice::perlin::{grad3, grad4_dot, gradient_of};
use crate::{Real, arch};

/// Simplex noise in 1 to 4 dimensions, continuous (C²) with its analytic gradient.
///
/// * **Lattice**: Perlin's simplices (the skewed integer lattice, module docs); 1D: the
///   integer cells.
/// * **Kernel**: `(1 − |d|²/r²)⁴ (g·d)` per corner, `r² = ½` (1D: `r² = 1`), scaled so the
///   largest value is 1.
/// * **Hash and gradients**: a multiplicative hash of each corner and the seed, its top bits
///   choosing one of Perlin's gradients (module docs).
/// * **Range**: `|n| ≤ 1`, measured: the largest value over all gradient choices, found by a
///   grid search over a skewed cell refined by coordinate ascent (`tests/tests/simplex.rs`;
///   1D: 81/256 at a cell's middle, exactly), sets the scale; [`Noise::amplitude_bound`] adds
///   2⁻¹⁰ for rounding. The proved bound is looser: `D + 1` corners at their single peak,
///   `(8/9)⁴ r/3` times the steepest gradient's length, 1.3 (1D) to 5 (4D) times the maximum.
///   Measured variance 0.145, 0.200, 0.154, 0.064 (1D–4D).
/// * **Fixed point** follows `f32` within 5.3·10⁻⁴ (4D; 3.9·10⁻⁴ in 2D, measured over
///   2·10⁵ points of `|x| < 256`): each rounding of `τ = 1 − |d|²/r²` is amplified by the
///   fourth power's slope and by the scale.
/// * **Bad input**: a non-finite coordinate, or coordinates whose sum overflows, sample the
///   origin's cell (as [`Real::split`]); fixed point takes any coordinate exactly.
///
/// [`Noise::amplitude_bound`]: crate::Noise::amplitude_bound
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Simplex {
    hash: PrimeHash,
}

impl Simplex {
    /// Simplex noise for `seed`. `const`, so `static NOISE: Simplex = Simplex::new(7);` works;
    /// the noise is 4 bytes (the mixed seed).
    #[must_use]
    pub const fn new(seed: u32) -> Self {
        Self {
            hash: PrimeHash::new(seed),
        }
    }
}

impl Default for Simplex {
    fn default() -> Self {
        Self::new(0)
    }
}

/// Where the corners of a simplex noise take their gradients from their hashes.
pub(crate) trait Gradients<R: Real, const D: usize> {
    /// The gradient of the corner whose hash is `h` (32 bits: each set reads its top bits,
    /// the best mixed).
    fn gradient(&self, h: u32) -> [R; D];
    /// `d · g` for an offset component `d` (below 2) and a gradient component `g`.
    fn times(d: R, g: R) -> R;
    /// `g · d` for the corner whose hash is `h`: the sum of [`times`](Self::times) in axis
    /// order (a point sample's form: one table row per corner).
    #[inline(always)]
    fn dot(&self, h: u32, d: &[R; D]) -> R {
        let g = self.gradient(h);
        let mut sum = R::ZERO;
        for (x, c) in d.iter().zip(g) {
            sum = sum + Self::times(*x, c);
        }
        sum
    }
    /// [`dot`](Self::dot) in a form that vectorises over lanes (a set may compute it by
    /// selects instead of a table: the same value; a zero's sign may differ, which sampling
    /// canonicalises).
    #[inline(always)]
    fn dot_lanes(&self, h: u32, d: &[R; D]) -> R {
        self.dot(h, d)
    }
}

/// Perlin's gradient sets (module docs), chosen by the hash's top bits: 1D slopes
/// `±¼ … ±1` (3 bits), the 12 cube edges of his `grad` in 2D and 3D (4 bits; 2D takes their
/// x and y), the 32 tesseract edges in 4D (5 bits).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct PerlinGradients;

impl PerlinGradients {
    /// The hash bits a `dims`-dimensional gradient is chosen by.
    const fn bits(dims: usize) -> u32 {
        match dims {
            1 => 3,
            2 | 3 => 4,
            _ => 5,
        }
    }
}

impl<R: Real, const D: usize> Gradients<R, D> for PerlinGradients {
    #[inline(always)]
    fn gradient(&self, h: u32) -> [R; D] {
        gradient_of(h >> (32 - Self::bits(D)))
    }
    #[inline(always)]
    fn times(d: R, g: R) -> R {
        if D == 1 {
            d.mul_fraction(g)
        } else {
            d.mul_unit(g)
        }
    }
    /// Components are exact units in 2D–4D, so the dot product is a signed sum of offsets:
    /// Perlin's `grad` (2D with `z = 0`) and its 4D counterpart, whose choices vectorise as
    /// selects.
    #[inline(always)]
    fn dot_lanes(&self, h: u32, d: &[R; D]) -> R {
        let b = h >> (32 - Self::bits(D));
        match D {
            2 | 3 => {
                let z = if D == 3 { d[2 % D] } else { R::ZERO };
                grad3(b, d[0], d[1 % D], z)
            }
            4 => grad4_dot(b, &core::array::from_fn(|a| d[a % D])),
            _ => self.dot(h, d),
        }
    }
}

/// The skew `F = (√(D+1) − 1)/D` in 2⁻³¹ units, by dimension (1D: no skew).
const SKEW: [i32; 5] = [0, 0, 786_033_569, 715_827_883, 663_608_942];

/// `G = (1 − 1/√(D+1))/D` in 2⁻³¹ units, by dimension: the `j`-th corner of a simplex lies
/// `j·G` back along the main diagonal. The corners' offsets use exact multiples of this one
/// rounded `G` (a separately rounded `j·G` would place a corner differently in the two cells
/// that share it, a jump of 10⁻⁹ across cell faces).
const UNSKEW: [i32; 5] = [0, 0, 453_816_693, 357_913_941, 296_774_941];

/// The scale `⌊2¹⁶ / max⌋ · 2⁻¹⁶` that makes the largest value 1, by dimension: `max` is the
/// largest `Σ (1 − |d|²/r²)⁴ (g·d)` over points and gradient choices (1D: 81/256 at a cell's
/// middle; searched in 2D–4D, `tests/tests/simplex.rs`).
const SCALE: [i32; 5] = [0, 207_126, 287_326, 314_903, 257_137];

/// The skewed cells of `N` points and the fractions of their skewed coordinates
/// `x_a + F·Σx`, to the type's precision at numbers below 4 whatever the coordinate: each
/// coordinate is split first, the cells' part `F·Σc` is taken in 64-bit integers (its whole
/// part added to the cells, its fraction rounded once), and only fractions are added in `R`.
/// (Skewing the coordinates themselves, as the reference code does, loses `f32`'s fraction
/// bits to their size: at 256 cells from the origin the offsets were off by 3·10⁻⁵.) Cells
/// wrap modulo 2³².
#[inline(always)]
fn skew<R: Real, const D: usize, const N: usize>(
    p: &[[R; N]; D],
    cell: &mut [[i32; N]; D],
    frac: &mut [[R; N]; D],
) {
    for a in 0..D {
        split(&p[a], &mut cell[a], &mut frac[a]);
    }
    if D == 1 {
        return;
    }
    let f = R::from_ratio(SKEW[D], 31);
    // In passes over the lanes, each of one kind (integers, then floats, then per axis), so
    // that a batch's 16 lanes vectorise (`bench/README.md`); a point's one lane is the same.
    let mut whole = [0i32; N];
    let mut part = [0i32; N];
    for l in 0..N {
        (part[l], whole[l]) = skewed_cells::<D>(core::array::from_fn(|a| cell[a][l]), N == 1);
    }
    let mut shared = [R::ZERO; N];
    for l in 0..N {
        // Sums start from their first term, not from 0: `0 + x` is `x` for these numbers
        // (`+0` included; none is `−0`), so the bits are the same and an addition is saved
        // (`bench/README.md`: the vector unit's operations bound a point).
        let mut fractions = frac[0][l];
        for axis in &frac[1..] {
            fractions = fractions + axis[l];
        }
        // Σf < D and F·D < 1.3: `shared` is below 2.3; its whole part is common to every
        // axis, and each fraction plus its fraction is below 2 (compare-and-subtract steps,
        // cheaper than a general split). In 2D the cells' part rounds to at most 1 and
        // F·Σf < 2F < 0.74, so `shared` is below 2 and one step is its floor (the second
        // would subtract 0 from every point, on the chain a sample waits for).
        let s = R::from_ratio(part[l], 31) + fractions.mul_fraction(f);
        let (mut up, mut s) = step_down(s);
        if D > 2 {
            let (up2, rest) = step_down(s);
            (up, s) = (up + up2, rest);
        }
        whole[l] = whole[l].wrapping_add(up);
        shared[l] = s;
    }
    for a in 0..D {
        for l in 0..N {
            let (up, t) = step_down(frac[a][l] + shared[l]);
            cell[a][l] = cell[a][l].wrapping_add(whole[l]).wrapping_add(up);
            frac[a][l] = t;
        }
    }
}

/// `F·Σc` for one lane's cells `c`, in units of 2⁻³¹: the low 31 bits (its fraction) and the
/// whole part modulo 2³². With `wide`, by one 64-bit product (a point); else from 32-bit
/// pieces, which SSE2 multiplies two lanes at a time (`pmuludq`; a batch's 16 lanes): `Σc`
/// is `lo + 2³²·hi` with `lo` its low 32 bits, so the product is `lo·F + 2³²·hi·F`, whose
/// second term moves only bits from 32 up: the same bits either way.
#[inline(always)]
fn skewed_cells<const D: usize>(c: [i32; D], wide: bool) -> (i32, i32) {
    let k = SKEW[D] as u32;
    if wide {
        let cells: i64 = c.iter().map(|&x| i64::from(x)).sum();
        // |Σc| < 2³³ and F < 2³¹·0.37: the product fits i64.
        let product = cells * i64::from(k);
        return ((product & 0x7FFF_FFFF) as i32, (product >> 31) as i32);
    }
    let (mut lo, mut hi) = (0u32, 0i32);
    for x in c {
        let (sum, carry) = lo.overflowing_add(x as u32);
        // x's sign extension is −1 or 0 above bit 31, plus the carry out of the low word.
        hi = hi.wrapping_add(x >> 31).wrapping_add(i32::from(carry));
        lo = sum;
    }
    let product = u64::from(lo) * u64::from(k);
    // Bits 31–62 of the whole product: the low product's, plus 2·hi·F from the high word.
    let whole = ((product >> 31) as u32).wrapping_add((hi as u32).wrapping_mul(k << 1));
    ((product as u32 & 0x7FFF_FFFF) as i32, whole as i32)
}

/// [`Real::split`] of `N` coordinates; 16 lanes take the vectorised form (the same bits).
#[inline(always)]
fn split<R: Real, const N: usize>(x: &[R; N], cell: &mut [i32; N], frac: &mut [R; N]) {
    if let (Ok(x), Ok(cell), Ok(frac)) = (
        <&[R; LANES]>::try_from(&x[..]),
        <&mut [i32; LANES]>::try_from(&mut cell[..]),
        <&mut [R; LANES]>::try_from(&mut frac[..]),
    ) {
        R::split_lanes(x, cell, frac);
    } else {
        for l in 0..N {
            (cell[l], frac[l]) = x[l].split();
        }
    }
}

/// The targets whose cores predict branches deep in an out-of-order pipeline, where a
/// mispredicted coin flip costs more than the arithmetic that avoids it.
pub(crate) const OUT_OF_ORDER: bool = cfg!(any(
    target_arch = "x86_64",
    target_arch = "x86",
    target_arch = "aarch64"
));

/// `(1, t − 1)` if `t ≥ 1`, else `(0, t)`: one step of the floor of a small non-negative number.
#[inline(always)]
fn step_down<R: Real>(t: R) -> (i32, R) {
    let up = t >= R::ONE;
    if !OUT_OF_ORDER {
        // Where branches are cheap (the microcontrollers: +2% instructions on the Cortex-M4F
        // the other way) or a subtraction is a library call, only where it is needed.
        (i32::from(up), if up { t - R::ONE } else { t })
    } else {
        // `t − 1` or `t − 0 = t`, the step subtracted as a number: as a select, the compiler
        // made the choice a branch, a coin flip for the predictor (bench/README.md).
        let up = i32::from(up);
        (up, t - R::from_i32(up))
    }
}

/// Whether the `j`-th corner of a `dims`-dimensional simplex is one step along the axis of
/// rank `rank` (in `0..dims`): the `j` axes ranked highest are (`rank + j ≥ dims`). The first
/// corner steps along none and the last along all whatever the ranks, so a point sample,
/// whose corners the compiler unrolls, compares only at the others (`bench/README.md`: 7%
/// fewer instructions in 2D, 8% in 3D; written per `N`, or as a bound on the rank, the
/// compiler laid the point sample out worse). Builds with the `small` feature compare at
/// every corner.
#[inline(always)]
fn stepped(rank: i32, j: usize, dims: usize) -> bool {
    if cfg!(feature = "small") {
        // Size first: one comparison for every corner (the shortcut's code is 0.65 KB of the
        // demo's module).
        rank + j as i32 >= dims as i32
    } else {
        j == dims || (j > 0 && rank + j as i32 >= dims as i32)
    }
}

/// `1/r²` as a shift: `r² = ½` in 2D–4D, 1 in 1D.
const fn inverse_radius_shift(dims: usize) -> u32 {
    if dims == 1 { 0 } else { 1 }
}

/// Simplex noise at `N` points (one for a point sample, [`LANES`] for a batch: each lane is
/// the same operations on the same numbers, so batches are `sample`'s bits), into `value`,
/// and with `GRADIENT`, its gradient into `gradient`. Written lane by lane in each step, so
/// that the arithmetic and the hashes vectorise (with `GRADIENT`, the gradients' rows are
/// read lane by lane).
#[inline(always)]
#[allow(
    clippy::needless_range_loop,
    reason = "each step loops over the lanes innermost, indexing the axis arrays, so that it vectorises"
)]
pub(crate) fn simplex<R, G, const D: usize, const N: usize, const GRADIENT: bool>(
    hash: &PrimeHash,
    gradients: &G,
    scale: i32,
    p: &[[R; N]; D],
    value: &mut [R; N],
    gradient: &mut [[R; N]; D],
) where
    R: Real,
    G: Gradients<R, D>,
{
    let mut cell = [[0i32; N]; D];
    let mut offset = [[R::ZERO; N]; D];
    skew(p, &mut cell, &mut offset);
    // Gustavson's ranks: the axis with the largest fraction is stepped first (ties go to the
    // later axis; a tie is a simplex face, where both choices give the same value).
    // Signed: SSE2 compares only signed integers.
    let mut rank = [[0i32; N]; D];
    for a in 0..D {
        for b in a + 1..D {
            for l in 0..N {
                let greater = i32::from(offset[a][l] > offset[b][l]);
                rank[a][l] += greater;
                rank[b][l] += 1 - greater;
            }
        }
    }
    // Unskewed offsets from the first corner. Σu < D and G < ¼: the product is below 1.
    let g = R::from_ratio(UNSKEW[D], 31);
    for l in 0..N {
        let mut sum = offset[0][l];
        for a in 1..D {
            sum = sum + offset[a][l];
        }
        let back = sum.mul_fraction(g);
        for a in 0..D {
            offset[a][l] = offset[a][l] - back;
        }
    }
    // Each axis's hash term `c·Pₐ` of the first corner's cell.
    let mut term = [[0u32; N]; D];
    for a in 0..D {
        for l in 0..N {
            term[a][l] = PrimeHash::axis(a, cell[a][l]);
        }
    }
    let shift = inverse_radius_shift(D);
    *value = [R::ZERO; N];
    *gradient = [[R::ZERO; N]; D];
    for j in 0..=D {
        // The j-th corner: one step along each of the j axes ranked highest. j·G < 2³¹:
        // exact in every type's precision of 2⁻³¹ units.
        let diagonal = R::from_ratio(UNSKEW[D] * j as i32, 31);
        let mut d = [[R::ZERO; N]; D];
        let mut tau = [R::ZERO; N];
        for l in 0..N {
            // |d| < 2 per axis: the squares and their sum stay in range.
            let mut q = R::ZERO;
            for a in 0..D {
                let x = offset[a][l] + diagonal;
                let x = if stepped(rank[a][l], j, D) {
                    x - R::ONE
                } else {
                    x
                };
                d[a][l] = x;
                q = q + x.mul_fraction(x);
            }
            // τ = 1 − |d|²/r², exact (a doubling); the corner contributes where τ > 0.
            // Clamped rather than skipped: a corner out of reach adds an exact 0 (a branch
            // here is a coin flip for the predictor).
            let mut t = R::ONE - q;
            if shift == 1 {
                t = t - q;
            }
            tau[l] = if t > R::ZERO { t } else { R::ZERO };
        }
        // The corners' hashes and dot products: integer products and selects over all
        // lanes (no table), then the kernel.
        let mut dot = [R::ZERO; N];
        let mut g = [[R::ZERO; N]; D];
        for l in 0..N {
            let mut h = hash.start();
            let mut dl = [R::ZERO; D];
            for a in 0..D {
                let step = stepped(rank[a][l], j, D);
                // (c + 1)·P = c·P + P, wrapping.
                h ^= term[a][l].wrapping_add(if step { PrimeHash::PRIMES[a & 3] } else { 0 });
                dl[a] = d[a][l];
            }
            let h = PrimeHash::finish(h);
            dot[l] = if N == 1 {
                gradients.dot(h, &dl)
            } else {
                gradients.dot_lanes(h, &dl)
            };
            if GRADIENT {
                let row = gradients.gradient(h);
                for a in 0..D {
                    g[a][l] = row[a];
                }
            }
        }
        for l in 0..N {
            let dot = dot[l];
            let tau2 = tau[l].mul_fraction(tau[l]);
            let tau4 = tau2.mul_fraction(tau2);
            // τ⁴ ≤ 1 and the other factors are small (below): every product fits, so the
            // cheaper `mul_fraction` (no saturation; 32-bit halves on ARMv6-M) rounds as
            // `mul_rn` would.
            value[l] = value[l] + tau4.mul_fraction(dot);
            if GRADIENT {
                // ∂/∂x [τ⁴ (g·d)] = τ⁴ g − 8τ³ (g·d) d / r²: with r² = ½, 16τ³ (g·d) d.
                let tau3 = tau2.mul_fraction(tau[l]);
                // |g·d| < 4, so 8·τ³(g·d)·2 stays within ±64.
                let mut radial = tau3.mul_fraction(dot);
                for _ in 0..3 + shift {
                    radial = radial + radial;
                }
                for a in 0..D {
                    gradient[a][l] =
                        gradient[a][l] + tau4.mul_fraction(g[a][l]) - radial.mul_fraction(d[a][l]);
                }
            }
        }
    }
    let scale = R::from_ratio(scale, 16);
    for l in 0..N {
        // |value| ≤ 1/scale, so the product is at most 1.
        value[l] = value[l].mul_fraction(scale).canonical();
        if GRADIENT {
            for a in 0..D {
                // Gradient components stay below 64 before and after scaling.
                gradient[a][l] = gradient[a][l].mul_fraction(scale).canonical();
            }
        }
    }
}

/// A batch through the target's corner kernel ([`arch::simplex_corners`], `f32` in 2D and
/// 3D on x86-64): the skew here, the rest there, the same bits as [`simplex`]. `false`
/// (nothing written) where there is none.
#[inline]
fn corners_kernel<R: Real, const D: usize>(
    hash: &PrimeHash,
    p: &[[R; LANES]; D],
    out: &mut [R; LANES],
) -> bool {
    if !arch::SIMPLEX_CORNERS || !R::BINARY32 || !(D == 2 || D == 3) {
        return false;
    }
    let mut cell = [[0i32; LANES]; D];
    let mut offset = [[R::ZERO; LANES]; D];
    skew(p, &mut cell, &mut offset);
    let offset = offset.map(|o| o.map(R::to_f32));
    let lanes = arch::SimplexLanes {
        cell: &cell,
        offset: &offset,
        constants: kernel_constants::<R, D>(hash),
    };
    let mut value = [0.0f32; LANES];
    if !arch::simplex_corners(&lanes, &mut value) {
        return false;
    }
    *out = value.map(R::from_f32);
    true
}

/// A point through the target's point kernel ([`arch::simplex_point`], `f32` in 3D on
/// x86-64): the skew here, the corners there, the same bits as [`simplex`]. `None` where
/// there is none.
#[inline(always)]
fn point_kernel<R: Real, const D: usize>(hash: &PrimeHash, p: [R; D]) -> Option<R> {
    if !arch::SIMPLEX_POINT || !R::BINARY32 || D != 3 {
        return None;
    }
    let mut cell = [[0i32; 1]; D];
    let mut offset = [[R::ZERO; 1]; D];
    skew(&p.map(|x| [x]), &mut cell, &mut offset);
    let k = kernel_constants::<R, D>(hash);
    arch::simplex_point(cell.map(|c| c[0]), offset.map(|o| o[0].to_f32()), &k).map(R::from_f32)
}

/// The target kernels' constants in `f32`, as the portable body computes them in `R`.
#[inline(always)]
fn kernel_constants<R: Real, const D: usize>(hash: &PrimeHash) -> arch::SimplexConstants {
    arch::SimplexConstants {
        start: hash.start(),
        unskew: R::from_ratio(UNSKEW[D], 31).to_f32(),
        // j·G < 2³¹ for j ≤ D (the corners); the rest is unused.
        diagonal: core::array::from_fn(|j| {
            if j <= D {
                R::from_ratio(UNSKEW[D] * j as i32, 31).to_f32()
            } else {
                0.0
            }
        }),
        scale: R::from_ratio(SCALE[D], 16).to_f32(),
    }
}

macro_rules! simplex_impls {
    ($($d:literal),*) => {$(
        impl<R: Real> crate::Noise<R, $d> for Simplex {
            #[inline]
            fn sample(&self, p: [R; $d]) -> R {
                if let Some(v) = point_kernel(&self.hash, p) {
                    return v;
                }
                let (mut value, mut gradient) = ([R::ZERO], [[R::ZERO]; $d]);
                let p = p.map(|x| [x]);
                simplex::<R, _, $d, 1, false>(&self.hash, &PerlinGradients, SCALE[$d], &p, &mut value, &mut gradient);
                value[0]
            }
            fn amplitude_bound(&self) -> f32 {
                1.0 + crate::lattice::ROUNDING
            }
            fn sample_lanes(&self, p: &[[R; LANES]; $d], out: &mut [R; LANES]) {
                if corners_kernel(&self.hash, p, out) {
                    return;
                }
                let mut gradient = [[R::ZERO; LANES]; $d];
                simplex::<R, _, $d, LANES, false>(&self.hash, &PerlinGradients, SCALE[$d], p, out, &mut gradient);
            }
        }

        impl<R: Real> crate::NoiseGradient<R, $d> for Simplex {
            #[inline]
            fn sample_with_gradient(&self, p: [R; $d]) -> (R, [R; $d]) {
                let (mut value, mut gradient) = ([R::ZERO], [[R::ZERO]; $d]);
                let p = p.map(|x| [x]);
                simplex::<R, _, $d, 1, true>(&self.hash, &PerlinGradients, SCALE[$d], &p, &mut value, &mut gradient);
                (value[0], gradient.map(|g| g[0]))
            }
        }
    )*};
}

simplex_impls!(1, 2, 3, 4);
crate::noise::inherent_amplitude_bound!(Simplex, []);

#[cfg(test)]
mod tests {
    use super::{
        LANES, PerlinGradients, SCALE, SKEW, corners_kernel, point_kernel, simplex, skewed_cells,
    };
    use crate::hash::prime::PrimeHash;
    use crate::{I16F16, Real};

    /// The 2D skew takes one step of the floor of its shared part (`skew`): even the largest
    /// cells' part and the largest fractions put it below 2, in every number type (a second
    /// step would find nothing to subtract).
    #[test]
    fn shared_skew_2d_is_below_two() {
        /// `skew`'s shared part for the largest part of the cells and `D` fractions `f`.
        fn largest<R: Real, const D: usize>(f: R) -> R {
            let sum = (1..D).fold(f, |sum, _| sum + f);
            R::from_ratio(0x7FFF_FFFF, 31) + sum.mul_fraction(R::from_ratio(SKEW[D], 31))
        }
        let two = |x: f64| x < 2.0;
        assert!(two(f64::from(largest::<f32, 2>(1.0 - f32::EPSILON / 2.0))));
        assert!(two(largest::<f64, 2>(1.0 - f64::EPSILON / 2.0)));
        assert!(two(largest::<I16F16, 2>(I16F16::from_bits(0xFFFF)).to_num()));
        // Not in 3D (the part rounds to 1 in f32, and F·Σf to just below 1): 3D keeps both.
        assert!(!two(f64::from(largest::<f32, 3>(1.0 - f32::EPSILON / 2.0))));
    }

    /// The batch's skew of the cells from 32-bit pieces is the point's 64-bit product, bit for
    /// bit: cells at the ends of `i32` (sums past 2³¹ either way), around 0 and random, 2D–4D.
    #[test]
    fn skewed_cells_in_pieces_are_the_product() {
        fn check<const D: usize>(c: [i32; D]) {
            assert_eq!(
                skewed_cells::<D>(c, false),
                skewed_cells::<D>(c, true),
                "{c:?}"
            );
        }
        let edges = [
            i32::MIN,
            i32::MIN + 1,
            -65_537,
            -2,
            -1,
            0,
            1,
            2,
            65_536,
            i32::MAX - 1,
            i32::MAX,
        ];
        let mut state = 0x2545_F491_4F6C_DD1Du64;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state as i32
        };
        for &a in &edges {
            for &b in &edges {
                check([a, b]);
                check([a, b, next()]);
                check([b, a, a, b]);
                check([a, next(), b, next()]);
            }
        }
        for _ in 0..100_000 {
            check([next(), next()]);
            check([next(), next(), next()]);
            check([next(), next(), next(), next()]);
        }
    }

    /// The target's corner kernel and point kernel (where there are) give the portable body's
    /// bits, over 16 lanes and at each of their points: random points near and far from the
    /// origin, points on cell and simplex faces, and non-finite coordinates, 2D and 3D,
    /// several seeds.
    #[test]
    fn corner_and_point_kernels_are_the_body() {
        /// Whether the point kernel ran.
        fn points<const D: usize>(hash: &PrimeHash, p: &[[f32; LANES]; D]) -> bool {
            let mut ran = false;
            let lanes = (0..LANES).map(|l| -> [f32; D] { core::array::from_fn(|a| p[a][l]) });
            for point in lanes {
                let (mut want, mut gradient) = ([0.0f32], [[0.0f32]; D]);
                let lane = point.map(|x| [x]);
                simplex::<f32, _, D, 1, false>(
                    hash,
                    &PerlinGradients,
                    SCALE[D],
                    &lane,
                    &mut want,
                    &mut gradient,
                );
                if let Some(got) = point_kernel(hash, point) {
                    assert_eq!(
                        got.to_bits(),
                        want[0].to_bits(),
                        "{point:?}: {got} {}",
                        want[0]
                    );
                    ran = true;
                }
            }
            ran
        }
        fn check<const D: usize>(hash: &PrimeHash, p: &[[f32; LANES]; D]) -> bool {
            let mut want = [0.0f32; LANES];
            let mut gradient = [[0.0f32; LANES]; D];
            simplex::<f32, _, D, LANES, false>(
                hash,
                &PerlinGradients,
                SCALE[D],
                p,
                &mut want,
                &mut gradient,
            );
            let mut got = [0.0f32; LANES];
            if !corners_kernel(hash, p, &mut got) {
                return false;
            }
            for l in 0..LANES {
                let point: [f32; D] = core::array::from_fn(|a| p[a][l]);
                assert_eq!(
                    got[l].to_bits(),
                    want[l].to_bits(),
                    "{point:?}: {} {}",
                    got[l],
                    want[l]
                );
            }
            true
        }
        let mut next = crate::testing::xorshift32(0x9E37_79B9);
        let specials = crate::testing::SPECIAL_COORDINATES;
        let (mut ran, mut ran_points) = (false, false);
        for seed in [0, 1, 77, u32::MAX] {
            let hash = PrimeHash::new(seed);
            for round in 0..4000 {
                let mut coordinate = |_| {
                    let r = next();
                    match round % 4 {
                        // Near the origin, on a grid of simplex faces (multiples of 1/8), far
                        // away, and special values.
                        0 => (r as f32 / u32::MAX as f32 - 0.5) * 20.0,
                        1 => (r % 64) as f32 / 8.0 - 4.0,
                        2 => (r as i32) as f32 / 64.0,
                        _ => specials[(r % specials.len() as u32) as usize],
                    }
                };
                let p2: [[f32; LANES]; 2] =
                    core::array::from_fn(|_| core::array::from_fn(&mut coordinate));
                let p3: [[f32; LANES]; 3] =
                    core::array::from_fn(|_| core::array::from_fn(&mut coordinate));
                ran |= check(&hash, &p2);
                ran |= check(&hash, &p3);
                ran_points |= points(&hash, &p2);
                ran_points |= points(&hash, &p3);
            }
        }
        // Where the target has the kernels, they ran.
        assert_eq!(ran, crate::arch::SIMPLEX_CORNERS);
        assert_eq!(ran_points, crate::arch::SIMPLEX_POINT);
    }
}

//! Cellular noise (Worley 1996, "A Cellular Texture Basis Function"): the distances from a point
//! to the nearest feature points of a random point set, `F1` and `F2`, their difference (the
//! cell borders), and the value of the nearest point's cell.
//!
//! **Feature points.** Every unit cell holds one feature point (as every peer does; Worley's
//! own code drew Poisson counts of mean 2.5), placed by the cell's [`CellRng`], keyed by the
//! cell's multiplicative hash `(s ⊕ x·P₀ ⊕ y·P₁ ⊕ …)·M` (simplex noise's, with FastNoise Lite's
//! primes: one product per axis, so the cells around a point share their terms and are hashed
//! as lanes; the generator's draw does the mixing). Its first draw
//! gives each axis `32/D` bits (16 in 1D and 2D, 10 in 3D, 8 in 4D), a position `u` in
//! `[0, 1)`, and the point sits at `½ + jitter·(u − ½)` across the cell, computed in 16.16
//! integers, so the points are the same in every number type and on every target. `jitter = 1`
//! spreads them over the whole cell; `0` puts each at its cell's centre (a square grid); values
//! between give the irregular but even tilings of FastNoise's `GridJitter`. The cell's value
//! (the [`Output::CellValue`] of the points nearest to it) is the generator's second draw, a
//! uniform number in `[−1, 1)`.
//!
//! **Exact, not approximate.** `F1` and `F2` are the exact nearest and second-nearest points,
//! found by a search over rings of cells around the point's cell, the point's own cell first,
//! ring by ring outwards, and stopping when the next ring cannot hold a point nearer than the
//! `F` sought. Every cell whose box of possible feature points is already farther than that
//! `F` is skipped before it is hashed (Worley's pruning, "doubles the speed"); the point's
//! cell and its neighbours are visited nearest first (own cell, faces, edges, corners), so
//! the `F` found early prunes the rest. On x86-64 in 2D and 3D, those 3ᴰ cells are hashed and
//! placed whole instead and offered in the same order (in `f32` by an SSE2 kernel, 4 cells per
//! vector, `arch::cellular_near`): the same `F1` and `F2` bit for bit,
//! faster where a mispredicted prune costs more than the hashes it saves (`bench/README.md`,
//! "cellular noise's near cells whole" and "cellular noise's multiplicative cell hash and SSE2
//! kernel"). A 3³
//! search, as most peers do, can miss `F2` (and, with the peers' looser placements, `F1`):
//! with `jitter = 1` the second-nearest point can lie two cells away. How far the search can
//! go is bounded: `F2` is never beyond the own cell's point and the near face neighbour's
//! (the bound [`Noise::amplitude_bound`](crate::Noise::amplitude_bound) reports), which is at most 4.5 cells in the worst
//! case (Manhattan, 4D, `jitter = 1`), so at most 5 rings are searched. `tests/tests/cellular.rs`
//! compares `F1`, `F2` and the cell value with a brute-force search over the 13ᴰ cells around
//! the point at 10⁵ random points per metric, jitter and dimension.
//!
//! **Distances** ([`Metric`]): Euclidean, squared Euclidean (no square root; the default of
//! FastNoise Lite), Manhattan and Chebyshev. The search compares squared Euclidean distances
//! and takes one square root per output. Fixed point works with the offsets from the point's own
//! cell (below 7 in every axis), so the squared distances stay far inside I16F16's range.
//!
//! **Values** are the distances themselves, not remapped to `[−1, 1]` (so a texture can use
//! them as distances: `F2 − F1` is the distance to the nearest cell border, up to a factor
//! ½ in the Euclidean metric); the cell value is in `[−1, 1)`. Ties between equally near
//! points go to the first found in the search order (they do not change `F1` or `F2`).
//!
//! **Gradients** ([`NoiseGradient`](crate::NoiseGradient)) are analytic: each distance's
//! gradient is the metric's derivative along the offset to its feature point (Euclidean: the
//! unit vector away from the point). They jump where the nearest point changes (`F1` has kinks
//! on cell borders) and the cell value's is 0 (it is piecewise constant).
//!
//! No periodic variant yet (wrapping the cells to a period, as
//! [`Periodic`](crate::lattice::Periodic) does for the lattice noises, would work: the search
//! hashes whole cells).
//!
//! # Examples
//!
//! ```
//! use bandnoise::{Noise, cellular::{Cellular, Metric, Output}};
//!
//! let worley = Cellular::new(7); // F1, Euclidean, jitter 1
//! let f1: f32 = worley.sample([0.3, 4.7]);
//! assert!((0.0..=worley.amplitude_bound::<2>()).contains(&f1));
//! let borders = Cellular::new(7).with_output(Output::F2MinusF1).with_metric(Metric::Manhattan);
//! let b: f32 = borders.sample([0.3, 4.7]);
//! assert!(b >= 0.0);
//! // A regular grid of points: jitter 0.
//! let grid = Cellular::new(7).with_jitter(0.0)?;
//! let d: f64 = grid.sample([0.5, 0.5]);
//! assert_eq!(d, 0.0);
//! # Ok::<(), bandnoise::Error>(())
//! ```

use crate::arch::{self, CellularCells, NearLanes, NearPair};
use crate::hash::CellRng;
use crate::hash::prime::PrimeHash;
use crate::lattice::kernel::split_point;
use crate::{Error, Real};

/// How cellular noise measures the distance from a point to a feature point.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Metric {
    /// `√(Σ dₐ²)`, the usual distance: round cells.
    #[default]
    Euclidean,
    /// `Σ dₐ²`: Euclidean cells (the same nearest points) with values growing quadratically.
    EuclideanSquared,
    /// `Σ |dₐ|`: diamond-shaped falloff, straight cell borders at 45°.
    Manhattan,
    /// `max |dₐ|`: square falloff.
    Chebyshev,
}

impl Metric {
    /// Every metric, in the order of the text form's documentation.
    pub const ALL: [Metric; 4] = [
        Metric::Euclidean,
        Metric::EuclideanSquared,
        Metric::Manhattan,
        Metric::Chebyshev,
    ];

    /// The key the search compares for one axis's offset `d ≥ 0`: `d²` for the Euclidean
    /// metrics (no square root in the search), `d` otherwise.
    #[inline]
    fn axis_key<R: Real>(self, d: R) -> R {
        if matches!(self, Metric::Euclidean | Metric::EuclideanSquared) {
            d.mul_rn(d)
        } else {
            d
        }
    }

    /// Two keys combined: their sum, or their maximum for Chebyshev. Both grow with each
    /// axis's key, which lets the search skip a cell as soon as its box is out of reach.
    #[inline]
    fn combine<R: Real>(self, a: R, b: R) -> R {
        if self != Metric::Chebyshev {
            a + b
        } else if b > a {
            b
        } else {
            a
        }
    }

    /// The metric's name in the text form (`euclidean`, `squared`, `manhattan`, `chebyshev`).
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Metric::Euclidean => "euclidean",
            Metric::EuclideanSquared => "squared",
            Metric::Manhattan => "manhattan",
            Metric::Chebyshev => "chebyshev",
        }
    }
}

/// The nearest and second-nearest feature points found so far: their keys (as
/// [`Metric::axis_key`] and [`Metric::combine`] make them), their offsets from the point, and
/// the nearest one's cell hash.
struct Nearest<R, const D: usize> {
    keys: [R; 2],
    offsets: [[R; D]; 2],
    hash: u32,
}

impl<R: Real, const D: usize> Nearest<R, D> {
    /// Keeps the point at key `d` and offset `q` (of the cell whose hash is `key`) if it is
    /// nearer than the second-nearest so far.
    #[inline]
    fn offer(&mut self, d: R, q: [R; D], key: u32) {
        if keep_nearest(&mut self.keys, &mut self.offsets, d, q) {
            self.hash = key;
        }
    }

    /// [`offer`](Self::offer) where only the nearest is sought: keeps the point if it is
    /// the nearest so far (the second key is left as it is), by selects rather than a
    /// branch, which is a coin flip for a predictor. Only on x86-64 (where [`PRUNE_NEAR`] is
    /// false): on the firmware cores `offer`'s branches are the cheaper (measured); wasm32
    /// keeps `offer` unmeasured.
    #[inline]
    fn offer_first(&mut self, d: R, q: [R; D], key: u32) {
        let nearer = d < self.keys[0];
        self.keys[0] = if nearer { d } else { self.keys[0] };
        for (o, q) in self.offsets[0].iter_mut().zip(q) {
            *o = if nearer { q } else { *o };
        }
        self.hash = if nearer { key } else { self.hash };
    }

    /// `F1` (`i = 0`) or `F2` (`i = 1`) in `metric`. The Euclidean distance is the length of
    /// the offset ([`norm`](crate::real::sealed::Sealed::norm)): in fixed point the square
    /// root of the rounded key would lose short distances (`√(2⁻¹⁶)` is 2⁻⁸). In floats it is
    /// the root of the key, which is `norm`'s sum of squares in its order, bit for bit.
    #[inline]
    fn distance(&self, metric: Metric, i: usize) -> R {
        match metric {
            Metric::Euclidean if R::FLOAT => self.keys[i].sqrt(),
            Metric::Euclidean => R::norm(self.offsets[i]),
            _ => self.keys[i],
        }
    }
}

/// Keeps `item`, at key `d`, among the nearest two `items` (keys `keys`, nearest first) if
/// it is nearer than the second: the earlier one stays ahead on ties. Whether it became the
/// nearest. ([`Nearest::offer`] keeps offsets; [`Cellular::near_whole`] cell indices.)
#[inline(always)]
fn keep_nearest<R: Real, T: Copy>(keys: &mut [R; 2], items: &mut [T; 2], d: R, item: T) -> bool {
    let nearest = d < keys[0];
    if nearest {
        keys[1] = keys[0];
        items[1] = items[0];
        keys[0] = d;
        items[0] = item;
    } else if d < keys[1] {
        keys[1] = d;
        items[1] = item;
    }
    nearest
}

/// What cellular noise returns.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Output {
    /// `F1`, the distance to the nearest feature point: 0 at the points, largest on the cell
    /// borders.
    #[default]
    F1,
    /// `F2`, the distance to the second-nearest feature point.
    F2,
    /// `F2 − F1`: 0 on the borders between cells, largest at the points (Worley's "cell
    /// borders", flagstones).
    F2MinusF1,
    /// The value of the nearest point's cell, uniform in `[−1, 1)`: flat-shaded cells (a
    /// Voronoi diagram).
    CellValue,
}

impl Output {
    /// Every output, in the order of the text form's documentation.
    pub const ALL: [Output; 4] = [Output::F1, Output::F2, Output::F2MinusF1, Output::CellValue];

    /// The output's name in the text form (`f1`, `f2`, `f2-f1`, `value`).
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Output::F1 => "f1",
            Output::F2 => "f2",
            Output::F2MinusF1 => "f2-f1",
            Output::CellValue => "value",
        }
    }

    /// Whether the search must find the second-nearest point too.
    const fn needs_f2(self) -> bool {
        matches!(self, Output::F2 | Output::F2MinusF1)
    }
}

/// `1` in the 16.16 units of feature point positions.
const UNIT: i32 = 1 << 16;

/// Whether the search prunes rings 0 and 1 cell by cell in 2D and 3D ([`Cellular::search`]):
/// on every target but x86-64, whose out-of-order cores search the whole 3ᴰ faster than the
/// pruned walk with its unpredictable branches (measured in `bench/README.md`). On the
/// in-order firmware cores pruning saves hashes; the demo's
/// module has no room for the whole search's code; other hosts are not measured. Where it
/// is true the pruned walk also keeps `F1` with `offer`, not [`Nearest::offer_first`].
const PRUNE_NEAR: bool = !cfg!(target_arch = "x86_64");

/// The most rings searched around the point's cell: ring `r + 1` is at least `r` away along
/// some axis, and `F2` is at most 4.5 away (Manhattan, 4D, jitter 1; see [`Cellular`]).
const MAX_RING: i32 = 5;

/// The 3ᴰ offsets of rings 0 and 1 in `D` dimensions ([`near_order`]): the point's own cell,
/// then the cells sharing a face with it, then an edge, and so on, so the nearest boxes come
/// first and the `F` they find prunes the farther ones (Worley's order). One table per
/// dimension, so a program links only those it samples (the demo's module: 108 bytes).
static NEAR_1: [[i8; 4]; 3] = near_order(1);
static NEAR_2: [[i8; 4]; 9] = near_order(2);
static NEAR_3: [[i8; 4]; 27] = near_order(3);
static NEAR_4: [[i8; 4]; 81] = near_order(4);

/// For `D` = 1 to 3 (entry `D − 1`), each cell of the near table (`NEAR_1`, …) as the index
/// [`Cellular::near_whole`] gives it: offset `k` is cell `Σ (kₐ + 1)·3^(D−1−a)` (axis 0 the
/// most significant digit, as the hash terms fork).
static NEAR_INDEX: [[u8; 27]; 3] = [
    near_index(&NEAR_1),
    near_index(&NEAR_2),
    near_index(&NEAR_3),
];

/// For `D` = 1 to 3 (entry `D − 1`), the offset along axis `a` of cell `i` of the 3ᴰ as
/// [`Cellular::near_whole`] numbers them: digit `a` of `i` in base 3, minus 1.
static DIGITS: [[[i8; 27]; 3]; 3] = [digits(1), digits(2), digits(3)];

const fn digits(dims: usize) -> [[i8; 27]; 3] {
    let mut out = [[0; 27]; 3];
    let mut count = 1;
    let mut a = 0;
    while a < dims {
        count *= 3;
        a += 1;
    }
    let mut i = 0;
    while i < count {
        let (mut rest, mut a) = (i, dims);
        while a > 0 {
            a -= 1;
            out[a][i] = (rest % 3) as i8 - 1;
            rest /= 3;
        }
        i += 1;
    }
    out
}

const fn near_index(near: &[[i8; 4]]) -> [u8; 27] {
    let mut out = [0; 27];
    let dims = match near.len() {
        3 => 1,
        9 => 2,
        _ => 3,
    };
    let mut n = 0;
    while n < near.len() {
        let mut index = 0;
        let mut a = 0;
        while a < dims {
            index = 3 * index + (near[n][a] + 1) as usize;
            a += 1;
        }
        out[n] = index as u8;
        n += 1;
    }
    out
}

/// The near cells of 2D and 3D as the lanes of [`arch::cellular_near`], in near order.
static NEAR_LANES: [NearLanes; 2] = [near_lanes(&NEAR_2, 2), near_lanes(&NEAR_3, 3)];

const fn near_lanes(near: &[[i8; 4]], dims: usize) -> NearLanes {
    let mut lanes = NearLanes {
        unit: [[0; 28]; 3],
        prime: [[0; 28]; 3],
    };
    let mut n = 0;
    while n < near.len() {
        let mut a = 0;
        while a < dims {
            let k = near[n][a] as i32;
            lanes.unit[a][n] = k * UNIT;
            lanes.prime[a][n] = (k as u32).wrapping_mul(PrimeHash::PRIMES[a]) as i32;
            a += 1;
        }
        n += 1;
    }
    lanes
}

/// The near table of `D` dimensions (1 to 4).
fn near_table<const D: usize>() -> &'static [[i8; 4]] {
    match D {
        1 => &NEAR_1,
        2 => &NEAR_2,
        3 => &NEAR_3,
        _ => &NEAR_4,
    }
}

const fn near_order<const N: usize>(dims: usize) -> [[i8; 4]; N] {
    let mut out = [[0i8; 4]; N];
    let mut n = 0;
    // By the number of non-zero offsets, then in odometer order.
    let mut nonzero = 0;
    while nonzero <= dims {
        let mut i = 0;
        while i < N {
            let (mut k, mut rest, mut count, mut a) = ([0i8; 4], i, 0, 0);
            while a < dims {
                k[a] = (rest % 3) as i8 - 1;
                if k[a] != 0 {
                    count += 1;
                }
                rest /= 3;
                a += 1;
            }
            if count == nonzero {
                out[n] = k;
                n += 1;
            }
            i += 1;
        }
        nonzero += 1;
    }
    out
}

/// Cellular noise (Worley 1996) in 1 to 4 dimensions: see the [module docs](self).
///
/// * **Defaults** ([`new`](Self::new)): `F1`, Euclidean, jitter 1.
/// * **Range**: the cell value is in `[−1, 1)`. Distances are at least 0 and at most the
///   distance to the second of two points always within reach, the own cell's and the face
///   neighbour's on the near side of axis 0: along axis 0 at most `1.5 − h`, along every other
///   axis `1 − h`, `h = (1 − jitter)/2` the margin between a cell's points and its borders. For
///   jitter 1 in 2D: `√3.25 ≈ 1.80` Euclidean, `3.25` squared, `2.5` Manhattan, `1.5`
///   Chebyshev. [`Noise::amplitude_bound`](crate::Noise::amplitude_bound) reports it (plus 2⁻¹⁰ for rounding).
/// * **Statistics** (jitter 1, Euclidean, measured over 10⁶ points in
///   `tests/tests/cellular.rs`): mean `F1` 0.43 in 2D, 0.52 in 3D.
///
/// # Examples
///
/// ```
/// use bandnoise::{I16F16, Noise, cellular::Cellular};
///
/// let worley = Cellular::new(1);
/// let v: f32 = worley.sample([2.25, -0.5, 7.0]);
/// let q: I16F16 = worley.sample([2.25, -0.5, 7.0].map(I16F16::from_num));
/// assert!((q.to_num::<f32>() - v).abs() < 1e-3);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Cellular {
    hash: PrimeHash,
    metric: Metric,
    output: Output,
    /// The jitter in 16.16 units, `0..=UNIT`.
    jitter: i32,
}

impl Default for Cellular {
    /// [`Cellular::new(0)`](Cellular::new).
    fn default() -> Self {
        Self::new(0)
    }
}

impl Cellular {
    /// Cellular noise for `seed`: `F1`, Euclidean, jitter 1. `const`, so
    /// `static N: Cellular = Cellular::new(3);` works.
    #[must_use]
    pub const fn new(seed: u32) -> Self {
        Self {
            hash: PrimeHash::new(seed),
            metric: Metric::Euclidean,
            output: Output::F1,
            jitter: UNIT,
        }
    }

    /// The same noise measuring distances with `metric`.
    #[must_use]
    pub const fn with_metric(self, metric: Metric) -> Self {
        Self { metric, ..self }
    }

    /// The same noise returning `output`.
    #[must_use]
    pub const fn with_output(self, output: Output) -> Self {
        Self { output, ..self }
    }

    /// The same noise with its feature points spread over `jitter` of each cell (0: at the
    /// centres; 1, the default: anywhere in the cell), rounded to a multiple of 2⁻¹⁶.
    ///
    /// # Errors
    ///
    /// [`Error::Jitter`] unless `0 ≤ jitter ≤ 1`.
    pub fn with_jitter(self, jitter: f32) -> Result<Self, Error> {
        if !(0.0..=1.0).contains(&jitter) {
            return Err(Error::Jitter(jitter));
        }
        // In range, so the rounded product is in 0..=UNIT.
        let jitter = libm::roundf(jitter * UNIT as f32) as i32;
        Ok(Self { jitter, ..self })
    }

    /// The metric.
    #[must_use]
    pub const fn metric(&self) -> Metric {
        self.metric
    }

    /// The output.
    #[must_use]
    pub const fn output(&self) -> Output {
        self.output
    }

    /// The jitter (a multiple of 2⁻¹⁶ in `[0, 1]`).
    #[must_use]
    pub fn jitter(&self) -> f32 {
        self.jitter as f32 / UNIT as f32
    }

    /// Where `cell`'s feature point lies, as offsets from the cell's lower corner in 16.16
    /// units (each in `[0, UNIT)`), from the cell's hash `key`.
    #[inline]
    fn offsets<const D: usize>(&self, key: u32) -> [i32; D] {
        let bits = CellRng::from_key(key).next_u32();
        core::array::from_fn(|a| self.axis_offset::<D>(bits, a))
    }

    /// Axis `a`'s offset of the feature point whose cell's first draw is `bits`
    /// ([`offsets`](Self::offsets)).
    #[inline]
    fn axis_offset<const D: usize>(&self, bits: u32, a: usize) -> i32 {
        let width = if D <= 2 { 16 } else { 32 / D as u32 };
        // Axis a's `width` bits, as a multiple of 2⁻¹⁶ in [0, 1) (`& 31` only says the
        // shift is in range to the compiler: it is below 32 for D ≤ 4).
        let u =
            ((bits >> ((32 - width * (a as u32 + 1)) & 31)) & ((1 << width) - 1)) << (16 - width);
        self.offset(u as i32)
    }

    /// The offset `½ + jitter·(u − ½)` across a cell of a point drawn at `u` (16.16, `u` in
    /// `0..UNIT`), floored.
    #[inline]
    fn offset(&self, u: i32) -> i32 {
        if self.jitter == UNIT {
            // The default, where the formula gives `u` itself: the search's loops over cells
            // then run without the multiply.
            return u;
        }
        // In i32: −2¹⁵ ≤ u − ½ < 2¹⁵ and 0 ≤ jitter ≤ 2¹⁶, so the product is in [−2³¹, 2³¹).
        UNIT / 2 + (((u - UNIT / 2) * self.jitter) >> 16)
    }

    /// The lowest and highest offset a feature point can have across its cell (16.16): those
    /// of `u = 0` and `u = 1 − 2⁻¹⁶` in [`offset`](Self::offset), `½ − ⌈jitter/2⌉` and
    /// `½ + ⌊(½ − 2⁻¹⁶)·jitter⌋`.
    ///
    /// In `i32` on purpose: written as `i64` products by constants, LLVM's constant hoisting
    /// miscompiled them for RV32IMC (rustc 1.95, opt-level 1 and above: the lowest offset
    /// came out as ½, so neighbours were pruned wrongly). The firmware checksums found it;
    /// `-C llvm-args=-opt-bisect-limit` narrowed it to `consthoist` on the search.
    #[inline]
    fn extent(&self) -> (i32, i32) {
        let j = self.jitter;
        (
            UNIT / 2 - ((j + 1) >> 1),
            UNIT / 2 + (((UNIT / 2 - 1) * j) >> 16),
        )
    }

    /// The feature point of `cell`: its coordinates in space (exact in `f64`).
    ///
    /// ```
    /// use bandnoise::cellular::Cellular;
    ///
    /// let p = Cellular::new(0).feature_point([3, -2]);
    /// assert!((3.0..4.0).contains(&p[0]) && (-2.0..-1.0).contains(&p[1]));
    /// ```
    #[must_use]
    pub fn feature_point<const D: usize>(&self, cell: [i32; D]) -> [f64; D] {
        let offsets = self.offsets::<D>(self.hash.hash(cell));
        core::array::from_fn(|a| cell[a] as f64 + offsets[a] as f64 / UNIT as f64)
    }

    /// The value of `cell` (what [`Output::CellValue`] returns where the cell's point is the
    /// nearest), uniform in `[−1, 1)`.
    #[must_use]
    pub fn cell_value<R: Real, const D: usize>(&self, cell: [i32; D]) -> R {
        Self::value_of_key(self.hash.hash(cell))
    }

    #[inline]
    fn value_of_key<R: Real>(key: u32) -> R {
        let mut rng = CellRng::from_key(key);
        rng.skip(1);
        rng.signed_uniform::<R>().canonical()
    }

    /// The bound on every distance output (see [`Cellular`]), in `D` dimensions.
    fn distance_bound(&self, dims: usize) -> f32 {
        let margin = (UNIT - self.jitter) as f32 / (2 * UNIT) as f32;
        let (near, other) = (1.5 - margin, 1.0 - margin);
        let others = (dims - 1) as f32;
        let bound = match self.metric {
            Metric::Euclidean => libm::sqrtf(near * near + others * other * other),
            Metric::EuclideanSquared => near * near + others * other * other,
            Metric::Manhattan => near + others * other,
            Metric::Chebyshev => near,
        };
        bound + crate::lattice::ROUNDING
    }

    /// Finds the nearest feature point (and the second-nearest where the output needs it).
    /// Out of line, and with the metric a value rather than a type parameter: one copy per
    /// number type and dimension however many entry points (point, batch, gradient,
    /// description) and metrics reach it. Compiled once per metric it was 6% faster on
    /// x86-64 (in 2D) but cost the demo's wasm module 7 KB, past its budget. On x86-64, where
    /// size matters less, it is inlined into [`value`](Self::value) and
    /// [`value_and_gradient`](Self::value_and_gradient), which are out of line instead: the
    /// search's result stays in registers (35 instructions fewer per 2D sample, 114 in 3D,
    /// than a call to the search, whose result returns through memory), and the copies are still one per
    /// number type, dimension and output (value, or value and gradient).
    #[cfg_attr(not(target_arch = "x86_64"), inline(never))]
    #[cfg_attr(target_arch = "x86_64", inline(always))]
    fn search<R: Real, const D: usize>(&self, p: [R; D]) -> Nearest<R, D> {
        self.search_in(p, (D == 2 || D == 3) && !PRUNE_NEAR)
    }

    /// [`search`](Self::search), with rings 0 and 1 searched whole
    /// ([`near_whole`](Self::near_whole)) or pruned cell by cell: the same result either way.
    #[inline(always)]
    fn search_in<R: Real, const D: usize>(&self, p: [R; D], whole: bool) -> Nearest<R, D> {
        let metric = self.metric;
        let needs_f2 = self.output.needs_f2();
        let (lo, hi) = self.extent();
        let mut best = Nearest {
            keys: [R::MAX; 2],
            offsets: [[R::ZERO; D]; 2],
            hash: 0,
        };
        // Where the near cells go whole, the target's kernel may split the point and search
        // them; otherwise the point is split here.
        let kernel = if whole {
            self.near_kernel(p, &mut best)
        } else {
            None
        };
        let (cell, frac) = kernel.unwrap_or_else(|| split_point(p));

        // Offers the point of the cell `cell + k` (whose hash is `key`).
        let offer = |k: &[i32; D], key: u32, best: &mut Nearest<R, D>| {
            let offsets = self.offsets::<D>(key);
            let mut d = R::ZERO;
            let mut q = [R::ZERO; D];
            for a in 0..D {
                q[a] = R::from_ratio(k[a] * UNIT + offsets[a], 16) - frac[a];
                d = metric.combine(d, metric.axis_key(q[a].abs()));
            }
            if needs_f2 || PRUNE_NEAR {
                best.offer(d, q, key);
            } else {
                best.offer_first(d, q, key);
            }
        };
        // How far the box of cell k's possible points lies from the point along axis a.
        let gap = |a: usize, k: i32| -> R {
            let low = R::from_ratio(k * UNIT + lo, 16) - frac[a];
            let high = frac[a] - R::from_ratio(k * UNIT + hi, 16);
            metric.axis_key(if low > R::ZERO {
                low
            } else if high > R::ZERO {
                high
            } else {
                R::ZERO
            })
        };

        let reach = |best: &Nearest<R, D>| best.keys[needs_f2 as usize];
        let start = self.hash.start();
        // Offers the point of cell `cell + k` unless its box's key is already out of reach
        // (then the cell is not even hashed).
        let visit = |k: &[i32; D], box_key: R, best: &mut Nearest<R, D>| {
            if box_key < reach(best) {
                let mut h = start;
                for a in 0..D {
                    h ^= PrimeHash::axis(a, cell[a].wrapping_add(k[a]));
                }
                offer(k, PrimeHash::finish(h), best);
            }
        };

        if kernel.is_some() {
            // Rings 0 and 1 are searched.
        } else if whole {
            self.near_whole(cell, frac, &mut best);
        } else {
            // Rings 0 and 1, the 3ᴰ cells around the point's, nearest boxes first (see
            // `NEAR_1`); a cell whose box of possible points is out of reach is skipped before
            // it is hashed. Axis a's box keys for offsets −1, 0, 1:
            let near_gaps: [[R; 3]; D] = core::array::from_fn(|a| [-1, 0, 1].map(|k| gap(a, k)));
            for k in near_table::<D>() {
                let k: [i32; D] = core::array::from_fn(|a| i32::from(k[a]));
                let mut box_key = R::ZERO;
                for a in 0..D {
                    // `min` says the index is in the table to the compiler (no bounds check).
                    box_key = metric.combine(box_key, near_gaps[a][((k[a] + 1) as usize).min(2)]);
                }
                visit(&k, box_key, &mut best);
            }
        }

        // The smallest margin between a cell's points and its borders, so ring r + 1 is at
        // least r + margin away along some axis.
        let margin = R::from_ratio(lo.min(UNIT - hi), 16);
        for r in 2..=MAX_RING {
            if metric.axis_key(R::from_i32(r - 1) + margin) >= reach(&best) {
                break;
            }
            // Ring r: the cells k of [−r, r]ᴰ with some |kₐ| = r, one flat loop over the box
            // (rarely reached, so kept small rather than fast).
            let side = (2 * r + 1) as usize;
            for index in 0..side.pow(D as u32) {
                let mut rest = index;
                let mut on_ring = false;
                let k: [i32; D] = core::array::from_fn(|_| {
                    let o = (rest % side) as i32 - r;
                    rest /= side;
                    on_ring |= o.abs() == r;
                    o
                });
                if on_ring {
                    let mut box_key = R::ZERO;
                    for (a, &o) in k.iter().enumerate() {
                        box_key = metric.combine(box_key, gap(a, o));
                    }
                    visit(&k, box_key, &mut best);
                }
            }
        }
        best
    }
}

impl Cellular {
    /// Rings 0 and 1 of [`search`](Self::search) whole, for up to 3 dimensions: every one of
    /// the 3ᴰ cells around the point's (`cell`; the point at `frac` in it) hashed (each
    /// axis's three terms shared), its point placed and its key taken, then the cells offered to
    /// `best` nearest box first, in `NEAR_1`'s order.
    ///
    /// The same `best` as the pruned walk, bit for bit: a cell it prunes has a box whose key
    /// is at least the reach, and every point in the box has a key at least the box's (the
    /// same roundings of larger offsets), so offering it changes neither `F1` nor, where the
    /// reach is `F2`, `F2` (with only `F1` sought it may replace the unused second key).
    #[inline]
    fn near_whole<R: Real, const D: usize>(
        &self,
        cell: [i32; D],
        frac: [R; D],
        best: &mut Nearest<R, D>,
    ) {
        // Arrays of exactly 3ᴰ cells, so no lane is computed for nothing (4D takes the pruned
        // walk).
        match D {
            1 => self.near_cells::<R, D, 3>(cell, frac, best),
            2 => self.near_cells::<R, D, 9>(cell, frac, best),
            _ => self.near_cells::<R, D, 27>(cell, frac, best),
        }
    }

    /// The point's split and [`near_whole`](Self::near_whole) through the target's kernel
    /// ([`arch::cellular_near`], `f32` in 2D and 3D on x86-64): the same bits. The cell and
    /// fraction, or `None` (nothing written) where there is no kernel or the point is beyond
    /// its range (±2²², or not finite).
    #[inline(always)]
    fn near_kernel<R: Real, const D: usize>(
        &self,
        p: [R; D],
        best: &mut Nearest<R, D>,
    ) -> Option<([i32; D], [R; D])> {
        if !arch::CELLULAR_NEAR || !R::BINARY32 || !(D == 2 || D == 3) {
            return None;
        }
        let k = CellularCells {
            start: self.hash.start(),
            jitter: self.jitter,
            squares: matches!(self.metric, Metric::Euclidean | Metric::EuclideanSquared),
            chebyshev: self.metric == Metric::Chebyshev,
            second: self.output.needs_f2(),
            lanes: &NEAR_LANES[D.saturating_sub(2).min(1)],
        };
        let mut out = NearPair {
            key: [0.0; 2],
            q: [[0.0; 3]; 2],
            hash: 0,
        };
        let (cell, frac) = arch::cellular_near(p.map(R::to_f32), &k, &mut out)?;
        let n = if self.output.needs_f2() { 2 } else { 1 };
        for i in 0..n {
            best.keys[i] = R::from_f32(out.key[i]);
            best.offsets[i] = core::array::from_fn(|a| R::from_f32(out.q[i][a.min(2)]));
        }
        best.hash = out.hash;
        Some((cell, frac.map(R::from_f32)))
    }

    /// [`near_whole`](Self::near_whole) over its `C = 3ᴰ` cells.
    #[inline(always)]
    fn near_cells<R: Real, const D: usize, const C: usize>(
        &self,
        cell: [i32; D],
        frac: [R; D],
        best: &mut Nearest<R, D>,
    ) {
        let metric = self.metric;
        // Cell i of the 3ᴰ is offset k_a = digit a of i in base 3, minus 1, axis 0 the most
        // significant digit, so the hash's terms fork digit by digit. (`min` keeps the
        // unused instances, of other dimensions, within the arrays.)
        let axis = |a: usize| cell[a.min(D - 1)];
        let first: [u32; 3] = fork(&[self.hash.start()], 0, axis(0));
        let folded: [u32; C] = match D {
            1 => pad(&first),
            2 => pad(&fork::<3, 9>(&first, 1, axis(1))),
            _ => pad(&fork::<9, 27>(
                &fork::<3, 9>(&first, 1, axis(1)),
                2,
                axis(2),
            )),
        };
        let hashes = folded.map(PrimeHash::finish);
        let digits = &DIGITS[(D - 1).min(2)];
        let mut keys = [R::ZERO; C];
        let mut points = [[R::ZERO; C]; D];
        let bits: [u32; C] = hashes.map(|h| CellRng::from_key(h).next_u32());
        for a in 0..D {
            for i in 0..C {
                let k = i32::from(digits[a.min(2)][i.min(26)]);
                let q = R::from_ratio(k * UNIT + self.axis_offset::<D>(bits[i], a), 16) - frac[a];
                points[a][i] = q;
                keys[i] = metric.combine(keys[i], metric.axis_key(q.abs()));
            }
        }
        // `Nearest::offer` over the cells in near order, on indices.
        let (mut key, mut index) = (best.keys, [0usize; 2]);
        for &i in NEAR_INDEX[(D - 1).min(2)].iter().take(C) {
            let i = usize::from(i).min(C - 1);
            keep_nearest(&mut key, &mut index, keys[i], i);
        }
        best.keys = key;
        best.offsets = index.map(|i| core::array::from_fn(|a| points[a][i.min(C - 1)]));
        best.hash = hashes[index[0].min(C - 1)];
    }
}

/// The folded hash terms ([`PrimeHash`]) of `parents` each continued by axis `a`'s
/// coordinates `c − 1`, `c`, `c + 1`: entry `i` of the result continues parent `i / 3` by
/// `c + i % 3 − 1` (`M = 3N`; constant sizes, so the loop unrolls).
#[inline(always)]
fn fork<const N: usize, const M: usize>(parents: &[u32; N], a: usize, c: i32) -> [u32; M] {
    let terms = [-1, 0, 1].map(|k| PrimeHash::axis(a, c.wrapping_add(k)));
    core::array::from_fn(|i| parents[(i / 3).min(N - 1)] ^ terms[i % 3])
}

/// `hashes` in the first slots of `M` (`M = N` where it is used).
#[inline(always)]
fn pad<const N: usize, const M: usize>(hashes: &[u32; N]) -> [u32; M] {
    core::array::from_fn(|i| hashes[i.min(N - 1)])
}

impl<R: Real, const D: usize> Nearest<R, D> {
    /// `∇F1` (`i = 0`) or `∇F2` (`i = 1`) in `metric`, given that distance `f`: the offset
    /// points from the sample to the feature point, so the distance grows against it. Where
    /// the derivative does not exist (at the point itself, on a Manhattan or Chebyshev kink)
    /// it is 0 along the axes concerned (Chebyshev: the first axis of largest offset moves it).
    fn gradient(&self, metric: Metric, i: usize, f: R) -> [R; D] {
        let q = self.offsets[i];
        let sign = |x: R| {
            if x > R::ZERO {
                R::NEG_ONE
            } else if x < R::ZERO {
                R::ONE
            } else {
                R::ZERO
            }
        };
        match metric {
            Metric::Euclidean => {
                if f > R::ZERO {
                    q.map(|x| (-x).div(f))
                } else {
                    [R::ZERO; D]
                }
            }
            Metric::EuclideanSquared => q.map(|x| -(x + x)),
            Metric::Manhattan => q.map(sign),
            Metric::Chebyshev => {
                let mut top = 0;
                for a in 1..D {
                    if q[a].abs() > q[top].abs() {
                        top = a;
                    }
                }
                core::array::from_fn(|a| if a == top { sign(q[a]) } else { R::ZERO })
            }
        }
    }
}

impl Cellular {
    /// The value at `p` (out of line on x86-64, see [`search`](Self::search)).
    #[cfg_attr(target_arch = "x86_64", inline(never))]
    #[cfg_attr(not(target_arch = "x86_64"), inline)]
    fn value<R: Real, const D: usize>(&self, p: [R; D]) -> R {
        self.evaluate::<R, D, false>(p).0
    }

    /// The value and gradient at `p` (out of line on x86-64, see [`search`](Self::search)).
    #[cfg_attr(target_arch = "x86_64", inline(never))]
    #[cfg_attr(not(target_arch = "x86_64"), inline)]
    fn value_and_gradient<R: Real, const D: usize>(&self, p: [R; D]) -> (R, [R; D]) {
        self.evaluate::<R, D, true>(p)
    }

    /// The value and, where `GRADIENT`, the gradient at `p`.
    #[inline]
    fn evaluate<R: Real, const D: usize, const GRADIENT: bool>(&self, p: [R; D]) -> (R, [R; D]) {
        let nearest = self.search::<R, D>(p);
        // The distance to the nearest (`i = 0`) or second-nearest point and, where
        // `GRADIENT`, its gradient (which needs the distance: computed once).
        let fg = |i: usize| {
            let f = nearest.distance(self.metric, i);
            let g = if GRADIENT {
                nearest.gradient(self.metric, i, f)
            } else {
                [R::ZERO; D]
            };
            (f, g)
        };
        let (value, gradient) = match self.output {
            Output::F1 => fg(0),
            Output::F2 => fg(1),
            Output::F2MinusF1 => {
                let ((f1, g1), (f0, g0)) = (fg(1), fg(0));
                (f1 - f0, core::array::from_fn(|a| g1[a] - g0[a]))
            }
            Output::CellValue => (Self::value_of_key(nearest.hash), [R::ZERO; D]),
        };
        (value.canonical(), gradient.map(R::canonical))
    }
}

macro_rules! cellular_impls {
    ($($d:literal),*) => {$(
        impl<R: Real> crate::Noise<R, $d> for Cellular {
            #[inline]
            fn sample(&self, p: [R; $d]) -> R {
                self.value::<R, $d>(p)
            }
            fn amplitude_bound(&self) -> f32 {
                match self.output {
                    Output::CellValue => 1.0,
                    _ => self.distance_bound($d),
                }
            }
        }

        impl<R: Real> crate::NoiseGradient<R, $d> for Cellular {
            #[inline]
            fn sample_with_gradient(&self, p: [R; $d]) -> (R, [R; $d]) {
                self.value_and_gradient::<R, $d>(p)
            }
        }
    )*};
}

cellular_impls!(1, 2, 3, 4);
crate::noise::inherent_amplitude_bound!(Cellular, []);

#[cfg(test)]
mod tests {
    use super::*;
    use crate::I16F16;
    use crate::testing::chi2;

    /// `NEAR_INDEX[d − 1]` is `near_order(d)` as indices whose base-3 digits, axis 0 the most
    /// significant, are the offsets plus 1 (the near table's order is what resolves ties
    /// between equal distances, so both searches must offer in it).
    #[test]
    fn near_index_follows_the_near_order() {
        fn check(dims: usize, near: &[[i8; 4]]) {
            assert_eq!(near.len(), 3usize.pow(dims as u32));
            for (n, k) in near.iter().enumerate() {
                let mut rest = usize::from(NEAR_INDEX[dims - 1][n]);
                for a in (0..dims).rev() {
                    assert_eq!((rest % 3) as i8 - 1, k[a], "{dims}D, cell {n}, axis {a}");
                    rest /= 3;
                }
                assert_eq!(rest, 0);
            }
        }
        check(1, &NEAR_1);
        check(2, &NEAR_2);
        check(3, &NEAR_3);
    }

    /// Rings 0 and 1 searched whole give what the pruned walk gives, bit for bit (keys,
    /// offsets and the nearest cell's hash; with only `F1` sought, the second key may differ
    /// and is not compared), for every metric, output and several jitters, in f32, f64 and
    /// I16F16, at random points and at points on cell borders; and in floats the Euclidean
    /// keys' roots are the offsets' norms (`Nearest::distance`).
    #[test]
    fn whole_search_is_the_pruned_search() {
        fn check<R: Real + core::fmt::Debug, const D: usize>(noise: &Cellular, p: [f32; D]) {
            let p = p.map(R::from_f32);
            let (a, b) = (noise.search_in(p, true), noise.search_in(p, false));
            let n = if noise.output.needs_f2() { 2 } else { 1 };
            assert_eq!(a.keys[..n], b.keys[..n], "{noise:?} at {p:?}");
            assert_eq!(a.offsets[..n], b.offsets[..n], "{noise:?} at {p:?}");
            assert_eq!(a.hash, b.hash, "{noise:?} at {p:?}");
            // `distance`'s shortcut: in floats the key's root is the offset's norm.
            if noise.metric == Metric::Euclidean && R::FLOAT {
                for i in 0..n {
                    assert_eq!(
                        a.keys[i].sqrt(),
                        R::norm(a.offsets[i]),
                        "{noise:?} at {p:?}"
                    );
                }
            }
        }
        let mut state = 0x1234_5678_9ABC_DEF0u64;
        let mut next = move || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((state >> 40) as f32 / (1u32 << 24) as f32 - 0.5) * 64.0
        };
        for metric in Metric::ALL {
            for output in Output::ALL {
                for jitter in [0.0, 0.3, 0.8, 1.0] {
                    let noise = Cellular::new(11)
                        .with_metric(metric)
                        .with_output(output)
                        .with_jitter(jitter)
                        .unwrap();
                    for i in 0..400 {
                        // Every tenth point on a cell border along its first axis.
                        let x = if i % 10 == 0 { next().floor() } else { next() };
                        let (y, z) = (next(), next());
                        check::<f32, 1>(&noise, [x]);
                        check::<f32, 2>(&noise, [x, y]);
                        check::<f32, 3>(&noise, [x, y, z]);
                        check::<f64, 2>(&noise, [x, y]);
                        check::<f64, 3>(&noise, [x, y, z]);
                        check::<I16F16, 2>(&noise, [x, y]);
                        check::<I16F16, 3>(&noise, [x, y, z]);
                    }
                }
            }
        }
    }

    /// The feature points are uniform in their cells and independent of their neighbours',
    /// as are the cell values, whose generator the multiplicative cell hash keys: χ² of each
    /// cell's point binned 4 × 4 (over its first two axes; 15 degrees of freedom) and of the
    /// pairs with the neighbour along each axis and the diagonal (255), and of the cell
    /// values' top 4 bits and their pairs, below their 10⁻⁶ quantiles (52 and 375), in 2D and
    /// 3D for several seeds.
    #[test]
    fn points_and_values_are_uniform_and_independent() {
        extern crate std;
        fn check<const D: usize>(noise: &Cellular) {
            // The point's bin (4 × 4 over axes 0 and 1) and the value's top 4 bits.
            let bins = |c: [i32; D]| {
                let p = noise.feature_point(c);
                let bin = |a: usize| ((p[a] - f64::from(c[a])) * 4.0) as usize;
                let v: f64 = noise.cell_value(c);
                (bin(0) * 4 + bin(1), ((v + 1.0) * 8.0) as usize)
            };
            let (n, depth) = if D == 3 { (40, 40) } else { (250, 1) };
            let steps: [[i32; 3]; 4] = [[1, 0, 0], [0, 1, 0], [1, 1, 0], [0, 0, 1]];
            let mut single = [[0u32; 16]; 2];
            let mut worst: [f64; 2] = [0.0; 2];
            for (k, step) in steps.iter().enumerate().take(if D == 3 { 4 } else { 3 }) {
                let mut pairs = [[0u32; 256]; 2];
                for x in 0..n {
                    for y in 0..n {
                        for z in 0..depth {
                            let at = [x * 7 - 300, y * 5 + 11, z * 3 - 50];
                            let c: [i32; D] = core::array::from_fn(|a| at[a]);
                            let next: [i32; D] = core::array::from_fn(|a| at[a] + step[a]);
                            let (b, nb) = (bins(c), bins(next));
                            if k == 0 {
                                single[0][b.0] += 1;
                                single[1][b.1] += 1;
                            }
                            pairs[0][b.0 * 16 + nb.0] += 1;
                            pairs[1][b.1 * 16 + nb.1] += 1;
                        }
                    }
                }
                for i in 0..2 {
                    worst[i] = worst[i].max(chi2(&pairs[i]));
                }
            }
            for i in 0..2 {
                let what = ["points", "values"][i];
                let one = chi2(&single[i]);
                std::println!("{D}D {what}: χ² {one:.1}, pairs {:.1}", worst[i]);
                assert!(
                    one < 52.0 && worst[i] < 375.0,
                    "{D}D {what}: {one} {}",
                    worst[i]
                );
            }
        }
        for seed in [0, 1, 2, 1234, u32::MAX] {
            check::<2>(&Cellular::new(seed));
            check::<3>(&Cellular::new(seed));
        }
    }

    /// `extent` is the lowest and highest `offset`, which grows with `u`, for every jitter.
    #[test]
    fn extent_bounds_the_offsets() {
        for jitter in (0..=UNIT)
            .step_by(97)
            .chain([1, 2, 3, 32_767, 32_768, UNIT - 1, UNIT])
        {
            let noise = Cellular {
                jitter,
                ..Cellular::new(0)
            };
            for u in 1..UNIT {
                assert!(
                    noise.offset(u - 1) <= noise.offset(u),
                    "jitter {jitter}, u {u}"
                );
                // The shortcut for jitter 1 is the formula's value.
                let formula = UNIT / 2 + (((u - UNIT / 2) * jitter) >> 16);
                assert_eq!(noise.offset(u), formula, "jitter {jitter}, u {u}");
            }
            let (first, last) = (noise.offset(0), noise.offset(UNIT - 1));
            assert_eq!(noise.extent(), (first, last), "jitter {jitter}");
            assert!(first >= 0 && last < UNIT);
        }
    }
}

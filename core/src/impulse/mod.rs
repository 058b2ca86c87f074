//! Noises made of random impulses convolved with a kernel: Lewis's sparse convolution noise
//! (Lewis 1989, §4), Lagae et al.'s Gabor noise (2009; [`Gabor`]), and the walk over cells and
//! impulses they share.
//!
//! # The impulse walk
//!
//! Lewis approximates a Poisson process of impulses by "choosing N Poisson-distributed
//! impulses in each voxel", the voxel's number seeding the generator of its impulses, with the
//! lattice spacing equal to the kernel's radius, "so only the voxel containing x and its
//! neighbours (3³ = 27 voxels) can contribute" (§4). bandnoise does exactly this, in any
//! dimension from 1 to 4, with the crate's per-cell generator ([`CellRng`], keyed by the
//! [`CellHash`] of the noise's seed and the cell):
//!
//! 1. Split the point (in units of the kernel's radius) into its cell and its fraction `f`.
//! 2. Of the `3^D` cells around it, skip those whose nearest point is at distance 1 or more
//!    (on average 20.6 of the 27 cells in 3D are visited, 8.1 of 9 in 2D).
//! 3. Draw the cell's count: Poisson with a per-cell mean ([`Impulses::poisson`], capped as
//!    [`Poisson`] documents, so amplitudes have a proved bound), or a fixed count per cell
//!    ([`Impulses::fixed`]: the "stratified Poisson" process that Tavernier et al. 2019 found
//!    as good and faster).
//! 4. Each impulse takes one 32-bit draw for its position (15 bits per axis in 1D and 2D, 10 in
//!    3D, 7 in 4D: the centres of `2^bits` equal bins, `(2k + 1)/2^(bits+1)`, so every number
//!    type holds them exactly) and, for [`Weights::Sign`], its sign from the draw's top bit;
//!    [`Weights::Uniform`] takes a second draw (`(2k + 1)/2¹⁶`, symmetric in `(−1, 1)`).
//! 5. Impulses at distance 1 or more add nothing; the others add their weight times the kernel
//!    at the squared distance. A kernel that needs more random numbers per impulse (Gabor
//!    noise's orientation and phase) declares how many, and gets them from the same cell
//!    generator at a place that does not depend on which impulses were skipped. What a
//!    kernel computes once per cell rather than per impulse (Gabor noise's harmonic along a
//!    shared direction) is a `PerCell`: a share per axis from the point's fraction, joined
//!    over the axes.
//!
//! Every step is integer arithmetic or the number type's `+ − ×` on fractions in `(−2, 2)`,
//! so a value is the same on every target, and fixed point cannot overflow whatever the
//! coordinate.

mod gabor;
mod kernel;
mod sparse;

pub(crate) use gabor::Parameters as GaborParameters;
pub use gabor::{Envelope, Gabor, Orientation, RADIUS_TIMES_BANDWIDTH};
pub use kernel::Kernel;
pub use sparse::SparseConvolution;

use crate::batch::LANES;
use crate::hash::chain::ChainHash;
use crate::hash::{CellHash, CellRng, Poisson};
use crate::real::sealed::SOFT_FLOAT;
use crate::{Error, Real};

/// The largest fixed count per cell ([`Impulses::fixed`]).
pub const MAX_FIXED: u32 = 32;
/// The default density of sparse convolution noise, in impulses per kernel volume (Lewis: at
/// ten and above, "usually not distinguishable" from convolved white noise).
pub const DEFAULT_DENSITY: f32 = 10.0;
/// The smallest density: below it the noise is isolated bumps.
pub const MIN_DENSITY: f32 = 0.01;

/// How an impulse's weight is drawn.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Weights {
    /// Uniform in `(−1, 1)` (one reading of Lewis's "uncorrelated intensities"; `E[w²] =
    /// 1/3`). One draw more per impulse than [`Sign`](Self::Sign).
    Uniform,
    /// `±1` with equal odds (Tavernier et al. 2019's Bernoulli weights; `E[w²] = 1`), the
    /// default: the sum is closer to Gaussian at a given density (its excess kurtosis is
    /// `E[w⁴]/E[w²]²` = 1 against 1.8 for uniform weights, times the same kernel factor),
    /// and the sign comes with the position's draw. Measured in `tests/tests/sparse.rs`.
    #[default]
    Sign,
}

impl Weights {
    /// `E[w²]` of the weights as drawn (the uniform weights' `2¹⁶` levels make it
    /// `(1 − 2⁻³²)/3`).
    #[must_use]
    pub fn power(self) -> f64 {
        match self {
            Weights::Uniform => (1.0 - 1.0 / 4_294_967_296.0) / 3.0,
            Weights::Sign => 1.0,
        }
    }
}

/// How many impulses a cell holds.
#[derive(Clone, Debug, PartialEq)]
#[allow(
    clippy::large_enum_variant,
    reason = "no allocation: the Poisson table lives in the noise, 392 bytes"
)]
enum Count {
    /// Poisson with this distribution.
    Poisson(Poisson),
    /// Exactly this many.
    Fixed(u32),
}

/// A cell's impulses: how many, and how they are weighted.
///
/// # Examples
///
/// ```
/// use bandnoise::{Error, impulse::{Impulses, Weights}};
///
/// let lewis = Impulses::poisson(2.5)?.with_weights(Weights::Uniform); // a mean of 2.5 per cell
/// assert_eq!(lewis.per_cell(), 2.5);
/// let fast = Impulses::fixed(3)?; // ±1 weights
/// assert_eq!((fast.cap(), fast.weights()), (3, Weights::Sign));
/// assert!(Impulses::fixed(0).is_err());
/// # Ok::<(), Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Impulses {
    count: Count,
    weights: Weights,
}

impl Impulses {
    /// Poisson counts with mean `per_cell`, ±1 weights.
    ///
    /// # Errors
    ///
    /// [`Error::PoissonMean`] unless `0 < per_cell ≤ 32`.
    pub fn poisson(per_cell: f32) -> Result<Self, Error> {
        Ok(Self {
            count: Count::Poisson(Poisson::new(per_cell)?),
            weights: Weights::default(),
        })
    }

    /// Poisson counts for a mean the caller has checked.
    pub(crate) fn poisson_checked(per_cell: f32, weights: Weights) -> Self {
        Self {
            count: Count::Poisson(Poisson::tabulate(per_cell)),
            weights,
        }
    }

    /// Exactly `per_cell` impulses in every cell, ±1 weights.
    ///
    /// # Errors
    ///
    /// [`Error::ImpulseCount`] unless `1 ≤ per_cell ≤` [`MAX_FIXED`].
    pub fn fixed(per_cell: u32) -> Result<Self, Error> {
        if !(1..=MAX_FIXED).contains(&per_cell) {
            return Err(Error::ImpulseCount {
                count: per_cell,
                max: MAX_FIXED,
            });
        }
        Ok(Self {
            count: Count::Fixed(per_cell),
            weights: Weights::default(),
        })
    }

    /// The same counts with weights drawn as `weights` says.
    #[must_use]
    pub fn with_weights(self, weights: Weights) -> Self {
        Self { weights, ..self }
    }

    /// The weights.
    #[must_use]
    pub fn weights(&self) -> Weights {
        self.weights
    }

    /// The mean number of impulses per cell.
    #[must_use]
    pub fn per_cell(&self) -> f32 {
        match &self.count {
            Count::Poisson(p) => p.mean(),
            Count::Fixed(n) => *n as f32,
        }
    }

    /// Whether the counts are fixed rather than Poisson.
    #[must_use]
    pub fn is_fixed(&self) -> bool {
        matches!(self.count, Count::Fixed(_))
    }

    /// The most impulses a cell ever holds.
    #[must_use]
    pub fn cap(&self) -> u32 {
        match &self.count {
            Count::Poisson(p) => p.cap(),
            Count::Fixed(n) => *n,
        }
    }

    /// The variance of `Σ w_k h(x − ξ_k)` by Campbell's theorem, `λ E[w²] ∫h²`, for a
    /// kernel whose `∫h²` over a unit-radius support is `power` (cells of volume 1, so `λ` is
    /// the mean count per cell). It holds for fixed counts too: with independent zero-mean
    /// weights only each impulse's own square survives, and uniform positions spread it over
    /// the cell.
    #[must_use]
    pub fn variance(&self, power: f64) -> f64 {
        self.per_cell() as f64 * self.weights.power() * power
    }

    /// The cell's count (one draw for Poisson counts, none for fixed ones).
    #[inline]
    fn count(&self, rng: &mut CellRng) -> u32 {
        match &self.count {
            Count::Poisson(p) => rng.poisson(p),
            Count::Fixed(n) => *n,
        }
    }
}

/// Whether the point walk tests its impulses in groups of [`GROUP`] (in `f32`, on targets
/// with vectors of four `f32`s, where the group's draws, positions and distances take a few
/// vector operations; elsewhere one by one).
const GROUPED: bool = cfg!(any(target_arch = "x86_64", target_arch = "aarch64"));

/// The impulses of a group.
const GROUP: usize = 4;

/// The walks' `(extra, prepare)` for kernels without random parameters of their own.
pub(crate) const NO_PARAMS: (u32, fn(&mut CellRng)) = (0, |_| ());

/// What a kernel computes once per cell rather than once per impulse, from the point's
/// coordinates relative to the cell's corner (Gabor noise's harmonic along a shared direction):
/// a share per axis, joined over the axes in order, `join(join(s₀, s₁), s₂)`. Both walks
/// compute the same joins of the same numbers, so a cell's value is the same bits in a point
/// walk (which keeps the joins of the axes its odometer has not moved) and in a lane's share
/// of the lanes' walk. `()` computes nothing.
pub(crate) trait PerCell<R, const D: usize> {
    /// One axis's share of a cell's value, and the join of the first axes' shares.
    type Share: Copy + Default;
    /// Axis `a`'s shares for the cells below, at and above the point's own along `a`, from
    /// the point's fraction `f` in its own cell (the point's coordinate relative to those
    /// cells' corners is `f + 1`, `f` and `f − 1`).
    fn axis(&self, a: usize, f: R) -> [Self::Share; 3];
    /// The join of the axes before one with that axis's share.
    fn join(&self, before: Self::Share, share: Self::Share) -> Self::Share;
}

impl<R, const D: usize> PerCell<R, D> for () {
    type Share = ();
    #[inline]
    fn axis(&self, _: usize, _: R) -> [(); 3] {
        [(); 3]
    }
    #[inline]
    fn join(&self, _: (), _: ()) {}
}

/// Bits of an impulse's position draw per axis in `D` dimensions (at most 31 in all: the top
/// bit is the sign of [`Weights::Sign`]).
const fn position_bits(d: usize) -> u32 {
    if d <= 2 { 15 } else { 31 / d as u32 }
}

/// An impulse's coordinate along axis `a` within its cell, from its position draw: the
/// centre of one of `2^bits` equal bins, `(2k + 1)/2^(bits+1)`.
#[inline]
fn position<R: Real, const D: usize>(draw: u32, a: usize) -> R {
    let bits = const { position_bits(D) };
    let k = (draw >> (a as u32 * bits)) & ((1u32 << bits) - 1);
    R::from_ratio((2 * k + 1) as i32, bits + 1)
}

impl Weights {
    /// An impulse's weight: the sign from its position `draw`'s top bit, or uniform from the
    /// next draw of `rng`.
    #[inline]
    fn draw<R: Real>(self, draw: u32, rng: &mut CellRng) -> R {
        match self {
            Weights::Sign => {
                if draw >> 31 == 1 {
                    R::NEG_ONE
                } else {
                    R::ONE
                }
            }
            Weights::Uniform => {
                let k = (rng.next_u32() >> 16) as i32 - (1 << 15);
                R::from_ratio(2 * k + 1, 16)
            }
        }
    }
}

/// Calls `visit(delta, d², w, params, cell)` for each impulse within distance 1 of `p` (in
/// cell units), in a fixed order: the walk of the module docs. `visit` gets the offset from the
/// impulse to `p`, its squared length (below 1), the weight, what `prepare` made of the
/// impulse's `extra` draws (a kernel's own random parameters: Gabor noise's phase and
/// orientation), which `prepare` takes from the generator it is given, and the value
/// `per_cell` computed for the impulse's cell.
///
/// The `3^D` cells are visited by [`CellHash::near`]: an odometer over the axes, the first
/// axis slowest, so the cell hash's chain (first axis folded first) shares its prefixes, and a
/// prefix of axes whose distances alone reach 1 skips all the cells beyond it at once.
#[inline]
pub(crate) fn walk<R: Real, const D: usize, P, K>(
    hash: &CellHash,
    impulses: &Impulses,
    p: [R; D],
    (extra, mut prepare): (u32, impl FnMut(&mut CellRng) -> P),
    per_cell: &K,
    mut visit: impl FnMut([R; D], R, R, &P, &K::Share),
) where
    K: PerCell<R, D>,
{
    // Per axis and offset −1, 0, 1: the cell, the point's coordinate relative to the cell's
    // corner, the squared distance from the point to the cell, and the kernel's share.
    let mut cells = [[0u32; 3]; D];
    let mut base = [[R::ZERO; 3]; D];
    let mut gaps = [[R::ZERO; 3]; D];
    let mut shares = [[K::Share::default(); 3]; D];
    for a in 0..D {
        let (c, f) = p[a].split();
        let g = R::ONE - f;
        cells[a] = [c.wrapping_sub(1) as u32, c as u32, c.wrapping_add(1) as u32];
        base[a] = [f + R::ONE, f, f - R::ONE];
        gaps[a] = [f.mul_rn(f), R::ZERO, g.mul_rn(g)];
        shares[a] = per_cell.axis(a, f);
    }
    let weight_draws = u32::from(impulses.weights == Weights::Uniform);
    // The joins of the shares of axes 0..=a at the last cell's digits.
    let mut joined = [K::Share::default(); D];
    let mut last = [usize::MAX; D];
    // On the cores without an FPU (where floats are emulated: Cortex-M0, RV32IMC), whose
    // multiplications are costly (the Cortex-M0 has no 64-bit product for fixed point either),
    // the last axis's join waits for the cell's first impulse in reach: most cells of a 3D
    // walk have none. Elsewhere the test costs more than the join it saves (most cells of a
    // 2D walk have one). The same joins either way: the same bits.
    let lazy = D > 1 && SOFT_FLOAT;
    let join = |joined: &[K::Share; D], a: usize, share| match a.checked_sub(1) {
        // `b % D` is `b` (below `a`); it says so to the compiler (no bounds check).
        Some(b) => per_cell.join(joined[b % D], share),
        None => share,
    };
    hash.near(&cells, &gaps, R::ONE, |digit, key, _| {
        let mut rng = CellRng::from_key(key);
        let here: [R; D] = core::array::from_fn(|a| base[a][digit[a].min(2)]);
        let mut moved = false;
        for a in 0..D - usize::from(lazy) {
            let d = digit[a].min(2);
            moved |= d != last[a];
            if moved {
                joined[a] = join(&joined, a, shares[a][d]);
                last[a] = d;
            }
        }
        let mut cell = (!lazy).then(|| joined[D - 1]);
        if GROUPED && R::BINARY32 {
            // Each impulse takes `stride` draws, so the position draws of a group of impulses
            // are at known places in the cell's sequence: a group's draws, positions and
            // squared distances are computed together (in vectors where the target has them,
            // the lanes innermost), then its impulses in reach visited in order, each from its
            // own place.
            let stride = 1 + weight_draws + extra;
            let count = impulses.count(&mut rng);
            for first in (0..count).step_by(GROUP) {
                // Impulse j's generator, just after its position draw.
                let mut rngs: [CellRng; GROUP] =
                    core::array::from_fn(|j| rng.ahead((first + j as u32).wrapping_mul(stride)));
                let draws = rngs.each_mut().map(CellRng::next_u32);
                let offset = |draw: u32, a: usize| here[a] - position::<R, D>(draw, a);
                let mut d2s = [R::ZERO; GROUP];
                for a in 0..D {
                    for j in 0..GROUP {
                        let d = offset(draws[j], a);
                        d2s[j] = d2s[j] + d.mul_rn(d);
                    }
                }
                for j in 0..GROUP.min((count - first) as usize) {
                    if d2s[j] >= R::ONE {
                        continue;
                    }
                    let (draw, mut rng) = (draws[j], rngs[j].clone());
                    let delta: [R; D] = core::array::from_fn(|a| offset(draw, a));
                    let w = impulses.weights.draw(draw, &mut rng);
                    let cell = cell.get_or_insert_with(|| {
                        let a = D - 1;
                        join(&joined, a, shares[a][digit[a].min(2)])
                    });
                    visit(delta, d2s[j], w, &prepare(&mut rng), cell);
                }
            }
            return;
        }
        for _ in 0..impulses.count(&mut rng) {
            let draw = rng.next_u32();
            // The offset along axis a from the impulse to the point.
            let offset = |a: usize| here[a] - position::<R, D>(draw, a);
            let mut d2 = R::ZERO;
            for a in 0..D {
                let d = offset(a);
                d2 = d2 + d.mul_rn(d);
            }
            if d2 >= R::ONE {
                rng.skip(weight_draws + extra);
                continue;
            }
            let delta: [R; D] = core::array::from_fn(offset);
            let w = impulses.weights.draw(draw, &mut rng);
            let mut own = rng.clone();
            rng.skip(extra);
            let cell = cell.get_or_insert_with(|| {
                let a = D - 1;
                join(&joined, a, shares[a][digit[a].min(2)])
            });
            visit(delta, d2, w, &prepare(&mut own), cell);
        }
    });
}

/// [`walk`] for [`LANES`] points at once, each visit bit-identical to the point walk's for
/// that lane and in the same order: `visit(lane, delta, d², w, params, cell)`, an impulse's
/// `params` prepared once for all the lanes it reaches. The cells within reach of
/// any lane are visited once for all of them (their impulses generated once), in the point
/// walk's order (first axis slowest), which restricted to each lane's `3^D` cells is that
/// lane's own order; each lane keeps the cells and impulses the point walk keeps (the same
/// offsets, squared distances and pruning, computed with the same operations).
///
/// Returns `false`, visiting nothing, when the lanes' cells span more than two cells along an
/// axis (scattered points): the caller then walks each lane alone.
#[inline]
pub(crate) fn walk_lanes<R: Real, const D: usize, P, K>(
    hash: &CellHash,
    impulses: &Impulses,
    p: &[[R; LANES]; D],
    (extra, mut prepare): (u32, impl FnMut(&mut CellRng) -> P),
    per_cell: &K,
    mut visit: impl FnMut(usize, [R; D], R, R, &P, &K::Share),
) -> bool
where
    K: PerCell<R, D>,
{
    // The box of cells: one below the lowest lane's to one above the highest's, at most 4
    // along an axis. Per axis and box cell, for every lane: the lane's coordinate relative to
    // the cell's corner and its squared distance to the cell, as the point walk has them (2,
    // out of reach, where the cell is not one of the lane's neighbours).
    let mut lo = [0i32; D];
    let mut side = [0usize; D];
    let mut here = [[[R::ZERO; LANES]; 4]; D];
    let mut gaps = [[[R::from_i32(2); LANES]; 4]; D];
    let mut shares = [[[K::Share::default(); LANES]; 4]; D];
    for a in 0..D {
        let split = p[a].map(Real::split);
        let (min, max) = split
            .iter()
            .fold((i32::MAX, i32::MIN), |(lo, hi), &(c, _)| {
                (lo.min(c), hi.max(c))
            });
        if i64::from(max) - i64::from(min) > 1 {
            return false;
        }
        lo[a] = min;
        side[a] = (max.wrapping_sub(min) as usize & 1) + 3;
        for (l, &(c, f)) in split.iter().enumerate() {
            let g = R::ONE - f;
            // The lane's own cell is box cell 1 or 2; its neighbours the ones either side.
            let at = (c.wrapping_sub(min) as usize & 1) + 1;
            let share = per_cell.axis(a, f);
            for (o, ((b, d), x)) in [
                (f + R::ONE, f.mul_rn(f)),
                (f, R::ZERO),
                (f - R::ONE, g.mul_rn(g)),
            ]
            .into_iter()
            .zip(share)
            .enumerate()
            {
                if let (Some(h), Some(q), Some(s)) = (
                    here[a].get_mut(at + o - 1),
                    gaps[a].get_mut(at + o - 1),
                    shares[a].get_mut(at + o - 1),
                ) {
                    h[l] = b;
                    q[l] = d;
                    s[l] = x;
                }
            }
        }
    }
    let weight_draws = u32::from(impulses.weights == Weights::Uniform);
    let mut digit = [0usize; D];
    let mut chain = [0u32; D];
    let mut from = 0;
    loop {
        for a in from..D {
            let h = if a == 0 { hash.start() } else { chain[a - 1] };
            let cell = lo[a].wrapping_add(digit[a] as i32 - 1);
            chain[a] = hash.step(h, cell as u32);
        }
        // Digits are below 4; `min` says so to the compiler (no bounds check).
        let rows: [usize; D] = core::array::from_fn(|a| digit[a].min(3));
        // The lanes this cell is within reach of. (The point walk prunes a prefix of axes at
        // 1; squared distances are not negative, so that is the whole sum at 1.)
        let mut gap = [R::ZERO; LANES];
        for (a, &row) in rows.iter().enumerate() {
            for (g, &d) in gap.iter_mut().zip(&gaps[a][row]) {
                *g = *g + d;
            }
        }
        let reach = gap
            .iter()
            .enumerate()
            .fold(0u32, |m, (l, &g)| m | (u32::from(g < R::ONE) << l));
        if reach != 0 {
            // Every lane's value of the cell (lanes out of reach are computed and ignored).
            let cell: [K::Share; LANES] = core::array::from_fn(|l| {
                let mut joined = shares[0][rows[0]][l];
                for (a, &row) in rows.iter().enumerate().skip(1) {
                    joined = per_cell.join(joined, shares[a][row][l]);
                }
                joined
            });
            let mut rng = CellRng::from_key(chain[D - 1]);
            for _ in 0..impulses.count(&mut rng) {
                let draw = rng.next_u32();
                let u: [R; D] = core::array::from_fn(|a| position::<R, D>(draw, a));
                // Every lane's squared distance (lanes out of reach are computed and ignored).
                let mut d2 = [R::ZERO; LANES];
                for a in 0..D {
                    for (s, &h) in d2.iter_mut().zip(&here[a][rows[a]]) {
                        let d = h - u[a];
                        *s = *s + d.mul_rn(d);
                    }
                }
                let mut near = d2
                    .iter()
                    .enumerate()
                    .fold(0u32, |m, (l, &s)| m | (u32::from(s < R::ONE) << l))
                    & reach;
                // The weight and the kernel's generator, as the point walk draws them.
                let mut own = rng.clone();
                rng.skip(weight_draws + extra);
                if near == 0 {
                    continue;
                }
                let w = impulses.weights.draw(draw, &mut own);
                let params = prepare(&mut own);
                while near != 0 {
                    let l = near.trailing_zeros() as usize;
                    near &= near - 1;
                    let delta = core::array::from_fn(|a| here[a][rows[a]][l % LANES] - u[a]);
                    visit(l, delta, d2[l % LANES], w, &params, &cell[l % LANES]);
                }
            }
        }
        // The next cell of the box: the last axis fastest.
        let mut a = D;
        loop {
            if a == 0 {
                return true;
            }
            a -= 1;
            digit[a] += 1;
            if digit[a] < side[a] {
                break;
            }
            digit[a] = 0;
        }
        from = a;
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;

    /// In `f32` (where the walk tests a cell's impulses in groups on the targets with
    /// vectors) the walk visits the impulses a one-by-one walk written out here visits, with
    /// the same numbers (offset, squared distance, weight, the draws after them): Poisson and
    /// fixed counts, ±1 and uniform weights, kernels with and without draws of their own, 1D
    /// to 3D, random points near and far.
    #[test]
    fn walk_visits_the_impulses_one_by_one() {
        type Visit = (std::vec::Vec<u32>, u32, u32, [u32; 2]);
        fn visits<const D: usize>(
            impulses: &Impulses,
            extra: u32,
            p: [f32; D],
        ) -> [std::vec::Vec<Visit>; 2] {
            let hash = CellHash::new(0x5EED);
            let prepare = |rng: &mut CellRng| [rng.next_u32(), rng.next_u32()];
            let mut seen = std::vec::Vec::new();
            let visit = |delta: [f32; D], d2: f32, w: f32, drawn: &[u32; 2], _: &()| {
                let delta = delta.iter().map(|d| d.to_bits()).collect();
                seen.push((delta, d2.to_bits(), w.to_bits(), *drawn));
            };
            walk(&hash, impulses, p, (extra, prepare), &(), visit);
            // One by one, over the 3^D cells in the walk's order (the first axis slowest).
            let weight_draws = u32::from(impulses.weights == Weights::Uniform);
            let split = p.map(Real::split);
            let mut want = std::vec::Vec::new();
            for n in 0..3usize.pow(D as u32) {
                let o: [usize; D] =
                    core::array::from_fn(|a| n / 3usize.pow((D - 1 - a) as u32) % 3);
                let mut gap = 0.0f32;
                let mut here = [0.0f32; D];
                let mut cell = [0i32; D];
                for a in 0..D {
                    let (c, f) = split[a];
                    let g = 1.0 - f;
                    gap += [f * f, 0.0, g * g][o[a]];
                    here[a] = [f + 1.0, f, f - 1.0][o[a]];
                    cell[a] = c.wrapping_add(o[a] as i32 - 1);
                }
                if gap >= 1.0 {
                    continue;
                }
                let mut rng = CellRng::new(&hash, cell);
                for _ in 0..impulses.count(&mut rng) {
                    let draw = rng.next_u32();
                    let delta: [f32; D] =
                        core::array::from_fn(|a| here[a] - position::<f32, D>(draw, a));
                    let d2 = delta.iter().fold(0.0f32, |s, d| s + d * d);
                    if d2 >= 1.0 {
                        rng.skip(weight_draws + extra);
                        continue;
                    }
                    let w = impulses.weights.draw::<f32>(draw, &mut rng);
                    let mut own = rng.clone();
                    rng.skip(extra);
                    let delta = delta.iter().map(|d| d.to_bits()).collect();
                    want.push((delta, d2.to_bits(), w.to_bits(), prepare(&mut own)));
                }
            }
            [seen, want]
        }
        let mut next = crate::testing::xorshift32(0x1357_9BDF);
        let mut unit = move || f64::from(next()) / f64::from(u32::MAX);
        let sets = [
            Impulses::poisson_checked(2.4, Weights::Sign),
            Impulses::poisson_checked(5.1, Weights::Uniform),
            Impulses::fixed(3).unwrap(),
            Impulses::fixed(9).unwrap().with_weights(Weights::Uniform),
        ];
        let mut visited = 0;
        for impulses in &sets {
            for extra in [0, 1, 2] {
                for round in 0..60 {
                    let scale = if round % 2 == 0 { 40.0 } else { 3e5 };
                    let mut c = || ((unit() - 0.5) * scale) as f32;
                    let (p1, p2, p3) = ([c()], [c(), c()], [c(), c(), c()]);
                    let [got, want] = visits(impulses, extra, p1);
                    assert_eq!(got, want, "{p1:?}");
                    visited += got.len();
                    let [got, want] = visits(impulses, extra, p2);
                    assert_eq!(got, want, "{p2:?}");
                    visited += got.len();
                    let [got, want] = visits(impulses, extra, p3);
                    assert_eq!(got, want, "{p3:?}");
                    visited += got.len();
                }
            }
        }
        assert!(visited > 10_000, "{visited}");
    }

    /// The walk's shared prefixes give each cell its [`CellHash`], and it visits exactly the
    /// cells within reach (against a direct loop over the 3^D cells).
    #[test]
    fn walk_visits_the_cells_in_reach_with_their_hashes() {
        let hash = CellHash::new(11);
        let impulses = Impulses::fixed(1).unwrap();
        for p in [
            [0.5f64, 0.5, 0.5],
            [0.05, 0.93, 0.5],
            [-3.2, 7.9, 0.01],
            [0.0, 0.0, 0.0],
        ] {
            // One impulse per cell: collect each visited cell's first draw through the kernel's
            // delta (the impulse's position identifies the draw).
            let mut seen = std::vec::Vec::new();
            walk(&hash, &impulses, p, NO_PARAMS, &(), |delta, _, _, _, _| {
                seen.push(delta)
            });
            let mut want = std::vec::Vec::new();
            for n in 0..27 {
                let o = [n / 9, n / 3 % 3, n % 3].map(|d: i32| d - 1);
                let cell: [i32; 3] = core::array::from_fn(|a| p[a].floor() as i32 + o[a]);
                let f: [f64; 3] = core::array::from_fn(|a| p[a] - p[a].floor());
                let reach: f64 = (0..3)
                    .map(|a| match o[a] {
                        -1 => f[a] * f[a],
                        1 => (1.0 - f[a]) * (1.0 - f[a]),
                        _ => 0.0,
                    })
                    .sum();
                if reach >= 1.0 {
                    continue;
                }
                let draw = CellRng::new(&hash, cell).next_u32();
                let delta: [f64; 3] = core::array::from_fn(|a| {
                    let k = (draw >> (a as u32 * 10)) & 1023;
                    (f[a] - o[a] as f64) - (2 * k + 1) as f64 / 2048.0
                });
                if delta.iter().map(|d| d * d).sum::<f64>() < 1.0 {
                    want.push(delta);
                }
            }
            assert_eq!(seen, want, "{p:?}");
        }
    }
}

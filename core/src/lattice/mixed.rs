//! Olano's **mixed mNoise** (Olano 2005, §3.4 "Separable Computation", and Table 2): mNoise in
//! any dimension evaluated from one precomputed 2D table over the `M × M` lattice, bit for bit
//! the computed [`MNoise<61>`].
//!
//! mNoise hashes a corner as `hash(x + hash(y + h))`, where `h` folds the axes above `y`
//! (`h = hash(z + hash(w + …))`). Every term in `x` and `y` depends on the higher axes only
//! through `h` added to `y`, so one table over `(x, y + h mod M)` serves every dimension: a 3D
//! corner reads it at `(x, y + hash(z))`, a 4D one at `(x, y + hash(z + hash(w)))`, Olano's
//! addresses `c₀ = (x, y + hash(z))` and `c_jk = (x, y + hash(z + k + hash(w + j)))`. The two
//! innermost hash steps of each of the `2^D` chains become one lookup per pair of corners;
//! only the `2 + 4` steps of the axes above `y` are computed (3D: 2 steps and 4 lookups instead
//! of 14 steps; 4D: 6 and 8 instead of 30).
//!
//! Olano stores continuous channels (the 2D noise, and the z- and w-gradients blended in x–y) in
//! a texture, and gets the 3D noise by interpolating them in `z`; that regroups the sums, which
//! rounds differently in floats and fixed point. Here the table holds what those channels are
//! made of, the corner gradients, and the sampling is the lattice body every other lattice
//! noise uses, so the result is the computed noise bit for bit in every number type. An entry
//! holds the gradient signs of two corners along `x`, four bits each: bit 0 and 1 the `x` and
//! `y` signs (the 2D noise, Olano's value channel), bit 2 the `z` and bit 3 the `w` sign (his
//! gradient channels). 61 × 61 entries: [`MixedMNoise::TABLE_BYTES`] bytes of read-only data,
//! built at compile time by a `const fn`.
//!
//! The modulus is Olano's `M = 61` only: the table grows as `M²` (4093² would be 16 MiB).

use super::corner::{corner_dot, corner_gradient};
use super::kernel::{Fade, MAX_CORNERS, Quintic, split_point};
use super::{
    Lattice, MNoise, blend, gradient_corners, half_dims, lattice_noise_impls, sample_lattice,
};
use crate::fractal::{Fractal, Octaves};
use crate::hash::Bbs;
use crate::{Noise, NoiseGradient, Real};

/// The modulus.
const M: u32 = 61;

/// Entries of the table: one per `(row, x)` of the `M × M` lattice.
const ENTRIES: usize = (M * M) as usize;

/// Entry `row · M + x`: the gradient signs (low 4 bits of the hash) of the corners `x` (low
/// nibble) and `x + 1` (high nibble) in row `row`, `hash(x + hash(row))`.
static TABLE: [u8; ENTRIES] = table();

const fn table() -> [u8; ENTRIES] {
    let mut t = [0u8; ENTRIES];
    let mut row = 0;
    while row < M {
        // row < M and x + 1 + h ≤ 2M: every argument is within what `step` accepts.
        let h = Bbs::<M>::step(row);
        let mut x = 0;
        while x < M {
            let lower = Bbs::<M>::step(x + h) & 15;
            let upper = Bbs::<M>::step(x + 1 + h) & 15;
            t[(row * M + x) as usize] = (lower | upper << 4) as u8;
            x += 1;
        }
        row += 1;
    }
    t
}

/// mNoise (`M = 61`) evaluated from Olano's 2D table (module docs): the same noise as
/// [`MNoise<61>`] with the same seed, bit for bit, for every point, number type and dimension
/// (`tests/tests/mixed.rs` compares every cell of a period in 2D and 3D), at the cost of
/// [`TABLE_BYTES`](Self::TABLE_BYTES) bytes of read-only data. Which is faster depends on the
/// core: `bench/README.md` has instructions per sample on the firmware cores and x86-64.
///
/// The seed, period, range and dimension reducibility are [`MNoise`]'s.
///
/// # Examples
///
/// ```
/// use bandnoise::{I16F16, Noise, lattice::{MNoise, MixedMNoise}};
///
/// let mixed = MixedMNoise::new(5);
/// let p = [I16F16::from_num(3.7), I16F16::from_num(-12.25), I16F16::from_num(40.5)];
/// assert_eq!(mixed.sample(p), MNoise::<61>::new(5).sample(p));
/// assert_eq!(mixed.computed(), MNoise::new(5));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MixedMNoise {
    noise: MNoise<M>,
}

impl MixedMNoise {
    /// Bytes of read-only data the table takes (once per program, shared by every seed).
    pub const TABLE_BYTES: usize = ENTRIES;

    /// Mixed mNoise for `seed`: the noise of [`MNoise::new(seed)`](MNoise::new).
    #[must_use]
    pub const fn new(seed: u32) -> Self {
        Self {
            noise: MNoise::new(seed),
        }
    }

    /// The computed noise this evaluates.
    #[must_use]
    pub const fn computed(&self) -> MNoise<M> {
        self.noise
    }

    /// The period on every axis.
    pub const PERIOD: u32 = M;
}

impl From<MNoise<M>> for MixedMNoise {
    fn from(noise: MNoise<M>) -> Self {
        Self { noise }
    }
}

impl<const D: usize> Lattice<D> for MixedMNoise {
    type Fade = Quintic;
    #[inline]
    fn corner_hashes(&self, cell: [i32; D]) -> [u32; MAX_CORNERS] {
        let n = &self.noise;
        let c: [u32; D] = core::array::from_fn(|a| Bbs::<M>::reduce_offset(cell[a], n.offset[a]));
        // The axes above y, folded last axis first from the fold of the missing axes (as
        // `MNoise`'s chain): `above[k]` for k's bit 0 the z corner, bit 1 the w corner.
        // In 1D and 2D there are none; 1D is the slice y = 0 of 2D (dimension reducibility),
        // whose cell along y is the seed's translation.
        let mut above = [n.inner[D.max(2) - 1]; 4];
        let mut count = 1;
        for a in (2..D).rev() {
            for j in (0..count).rev() {
                let h = above[j];
                above[2 * j + 1] = Bbs::<M>::step(h + c[a] + 1);
                above[2 * j] = Bbs::<M>::step(h + c[a]);
            }
            count *= 2;
        }
        let (y, rows) = if D >= 2 { (c[1], 2) } else { (n.offset[1], 1) };
        let mut h = [0; MAX_CORNERS];
        for (k, &ak) in above.iter().enumerate().take(count) {
            for b in 0..rows {
                // y < M, b ≤ 1 and ak < M: one subtraction reduces the row.
                let row = y + b + ak;
                let row = if row >= M { row - M } else { row };
                let pair = TABLE.get((row * M + c[0]) as usize).copied().unwrap_or(0);
                let m = (k << 2 | (b as usize) << 1) & (MAX_CORNERS - 2);
                h[m] = u32::from(pair & 15);
                h[m | 1] = u32::from(pair >> 4);
            }
        }
        h
    }
    gradient_corners!(D, mul_rn);
    #[inline]
    fn dot<R: Real>(&self, h: u32, d: &[R; D]) -> R {
        corner_dot(h ^ self.noise.flip, d)
    }
    #[inline]
    fn gradient<R: Real>(&self, h: u32) -> [R; D] {
        corner_gradient(h ^ self.noise.flip)
    }
}

lattice_noise_impls!(MixedMNoise, [], |_, d| half_dims(d));
crate::noise::inherent_amplitude_bound!(MixedMNoise, []);

/// Olano's turbulence (§4) over [`MixedMNoise`]: `Σ_i |n(2^i·p)| / 2^i` over `OCTAVES`
/// octaves (4 by default, as in Olano's figures; 1 to 30).
///
/// Olano's shader computes the hashes of two octaves in one four-wide operation and interpolates
/// and sums four octaves at once. Where the target has vector units (x86-64) the octaves are
/// likewise the lanes of one lattice body: each octave's corners are looked up in the table,
/// then the body interpolates all octaves at once, vectorised by the compiler. On scalar cores
/// (every other target) the lanes would spill to the stack, so there the octaves are sampled
/// one by one (the choice is `arch`'s; `bench/README.md` measures both). Either way the
/// result is [`Fractal::turbulence`] of [`MNoise<61>`] with lacunarity 2 and gain ½, bit for
/// bit (`tests/tests/mixed.rs`); [`fractal`](Self::fractal) is that sum, and gives the
/// gradient.
/// Olano's printed sum, `|n(p)| + ½|n(½p)| + …`, halves the frequency with the amplitude,
/// which would weight the coarse octaves least; the sum here is that of Perlin 1985, which he
/// cites: the frequency doubles as the amplitude halves.
///
/// # Examples
///
/// ```
/// use bandnoise::{Noise, fractal::{Fractal, Octaves}, lattice::{MNoise, MixedTurbulence}};
///
/// let t = MixedTurbulence::<4>::new(3);
/// let sum = Fractal::turbulence(MNoise::<61>::new(3), Octaves::new(4, 2.0, 0.5).unwrap());
/// let p = [0.3f32, 4.7, -2.2];
/// assert_eq!(t.sample(p), sum.sample(p));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct MixedTurbulence<const OCTAVES: usize = 4> {
    sum: Fractal<MixedMNoise>,
    /// The same sum over the computed noise, for the batch paths.
    computed: Fractal<MNoise<M>>,
}

impl<const OCTAVES: usize> MixedTurbulence<OCTAVES> {
    const VALID: () = assert!(
        OCTAVES >= 1 && OCTAVES <= Octaves::MAX as usize,
        "1 to 30 octaves"
    );

    /// Turbulence of [`MixedMNoise::new(seed)`](MixedMNoise::new).
    #[must_use]
    pub fn new(seed: u32) -> Self {
        let () = Self::VALID;
        // Valid for every OCTAVES the assertion admits; the default is never taken.
        let octaves = Octaves::new(OCTAVES as u32, 2.0, 0.5).unwrap_or_default();
        let sum = Fractal::turbulence(MixedMNoise::new(seed), octaves);
        Self {
            computed: sum.with_noise(MNoise::new(seed)),
            sum,
        }
    }

    /// The same sum as a [`Fractal`] (octave by octave).
    #[must_use]
    pub fn fractal(&self) -> &Fractal<MixedMNoise> {
        &self.sum
    }
}

impl<R: Real, const D: usize, const OCTAVES: usize> Noise<R, D> for MixedTurbulence<OCTAVES>
where
    MixedMNoise: Lattice<D>,
{
    fn sample(&self, p: [R; D]) -> R {
        if crate::arch::OCTAVES_AS_LANES {
            self.together(p)
        } else {
            self.one_by_one(p)
        }
    }

    fn amplitude_bound(&self) -> f32 {
        Noise::<R, D>::amplitude_bound(&self.sum)
    }

    /// The octave-by-octave sum over [`LANES`](crate::batch::LANES) points of the *computed*
    /// noise, whose hashes vectorise across points (the table's lookups do not): the same
    /// values, fewer instructions (`bench/README.md`).
    #[inline]
    fn sample_lanes(&self, p: &[[R; crate::batch::LANES]; D], out: &mut [R; crate::batch::LANES]) {
        self.computed.sample_lanes(p, out);
    }
}

impl<const OCTAVES: usize> MixedTurbulence<OCTAVES> {
    /// The octaves together: each octave's corners looked up, then one [`blend`] over the
    /// octaves as lanes (vector units).
    #[inline]
    fn together<R: Real, const D: usize>(&self, p: [R; D]) -> R
    where
        MixedMNoise: Lattice<D>,
    {
        let noise = self.sum.noise();
        // The octaves' points, as `Fractal` computes them (the frequency doubles, saturating;
        // the coordinate wraps in fixed point), split into cells and fractions.
        let mut cells = [[0i32; D]; OCTAVES];
        let mut f = [[R::ZERO; D]; OCTAVES];
        let mut frequency = R::ONE;
        let two = R::from_i32(2);
        for (c, fo) in cells.iter_mut().zip(&mut f) {
            (*c, *fo) = split_point(p.map(|x| x.wrapping_mul(frequency)));
            frequency = frequency.saturating_mul(two);
        }
        // The gradient bits of every octave's corners (4 bits each, so the octaves' corners
        // take 16 bytes each rather than 64: copying words cost more than the lookups on
        // RV32IMC).
        let mut h = [[0u8; MAX_CORNERS]; OCTAVES];
        for (ho, c) in h.iter_mut().zip(&cells) {
            let corners = noise.corner_hashes(*c);
            for (b, &hm) in ho.iter_mut().zip(&corners).take(1 << D) {
                *b = hm as u8;
            }
        }
        let mut s = f;
        for so in &mut s {
            for x in so.iter_mut() {
                *x = Quintic::fade(*x);
            }
        }
        let n = blend::<R, D, OCTAVES>(
            |a, o| f[o][a],
            |a, o| s[o][a],
            |m, o, d| noise.dot(u32::from(h[o][m]), d),
        );
        Self::sum(n)
    }

    /// The octaves one by one (scalar cores).
    #[inline]
    fn one_by_one<R: Real, const D: usize>(&self, p: [R; D]) -> R
    where
        MixedMNoise: Lattice<D>,
    {
        let noise = self.sum.noise();
        let mut n = [R::ZERO; OCTAVES];
        let mut frequency = R::ONE;
        let two = R::from_i32(2);
        for v in &mut n {
            *v = sample_lattice(noise, p.map(|x| x.wrapping_mul(frequency)));
            frequency = frequency.saturating_mul(two);
        }
        Self::sum(n)
    }

    /// `Σ_i |n_i| / 2^i`, saturating, as [`Fractal`] sums.
    #[inline]
    fn sum<R: Real>(n: [R; OCTAVES]) -> R {
        let half = R::from_ratio(1, 1);
        let (mut sum, mut amplitude) = (R::ZERO, R::ONE);
        for v in n {
            sum = sum.saturating_add(amplitude.saturating_mul(v.abs()));
            amplitude = amplitude.saturating_mul(half);
        }
        sum.canonical()
    }
}

crate::noise::inherent_amplitude_bound!(MixedTurbulence<OCTAVES>, [const OCTAVES: usize]);

impl<R: Real, const D: usize, const OCTAVES: usize> NoiseGradient<R, D> for MixedTurbulence<OCTAVES>
where
    MixedMNoise: Lattice<D>,
{
    /// [`Fractal`]'s gradient; the value is the same as [`sample`](Noise::sample)'s.
    fn sample_with_gradient(&self, p: [R; D]) -> (R, [R; D]) {
        self.sum.sample_with_gradient(p)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::hash::chain::{self, Order};

    /// The lookups give the corner hashes of the computed chain (their gradient bits) for every
    /// cell of a period in 1D–3D and a spread of 4D cells, for seeds with and without a
    /// translation and flips.
    #[test]
    fn corners_are_the_computed_chains() {
        fn check<const D: usize>(noise: &MixedMNoise, cell: [i32; D]) {
            let computed = Lattice::<D>::corner_hashes(&noise.noise, cell);
            let mixed = Lattice::<D>::corner_hashes(noise, cell);
            for m in 0..1 << D {
                assert_eq!(mixed[m], computed[m] & 15, "{cell:?} corner {m}");
            }
        }
        for seed in [0, 1, 7, 12345] {
            let noise = MixedMNoise::new(seed);
            for x in -61..61 {
                check(&noise, [x]);
                for y in 0..61 {
                    check(&noise, [x, y]);
                }
            }
            for x in 0..61 {
                for y in 0..61 {
                    for z in 0..61 {
                        check(&noise, [x, y, z]);
                    }
                    check(&noise, [x, y, 2 * x - 7, y * 3 + 11]);
                }
            }
        }
        // The chain the table replaces, spelled out for one cell.
        let noise = MixedMNoise::new(0);
        let step = |h: u32, c: u32| Bbs::<M>::step(h + c);
        let want = chain::cell(Order::LastFirst, 0, [4, 9, 33, 50], step);
        assert_eq!(
            Lattice::<4>::corner_hashes(&noise, [4, 9, 33, 50])[0],
            want & 15
        );
    }

    /// Both ways of summing the octaves give the same bits (the target runs one of them in
    /// `sample`; the tests of `tests/tests/mixed.rs` compare that one with `Fractal`).
    #[test]
    fn turbulence_octaves_together_or_one_by_one() {
        use crate::I16F16;
        let t = MixedTurbulence::<5>::new(3);
        let mut x = 0x1234_5678u32;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 17;
            x ^= x << 5;
            x
        };
        for _ in 0..20_000 {
            let q: [I16F16; 3] = core::array::from_fn(|_| I16F16::from_bits(next() as i32));
            assert_eq!(t.together(q), t.one_by_one(q), "{q:?}");
            let p: [f32; 4] = core::array::from_fn(|_| (next() as i32) as f32 / 65536.0);
            assert_eq!(t.together(p).to_bits(), t.one_by_one(p).to_bits(), "{p:?}");
            let p2 = [p[0], p[1]];
            assert_eq!(
                t.together(p2).to_bits(),
                t.one_by_one(p2).to_bits(),
                "{p:?}"
            );
        }
    }
}

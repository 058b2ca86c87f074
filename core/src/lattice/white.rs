//! Lattice white noise (Lewis 1989 §2.2): [`WhiteNoise`] and its tables.

use super::Periodic;
use crate::Real;
use crate::hash::CellHash;
use crate::lattice::kernel::split_point;
use crate::wavelet::Distribution;
use crate::wavelet::constmath::{ln, sqrt};

/// The length of each table of values: a prime, as Lewis's `RANTABLEN`.
pub const VALUES: usize = 1021;

/// The table's values are in units of 2⁻¹² (exact in `f32`, `f64` and I16F16).
const SHIFT: u32 = 12;

/// Value `k` (of [`VALUES`], ascending) of `distribution`'s table, in units of 2⁻¹²; `k` is
/// taken modulo [`VALUES`].
///
/// * [`Uniform`](Distribution::Uniform): `(2k + 1)/N − 1`, uniform in `[-1, 1]` (mean 0,
///   variance `(1 − 1/N²)/3 ≈ ⅓`, largest magnitude `1 − 1/N`), computed.
/// * [`Gaussian`](Distribution::Gaussian): the standard normal's quantile at `(k + ½)/N`
///   (mean 0; variance 0.9987 and largest magnitude 3.2964, both of the table itself, as `N`
///   stratified values have a slightly shorter tail than the distribution), read from the
///   upper half of the table (the lower half is its mirror image), 1022 bytes.
///
/// ```
/// use bandnoise::lattice::{VALUES, table_value};
/// use bandnoise::wavelet::Distribution;
///
/// assert_eq!(table_value(Distribution::Uniform, 0), -4092); // −1 + 1/1021, to 2⁻¹²
/// assert_eq!(table_value(Distribution::Gaussian, VALUES / 2), 0); // the median
/// ```
#[must_use]
pub const fn table_value(distribution: Distribution, k: usize) -> i16 {
    let k = k % VALUES;
    // The tables are odd about their middle entry: |value| from the distance to it.
    let (negative, j) = if k < MIDDLE {
        (true, MIDDLE - k)
    } else {
        (false, k - MIDDLE)
    };
    let magnitude = match distribution {
        // round(j · 2¹³ / N): j · 8192 + N/2 < 2³¹.
        Distribution::Uniform => ((j as u32 * 8192 + VALUES as u32 / 2) / VALUES as u32) as i16,
        // `j ≤ MIDDLE`: in the table (the comparison shows it, no bounds check).
        Distribution::Gaussian => GAUSSIAN_HALF[if j < MIDDLE { j } else { MIDDLE }],
    };
    if negative { -magnitude } else { magnitude }
}

/// The middle entry (value 0) of a table.
const MIDDLE: usize = VALUES / 2;

/// The largest magnitude in `distribution`'s table (the noise's bound).
const fn largest(distribution: Distribution) -> f32 {
    table_value(distribution, VALUES - 1) as f32 / (1 << SHIFT) as f32
}

/// The Gaussian table's upper half: entries `MIDDLE..VALUES`.
static GAUSSIAN_HALF: [i16; MIDDLE + 1] = gaussian_half();

/// Every entry of each table ([`table_value`]), so that a sample reads its value with one load
/// (2 KiB each; the formula's remainder, division and sign took a cubic value-noise sample
/// half of its instructions). Not with the `small` feature.
#[cfg(not(feature = "small"))]
static UNIFORM: [i16; VALUES] = full_table(Distribution::Uniform);
#[cfg(not(feature = "small"))]
static GAUSSIAN: [i16; VALUES] = full_table(Distribution::Gaussian);

#[cfg(not(feature = "small"))]
const fn full_table(distribution: Distribution) -> [i16; VALUES] {
    let mut t = [0i16; VALUES];
    let mut k = 0;
    while k < VALUES {
        t[k] = table_value(distribution, k);
        k += 1;
    }
    t
}

/// `round(v · 2¹²)`, halves away from zero (so the tables are symmetric).
const fn quantise(v: f64) -> i16 {
    let scaled = v * (1 << SHIFT) as f64;
    let r = if scaled < 0.0 {
        -((-scaled + 0.5) as i64)
    } else {
        (scaled + 0.5) as i64
    };
    r as i16
}

const fn gaussian_half() -> [i16; MIDDLE + 1] {
    let mut t = [0i16; MIDDLE + 1];
    let mut j = 0;
    while j <= MIDDLE {
        t[j] = quantise(normal_quantile(
            (MIDDLE + j) as f64 / VALUES as f64 + 0.5 / VALUES as f64,
        ));
        j += 1;
    }
    t
}

/// `Φ⁻¹(p)` for `p` in `(0, 1)`: Acklam's rational approximation (relative error below
/// 1.2·10⁻⁹, far below the tables' 2⁻¹³ rounding; the tables are checked against `erfc` in
/// `tests/tests/white.rs`). `const` (with the wavelet tiles' `ln` and `sqrt`), so the tables
/// are built at compile time, identically on every target.
const fn normal_quantile(p: f64) -> f64 {
    const A: [f64; 6] = [
        -3.969_683_028_665_376e1,
        2.209_460_984_245_205e2,
        -2.759_285_104_469_687e2,
        1.383_577_518_672_69e2,
        -3.066_479_806_614_716e1,
        2.506_628_277_459_239,
    ];
    const B: [f64; 5] = [
        -5.447_609_879_822_406e1,
        1.615_858_368_580_409e2,
        -1.556_989_798_598_866e2,
        6.680_131_188_771_972e1,
        -1.328_068_155_288_572e1,
    ];
    const C: [f64; 6] = [
        -7.784_894_002_430_293e-3,
        -3.223_964_580_411_365e-1,
        -2.400_758_277_161_838,
        -2.549_732_539_343_734,
        4.374_664_141_464_968,
        2.938_163_982_698_783,
    ];
    const D: [f64; 4] = [
        7.784_695_709_041_462e-3,
        3.224_671_290_700_398e-1,
        2.445_134_137_142_996,
        3.754_408_661_907_416,
    ];
    const LOW: f64 = 0.02425;
    // The tails: a rational function of q = √(−2 ln p), odd about ½.
    const fn tail(p: f64) -> f64 {
        let q = sqrt(-2.0 * ln(p));
        (((((C[0] * q + C[1]) * q + C[2]) * q + C[3]) * q + C[4]) * q + C[5])
            / ((((D[0] * q + D[1]) * q + D[2]) * q + D[3]) * q + 1.0)
    }
    if p < LOW {
        tail(p)
    } else if p > 1.0 - LOW {
        -tail(1.0 - p)
    } else {
        let q = p - 0.5;
        let r = q * q;
        (((((A[0] * r + A[1]) * r + A[2]) * r + A[3]) * r + A[4]) * r + A[5]) * q
            / (((((B[0] * r + B[1]) * r + B[2]) * r + B[3]) * r + B[4]) * r + 1.0)
    }
}

/// Lattice white noise (Lewis 1989 §2.2, Fig. 1): an uncorrelated random value per integer
/// cell, constant across the cell.
///
/// Lewis hashes a point's cell into an index of a table of random values "with the desired
/// probability density" whose length is prime (`Rantab[i % RANTABLEN]`). bandnoise's index is
/// the seed's [`CellHash`] of the cell (the hash every cell-based noise shares; Lewis's
/// per-axis indirection tables are its role), and its tables hold [`VALUES`] (a prime)
/// stratified quantiles of a [`Distribution`] ([`table_value`]): value `k` is the quantile at `(k + ½)/N`, so
/// the table's values follow the distribution as closely as `N` values can, in 1/4096 steps
/// (exact in every number type, so `f32`, `f64` and I16F16 give the same values). The order
/// of the table does not matter: the hash picks an entry at random.
///
/// It is the input that interpolation and filtering turn into smooth noise (Lewis §2.3):
/// [`CubicValueNoise`](super::CubicValueNoise) interpolates these values.
///
///
/// * **Value**: `table[h mod N]` for the cell's hash `h` (`CellHash` of `floor(p)`), constant
///   on each cell `[i, i + 1)ᴰ`, so discontinuous at cell borders (its
///   [`NoiseGradient`](crate::NoiseGradient) is 0, the derivative inside the cells).
/// * **Distribution**: [`Uniform`](Distribution::Uniform) in `[-1, 1]` by default, or
///   [`Gaussian`](Distribution::Gaussian) ([`with_distribution`](Self::with_distribution)).
/// * **Range**: the table's largest magnitude ([`largest`](Self::largest), [`table_value`]):
///   `1 − 1/N` for uniform values, 3.2964 for Gaussian ones.
/// * **Period**: 2³² cells per axis (the hash uses each cell's whole coordinate), or any
///   period per axis from 1 to 2¹⁶ cells wrapped by [`Periodic`].
///
/// # Examples
///
/// ```
/// use bandnoise::{Noise, lattice::WhiteNoise, wavelet::Distribution};
///
/// let white = WhiteNoise::new(7);
/// // One value per cell.
/// assert_eq!(white.sample([2.25f32, -4.5]), white.sample([2.75, -4.25]));
/// assert!(white.sample([2.25f32, -4.5]).abs() <= 1.0);
/// // Gaussian values: most within ±3, and the bound is the table's largest.
/// let g = white.with_distribution(Distribution::Gaussian);
/// assert!(g.sample([0.5f64, 0.5]).abs() <= g.amplitude_bound::<2>() as f64);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct WhiteNoise {
    hash: CellHash,
    distribution: Distribution,
}

impl WhiteNoise {
    /// Lattice white noise for `seed`, uniform in `[-1, 1]`.
    #[must_use]
    pub const fn new(seed: u32) -> Self {
        Self {
            hash: CellHash::new(seed),
            distribution: Distribution::Uniform,
        }
    }

    /// The largest magnitude of its values: its bound in every dimension.
    #[must_use]
    pub const fn largest(&self) -> f32 {
        largest(self.distribution)
    }

    /// The same noise with values of `distribution`.
    #[must_use]
    pub const fn with_distribution(self, distribution: Distribution) -> Self {
        Self {
            distribution,
            ..self
        }
    }

    /// The distribution of the values.
    #[must_use]
    pub const fn distribution(&self) -> Distribution {
        self.distribution
    }

    /// The value of integer cell `cell`: the noise anywhere in `[cell, cell + 1)ᴰ`.
    #[must_use]
    pub fn cell_value<R: Real, const D: usize>(&self, cell: [i32; D]) -> R {
        self.value_of_hash(self.hash.hash(cell))
    }

    /// The chain hash the cell values come from (shared with the cubic interpolant).
    pub(crate) fn hash(&self) -> &CellHash {
        &self.hash
    }

    /// The value for a cell whose hash is `h`.
    #[inline]
    pub(crate) fn value_of_hash<R: Real>(&self, h: u32) -> R {
        // The `small` feature computes the entry (4 KiB less data, more instructions).
        #[cfg(feature = "small")]
        let value = table_value(self.distribution, h as usize);
        #[cfg(not(feature = "small"))]
        let value = {
            let table = match self.distribution {
                Distribution::Uniform => &UNIFORM,
                Distribution::Gaussian => &GAUSSIAN,
            };
            // `% VALUES` keeps the index in the table (the comparison-free bounds proof).
            table[(h % VALUES as u32) as usize]
        };
        R::from_ratio(i32::from(value), SHIFT)
    }
}

impl Default for WhiteNoise {
    fn default() -> Self {
        Self::new(0)
    }
}

macro_rules! white_impls {
    ($($d:literal),*) => {$(
        impl<R: Real> crate::Noise<R, $d> for WhiteNoise {
            #[inline]
            fn sample(&self, p: [R; $d]) -> R {
                let (cell, _) = split_point(p);
                self.cell_value(cell)
            }
            fn amplitude_bound(&self) -> f32 {
                largest(self.distribution)
            }
        }

        /// The gradient is 0: the derivative wherever it exists (inside each cell; the noise
        /// jumps at the cell borders, where it has none).
        impl<R: Real> crate::NoiseGradient<R, $d> for WhiteNoise {
            #[inline]
            fn sample_with_gradient(&self, p: [R; $d]) -> (R, [R; $d]) {
                (crate::Noise::sample(self, p), [R::ZERO; $d])
            }
        }
    )*};
}

macro_rules! periodic_white_impls {
    ($($d:literal),*) => {$(
        impl<R: Real> crate::Noise<R, $d> for Periodic<WhiteNoise, $d> {
            #[inline]
            fn sample(&self, p: [R; $d]) -> R {
                crate::Noise::sample(&self.with_noise(self.noise()), p)
            }
            fn amplitude_bound(&self) -> f32 {
                self.noise().largest()
            }
        }

        impl<R: Real> crate::NoiseGradient<R, $d> for Periodic<WhiteNoise, $d> {
            #[inline]
            fn sample_with_gradient(&self, p: [R; $d]) -> (R, [R; $d]) {
                (crate::Noise::sample(self, p), [R::ZERO; $d])
            }
        }

        /// The value of the cell wrapped to the period along each axis: periodic bit for
        /// bit, and the unwrapped noise's values on the cells `0..P`.
        impl<R: Real> crate::Noise<R, $d> for Periodic<&WhiteNoise, $d> {
            #[inline]
            fn sample(&self, p: [R; $d]) -> R {
                let (cell, _) = split_point(p);
                let wrap = self.wrap();
                // Wrapped coordinates are below 2¹⁶: the same `i32`s as unwrapped ones there.
                let wrapped: [i32; $d] = core::array::from_fn(|a| wrap.cell(a, cell[a], 0) as i32);
                self.noise().cell_value(wrapped)
            }
            fn amplitude_bound(&self) -> f32 {
                self.noise().largest()
            }
        }

        impl<R: Real> crate::NoiseGradient<R, $d> for Periodic<&WhiteNoise, $d> {
            #[inline]
            fn sample_with_gradient(&self, p: [R; $d]) -> (R, [R; $d]) {
                (crate::Noise::sample(self, p), [R::ZERO; $d])
            }
        }
    )*};
}

white_impls!(1, 2, 3, 4);
periodic_white_impls!(1, 2, 3, 4);
crate::noise::inherent_amplitude_bound!(WhiteNoise, []);

#[cfg(test)]
mod tests {
    use super::*;

    /// The tables' values by definition: the quantiles at `(k + ½)/N`, rounded to 2⁻¹²
    /// (uniform: `(2k + 1)/N − 1`).
    #[test]
    fn tables_hold_the_stratified_quantiles() {
        for k in 0..VALUES {
            let p = (k as f64 + 0.5) / VALUES as f64;
            assert_eq!(
                table_value(Distribution::Uniform, k),
                quantise(2.0 * p - 1.0),
                "{k}"
            );
            assert_eq!(
                table_value(Distribution::Gaussian, k),
                quantise(normal_quantile(p)),
                "{k}"
            );
            for d in [Distribution::Uniform, Distribution::Gaussian] {
                assert_eq!(
                    table_value(d, k),
                    -table_value(d, VALUES - 1 - k),
                    "{d:?} {k}"
                );
                if k > 0 {
                    assert!(table_value(d, k - 1) < table_value(d, k), "{d:?} {k}");
                }
            }
        }
        assert_eq!(table_value(Distribution::Gaussian, MIDDLE), 0);
    }

    /// The wavelet tiles' const `ln` and `sqrt`, over the range the Gaussian table's tails use.
    #[test]
    fn const_math_is_accurate() {
        for x in [1e-300, 1e-9, 0.02, 0.5, 1.0, 3.0, 1e10] {
            assert!((ln(x) - libm::log(x)).abs() <= 1e-13 * libm::log(x).abs().max(1.0));
            assert!((sqrt(x) - libm::sqrt(x)).abs() <= 1e-15 * libm::sqrt(x));
        }
    }

    #[test]
    fn length_is_prime() {
        assert!(
            (2..VALUES)
                .take_while(|d| d * d <= VALUES)
                .all(|d| !VALUES.is_multiple_of(d))
        );
    }
}

//! Multiband wavelet noise (Cook & DeRose 2005, eq. 1, §4.2, Appendix 2 with erratum 8):
//! `M(x) = Σ_b w_b N(2^b x)` over a bounded list of bands, normalised to variance 1 and
//! optionally remapped to a uniform distribution.
//!
//! Each band is offset by a pseudo-random translation so bands do not line up (footnote 1).
//! Because wavelet bands are orthogonal, the variance of the sum is `σ_N² Σ w_b²` (eq. 39):
//! dividing by its square root gives variance 1 whatever the weights. For `σ_N²` the paper uses
//! one figure per kind; bandnoise uses each tile's exact band variance, computed when the tile
//! is generated ([`Tile3::variance`](super::Tile3::variance)), so the variance is 1 for every
//! tile and not only on average (a single 64² tile's variance is up to 8% off the average).
//! A projected band's variance is that variance times a ratio that depends on the normal
//! (1.483 to 1.561, [`projected_gain`](super::projected_gain)), computed from the tile filters;
//! projected sums are multiplied by the normal's gain, so their variance is 1 for every normal,
//! not only on average. The averages over many tiles, against the paper: 2D [`VARIANCE_2D`]
//! (0.265, +2%), projected [`VARIANCE_PROJECTED`] (0.296, −1%), 3D [`VARIANCE_3D`] (0.210,
//! −7%). The paper's 3D
//! figure is that of its printed generator taken literally: `if (n/2) n++` (erratum 1) turns a
//! requested 64³ tile into an odd 65³ one, whose coarse part is not fully removed, and a
//! transcription of that code gives 0.209–0.211; the same transcription with an even tile gives
//! 0.193–0.198, as bandnoise does (`tests/tests/wavelet.rs`).

use heapless::Vec;

use crate::batch::{Grid, LANES, for_each_rows};
use crate::{Error, Noise, ProjectedNoise, Real};

use super::band::{GROUP, TileData, Tiling, Wavelet};
use super::erf::erf_with_derivative;
use super::projected::GAIN_MAX;

/// Average variance of one 2D band over many tiles (measured: 24 tiles of 64²; the paper gives
/// 0.265).
pub const VARIANCE_2D: f32 = 0.270;
/// Average variance of one 3D band over many tiles (measured: 24 tiles of 32³; the paper's
/// 0.210 is that of the odd 65³ tile its printed code builds, see the module docs).
pub const VARIANCE_3D: f32 = 0.1955;
/// Average variance of one 3D band projected onto a plane, over random normals (measured: 1.50
/// times the 3D variance; the paper gives 0.296).
pub const VARIANCE_PROJECTED: f32 = 0.2937;

/// The most bands a [`Bands`] list holds.
pub const MAX_BANDS: usize = 16;

/// The band weights of a multiband noise: band `first + i` has weight `weights[i]`.
///
/// Band `b` samples the noise band at frequency `2^b` relative to band 0, whose frequencies lie
/// between ½ and 1 cycle per unit, like Perlin noise's.
///
/// Plain `Copy` data (a fixed array of [`MAX_BANDS`] weights and a count), so a
/// [`Spec`](crate::spec::Spec) holds one as it is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bands {
    first: i32,
    /// The first `count` entries are the weights; the rest stay 0 (so `PartialEq` compares
    /// only the weights).
    weights: [f32; MAX_BANDS],
    count: u8,
}

/// [`Bands::default`], usable in `const` code.
pub(crate) const DEFAULT_BANDS: Bands = {
    let mut weights = [0.0; MAX_BANDS];
    weights[0] = 1.0;
    weights[1] = 0.5;
    weights[2] = 0.25;
    weights[3] = 0.125;
    weights[4] = 0.0625;
    Bands {
        first: 0,
        weights,
        count: 5,
    }
};

impl Bands {
    /// Bands `first, first + 1, …` with the given weights.
    ///
    /// # Errors
    ///
    /// [`Error::TooManyBands`] for more than [`MAX_BANDS`] weights, [`Error::BandWeight`] for a
    /// weight that is not finite or exceeds 10⁶ in magnitude, [`Error::FirstBand`] unless
    /// `-24 ≤ first ≤ 8`. All weights 0 is allowed: the noise is then 0.
    ///
    /// # Examples
    ///
    /// ```
    /// use bandnoise::{Error, wavelet::Bands};
    ///
    /// let b = Bands::new(-2, &[0.25, 0.5, 1.0]).unwrap();
    /// assert_eq!(b.weights(), &[0.25, 0.5, 1.0]);
    /// assert!(matches!(Bands::new(0, &[1.0, f32::NAN]), Err(Error::BandWeight { index: 1, .. })));
    /// assert!(Bands::new(0, &[1.0; 17]).is_err());
    /// ```
    pub fn new(first: i32, weights: &[f32]) -> Result<Self, Error> {
        if !(-24..=8).contains(&first) {
            return Err(Error::FirstBand(first));
        }
        if weights.len() > MAX_BANDS {
            return Err(Error::TooManyBands {
                count: weights.len(),
                max: MAX_BANDS,
            });
        }
        let mut v = [0.0; MAX_BANDS];
        for (index, (&value, slot)) in weights.iter().zip(&mut v).enumerate() {
            if !value.is_finite() || value.abs() > 1e6 {
                return Err(Error::BandWeight { index, value });
            }
            *slot = value;
        }
        Ok(Self {
            first,
            weights: v,
            count: weights.len() as u8,
        })
    }

    /// `count` bands from `first` with weights `1, gain, gain², …` (fractal noise).
    ///
    /// # Errors
    ///
    /// As [`Bands::new`].
    pub fn fractal(first: i32, count: usize, gain: f32) -> Result<Self, Error> {
        let mut w = [0.0f32; MAX_BANDS];
        let mut a = 1.0f32;
        for wi in w.iter_mut().take(count.min(MAX_BANDS)) {
            *wi = a;
            a *= gain;
        }
        if count > MAX_BANDS {
            return Err(Error::TooManyBands {
                count,
                max: MAX_BANDS,
            });
        }
        Self::new(first, &w[..count])
    }

    /// The first band.
    #[must_use]
    pub fn first(&self) -> i32 {
        self.first
    }

    /// The weights.
    #[must_use]
    pub fn weights(&self) -> &[f32] {
        // `count` is at most MAX_BANDS by construction.
        self.weights.get(..usize::from(self.count)).unwrap_or(&[])
    }
}

impl Default for Bands {
    /// Five bands from 0 with weights `1, ½, ¼, ⅛, 1/16`.
    fn default() -> Self {
        DEFAULT_BANDS
    }
}

/// The distribution of multiband noise values.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum Distribution {
    /// Gaussian with mean 0 and variance 1 (the natural distribution of wavelet noise).
    #[default]
    Gaussian,
    /// Uniform on `[-1, 1]`: the Gaussian value `g` becomes `erf(g/√2)` (§4.2). The ends are
    /// reached: `erf` is ±1 beyond `|g/√2| ≥ 4` and first rounds to ±1 at 3.8758 in `f32`
    /// (3.09375 in I16F16), so the rare tail values beyond those are ±1 exactly.
    Uniform,
}

/// Multiband wavelet noise over a tile `T` (2D or 3D).
///
/// Sampling follows the [`Noise`] contract: never panics; a NaN or ±∞ coordinate is 0, so
/// every band samples its own offset there; band `b` samples its band at `2^(b+1)·p + offset_b`
/// (a float coordinate so large that this overflows is a multiple of 2³², and is taken as 0);
/// the result is finite, never `-0.0`, and within [`amplitude_bound`](Noise::amplitude_bound).
///
/// # Examples
///
/// ```
/// use bandnoise::{Noise, wavelet::{Bands, Distribution, Multiband, TILE2}};
///
/// let m = Multiband::new(7, &TILE2, Bands::default(), Distribution::Uniform);
/// let v: f32 = m.sample([0.25, 4.5]);
/// assert!(v.abs() <= 1.0);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Multiband<'t, T> {
    band: Wavelet<'t, T>,
    bands: Bands,
    distribution: Distribution,
    /// Each band's weight divided by `sqrt(σ² Σ w²)`, for 2D (index 0), 3D (1) and projected
    /// (2) bands. Projected sums are also multiplied by the normal's
    /// [`projected_gain`](super::projected_gain).
    scaled: Vec<[f32; 3], MAX_BANDS>,
}

/// The exact band variance of any tile (2D or 3D), for [`Multiband::new`].
pub trait TileVariance {
    /// See [`Tile3::variance`](super::Tile3::variance).
    fn band_variance(&self) -> f32;
}

macro_rules! tile_variance {
    ($($t:ident),*) => {$(
        impl<const N: usize> TileVariance for super::$t<N> {
            fn band_variance(&self) -> f32 {
                self.variance()
            }
        }
    )*};
}
tile_variance!(Tile2, Tile3, QuantizedTile2, QuantizedTile3);

/// A per-band, per-axis translation in `[0, 64)` coefficients, in 16-bit fixed steps.
fn band_offset(seed: u32, band: i32, axis: usize) -> i32 {
    let mut h =
        seed ^ (band as u32).wrapping_mul(0x9E37_79B9) ^ (axis as u32).wrapping_mul(0x85EB_CA6B);
    h ^= h >> 16;
    h = h.wrapping_mul(0x7FEB_352D);
    h ^= h >> 15;
    h = h.wrapping_mul(0x846C_A68B);
    h ^= h >> 16;
    (h & 0x3F_FFFF) as i32
}

impl<'t, T> Multiband<'t, T> {
    /// Multiband noise over `tile`; `seed` picks tile orientations and band offsets.
    ///
    /// Not `const`: the normalisation takes square roots in `f64` (`libm`), and a [`Bands`]
    /// list is validated when it is built, at run time.
    #[must_use]
    pub fn new(seed: u32, tile: &'t T, bands: Bands, distribution: Distribution) -> Self
    where
        T: TileVariance,
    {
        // Normalise in f64 after dividing by the largest weight, so tiny or huge weights
        // neither underflow nor overflow Σw² (found by the fuzz target `wavelet`).
        let largest = bands
            .weights()
            .iter()
            .fold(0.0f64, |m, w| m.max((*w as f64).abs()));
        let ss: f64 = bands
            .weights()
            .iter()
            .map(|w| {
                let r = *w as f64 / largest;
                r * r
            })
            .sum();
        // The tile's own exact band variance. Projected bands have that of the sampled band
        // times a ratio that depends on the normal: each sample multiplies by its
        // `projected_gain` (so index 2 is index 1, kept apart for the bounds).
        let var = tile.band_variance() as f64;
        let mut scaled = Vec::new();
        for &w in bands.weights() {
            let s = |var: f64| {
                if largest > 0.0 && var > 0.0 {
                    (w as f64 / largest / libm::sqrt(var * ss)) as f32
                } else {
                    0.0
                }
            };
            // Cannot fail: as many entries as bands.
            let _ = scaled.push([s(var), s(var), s(var)]);
        }
        Self {
            band: Wavelet::new(seed, tile),
            bands,
            distribution,
            scaled,
        }
    }

    /// The same noise with another tiling.
    #[must_use]
    pub fn with_tiling(mut self, tiling: Tiling) -> Self {
        self.band = self.band.with_tiling(tiling);
        self
    }

    /// The bands.
    #[must_use]
    pub fn bands(&self) -> &Bands {
        &self.bands
    }

    /// The distribution.
    #[must_use]
    pub fn distribution(&self) -> Distribution {
        self.distribution
    }

    /// `Σ_b w'_b f_b(p_b)` with `p_b = 2^(first+b+1) p + offset_b`, then the distribution.
    ///
    /// A scaled coordinate that is not finite (a NaN or ±∞ coordinate, or a float so large
    /// that the scaling overflows) is 0 before the band's offset is added: each band samples
    /// `offset_b`, as the [`Noise`] contract's "NaN and ±∞ are 0" asks. (An overflowing float
    /// is a multiple of 2³² anyway, whose cell wraps to 0.)
    fn sum<R: Real, const D: usize>(&self, p: [R; D], which: usize, f: impl Fn([R; D]) -> R) -> R {
        self.sum_with_gradient(p, which, |_, q| (f(q), [R::ZERO; D]))
            .0
    }

    /// [`sum`](Self::sum) and its gradient, from each band's value and gradient `f(b, q)`: band
    /// `b` samples at `2^(b+1)·p + offset_b`, so its gradient counts `2^(b+1)` times; the
    /// uniform distribution multiplies by the derivative of its `erf`. The value is `sum`'s,
    /// bit for bit (`sum` is this with the gradients unused).
    #[inline]
    fn sum_with_gradient<R: Real, const D: usize>(
        &self,
        p: [R; D],
        which: usize,
        f: impl Fn(i32, [R; D]) -> (R, [R; D]),
    ) -> (R, [R; D]) {
        let first = self.bands.first;
        let weights = self.scaled.iter().enumerate();
        self.sum_weighted(p, weights.map(|(i, w)| (first + i as i32, w[which])), f)
    }

    /// [`sum_with_gradient`](Self::sum_with_gradient) over the bands and scaled weights that
    /// `weights` lists.
    #[inline]
    fn sum_weighted<R: Real, const D: usize>(
        &self,
        p: [R; D],
        weights: impl Iterator<Item = (i32, f32)>,
        f: impl Fn(i32, [R; D]) -> (R, [R; D]),
    ) -> (R, [R; D]) {
        let mut sum = R::ZERO;
        let mut gradient = [R::ZERO; D];
        for (band, w) in weights {
            if w == 0.0 {
                continue;
            }
            let (scale, to_band) = self.band_map::<R, D>(band);
            let q: [R; D] = core::array::from_fn(|a| to_band(p[a], a));
            let weight = R::from_f32(w);
            let (v, g) = f(band, q);
            sum = sum.saturating_add(weight.mul_rn(v));
            for (ga, gb) in gradient.iter_mut().zip(g) {
                *ga = ga.saturating_add(weight.mul_rn(gb).saturating_mul(scale));
            }
        }
        let (value, chain) = self.finish(sum);
        let gradient = match chain {
            None => gradient.map(R::canonical),
            Some(chain) => gradient.map(|g| g.saturating_mul(chain).canonical()),
        };
        (value, gradient)
    }

    /// Band `band`'s scale `2^(band+1)` and the map of a coordinate along an axis into the
    /// band: scaled, then offset by the band's translation (footnote 1).
    #[inline]
    fn band_map<R: Real, const D: usize>(&self, band: i32) -> (R, impl Fn(R, usize) -> R) {
        let e = band + 1;
        let scale = if e >= 0 {
            R::from_i32(1 << e.min(30))
        } else {
            R::from_ratio(1, (-e) as u32)
        };
        let seed = self.band.seed();
        let offsets: [R; D] =
            core::array::from_fn(|a| R::from_ratio(band_offset(seed, band, a), 16));
        let map = move |x: R, a: usize| {
            let offset = offsets.get(a).copied().unwrap_or(R::ZERO);
            x.wrapping_mul(scale)
                .finite_or_zero()
                .saturating_add(offset)
        };
        (scale, map)
    }

    /// The value from the weighted sum of the bands, and for the uniform distribution the
    /// derivative of its remapping (which the gradient is multiplied by).
    #[inline]
    fn finish<R: Real>(&self, sum: R) -> (R, Option<R>) {
        match self.distribution {
            Distribution::Gaussian => (sum.canonical(), None),
            Distribution::Uniform => {
                let c = R::from_f32(core::f32::consts::FRAC_1_SQRT_2);
                let (u, du) = erf_with_derivative(sum.mul_rn(c));
                (u.canonical(), Some(du.mul_rn(c)))
            }
        }
    }

    /// Infinite noise (§5.4): the band weights follow the sample's footprint, so zooming in
    /// or out keeps the look of the noise, coarse bands fading out as fine ones fade in.
    ///
    /// The bands are read relative to a footprint of 1: with a footprint of `2^L` noise units
    /// per pixel, the band `k` places after [`Bands::first`] sits at absolute band
    /// `first + k − L`, and for fractional `L` each absolute band takes the weight interpolated
    /// linearly between its two neighbours in the list (the list's ends fade to 0 one band
    /// beyond them). The weights are normalised at every footprint, so the variance is 1 at
    /// every zoom and changes with `L` continuously: there is no jump as bands fade.
    ///
    /// # Contract
    ///
    /// Never panics; coordinates as [`sample`](Noise::sample). A footprint that is zero,
    /// negative or not finite counts as 1 (the bands as listed). Absolute bands outside
    /// `[−40, 29]` (footprints beyond about 2⁻²⁹ or 2⁴⁰ for the default bands) are left out,
    /// and with none left the result is 0. The result is within
    /// [`infinite_bound`](Self::infinite_bound) (within `[-1, 1]` for
    /// [`Distribution::Uniform`]).
    ///
    /// # Examples
    ///
    /// ```
    /// use bandnoise::{Noise, wavelet::{Multiband, TILE2}};
    ///
    /// let m = Multiband::new(0, &TILE2, Default::default(), Default::default());
    /// let p = [0.3f32, 4.1];
    /// // A footprint of 1: the bands as listed (the same weights, normalised per sample).
    /// assert!((m.sample_infinite(p, 1.0) - m.sample(p)).abs() < 1e-5);
    /// // Zoomed in 1000 times: as much detail per pixel, at a thousandth of the scale.
    /// let v = m.sample_infinite(p, 1e-3);
    /// assert!(v.abs() <= m.infinite_bound::<2>());
    /// ```
    pub fn sample_infinite<R: Real, const D: usize>(&self, p: [R; D], footprint: R) -> R
    where
        T: TileData<D>,
        Wavelet<'t, T>: Noise<R, D>,
    {
        let which = D - 2;
        let f = footprint.to_f32();
        let l = if f > 0.0 && f.is_finite() {
            libm::log2f(f)
        } else {
            0.0
        };
        // The list's weights, 0 one place beyond each end.
        let listed = |k: i32| -> f32 {
            usize::try_from(k)
                .ok()
                .and_then(|k| self.scaled.get(k))
                .map_or(0.0, |w| w[which])
        };
        // Absolute band b is at place x = b − first + L of the list.
        let first = self.bands.first;
        let count = self.scaled.len() as i32;
        let x0 = libm::floorf(l);
        let t = l - x0;
        let mut weights: Vec<(i32, f32), { MAX_BANDS + 1 }> = Vec::new();
        let mut largest = 0.0f32;
        // Places k + t for k in −1..count: absolute bands first + k − x0.
        for k in -1..count {
            let w = (1.0 - t) * listed(k) + t * listed(k + 1);
            let band = (first + k) as i64 - x0 as i64;
            if w != 0.0 && (-40..=29).contains(&band) {
                largest = largest.max(w.abs());
                // Cannot fail: at most MAX_BANDS + 1 places.
                let _ = weights.push((band as i32, w));
            }
        }
        if largest <= 0.0 {
            return R::ZERO; // no band: 0 in either distribution
        }
        // Σ w² relative to the largest weight (at least 1, so the ratio cannot overflow even
        // where only tiny weights are left; the listed weights' Σ w² is 1/σ², about 4).
        let ss: f32 = weights
            .iter()
            .map(|(_, w)| (w / largest) * (w / largest))
            .sum();
        let listed_ss: f32 = (0..count).map(|k| listed(k) * listed(k)).sum();
        let norm = libm::sqrtf(listed_ss / ss);
        let bands = weights.iter().map(|&(b, w)| (b, w / largest * norm));
        self.sum_weighted(p, bands, |_, q| (self.band.sample(q), [R::ZERO; D]))
            .0
    }

    /// A bound on `|sample_infinite|` in `D` dimensions: the weights at any footprint have the
    /// listed weights' sum of squares over at most one band more, so their sum of magnitudes is
    /// at most `√((n + 1) Σ w²)` (Cauchy–Schwarz), times the largest coefficient. 1 for
    /// [`Distribution::Uniform`].
    #[must_use]
    pub fn infinite_bound<const D: usize>(&self) -> f32
    where
        T: TileData<D>,
    {
        match self.distribution {
            Distribution::Uniform => 1.0,
            Distribution::Gaussian => {
                let which = D - 2;
                let ss: f32 = self.scaled.iter().map(|w| w[which] * w[which]).sum();
                let n = (self.scaled.len() + 1) as f32;
                libm::sqrtf(n * ss) * self.band.coefficient_bound::<D>() * (1.0 + 1e-4)
                    + crate::lattice::ROUNDING
            }
        }
    }

    /// The bound for a sum with the scaled weights of `which`.
    fn bound(&self, which: usize, max_abs: f32) -> f32 {
        match self.distribution {
            Distribution::Uniform => 1.0,
            Distribution::Gaussian => {
                let s: f32 = self.scaled.iter().map(|w| w[which].abs()).sum();
                s * max_abs * (1.0 + 1e-5) + crate::lattice::ROUNDING
            }
        }
    }
}

impl<T: TileData<3>> Multiband<'_, T> {
    /// A bound on `|sample_projected|`. The projected basis weights sum to 2 for an axis-aligned
    /// normal and stay below 3 for any normal (measured in `tests/tests/wavelet.rs`), and the
    /// normal's [`projected_gain`](super::projected_gain) is at most 0.822, so this is
    /// `3 · 0.822 · max |n_c|` per unit of normalised weight.
    #[must_use]
    pub fn projected_bound(&self) -> f32 {
        self.bound(2, 3.0 * GAIN_MAX * self.band.coefficient_bound::<3>())
    }
}

impl<R: Real, T: TileData<3>> ProjectedNoise<R> for Multiband<'_, T> {
    /// Multiband noise projected onto the surface through `p` with normal `normal` (§3.7): each
    /// band is [`Wavelet::sample_projected`](ProjectedNoise::sample_projected), normalised with
    /// the tile's variance and the normal's [`projected_gain`](super::projected_gain), so the
    /// variance is 1 whatever the normal.
    ///
    /// # Contract
    ///
    /// Never panics; coordinates as [`sample`](Noise::sample) (a NaN or ±∞ coordinate is 0),
    /// normals as [`unit_normal`](super::unit_normal). The result is finite and within
    /// [`projected_bound`](Multiband::projected_bound) (within `[-1, 1]` for
    /// [`Distribution::Uniform`]); 0 when every band weight is 0.
    #[inline]
    fn sample_projected(&self, p: [R; 3], normal: [R; 3]) -> R {
        let n = super::projected::unit_normal(normal);
        // Each band times the normal's gain, so the sum's variance is 1 for this normal.
        let gain = super::projected::gain_unit(n);
        self.sum(p, 2, |q| self.band.sample_projected_unit(q, n).mul_rn(gain))
    }

    fn projected_bound(&self) -> f32 {
        Multiband::projected_bound(self)
    }

    /// Multiband noise over `grid` along one normal, bit for bit as
    /// [`sample_projected`](ProjectedNoise::sample_projected) at each point: the normal and
    /// its gain are computed once, and each band samples 16 points of a row at a time
    /// (along an axis-aligned normal sharing the row's work, `projected/rows.rs`), summed
    /// lane by lane in the points' order.
    fn fill_grid_projected(
        &self,
        grid: &Grid<R, 3>,
        normal: [R; 3],
        out: &mut [R],
    ) -> Result<(), Error> {
        let n = super::projected::unit_normal(normal);
        let gain = super::projected::gain_unit(n);
        let first = self.bands.first;
        crate::batch::for_each_row(grid, out, |start, row_out| {
            for (c, chunk) in row_out.chunks_mut(LANES).enumerate() {
                let xs = grid.lanes(0, c * LANES);
                let mut sum = [R::ZERO; LANES];
                for (i, w) in self.scaled.iter().enumerate() {
                    // The points' sum (`sum_weighted`): bands of weight 0 left out.
                    let (band, w) = (first + i as i32, w[2]);
                    if w == 0.0 {
                        continue;
                    }
                    let (_, to_band) = self.band_map::<R, 3>(band);
                    let q = xs.map(|x| to_band(x, 0));
                    let mut v = [R::ZERO; LANES];
                    let row = [to_band(start[1], 1), to_band(start[2], 2)];
                    self.band.projected_row(&q, row, n, &mut v);
                    let weight = R::from_f32(w);
                    for (sum, v) in sum.iter_mut().zip(v) {
                        *sum = sum.saturating_add(weight.mul_rn(v.mul_rn(gain)));
                    }
                }
                crate::batch::store_lanes(chunk, &sum.map(|s| self.finish(s).0));
            }
        })
    }
}

/// The analytic gradient of projected multiband noise: each projected band's gradient (scaled
/// by the normal's gain), combined as for [`NoiseGradient`](crate::NoiseGradient).
impl<R: Real, T: TileData<3>> crate::ProjectedNoiseGradient<R> for Multiband<'_, T> {
    #[inline]
    fn sample_projected_with_gradient(&self, p: [R; 3], normal: [R; 3]) -> (R, [R; 3]) {
        let n = super::projected::unit_normal(normal);
        let gain = super::projected::gain_unit(n);
        self.sum_with_gradient(p, 2, |_, q| {
            let (v, g) = self.band.sample_projected_unit_with_gradient(q, n);
            (v.mul_rn(gain), g.map(|x| x.mul_rn(gain)))
        })
    }
}

crate::noise::inherent_amplitude_bound!(Multiband<'_, T>, [T]);

/// The analytic gradient: the bands' gradients, each times its frequency `2^(b+1)`, and for
/// [`Distribution::Uniform`] times the derivative of the interpolated `erf` that maps the sum.
impl<R: Real, T: TileData<D>, const D: usize> crate::NoiseGradient<R, D> for Multiband<'_, T> {
    #[inline]
    fn sample_with_gradient(&self, p: [R; D]) -> (R, [R; D]) {
        self.sum_with_gradient(p, D - 2, |_, q| {
            crate::NoiseGradient::<R, D>::sample_with_gradient(&self.band, q)
        })
    }
}

/// Multiband noise filtered by a sample's footprint (§3.1, §4.1): each band averaged over the
/// footprint's box in its own coefficients ([`Wavelet`](super::Wavelet)'s
/// [`FilteredNoise`](crate::FilteredNoise)).
impl<R: Real, T: TileData<D>, const D: usize> crate::FilteredNoise<R, D> for Multiband<'_, T> {
    /// Multiband noise as a pixel whose footprint is spanned by `dpdx` and `dpdy` sees it:
    /// band `b` samples `2^(b+1)·p`, so it has `2^(b+1)` times the footprint's width in
    /// coefficients per pixel. Bands with at most ¼ are sampled as they are, wider ones are
    /// averaged over the footprint's box through a widened basis, and bands with 3 to 4 or
    /// more coefficients per pixel (whose box average has less than 4% of their variance left)
    /// fade out. The weights stay those of [`sample`](Noise::sample), so the filtered value has
    /// the smaller variance a filtered pixel has.
    ///
    /// # Contract
    ///
    /// As [`sample`](Noise::sample) for `p`; a zero or NaN footprint gives `sample(p)`, bit for
    /// bit; an infinite one 0; never panics, and the result is within
    /// [`amplitude_bound`](Noise::amplitude_bound).
    ///
    /// # Examples
    ///
    /// ```
    /// use bandnoise::{FilteredNoise, Noise, wavelet::{Multiband, TILE2}};
    ///
    /// let m = Multiband::new(0, &TILE2, Default::default(), Default::default());
    /// let p = [0.3f32, 4.1];
    /// assert_eq!(m.sample_filtered(p, [0.0, 0.0], [0.0, 0.0]), m.sample(p));
    /// // A pixel 1/8 wide: bands 0–4 (sampled at 2p to 32p) have 1/4 to 4 coefficients in it.
    /// let pixel = 1.0 / 8.0;
    /// let v = m.sample_filtered(p, [pixel, 0.0], [0.0, pixel]);
    /// assert!(v.abs() <= Noise::<f32, 2>::amplitude_bound(&m));
    /// ```
    fn sample_filtered(&self, p: [R; D], dpdx: [R; D], dpdy: [R; D]) -> R {
        let widths = super::filtered::footprint_widths(&dpdx, &dpdy);
        self.sum_with_gradient(p, D - 2, |band, q| {
            // 2^(band + 1), exactly: band + 1 is in [−23, 25], a normal f32's exponent.
            let scale = f32::from_bits(((band + 1 + 127) as u32) << 23);
            let v = self.band.sample_boxed(q, widths.map(|w| w * scale));
            (v, [R::ZERO; D])
        })
        .0
    }
}

impl<R: Real, T: TileData<D>, const D: usize> Noise<R, D> for Multiband<'_, T> {
    #[inline]
    fn sample(&self, p: [R; D]) -> R {
        self.sum(p, D - 2, |q| self.band.sample(q))
    }

    /// Row by row, band by band: each band's row through the band's row kernel (its shared
    /// coefficients fetched once), its weighted value added to the row in `sample`'s order,
    /// then each value finished as `sample` does.
    fn fill_grid(&self, grid: &Grid<R, D>, out: &mut [R]) -> Result<(), Error> {
        let first = self.bands.first;
        for_each_rows::<R, D, GROUP>(grid, out, |starts, values| {
            values.fill(R::ZERO);
            for (i, w) in self.scaled.iter().enumerate() {
                let (band, w) = (first + i as i32, w[D - 2]);
                if w == 0.0 {
                    continue;
                }
                let (_, to_band) = self.band_map::<R, D>(band);
                let weight = R::from_f32(w);
                let mut rests = [[R::ZERO; D]; GROUP];
                for (rest, start) in rests.iter_mut().zip(starts) {
                    *rest = core::array::from_fn(|a| to_band(start[a], a));
                }
                self.band.fill_rows(
                    rests.get(..starts.len()).unwrap_or_default(),
                    |first| grid.lanes(0, first).map(|x| to_band(x, 0)),
                    values,
                    |sum, v| *sum = sum.saturating_add(weight.mul_rn(v)),
                );
            }
            for v in values.iter_mut() {
                *v = self.finish(*v).0;
            }
        })
    }

    /// Uniform: 1. Gaussian: `Σ_b |w'_b| · max |n_c|` (each band is bounded by the largest
    /// coefficient, blended ones included).
    fn amplitude_bound(&self) -> f32 {
        self.bound(D - 2, self.band.coefficient_bound::<D>())
    }
}

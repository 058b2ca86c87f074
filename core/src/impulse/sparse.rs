//! Lewis's sparse convolution noise (Lewis 1989, §4): `η(x) = Σ_k a_k h(x − ξ_k)`, random
//! impulses of uncorrelated weights `a_k` at the points `ξ_k` of a Poisson process,
//! convolved with a kernel `h`.
//!
//! The impulses are white noise, so the noise's power spectrum is the kernel's, `|H(f)|²`
//! scaled (§4: `S_y = S_x |H|²` with `S_x` constant): the kernel is the spectral control.
//! Density trades quality for speed: below one impulse per kernel volume the noise is
//! "lumpy"; at ten and above it is "usually not distinguishable" from convolved white noise
//! (measured here by the distance of its amplitudes to a Gaussian). The walk over cells and
//! impulses is the [module's](super); cells are the kernel's radius wide.
//!
//! The variance is not measured but follows from Campbell's theorem for shot noise,
//! `Var η = λ E[a²] ∫h²` (λ impulses per unit volume), and the noise is divided by its square
//! root, so it has variance 1 and mean 0 (the weights have mean 0) at every density.

use super::kernel::Kernel;
use super::{Impulses, NO_PARAMS, Weights, walk, walk_lanes};
use crate::batch::{self, LANES};
use crate::hash::CellHash;
use crate::radial::ball_volume;
use crate::{Error, I16F16, Noise, NoiseGradient, Real};

/// Lewis's sparse convolution noise in `D` dimensions (1 to 4).
///
/// The kernel's radius is one unit: sample at `x · f` for features `1/f` units wide. The
/// default is Lewis's cosine kernel at 10 impulses per kernel volume with Poisson counts and
/// ±1 weights (closer to Gaussian than uniform weights: see [`Weights`]); the builders change
/// each (a smaller density is faster: `bench/README.md`).
///
/// # Amplitude
///
/// Variance 1 and mean 0 (Campbell's theorem, see the module docs; tested over 10⁶
/// samples). Each of the `3^D` cells holds at most [`Impulses::cap`] impulses of weight at
/// most 1 and the kernels are at most 1, so `|η| ≤ 3^D · cap / σ`
/// ([`amplitude_bound`](Noise::amplitude_bound)): a proved bound, far above what occurs.
///
/// # Examples
///
/// ```
/// use bandnoise::{Error, I16F16, Noise, impulse::{Kernel, SparseConvolution}};
///
/// let lewis = SparseConvolution::<3>::new(7);
/// let v: f32 = lewis.sample([0.5, 1.25, -2.0]);
/// assert!(v.abs() <= lewis.amplitude_bound());
///
/// // Peachey's kernel, sparser (faster, lumpier), in fixed point.
/// let peachey = SparseConvolution::<2>::new(7)
///     .with_kernel(Kernel::CatmullRom)
///     .with_density(3.0)?;
/// let q: I16F16 = peachey.sample([I16F16::from_num(0.5), I16F16::from_num(1.25)]);
/// assert!((q.to_num::<f32>() - peachey.sample([0.5f32, 1.25])).abs() < 1e-3);
/// # Ok::<(), Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct SparseConvolution<const D: usize> {
    hash: CellHash,
    kernel: Kernel,
    impulses: Impulses,
    /// `1/σ`, in floats and in fixed point.
    scale: f32,
    scale_fixed: I16F16,
}

impl<const D: usize> SparseConvolution<D> {
    /// The default density: impulses per kernel volume ([`super::DEFAULT_DENSITY`]).
    pub const DEFAULT_DENSITY: f32 = super::DEFAULT_DENSITY;
    /// The smallest density ([`super::MIN_DENSITY`]).
    pub const MIN_DENSITY: f32 = super::MIN_DENSITY;

    /// The noise for `seed`: Lewis's cosine kernel, [`DEFAULT_DENSITY`](Self::DEFAULT_DENSITY),
    /// Poisson counts, ±1 weights.
    #[must_use]
    pub fn new(seed: u32) -> Self {
        const {
            assert!(
                D >= 1 && D <= 4,
                "sparse convolution noise has 1 to 4 dimensions"
            )
        };
        Self::build(
            CellHash::new(seed),
            Kernel::Cosine,
            Impulses::poisson_checked(Self::per_cell(Self::DEFAULT_DENSITY), Weights::default()),
        )
    }

    fn build(hash: CellHash, kernel: Kernel, impulses: Impulses) -> Self {
        let sigma = libm::sqrt(impulses.variance(kernel.power_of(D)));
        let scale = (1.0 / sigma) as f32;
        Self {
            hash,
            kernel,
            impulses,
            scale,
            scale_fixed: I16F16::from_f32(scale),
        }
    }

    /// The mean count per cell (of volume 1) for `density` impulses per kernel volume.
    fn per_cell(density: f32) -> f32 {
        (density as f64 / ball_volume(D)) as f32
    }

    /// The largest density in `D` dimensions: 32 impulses per cell on average (the most a
    /// [`Poisson`](crate::hash::Poisson) count is tabulated for), `32 / V_D` per kernel
    /// volume (`V_D`: the unit ball's volume; 100.5 in 2D, 134 in 3D).
    #[must_use]
    pub fn max_density() -> f32 {
        (32.0 * ball_volume(D)) as f32
    }

    /// The same noise with `density` impulses per kernel volume on average (Poisson counts
    /// per cell, mean `density / V_D`), keeping the weights.
    ///
    /// # Errors
    ///
    /// [`Error::Density`] unless `density` is finite and in
    /// `[MIN_DENSITY, max_density()]`.
    pub fn with_density(self, density: f32) -> Result<Self, Error> {
        let max = Self::max_density();
        if !(Self::MIN_DENSITY..=max).contains(&density) {
            return Err(Error::Density {
                density,
                min: Self::MIN_DENSITY,
                max,
            });
        }
        let weights = self.impulses.weights();
        Ok(Self::build(
            self.hash,
            self.kernel,
            Impulses::poisson_checked(Self::per_cell(density), weights),
        ))
    }

    /// The same noise with exactly `per_cell` impulses in every cell (Tavernier et al. 2019's
    /// stratified process: no count to draw, the same variance), keeping the weights; its
    /// density is `per_cell · V_D` per kernel volume.
    ///
    /// # Errors
    ///
    /// [`Error::ImpulseCount`] unless `1 ≤ per_cell ≤` [`MAX_FIXED`](super::MAX_FIXED).
    pub fn with_fixed_count(self, per_cell: u32) -> Result<Self, Error> {
        let weights = self.impulses.weights();
        let impulses = Impulses::fixed(per_cell)?.with_weights(weights);
        Ok(Self::build(self.hash, self.kernel, impulses))
    }

    /// The same noise with impulse weights drawn as `weights` says.
    #[must_use]
    pub fn with_weights(self, weights: Weights) -> Self {
        Self::build(self.hash, self.kernel, self.impulses.with_weights(weights))
    }

    /// The same noise with another kernel.
    #[must_use]
    pub fn with_kernel(self, kernel: Kernel) -> Self {
        Self::build(self.hash, kernel, self.impulses)
    }

    /// The kernel.
    #[must_use]
    pub fn kernel(&self) -> Kernel {
        self.kernel
    }

    /// The impulses per cell.
    #[must_use]
    pub fn impulses(&self) -> &Impulses {
        &self.impulses
    }

    /// The mean number of impulses per kernel volume.
    #[must_use]
    pub fn density(&self) -> f32 {
        (self.impulses.per_cell() as f64 * ball_volume(D)) as f32
    }

    /// The bound on `|sample(p)|` in every number type (see [Amplitude](Self#amplitude)).
    #[must_use]
    pub fn amplitude_bound(&self) -> f32 {
        let cells = 3u32.pow(D as u32) as f64;
        // A little above: the roundings of the sum and of the fixed-point scale.
        (cells * self.impulses.cap() as f64 * self.scale as f64 * (1.0 + 1e-4)) as f32
    }

    /// The standard deviation of the unscaled sum, `√(λ E[w²] ∫h²)` (Campbell's theorem),
    /// which the noise divides by.
    #[must_use]
    pub fn sigma(&self) -> f64 {
        libm::sqrt(self.impulses.variance(self.kernel.power_of(D)))
    }
}

impl<R: Real, const D: usize> Noise<R, D> for SparseConvolution<D> {
    #[inline]
    fn sample(&self, p: [R; D]) -> R {
        let kernel = self.kernel;
        let mut total = R::ZERO;
        walk(
            &self.hash,
            &self.impulses,
            p,
            NO_PARAMS,
            &(),
            |_, d2, w, _, _| {
                total = total + w.mul_rn(kernel.at(d2));
            },
        );
        total
            .mul_rn(R::from_setting(self.scale, self.scale_fixed))
            .canonical()
    }

    fn amplitude_bound(&self) -> f32 {
        SparseConvolution::amplitude_bound(self)
    }

    /// Lanes near each other (a grid's chunk) share the walk: each cell's impulses are
    /// generated once for all of them (the module's shared walk); scattered lanes are walked one by
    /// one. Bit-identical to [`sample`](Noise::sample) either way.
    fn sample_lanes(&self, p: &[[R; LANES]; D], out: &mut [R; LANES]) {
        let kernel = self.kernel;
        let mut totals = [R::ZERO; LANES];
        let shared = walk_lanes(
            &self.hash,
            &self.impulses,
            p,
            NO_PARAMS,
            &(),
            |l, _, d2, w, _, _| {
                if let Some(t) = totals.get_mut(l) {
                    *t = *t + w.mul_rn(kernel.at(d2));
                }
            },
        );
        if shared {
            let scale = R::from_setting(self.scale, self.scale_fixed);
            for (o, t) in out.iter_mut().zip(totals) {
                *o = t.mul_rn(scale).canonical();
            }
        } else {
            for (l, o) in out.iter_mut().enumerate() {
                *o = self.sample(batch::lane(p, l));
            }
        }
    }
}

/// The analytic gradient: `∇η = Σ_k a_k · 2(x − ξ_k) · dh/d(d²)`, from the kernel's table
/// ([`Kernel::at_with_slope`]); the value is [`sample`](Noise::sample)'s bit for bit. Each
/// term is at most `2 · 2 · 10` in magnitude, so `|∇η| ≤ 40 · 3^D · cap / σ` per axis.
impl<R: Real, const D: usize> NoiseGradient<R, D> for SparseConvolution<D> {
    fn sample_with_gradient(&self, p: [R; D]) -> (R, [R; D]) {
        let kernel = self.kernel;
        let mut total = R::ZERO;
        let mut gradient = [R::ZERO; D];
        walk(
            &self.hash,
            &self.impulses,
            p,
            NO_PARAMS,
            &(),
            |delta, d2, w, _, _| {
                let (h, slope) = kernel.at_with_slope(d2);
                total = total + w.mul_rn(h);
                let ws = w.mul_rn(slope);
                for (g, d) in gradient.iter_mut().zip(delta) {
                    *g = g.saturating_add((ws + ws).mul_rn(d));
                }
            },
        );
        let scale = R::from_setting(self.scale, self.scale_fixed);
        (
            total.mul_rn(scale).canonical(),
            gradient.map(|g| g.saturating_mul(scale).canonical()),
        )
    }
}

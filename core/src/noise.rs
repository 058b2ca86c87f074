//! The sampling traits every noise implements.

use crate::Real;

/// A scalar noise over `D`-dimensional space in the number type `R`.
///
/// Every noise in bandnoise implements it for `D` in `1..=4` and for `f32`, `f64` and
/// [`I16F16`](crate::I16F16), so fractal sums, textures and tests are written once over any noise
/// and any number type.
///
/// # Contract
///
/// `sample` never panics and returns a value for every input:
/// * a coordinate component that is NaN or ±∞ is treated as 0 (see [`Real::split`]);
/// * a coordinate whose cell lies outside `i32` has its cell wrapped modulo 2³²;
/// * the result is never NaN and satisfies `|v| ≤ amplitude_bound()`;
/// * the result is never `-0.0` (zeros are `+0.0`), so equal values are equal bit for bit.
///
/// # Examples
///
/// ```
/// use bandnoise::{Noise, lattice::Perlin};
///
/// let perlin = Perlin::new(0);
/// assert_eq!(perlin.sample([3.14f64, 42.0, 7.0]), 0.13691995878400012); // Perlin's reference
/// let v: f32 = perlin.sample([0.5, 0.25]);
/// assert!(v.abs() <= Noise::<f32, 2>::amplitude_bound(&perlin));
/// ```
pub trait Noise<R: Real, const D: usize> {
    /// The noise at `p`.
    #[must_use]
    fn sample(&self, p: [R; D]) -> R;

    /// An upper bound on `|sample(p)|` over all `p` in `D` dimensions, proved in the docs of
    /// each noise (so that fuzzers, tests and normalisations can rely on it).
    #[must_use]
    fn amplitude_bound(&self) -> f32;
}

/// A noise that also gives its analytic gradient.
///
/// # Examples
///
/// ```
/// use bandnoise::{NoiseGradient, lattice::MNoise};
///
/// let (v, g) = MNoise::<61>::new(3).sample_with_gradient([0.3f32, 1.7]);
/// assert!(v.is_finite() && g.iter().all(|d| d.is_finite()));
/// ```
pub trait NoiseGradient<R: Real, const D: usize>: Noise<R, D> {
    /// The value at `p` (bit-identical to [`Noise::sample`]) and `∂noise/∂p`.
    ///
    /// # Contract
    ///
    /// As [`Noise::sample`] for the value; the gradient is finite for every input (a
    /// non-finite coordinate is 0, where the gradient is that of the origin) and never panics.
    #[must_use]
    fn sample_with_gradient(&self, p: [R; D]) -> (R, [R; D]);
}

impl<R: Real, const D: usize, N: Noise<R, D> + ?Sized> Noise<R, D> for &N {
    #[inline]
    fn sample(&self, p: [R; D]) -> R {
        (**self).sample(p)
    }
    fn amplitude_bound(&self) -> f32 {
        (**self).amplitude_bound()
    }
}

impl<R: Real, const D: usize, N: NoiseGradient<R, D> + ?Sized> NoiseGradient<R, D> for &N {
    #[inline]
    fn sample_with_gradient(&self, p: [R; D]) -> (R, [R; D]) {
        (**self).sample_with_gradient(p)
    }
}

//! The sampling traits every noise implements.

use crate::batch::{self, Grid, LANES};
use crate::{Error, Real};

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
/// assert!(v.abs() <= perlin.amplitude_bound::<2>());
/// ```
pub trait Noise<R: Real, const D: usize> {
    /// The noise at `p`.
    #[must_use]
    fn sample(&self, p: [R; D]) -> R;

    /// An upper bound on `|sample(p)|` over all `p` in `D` dimensions, proved in the docs of
    /// each noise (so that fuzzers, tests and normalisations can rely on it).
    #[must_use]
    fn amplitude_bound(&self) -> f32;

    /// Samples [`LANES`] points at once, given as structure of arrays: lane `l` is the point
    /// `[p[0][l], p[1][l], …]`, its value goes to `out[l]`. Bit-identical to
    /// [`sample`](Self::sample) lane by lane, with the same contract.
    ///
    /// The default evaluates lane by lane; the lattice noises and fractal sums override it with
    /// kernels the compiler vectorises (see [`batch`](crate::batch)). Most code calls
    /// [`fill_grid`](Self::fill_grid) or [`fill_points`](Self::fill_points) instead.
    #[inline]
    fn sample_lanes(&self, p: &[[R; LANES]; D], out: &mut [R; LANES]) {
        for (l, o) in out.iter_mut().enumerate() {
            *o = self.sample(batch::lane(p, l));
        }
    }

    /// Fills `out` with the noise over `grid`, row-major with axis 0 fastest: point
    /// `[i, j, k]` goes to `out[i + size[0]·(j + size[1]·k)]`. Each value is bit-identical to
    /// `self.sample(grid.point([i, j, k]))`.
    ///
    /// # Errors
    ///
    /// [`Error::BufferLength`] unless `out.len() == grid.len()`; `out` is then left untouched.
    ///
    /// # Examples
    ///
    /// ```
    /// use bandnoise::{Noise, batch::Grid, lattice::MNoise};
    ///
    /// let m = MNoise::<61>::new(3);
    /// let grid = Grid::new([0.0f32, 0.0], [0.1, 0.1], [100, 10]);
    /// let mut out = [0.0f32; 1000];
    /// m.fill_grid(&grid, &mut out)?;
    /// assert_eq!(out[2 * 100 + 7], m.sample(grid.point([7, 2])));
    /// # Ok::<(), bandnoise::Error>(())
    /// ```
    fn fill_grid(&self, grid: &Grid<R, D>, out: &mut [R]) -> Result<(), Error> {
        batch::fill_grid(self, grid, out)
    }

    /// Fills `out[i]` with the noise at `[points[0][i], points[1][i], …]` (one slice per axis,
    /// structure of arrays), each value bit-identical to [`sample`](Self::sample) there.
    ///
    /// # Errors
    ///
    /// [`Error::BufferLength`] unless every slice of `points` has `out.len()` elements.
    ///
    /// # Examples
    ///
    /// ```
    /// use bandnoise::{Noise, lattice::Perlin};
    ///
    /// let xs = [0.5f32, 1.25, -3.0];
    /// let ys = [0.1f32, 7.5, 2.0];
    /// let mut out = [0.0f32; 3];
    /// Perlin::new(0).fill_points([&xs, &ys], &mut out)?;
    /// assert_eq!(out[1], Perlin::new(0).sample([1.25, 7.5]));
    /// # Ok::<(), bandnoise::Error>(())
    /// ```
    fn fill_points(&self, points: [&[R]; D], out: &mut [R]) -> Result<(), Error> {
        batch::fill_points(self, points, out)
    }
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

/// A noise that anti-aliases itself from a sample's footprint (pbrt §10.6.3): the detail
/// finer than the footprint, which a pixel cannot show without aliasing, is left out.
///
/// Implemented by [`Fractal`](crate::fractal::Fractal) (pbrt's octave clamping), and by
/// [`Wavelet`](crate::wavelet::Wavelet) and [`Multiband`](crate::wavelet::Multiband) (each band
/// averaged over the footprint's box, Cook & DeRose §4.1).
///
/// # Examples
///
/// ```
/// use bandnoise::{FilteredNoise, Noise, fractal::{Fractal, Octaves}, lattice::Perlin};
///
/// fn pixel<N: FilteredNoise<f32, 2>>(noise: &N, p: [f32; 2], pixel_size: f32) -> f32 {
///     noise.sample_filtered(p, [pixel_size, 0.0], [0.0, pixel_size])
/// }
/// let fbm = Fractal::fbm(Perlin::new(0), Octaves::default());
/// assert_eq!(pixel(&fbm, [0.3, 0.7], 0.0), fbm.sample([0.3, 0.7])); // no footprint: every octave
/// ```
pub trait FilteredNoise<R: Real, const D: usize>: Noise<R, D> {
    /// The noise at `p` for a sample whose footprint in noise space is spanned by `dpdx` and
    /// `dpdy` (the change of `p` from one pixel to the next).
    ///
    /// # Contract
    ///
    /// As [`Noise::sample`] for `p`; any footprint (NaN, ±∞, huge) gives a value, never a
    /// panic, and the footprint is symmetric in `dpdx` and `dpdy`.
    #[must_use]
    fn sample_filtered(&self, p: [R; D], dpdx: [R; D], dpdy: [R; D]) -> R;
}

/// A 3D noise that can be projected onto a surface (Cook & DeRose 2005, §3.7): integrated along
/// the surface normal, so that the noise on the surface keeps its band limit, where a slice
/// through 3D noise would not.
///
/// Implemented by [`Wavelet`](crate::wavelet::Wavelet) and
/// [`Multiband`](crate::wavelet::Multiband) over 3D tiles.
///
/// # Examples
///
/// ```
/// use bandnoise::{ProjectedNoise, wavelet::{TILE3, Wavelet}};
///
/// fn on_sphere<N: ProjectedNoise<f32>>(noise: &N, p: [f32; 3]) -> f32 {
///     noise.sample_projected(p, p) // the normal of a sphere at the origin points along p
/// }
/// let band = Wavelet::new(0, &TILE3);
/// assert!(on_sphere(&band, [0.0, 0.6, 0.8]).abs() <= band.projected_bound());
/// ```
pub trait ProjectedNoise<R: Real>: Noise<R, 3> {
    /// The noise projected onto the surface through `p` with normal `normal` (any finite
    /// non-zero length; see [`unit_normal`](crate::wavelet::unit_normal)).
    ///
    /// # Contract
    ///
    /// As [`Noise::sample`] for `p`; any normal gives a value, never a panic; the result is
    /// within [`projected_bound`](Self::projected_bound).
    #[must_use]
    fn sample_projected(&self, p: [R; 3], normal: [R; 3]) -> R;

    /// A bound on `|sample_projected|`.
    #[must_use]
    fn projected_bound(&self) -> f32;

    /// Fills `out` with the noise projected along one `normal` at every point of `grid`
    /// (row-major, axis 0 fastest, as [`Noise::fill_grid`]): a plane or volume of
    /// surface noise whose surface normal is the same everywhere, such as a flat patch of
    /// terrain or a wall.
    ///
    /// The values are [`sample_projected`](Self::sample_projected)`(grid.point(i), normal)`,
    /// bit for bit. The provided method samples point by point; wavelet noise (a band, and
    /// each band of multiband noise) shares the work of a grid row along an axis-aligned
    /// normal (several times faster: `bench/README.md`).
    ///
    /// # Errors
    ///
    /// [`Error::BufferLength`] if `out.len()` is not `grid.len()`.
    ///
    /// # Examples
    ///
    /// ```
    /// use bandnoise::{ProjectedNoise, batch::Grid, wavelet::{TILE3, Wavelet}};
    ///
    /// let band = Wavelet::new(0, &TILE3);
    /// // 64 × 32 samples of the plane z = 0.37, projected along z.
    /// let grid = Grid::new([0.2f32, -1.5, 0.37], [0.0737, 0.0737, 0.0], [64, 32, 1]);
    /// let mut image = [0.0f32; 64 * 32];
    /// band.fill_grid_projected(&grid, [0.0, 0.0, 1.0], &mut image).unwrap();
    /// let p = grid.point([5, 3, 0]);
    /// assert_eq!(image[3 * 64 + 5], band.sample_projected(p, [0.0, 0.0, 1.0]));
    /// // A buffer of the wrong size is an error, not a panic.
    /// assert!(band.fill_grid_projected(&grid, [0.0, 0.0, 1.0], &mut image[..10]).is_err());
    /// ```
    fn fill_grid_projected(
        &self,
        grid: &Grid<R, 3>,
        normal: [R; 3],
        out: &mut [R],
    ) -> Result<(), Error> {
        batch::fill_grid_by(grid, out, |p| self.sample_projected(p, normal))
    }
}

/// A projected noise that also gives its analytic gradient.
///
/// Implemented by [`Wavelet`](crate::wavelet::Wavelet) and
/// [`Multiband`](crate::wavelet::Multiband) over 3D tiles.
///
/// # Examples
///
/// ```
/// use bandnoise::{ProjectedNoise, ProjectedNoiseGradient, wavelet::{TILE3, Wavelet}};
///
/// let band = Wavelet::new(0, &TILE3);
/// let (p, normal) = ([0.3f32, 1.6, -2.2], [0.0, 0.6, 0.8]);
/// let (v, g) = band.sample_projected_with_gradient(p, normal);
/// assert_eq!(v, band.sample_projected(p, normal));
/// assert!(g.iter().all(|d| d.is_finite()));
/// ```
pub trait ProjectedNoiseGradient<R: Real>: ProjectedNoise<R> {
    /// The projected value at `p` (bit-identical to
    /// [`ProjectedNoise::sample_projected`]) and its gradient `∂/∂p`, the normal held fixed.
    ///
    /// # Contract
    ///
    /// As [`ProjectedNoise::sample_projected`] for the value; the gradient is finite for every
    /// input (a non-finite coordinate is 0, where the gradient is that of the origin) and
    /// never panics.
    #[must_use]
    fn sample_projected_with_gradient(&self, p: [R; 3], normal: [R; 3]) -> (R, [R; 3]);
}

impl<R: Real, const D: usize, N: FilteredNoise<R, D> + ?Sized> FilteredNoise<R, D> for &N {
    #[inline]
    fn sample_filtered(&self, p: [R; D], dpdx: [R; D], dpdy: [R; D]) -> R {
        (**self).sample_filtered(p, dpdx, dpdy)
    }
}

impl<R: Real, N: ProjectedNoise<R> + ?Sized> ProjectedNoise<R> for &N {
    #[inline]
    fn sample_projected(&self, p: [R; 3], normal: [R; 3]) -> R {
        (**self).sample_projected(p, normal)
    }
    fn projected_bound(&self) -> f32 {
        (**self).projected_bound()
    }
    // Forwarded, so a call through a reference reaches the noise's own grid path.
    fn fill_grid_projected(
        &self,
        grid: &Grid<R, 3>,
        normal: [R; 3],
        out: &mut [R],
    ) -> Result<(), Error> {
        (**self).fill_grid_projected(grid, normal, out)
    }
}

impl<R: Real, N: ProjectedNoiseGradient<R> + ?Sized> ProjectedNoiseGradient<R> for &N {
    #[inline]
    fn sample_projected_with_gradient(&self, p: [R; 3], normal: [R; 3]) -> (R, [R; 3]) {
        (**self).sample_projected_with_gradient(p, normal)
    }
}

impl<R: Real, const D: usize, N: Noise<R, D> + ?Sized> Noise<R, D> for &N {
    #[inline]
    fn sample(&self, p: [R; D]) -> R {
        (**self).sample(p)
    }
    fn amplitude_bound(&self) -> f32 {
        (**self).amplitude_bound()
    }
    #[inline]
    fn sample_lanes(&self, p: &[[R; LANES]; D], out: &mut [R; LANES]) {
        (**self).sample_lanes(p, out);
    }
    // Forwarded, so a call through a reference reaches the noise's own grid kernel.
    fn fill_grid(&self, grid: &Grid<R, D>, out: &mut [R]) -> Result<(), Error> {
        (**self).fill_grid(grid, out)
    }
    fn fill_points(&self, points: [&[R]; D], out: &mut [R]) -> Result<(), Error> {
        (**self).fill_points(points, out)
    }
}

impl<R: Real, const D: usize, N: NoiseGradient<R, D> + ?Sized> NoiseGradient<R, D> for &N {
    #[inline]
    fn sample_with_gradient(&self, p: [R; D]) -> (R, [R; D]) {
        (**self).sample_with_gradient(p)
    }
}

/// Gives a noise type an inherent `amplitude_bound::<D>()`, so that concrete code asks for the
/// bound in `D` dimensions without naming the trait and a number type (the method-call form of
/// [`Noise::amplitude_bound`] cannot infer them).
macro_rules! inherent_amplitude_bound {
    ($ty:ty, [$($generics:tt)*]) => {
        impl<$($generics)*> $ty {
            /// [`Noise::amplitude_bound`](crate::Noise::amplitude_bound) in `D` dimensions:
            /// `noise.amplitude_bound::<3>()`. This is the `f32` bound; every noise of the crate
            /// has the same bound in every number type.
            #[must_use]
            pub fn amplitude_bound<const D: usize>(&self) -> f32
            where
                Self: crate::Noise<f32, D>,
            {
                crate::Noise::<f32, D>::amplitude_bound(self)
            }
        }
    };
}
pub(crate) use inherent_amplitude_bound;

//! Periodic lattice noise: any lattice noise with an integer period per axis, from 1 to 2¹⁶
//! cells, by wrapping each lattice coordinate before it is hashed (the `pnoise` of RenderMan
//! and OSL; Perlin 1985's noise is periodic with its table size the same way).
//!
//! Wrapping the cell, not the coordinate, keeps everything else as it is: the fraction, the
//! fade, the gradients, so the noise is the same function of the same kind (same spectrum,
//! same bounds, analytic gradients), and periodic bit for bit: `n(x + P·k) == n(x)` wherever
//! `x + P·k` is exact in the number type. A period longer than the hash's own (256 for the
//! permutation noises, `M` for mNoise) folds the wrapped coordinate digit by digit, so cells
//! within one period do not repeat with the hash's period.
//!
//! The peers make 2D noise tileable another way: noise-functions' `tileable` and FastNoise2's
//! `GenTileable2D` map the plane onto a torus in 4D (`x → (cos 2πx/W, sin 2πx/W)·r`) and sample
//! 4D noise. That works for any noise, but costs a 4D evaluation, exists only for 2D, bends
//! the sampled surface (the statistics are those of a curved slice through 4D noise, not of
//! the 2D noise) and has no analytic gradient. A lattice wrap costs a remainder per axis, works
//! in every dimension and for gradients and batches, but takes only integer periods in cells.

use super::Lattice;
use super::kernel::MAX_CORNERS;
use crate::Error;
use crate::hash::chain::Wrap;

/// A lattice noise that repeats with an integer period along each axis.
///
/// `Periodic::new(noise, [16, 8])` is `noise` with its lattice wrapped every 16 cells along x
/// and 8 along y: `sample([x + 16, y]) == sample([x, y + 8]) == sample([x, y])`, bit for bit in
/// fixed point and wherever the shifted coordinate is exact in a float. It works for every
/// lattice noise ([`Perlin`](super::Perlin), [`OriginalPerlin`](super::OriginalPerlin),
/// [`ValueNoise`](super::ValueNoise), [`CNoise`](super::CNoise), [`MNoise`](super::MNoise)), and for
/// [`WhiteNoise`](super::WhiteNoise) and [`CubicValueNoise`](super::CubicValueNoise) (each of the
/// 4ᴰ lattice points it interpolates wrapped), in point, gradient and batch sampling, with the
/// same bounds as the noise it wraps.
///
/// A period equal to the noise's own (256 cells for the permutation noises, `M` for
/// `MNoise<M>`) gives the noise itself, bit for bit. A longer period folds each wrapped
/// coordinate into the hash digit by digit, so the noise 256 cells on is as unrelated to the
/// noise here as the noise 100 cells on (`tests/tests/periodic.rs`), except with `MNoise<61>`: its
/// hash has only 61 states, so its blocks of 61 cells correlate (−0.12 at a period of 1000) and
/// at most 61 distinct blocks exist. Use `MNoise<4093>` for long periods. Fractal sums keep the period when every
/// octave's frequency is an integer: a lacunarity of 2 (or 3, …) does; pbrt's default 1.99 does
/// not (octave `i` then repeats every `P / 1.99^i`, not a divisor of `P`).
///
/// # Examples
///
/// ```
/// use bandnoise::{Noise, lattice::{Periodic, Perlin}};
///
/// let tile = Periodic::new(Perlin::new(3), [16, 8]).expect("periods in 1..=65536");
/// let v: f32 = tile.sample([2.25, 5.5]);
/// assert_eq!(v, tile.sample([2.25 + 16.0, 5.5 - 8.0]));
/// assert!(Periodic::new(Perlin::new(3), [0, 8]).is_err());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Periodic<N, const D: usize> {
    noise: N,
    wrap: Wrap<D>,
}

impl<N, const D: usize> Periodic<N, D> {
    /// The longest period, in cells.
    pub const MAX_PERIOD: u32 = 1 << 16;

    /// `noise` repeating every `period[a]` cells along axis `a`.
    ///
    /// # Errors
    ///
    /// [`Error::Period`] unless every period is in `1..=65536`.
    pub fn new(noise: N, period: [u32; D]) -> Result<Self, Error> {
        for (axis, &p) in period.iter().enumerate() {
            if !(1..=Self::MAX_PERIOD).contains(&p) {
                return Err(Error::Period { axis, period: p });
            }
        }
        Ok(Self {
            noise,
            wrap: Wrap::new(period),
        })
    }

    /// The period along each axis, in cells.
    #[must_use]
    pub fn period(&self) -> [u32; D] {
        self.wrap.period()
    }

    /// The noise that is wrapped.
    #[must_use]
    pub fn noise(&self) -> &N {
        &self.noise
    }

    /// The wrap of each lattice coordinate.
    pub(crate) fn wrap(&self) -> &Wrap<D> {
        &self.wrap
    }

    /// `noise` with these (validated) periods.
    pub(crate) fn with_noise<M>(&self, noise: M) -> Periodic<M, D> {
        Periodic {
            noise,
            wrap: self.wrap,
        }
    }
}

/// A lattice noise whose corners can be hashed with wrapped coordinates.
pub(crate) trait WrapCorners<const D: usize> {
    /// The hash of each corner of `cell`, every coordinate wrapped by `wrap` (as
    /// `corner_hashes`, which is this with the hash's own period).
    fn corner_hashes_wrapped(&self, cell: [i32; D], wrap: &Wrap<D>) -> [u32; MAX_CORNERS];
}

impl<L: WrapCorners<D>, const D: usize> WrapCorners<D> for &L {
    #[inline]
    fn corner_hashes_wrapped(&self, cell: [i32; D], wrap: &Wrap<D>) -> [u32; MAX_CORNERS] {
        (**self).corner_hashes_wrapped(cell, wrap)
    }
}

impl<L: Lattice<D> + WrapCorners<D>, const D: usize> Lattice<D> for Periodic<L, D> {
    type Fade = L::Fade;
    type Corner<R: crate::Real> = L::Corner<R>;
    #[inline]
    fn corner_hashes(&self, cell: [i32; D]) -> [u32; MAX_CORNERS] {
        self.noise.corner_hashes_wrapped(cell, &self.wrap)
    }
    #[inline]
    fn corner<R: crate::Real>(&self, h: u32) -> Self::Corner<R> {
        self.noise.corner(h)
    }
    #[inline]
    fn contribution<R: crate::Real>(&self, c: &Self::Corner<R>, d: &[R; D]) -> R {
        self.noise.contribution(c, d)
    }
    #[inline]
    fn gradient<R: crate::Real>(&self, h: u32) -> [R; D] {
        self.noise.gradient(h)
    }
    #[inline]
    fn dot<R: crate::Real>(&self, h: u32, d: &[R; D]) -> R {
        self.noise.dot(h, d)
    }
}

// The bound of the noise wrapped: wrapping changes which gradients meet, not their range.
super::lattice_noise_impls!(
    Periodic<L, P>,
    [L: crate::Noise<R, D>, const P: usize],
    |n: &Self, _| crate::Noise::<R, D>::amplitude_bound(&n.noise)
);

crate::noise::inherent_amplitude_bound!(Periodic<N, P>, [N, const P: usize]);

//! Value noise with cubic (Catmull-Rom) interpolation (Lewis 1989 §2.3): [`CubicValueNoise`].

use super::Periodic;
use super::white::WhiteNoise;
use crate::Real;
use crate::hash::chain::ChainHash;
use crate::lattice::kernel::split_point;
use crate::wavelet::Distribution;

/// Value noise with cubic (Catmull-Rom) interpolation (Lewis 1989 §2.3): lattice white noise
/// ([`WhiteNoise`]) interpolated by the tensor product of Catmull-Rom splines over the 4ᴰ
/// nearest lattice values.
///
/// Catmull-Rom weights for the fraction `t` and the lattice points at `−1, 0, 1, 2`:
/// `w₋₁ = −t(1 − t)²/2`, `w₀ = 1 − t²(5 − 3t)/2`, `w₁ = 1 − (1 − t)²(2 + 3t)/2`,
/// `w₂ = −t²(1 − t)/2`. They sum to 1, pass through the lattice values (`w = (0, 1, 0, 0)` at
/// `t = 0`), and the noise is C¹. Lewis's point stands: interpolated white noise is low-pass,
/// not band-pass (its mean is not removed), and its spectrum falls as ω⁻⁴; Catmull-Rom's
/// negative lobes ring a little, so it overshoots its lattice values. It costs 4ᴰ cell hashes
/// (16 in 2D, 64 in 3D, 256 in 4D), each an integer mix, against the 2ᴰ of linear-fade value
/// noise ([`ValueNoise`](super::ValueNoise)).
///
///
/// * **Lattice values**: [`WhiteNoise`]'s for the same seed and distribution: at every
///   integer point `n`, `CubicValueNoise::sample(n)` is exactly `WhiteNoise::sample(n)`, in
///   every number type.
/// * **Range**: `|n| ≤ 1.25ᴰ · m` with `m` the distribution's largest value
///   ([`WhiteNoise::largest`]): per axis the weights' magnitudes sum to `1 + t(1 − t) ≤ 1.25`.
///   The largest seen (uniform values, `tests/tests/white.rs`, 10⁵ random points in 1D and
///   2D, 2·10⁴ in 3D, 2·10³ in 4D): 1.19, 1.24, 1.19, 1.14: past the lattice values' `1 − 1/N`
///   (Catmull-Rom overshoots), well within the bound.
/// * **Gradient**: analytic ([`NoiseGradient`](crate::NoiseGradient)), continuous.
/// * **Period**: none (2³² cells), or any period per axis from 1 to 2¹⁶ cells wrapped by
///   [`Periodic`] (each of the 4ᴰ lattice points wrapped before it is hashed).
///
/// # Examples
///
/// ```
/// use bandnoise::{Noise, NoiseGradient, lattice::{CubicValueNoise, WhiteNoise}};
///
/// let cubic = CubicValueNoise::new(3);
/// // It passes through the white noise's values at the lattice points.
/// assert_eq!(cubic.sample([2.0f32, -5.0]), WhiteNoise::new(3).sample([2.0f32, -5.0]));
/// let (v, g) = cubic.sample_with_gradient([2.3f32, -4.6]);
/// assert!(v.abs() <= cubic.amplitude_bound::<2>() && g.iter().all(|d| d.is_finite()));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct CubicValueNoise {
    white: WhiteNoise,
}

impl CubicValueNoise {
    /// Cubic value noise for `seed`, lattice values uniform in `[-1, 1]`.
    #[must_use]
    pub const fn new(seed: u32) -> Self {
        Self {
            white: WhiteNoise::new(seed),
        }
    }

    /// The Catmull-Rom interpolant of `white`'s values.
    #[must_use]
    pub const fn interpolating(white: WhiteNoise) -> Self {
        Self { white }
    }

    /// The same noise with lattice values of `distribution`.
    #[must_use]
    pub const fn with_distribution(self, distribution: Distribution) -> Self {
        Self {
            white: self.white.with_distribution(distribution),
        }
    }

    /// The distribution of the lattice values.
    #[must_use]
    pub const fn distribution(&self) -> Distribution {
        self.white.distribution()
    }

    /// The lattice white noise it interpolates.
    #[must_use]
    pub const fn lattice_values(&self) -> WhiteNoise {
        self.white
    }

    /// The value and, where `GRADIENT`, the gradient at `p`, the lattice point `c + k` of axis
    /// `a` hashed as `cell(a, c, k)` (its coordinate, or wrapped to a period).
    #[inline]
    fn evaluate<R: Real, const D: usize, const GRADIENT: bool>(
        &self,
        p: [R; D],
        cell: impl Fn(usize, i32, i32) -> u32 + Copy,
    ) -> (R, [R; D]) {
        let (cells, frac) = split_point(p);
        let mut w = [[R::ZERO; 4]; D];
        let mut dw = [[R::ZERO; 4]; D];
        for a in 0..D {
            let (t, u) = (frac[a], R::ONE - frac[a]);
            // The weights are symmetric: the points at 1 and 2 see `u` as those at 0 and −1
            // see `t`, and d/dt = −d/du.
            let ([far, near, d_far, d_near], [far_u, near_u, d_far_u, d_near_u]) =
                (side::<R, GRADIENT>(t, u), side::<R, GRADIENT>(u, t));
            w[a] = [far, near, near_u, far_u];
            dw[a] = [d_far, d_near, -d_near_u, -d_far_u];
        }
        let start = self.white.hash().start();
        let (value, gradient) = if GRADIENT {
            self.sum_with_gradient(start, &cells, &w, &dw, cell)
        } else {
            (self.sum(start, &cells, &w, cell), [R::ZERO; D])
        };
        (value.canonical(), gradient.map(R::canonical))
    }

    /// The interpolation of the lattice values around the point: over axis 0's four lattice
    /// points, the weighted sum of the sums over the remaining axes (nested in that order, as
    /// [`sum_with_gradient`](Self::sum_with_gradient) nests them, so both round alike), the
    /// hash chain continued one axis per level from `h`. The levels are nested closures that
    /// the compiler inlines into one loop nest per dimension (a recursive function over the
    /// axes took four times the instructions: a call per lattice point).
    #[inline]
    fn sum<R: Real, const D: usize>(
        &self,
        h: u32,
        cells: &[i32; D],
        w: &[[R; 4]; D],
        cell: impl Fn(usize, i32, i32) -> u32 + Copy,
    ) -> R {
        let value = |h: u32| self.white.value_of_hash::<R>(h);
        // `a % D`: a level that a dimension below 4 never reaches, kept in bounds.
        let (c, w) = (|a: usize| (a, cells[a % D]), |a: usize| &w[a % D]);
        match D {
            1 => self.axis(h, c(0), w(0), cell, value),
            2 => self.axis(h, c(0), w(0), cell, |h| {
                self.axis(h, c(1), w(1), cell, value)
            }),
            3 => self.axis(h, c(0), w(0), cell, |h| {
                self.axis(h, c(1), w(1), cell, |h| {
                    self.axis(h, c(2), w(2), cell, value)
                })
            }),
            _ => self.axis(h, c(0), w(0), cell, |h| {
                self.axis(h, c(1), w(1), cell, |h| {
                    self.axis(h, c(2), w(2), cell, |h| {
                        self.axis(h, c(3), w(3), cell, value)
                    })
                })
            }),
        }
    }

    /// One axis `a` of [`sum`](Self::sum): `Σ_k w[k] · inner(hash step of c + k)` over the
    /// four lattice points `c − 1 … c + 2`.
    #[inline(always)]
    fn axis<R: Real>(
        &self,
        h: u32,
        (a, c): (usize, i32),
        w: &[R; 4],
        cell: impl Fn(usize, i32, i32) -> u32,
        inner: impl Fn(u32) -> R,
    ) -> R {
        let mut value = R::ZERO;
        for (k, wk) in (-1..).zip(w) {
            let hk = self.white.hash().step(h, cell(a, c, k));
            value = value + wk.mul_fraction(inner(hk));
        }
        value
    }

    /// [`sum`](Self::sum) and its gradient (the axes before `cells[0]` are zero), from the
    /// weights `w` and their derivatives `dw`.
    fn sum_with_gradient<R: Real, const D: usize>(
        &self,
        h: u32,
        cells: &[i32],
        w: &[[R; 4]],
        dw: &[[R; 4]],
        cell: impl Fn(usize, i32, i32) -> u32 + Copy,
    ) -> (R, [R; D]) {
        let (Some((&c, cells)), Some((wa, w)), Some((da, dw))) =
            (cells.split_first(), w.split_first(), dw.split_first())
        else {
            return (self.white.value_of_hash(h), [R::ZERO; D]);
        };
        let axis = D - 1 - cells.len();
        let (mut value, mut gradient) = (R::ZERO, [R::ZERO; D]);
        for (k, (wk, dk)) in (-1..).zip(wa.iter().zip(da)) {
            let hk = self.white.hash().step(h, cell(axis, c, k));
            let (v, g) = self.sum_with_gradient::<R, D>(hk, cells, w, dw, cell);
            value = value + wk.mul_fraction(v);
            for (total, g) in gradient.iter_mut().zip(g).skip(axis + 1) {
                *total = *total + wk.mul_fraction(g);
            }
            if let Some(total) = gradient.get_mut(axis) {
                *total = *total + dk.mul_fraction(v);
            }
        }
        (value, gradient)
    }
}

/// One side's Catmull-Rom weights for a point `t` past the lattice point 0 (`u = 1 − t`):
/// the far point −1's `−t u²/2` and the near point 0's `1 − t²(5 − 3t)/2`, and, where
/// `GRADIENT`, their derivatives along `t`, `−u(u − 2t)/2` and `−t(5 − 9t/2)` (else 0).
///
/// Every product has a factor of magnitude at most 1 (`t`, `u`, `½` or their products), so
/// `mul_fraction` rounds as `mul_rn` without its saturation.
#[inline]
fn side<R: Real, const GRADIENT: bool>(t: R, u: R) -> [R; 4] {
    let half = R::from_ratio(1, 1);
    let tt = t.mul_fraction(t);
    let far = -half.mul_fraction(t).mul_fraction(u.mul_fraction(u));
    let near = R::ONE - tt.mul_fraction(R::from_ratio(5, 1) - R::from_ratio(3, 1).mul_fraction(t));
    if !GRADIENT {
        return [far, near, R::ZERO, R::ZERO];
    }
    let d_far = -half.mul_fraction(u).mul_fraction(u - t - t);
    let d_near = -t.mul_fraction(R::from_i32(5) - R::from_ratio(9, 1).mul_fraction(t));
    [far, near, d_far, d_near]
}

macro_rules! cubic_impls {
    ($($d:literal),*) => {$(
        impl<R: Real> crate::Noise<R, $d> for CubicValueNoise {
            #[inline]
            fn sample(&self, p: [R; $d]) -> R {
                self.evaluate::<R, $d, false>(p, unwrapped).0
            }
            fn amplitude_bound(&self) -> f32 {
                // 1.25ᴰ · the largest lattice value, plus rounding.
                let mut bound = self.white.largest();
                for _ in 0..$d {
                    bound *= 1.25;
                }
                // Fixed point rounds each of the 4ᴰ products to 2⁻¹⁷ and each weight to a few
                // 2⁻¹⁶: 2⁻⁷ covers them (the error measured against `f64` is below 2⁻¹²,
                // `tests/tests/white.rs`).
                bound + 1.0 / 128.0
            }
        }

        impl<R: Real> crate::NoiseGradient<R, $d> for CubicValueNoise {
            #[inline]
            fn sample_with_gradient(&self, p: [R; $d]) -> (R, [R; $d]) {
                self.evaluate::<R, $d, true>(p, unwrapped)
            }
        }

        impl<R: Real> crate::Noise<R, $d> for Periodic<CubicValueNoise, $d> {
            #[inline]
            fn sample(&self, p: [R; $d]) -> R {
                crate::Noise::sample(&self.with_noise(self.noise()), p)
            }
            fn amplitude_bound(&self) -> f32 {
                crate::Noise::<R, $d>::amplitude_bound(self.noise())
            }
        }

        impl<R: Real> crate::NoiseGradient<R, $d> for Periodic<CubicValueNoise, $d> {
            #[inline]
            fn sample_with_gradient(&self, p: [R; $d]) -> (R, [R; $d]) {
                self.with_noise(self.noise()).sample_with_gradient(p)
            }
        }

        /// The noise with each lattice coordinate wrapped to its axis's period before it
        /// is hashed: periodic bit for bit (where all 4ᴰ lattice points lie in `0..P`, the
        /// unwrapped noise's values).
        impl<R: Real> crate::Noise<R, $d> for Periodic<&CubicValueNoise, $d> {
            #[inline]
            fn sample(&self, p: [R; $d]) -> R {
                let wrap = self.wrap();
                self.noise()
                    .evaluate::<R, $d, false>(p, |a, c, k| wrap.cell(a, c, k))
                    .0
            }
            fn amplitude_bound(&self) -> f32 {
                crate::Noise::<R, $d>::amplitude_bound(*self.noise())
            }
        }

        impl<R: Real> crate::NoiseGradient<R, $d> for Periodic<&CubicValueNoise, $d> {
            #[inline]
            fn sample_with_gradient(&self, p: [R; $d]) -> (R, [R; $d]) {
                let wrap = self.wrap();
                self.noise()
                    .evaluate::<R, $d, true>(p, |a, c, k| wrap.cell(a, c, k))
            }
        }
    )*};
}

/// The lattice point `c + k` of any axis, unwrapped: its coordinate (modulo 2³², as the hash
/// takes it).
#[inline(always)]
fn unwrapped(_: usize, c: i32, k: i32) -> u32 {
    c.wrapping_add(k) as u32
}

cubic_impls!(1, 2, 3, 4);
crate::noise::inherent_amplitude_bound!(CubicValueNoise, []);

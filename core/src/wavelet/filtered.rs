//! Wavelet noise filtered by a sample's footprint (Cook & DeRose 2005, §3.1, §4.1, §6).
//!
//! A renderer that takes one sample per pixel does not average the noise over the pixel, so
//! bands finer than the pixels alias. §4.1's remedy is to evaluate the finest bands through a
//! widened basis, which averages them as the pixel would. Here the widening is the pixel's own
//! box: each band's quadratic B-spline `B` is convolved with a box as wide as the footprint
//! along each axis, in that band's coefficients,
//!
//! `(B ∗ box_w)(d) = (C(d + w/2) − C(d − w/2)) / w`, with `C` the integral of `B`,
//!
//! a basis `3 + w` coefficients wide whose weights still sum to 1, so a filtered band is the
//! box-filtered band exactly (for an axis-aligned footprint; a sheared one is replaced by the
//! box of the same second moment along each axis, `w_a = √(dpdx_a² + dpdy_a²)`).
//!
//! | widest axis `w` (coefficients per pixel) | band rendered |
//! |---|---|
//! | `≤ 1/4` | as [`Noise::sample`](crate::Noise::sample) gives it (the box changes it by < 0.1%) |
//! | `(1/4, 3]` | through the box-widened basis |
//! | `(3, 4)` | widened, fading out (`1 − smoothstep(w − 3)`) |
//! | `≥ 4` | left out |
//!
//! The box-filtered band keeps 11% of its variance at 2.15 coefficients per pixel and 1.1% at
//! 4.3, so leaving out the bands past 4 costs about 1% of their power as error, and bounds the
//! widened basis to 8 coefficients per axis.
//!
//! The paper's own widening, `B` stretched to `3(1 + 2^j)` coefficients for `j = log2(w)` near
//! 0 and unwidened over `−2 < j ≤ −1`, blurs more than a one-pixel box: measured against a
//! box-filtered reference (`tests/tests/filtering.rs`), the band with 0.54 coefficients per pixel
//! had a squared error of 0.37 that way, against 0.0073 sampled plainly and 9e-8 here.
//!
//! The footprint's widths and each band's fade are computed in `f32` whatever the number type,
//! so every type keeps and widens the same bands (a footprint of 1/512 squares to 2⁻¹⁸, below
//! I16F16's resolution).

use crate::Real;

use super::band::{TileData, Wavelet};
use super::window::{WIDTH, Window};

/// Coefficients per pixel up to which a band is sampled plainly.
const PLAIN: f32 = 0.25;
/// Coefficients per pixel from which a band fades out, and past which it is left out.
const FADE: [f32; 2] = [3.0, 4.0];
/// The most coefficients the widened basis reaches along an axis: `|d| < 3/2 + w/2 ≤ 7/2`.
const REACH: usize = WIDTH;

/// How a band is rendered for a footprint of `widths` coefficients along each axis: `None`
/// plainly, else the fade (1 down to 0) of the box-widened band.
fn fade<const D: usize>(widths: &[f32; D]) -> Option<f32> {
    let widest = widths.iter().fold(0.0f32, |m, w| m.max(*w));
    if widest <= PLAIN {
        None
    } else if widest <= FADE[0] {
        Some(1.0)
    } else if widest < FADE[1] {
        let x = (widest - FADE[0]) / (FADE[1] - FADE[0]);
        Some(1.0 - x * x * (3.0 - 2.0 * x))
    } else {
        Some(0.0)
    }
}

/// The footprint's box width along each axis, in noise units: `√(dpdx_a² + dpdy_a²)`, in
/// `f32`. A vector with a NaN component is unknown and gives way to the other; both unknown
/// give 0 (no filtering).
pub(crate) fn footprint_widths<R: Real, const D: usize>(dpdx: &[R; D], dpdy: &[R; D]) -> [f32; D] {
    let known = |v: &[R; D]| {
        let v = v.map(R::to_f32);
        if v.iter().any(|x| x.is_nan()) {
            [0.0; D]
        } else {
            v
        }
    };
    let (x, y) = (known(dpdx), known(dpdy));
    core::array::from_fn(|a| libm::sqrtf(x[a] * x[a] + y[a] * y[a]))
}

/// The integral of the centred quadratic B-spline from −∞ to `u`: 0 below −3/2, 1 above 3/2.
/// Out of line: the widened basis calls it for every coefficient of every axis, and inlined
/// copies would not fit the Cortex-M0's checksum program.
#[inline(never)]
fn bspline_integral<R: Real>(u: R) -> R {
    let half = R::from_ratio(1, 1);
    let three_halves = R::from_ratio(3, 1);
    let sixth = |x: R| x.mul_rn(x).mul_rn(x).div(R::from_i32(6));
    if u <= -three_halves {
        R::ZERO
    } else if u <= -half {
        sixth(u + three_halves)
    } else if u < half {
        // 1/2 + 3u/4 − u³/3
        half + u.mul_rn(R::from_ratio(3, 2)) - u.mul_rn(u).mul_rn(u).div(R::from_i32(3))
    } else if u < three_halves {
        R::ONE - sixth(three_halves - u)
    } else {
        R::ONE
    }
}

/// The box-widened basis along one axis at `x` for a box `w` coefficients wide: the first
/// coefficient it reaches, how many, and their weights. Out of line, for code size.
#[inline(never)]
fn axis_weights<R: Real>(x: R, w: f32, weights: &mut [R; REACH]) -> (i32, usize) {
    let w = R::from_f32(w.clamp(PLAIN, FADE[1]));
    let (cell, frac) = x.split();
    let half_width = w.mul_rn(R::from_ratio(1, 1));
    let reach = R::from_ratio(3, 1) + half_width;
    // Coefficients cell + k with |frac − k| < reach (one exactly at the edge weighs 0).
    let kmin = (frac - reach).split().0 + 1;
    let kmax = (frac + reach).split().0;
    let inverse = R::ONE.div(w);
    let mut count = 0;
    for (slot, offset) in weights.iter_mut().zip(kmin..=kmax) {
        let d = frac - R::from_i32(offset);
        let area = bspline_integral(d + half_width) - bspline_integral(d - half_width);
        *slot = area.mul_rn(inverse);
        count += 1;
    }
    (cell.wrapping_add(kmin), count)
}

impl<T> Wavelet<'_, T> {
    /// The band at `p` as a pixel `widths` coefficients wide along each axis sees it (the
    /// module's table): plainly, through the box-widened basis, fading, or 0.
    pub(crate) fn sample_boxed<R: Real, const D: usize>(&self, p: [R; D], widths: [f32; D]) -> R
    where
        T: TileData<D>,
        Self: crate::Noise<R, D>,
    {
        match fade(&widths) {
            None => crate::Noise::sample(self, p),
            Some(f) if f > 0.0 => self.widened(p, widths).mul_rn(R::from_f32(f)),
            Some(_) => R::ZERO,
        }
    }

    /// `Σ_c n_c Π_a (B ∗ box_{w_a})(p_a − c_a)`, for widths below [`FADE`]`[1]`. Out of
    /// line: it is long, and off the plain sampling path.
    #[inline(never)]
    pub(crate) fn widened<R: Real, const D: usize>(&self, p: [R; D], widths: [f32; D]) -> R
    where
        T: TileData<D>,
    {
        self.widened_by(p, widths, |first, count| {
            let mut window = Window::new(self, first, count);
            move |k| window.coefficient(k)
        })
    }

    /// [`widened`](Self::widened) with the coefficients at offsets `k` from global index
    /// `first`, `count` along each axis, read through `open(first, count)`: a [`Window`], or in
    /// tests the reference that finds each on its own (the same values).
    pub(crate) fn widened_by<R: Real, const D: usize, S: FnMut([usize; D]) -> R>(
        &self,
        p: [R; D],
        widths: [f32; D],
        open: impl FnOnce([i32; D], [usize; D]) -> S,
    ) -> R
    where
        T: TileData<D>,
    {
        let mut weights = [[R::ZERO; REACH]; D];
        let mut first = [0i32; D];
        let mut count = [0usize; D];
        for a in 0..D {
            (first[a], count[a]) = axis_weights(p[a], widths[a], &mut weights[a]);
        }
        let mut coefficient = open(first, count);
        let mut sum = R::ZERO;
        let mut index = [0usize; D];
        'coefficients: loop {
            let mut w = R::ONE;
            for a in 0..D {
                w = w.mul_rn(weights[a][index[a] % REACH]);
            }
            let c = coefficient(index);
            sum = sum.saturating_add(w.mul_rn(c));
            // The next coefficient, x fastest.
            for a in 0..D {
                index[a] += 1;
                if index[a] < count[a] {
                    continue 'coefficients;
                }
                index[a] = 0;
            }
            break;
        }
        sum.canonical()
    }
}

/// One band filtered by a sample's footprint: a band has one coefficient per unit, so the
/// footprint's widths are its coefficients per pixel.
impl<R: Real, T: TileData<D>, const D: usize> crate::FilteredNoise<R, D> for Wavelet<'_, T> {
    /// The band as a pixel whose footprint is spanned by `dpdx` and `dpdy` sees it: the band
    /// averaged over a box as wide as the footprint along each axis (see the module's table).
    ///
    /// # Contract
    ///
    /// As [`sample`](crate::Noise::sample) for `p`; a footprint of at most ¼ along every axis
    /// (or zero, or NaN) gives `sample(p)`, bit for bit; one of 4 or more along an axis (or
    /// infinite) gives 0; never panics, and the result is within
    /// [`amplitude_bound`](crate::Noise::amplitude_bound) (the widened weights are
    /// non-negative and sum to 1).
    ///
    /// # Examples
    ///
    /// ```
    /// use bandnoise::{FilteredNoise, Noise, wavelet::{TILE2, Wavelet}};
    ///
    /// let band = Wavelet::new(0, &TILE2);
    /// let p = [3.3f32, 0.7];
    /// assert_eq!(band.sample_filtered(p, [0.25, 0.0], [0.0, 0.1]), band.sample(p));
    /// assert_eq!(band.sample_filtered(p, [4.0, 0.0], [0.0, 4.0]), 0.0);
    /// let blurred = band.sample_filtered(p, [0.7, 0.0], [0.0, 0.7]);
    /// assert!(blurred.abs() <= band.amplitude_bound::<2>());
    /// ```
    fn sample_filtered(&self, p: [R; D], dpdx: [R; D], dpdy: [R; D]) -> R {
        self.sample_boxed(p, footprint_widths(&dpdx, &dpdy))
            .canonical()
    }
}

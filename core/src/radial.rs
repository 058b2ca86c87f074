//! Radial functions of the squared distance: the kernels of sparse convolution noise
//! ([`Kernel`](crate::impulse::Kernel)) and the covariances of Wiener-interpolated noise
//! ([`Covariance`](crate::wiener::Covariance)). Each has its `f64` formula here ([`Profile`]:
//! what tests compare with, and the integrals that normalise the noises, at compile time);
//! Lewis's cosine is also tabulated against the squared distance, so that no square root is
//! taken per evaluation (Lewis 1989, §4: "remove square roots by indexing a pre-warped table
//! `ĥ(d²) = h(√d²)`"), the others are evaluated from their formulas in each number type.
//!
//! A [`Table`] holds `ĥ(s)` and `ĥ′(s)·Δ` at the knots `s = kΔ` of the function's support
//! `[0, S)` (`S` = 1 or 4: radius 1 or 2), computed at compile time in `f64` from the
//! function's formula ([`Profile::exact`]) and stored in Q2.30, and is read by cubic Hermite
//! interpolation with the same operations in every number type (as
//! [`exp_neg`](crate::Real::exp_neg) is), so a value is the same on every target. The
//! errors of each table are stated where its function is documented, and tested.

use crate::Real;
use crate::special::{exp_neg_f64, hermite, q30};
use crate::wavelet::constmath;

/// One in Q2.30.
const Q30: f64 = (1u64 << 30) as f64;

/// A radial function of the squared distance, with compact support.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Profile {
    /// Lewis's `½ + ½ cos(π d)`, support 1.
    Cosine,
    /// Peachey's Catmull-Rom spline scaled to radius 1.
    CatmullRom,
    /// Wendland's `ψ₃,₁(d) = (1 − d)⁴(4d + 1)`, support 1.
    Wendland,
    /// The band-pass covariance of Wiener noise in this many dimensions, support 2.
    BandPass(usize),
    /// Gabor noise's Gaussian envelope `e^{−c s}` cut at `s = 1` (`c = ln 20`: 5% of its
    /// peak at the rim, Lagae et al. 2009), support 1. Not continuous at the rim: its value
    /// there is the limit from inside.
    Gaussian,
    /// The same Gaussian times Hann's window in `s`, `½ + ½ cos(π s)`: 0 with a zero slope at
    /// the rim (`C¹`), support 1.
    GaussianHann,
    /// Hann's window in `s` alone, `½ + ½ cos(π s)`, support 1 (filtered Gabor kernels).
    HannWindow,
}

/// The Gaussian envelope's rate in cell units: `ln 20`, so the envelope is 5% of its peak at
/// the cell's (the kernel's) radius (Lagae et al. 2009's truncation).
pub(crate) const GAUSSIAN_RATE: f64 = 2.995_732_273_553_991;

impl Profile {
    /// The same function in `d` dimensions (only the band-pass covariance depends on it).
    pub(crate) const fn in_dimension(self, d: usize) -> Self {
        match self {
            Profile::BandPass(_) => Profile::BandPass(d),
            other => other,
        }
    }

    /// The squared radius of the support, as a power of two: `S = 2^shift`.
    pub(crate) const fn support_shift(self) -> u32 {
        match self {
            Profile::BandPass(_) => 2,
            _ => 0,
        }
    }

    /// The function at squared distance `s` and its derivative with respect to `s`, in `f64`,
    /// from its formula; both 0 from `s = S` on.
    pub(crate) const fn exact(self, s: f64) -> (f64, f64) {
        if let Profile::Gaussian = self {
            // The limit from inside at the rim, where the function jumps to 0.
            if s > 1.0 {
                return (0.0, 0.0);
            }
            let e = exp_neg_f64(GAUSSIAN_RATE * if s > 0.0 { s } else { 0.0 });
            return (e, -GAUSSIAN_RATE * e);
        }
        if s >= (1u32 << self.support_shift()) as f64 {
            return (0.0, 0.0);
        }
        match self {
            Profile::Cosine => cosine(s),
            Profile::CatmullRom => catmull_rom(s),
            Profile::Wendland => wendland(s),
            Profile::BandPass(d) => band_pass(s, d, band_pass_a1_of(d)),
            Profile::Gaussian => (0.0, 0.0),
            Profile::HannWindow => {
                let s = if s > 0.0 { s } else { 0.0 };
                let (w, dw) = cosine(s * s);
                (w, 2.0 * s * dw)
            }
            Profile::GaussianHann => {
                let s = if s > 0.0 { s } else { 0.0 };
                let e = exp_neg_f64(GAUSSIAN_RATE * s);
                // ½ + ½ cos(π s) is Lewis's cosine at s², whose slope in s is 2s times its
                // slope there.
                let (w, dw) = cosine(s * s);
                product((e, -GAUSSIAN_RATE * e), (w, 2.0 * s * dw))
            }
        }
    }

    /// `∫ h(|x|)^power dx` over `D`-dimensional space (`D` in 1..=4, `power` 1 or 2), by
    /// Simpson's rule over the radius (512 intervals per unit of radius; a knot on the
    /// Catmull-Rom spline's seam at `d = ½`).
    pub(crate) const fn integral(self, d: usize, power: u32) -> f64 {
        let radius = if self.support_shift() == 0 { 1 } else { 2 };
        let n = 512 * radius;
        let mut sum = 0.0;
        let mut k = 0;
        while k <= n {
            let r = k as f64 / 512.0;
            let (h, _) = self.exact(r * r);
            let f = if power == 1 { h } else { h * h };
            sum += simpson(k, n) * f * power_of(r, d - 1);
            k += 1;
        }
        sum / (3.0 * 512.0) * sphere_area(d)
    }
}

/// `∫h²` of `profile` in dimensions 1 to 4 (index `D − 1`), for a compile-time table: the
/// quadrature is too slow to run per construction on a microcontroller without an FPU.
pub(crate) const fn powers(profile: Profile) -> [f64; 4] {
    [
        profile.in_dimension(1).integral(1, 2),
        profile.in_dimension(2).integral(2, 2),
        profile.in_dimension(3).integral(3, 2),
        profile.in_dimension(4).integral(4, 2),
    ]
}

/// The entry of a table of [`powers`] for `d` dimensions.
pub(crate) const fn power_in(powers: &[f64; 4], d: usize) -> f64 {
    match d {
        1 => powers[0],
        2 => powers[1],
        3 => powers[2],
        _ => powers[3],
    }
}

/// A [`Profile`]'s knots: `[ĥ(s), ĥ′(s)·Δ]` at `s = kΔ`, Q2.30, `KNOTS − 1` intervals (a power
/// of two) over its support.
pub(crate) const fn knots<const KNOTS: usize>(profile: Profile) -> [[i32; 2]; KNOTS] {
    let step = 1.0 / (1u32 << Table::shift(profile, KNOTS)) as f64;
    let mut knots = [[0i32; 2]; KNOTS];
    let mut k = 0;
    while k < KNOTS {
        let (v, d) = profile.exact(k as f64 * step);
        knots[k] = [round(v * Q30), round(d * step * Q30)];
        k += 1;
    }
    knots
}

/// A [`Profile`]'s table: its [`knots`] and where they lie. One type for every table, so code
/// that picks a table at run time reads it with one copy of the interpolation.
pub(crate) struct Table {
    knots: &'static [[i32; 2]],
    /// Intervals per unit of `s`, as a power of two.
    shift: u32,
    /// The support's squared radius, as a power of two.
    support: u32,
}

impl Table {
    /// The table of `profile` over `knots` (from [`knots`] of the same profile).
    pub(crate) const fn new(profile: Profile, knots: &'static [[i32; 2]]) -> Self {
        Self {
            knots,
            shift: Self::shift(profile, knots.len()),
            support: profile.support_shift(),
        }
    }

    /// Intervals per unit of `s` for `count` knots over `profile`'s support, as a power of two.
    const fn shift(profile: Profile, count: usize) -> u32 {
        let intervals = (count - 1) as u32;
        assert!(intervals.is_power_of_two());
        intervals.trailing_zeros() - profile.support_shift()
    }

    /// The function at squared distance `s`: 0 from the support's rim on (and for NaN), the
    /// value at 0 for `s ≤ 0`. Out of line in wasm (the demo's size budget).
    #[cfg_attr(target_arch = "wasm32", inline(never))]
    #[cfg_attr(not(target_arch = "wasm32"), inline)]
    pub(crate) fn at<R: Real>(&self, s: R) -> R {
        match self.knots(s) {
            Knots::Inside(t, [v0, d0, v1, d1]) => hermite(t, v0, d0, v1, d1),
            Knots::Centre => q30(self.first()[0]),
            Knots::Outside => R::ZERO,
        }
    }

    /// [`at`](Self::at) and its derivative with respect to `s` (the derivative of the same
    /// interpolant, so the pair is consistent). At `s ≤ 0` the slope is the first knot's;
    /// from the rim on both are 0. Out of line in wasm, as [`at`](Self::at).
    #[cfg_attr(target_arch = "wasm32", inline(never))]
    #[cfg_attr(not(target_arch = "wasm32"), inline)]
    pub(crate) fn at_with_slope<R: Real>(&self, s: R) -> (R, R) {
        let per_unit = R::from_i32(1 << self.shift);
        match self.knots(s) {
            Knots::Inside(t, [v0, d0, v1, d1]) => {
                // The Hermite basis's derivatives in t, then × 2^shift for the slope in s.
                let t2 = t.mul_rn(t);
                let six = R::from_i32(6);
                let (a, b) = (six.mul_rn(t2 - t), t2 + t2 + t2);
                let g = a.mul_rn(v0 - v1)
                    + (b - t - t - t - t + R::ONE).mul_rn(d0)
                    + (b - t - t).mul_rn(d1);
                (hermite(t, v0, d0, v1, d1), g.saturating_mul(per_unit))
            }
            Knots::Centre => {
                let [v, d] = self.first();
                (q30(v), q30::<R>(d).saturating_mul(per_unit))
            }
            Knots::Outside => (R::ZERO, R::ZERO),
        }
    }

    /// The first knot.
    #[inline]
    fn first(&self) -> [i32; 2] {
        self.knots.first().copied().unwrap_or_default()
    }

    /// Where `s` falls in the table.
    #[inline]
    fn knots<R: Real>(&self, s: R) -> Knots<R> {
        if s.is_nan() || s >= R::from_i32(1 << self.support) {
            return Knots::Outside;
        }
        if s <= R::ZERO {
            return Knots::Centre;
        }
        let (i, t) = s.mul_rn(R::from_i32(1 << self.shift)).split();
        // `get` keeps the reads within the table, provably.
        let i = i.max(0) as usize;
        match self.knots.get(i..i.saturating_add(2)) {
            Some(&[[v0, d0], [v1, d1]]) => Knots::Inside(t, [q30(v0), q30(d0), q30(v1), q30(d1)]),
            _ => Knots::Outside,
        }
    }
}

/// Where a squared distance falls in a table.
enum Knots<R> {
    /// Between two knots: the fraction, and the values and slopes (times the spacing).
    Inside(R, [R; 4]),
    /// At or below 0.
    Centre,
    /// At the rim or beyond (or NaN).
    Outside,
}

/// The area of the unit sphere in `D` dimensions (the two points of the 1D "sphere" count 2).
pub(crate) const fn sphere_area(d: usize) -> f64 {
    const PI: f64 = core::f64::consts::PI;
    match d {
        1 => 2.0,
        2 => 2.0 * PI,
        3 => 4.0 * PI,
        _ => 2.0 * PI * PI,
    }
}

/// The volume of the unit ball in `D` dimensions (`D` in 1..=4): the volume of a kernel.
pub(crate) const fn ball_volume(d: usize) -> f64 {
    sphere_area(d) / d as f64
}

/// Lewis's `½ + ½ cos(π√s)` and its derivative in `s`, by the power series of
/// `cos(π√s) = Σ (−π² s)^k / (2k)!` (30 terms: far below `f64`'s precision for `s ≤ 1`).
const fn cosine(s: f64) -> (f64, f64) {
    const PI2: f64 = core::f64::consts::PI * core::f64::consts::PI;
    let x = -PI2 * s;
    let (mut c, mut dc) = (1.0, 0.0);
    // prev = x^{k−1} / (2k − 2)!
    let mut prev = 1.0;
    let mut k = 1;
    while k < 30 {
        let div = ((2 * k - 1) * (2 * k)) as f64;
        dc += prev * -PI2 * k as f64 / div;
        prev *= x / div;
        c += prev;
        k += 1;
    }
    (0.5 + 0.5 * c, 0.5 * dc)
}

/// Peachey's Catmull-Rom spline at `x = 2√s`, in terms of `s`, and its derivative in `s`.
const fn catmull_rom(s: f64) -> (f64, f64) {
    if s <= 0.0 {
        return (1.0, -10.0);
    }
    let r = constmath::sqrt(s);
    if s < 0.25 {
        // ½(2 − 5x² + 3x³) with x² = 4s, x³ = 8s√s.
        (1.0 - 10.0 * s + 12.0 * s * r, -10.0 + 18.0 * r)
    } else {
        // ½(4 − 8x + 5x² − x³).
        (
            2.0 - 8.0 * r + 10.0 * s - 4.0 * s * r,
            -4.0 / r + 10.0 - 6.0 * r,
        )
    }
}

/// Wendland's `(1 − d)⁴(4d + 1)` at `d = √s` and its derivative in `s`: `dh/dd = −20 d (1 −
/// d)³`, so `dh/ds = −10 (1 − d)³`.
const fn wendland(s: f64) -> (f64, f64) {
    let d = if s <= 0.0 { 0.0 } else { constmath::sqrt(s) };
    let e = 1.0 - d;
    let e3 = e * e * e;
    (e3 * e * (4.0 * d + 1.0), -10.0 * e3)
}

/// The band-pass covariance's free coefficients `[a₂, a₃]` of `s²` and `s³` in `D`
/// dimensions (index `D − 1`); `a₁` follows from `∫h = 0` ([`band_pass_a1`]).
const BAND_PASS_A: [[f64; 2]; 4] = [
    [4.037, -1.524],
    [2.502, -0.879],
    [1.957, -0.659],
    [1.801, -0.574],
];

/// The band-pass covariance's `[a₁, a₂, a₃]` in `d` dimensions (1 to 4).
pub(crate) const fn band_pass_coefficients(d: usize) -> [f64; 3] {
    let [a2, a3] = match d {
        1 => BAND_PASS_A[0],
        2 => BAND_PASS_A[1],
        3 => BAND_PASS_A[2],
        _ => BAND_PASS_A[3],
    };
    [band_pass_a1_of(d), a2, a3]
}

/// `a₁` of the band-pass covariance per dimension ([`band_pass_a1`]).
const BAND_PASS_A1: [f64; 4] = [
    band_pass_a1(1),
    band_pass_a1(2),
    band_pass_a1(3),
    band_pass_a1(4),
];

/// [`BAND_PASS_A1`] for `D` dimensions (constant indices: no bounds check at run time).
const fn band_pass_a1_of(d: usize) -> f64 {
    match d {
        1 => BAND_PASS_A1[0],
        2 => BAND_PASS_A1[1],
        3 => BAND_PASS_A1[2],
        _ => BAND_PASS_A1[3],
    }
}

/// The band-pass covariance in `D` dimensions with `a₁ = a1`, and its derivative in `s`:
/// `h(s) = (1 − s)(2 − s)(3 − s)/6 · (1 − s/4)⁸ · (1 + a₁s + a₂s² + a₃s³)`.
const fn band_pass(s: f64, d: usize, a1: f64) -> (f64, f64) {
    let [a2, a3] = match d {
        1 => BAND_PASS_A[0],
        2 => BAND_PASS_A[1],
        3 => BAND_PASS_A[2],
        _ => BAND_PASS_A[3],
    };
    // Value and derivative of each factor, multiplied by the product rule.
    let zeros = (
        (1.0 - s) * (2.0 - s) * (3.0 - s) / 6.0,
        -((2.0 - s) * (3.0 - s) + (1.0 - s) * (3.0 - s) + (1.0 - s) * (2.0 - s)) / 6.0,
    );
    let q = 1.0 - s / 4.0;
    let q7 = q * q * q * q * q * q * q;
    let envelope = (q7 * q, -2.0 * q7);
    let poly = (
        1.0 + s * (a1 + s * (a2 + s * a3)),
        a1 + s * (2.0 * a2 + 3.0 * a3 * s),
    );
    let (v, dv) = product(zeros, envelope);
    product((v, dv), poly)
}

/// `(f, f′) · (g, g′)`.
const fn product(f: (f64, f64), g: (f64, f64)) -> (f64, f64) {
    (f.0 * g.0, f.0 * g.1 + f.1 * g.0)
}

/// `a₁` of the band-pass covariance in `D` dimensions: the value that makes `∫h = 0`, so its
/// spectrum is 0 at the origin. `h` is linear in `a₁`: `∫h = I₀ + a₁ I₁`.
const fn band_pass_a1(d: usize) -> f64 {
    // ∫ over the radius of the band-pass function with a₁ = 0 and a₁ = 1.
    let (mut i0, mut i1) = (0.0, 0.0);
    const N: usize = 1024;
    let mut k = 0;
    while k <= N {
        let r = 2.0 * k as f64 / N as f64;
        let (h0, _) = band_pass(r * r, d, 0.0);
        let (h1, _) = band_pass(r * r, d, 1.0);
        let w = simpson(k, N) * power_of(r, d - 1);
        i0 += w * h0;
        i1 += w * (h1 - h0);
        k += 1;
    }
    -i0 / i1
}

/// Simpson's weight of knot `k` of `n` (even): 1 at the ends, then 4, 2, 4, …
const fn simpson(k: usize, n: usize) -> f64 {
    if k == 0 || k == n {
        1.0
    } else if k % 2 == 1 {
        4.0
    } else {
        2.0
    }
}

/// `r^e`.
const fn power_of(r: f64, e: usize) -> f64 {
    let (mut p, mut i) = (1.0, 0);
    while i < e {
        p *= r;
        i += 1;
    }
    p
}

/// Nearest integer (ties away from zero).
const fn round(v: f64) -> i32 {
    if v < 0.0 {
        -((-v + 0.5) as i32)
    } else {
        (v + 0.5) as i32
    }
}

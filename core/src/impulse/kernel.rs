//! The radial kernels of sparse convolution noise, tabulated against the squared distance so
//! that no square root is taken per impulse (Lewis 1989, §4: "remove square roots by indexing
//! a pre-warped table `ĥ(d²) = h(√d²)`").
//!
//! Each kernel has radius 1. Its table holds `ĥ(s)` and `ĥ′(s)·Δ` at the knots `s = kΔ`,
//! computed at compile time in `f64` and stored in Q2.30, and is read by cubic Hermite
//! interpolation with the same operations in every number type (as
//! [`exp_neg`](crate::Real::exp_neg) is). Errors of the interpolation against the kernel in
//! `f64` (tested; `f32` adds 3e-7, I16F16 1e-4):
//!
//! | kernel | knots | table | error |
//! |---|---|---|---|
//! | [`Kernel::Cosine`] | 33, `Δ = 1/32` | 264 B | 1e-8 |
//! | [`Kernel::CatmullRom`] | 257, `Δ = 1/256` | 2056 B | 2e-6; 1.5e-4 for `d < 1/16`, where its `d³` term is not smooth in `d²` |

use crate::Real;
use crate::special::{hermite, q30};
use crate::wavelet::constmath;

/// A radial kernel of radius 1 (in cell units: the cell size is the kernel's radius).
///
/// # Examples
///
/// ```
/// use bandnoise::impulse::Kernel;
///
/// assert_eq!(Kernel::Cosine.at(0.0f32), 1.0);
/// assert_eq!(Kernel::Cosine.at(1.0f32), 0.0);
/// assert!((Kernel::Cosine.at(0.25f32) - 0.5).abs() < 1e-6); // ½ + ½ cos(π/2)
/// assert!(Kernel::CatmullRom.at(0.5f32) < 0.0); // its negative lobe
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Kernel {
    /// Lewis's smooth cosine `h(d) = ½ + ½ cos(π d)` (1989, §4, the kernel of his Fig. 5):
    /// positive, `C¹` at the rim, a low-pass spectrum.
    #[default]
    Cosine,
    /// Peachey's radial Catmull-Rom spline (Texturing & Modeling, ch. 2, `scnoise`), scaled
    /// from his radius 2 to radius 1: `h(d) = c(2d)` with `c(x) = ½(2 − 5x² + 3x³)` for
    /// `x < 1` and `½(4 − 8x + 5x² − x³)` for `1 ≤ x < 2`. Its negative lobe (down to
    /// `−2/27`) makes the noise mildly band-pass.
    CatmullRom,
}

/// Intervals of the cosine's table in `s = d²`, as a power of two.
const COSINE_SHIFT: u32 = 5;
/// Intervals of the Catmull-Rom spline's table, as a power of two: its `s√s` term needs
/// finer knots near 0.
const CATMULL_ROM_SHIFT: u32 = 8;
/// One in Q2.30.
const Q30: f64 = (1u64 << 30) as f64;

impl Kernel {
    /// The kernel at squared distance `d2`: `h(√d2)`, 0 from `d2 = 1` on; `d2 ≤ 0` gives
    /// `h(0) = 1`. From the kernel's table (see the module docs), in `[−2/27, 1]`.
    #[inline]
    #[must_use]
    pub fn at<R: Real>(self, d2: R) -> R {
        match self.knots(d2) {
            Knots::Inside(t, [v0, d0, v1, d1]) => hermite(t, v0, d0, v1, d1),
            Knots::Centre => R::ONE,
            Knots::Outside => R::ZERO,
        }
    }

    /// [`at`](Self::at) and its derivative with respect to `d2` (the derivative of the same
    /// interpolant, so the pair is consistent): `∇_x h(|x|) = 2 x · dh/d(d²)`. At `d2 ≤ 0` the
    /// slope is the first knot's; from `d2 = 1` on both are 0. The slope is at most 10 in
    /// magnitude (the Catmull-Rom spline's at 0; the cosine's is at most `π²/4`).
    #[inline]
    #[must_use]
    pub fn at_with_slope<R: Real>(self, d2: R) -> (R, R) {
        let shift = match self {
            Kernel::Cosine => COSINE_SHIFT,
            Kernel::CatmullRom => CATMULL_ROM_SHIFT,
        };
        match self.knots(d2) {
            Knots::Inside(t, [v0, d0, v1, d1]) => {
                // The Hermite basis's derivatives in t, then × 2^shift for the slope in s.
                let t2 = t.mul_rn(t);
                let six = R::from_i32(6);
                let (a, b) = (six.mul_rn(t2 - t), t2 + t2 + t2);
                let g = a.mul_rn(v0 - v1)
                    + (b - t - t - t - t + R::ONE).mul_rn(d0)
                    + (b - t - t).mul_rn(d1);
                (
                    hermite(t, v0, d0, v1, d1),
                    g.saturating_mul(R::from_i32(1 << shift)),
                )
            }
            Knots::Centre => {
                let first = match self {
                    Kernel::Cosine => COSINE[0][1],
                    Kernel::CatmullRom => CATMULL_ROM[0][1],
                };
                (
                    R::ONE,
                    q30::<R>(first).saturating_mul(R::from_i32(1 << shift)),
                )
            }
            Knots::Outside => (R::ZERO, R::ZERO),
        }
    }

    /// Where `d2` falls in the kernel's table.
    #[inline]
    fn knots<R: Real>(self, d2: R) -> Knots<R> {
        let (table, shift): (&[[i32; 2]], u32) = match self {
            Kernel::Cosine => (&COSINE, COSINE_SHIFT),
            Kernel::CatmullRom => (&CATMULL_ROM, CATMULL_ROM_SHIFT),
        };
        if d2.is_nan() || d2 >= R::ONE {
            return Knots::Outside;
        }
        if d2 <= R::ZERO {
            return Knots::Centre;
        }
        let (i, t) = d2.mul_rn(R::from_i32(1 << shift)).split();
        // `take` and `skip` keep the reads within the table, provably.
        let mut knots = table.iter().skip(i.max(0) as usize).take(2);
        match (knots.next(), knots.next()) {
            (Some(&[v0, d0]), Some(&[v1, d1])) => {
                Knots::Inside(t, [q30(v0), q30(d0), q30(v1), q30(d1)])
            }
            _ => Knots::Outside,
        }
    }

    /// The kernel at squared distance `s` (`h(√s)`) and its derivative with respect to `s`,
    /// in `f64`, from the kernel's formula (what the tables hold, and what tests compare
    /// with); both 0 from `s = 1` on.
    #[must_use]
    pub const fn exact(self, s: f64) -> (f64, f64) {
        if s >= 1.0 {
            return (0.0, 0.0);
        }
        match self {
            Kernel::Cosine => cosine(s),
            Kernel::CatmullRom => catmull_rom(s),
        }
    }

    /// `∫ h(|x|)² dx` over `D`-dimensional space (for `D` in 1..=4), by Simpson's rule over
    /// the radius (512 intervals; a knot on the Catmull-Rom spline's seam at `d = ½`). It
    /// enters the variance by Campbell's theorem, `λ E[w²] ∫h²`.
    #[must_use]
    pub const fn power(self, d: usize) -> f64 {
        const N: usize = 512;
        let mut sum = 0.0;
        let mut k = 0;
        while k <= N {
            let r = k as f64 / N as f64;
            let (h, _) = self.exact(r * r);
            let mut f = h * h;
            let mut e = 1;
            while e < d {
                f *= r;
                e += 1;
            }
            let w = if k == 0 || k == N {
                1.0
            } else if k % 2 == 1 {
                4.0
            } else {
                2.0
            };
            sum += w * f;
            k += 1;
        }
        sum / (3.0 * N as f64) * sphere_area(d)
    }
}

/// Where a squared distance falls in a kernel's table.
enum Knots<R> {
    /// Between two knots: the fraction, and the values and slopes (times the spacing).
    Inside(R, [R; 4]),
    /// At or below 0.
    Centre,
    /// At 1 or beyond (or NaN).
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

/// A kernel's table: `[ĥ(s), ĥ′(s)·Δ]` at `s = kΔ`, `Δ = 2^−shift`, Q2.30.
const fn table<const KNOTS: usize>(kernel: Kernel, shift: u32) -> [[i32; 2]; KNOTS] {
    let mut t = [[0i32; 2]; KNOTS];
    let mut k = 0;
    while k < KNOTS {
        let (v, d) = kernel.exact(k as f64 / (1 << shift) as f64);
        t[k] = [round(v * Q30), round(d / (1 << shift) as f64 * Q30)];
        k += 1;
    }
    t
}

/// Nearest integer (ties away from zero).
const fn round(v: f64) -> i32 {
    if v < 0.0 {
        -((-v + 0.5) as i32)
    } else {
        (v + 0.5) as i32
    }
}

static COSINE: [[i32; 2]; (1 << COSINE_SHIFT) + 1] = table(Kernel::Cosine, COSINE_SHIFT);
static CATMULL_ROM: [[i32; 2]; (1 << CATMULL_ROM_SHIFT) + 1] =
    table(Kernel::CatmullRom, CATMULL_ROM_SHIFT);

#[cfg(test)]
mod tests {
    use super::*;
    use crate::I16F16;

    /// The errors the module docs state.
    #[test]
    fn tables_follow_the_kernels() {
        for (kernel, inner, outer) in [
            (Kernel::Cosine, 1e-8, 1e-8),
            (Kernel::CatmullRom, 1.5e-4, 2e-6),
        ] {
            let (mut wi, mut wo) = (0.0f64, 0.0f64);
            for i in 0..=100_000 {
                let s = i as f64 / 100_000.0;
                let e = (kernel.at(s) - kernel.exact(s).0).abs();
                if s < 1.0 / 256.0 {
                    wi = wi.max(e);
                } else {
                    wo = wo.max(e);
                }
                // f32 and I16F16 add only their roundings.
                let e32 = (kernel.at(s as f32) as f64 - kernel.at(s as f32 as f64)).abs();
                assert!(e32 < 3e-7, "{kernel:?} {s} {e32}");
                let q = I16F16::from_num(s);
                let eq = (kernel.at(q).to_num::<f64>() - kernel.at(q.to_num::<f64>())).abs();
                assert!(eq < 1e-4, "{kernel:?} {s} {eq}");
            }
            assert!(wi < inner && wo < outer, "{kernel:?} {wi} {wo}");
        }
    }

    /// The slope is the derivative of the value (central differences of `at` in `f64`), and
    /// near the kernel's (in `f32` and I16F16 too).
    #[test]
    fn slopes_are_the_derivative() {
        for kernel in [Kernel::Cosine, Kernel::CatmullRom] {
            for i in 1..1000 {
                let s = i as f64 / 1000.0;
                let (v, g) = kernel.at_with_slope(s);
                assert_eq!(v, kernel.at(s));
                let e = 1e-6;
                let numeric = (kernel.at(s + e) - kernel.at(s - e)) / (2.0 * e);
                assert!((g - numeric).abs() < 1e-5, "{kernel:?} {s}: {g} {numeric}");
                if s > 1.0 / 64.0 {
                    assert!((g - kernel.exact(s).1).abs() < 2e-3, "{kernel:?} {s}");
                }
                let (_, g32) = kernel.at_with_slope(s as f32);
                assert!((g32 as f64 - g).abs() < 1e-4, "{kernel:?} {s}");
                let (_, gq) = kernel.at_with_slope(I16F16::from_num(s));
                let gq_want = kernel.at_with_slope(I16F16::from_num(s).to_num::<f64>()).1;
                assert!(
                    (gq.to_num::<f64>() - gq_want).abs() < 0.03,
                    "{kernel:?} {s}"
                );
            }
            assert_eq!(kernel.at_with_slope(2.0f32), (0.0, 0.0));
            let (v0, g0) = kernel.at_with_slope(0.0f64);
            assert_eq!(v0, 1.0);
            assert!((g0 - kernel.exact(0.0).1).abs() < 1e-7, "{kernel:?} {g0}");
        }
    }

    #[test]
    fn kernels_at_their_ends() {
        for k in [Kernel::Cosine, Kernel::CatmullRom] {
            assert_eq!(k.at(0.0f32), 1.0);
            assert_eq!(k.at(-1.0f32), 1.0);
            assert_eq!(k.at(1.0f32), 0.0);
            assert_eq!(k.at(f32::NAN), 0.0);
            assert_eq!(k.at(f32::INFINITY), 0.0);
            assert_eq!(k.at(I16F16::MAX), I16F16::ZERO);
            // Continuous at the rim: the last knot is 0.
            assert!(k.at(0.999_999f64).abs() < 1e-9);
        }
        // The Catmull-Rom spline's seam at d = ½ and its minimum, −2/27 at x = 4/3.
        assert!(Kernel::CatmullRom.exact(0.25).0.abs() < 1e-15);
        let min = Kernel::CatmullRom.exact(4.0 / 9.0).0;
        assert!((min + 2.0 / 27.0).abs() < 1e-12, "{min}");
    }

    /// ∫h² against closed forms: for the cosine in 2D, 3π/8 − 2/π; in 1D, 3/4; for the
    /// Catmull-Rom spline in 1D, 57/140.
    #[test]
    fn power_matches_closed_forms() {
        let pi = core::f64::consts::PI;
        let p2 = Kernel::Cosine.power(2);
        assert!((p2 - (3.0 * pi / 8.0 - 2.0 / pi)).abs() < 1e-10, "{p2}");
        let p1 = Kernel::Cosine.power(1);
        assert!((p1 - 0.75).abs() < 1e-10, "{p1}");
        // The Catmull-Rom spline in 1D: 2·∫₀¹ c(2r)² dr = ∫₀² c(x)² dx = 57/140 (exact
        // polynomial integrals).
        let c1 = Kernel::CatmullRom.power(1);
        assert!((c1 - 57.0 / 140.0).abs() < 1e-10, "{c1}");
    }
}

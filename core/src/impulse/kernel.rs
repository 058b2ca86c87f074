//! The radial kernels of sparse convolution noise, as functions of the squared distance (Lewis
//! 1989, §4: "remove square roots by indexing a pre-warped table `ĥ(d²) = h(√d²)`"): Lewis's
//! cosine from a table (the crate's radial tables), Peachey's spline from its formula.
//!
//! Each kernel has radius 1. Errors against the kernel in `f64` (tested; `f32` adds 3e-7 to the
//! cosine's and is within 1e-6 of the spline; I16F16 within 1e-4 and 3e-5, its square root
//! rounded to nearest):
//!
//! | kernel | evaluation | error |
//! |---|---|---|
//! | [`Kernel::Cosine`] | table of 33 knots, `Δ = 1/32` (264 B) | 1e-8 |
//! | [`Kernel::CatmullRom`] | its formula, with one square root (its `d³` term is not smooth in `d²`: a table would need many knots) | the type's rounding (I16F16: 3e-5) |

use crate::Real;
use crate::radial::{Profile, Table, knots, power_in, powers};

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

impl Kernel {
    /// The kernel at squared distance `d2`: `h(√d2)`, 0 from `d2 = 1` on; `d2 ≤ 0` gives
    /// `h(0) = 1`. From the kernel's table (see the module docs), in `[−2/27, 1]`.
    #[inline]
    #[must_use]
    pub fn at<R: Real>(self, d2: R) -> R {
        match self {
            Kernel::Cosine => COSINE.at(d2),
            Kernel::CatmullRom => catmull_rom::<R, false>(d2).0,
        }
    }

    /// [`at`](Self::at) and its derivative with respect to `d2` (the derivative of the same
    /// interpolant, so the pair is consistent): `∇_x h(|x|) = 2 x · dh/d(d²)`. At `d2 ≤ 0` the
    /// slope is the first knot's; from `d2 = 1` on both are 0. The slope is at most 10 in
    /// magnitude (the Catmull-Rom spline's at 0; the cosine's is at most `π²/4`).
    #[inline]
    #[must_use]
    pub fn at_with_slope<R: Real>(self, d2: R) -> (R, R) {
        match self {
            Kernel::Cosine => COSINE.at_with_slope(d2),
            Kernel::CatmullRom => catmull_rom::<R, true>(d2),
        }
    }

    /// The kernel at squared distance `s` (`h(√s)`) and its derivative with respect to `s`,
    /// in `f64`, from the kernel's formula (what the tables hold, and what tests compare
    /// with); both 0 from `s = 1` on.
    #[must_use]
    pub const fn exact(self, s: f64) -> (f64, f64) {
        self.profile().exact(s)
    }

    /// The kernel as a radial profile.
    const fn profile(self) -> Profile {
        match self {
            Kernel::Cosine => Profile::Cosine,
            Kernel::CatmullRom => Profile::CatmullRom,
        }
    }

    /// `∫ h(|x|)² dx` over `D`-dimensional space (for `D` in 1..=4), by Simpson's rule over
    /// the radius (512 intervals; a knot on the Catmull-Rom spline's seam at `d = ½`). It
    /// enters the variance by Campbell's theorem, `λ E[w²] ∫h²`.
    #[must_use]
    pub const fn power(self, d: usize) -> f64 {
        self.profile().integral(d, 2)
    }

    /// [`power`](Self::power) from a table built at compile time (the quadrature is slow
    /// without an FPU), for `d` in 1..=4.
    pub(crate) fn power_of(self, d: usize) -> f64 {
        const COSINE_POWERS: [f64; 4] = powers(Profile::Cosine);
        const CATMULL_ROM_POWERS: [f64; 4] = powers(Profile::CatmullRom);
        match self {
            Kernel::Cosine => power_in(&COSINE_POWERS, d),
            Kernel::CatmullRom => power_in(&CATMULL_ROM_POWERS, d),
        }
    }
}

/// The cosine's table: 33 knots, `Δ = 1/32`.
static COSINE: Table = Table::new(Profile::Cosine, &COSINE_KNOTS);
static COSINE_KNOTS: [[i32; 2]; 33] = knots(Profile::Cosine);

/// Peachey's spline at squared distance `s` from its formula (no table): with `d = √s`,
/// `1 − 10s + 12sd` below `d = ½` and `2(1 − d)²(1 − 2d)` from there to 1 (factored: no
/// cancellation in fixed point); and if `SLOPE` its derivative in `s`, `−10 + 18d` and
/// `−2(1 − d)(2 − 3d)/d` (else 0).
#[inline]
fn catmull_rom<R: Real, const SLOPE: bool>(s: R) -> (R, R) {
    if s.is_nan() || s >= R::ONE {
        return (R::ZERO, R::ZERO);
    }
    let s = if s > R::ZERO { s } else { R::ZERO };
    let d = s.sqrt();
    if s < R::from_ratio(1, 2) {
        // Integer multiples first (exact), then one rounded product.
        let value = R::ONE - s.mul_fraction(R::from_i32(10))
            + s.mul_fraction(R::from_i32(12)).mul_fraction(d);
        let slope = if SLOPE {
            d.mul_fraction(R::from_i32(18)) - R::from_i32(10)
        } else {
            R::ZERO
        };
        (value, slope)
    } else {
        let e = R::ONE - d;
        let e2 = e.mul_fraction(e);
        let value = (e2 + e2).mul_fraction(R::ONE - d - d);
        let slope = if SLOPE {
            -(e + e).mul_fraction(R::from_i32(2) - d - d - d).div(d)
        } else {
            R::ZERO
        };
        (value, slope)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::I16F16;

    /// The errors the module docs state.
    #[test]
    fn tables_follow_the_kernels() {
        for (kernel, inner, outer, single, fixed) in [
            (Kernel::Cosine, 1e-8, 1e-8, 3e-7, 1e-4),
            (Kernel::CatmullRom, 1e-14, 1e-14, 1e-6, 3e-5),
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
                assert!(e32 < single, "{kernel:?} {s} {e32}");
                let q = I16F16::from_num(s);
                let eq = (kernel.at(q).to_num::<f64>() - kernel.at(q.to_num::<f64>())).abs();
                assert!(eq < fixed, "{kernel:?} {s} {eq}");
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

//! `e^{−x}` and `cos 2πx` in every number type with `+ − ×` only, for the kernels of sparse
//! convolution and Gabor noise (Lewis 1989 §2.3; Lagae et al. 2009, eq. 1: a Gaussian envelope
//! `e^{−π a² r²}` times a harmonic `cos(2π F₀ ω·x)`).
//!
//! As [`erf`](crate::wavelet::erf) does, each function reads a table of knots computed at
//! compile time (`const fn` series in `f64`, stored in Q2.30) and interpolates it by cubic
//! Hermite polynomials, with the same operations in every type, so a value is the same on
//! every target: bit for bit in a given type, and the same number up to the type's precision
//! across `f32`, `f64` and I16F16. Errors against `libm` (tests below; `f32` and I16F16 add
//! the rounding of a few operations to the interpolation's error):
//!
//! | | knots | table | f64 | f32 | I16F16 |
//! |---|---|---|---|---|---|
//! | [`exp_neg`] on `[0, 16]`, 0 beyond | 257, step 1/16 | 1028 B | 1.2e-7 (4e-8 below 16) | 2e-7 | 1e-4 |
//! | [`cos_turns`], one quarter wave | 33, step 1/128 | 132 B | 2e-8 | 3e-7 | 1e-4 |
//!
//! `e^{−x}`'s derivative is `−e^{−x}` and `cos 2πx`'s is `−2π sin 2πx = −2π cos 2π(¼ − x)`,
//! so each table holds values only: the derivatives at the knots are read from it too.

use crate::Real;

/// Knots of [`exp_neg`] per unit, as a power of two.
const EXP_SHIFT: u32 = 4;
/// Knots of [`exp_neg`]: `[0, 16]` in steps of 1/16.
const EXP_KNOTS: usize = (16 << EXP_SHIFT) + 1;
/// Knots of [`cos_turns`] per turn, as a power of two.
const COS_SHIFT: u32 = 7;
/// Knots of [`cos_turns`]: a quarter turn in steps of 1/128.
const COS_KNOTS: usize = (1 << COS_SHIFT) / 4 + 1;
/// One in Q2.30.
const Q30: f64 = (1u64 << 30) as f64;
/// The knot spacing times the largest slope of `cos 2πx`, `2π/128`, in Q2.30: the derivative
/// times the spacing at a knot is `−COS_SLOPE · cos 2π(¼ − x)`.
const COS_SLOPE: i32 = (2.0 * core::f64::consts::PI / (1 << COS_SHIFT) as f64 * Q30 + 0.5) as i32;

/// `e^{−y}` for `0 ≤ y ≤ 16` in `f64`: the Taylor series of `e^{−y/32}`, squared five times.
pub(crate) const fn exp_neg_f64(y: f64) -> f64 {
    let x = -y / 32.0;
    let mut term = 1.0;
    let mut sum = 1.0;
    let mut k = 1;
    while k < 24 {
        term *= x / k as f64;
        sum += term;
        k += 1;
    }
    let mut i = 0;
    while i < 5 {
        sum *= sum;
        i += 1;
    }
    sum
}

/// `cos x` for `0 ≤ x ≤ π/2` in `f64`, by its Taylor series (30 terms: far below `f64`'s
/// precision there).
pub(crate) const fn cos_f64(x: f64) -> f64 {
    let mut term = 1.0;
    let mut sum = 1.0;
    let mut k = 1;
    while k < 30 {
        term *= -x * x / ((2 * k - 1) * (2 * k)) as f64;
        sum += term;
        k += 1;
    }
    sum
}

/// `cos 2πx` for `0 ≤ x ≤ 1` in `f64`: [`cos_f64`] on the quarter wave, folded (even about ½,
/// odd about ¼).
pub(crate) const fn cos_turn_f64(x: f64) -> f64 {
    let x = if x > 0.5 { 1.0 - x } else { x };
    if x > 0.25 {
        -cos_f64(2.0 * core::f64::consts::PI * (0.5 - x))
    } else {
        cos_f64(2.0 * core::f64::consts::PI * x)
    }
}

/// `[cos 2πx, sin 2πx]` for any finite `x` in `f64`, without `libm`'s trigonometry (whose
/// argument reduction tables the demo's size budget cannot hold): `x` is reduced modulo 1
/// exactly, then [`cos_turn_f64`]. For settings, not samples: out of line.
#[inline(never)]
pub(crate) fn cis_turns_f64(x: f64) -> [f64; 2] {
    let t = x - libm::floor(x);
    // sin 2πt = cos 2π(t − ¼), with t − ¼ taken back into [0, 1) (exact).
    let s = if t >= 0.25 { t - 0.25 } else { t + 0.75 };
    [cos_turn_f64(t), cos_turn_f64(s)]
}

/// `e^{−x}` at the knots, Q2.30.
static EXP_TABLE: [i32; EXP_KNOTS] = {
    let mut t = [0i32; EXP_KNOTS];
    let mut i = 0;
    while i < EXP_KNOTS {
        t[i] = (exp_neg_f64(i as f64 / (1 << EXP_SHIFT) as f64) * Q30 + 0.5) as i32;
        i += 1;
    }
    t
};

/// `cos 2πx` at the knots of a quarter turn, Q2.30.
static COS_TABLE: [i32; COS_KNOTS] = {
    let mut t = [0i32; COS_KNOTS];
    let mut i = 0;
    while i < COS_KNOTS {
        let x = i as f64 / (1 << COS_SHIFT) as f64;
        t[i] = (cos_f64(2.0 * core::f64::consts::PI * x) * Q30 + 0.5) as i32;
        i += 1;
    }
    t
};

/// The cubic Hermite basis `[h₀₀, h₁₀, h₀₁, h₁₁]` at `t ∈ [0, 1]`.
#[inline]
pub(crate) fn hermite_basis<R: Real>(t: R) -> [R; 4] {
    let t2 = t.mul_rn(t);
    let t3 = t2.mul_rn(t);
    let two_t3 = t3 + t3;
    let three_t2 = t2 + t2 + t2;
    [
        two_t3 - three_t2 + R::ONE,
        t3 - t2 - t2 + t,
        three_t2 - two_t3,
        t3 - t2,
    ]
}

/// The cubic Hermite interpolant at `t ∈ [0, 1]` between knots with values `v0`, `v1` and
/// derivatives times the knot spacing `d0`, `d1`: `h₀₀ v₀ + h₁₀ d₀ + h₀₁ v₁ + h₁₁ d₁`.
#[inline]
pub(crate) fn hermite<R: Real>(t: R, v0: R, d0: R, v1: R, d1: R) -> R {
    let [h00, h10, h01, h11] = hermite_basis(t);
    h00.mul_rn(v0) + h10.mul_rn(d0) + h01.mul_rn(v1) + h11.mul_rn(d1)
}

/// A Q2.30 table entry as `R`.
#[inline]
pub(crate) fn q30<R: Real>(v: i32) -> R {
    R::from_ratio(v, 30)
}

/// [`Real::exp_neg`].
#[inline]
pub(crate) fn exp_neg<R: Real>(x: R) -> R {
    if x.is_nan() || x >= R::from_i32(16) {
        return R::ZERO;
    }
    if x <= R::ZERO {
        return R::ONE;
    }
    let (i, t) = x.saturating_mul(R::from_i32(1 << EXP_SHIFT)).split();
    let i = i.clamp(0, EXP_KNOTS as i32 - 2) as usize;
    let (v0, v1) = (q30::<R>(EXP_TABLE[i]), q30::<R>(EXP_TABLE[i + 1]));
    // The derivative is −e^{−x}; times the spacing 1/16.
    let step = R::from_ratio(1, EXP_SHIFT);
    let (d0, d1) = (-v0.mul_rn(step), -v1.mul_rn(step));
    hermite(t, v0, d0, v1, d1).clamp_to(R::ZERO, R::ONE)
}

/// [`Real::cos_turns`]. Out of line in the demo's size-bound build, where Gabor noise's
/// walks would inline it at each of their call sites.
#[cfg_attr(feature = "small", inline(never))]
#[cfg_attr(not(feature = "small"), inline)]
pub(crate) fn cos_turns<R: Real>(x: R) -> R {
    let (_, t) = x.split();
    // cos 2πt is even about ½: fold t into [0, ½] (exact: Sterbenz), then into [0, ¼] with
    // cos 2πu = −cos 2π(½ − u).
    let half = R::from_ratio(1, 1);
    let u = if t > half { R::ONE - t } else { t };
    let quarter = R::from_ratio(1, 2);
    let (u, negative) = if u > quarter {
        (half - u, true)
    } else {
        (u, false)
    };
    let (i, f) = u.mul_rn(R::from_i32(1 << COS_SHIFT)).split();
    let last = COS_KNOTS as i32 - 1;
    let v = if i >= last || i < 0 {
        // u = ¼ exactly: the zero of the cosine.
        R::ZERO
    } else {
        let i = i as usize;
        // The derivative times the spacing: −2π/128 · cos 2π(¼ − x), read from the table.
        let scale = q30::<R>(COS_SLOPE);
        let (v0, v1) = (q30::<R>(COS_TABLE[i]), q30::<R>(COS_TABLE[i + 1]));
        let d0 = -q30::<R>(COS_TABLE[COS_KNOTS - 1 - i]).mul_rn(scale);
        let d1 = -q30::<R>(COS_TABLE[COS_KNOTS - 2 - i]).mul_rn(scale);
        hermite(f, v0, d0, v1, d1).clamp_to(R::ZERO, R::ONE)
    };
    (if negative { -v } else { v }).canonical()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::I16F16;

    /// The errors the module's table states, over a dense sweep, in each type.
    #[test]
    fn exp_neg_matches_libm() {
        let (mut w64, mut w32, mut wq) = (0.0f64, 0.0f64, 0.0f64);
        for i in 0..=20_000 {
            let x = i as f64 / 1000.0;
            let want = libm::exp(-x);
            w64 = w64.max((exp_neg(x) - want).abs());
            w32 = w32.max((exp_neg(x as f32) as f64 - libm::exp(-(x as f32 as f64))).abs());
            let q = I16F16::from_num(x);
            wq = wq.max((exp_neg(q).to_num::<f64>() - libm::exp(-q.to_num::<f64>())).abs());
        }
        assert!(w64 < 1.2e-7 && w32 < 2e-7 && wq < 1e-4, "{w64} {w32} {wq}");
        // Below the cut-off at 16, the interpolation's own error.
        let inner = (0..=15_000).map(|i| i as f64 / 1000.0);
        let w = inner
            .map(|x| (exp_neg(x) - libm::exp(-x)).abs())
            .fold(0.0, f64::max);
        assert!(w < 4e-8, "{w}");
        assert_eq!(exp_neg(0.0f32), 1.0);
        assert_eq!(exp_neg(-3.0f32), 1.0);
        assert_eq!(exp_neg(f32::INFINITY), 0.0);
        assert_eq!(exp_neg(f32::NAN), 0.0);
        assert_eq!(exp_neg(I16F16::MAX), I16F16::ZERO);
        assert_eq!(exp_neg(I16F16::MIN), I16F16::ONE);
    }

    #[test]
    fn cos_turns_matches_libm() {
        let (mut w64, mut w32, mut wq) = (0.0f64, 0.0f64, 0.0f64);
        for i in -40_000..=40_000 {
            let x = i as f64 / 10_000.0 + 1e-5;
            let want = |x: f64| libm::cos(2.0 * core::f64::consts::PI * x);
            w64 = w64.max((cos_turns(x) - want(x)).abs());
            w32 = w32.max((cos_turns(x as f32) as f64 - want(x as f32 as f64)).abs());
            let q = I16F16::from_num(x);
            wq = wq.max((cos_turns(q).to_num::<f64>() - want(q.to_num::<f64>())).abs());
        }
        assert!(w64 < 2e-8 && w32 < 3e-7 && wq < 1e-4, "{w64} {w32} {wq}");
        // Exact where the cosine is 0 or ±1, in every type.
        for (x, want) in [
            (0.0, 1.0),
            (0.25, 0.0),
            (0.5, -1.0),
            (0.75, 0.0),
            (-2.0, 1.0),
        ] {
            assert_eq!(cos_turns(x), want, "{x}");
            assert_eq!(cos_turns(x as f32), want as f32, "{x}");
            assert_eq!(
                cos_turns(I16F16::from_num(x)),
                I16F16::from_num(want),
                "{x}"
            );
        }
        assert_eq!(cos_turns(f32::NAN), 1.0);
        assert_eq!(cos_turns(f32::NEG_INFINITY), 1.0);
        assert_eq!(cos_turns(1e30f32), 1.0);
        assert_eq!(cos_turns(I16F16::MIN), I16F16::ONE);
    }

    /// Even: cos 2π(−x) = cos 2πx bit for bit, wherever the fraction of −x, 1 − x, is exact.
    #[test]
    fn cos_turns_is_even() {
        for i in 1..4096 {
            let x = i as f32 / 4096.0;
            assert_eq!(cos_turns(x).to_bits(), cos_turns(-x).to_bits(), "{x}");
        }
    }
}

//! The error function for remapping Gaussian noise to a uniform distribution (Cook & DeRose
//! 2005, §4.2; Abramowitz & Stegun 7.1), in every number type with `+ − ×` only.
//!
//! A table of `erf` and its derivative at 65 knots over `[0, 4]` (step 1/16) is computed at
//! compile time, stored in Q2.30, and interpolated by cubic Hermite polynomials (error below
//! 1e-6); beyond 4, `erf = ±1` to within 1.6e-8.

use crate::Real;
use crate::special::{exp_neg_f64 as exp_neg, hermite_basis};

const KNOTS: usize = 65;
const STEP_SHIFT: u32 = 4; // knots every 2^-4

/// `erf(x) = (2/√π) e^{−x²} Σ_n 2^n x^{2n+1} / (2n+1)!!` (all terms positive: no cancellation).
const fn erf_series(x: f64) -> f64 {
    let mut term = x;
    let mut sum = x;
    let mut n = 0;
    while n < 120 {
        term *= 2.0 * x * x / (2 * n + 3) as f64;
        sum += term;
        n += 1;
    }
    core::f64::consts::FRAC_2_SQRT_PI * exp_neg(x * x) * sum
}

/// `(erf, erf')` at every knot, in Q2.30.
const TABLE: [[i32; 2]; KNOTS] = {
    let mut t = [[0i32; 2]; KNOTS];
    let mut i = 0;
    while i < KNOTS {
        let x = i as f64 / (1 << STEP_SHIFT) as f64;
        let scale = (1u64 << 30) as f64;
        t[i][0] = (erf_series(x) * scale + 0.5) as i32;
        t[i][1] = (core::f64::consts::FRAC_2_SQRT_PI * exp_neg(x * x) * scale + 0.5) as i32;
        i += 1;
    }
    t
};

/// `erf(x)`, to within 1e-6 in floating point and 1e-4 in I16F16. `erf(±∞) = ±1`; NaN gives 0.
#[must_use]
#[inline]
pub fn erf<R: Real>(x: R) -> R {
    erf_with_derivative(x).0
}

/// `erf(x)` (bit for bit [`erf`]) and the derivative of the interpolant that computes it: the
/// derivative of the cubic Hermite piece, `(h₀₀′ e₀ + h₁₀′ h e₀′ + h₀₁′ e₁ + h₁₁′ h e₁′)/h`, which
/// approximates `2/√π e^{−x²}`; 0 where `erf` is the constant ±1.
#[must_use]
#[inline]
pub(crate) fn erf_with_derivative<R: Real>(x: R) -> (R, R) {
    if x.is_nan() {
        return (R::ZERO, R::ZERO);
    }
    let negative = x < R::ZERO;
    let a = x.abs();
    let one = if negative { -R::ONE } else { R::ONE };
    // Beyond the table (and for ±∞, which `split` would send to the origin): ±1.
    if a >= R::from_i32(4) {
        return (one, R::ZERO);
    }
    let scaled = a.saturating_mul(R::from_i32(1 << STEP_SHIFT));
    let (i, t) = scaled.split();
    if i < 0 || i as usize >= KNOTS - 1 {
        return (one, R::ZERO);
    }
    let (k0, k1) = (TABLE[i as usize], TABLE[i as usize + 1]);
    let q = |v: i32| R::from_ratio(v, 30);
    let h = R::from_ratio(1, STEP_SHIFT);
    let [h00, h10, h01, h11] = hermite_basis(t);
    let v = h00.mul_rn(q(k0[0]))
        + h10.mul_rn(h).mul_rn(q(k0[1]))
        + h01.mul_rn(q(k1[0]))
        + h11.mul_rn(h).mul_rn(q(k1[1]));
    let v = v.clamp_to(R::ZERO, R::ONE);
    // d/dt of the basis: 6t² − 6t, 3t² − 4t + 1, −(6t² − 6t), 3t² − 2t; dt/dx = 1/h = 16.
    let t2 = t.mul_rn(t);
    let three_t2 = t2 + t2 + t2;
    let six = three_t2 + three_t2 - (t + t + t) - (t + t + t);
    let d10 = three_t2 - (t + t + t + t) + R::ONE;
    let d11 = three_t2 - t - t;
    let slope = (six.mul_rn(q(k0[0]) - q(k1[0]))
        + d10.mul_rn(h).mul_rn(q(k0[1]))
        + d11.mul_rn(h).mul_rn(q(k1[1])))
    .mul_rn(R::from_i32(1 << STEP_SHIFT));
    // erf is odd, so its derivative is even: the same slope on both sides.
    (if negative { -v } else { v }, slope)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::I16F16;

    #[test]
    fn erf_matches_libm() {
        let mut worst = 0.0f64;
        let mut worst_fixed = 0.0f64;
        for i in -6000..=6000 {
            let x = i as f64 / 1000.0;
            let want = libm::erf(x);
            worst = worst.max((erf(x) - want).abs());
            worst = worst.max((erf(x as f32) as f64 - want).abs() - 1e-7);
            worst_fixed = worst_fixed.max((erf(I16F16::from_num(x)).to_num::<f64>() - want).abs());
        }
        assert!(worst < 1e-6, "{worst}");
        assert!(worst_fixed < 1e-4, "{worst_fixed}");
        assert_eq!(erf(f32::NAN), 0.0);
        assert_eq!(erf(f32::INFINITY), 1.0);
        assert_eq!(erf(I16F16::MIN), -I16F16::ONE);
    }

    /// The interpolant's derivative is close to erf′ = 2/√π e^{−x²}, in f64 and in fixed point.
    #[test]
    fn erf_derivative_matches_the_exact_one() {
        let mut worst = 0.0f64;
        let mut worst_fixed = 0.0f64;
        for i in -4500..=4500 {
            let x = i as f64 / 1000.0;
            let want = core::f64::consts::FRAC_2_SQRT_PI * libm::exp(-x * x);
            let want = if x.abs() >= 4.0 { 0.0 } else { want };
            worst = worst.max((erf_with_derivative(x).1 - want).abs());
            let (_, d) = erf_with_derivative(I16F16::from_num(x));
            worst_fixed = worst_fixed.max((d.to_num::<f64>() - want).abs());
            assert_eq!(erf_with_derivative(x).0.to_bits(), erf(x).to_bits());
        }
        assert!(worst < 1e-4, "{worst}");
        assert!(worst_fixed < 2e-3, "{worst_fixed}");
    }
}

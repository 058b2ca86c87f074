//! The machinery every lattice noise shares: splitting a point into a cell and a fraction,
//! fading, and multilinear interpolation (with its analytic gradient). The corners are hashed
//! through the crate's hashing seam (`hash/chain.rs`).
//!
//! Corners are indexed by a bit mask: bit `a` set means the upper corner along axis `a`.
//! Interpolation runs along axis 0 first, then 1, …, exactly in the order of Perlin's reference
//! code, so that f64 results match it bit for bit.

use crate::Real;

pub(crate) use crate::hash::chain::MAX_CORNERS;

/// Splits every coordinate into a cell and a fraction in `[0, 1)` (see [`Real::split`]).
#[inline]
pub(crate) fn split_point<R: Real, const D: usize>(p: [R; D]) -> ([i32; D], [R; D]) {
    const { assert!(D >= 1 && D <= 4, "lattice noises have 1 to 4 dimensions") };
    let mut cell = [0i32; D];
    let mut frac = [R::ZERO; D];
    for a in 0..D {
        (cell[a], frac[a]) = p[a].split();
    }
    (cell, frac)
}

/// Perlin's `lerp(t, a, b) = a + t·(b − a)` (this form, not `(1−t)a + tb`, for his exact values),
/// for a weight `t` in `[0, 2]` (a faded fraction; see [`Fade`]) and corner values below 2¹³.
#[inline]
pub(crate) fn lerp<R: Real>(t: R, a: R, b: R) -> R {
    a + t.mul_fraction(b - a)
}

/// A fade curve applied to each fraction before interpolating. Every product has a factor in
/// `[0, 1]` (`mul_fraction`, the cheap fixed-point multiply), and the curve stays in `[0, 1]`
/// up to rounding: I16F16 reaches `1 + 2⁻¹⁶` (the quintic at a few fractions, tested over all
/// of them), f32 `1 + 9·2⁻²³` (the quintic near 0.998; an exhaustive search over every f32
/// fraction, too slow for the tests, found no more), well inside the `[0, 2]` that lets it
/// weight [`lerp`].
pub(crate) trait Fade {
    /// The curve at `t` in `[0, 1)`.
    fn fade<R: Real>(t: R) -> R;
    /// Its derivative.
    fn fade_derivative<R: Real>(t: R) -> R;
}

/// Perlin's 2002 quintic `6t⁵ − 15t⁴ + 10t³` (C² continuous).
pub(crate) struct Quintic;

impl Fade for Quintic {
    #[inline]
    fn fade<R: Real>(t: R) -> R {
        // Perlin's operation order: t·t·t·(t·(t·6 − 15) + 10).
        let t3 = t.mul_fraction(t).mul_fraction(t);
        t3.mul_fraction(
            t.mul_fraction(t.mul_fraction(R::from_i32(6)) - R::from_i32(15)) + R::from_i32(10),
        )
    }
    #[inline]
    fn fade_derivative<R: Real>(t: R) -> R {
        // 30 t² (t − 1)², with u = t(1 − t) in [0, 1/4] (−u is exact, and (−u)² = u² exactly
        // in every type, so the bits are those of squaring t(t − 1)).
        let u = -t.mul_fraction(t - R::ONE);
        u.mul_fraction(u).mul_fraction(R::from_i32(30))
    }
}

/// Perlin's 1985 cubic `3t² − 2t³` (C¹ continuous).
pub(crate) struct Cubic;

impl Fade for Cubic {
    #[inline]
    fn fade<R: Real>(t: R) -> R {
        t.mul_fraction(t).mul_fraction(R::from_i32(3) - t - t)
    }
    #[inline]
    fn fade_derivative<R: Real>(t: R) -> R {
        // 6 t (1 − t)
        t.mul_fraction(R::ONE - t).mul_fraction(R::from_i32(6))
    }
}

/// The offset from corner `m` to the point: `f − corner`.
#[inline]
pub(crate) fn corner_offset<R: Real, const D: usize>(f: &[R; D], f1: &[R; D], m: usize) -> [R; D] {
    let mut d = [R::ZERO; D];
    for a in 0..D {
        d[a] = if m >> a & 1 == 0 { f[a] } else { f1[a] };
    }
    d
}

/// `Σ_a d_a·g_a` in axis order, each product by `mul`.
#[inline]
pub(crate) fn sum_of_products<R: Real, const D: usize>(
    d: &[R; D],
    g: &[R; D],
    mul: impl Fn(R, R) -> R,
) -> R {
    let mut sum = mul(d[0], g[0]);
    for a in 1..D {
        sum = sum + mul(d[a], g[a]);
    }
    sum
}

/// `f − 1` for every fraction.
#[inline]
pub(crate) fn minus_one<R: Real, const D: usize>(f: &[R; D]) -> [R; D] {
    f.map(|x| x - R::ONE)
}

/// Multilinear interpolation of `2^D` corner values along axis 0, then 1, … with weights `t`.
#[inline]
pub(crate) fn interpolate<R: Real, const D: usize>(mut v: [R; MAX_CORNERS], t: &[R; D]) -> R {
    let mut n = 1 << D;
    for ta in t {
        n >>= 1;
        for j in 0..n {
            v[j] = lerp(*ta, v[2 * j], v[2 * j + 1]);
        }
    }
    v[0]
}

/// `∂/∂t_axis` of [`interpolate`] times `dt`: the same reduction, with the lerp along `axis`
/// replaced by `dt · (b − a)`.
#[inline]
fn interpolate_derivative<R: Real, const D: usize>(
    mut v: [R; MAX_CORNERS],
    t: &[R; D],
    axis: usize,
    dt: R,
) -> R {
    let mut n = 1 << D;
    for (a, ta) in t.iter().enumerate() {
        n >>= 1;
        for j in 0..n {
            v[j] = if a == axis {
                dt.mul_rn(v[2 * j + 1] - v[2 * j])
            } else {
                lerp(*ta, v[2 * j], v[2 * j + 1])
            };
        }
    }
    v[0]
}

/// Value and gradient of a gradient-noise cell: `n = Σ_c W_c(s) (g_c · d_c)`, so
/// `∂n/∂f_a = Σ_c ∂W_c/∂f_a (g_c · d_c) + Σ_c W_c g_{c,a}`.
///
/// `dots[m] = g_m · d_m`, `grads[m] = g_m`, `s` the faded fractions and `ds` the fade's
/// derivative at each fraction. The value is computed exactly as [`interpolate`] does.
#[inline]
pub(crate) fn interpolate_with_gradient<R: Real, const D: usize>(
    dots: [R; MAX_CORNERS],
    grads: &[[R; D]; MAX_CORNERS],
    s: &[R; D],
    ds: &[R; D],
) -> (R, [R; D]) {
    let value = interpolate(dots, s);
    let mut gradient = [R::ZERO; D];
    for (a, g) in gradient.iter_mut().enumerate() {
        let mut component = [R::ZERO; MAX_CORNERS];
        for m in 0..(1 << D) {
            component[m] = grads[m][a];
        }
        *g = (interpolate_derivative(dots, s, a, ds[a]) + interpolate(component, s)).canonical();
    }
    (value.canonical(), gradient)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::I16F16;

    /// The fades stay in `[0, 1]` up to rounding (so they can weight `lerp` through
    /// `mul_fraction`): in `[0, 1 + 2⁻¹⁶]` for every I16F16 fraction (the quintic reaches the
    /// upper end, at 0xfdd0 for one), in `[0, 1 + 9·2⁻²³]` (the exhaustive maximum, see
    /// [`Fade`]) for the f32 fractions nearest 0 and 1 and a spread between.
    #[test]
    fn fades_stay_in_the_unit_interval() {
        fn check<F: Fade>() {
            let top = I16F16::ONE + I16F16::DELTA;
            for bits in 0..0x1_0000 {
                let s = F::fade(I16F16::from_bits(bits));
                assert!((I16F16::ZERO..=top).contains(&s), "{bits:#x}: {s}");
            }
            let below_one = (0..1 << 20).map(|i| f32::from_bits(1.0f32.to_bits() - 1 - i));
            let spread = (0..1 << 20).map(|i| i as f32 / (1 << 20) as f32 + 1e-7);
            let near_zero = (0..1 << 16).map(f32::from_bits);
            for t in below_one.chain(spread).chain(near_zero) {
                let s = F::fade(t);
                let top = f32::from_bits(1.0f32.to_bits() + 9);
                assert!((0.0..=top).contains(&s), "{t}: {s}");
            }
        }
        check::<Quintic>();
        check::<Cubic>();
    }
}

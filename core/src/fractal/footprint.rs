//! Anti-aliasing by octave clamping (pbrt §10.6.3): from the footprint of a sample, the number of
//! octaves whose frequencies stay below the Nyquist limit.

use crate::Real;

/// Octaves to sum for a footprint, as pbrt computes them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Clamp<R> {
    /// Octaves summed in full.
    pub full: u32,
    /// The weight of octave `full` (faded in), or 0 when `full` is the maximum.
    pub partial: R,
}

/// `max(|dpdx|², |dpdy|²)` with saturating arithmetic (so fixed point cannot overflow).
pub(crate) fn footprint_len2<R: Real, const D: usize>(dpdx: &[R; D], dpdy: &[R; D]) -> R {
    let len2 = |v: &[R; D]| {
        v.iter()
            .fold(R::ZERO, |acc, x| acc.saturating_add(x.saturating_mul(*x)))
    };
    let (a, b) = (len2(dpdx), len2(dpdy));
    // IEEE maxNum, symmetric: a NaN footprint (unknown) gives way to the other, and if both
    // are NaN the result stays NaN, which `octaves_for` treats as no filtering.
    if a.is_nan() || b > a { b } else { a }
}

/// pbrt's `n = clamp(−1 − ½·log2(len²), 0, max)`: `full = floor(n)` octaves in full, then
/// octave `full` faded in by `smoothstep(0.3, 0.7, n − full)`.
///
/// A footprint of 0 or NaN (so fine it cannot alias, or unknown) gives every octave; an infinite
/// one gives none.
pub(crate) fn octaves_for<R: Real>(len2: R, max: u32) -> Clamp<R> {
    let max_r = R::from_i32(max as i32);
    let half = R::from_ratio(1, 1);
    let n = (-R::ONE - half * len2.log2()).clamp_to(R::ZERO, max_r);
    let n = if len2.is_nan() { max_r } else { n };
    let (full, frac) = n.split();
    // max(0).min(..), not clamp: clamp asserts its bounds, a panic path (firmware/nopanic).
    let full = (full.max(0) as u32).min(max);
    if full >= max {
        return Clamp {
            full: max,
            partial: R::ZERO,
        };
    }
    Clamp {
        full,
        partial: smoothstep(R::from_f32(0.3), R::from_f32(0.7), frac),
    }
}

/// pbrt's `SmoothStep(lo, hi, x)`: 0 below `lo`, 1 above `hi`, `v²(3 − 2v)` between.
fn smoothstep<R: Real>(lo: R, hi: R, x: R) -> R {
    if x <= lo {
        return R::ZERO;
    }
    if x >= hi {
        return R::ONE;
    }
    // (x − lo)/(hi − lo) with hi − lo = 0.4: multiply by 2.5 (no division in the kernels).
    let v = (x - lo) * R::from_ratio(5, 1);
    v * v * (R::from_i32(3) - v - v)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn octave_counts() {
        // Footprint 1/2^k: n = -1 + k octaves.
        let c = octaves_for(1.0f32 / 4096.0 / 4096.0, 8); // k = 12 → n = 11, clamped to 8
        assert_eq!(
            c,
            Clamp {
                full: 8,
                partial: 0.0
            }
        );
        let c = octaves_for(1.0f32 / 64.0 / 64.0, 8); // k = 6 → n = 5 exactly
        assert_eq!(
            c,
            Clamp {
                full: 5,
                partial: 0.0
            }
        );
        let c = octaves_for(0.0f32, 8);
        assert_eq!(c.full, 8);
        let c = octaves_for(f32::NAN, 8);
        assert_eq!(c.full, 8);
        let c = octaves_for(f32::INFINITY, 8);
        assert_eq!(
            c,
            Clamp {
                full: 0,
                partial: 0.0
            }
        );
        // n = 2.5: two full octaves, the third half faded in.
        let len2 = libm::exp2f(-7.0);
        let c = octaves_for(len2, 8);
        assert_eq!(c.full, 2);
        assert!((c.partial - 0.5).abs() < 1e-6);
    }

    #[test]
    fn smoothstep_shape() {
        assert_eq!(smoothstep(0.3f32, 0.7, 0.2), 0.0);
        assert_eq!(smoothstep(0.3f32, 0.7, 0.9), 1.0);
        assert!((smoothstep(0.3f32, 0.7, 0.5) - 0.5).abs() < 1e-6);
    }
}

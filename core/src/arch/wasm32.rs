//! The WebAssembly kernels of [`arch`](super), in builds with the `simd128` target feature
//! (every browser since 2021–2023; the npm package and the demo are built with it) and without
//! the crate's `small` feature (whose size budget keeps the portable kernel): the 4-lane vector
//! Perlin's point kernels ([`vector`](super::vector)) run on, and `f32x4.sqrt`. The intrinsics
//! of `core::arch::wasm32` are safe functions (an engine without SIMD refuses the module when
//! it loads; it never runs an instruction it lacks).

use core::arch::wasm32::{
    f32x4, f32x4_abs, f32x4_add, f32x4_convert_i32x4, f32x4_extract_lane, f32x4_gt, f32x4_lt,
    f32x4_mul, f32x4_splat, f32x4_sqrt, f32x4_sub, i32x4_add, i32x4_bitmask, i32x4_extract_lane,
    i32x4_shuffle, i32x4_trunc_sat_f32x4, u64x2, v128, v128_and, v128_andnot, v128_not,
};

use super::vector::Lanes;

/// The vector the Perlin point kernels run on.
pub(super) type F32x4 = v128;

/// Not measured in WebAssembly yet: the octaves one by one, as on scalar cores.
pub(crate) const OCTAVES_AS_LANES: bool = false;

impl Lanes for v128 {
    #[inline]
    fn from_array([a, b, c, d]: [f32; 4]) -> Self {
        f32x4(a, b, c, d)
    }
    #[inline]
    fn from_halves(lo: &f64, hi: &f64) -> Self {
        u64x2(lo.to_bits(), hi.to_bits())
    }
    #[inline]
    fn load(row: &[f32; 4]) -> Self {
        // Four adjacent loads: one `v128.load` once compiled.
        f32x4(row[0], row[1], row[2], row[3])
    }
    #[inline]
    fn splat(v: f32) -> Self {
        f32x4_splat(v)
    }
    #[inline]
    fn add(self, o: Self) -> Self {
        f32x4_add(self, o)
    }
    #[inline]
    fn sub(self, o: Self) -> Self {
        f32x4_sub(self, o)
    }
    #[inline]
    fn mul(self, o: Self) -> Self {
        f32x4_mul(self, o)
    }
    #[inline]
    fn broadcast<const L: usize>(self) -> Self {
        match L {
            0 => i32x4_shuffle::<0, 0, 0, 0>(self, self),
            1 => i32x4_shuffle::<1, 1, 1, 1>(self, self),
            2 => i32x4_shuffle::<2, 2, 2, 2>(self, self),
            _ => i32x4_shuffle::<3, 3, 3, 3>(self, self),
        }
    }
    #[inline]
    fn evens(self, b: Self) -> Self {
        i32x4_shuffle::<0, 2, 4, 6>(self, b)
    }
    #[inline]
    fn odds(self, b: Self) -> Self {
        i32x4_shuffle::<1, 3, 5, 7>(self, b)
    }
    #[inline]
    fn interleave_low(self, b: Self) -> Self {
        i32x4_shuffle::<0, 4, 1, 5>(self, b)
    }
    #[inline]
    fn interleave_high(self, b: Self) -> Self {
        i32x4_shuffle::<2, 6, 3, 7>(self, b)
    }
    #[inline]
    fn low_halves(self, b: Self) -> Self {
        i32x4_shuffle::<0, 1, 4, 5>(self, b)
    }
    #[inline]
    fn high_half(self) -> Self {
        i32x4_shuffle::<2, 3, 2, 3>(self, self)
    }
    #[inline]
    fn low_pairs(self) -> Self {
        i32x4_shuffle::<0, 0, 1, 1>(self, self)
    }
    #[inline]
    fn high_pairs(self) -> Self {
        i32x4_shuffle::<2, 2, 3, 3>(self, self)
    }
    #[inline]
    fn first(self) -> f32 {
        f32x4_extract_lane::<0>(self)
    }
    #[inline]
    fn signs(self) -> u32 {
        u32::from(i32x4_bitmask(self))
    }
    #[inline]
    fn signs_without(self, clear: Self) -> u32 {
        u32::from(i32x4_bitmask(v128_andnot(self, clear)))
    }
    #[inline]
    fn split(self, axes: u32) -> Option<([usize; 4], Self)> {
        // floor: truncate, then one down where truncation rounded up (negative non-integers).
        let t = i32x4_trunc_sat_f32x4(self);
        let above = f32x4_gt(f32x4_convert_i32x4(t), self);
        let cell = i32x4_add(t, above);
        let f = f32x4_sub(self, f32x4_convert_i32x4(cell));
        // Outside (−2^31, 2^31) or NaN (the conversion saturates there, and the fraction may
        // then be in [0, 1)); the kernels test the fractions of the others.
        let invalid = v128_not(f32x4_lt(f32x4_abs(self), f32x4_splat(2_147_483_648.0)));
        if u32::from(i32x4_bitmask(invalid)) & axes != 0 {
            return None;
        }
        let cells = [
            i32x4_extract_lane::<0>(cell) as usize & 255,
            i32x4_extract_lane::<1>(cell) as usize & 255,
            i32x4_extract_lane::<2>(cell) as usize & 255,
            i32x4_extract_lane::<3>(cell) as usize & 255,
        ];
        Some((cells, f))
    }
}

/// [`Real::sqrt`](crate::Real::sqrt) of 16 lanes, four at a time: `f32x4.sqrt`, then 0
/// wherever the lane is not above 0 (negative, zero or NaN), as the scalar `sqrt` gives. Both
/// square roots are IEEE's, correctly rounded: the same bits.
#[inline]
pub(crate) fn sqrt_lanes(x: &mut [f32; crate::batch::LANES]) {
    for quad in x.chunks_exact_mut(4) {
        let v = f32x4(quad[0], quad[1], quad[2], quad[3]);
        let root = v128_and(f32x4_sqrt(v), f32x4_gt(v, f32x4_splat(0.0)));
        quad.copy_from_slice(&[
            f32x4_extract_lane::<0>(root),
            f32x4_extract_lane::<1>(root),
            f32x4_extract_lane::<2>(root),
            f32x4_extract_lane::<3>(root),
        ]);
    }
}

/// No simplex corner kernel yet in WebAssembly: the portable body runs (compiled with
/// `simd128`, it vectorises).
pub(crate) const SIMPLEX_CORNERS: bool = false;

#[inline]
pub(crate) fn simplex_corners<const D: usize>(
    _: &super::SimplexLanes<'_, D>,
    _: &mut [f32; crate::batch::LANES],
) -> bool {
    false
}

/// No simplex point kernel: the portable body runs.
pub(crate) const SIMPLEX_POINT: bool = false;

#[inline]
pub(crate) fn simplex_point<const D: usize>(
    _: [i32; D],
    _: [f32; D],
    _: &super::SimplexConstants,
) -> Option<f32> {
    None
}

/// No cellular near-cell kernel: the portable body runs.
pub(crate) const CELLULAR_NEAR: bool = false;

#[inline]
pub(crate) fn cellular_near<const D: usize>(
    _: [f32; D],
    _: &super::CellularCells<'_>,
    _: &mut super::NearPair,
) -> Option<([i32; D], [f32; D])> {
    None
}

/// No vector split (its test's entry point).
#[cfg(test)]
pub(crate) fn split_point<const D: usize>(_: [f32; D]) -> Option<([i32; D], [f32; D])> {
    None
}

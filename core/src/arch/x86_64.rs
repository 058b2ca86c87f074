//! The x86-64 kernels of [`arch`](super) (SSE2, which every x86-64 processor has): the 4-lane
//! vector Perlin's point kernels ([`vector`](super::vector)) run on, and `sqrtps`. The
//! intrinsics are the safe wrappers of `safe_arch`, so the crate keeps
//! `#![forbid(unsafe_code)]`.

use safe_arch::{
    add_i32_m128i, add_m128, bitand_m128, bitor_m128, cast_to_m128_from_m128i,
    cast_to_m128i_from_m128, cmp_eq_mask_i32_m128i, cmp_ge_mask_m128, cmp_gt_mask_m128,
    convert_to_m128_from_i32_m128i, extract_i16_as_i32_m128i, get_f32_from_m128_s,
    get_i32_from_m128i_s, load_unaligned_m128, m128, move_high_low_m128, move_low_high_m128,
    move_mask_m128, mul_m128, set_splat_i32_m128i, set_splat_m128, shuffle_abi_f32_all_m128,
    sqrt_m128, sub_m128, transpose_four_m128, truncate_m128_to_m128i, unpack_high_m128,
    unpack_low_m128, zeroed_m128,
};

use super::vector::Lanes;

/// The vector the Perlin point kernels run on.
pub(super) type F32x4 = m128;

/// SSE2 interpolates four octaves in one vector (`bench/README.md`: 0.7× the octaves one by one).
pub(crate) const OCTAVES_AS_LANES: bool = true;

impl Lanes for m128 {
    #[inline]
    fn from_array(a: [f32; 4]) -> Self {
        m128::from_array(a)
    }
    #[inline]
    fn load(row: &[f32; 4]) -> Self {
        load_unaligned_m128(row)
    }
    #[inline]
    fn splat(v: f32) -> Self {
        set_splat_m128(v)
    }
    #[inline]
    fn add(self, o: Self) -> Self {
        add_m128(self, o)
    }
    #[inline]
    fn sub(self, o: Self) -> Self {
        sub_m128(self, o)
    }
    #[inline]
    fn mul(self, o: Self) -> Self {
        mul_m128(self, o)
    }
    #[inline]
    fn broadcast<const L: usize>(self) -> Self {
        match L {
            0 => shuffle_abi_f32_all_m128::<0b00_00_00_00>(self, self),
            1 => shuffle_abi_f32_all_m128::<0b01_01_01_01>(self, self),
            2 => shuffle_abi_f32_all_m128::<0b10_10_10_10>(self, self),
            _ => shuffle_abi_f32_all_m128::<0b11_11_11_11>(self, self),
        }
    }
    #[inline]
    fn evens(self, b: Self) -> Self {
        shuffle_abi_f32_all_m128::<0b10_00_10_00>(self, b)
    }
    #[inline]
    fn odds(self, b: Self) -> Self {
        shuffle_abi_f32_all_m128::<0b11_01_11_01>(self, b)
    }
    #[inline]
    fn interleave_low(self, b: Self) -> Self {
        unpack_low_m128(self, b)
    }
    #[inline]
    fn interleave_high(self, b: Self) -> Self {
        unpack_high_m128(self, b)
    }
    #[inline]
    fn low_halves(self, b: Self) -> Self {
        move_low_high_m128(self, b)
    }
    #[inline]
    fn high_half(self) -> Self {
        move_high_low_m128(self, self)
    }
    #[inline]
    fn low_pairs(self) -> Self {
        shuffle_abi_f32_all_m128::<0b01_01_00_00>(self, self)
    }
    #[inline]
    fn high_pairs(self) -> Self {
        shuffle_abi_f32_all_m128::<0b11_11_10_10>(self, self)
    }
    #[inline]
    fn first(self) -> f32 {
        get_f32_from_m128_s(self)
    }
    #[inline]
    fn transpose([mut a, mut b, mut c, mut d]: [Self; 4]) -> [Self; 4] {
        transpose_four_m128(&mut a, &mut b, &mut c, &mut d);
        [a, b, c, d]
    }
    #[inline]
    fn split(self, axes: u32) -> Option<([usize; 4], Self)> {
        // floor: truncate, then one down where truncation rounded up (negative non-integers).
        let t = truncate_m128_to_m128i(self);
        let above = cmp_gt_mask_m128(convert_to_m128_from_i32_m128i(t), self);
        let cell = add_i32_m128i(t, cast_to_m128i_from_m128(above));
        let f = sub_m128(self, convert_to_m128_from_i32_m128i(cell));
        // The truncating conversion gives its "invalid" value −2^31 outside (−2^31, 2^31) and
        // for NaN (−2^31 itself goes there too).
        let invalid = cmp_eq_mask_i32_m128i(t, set_splat_i32_m128i(i32::MIN));
        let rounds_to_one = cmp_ge_mask_m128(f, set_splat_m128(1.0));
        let refused = move_mask_m128(bitor_m128(cast_to_m128_from_m128i(invalid), rounds_to_one));
        if refused as u32 & axes != 0 {
            return None;
        }
        let cells = [
            get_i32_from_m128i_s(cell) as usize & 255,
            extract_i16_as_i32_m128i::<2>(cell) as usize & 255,
            extract_i16_as_i32_m128i::<4>(cell) as usize & 255,
            extract_i16_as_i32_m128i::<6>(cell) as usize & 255,
        ];
        Some((cells, f))
    }
}

/// [`Real::sqrt`](crate::Real::sqrt) of 16 lanes, four at a time: `sqrtps`, then 0 wherever
/// the lane is not above 0 (negative, zero or NaN), as the scalar `sqrt` gives. Both square
/// roots are IEEE's, correctly rounded: the same bits (a test compares them).
#[inline]
pub(crate) fn sqrt_lanes(x: &mut [f32; crate::batch::LANES]) {
    for quad in x.chunks_exact_mut(4) {
        let v = load_unaligned_m128(&[quad[0], quad[1], quad[2], quad[3]]);
        let positive = cmp_gt_mask_m128(v, zeroed_m128());
        let root = bitand_m128(sqrt_m128(v), positive).to_array();
        quad.copy_from_slice(&root);
    }
}

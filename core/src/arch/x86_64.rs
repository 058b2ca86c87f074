//! The x86-64 kernels of [`arch`](super) (SSE2, which every x86-64 processor has): the 4-lane
//! vector Perlin's point kernels ([`vector`](super::vector)) run on, `sqrtps`, and simplex
//! noise's corners over a batch's lanes. The intrinsics are the safe wrappers of `safe_arch`,
//! so the crate keeps `#![forbid(unsafe_code)]`.

use safe_arch::{
    add_i32_m128i, add_m128, bitand_m128, bitand_m128i, bitandnot_m128, bitor_m128, bitor_m128i,
    bitxor_m128, bitxor_m128i, cast_to_m128_from_m128d, cast_to_m128_from_m128i,
    cast_to_m128i_from_m128, cmp_eq_mask_i32_m128i, cmp_eq_mask_m128, cmp_ge_mask_m128,
    cmp_gt_mask_i32_m128i, cmp_gt_mask_m128, cmp_lt_mask_i32_m128i, convert_to_m128_from_i32_m128i,
    extract_i16_as_i32_m128i, get_f32_from_m128_s, get_i32_from_m128i_s, load_f64_m128d_s,
    load_replace_high_m128d, load_unaligned_m128, m128, m128i, max_m128, min_m128,
    move_high_low_m128, move_low_high_m128, move_mask_m128, mul_m128, mul_widen_u32_odd_m128i,
    set_splat_i32_m128i, set_splat_m128, shl_imm_u32_m128i, shr_imm_i32_m128i, shr_imm_u32_m128i,
    shr_imm_u64_m128i, shuffle_abi_f32_all_m128, shuffle_ai_f32_all_m128i, sqrt_m128,
    sub_i32_m128i, sub_m128, truncate_m128_to_m128i, unpack_high_m128, unpack_low_i32_m128i,
    unpack_low_m128, zeroed_m128, zeroed_m128i,
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
    fn from_halves(lo: &f64, hi: &f64) -> Self {
        // `movsd`, then `movhpd` from memory.
        cast_to_m128_from_m128d(load_replace_high_m128d(load_f64_m128d_s(lo), hi))
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
    fn signs(self) -> u32 {
        move_mask_m128(self) as u32
    }
    #[inline]
    fn signs_without(self, clear: Self) -> u32 {
        move_mask_m128(bitandnot_m128(clear, self)) as u32
    }
    #[inline]
    fn split(self, _: u32) -> Option<([usize; 4], Self)> {
        // floor: truncate, then one down where truncation rounded up (negative non-integers).
        // Never `None`: the truncating conversion gives −2^31 outside [−2^31, 2^31) and for
        // NaN, and the fraction is then NaN (from NaN), at least 2^32 (at or above 2^31), or
        // negative (below −2^31, where the cell wraps to 2^31 − 1; −∞), which the kernels'
        // test of the fractions refuses.
        let t = truncate_m128_to_m128i(self);
        let above = cmp_gt_mask_m128(convert_to_m128_from_i32_m128i(t), self);
        let cell = add_i32_m128i(t, cast_to_m128i_from_m128(above));
        let f = sub_m128(self, convert_to_m128_from_i32_m128i(cell));
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

/// `a · b` in each `u32` lane, wrapping (SSE2 multiplies two lanes to 64 bits at a time:
/// `pmuludq` on the even lanes and on the odd ones shifted down, then the low halves
/// interleaved).
#[inline(always)]
fn mul_u32(a: m128i, b: m128i) -> m128i {
    let even = mul_widen_u32_odd_m128i(a, b);
    let odd = mul_widen_u32_odd_m128i(shr_imm_u64_m128i::<32>(a), shr_imm_u64_m128i::<32>(b));
    unpack_low_i32_m128i(
        shuffle_ai_f32_all_m128i::<0b00_00_10_00>(even),
        shuffle_ai_f32_all_m128i::<0b00_00_10_00>(odd),
    )
}

/// `mask ? a : b` per lane (`mask` all ones or all zeros).
#[inline(always)]
fn select(mask: m128, a: m128, b: m128) -> m128 {
    bitor_m128(bitand_m128(mask, a), bitandnot_m128(mask, b))
}

/// This target has [`simplex_corners`] (2D and 3D).
pub(crate) const SIMPLEX_CORNERS: bool = true;

/// Simplex noise's corners over 16 lanes in `f32` with Perlin's gradients, 2D and 3D
/// (`simplex::corners`: the same operations on the same numbers, 4 lanes per vector, so the
/// same bits; a test compares them): the ranks, the unskewed offsets, and per corner the
/// offset, `τ`, the hash and the gradient's signed offsets by masks, `τ⁴ (g·d)`; then the
/// scale. `false` (nothing written) in other dimensions.
#[inline]
pub(crate) fn simplex_corners<const D: usize>(
    k: &super::SimplexLanes<'_, D>,
    value: &mut [f32; crate::batch::LANES],
) -> bool {
    use crate::hash::prime::PrimeHash;
    if D != 2 && D != 3 {
        return false;
    }
    let zero = zeroed_m128();
    let one = set_splat_m128(1.0);
    let prime: [m128i; D] =
        core::array::from_fn(|a| set_splat_i32_m128i(PrimeHash::PRIMES[a & 3] as i32));
    for (group, out) in value.chunks_exact_mut(4).enumerate() {
        let at = 4 * group;
        let lanes = |x: &[f32; crate::batch::LANES]| {
            load_unaligned_m128(&[x[at], x[at + 1], x[at + 2], x[at + 3]])
        };
        let offset: [m128; D] = core::array::from_fn(|a| lanes(&k.offset[a]));
        // Gustavson's ranks: +1 for each axis whose fraction this one's exceeds.
        let mut rank = [zeroed_m128i(); D];
        for a in 0..D {
            for b in a + 1..D {
                let greater = cast_to_m128i_from_m128(cmp_gt_mask_m128(offset[a], offset[b]));
                rank[a] = sub_i32_m128i(rank[a], greater);
                rank[b] = add_i32_m128i(rank[b], add_i32_m128i(set_splat_i32_m128i(1), greater));
            }
        }
        let mut sum = zero;
        for o in &offset {
            sum = add_m128(sum, *o);
        }
        let back = mul_m128(sum, set_splat_m128(k.constants.unskew));
        let first: [m128; D] = core::array::from_fn(|a| sub_m128(offset[a], back));
        let term: [m128i; D] = core::array::from_fn(|a| {
            let c = &k.cell[a];
            mul_u32(
                m128i::from([c[at], c[at + 1], c[at + 2], c[at + 3]]),
                prime[a],
            )
        });
        let mut total = zero;
        for j in 0..=D {
            let diagonal = set_splat_m128(k.constants.diagonal[j]);
            let mut q = zero;
            let mut h = set_splat_i32_m128i(k.constants.start as i32);
            let mut d = [zero; D];
            for a in 0..D {
                // Axis a is stepped at corner j when rank + j ≥ D: never at the first corner,
                // always at the last (`simplex::stepped`).
                let step = if j == 0 {
                    zeroed_m128i()
                } else if j == D {
                    set_splat_i32_m128i(-1)
                } else {
                    cmp_gt_mask_i32_m128i(
                        add_i32_m128i(rank[a], set_splat_i32_m128i(j as i32)),
                        set_splat_i32_m128i(D as i32 - 1),
                    )
                };
                // x − 1 where stepped, else x − 0 = x exactly: the same bits as a select.
                let x = add_m128(first[a], diagonal);
                let x = sub_m128(x, bitand_m128(cast_to_m128_from_m128i(step), one));
                d[a] = x;
                q = add_m128(q, mul_m128(x, x));
                h = bitxor_m128i(h, add_i32_m128i(term[a], bitand_m128i(step, prime[a])));
            }
            total = add_m128(total, corner_contribution(d, q, h));
        }
        // The scale, then `+ 0` (`Real::canonical`: −0 to +0).
        let v = add_m128(mul_m128(total, set_splat_m128(k.constants.scale)), zero);
        out.copy_from_slice(&v.to_array());
    }
    true
}

/// A simplex corner's `τ⁴ (g·d)` in each lane (`simplex::simplex`'s per-corner step) from
/// its offset `d`, the offset's squared length `q` summed in axis order, and its folded hash
/// `h`: `τ = max(1 − q − q, 0)`, the gradient chosen by the finished hash's top 4 bits and
/// applied as Perlin's `grad`, signed offsets picked by masks.
#[inline(always)]
fn corner_contribution<const D: usize>(d: [m128; D], q: m128, h: m128i) -> m128 {
    use crate::hash::prime::PrimeHash;
    let zero = zeroed_m128();
    let t = sub_m128(sub_m128(set_splat_m128(1.0), q), q);
    // maxps gives its second operand unless the first is greater: `t > 0 ? t : 0`.
    let tau = max_m128(t, zero);
    let b = shr_imm_u32_m128i::<28>(mul_u32(
        h,
        set_splat_i32_m128i(PrimeHash::MULTIPLIER as i32),
    ));
    // Perlin's grad: ±u ± v, u = b < 8 ? x : y, v = b < 4 ? y : (b is 12 or 14 ? x : z).
    let (x, y) = (d[0], d[1 % D]);
    let z = if D == 3 { d[2 % D] } else { zero };
    let below = |n: i32| cast_to_m128_from_m128i(cmp_lt_mask_i32_m128i(b, set_splat_i32_m128i(n)));
    let twelve_or_fourteen = cast_to_m128_from_m128i(cmp_eq_mask_i32_m128i(
        bitor_m128i(b, set_splat_i32_m128i(2)),
        set_splat_i32_m128i(14),
    ));
    let u = select(below(8), x, y);
    let v = select(below(4), y, select(twelve_or_fourteen, x, z));
    // The signs from bits 0 and 1, moved to the sign bit.
    let sign_u = cast_to_m128_from_m128i(shl_imm_u32_m128i::<31>(b));
    let sign_v = cast_to_m128_from_m128i(shl_imm_u32_m128i::<31>(shr_imm_u32_m128i::<1>(b)));
    let dot = add_m128(bitxor_m128(u, sign_u), bitxor_m128(v, sign_v));
    let tau2 = mul_m128(tau, tau);
    let tau4 = mul_m128(tau2, tau2);
    mul_m128(tau4, dot)
}

/// This target has [`simplex_point`] (3D).
pub(crate) const SIMPLEX_POINT: bool = true;

/// Simplex noise at one point in `f32` with Perlin's gradients, 3D, from its skewed cell and
/// the fractions of its skewed coordinates (`simplex::simplex` with one lane: the same
/// operations on the same numbers, so the same bits; a test compares them): the ranks and
/// the unskewed offset by scalar operations, then the 4 corners as the lanes of one vector
/// (offset, hash, `τ⁴ (g·d)`), summed in corner order, then the scale. The corners' chains
/// run side by side instead of one after another (`bench/README.md`: 3D 270 → 229
/// instructions per sample; in 2D, 3 corners in 4 lanes, 172 → 176 and no faster, so 2D
/// keeps the portable body). `None` in other dimensions.
#[inline]
pub(crate) fn simplex_point<const D: usize>(
    cell: [i32; D],
    offset: [f32; D],
    k: &super::SimplexConstants,
) -> Option<f32> {
    use crate::hash::prime::PrimeHash;
    if D != 3 {
        return None;
    }
    // Gustavson's ranks: +1 for each axis whose fraction this one's exceeds.
    let mut rank = [0i32; D];
    for a in 0..D {
        for b in a + 1..D {
            let greater = i32::from(offset[a] > offset[b]);
            rank[a] += greater;
            rank[b] += 1 - greater;
        }
    }
    let mut sum = 0.0f32;
    for o in offset {
        sum += o;
    }
    let back = sum * k.unskew;
    // Lane j is corner j: axis a is stepped there when rank + j ≥ D, that is when
    // rank > D − 1 − j (small numbers: no wrapping).
    let last = D as i32 - 1;
    let bound = m128i::from([last, last - 1, last - 2, last - 3]);
    let [d0, d1, d2, d3, _] = k.diagonal;
    let diagonal = m128::from_array([d0, d1, d2, d3]);
    let one = set_splat_m128(1.0);
    let mut q = zeroed_m128();
    let mut h = set_splat_i32_m128i(k.start as i32);
    let d: [m128; D] = core::array::from_fn(|a| {
        let step = cmp_gt_mask_i32_m128i(set_splat_i32_m128i(rank[a]), bound);
        // x − 1 where stepped, else x − 0 = x exactly: the same bits as a select.
        let x = add_m128(set_splat_m128(offset[a] - back), diagonal);
        let x = sub_m128(x, bitand_m128(cast_to_m128_from_m128i(step), one));
        q = add_m128(q, mul_m128(x, x));
        let prime = set_splat_i32_m128i(PrimeHash::PRIMES[a & 3] as i32);
        let term = set_splat_i32_m128i(PrimeHash::axis(a, cell[a]) as i32);
        h = bitxor_m128i(h, add_i32_m128i(term, bitand_m128i(step, prime)));
        x
    });
    let contribution = corner_contribution(d, q, h).to_array();
    let mut total = 0.0f32;
    for c in &contribution[..=D] {
        total += c;
    }
    // The scale, then `+ 0` (`Real::canonical`: −0 to +0).
    Some(total * k.scale + 0.0)
}

/// This target has [`cellular_near`] (2D and 3D).
pub(crate) const CELLULAR_NEAR: bool = true;

/// Cellular noise's 3ᴰ near cells in `f32`, 2D and 3D (`Cellular::near_whole`: the same
/// operations on the same numbers, 4 cells per vector, so the same bits; a test compares
/// them): each cell's hash and its generator's first draw by `pmuludq` products, the point's
/// offsets from it, the offsets from the sample and the cell's key; then the first cell of
/// least key and, where asked, the first of least key among the others (what
/// `keep_nearest` over the cells in near order keeps). The point is split here too
/// ([`split_vectors`]), so its cell and fraction reach the hashes in registers (read back
/// from memory, they stalled store forwarding: `bench/README.md`); they are returned for the
/// rings beyond. `None` (nothing written) in other dimensions or for a point beyond ±2²².
#[inline]
pub(crate) fn cellular_near<const D: usize>(
    p: [f32; D],
    k: &super::CellularCells<'_>,
    out: &mut super::NearPair,
) -> Option<([i32; D], [f32; D])> {
    if D != 2 && D != 3 {
        return None;
    }
    let (cell, frac) = split_vectors(p)?;
    match D {
        // The own cell by scalar operations, the 8 others as 2 vectors.
        2 => near_cells::<D, 2, true>(cell, frac, k, out),
        _ => near_cells::<D, 7, false>(cell, frac, k, out),
    }
    let (cell, frac) = (<[i32; 4]>::from(cell), frac.to_array());
    Some((
        core::array::from_fn(|a| cell[a.min(3)]),
        core::array::from_fn(|a| frac[a.min(3)]),
    ))
}

/// Lane `a` (0 to 2) of `v` in every lane.
#[inline(always)]
fn broadcast_i32(v: m128i, a: usize) -> m128i {
    match a {
        0 => shuffle_ai_f32_all_m128i::<0b00_00_00_00>(v),
        1 => shuffle_ai_f32_all_m128i::<0b01_01_01_01>(v),
        _ => shuffle_ai_f32_all_m128i::<0b10_10_10_10>(v),
    }
}

/// Lane `a` (0 to 2) of `v` in every lane.
#[inline(always)]
fn broadcast_f32(v: m128, a: usize) -> m128 {
    match a {
        0 => shuffle_abi_f32_all_m128::<0b00_00_00_00>(v, v),
        1 => shuffle_abi_f32_all_m128::<0b01_01_01_01>(v, v),
        _ => shuffle_abi_f32_all_m128::<0b10_10_10_10>(v, v),
    }
}

/// [`cellular_near`] over `G` vectors of 4 cells (the 3ᴰ and padding), after the own cell
/// (lane 0) by scalar operations where `OWN`.
#[inline(always)]
fn near_cells<const D: usize, const G: usize, const OWN: bool>(
    cell: m128i,
    fraction: m128,
    k: &super::CellularCells<'_>,
    out: &mut super::NearPair,
) {
    use crate::hash::prime::PrimeHash;
    use crate::hash::{cell::MIX, rng::WEYL};
    const UNIT: i32 = 1 << 16;
    let count = 3i32.pow(D as u32);
    let width: u32 = if D == 2 { 16 } else { 10 };
    let splat = set_splat_i32_m128i;
    let multiplier = splat(PrimeHash::MULTIPLIER as i32);
    let mix = MIX.map(|m| splat(m as i32));
    let weyl = splat(WEYL as i32);
    let start = splat(k.start as i32);
    // Each axis's term `c·Pₐ` and fraction, in every lane.
    let products = mul_u32(cell, m128i::from(PrimeHash::PRIMES.map(|p| p as i32)));
    let term: [m128i; D] = core::array::from_fn(|a| broadcast_i32(products, a));
    let frac: [m128; D] = core::array::from_fn(|a| broadcast_f32(fraction, a));
    let scale = set_splat_m128(1.0 / UNIT as f32);
    let half = splat(UNIT / 2);
    let jitter = splat(k.jitter);
    let sign = set_splat_m128(-0.0);
    let infinity = set_splat_m128(f32::INFINITY);
    let base = usize::from(OWN);
    // The own cell (offsets 0), where `OWN`: the vector body's operations on one lane.
    let own = OWN.then(|| {
        let (cell, fraction) = (<[i32; 4]>::from(cell), fraction.to_array());
        let mut h = k.start;
        for (a, &c) in cell.iter().enumerate().take(D) {
            h ^= PrimeHash::axis(a, c);
        }
        let h = PrimeHash::finish(h);
        let bits = crate::hash::mix(h.wrapping_add(WEYL));
        let mut q = [0.0f32; 3];
        let mut key = 0.0f32;
        for (a, (q, frac)) in q.iter_mut().zip(fraction).enumerate().take(D) {
            let mut u = ((bits >> (32 - width * (a as u32 + 1))) & ((1 << width) - 1)) as i32;
            u <<= 16 - width;
            if k.jitter != UNIT {
                u = UNIT / 2 + ((u - UNIT / 2).wrapping_mul(k.jitter) >> 16);
            }
            *q = u as f32 * (1.0 / UNIT as f32) - frac;
            let axis_key = if k.squares { *q * *q } else { q.abs() };
            key = if a == 0 {
                axis_key
            } else if k.chebyshev {
                if axis_key > key { axis_key } else { key }
            } else {
                key + axis_key
            };
        }
        (key, q, h)
    });
    let mut keys = [zeroed_m128(); G];
    let mut hashes = [zeroed_m128i(); G];
    let mut offsets = [[zeroed_m128(); G]; D];
    for g in 0..G {
        let at = base + 4 * g;
        let lanes = |x: &[i32; 28]| m128i::from([x[at], x[at + 1], x[at + 2], x[at + 3]]);
        // The cell's hash: the start, each axis's term `(c + kₐ)·Pₐ = c·Pₐ + kₐ·Pₐ`, the
        // product with the multiplier.
        let mut h = start;
        for (term, prime) in term.iter().zip(&k.lanes.prime) {
            h = bitxor_m128i(h, add_i32_m128i(*term, lanes(prime)));
        }
        let h = mul_u32(h, multiplier);
        hashes[g] = h;
        // The generator's first draw: the mixer of the key plus the Weyl step.
        let x = add_i32_m128i(h, weyl);
        let x = bitxor_m128i(x, shr_imm_u32_m128i::<16>(x));
        let x = mul_u32(x, mix[0]);
        let x = bitxor_m128i(x, shr_imm_u32_m128i::<15>(x));
        let x = mul_u32(x, mix[1]);
        let bits = bitxor_m128i(x, shr_imm_u32_m128i::<16>(x));
        let mut key = zeroed_m128();
        for a in 0..D {
            // Axis a's `width` bits as a 16.16 position, the jitter's offset, the cell's.
            let shifted = match (D, a) {
                (2, 0) => shr_imm_u32_m128i::<16>(bits),
                (2, _) => bits,
                (_, 0) => shr_imm_u32_m128i::<22>(bits),
                (_, 1) => shr_imm_u32_m128i::<12>(bits),
                _ => shr_imm_u32_m128i::<2>(bits),
            };
            let mut u = bitand_m128i(shifted, splat((1 << width) - 1));
            if width == 10 {
                u = shl_imm_u32_m128i::<6>(u);
            }
            if k.jitter != UNIT {
                // ½ + ((u − ½)·jitter >> 16): the product fits in i32 (`Cellular::offset`).
                let product = mul_u32(sub_i32_m128i(u, half), jitter);
                u = add_i32_m128i(half, shr_imm_i32_m128i::<16>(product));
            }
            let n = add_i32_m128i(u, lanes(&k.lanes.unit[a]));
            let q = sub_m128(mul_m128(convert_to_m128_from_i32_m128i(n), scale), frac[a]);
            offsets[a][g] = q;
            let axis_key = if k.squares {
                mul_m128(q, q)
            } else {
                bitandnot_m128(sign, q)
            };
            key = if a == 0 {
                axis_key
            } else if k.chebyshev {
                // `combine`: `b > a ? b : a`, which is `maxps(b, a)`.
                max_m128(axis_key, key)
            } else {
                add_m128(key, axis_key)
            };
        }
        // Lanes past the 3ᴰ cells never win.
        let valid = cmp_gt_mask_i32_m128i(
            splat(count),
            m128i::from([at as i32, at as i32 + 1, at as i32 + 2, at as i32 + 3]),
        );
        keys[g] = select(cast_to_m128_from_m128i(valid), key, infinity);
    }
    let lane = |v: &[m128; G], i: usize| v[(i / 4).min(G - 1)].to_array()[i % 4];
    // The nearest and second-nearest cells: `Some(i)` for lane `base + i` of the vectors,
    // `None` for the own cell, which comes first in near order (it wins ties).
    // The keys come from the least values themselves, so the distance does not wait for the
    // lane search (equal keys have equal bits: none is −0).
    let (first, least) = first_least(&keys);
    let (first, first_key) = match own {
        Some((key, ..)) if key <= least => (None, key),
        _ => (Some(first), least),
    };
    let mut nearest = [(first, first_key), (None, 0.0)];
    if k.second {
        // The others: the first out of the running.
        if let Some(first) = first {
            for (g, key) in keys.iter_mut().enumerate() {
                let at = 4 * g as i32;
                let is_first = cmp_eq_mask_i32_m128i(
                    splat(first as i32),
                    m128i::from([at, at + 1, at + 2, at + 3]),
                );
                *key = select(cast_to_m128_from_m128i(is_first), infinity, *key);
            }
        }
        let (second, least) = first_least(&keys);
        nearest[1] = match own {
            Some((key, ..)) if first.is_some() && key <= least => (None, key),
            _ => (Some(second), least),
        };
    }
    let (_, own_q, own_hash) = own.unwrap_or((0.0, [0.0; 3], 0));
    for (j, (cell, key)) in nearest
        .into_iter()
        .enumerate()
        .take(1 + usize::from(k.second))
    {
        out.key[j] = key;
        if let Some(i) = cell {
            out.q[j] = core::array::from_fn(|a| lane(&offsets[a.min(D - 1)], i));
            if j == 0 {
                out.hash = <[i32; 4]>::from(hashes[(i / 4).min(G - 1)])[i % 4] as u32;
            }
        } else {
            out.q[j] = own_q;
            if j == 0 {
                out.hash = own_hash;
            }
        }
    }
}

/// The first lane of `keys` (`G` vectors of 4 finite or infinite keys, not all infinite) whose
/// key is the least, and the least: `minps` over the vectors and across the lanes, then
/// `movmskps` of the lanes equal to it.
#[inline(always)]
fn first_least<const G: usize>(keys: &[m128; G]) -> (usize, f32) {
    let mut least = keys[0];
    for key in &keys[1..] {
        least = min_m128(least, *key);
    }
    least = min_m128(
        least,
        shuffle_abi_f32_all_m128::<0b10_11_00_01>(least, least),
    );
    least = min_m128(
        least,
        shuffle_abi_f32_all_m128::<0b01_00_11_10>(least, least),
    );
    let mut found = 0u32;
    for (g, key) in keys.iter().enumerate() {
        found |= (move_mask_m128(cmp_eq_mask_m128(*key, least)) as u32) << (4 * g);
    }
    (found.trailing_zeros() as usize, get_f32_from_m128_s(least))
}

/// [`Real::split`](crate::Real::split) of each of the `D` (up to 4) coordinates of a point in
/// `f32`, in one vector: `split_lanes`' arithmetic (the `1.5·2²³` rounding, one correction,
/// the fraction's carry), so the same bits (a test compares them). `None` unless every
/// coordinate is within `(−2²², 2²²)` (NaN is not). Lanes past `D` hold 0's split.
#[inline(always)]
fn split_vectors<const D: usize>(p: [f32; D]) -> Option<(m128i, m128)> {
    if D > 4 {
        return None;
    }
    const MAGIC: f32 = 12_582_912.0;
    let x = m128::from_array(core::array::from_fn(|a| if a < D { p[a] } else { 0.0 }));
    let magnitude = bitandnot_m128(set_splat_m128(-0.0), x);
    if move_mask_m128(cmp_gt_mask_m128(set_splat_m128(4_194_304.0), magnitude)) != 0b1111 {
        return None;
    }
    let nearest = sub_i32_m128i(
        cast_to_m128i_from_m128(add_m128(x, set_splat_m128(MAGIC))),
        set_splat_i32_m128i(MAGIC.to_bits() as i32),
    );
    // `nearest − (nearest > x)`: the mask is −1 where the rounding went up.
    let above = cmp_gt_mask_m128(convert_to_m128_from_i32_m128i(nearest), x);
    let cell = add_i32_m128i(nearest, cast_to_m128i_from_m128(above));
    let frac = sub_m128(x, convert_to_m128_from_i32_m128i(cell));
    // A fraction that rounded to 1 carries into the cell. Rare (tiny negative coordinates),
    // so tested by a branch: the cell is ready for the hash without waiting for the test.
    let up = cmp_ge_mask_m128(frac, set_splat_m128(1.0));
    let (cell, frac) = if move_mask_m128(up) == 0 {
        (cell, frac)
    } else {
        (
            sub_i32_m128i(cell, cast_to_m128i_from_m128(up)),
            bitandnot_m128(up, frac),
        )
    };
    let frac = add_m128(frac, zeroed_m128());
    Some((cell, frac))
}

/// [`split_vectors`] as arrays, for its test.
#[cfg(test)]
pub(crate) fn split_point<const D: usize>(p: [f32; D]) -> Option<([i32; D], [f32; D])> {
    let (cell, frac) = split_vectors(p)?;
    let (cell, frac) = (<[i32; 4]>::from(cell), frac.to_array());
    Some((
        core::array::from_fn(|a| cell[a.min(3)]),
        core::array::from_fn(|a| frac[a.min(3)]),
    ))
}

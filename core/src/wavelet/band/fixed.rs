//! Fixed-point samples of a band on a quantized tile in 32-bit integer arithmetic, bit for bit
//! as [`Wavelet::evaluate`] computes them through [`Real`](crate::Real)'s I16F16 operations:
//! Cook & DeRose 2005's band (§3.6, Appendix 2: the quadratic B-spline through 3ᵈ
//! coefficients) over the blocks of `band.rs`'s tilings (§4.3), for cores without a long
//! multiply.
//!
//! A quantized tile's coefficient is `c = q · 2^−s` with `q` an `i16`
//! ([`TileData::quantized_shift`]): in I16F16 its bits are `q · 2^(16−s)`, and the rounded
//! product of a weight `w` (in 2⁻¹⁶ units) with it, `⌊(w·c + 2¹⁵) / 2¹⁶⌋` in the bits, is
//! `⌊(w·q + 2^(s−1)) / 2^s⌋`: one 32-bit multiplication (`|w·q| < 2³¹`), an addition and a
//! shift, where the generic path forms a 64-bit product (four 32-bit multiplications on
//! ARMv6-M, which has no long multiply). The B-spline weights are formed as in
//! `bspline3_weights` with the squares in 32 bits (`(1 − f)²` from `f²`: one multiplication
//! per axis), the blend weights by one 32-bit product each, and each column's weighted sum
//! by two 32-bit products ([`mul_weight`]) on ARMv6-M.
//!
//! The generic path rounds each product as these do, in the same places; its additions
//! saturate, and these do not, which gives the same bits whenever no sum reaches I16F16's
//! limit: with `s ≥` [`MIN_SHIFT`] every coefficient is below 2¹³ in magnitude, a block's
//! weights along an axis sum to at most 1 and a blend zone's pairs to at most `BLEND_GAIN`
//! (1.41) per axis, so a sample's sums stay below 2¹³ · 1.41ᴰ < 2¹⁵ (2¹³ · 2.8 in 3D).
//! Without saturation, integer additions in any order give the same sum, so blocks and
//! coefficients may be visited in any order; coefficients beyond a block's reach are skipped
//! (whole x columns) or weigh 0 (along the other axes: a zero weight's rounded product is 0),
//! as the generic path skips them or adds their zero products.

use super::{TileData, Wavelet, ZONE, axis_span, members, offset_run, zone_at};

/// Whether fixed-point point samples on quantized tiles take these sums: everywhere but
/// wasm32, whose demo module's size budget would pay for a second copy of the sums (its
/// I16F16 samples keep the generic path, with the same bits).
pub(super) const QUANTIZED: bool = cfg!(not(target_arch = "wasm32"));

/// The smallest shift of a quantized tile that [`Wavelet::evaluate_quantized`] takes: its
/// coefficients are below 2¹³ in magnitude (`|q| ≤ 2¹⁵`), so no sum saturates (module docs).
/// Every default tile has a shift of 12 or more.
pub(super) const MIN_SHIFT: u32 = 2;

/// The three quadratic B-spline weights of fraction `f` (in 2⁻¹⁶ units, below 2¹⁶), as I16F16
/// bits, as `bspline3_weights` rounds them: `w₀ = ⌊(⌊(g² + 2¹⁵)/2¹⁶⌋ + 1)/2⌋` with `g = 1 − f`,
/// `w₂` likewise from `f`, `w₁ = 1 − w₀ − w₂`. `g² = 2³² − 2¹⁷f + f²`, so its rounded
/// quotient is `2¹⁶ − 2f` plus that of `f²` (the same product, which fits 32 bits where `g²`
/// does not at `f = 0`).
#[inline]
fn weights(f: u32) -> [i32; 3] {
    let ff = (f * f + (1 << 15)) >> 16;
    // Wrapping: `2¹⁶ − 2f` alone is negative for `f > ½`; the sum is not.
    let gg = (1u32 << 16).wrapping_sub(2 * f).wrapping_add(ff);
    // `mul_fraction(x, ½)` of `x ≥ 0` is `⌊(x·2¹⁵ + 2¹⁵)/2¹⁶⌋ = ⌊(x + 1)/2⌋`.
    let (w0, w2) = ((gg + 1) >> 1, (ff + 1) >> 1);
    [w0 as i32, ((1 << 16) - w0 - w2) as i32, w2 as i32]
}

/// I16F16 `mul_fraction(w, c)` (bits), for a weight `0 ≤ w < 2¹⁶` and any `c` whose product
/// fits: `⌊(w·c + 2¹⁵)/2¹⁶⌋`. On ARMv6-M from two 32-bit multiplications (`c = cₕ·2¹⁶ + cₗ`:
/// `w·cₕ + ⌊(w·cₗ + 2¹⁵)/2¹⁶⌋`, exact, `w·cₗ + 2¹⁵ < 2³²` for `w ≤ ¾`, every weight
/// here), elsewhere one 64-bit product.
#[inline]
fn mul_weight(w: i32, c: i32) -> i32 {
    #[cfg(bandnoise_armv6m)]
    let product = mul_weight_halves(w, c);
    #[cfg(not(bandnoise_armv6m))]
    let product = ((i64::from(w) * i64::from(c) + (1 << 15)) >> 16) as i32;
    product
}

/// [`mul_weight`] on ARMv6-M: two 32-bit multiplications.
#[cfg(any(test, bandnoise_armv6m))]
#[inline]
fn mul_weight_halves(w: i32, c: i32) -> i32 {
    let (ch, cl) = (c >> 16, c as u32 & 0xFFFF);
    w.wrapping_mul(ch)
        .wrapping_add(((w as u32).wrapping_mul(cl).wrapping_add(1 << 15) >> 16) as i32)
}

/// The flat index of two parts from [`offset_run`] of different axes: their sum, which for a
/// power-of-two side is their bitwise or (each part lies in its axis's bits), so the
/// optimiser sees the index below `n^D` and the read needs no mask.
#[inline(always)]
fn join(a: usize, b: usize, n: usize) -> usize {
    if n.is_power_of_two() { a | b } else { a + b }
}

impl<T> Wavelet<'_, T> {
    /// [`evaluate`](Wavelet::evaluate) in I16F16 (`p` and the result as bits) on a tile with
    /// [`quantized_shift`](TileData::quantized_shift) `shift ≥` [`MIN_SHIFT`]: the same bits
    /// (module docs), in 32-bit integer operations.
    #[inline]
    pub(super) fn evaluate_quantized<const D: usize>(&self, p: [i32; D], shift: u32) -> i32
    where
        T: TileData<D>,
    {
        let (n, h) = (T::SIZE, self.half_width::<D>());
        let mut w = [[0i32; 3]; D];
        let mut block = [0i32; D];
        let mut local0 = [0usize; D];
        let mut crossing = 0usize;
        for a in 0..D {
            // `split` and `minus_half` on the bits.
            let (cell, frac) = (p[a] >> 16, (p[a] & 0xFFFF) as u32);
            let (first, f) = if frac >= 1 << 15 {
                (cell, frac - (1 << 15))
            } else {
                (cell.wrapping_sub(1), frac + (1 << 15))
            };
            w[a] = weights(f);
            let (b, l0, two) = axis_span(first, n, h);
            (block[a], local0[a]) = (b, l0);
            crossing |= (two as usize) << a;
        }
        if crossing == 0 {
            let place = self.placement(block);
            let off = core::array::from_fn(|a| offset_run(&place, a, 0, local0[a], n));
            return self.quantized_block(&w, &off, 0b111, shift);
        }
        // Each axis's weights in the first block and the next: along a crossing axis in a
        // blend zone, times each block's blend weights (`blend_axis`'s products).
        let mut sides = [w; 2];
        if h > 0 {
            for (s, side) in sides.iter_mut().enumerate() {
                for (a, axis) in side.iter_mut().enumerate() {
                    if crossing >> a & 1 == 1 {
                        let at = zone_at(local0[a], n, h);
                        for (j, wj) in axis.iter_mut().enumerate() {
                            let b = ZONE[s & 1][(at + j) & 15] as u32;
                            // `w ≤ ¾`, `b ≤ 1`: the product fits 32 bits unsigned.
                            *wj = ((*wj as u32 * b + (1 << 15)) >> 16) as i32;
                        }
                    }
                }
            }
        }
        // Coefficients beyond a block's reach: skipped along x (whole columns), weighing 0
        // along the other axes (only needed where blocks abut: a blend weight is 0 there).
        let bits = members(crossing, local0, n, h);
        for (side, bits) in sides.iter_mut().zip(bits) {
            for (axis, bits) in side.iter_mut().zip(bits).skip(1) {
                for (j, wj) in axis.iter_mut().enumerate() {
                    if bits >> j & 1 == 0 {
                        *wj = 0;
                    }
                }
            }
        }
        let mut sum = 0i32;
        for m in 0..=crossing {
            if m & !crossing != 0 {
                continue;
            }
            let place = self.placement(self.step(block, m));
            let off = core::array::from_fn(|a| offset_run(&place, a, m, local0[a], n));
            let weights = core::array::from_fn(|a| sides[m >> a & 1][a]);
            let columns = bits[m & 1][0];
            sum = sum.wrapping_add(self.quantized_block(&weights, &off, columns, shift));
        }
        sum
    }

    /// One block's part of [`evaluate_quantized`](Self::evaluate_quantized): for each x
    /// index whose bit is set in `columns`, its column (lines along z, then along y) weighted
    /// by its x weight, as `add_block` sums. Written out, not looped: the loops, with their
    /// bounds from the bits, stayed loops on the Cortex-M0. The coefficients of a column are
    /// all read; those beyond the block's reach weigh 0 (`w` says so), and a zero weight's
    /// product is 0.
    #[inline(always)]
    fn quantized_block<const D: usize>(
        &self,
        w: &[[i32; 3]; D],
        off: &[[usize; 3]; D],
        columns: u8,
        shift: u32,
    ) -> i32
    where
        T: TileData<D>,
    {
        // The rounded product of a weight and a coefficient, from the coefficient's integer:
        // `⌊(x + 2^(s−1)) / 2^s⌋`. On ARMv6-M as `⌊(⌊x / 2^(s−1)⌋ + 1) / 2⌋`, the same
        // integer, which keeps one number (`s − 1`) in one of its eight registers instead of
        // two (1% fewer instructions there, 2–3% more on the Cortex-M4F and RV32IMC).
        let (down, round) = (shift - 1, 1 << (shift - 1));
        let n = T::SIZE;
        let product = |w: i32, index: usize| {
            let x = w.wrapping_mul(i32::from(self.tile.raw(index)));
            if cfg!(bandnoise_armv6m) {
                ((x >> down) + 1) >> 1
            } else {
                (x + round) >> shift
            }
        };
        // The innermost axis's weighted sum of three coefficients from `base`.
        let line = |base: usize| {
            let (w, off) = (&w[D - 1], &off[D - 1]);
            product(w[0], join(base, off[0], n))
                .wrapping_add(product(w[1], join(base, off[1], n)))
                .wrapping_add(product(w[2], join(base, off[2], n)))
        };
        let column = |jx: usize| {
            let base = off[0][jx];
            if D == 3 {
                let (w, off) = (&w[1], &off[1]);
                mul_weight(w[0], line(join(base, off[0], n)))
                    .wrapping_add(mul_weight(w[1], line(join(base, off[1], n))))
                    .wrapping_add(mul_weight(w[2], line(join(base, off[2], n))))
            } else {
                line(base)
            }
        };
        let mut sum = 0i32;
        if columns & 1 == 1 {
            sum = mul_weight(w[0][0], column(0));
        }
        if columns & 2 == 2 {
            sum = sum.wrapping_add(mul_weight(w[0][1], column(1)));
        }
        if columns & 4 == 4 {
            sum = sum.wrapping_add(mul_weight(w[0][2], column(2)));
        }
        sum
    }
}

#[cfg(test)]
mod tests {
    use super::super::super::quantized::{QuantizedTile2, QuantizedTile3};
    use super::super::super::tile::{Tile2, Tile3};
    use super::super::super::{TILE2_I16, TILE3_I16};
    use super::super::{TileData, Tiling, Wavelet};
    use super::{mul_weight, mul_weight_halves, weights};
    use crate::real::sealed::Sealed;
    use crate::{I16F16, Noise, Real};

    /// A tile read through `flat` only (no `quantized_shift`): the generic path.
    struct Plain<'t, T>(&'t T);

    impl<T: TileData<D>, const D: usize> TileData<D> for Plain<'_, T> {
        const SIZE: usize = T::SIZE;
        fn get<R: Real>(&self, index: [usize; D]) -> R {
            self.0.get(index)
        }
        fn flat<R: Real>(&self, index: usize) -> R {
            self.0.flat(index)
        }
        fn unit<R: Real>(&self) -> R {
            self.0.unit()
        }
        fn flat_with<R: Real>(&self, index: usize, unit: R) -> R {
            self.0.flat_with(index, unit)
        }
        fn max_abs(&self) -> f32 {
            self.0.max_abs()
        }
    }

    /// Points over I16F16's whole range, and near the origin where the tests' tiles' block
    /// borders and blend zones lie at every scale.
    fn points<const D: usize>(count: usize) -> impl Iterator<Item = [I16F16; D]> {
        let mut x = 0x9E37_79B9u32;
        (0..count).map(move |i| {
            core::array::from_fn(|_| {
                x ^= x << 13;
                x ^= x >> 17;
                x ^= x << 5;
                let bits = if i % 2 == 0 {
                    x as i32
                } else {
                    (x as i32) >> 9
                };
                I16F16::from_bits(bits)
            })
        })
    }

    /// The integer sums give the generic path's bits: 2D and 3D, every tiling, the default
    /// tiles, small tiles (blend zones on both sides of a 12-wide block; 8- and 6-wide blocks
    /// without zones) and a tile whose coefficients reach the bound of `MIN_SHIFT`.
    fn same_bits<T: TileData<D>, const D: usize>(tile: &T, count: usize) {
        let plain = Plain(tile);
        for tiling in [Tiling::Blended, Tiling::Varied, Tiling::Periodic] {
            for seed in [0, 7, 0xDEAD_BEEF] {
                let fast = Wavelet::new(seed, tile).with_tiling(tiling);
                let generic = Wavelet::new(seed, &plain).with_tiling(tiling);
                for p in points::<D>(count) {
                    let (a, b): (I16F16, I16F16) = (fast.sample(p), generic.sample(p));
                    assert_eq!(a, b, "{tiling:?}, seed {seed}, {p:?}");
                }
            }
        }
    }

    #[test]
    fn quantized_sums_are_the_generic_ones() {
        same_bits(&TILE2_I16, 20_000);
        same_bits(&QuantizedTile2::quantize(&Tile2::<12>::generate(3)), 20_000);
        same_bits(&QuantizedTile2::quantize(&Tile2::<8>::generate(4)), 5_000);
        same_bits(&QuantizedTile2::quantize(&Tile2::<6>::generate(5)), 5_000);
        same_bits(&TILE3_I16, 5_000);
        same_bits(&QuantizedTile3::quantize(&Tile3::<12>::generate(3)), 5_000);
        same_bits(&QuantizedTile3::quantize(&Tile3::<6>::generate(5)), 2_000);
        // Coefficients up to ±8191, the largest with a shift of 2.
        let mut x = 1u32;
        let mut extreme = Tile2::<16>::generate(1);
        for row in &mut extreme.data {
            for c in row {
                x = x.wrapping_mul(747_796_405).wrapping_add(2_891_336_453);
                *c = if x >> 31 == 0 { 8191.0 } else { -8191.0 } * (x >> 20 & 1) as f32;
            }
        }
        extreme.max_abs = 8191.0;
        let extreme = QuantizedTile2::quantize(&extreme);
        assert_eq!(extreme.shift(), super::MIN_SHIFT);
        same_bits(&extreme, 20_000);
        let mut extreme3 = Tile3::<12>::generate(1);
        for c in extreme3.data.as_flattened_mut().as_flattened_mut() {
            x = x.wrapping_mul(747_796_405).wrapping_add(2_891_336_453);
            *c = if x >> 31 == 0 { 8191.0 } else { -8191.0 };
        }
        extreme3.max_abs = 8191.0;
        let extreme3 = QuantizedTile3::quantize(&extreme3);
        assert_eq!(extreme3.shift(), super::MIN_SHIFT);
        same_bits(&extreme3, 5_000);
    }

    /// [`weights`] are `bspline3_weights`' in I16F16, for every fraction.
    #[test]
    fn weights_are_the_generic_ones() {
        for f in 0..1u32 << 16 {
            let generic = super::super::bspline3_weights(I16F16::from_bits(f as i32));
            assert_eq!(weights(f), generic.map(I16F16::to_bits), "f = {f}");
        }
    }

    /// [`mul_weight`] is I16F16's `mul_fraction` for weights up to ¾ and sums of a sample's
    /// size.
    #[test]
    fn weight_products_are_mul_fraction() {
        let mut x = 0x2545_F491u32;
        for _ in 0..200_000 {
            x ^= x << 13;
            x ^= x >> 17;
            x ^= x << 5;
            let w = (x % 49_153) as i32;
            let c = (x.rotate_left(11) as i32) >> 2;
            let generic = I16F16::from_bits(w).mul_fraction(I16F16::from_bits(c));
            assert_eq!(mul_weight(w, c), generic.to_bits(), "w = {w}, c = {c}");
            assert_eq!(
                mul_weight_halves(w, c),
                generic.to_bits(),
                "w = {w}, c = {c}"
            );
        }
    }
}

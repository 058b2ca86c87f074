//! The x86-64 kernels of [`arch`](super) (SSE2, which every x86-64 processor has).
//!
//! Perlin's improved noise (Perlin 2002, "Improving Noise") at one point in 2D, 3D and 4D, in
//! `f32`: the axes split and faded together, and the 4 (2D), 8 (3D) or 16 (4D) corner dot
//! products and the lerps in 4-lane vectors. The point kernel of [`sample_lattice`] does the
//! same steps one number at a time.
//!
//! A sample is bound by latency: Perlin's hash is a chain of dependent lookups (`p[p[x] + y]`,
//! then a gradient), and every lerp waits for the one before. The gradients of two neighbouring
//! hash values come from one row of a static table ([`PAIR_ROWS`]), already split by axis, so
//! the vectors need no transposition. In 4D (32 gradients, a pair table would be 32 KiB) each
//! corner's gradient is one row of the portable kernel's `f32` gradient table (`Grad4`), and
//! four rows are transposed into the vectors of their components.
//!
//! Every lane computes the operations of the shared kernel on the same numbers in the same order
//! (IEEE `+ − ×`, no fused multiply-add), so the results are those of [`sample_lattice`] bit for
//! bit; a test compares them over random and edge-case points. The intrinsics are the safe
//! wrappers of `safe_arch`, so the crate keeps `#![forbid(unsafe_code)]`.
//!
//! [`sample_lattice`]: crate::lattice

use safe_arch::{
    add_i32_m128i, add_m128, add_m128_s, bitand_m128, bitor_m128, cast_to_m128_from_m128i,
    cast_to_m128i_from_m128, cmp_eq_mask_i32_m128i, cmp_ge_mask_m128, cmp_gt_mask_m128,
    convert_to_m128_from_i32_m128i, extract_i16_as_i32_m128i, get_f32_from_m128_s,
    get_i32_from_m128i_s, load_unaligned_m128, m128, move_high_low_m128, move_low_high_m128,
    move_mask_m128, mul_m128, mul_m128_s, set_splat_i32_m128i, set_splat_m128,
    shuffle_abi_f32_all_m128, sqrt_m128, sub_m128, sub_m128_s, transpose_four_m128,
    truncate_m128_to_m128i, unpack_high_m128, unpack_low_m128, zeroed_m128,
};

use crate::lattice::perlin::{GRAD3, Grad4};

pub(crate) const PERLIN_POINT: bool = true;

/// SSE2 interpolates four octaves in one vector (`bench/README.md`: 0.7× the octaves one by one).
pub(crate) const OCTAVES_AS_LANES: bool = true;

#[inline]
pub(crate) fn perlin2(p: &[u8; 512], x: f32, y: f32) -> Option<f32> {
    Kernel {
        p,
        pairs: &PAIR_ROWS,
    }
    .sample2(x, y)
}

#[inline]
pub(crate) fn perlin3(p: &[u8; 512], x: f32, y: f32, z: f32) -> Option<f32> {
    Kernel {
        p,
        pairs: &PAIR_ROWS,
    }
    .sample3(x, y, z)
}

#[inline]
pub(crate) fn perlin4(p: &[u8; 512], x: f32, y: f32, z: f32, w: f32) -> Option<f32> {
    Kernel {
        p,
        pairs: &PAIR_ROWS,
    }
    .sample4(x, y, z, w)
}

#[inline]
pub(crate) fn perlin2_paired(p: &[u8; 512], pairs: &PerlinPairs, x: f32, y: f32) -> Option<f32> {
    Kernel { p, pairs }.sample2(x, y)
}

#[inline]
pub(crate) fn perlin3_paired(
    p: &[u8; 512],
    pairs: &PerlinPairs,
    x: f32,
    y: f32,
    z: f32,
) -> Option<f32> {
    Kernel { p, pairs }.sample3(x, y, z)
}

/// Where the kernel finds the gradients of `p[i]` and `p[i + 1]`, split by axis:
/// `[g₀ₓ, g₀ᵧ, g₁ₓ, g₁ᵧ]` and `[g₀z, g₁z, 0, 0]`.
trait GradientPairs {
    fn pair(&self, p: &[u8; 512], i: usize) -> &[[f32; 4]; 2];
}

/// The static table: look up `p[i]` and `p[i + 1]`, then their row.
impl GradientPairs for PairRows {
    #[inline]
    fn pair(&self, p: &[u8; 512], i: usize) -> &[[f32; 4]; 2] {
        let row = usize::from(p[i] & 15) | usize::from(p[i + 1] & 15) << 4;
        &self.0[row]
    }
}

/// A seed's table, `PAIR_ROWS` composed with the permutation: entry `b` (`b < 512`, an index of
/// the doubled permutation `p`) is the row of `p[b]` and `p[b + 1]`. One lookup replaces two
/// permutation lookups and a row lookup, and takes a level off the chain of dependent loads:
/// `p[p[x] + y]` and its neighbour in 2D, `p[p[p[x] + y] + z]` and its neighbour in 3D.
/// 16 KiB, built by `const fn`; a caller opts into it with
/// [`TabledPerlin`](crate::lattice::TabledPerlin).
#[derive(Clone)]
#[repr(align(32))]
pub(crate) struct PerlinPairs([[[f32; 4]; 2]; 512]);

impl PerlinPairs {
    pub(crate) const fn new(p: &[u8; 512]) -> Self {
        let mut pairs = [[[0.0f32; 4]; 2]; 512];
        let mut b = 0;
        while b < 512 {
            // Entry 511 is never read (b ≤ 255 + 255); its p[b + 1] wraps as p does.
            let row = (p[b] & 15) as usize | ((p[(b + 1) & 511] & 15) as usize) << 4;
            pairs[b] = PAIR_ROWS.0[row];
            b += 1;
        }
        Self(pairs)
    }
}

impl GradientPairs for PerlinPairs {
    #[inline]
    fn pair(&self, _: &[u8; 512], i: usize) -> &[[f32; 4]; 2] {
        &self.0[i]
    }
}

/// The gradients of every pair of hash values, split by axis: entry `i + 16·j` holds the
/// gradients `g` and `h` that Perlin's `grad` selects for hashes `i` and `j` (mod 16) as
/// `[gₓ, gᵧ, hₓ, hᵧ]` and `[g_z, h_z, 0, 0]`. The last step of Perlin's chain looks up two
/// corners that differ along the innermost hashed axis, `p[b]` and `p[b + 1]`; one row gives
/// both gradients already transposed for the dot products. 8 KiB, the same for every seed
/// (a `static` the kernel owns, so [`Perlin`](crate::lattice::Perlin) has one size on every
/// target).
#[repr(align(32))]
struct PairRows([[[f32; 4]; 2]; 256]);

static PAIR_ROWS: PairRows = PairRows::new();

impl PairRows {
    const fn new() -> Self {
        let mut rows = [[[0.0f32; 4]; 2]; 256];
        let mut i = 0;
        while i < 256 {
            let g = GRAD3[i & 15];
            let h = GRAD3[i >> 4];
            rows[i] = [
                [g[0] as f32, g[1] as f32, h[0] as f32, h[1] as f32],
                [g[2] as f32, h[2] as f32, 0.0, 0.0],
            ];
            i += 1;
        }
        PairRows(rows)
    }
}

/// The SSE2 kernel over a seed's doubled permutation (see
/// [`Perlin`](crate::lattice::Perlin)), whose hash chain `p[p[x] + y]` needs no `& 255` (every
/// index it forms is at most 255 + 256).
struct Kernel<'a, G> {
    p: &'a [u8; 512],
    pairs: &'a G,
}

impl<G: GradientPairs> Kernel<'_, G> {
    /// Perlin's `p[i]` for `i < 512`.
    #[inline]
    fn p(&self, i: usize) -> usize {
        usize::from(self.p[i])
    }

    /// The gradients of `p[i]` and `p[i + 1]` (`i < 511`).
    #[inline]
    fn pair(&self, i: usize) -> &[[f32; 4]; 2] {
        self.pairs.pair(self.p, i)
    }

    /// The x and y components of the gradients of hash inputs `a`, `a + 1`, `b`, `b + 1`, in
    /// that lane order.
    #[inline]
    fn gradients_xy(&self, a: usize, b: usize) -> (m128, m128) {
        let [ra, rb] = [a, b].map(|i| load_unaligned_m128(&self.pair(i)[0]));
        let gx = shuffle_abi_f32_all_m128::<0b10_00_10_00>(ra, rb);
        let gy = shuffle_abi_f32_all_m128::<0b11_01_11_01>(ra, rb);
        (gx, gy)
    }

    /// The noise at `(x, y)`, or `None` outside the vector path's range.
    #[inline]
    fn sample2(&self, x: f32, y: f32) -> Option<f32> {
        let (cell, f, s) = split_fade(m128::from_array([x, y, 0.0, 0.0]), 0b11)?;
        let [cx, cy, ..] = cell;
        // Perlin's chain, x innermost: corner (i, j) hashes p[p[x + i] + y + j]. Lanes hold
        // the corners (0, 0), (0, 1), (1, 0), (1, 1), so that the pairs the lerp along x
        // takes are the vector's halves.
        let (gx, gy) = self.gradients_xy(self.p(cx) + cy, self.p(cx + 1) + cy);
        let f1 = sub_m128(f, set_splat_m128(1.0));
        let u = unpack_low_m128(f, f1); // fx, fx − 1, fy, fy − 1
        let dx = shuffle_abi_f32_all_m128::<0b01_01_00_00>(u, u);
        let dy = shuffle_abi_f32_all_m128::<0b11_10_11_10>(u, u);
        // g_x·d_x + g_y·d_y, the shared kernel's order.
        let v = add_m128(mul_m128(dx, gx), mul_m128(dy, gy));
        // Along x, then y.
        let r = lerp_halves(v, splat::<0b00_00_00_00>(s));
        Some(finish(r, splat::<0b01_01_01_01>(s)))
    }

    /// The noise at `(x, y, z)`, or `None` outside the vector path's range.
    #[inline]
    fn sample3(&self, x: f32, y: f32, z: f32) -> Option<f32> {
        let (cell, f, s) = split_fade(m128::from_array([x, y, z, 0.0]), 0b111)?;
        let [cx, cy, cz, _] = cell;
        // Perlin's chain, x innermost: corner (i, j, k) hashes p[p[p[x + i] + y + j] + z + k].
        let a = self.p(cx) + cy;
        let b = self.p(cx + 1) + cy;
        let (aa, ab) = (self.p(a) + cz, self.p(a + 1) + cz);
        let (ba, bb) = (self.p(b) + cz, self.p(b + 1) + cz);
        let f1 = sub_m128(f, set_splat_m128(1.0));
        let u = unpack_low_m128(f, f1); // fx, fx − 1, fy, fy − 1
        let w = unpack_high_m128(f, f1); // fz, fz − 1, 0, −1
        let dy = shuffle_abi_f32_all_m128::<0b11_11_10_10>(u, u);
        let dz = move_low_high_m128(w, w);
        // The corners with i = 0 in one vector, i = 1 in the other, (j, k) = (0, 0), (0, 1),
        // (1, 0), (1, 1) in lanes 0–3: the lerp along x pairs lanes, along y the halves.
        let x0 = self.dots3(aa, ab, splat::<0b00_00_00_00>(f), dy, dz);
        let x1 = self.dots3(ba, bb, splat::<0b00_00_00_00>(f1), dy, dz);
        let r = lerp(splat::<0b00_00_00_00>(s), x0, x1);
        let q = lerp_halves(r, splat::<0b01_01_01_01>(s));
        Some(finish(q, splat::<0b10_10_10_10>(s)))
    }

    /// The noise at `(x, y, z, w)`, or `None` outside the vector path's range.
    #[inline]
    fn sample4(&self, x: f32, y: f32, z: f32, w: f32) -> Option<f32> {
        let (cell, f, s) = split_fade(m128::from_array([x, y, z, w]), 0b1111)?;
        let [cx, cy, cz, cw] = cell;
        // Perlin's chain, x innermost: corner (i, j, k, l) hashes
        // p[p[p[p[x + i] + y + j] + z + k] + w + l].
        let (a0, a1) = (self.p(cx) + cy, self.p(cx + 1) + cy);
        let b = |a: usize| (self.p(a) + cz, self.p(a + 1) + cz);
        let c = |b: usize| (self.p(b) + cw, self.p(b + 1) + cw);
        let ((b00, b01), (b10, b11)) = (b(a0), b(a1));
        let f1 = sub_m128(f, set_splat_m128(1.0));
        let u = unpack_low_m128(f, f1); // fx, fx − 1, fy, fy − 1
        let v = unpack_high_m128(f, f1); // fz, fz − 1, fw, fw − 1
        // Lanes hold the corners (k, l) = (0, 0), (0, 1), (1, 0), (1, 1) of one (i, j).
        let dz = shuffle_abi_f32_all_m128::<0b01_01_00_00>(v, v);
        let dw = shuffle_abi_f32_all_m128::<0b11_10_11_10>(v, v);
        let [dx0, dx1] = [splat::<0b00_00_00_00>(u), splat::<0b01_01_01_01>(u)];
        let [dy0, dy1] = [splat::<0b10_10_10_10>(u), splat::<0b11_11_11_11>(u)];
        let dots = |b: usize, dx: m128, dy: m128| {
            let (c0, c1) = c(b);
            self.dots4([c0, c0 + 1, c1, c1 + 1], dx, dy, dz, dw)
        };
        // The lerps in the shared kernel's order: along x, y, z, then w.
        let sx = splat::<0b00_00_00_00>(s);
        let x0 = lerp(sx, dots(b00, dx0, dy0), dots(b10, dx1, dy0));
        let x1 = lerp(sx, dots(b01, dx0, dy1), dots(b11, dx1, dy1));
        let r = lerp(splat::<0b01_01_01_01>(s), x0, x1);
        let q = lerp_halves(r, splat::<0b10_10_10_10>(s));
        Some(finish(q, splat::<0b11_11_11_11>(s)))
    }

    /// The dot products of the 4D gradients of `p[i]` for the four hash inputs `i` with the
    /// offsets, one corner per lane, in the shared kernel's order
    /// `((d_x·g_x + d_y·g_y) + d_z·g_z) + d_w·g_w` (its zero term changes at most the sign of a
    /// zero, which [`finish`] canonicalises).
    #[inline]
    fn dots4(&self, i: [usize; 4], dx: m128, dy: m128, dz: m128, dw: m128) -> m128 {
        // A reference, so the table is a promoted static, not built on the stack.
        let table: &[[f32; 4]; 32] = &Grad4::<f32>::TABLE;
        let [mut gx, mut gy, mut gz, mut gw] =
            i.map(|i| load_unaligned_m128(&table[self.p(i) & 31]));
        transpose_four_m128(&mut gx, &mut gy, &mut gz, &mut gw);
        add_m128(
            add_m128(
                add_m128(mul_m128(dx, gx), mul_m128(dy, gy)),
                mul_m128(dz, gz),
            ),
            mul_m128(dw, gw),
        )
    }

    /// The dot products of the gradients of hash inputs `a`, `a + 1`, `b`, `b + 1` with the
    /// offsets, in the shared kernel's order `(d_x·g_x + d_y·g_y) + d_z·g_z`, one corner per
    /// lane.
    #[inline]
    fn dots3(&self, a: usize, b: usize, dx: m128, dy: m128, dz: m128) -> m128 {
        let (gx, gy) = self.gradients_xy(a, b);
        let [za, zb] = [a, b].map(|i| load_unaligned_m128(&self.pair(i)[1]));
        let gz = move_low_high_m128(za, zb);
        add_m128(
            add_m128(mul_m128(dx, gx), mul_m128(dy, gy)),
            mul_m128(dz, gz),
        )
    }
}

/// Lane `L` of `v` in every lane (`MASK` repeats `L` four times).
#[inline]
fn splat<const MASK: i32>(v: m128) -> m128 {
    shuffle_abi_f32_all_m128::<MASK>(v, v)
}

/// [`Real::split`](crate::Real::split) of the lanes `axes` selects (a bit per lane), and the
/// quintic fade of the fractions: the cells reduced mod 256, the fractions and the faded
/// fractions. `None` leaves the point to the shared kernel: a coordinate outside
/// `(−2^31, 2^31)` or not finite (where the truncating conversion gives its "invalid" value
/// −2^31; −2^31 itself goes there too), or a negative one so small that its fraction rounds
/// to 1 (the next cell, fraction 0, in [`Real::split`](crate::Real::split)). Leaving that rare
/// case out keeps the cells, and so the hash chain that waits for them, one comparison earlier.
///
/// The fraction of `−0.0` stays `−0.0` here (the shared kernel adds `+0.0`); that changes at
/// most the sign of a zero in the sum, which [`finish`] canonicalises like the shared kernel.
#[inline]
fn split_fade(v: m128, axes: i32) -> Option<([usize; 4], m128, m128)> {
    // floor: truncate, then one down where truncation rounded up (negative non-integers).
    let t = truncate_m128_to_m128i(v);
    let above = cmp_gt_mask_m128(convert_to_m128_from_i32_m128i(t), v);
    let cell = add_i32_m128i(t, cast_to_m128i_from_m128(above));
    let f = sub_m128(v, convert_to_m128_from_i32_m128i(cell));
    let invalid = cmp_eq_mask_i32_m128i(t, set_splat_i32_m128i(i32::MIN));
    let rounds_to_one = cmp_ge_mask_m128(f, set_splat_m128(1.0));
    if move_mask_m128(bitor_m128(cast_to_m128_from_m128i(invalid), rounds_to_one)) & axes != 0 {
        return None;
    }
    // Perlin's order: t·t·t·(t·(t·6 − 15) + 10).
    let t3 = mul_m128(mul_m128(f, f), f);
    let inner = sub_m128(mul_m128(f, set_splat_m128(6.0)), set_splat_m128(15.0));
    let s = mul_m128(t3, add_m128(mul_m128(f, inner), set_splat_m128(10.0)));
    let cells = [
        get_i32_from_m128i_s(cell) as usize & 255,
        extract_i16_as_i32_m128i::<2>(cell) as usize & 255,
        extract_i16_as_i32_m128i::<4>(cell) as usize & 255,
        extract_i16_as_i32_m128i::<6>(cell) as usize & 255,
    ];
    Some((cells, f, s))
}

/// Perlin's `lerp(t, a, b) = a + t·(b − a)`, lane by lane.
#[inline]
fn lerp(t: m128, a: m128, b: m128) -> m128 {
    add_m128(a, mul_m128(t, sub_m128(b, a)))
}

/// [`lerp`] of the pairs `(v0, v2)` and `(v1, v3)`, in lanes 0 and 1.
#[inline]
fn lerp_halves(v: m128, t: m128) -> m128 {
    lerp(t, v, move_high_low_m128(v, v))
}

/// The last interpolation step, `lerp(t, v0, v1)`, then `+ 0.0` as
/// [`Real::canonical`](crate::Real::canonical) does.
#[inline]
fn finish(v: m128, t: m128) -> f32 {
    let v1 = splat::<0b01_01_01_01>(v);
    let n = add_m128_s(v, mul_m128_s(t, sub_m128_s(v1, v)));
    get_f32_from_m128_s(add_m128_s(n, zeroed_m128()))
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

#[cfg(test)]
mod tests {
    use super::{GradientPairs, Kernel, PAIR_ROWS, PerlinPairs};
    use crate::lattice::{Perlin, sample_lattice};

    /// Random coordinates of every magnitude (random bit patterns: NaN, ±∞, subnormals, huge)
    /// and in the range where noise is usually sampled, with the edge cases of `split`.
    fn points(n: usize) -> impl Iterator<Item = [f32; 4]> {
        let mut state = 0x853c_49e6_748f_ea9b_u64;
        let edges = [
            0.0,
            -0.0,
            -1e-30,
            1e-30,
            -1e-8,
            0.999_999_94,
            -0.999_999_94,
            255.5,
            256.0,
            -256.0,
            4_194_303.5,
            -4_194_303.5,
            4_194_304.0,
            -4_194_304.0,
            2_147_483_520.0,
            -2_147_483_520.0,
            2_147_483_648.0,
            -2_147_483_648.0,
            f32::NAN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::MAX,
            f32::MIN_POSITIVE,
        ];
        let edge_points = edges
            .into_iter()
            .flat_map(move |x| edges.into_iter().map(move |y| [x, y, -y, x]));
        let random = core::iter::repeat_with(move || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            let bits = state;
            let coordinate = |shift: u32| {
                let v = (bits >> shift) as u32;
                if bits & 1 == 0 {
                    f32::from_bits(v)
                } else {
                    (v >> 8) as f32 / 65_536.0 - 128.0
                }
            };
            let w = if bits >> 63 == 0 {
                coordinate(11)
            } else {
                -coordinate(32)
            };
            [coordinate(0), coordinate(21), coordinate(42), w]
        });
        edge_points.chain(random.take(n))
    }

    /// The kernel over `pairs` against the shared kernel, bit for bit.
    fn check<G: GradientPairs>(perlin: &Perlin, pairs: &G) {
        let kernel = Kernel {
            p: perlin.doubled(),
            pairs,
        };
        let mut vector_path = [0usize; 3];
        for [x, y, z, w] in points(200_000) {
            let expected2: f32 = sample_lattice(perlin, [x, y]);
            if let Some(v) = kernel.sample2(x, y) {
                assert_eq!(v.to_bits(), expected2.to_bits(), "2D ({x}, {y})");
                vector_path[0] += 1;
            }
            let expected3: f32 = sample_lattice(perlin, [x, y, z]);
            if let Some(v) = kernel.sample3(x, y, z) {
                assert_eq!(v.to_bits(), expected3.to_bits(), "3D ({x}, {y}, {z})");
                vector_path[1] += 1;
            }
            let expected4: f32 = sample_lattice(perlin, [x, y, z, w]);
            if let Some(v) = kernel.sample4(x, y, z, w) {
                assert_eq!(v.to_bits(), expected4.to_bits(), "4D ({x}, {y}, {z}, {w})");
                vector_path[2] += 1;
            }
        }
        // Half the random points are in range: the vector path was exercised.
        assert!(vector_path.iter().all(|&n| n > 90_000), "{vector_path:?}");
    }

    #[test]
    fn vector_kernel_is_the_shared_kernel_bit_for_bit() {
        for seed in [0, 1, 0xdead_beef] {
            let perlin = Perlin::new(seed);
            check(&perlin, &PAIR_ROWS);
            check(&perlin, &PerlinPairs::new(perlin.doubled()));
        }
    }
}

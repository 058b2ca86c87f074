//! Perlin's improved noise (Perlin 2002, "Improving Noise") at one point in 2D, 3D and 4D, in
//! `f32`, over a 4-lane vector of `f32` ([`Lanes`]): written once here, compiled for each
//! target's vector unit ([`x86_64`](super) SSE2, `wasm32` simd128). The axes are split and
//! faded together, and the 4 (2D), 8 (3D) or 16 (4D) corner dot products and the lerps are
//! done in vectors. The point kernel of [`sample_lattice`] does the same steps one number at a
//! time.
//!
//! A sample is bound by latency: Perlin's hash is a chain of dependent lookups (`p[p[x] + y]`,
//! then a gradient), and every lerp waits for the one before; and by the number of its
//! operations on the ports vector and integer arithmetic share (`bench/README.md`). The
//! gradient components come from static tables indexed by the hash byte itself, two
//! components of a corner in one 8-byte entry, so that two corners' entries load into one
//! vector with no index arithmetic ([`HALVES`]: x and y in 2D, x and y, then z and w in 4D);
//! one shuffle more per pair of vectors splits them by axis. In 3D the
//! gradients of two neighbouring hash values come from one row of a table indexed by both
//! hashes' low nibbles ([`PAIR_ROWS`]), already split by axis. A seed's own table
//! ([`PerlinPairs`], which [`TabledPerlin`](crate::lattice::TabledPerlin) holds) composes
//! those rows with the permutation, so that the last level of the chain reads gradients at the
//! index it forms, without reading the permutation there.
//!
//! Every lane computes the operations of the shared kernel on the same numbers in the same order
//! (IEEE `+ − ×`, no fused multiply-add), so the results are those of [`sample_lattice`] bit for
//! bit; a test compares them over random and edge-case points (natively; in WebAssembly,
//! `bindings/wasm/tests/kernel.rs` compares the point kernel with the batch kernels).
//!
//! [`sample_lattice`]: crate::lattice

use crate::lattice::perlin::{GRAD3, Grad4};

use super::selected::F32x4;

/// The operations the kernels need of a target's 4-lane `f32` vector, each one instruction or a
/// few. Lane order is memory order: `from_array([a, b, c, d])` has `a` in lane 0.
pub(super) trait Lanes: Copy {
    /// The vector of four values.
    fn from_array(a: [f32; 4]) -> Self;
    /// The two pairs of `f32` whose bits `lo` and `hi` hold, each the low word first (as
    /// [`packed`] stores them): one 8-byte load and one load into the high half.
    fn from_halves(lo: &f64, hi: &f64) -> Self;
    /// A row of a table.
    fn load(row: &[f32; 4]) -> Self;
    /// `v` in every lane.
    fn splat(v: f32) -> Self;
    /// IEEE `+`, lane by lane.
    fn add(self, o: Self) -> Self;
    /// IEEE `−`, lane by lane.
    fn sub(self, o: Self) -> Self;
    /// IEEE `×`, lane by lane.
    fn mul(self, o: Self) -> Self;
    /// Lane `L` in every lane.
    fn broadcast<const L: usize>(self) -> Self;
    /// `[a₀, a₂, b₀, b₂]`.
    fn evens(self, b: Self) -> Self;
    /// `[a₁, a₃, b₁, b₃]`.
    fn odds(self, b: Self) -> Self;
    /// `[a₀, b₀, a₁, b₁]`.
    fn interleave_low(self, b: Self) -> Self;
    /// `[a₂, b₂, a₃, b₃]`.
    fn interleave_high(self, b: Self) -> Self;
    /// `[a₀, a₁, b₀, b₁]`.
    fn low_halves(self, b: Self) -> Self;
    /// `[a₂, a₃, a₂, a₃]`.
    fn high_half(self) -> Self;
    /// `[a₀, a₀, a₁, a₁]`.
    fn low_pairs(self) -> Self;
    /// `[a₂, a₂, a₃, a₃]`.
    fn high_pairs(self) -> Self;
    /// Lane 0.
    fn first(self) -> f32;
    /// The sign bits, lane `l` at bit `l` (`movmskps`).
    fn signs(self) -> u32;
    /// The lanes whose sign bit is set in `self` and clear in `clear`, lane `l` at bit `l`.
    fn signs_without(self, clear: Self) -> u32;
    /// The floor and the fraction of each lane, the cells reduced mod 256, as
    /// [`Real::split`](crate::Real::split) gives them wherever the fraction is in `[0, 1)`;
    /// the kernels keep a point only where every fraction they use is
    /// ([`split_fade`]), and leave the others to the shared kernel: a coordinate outside
    /// `(−2^31, 2^31)` or not finite, whose fraction is then outside `[0, 1)` or NaN, or a
    /// negative one so small that its fraction rounds to 1 (the next cell, fraction 0, in
    /// `Real::split`). Leaving that rare case out keeps the cells, and so the hash chain that
    /// waits for them, one comparison earlier. `None` where a target's conversion cannot tell
    /// such a coordinate by its fraction (WebAssembly's saturates), for the lanes `axes`
    /// selects (a bit per lane). `−0.0` is left too (its fraction is `−0.0`), and x86-64 takes
    /// `−2^31`: the same value either way.
    fn split(self, axes: u32) -> Option<([usize; 4], Self)>;
}

pub(crate) const PERLIN_POINT: bool = true;

#[inline]
pub(crate) fn perlin2(p: &[u8; 512], x: f32, y: f32) -> Option<f32> {
    Kernel {
        p,
        pairs: &PAIR_ROWS,
    }
    .sample2::<F32x4>(x, y)
}

#[inline]
pub(crate) fn perlin3(p: &[u8; 512], x: f32, y: f32, z: f32) -> Option<f32> {
    Kernel {
        p,
        pairs: &PAIR_ROWS,
    }
    .sample3::<F32x4>(x, y, z)
}

#[inline]
pub(crate) fn perlin4(p: &[u8; 512], x: f32, y: f32, z: f32, w: f32) -> Option<f32> {
    Kernel {
        p,
        pairs: &PAIR_ROWS,
    }
    .sample4::<F32x4>(x, y, z, w)
}

#[inline]
pub(crate) fn perlin4_paired(
    p: &[u8; 512],
    pairs: &PerlinPairs,
    x: f32,
    y: f32,
    z: f32,
    w: f32,
) -> Option<f32> {
    Kernel { p, pairs }.sample4::<F32x4>(x, y, z, w)
}

#[inline]
pub(crate) fn perlin2_paired(p: &[u8; 512], pairs: &PerlinPairs, x: f32, y: f32) -> Option<f32> {
    Kernel { p, pairs }.sample2::<F32x4>(x, y)
}

#[inline]
pub(crate) fn perlin3_paired(
    p: &[u8; 512],
    pairs: &PerlinPairs,
    x: f32,
    y: f32,
    z: f32,
) -> Option<f32> {
    Kernel { p, pairs }.sample3::<F32x4>(x, y, z)
}

/// Where the kernel finds the gradients of `p[i]` and `p[i + 1]`, split by axis:
/// `[g₀ₓ, g₀ᵧ, g₁ₓ, g₁ᵧ]` and `[g₀z, g₁z, 0, 0]` (2D and 3D, `GRAD3`), and the 4D gradients
/// (`Grad4`) as `[g₀ₓ, g₀ᵧ, g₁ₓ, g₁ᵧ]` and `[g₀z, g₀w, g₁z, g₁w]`.
trait GradientPairs {
    fn pair(&self, p: &[u8; 512], i: usize) -> &[[f32; 4]; 2];

    /// `[g₀ₓ, g₀ᵧ, g₁ₓ, g₁ᵧ]`, the first row of [`pair`](Self::pair).
    #[inline]
    fn xy<V: Lanes>(&self, p: &[u8; 512], i: usize) -> V {
        V::load(&self.pair(p, i)[0])
    }

    /// The 4D gradients of `p[i]` and `p[i + 1]`: their x and y components, then their z and
    /// w components.
    fn four<V: Lanes>(&self, p: &[u8; 512], i: usize) -> (V, V);
}

/// The static table: look up `p[i]` and `p[i + 1]`, then their row.
impl GradientPairs for PairRows {
    #[inline]
    fn pair(&self, p: &[u8; 512], i: usize) -> &[[f32; 4]; 2] {
        let row = usize::from(p[i] & 15) | usize::from(p[i + 1] & 15) << 4;
        &self.0[row]
    }

    /// The gradients of `p[i]` and `p[i + 1]` from [`HALVES`], one entry each: no row index to
    /// compute (8 integer operations fewer per 2D sample, 7% of its time, `bench/README.md`).
    /// 3D keeps the pair's row, which also has the z components.
    #[inline]
    fn xy<V: Lanes>(&self, p: &[u8; 512], i: usize) -> V {
        let [a, b] = [p[i], p[i + 1]].map(|h| &HALVES.0[XY + usize::from(h)]);
        V::from_halves(a, b)
    }

    /// From [`HALVES`]' 4D sections, at the hash bytes.
    #[inline]
    fn four<V: Lanes>(&self, p: &[u8; 512], i: usize) -> (V, V) {
        let [a, b] = [p[i], p[i + 1]].map(usize::from);
        let half = |at: usize| V::from_halves(&HALVES.0[at + a], &HALVES.0[at + b]);
        (half(XY4), half(ZW4))
    }
}

/// Two components of the gradient Perlin's `grad` selects for each hash `h < 256`, as the
/// bits of two `f32`, the first in the low word ([`packed`]), in three sections of 256:
/// x and y in 2D and 3D (`GRAD3[h & 15]`) at [`XY`], then x and y at [`XY4`] and z and w at
/// [`ZW4`] in 4D (`Grad4`'s row `h & 31`). One table, so that every read is at the hash byte
/// scaled by 8 plus a constant, with no shift. 6 KiB.
#[repr(align(64))]
struct Halves([f64; 768]);

/// Where [`HALVES`]' sections start.
const XY: usize = 0;
const XY4: usize = 256;
const ZW4: usize = 512;

static HALVES: Halves = {
    let mut rows = [0.0f64; 768];
    let mut i = 0;
    while i < 768 {
        let (g3, g4) = (GRAD3[i & 15], Grad4::<f32>::TABLE[i & 31]);
        rows[i] = match i / 256 {
            0 => packed(g3[0] as f32, g3[1] as f32),
            1 => packed(g4[0], g4[1]),
            _ => packed(g4[2], g4[3]),
        };
        i += 1;
    }
    Halves(rows)
};

/// The bits of `a` and `b` as one `f64`, `a` in the low word, as [`Lanes::from_halves`] reads
/// them. Never a NaN for the gradients' components (`b`'s bits are those of −1, 0 or 1), and
/// only the bits are ever read.
const fn packed(a: f32, b: f32) -> f64 {
    f64::from_bits((b.to_bits() as u64) << 32 | a.to_bits() as u64)
}

/// A seed's tables, the gradients composed with the permutation: entry `b` (`b < 512`, an
/// index of the doubled permutation `p`) holds the gradients of `p[b]` and `p[b + 1]`, for 2D
/// and 3D (`PAIR_ROWS`' row) and for 4D (`Grad4`'s rows, as [`GradientPairs::four`] gives
/// them). One lookup replaces two permutation lookups and their gradients' lookups, and takes
/// a level off the chain of dependent loads: `p[p[x] + y]` and its neighbour in 2D,
/// `p[p[p[x] + y] + z]` and its neighbour in 3D, `p[p[p[p[x] + y] + z] + w]` and its
/// neighbour in 4D. 16 KiB each, built by `const fn`; a caller opts into them with
/// [`TabledPerlin`](crate::lattice::TabledPerlin).
#[derive(Clone)]
#[repr(align(32))]
pub(crate) struct PerlinPairs {
    three: [[[f32; 4]; 2]; 512],
    four: [[[f32; 4]; 2]; 512],
}

impl PerlinPairs {
    pub(crate) const fn new(p: &[u8; 512]) -> Self {
        let mut three = [[[0.0f32; 4]; 2]; 512];
        let mut four = [[[0.0f32; 4]; 2]; 512];
        let mut b = 0;
        while b < 512 {
            // Entry 511 is never read (b ≤ 255 + 255); its p[b + 1] wraps as p does.
            let (g, h) = (p[b], p[(b + 1) & 511]);
            three[b] = PAIR_ROWS.0[(g & 15) as usize | ((h & 15) as usize) << 4];
            let (g, h) = (
                Grad4::<f32>::TABLE[(g & 31) as usize],
                Grad4::<f32>::TABLE[(h & 31) as usize],
            );
            four[b] = [[g[0], g[1], h[0], h[1]], [g[2], g[3], h[2], h[3]]];
            b += 1;
        }
        Self { three, four }
    }
}

impl GradientPairs for PerlinPairs {
    #[inline]
    fn pair(&self, _: &[u8; 512], i: usize) -> &[[f32; 4]; 2] {
        &self.three[i]
    }

    #[inline]
    fn four<V: Lanes>(&self, _: &[u8; 512], i: usize) -> (V, V) {
        let [xy, zw] = &self.four[i];
        (V::load(xy), V::load(zw))
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

/// The kernel over a seed's doubled permutation (see [`Perlin`](crate::lattice::Perlin)),
/// whose hash chain `p[p[x] + y]` needs no `& 255` (every index it forms is at most
/// 255 + 256).
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
    /// that lane order (2D).
    #[inline]
    fn gradients_xy<V: Lanes>(&self, a: usize, b: usize) -> (V, V) {
        let [ra, rb] = [a, b].map(|i| self.pairs.xy::<V>(self.p, i));
        (ra.evens(rb), ra.odds(rb))
    }

    /// The noise at `(x, y)`, or `None` outside the vector path's range.
    #[inline]
    fn sample2<V: Lanes>(&self, x: f32, y: f32) -> Option<f32> {
        // Each coordinate in two lanes, `[x, x, y, y]` (one shuffle from two numbers), so that
        // the offsets `[fx, fx − 1, fy, fy − 1]`, and the fade each lerp takes, are one
        // shuffle each or none: the kernel is bound by its vector operations
        // (`bench/README.md`).
        let (cell, _, e, s) = split_fade::<V, true>(V::from_array([x, x, y, y]))?;
        let [cx, _, cy, _] = cell;
        // Perlin's chain, x innermost: corner (i, j) hashes p[p[x + i] + y + j]. Lanes hold
        // the corners (0, 0), (0, 1), (1, 0), (1, 1), so that the pairs the lerp along x
        // takes are the vector's halves.
        let (gx, gy) = self.gradients_xy::<V>(self.p(cx) + cy, self.p(cx + 1) + cy);
        // fx, fx, fx − 1, fx − 1 and fy, fy − 1, fy, fy − 1.
        let (dx, dy) = (e.low_pairs(), e.high_half());
        // g_x·d_x + g_y·d_y, the shared kernel's order.
        let v = dx.mul(gx).add(dy.mul(gy));
        // Along x (the fade of x in lanes 0 and 1), then y (in lane 2).
        let r = lerp_halves(v, s);
        Some(finish(r, s.high_half()))
    }

    /// The noise at `(x, y, z)`, or `None` outside the vector path's range.
    #[inline]
    fn sample3<V: Lanes>(&self, x: f32, y: f32, z: f32) -> Option<f32> {
        let (cell, f, f1, s) = split_fade::<V, false>(V::from_array([x, y, z, 0.0]))?;
        let [cx, cy, cz, _] = cell;
        // Perlin's chain, x innermost: corner (i, j, k) hashes p[p[p[x + i] + y + j] + z + k].
        let a = self.p(cx) + cy;
        let b = self.p(cx + 1) + cy;
        let (aa, ab) = (self.p(a) + cz, self.p(a + 1) + cz);
        let (ba, bb) = (self.p(b) + cz, self.p(b + 1) + cz);
        let u = f.interleave_low(f1); // fx, fx − 1, fy, fy − 1
        let w = f.interleave_high(f1); // fz, fz − 1, 0, −1
        let (dy, dz) = (u.high_pairs(), w.low_halves(w));
        // The corners with i = 0 in one vector, i = 1 in the other, (j, k) = (0, 0), (0, 1),
        // (1, 0), (1, 1) in lanes 0–3: the lerp along x pairs lanes, along y the halves.
        let x0 = self.dots3(aa, ab, f.broadcast::<0>(), dy, dz);
        let x1 = self.dots3(ba, bb, f1.broadcast::<0>(), dy, dz);
        let r = lerp(s.broadcast::<0>(), x0, x1);
        let q = lerp_halves(r, s.broadcast::<1>());
        Some(finish(q, s.broadcast::<2>()))
    }

    /// The noise at `(x, y, z, w)`, or `None` outside the vector path's range.
    #[inline]
    fn sample4<V: Lanes>(&self, x: f32, y: f32, z: f32, w: f32) -> Option<f32> {
        let (cell, f, f1, s) = split_fade::<V, false>(V::from_array([x, y, z, w]))?;
        let [cx, cy, cz, cw] = cell;
        // Perlin's chain, x innermost: corner (i, j, k, l) hashes
        // p[p[p[p[x + i] + y + j] + z + k] + w + l].
        let (a0, a1) = (self.p(cx) + cy, self.p(cx + 1) + cy);
        let b = |a: usize| (self.p(a) + cz, self.p(a + 1) + cz);
        let c = |b: usize| (self.p(b) + cw, self.p(b + 1) + cw);
        let ((b00, b01), (b10, b11)) = (b(a0), b(a1));
        let u = f.interleave_low(f1); // fx, fx − 1, fy, fy − 1
        let v = f.interleave_high(f1); // fz, fz − 1, fw, fw − 1
        // Lanes hold the corners (k, l) = (0, 0), (0, 1), (1, 0), (1, 1) of one (i, j).
        let (dz, dw) = (v.low_pairs(), v.high_half());
        let [dx0, dx1] = [u.broadcast::<0>(), u.broadcast::<1>()];
        let [dy0, dy1] = [u.broadcast::<2>(), u.broadcast::<3>()];
        let dots = |b: usize, dx: V, dy: V| {
            let (c0, c1) = c(b);
            self.dots4(c0, c1, dx, dy, dz, dw)
        };
        // The lerps in the shared kernel's order: along x, y, z, then w.
        let sx = s.broadcast::<0>();
        let x0 = lerp(sx, dots(b00, dx0, dy0), dots(b10, dx1, dy0));
        let x1 = lerp(sx, dots(b01, dx0, dy1), dots(b11, dx1, dy1));
        let r = lerp(s.broadcast::<1>(), x0, x1);
        let q = lerp_halves(r, s.broadcast::<2>());
        Some(finish(q, s.broadcast::<3>()))
    }

    /// The dot products of the 4D gradients of hash inputs `a`, `a + 1`, `b`, `b + 1` with
    /// the offsets, one corner per lane, in the shared kernel's order
    /// `((d_x·g_x + d_y·g_y) + d_z·g_z) + d_w·g_w` (its zero term changes at most the sign of a
    /// zero, which [`finish`] canonicalises).
    #[inline]
    fn dots4<V: Lanes>(&self, a: usize, b: usize, dx: V, dy: V, dz: V, dw: V) -> V {
        let (xy01, zw01) = self.pairs.four::<V>(self.p, a);
        let (xy23, zw23) = self.pairs.four::<V>(self.p, b);
        let (gx, gy) = (xy01.evens(xy23), xy01.odds(xy23));
        let (gz, gw) = (zw01.evens(zw23), zw01.odds(zw23));
        dx.mul(gx).add(dy.mul(gy)).add(dz.mul(gz)).add(dw.mul(gw))
    }

    /// The dot products of the gradients of hash inputs `a`, `a + 1`, `b`, `b + 1` with the
    /// offsets, in the shared kernel's order `(d_x·g_x + d_y·g_y) + d_z·g_z`, one corner per
    /// lane.
    #[inline]
    fn dots3<V: Lanes>(&self, a: usize, b: usize, dx: V, dy: V, dz: V) -> V {
        let [ra, rb] = [a, b].map(|i| self.pair(i));
        let [xa, xb, za, zb] = [&ra[0], &rb[0], &ra[1], &rb[1]].map(V::load);
        let (gx, gy) = (xa.evens(xb), xa.odds(xb));
        let gz = za.low_halves(zb);
        dx.mul(gx).add(dy.mul(gy)).add(dz.mul(gz))
    }
}

/// [`Lanes::split`], the fractions less 1 (with `PAIRS`, less 0 and 1: the lanes hold two
/// coordinates, each twice, `[a, a, b, b]`, and become `[fa, fa − 1, fb, fb − 1]`), and the
/// quintic fade of the fractions: the cells, the fractions, the differences and the faded
/// fractions. `None` unless every fraction is in `[0, 1)`: its sign bit clear and that of the
/// fraction less 1 set (`f − 1` is never 0 for `f < 1`; NaN keeps its sign through the
/// subtraction). The kernels need the differences for the corners' offsets, so the test costs
/// one `andnps` and the mask, and with `PAIRS` the mask alone (the differences' signs are
/// both; `bench/README.md`: the vector operations bound a sample).
#[inline]
fn split_fade<V: Lanes, const PAIRS: bool>(v: V) -> Option<([usize; 4], V, V, V)> {
    let (cells, f) = v.split(if PAIRS { 0b0101 } else { 0b1111 })?;
    let (e, kept) = if PAIRS {
        let e = f.sub(V::from_array([0.0, 1.0, 0.0, 1.0]));
        (e, e.signs() == 0b1010)
    } else {
        let e = f.sub(V::splat(1.0));
        (e, e.signs_without(f) == 0b1111)
    };
    if !kept {
        return None;
    }
    // Perlin's order: t·t·t·(t·(t·6 − 15) + 10).
    let t3 = f.mul(f).mul(f);
    let inner = f.mul(V::splat(6.0)).sub(V::splat(15.0));
    let s = t3.mul(f.mul(inner).add(V::splat(10.0)));
    Some((cells, f, e, s))
}

/// Perlin's `lerp(t, a, b) = a + t·(b − a)`, lane by lane.
#[inline]
fn lerp<V: Lanes>(t: V, a: V, b: V) -> V {
    a.add(t.mul(b.sub(a)))
}

/// [`lerp`] of the pairs `(v0, v2)` and `(v1, v3)`, in lanes 0 and 1.
#[inline]
fn lerp_halves<V: Lanes>(v: V, t: V) -> V {
    lerp(t, v, v.high_half())
}

/// The last interpolation step, `lerp(t, v0, v1)`, then `+ 0.0` as
/// [`Real::canonical`](crate::Real::canonical) does.
#[inline]
fn finish<V: Lanes>(v: V, t: V) -> f32 {
    let (v0, v1, t) = (v.first(), v.broadcast::<1>().first(), t.first());
    (v0 + t * (v1 - v0)) + 0.0
}

#[cfg(test)]
mod tests {
    use super::{F32x4, GradientPairs, Kernel, PAIR_ROWS, PerlinPairs};
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
            -2_147_483_904.0,
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
            if let Some(v) = kernel.sample2::<F32x4>(x, y) {
                assert_eq!(v.to_bits(), expected2.to_bits(), "2D ({x}, {y})");
                vector_path[0] += 1;
            }
            let expected3: f32 = sample_lattice(perlin, [x, y, z]);
            if let Some(v) = kernel.sample3::<F32x4>(x, y, z) {
                assert_eq!(v.to_bits(), expected3.to_bits(), "3D ({x}, {y}, {z})");
                vector_path[1] += 1;
            }
            let expected4: f32 = sample_lattice(perlin, [x, y, z, w]);
            if let Some(v) = kernel.sample4::<F32x4>(x, y, z, w) {
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

//! A window of a band's coefficient grid, for the bases wider than a plain band's 3 per axis:
//! the projected basis (`projected.rs`) and the box-widened basis (`filtered.rs`).
//!
//! With blended or varied tiling (§4.3), the coefficient at a global index is the tile read in
//! the placement of the block that holds it or, in a blend zone, the blend-weighted sum of
//! the blocks' coefficients along each axis that crosses one (`band.rs`). Found for each
//! coefficient on its own (`Wavelet::fetch`, the tests' reference in `compact.rs`), that
//! costs per axis a division by the tile size and the blend weights' branches, and per block
//! a placement lookup. A window resolves the per-axis part once per axis and offset (at most [`WIDTH`]
//! offsets per axis) and each block's placement once, into per-axis parts of the tile's flat
//! index, so reading a coefficient costs D − 1 additions and a load per block and, in a
//! zone, the blend products.
//!
//! The values are those of `fetch`, bit for bit: the same blocks in the same order (x
//! fastest), each read `t_b ω_x ω_y ω_z`, rounded in that order (the tests in `projected.rs`
//! compare the two).

use crate::Real;

use super::band::{TileData, Wavelet, blend_weight, first_block, tile_index};

/// The most coefficients a window spans along an axis. The projected basis reaches
/// `|d| < 3|n_a| + 3√((1 − n_a²)/2) + 1/256 < 3.7` along axis `a`, so at most 8 integers;
/// the box-widened basis `|d| < 3/2 + w/2 ≤ 7/2`, also 8.
pub(crate) const WIDTH: usize = 8;

/// One offset of the window along one axis.
#[derive(Clone, Copy, Debug)]
struct Along<R> {
    /// The first block that reaches the coefficient.
    block: i32,
    /// That block's slot, counted from the window's first block along the axis (0 or 1 when
    /// the window is cached).
    slot: usize,
    /// The coefficient's local index in that block, plus the tile size `n` (in `[n − h,
    /// 2n + h)` for a blend half-width `h`).
    local: usize,
    /// Whether the next block reaches it too (a blend zone).
    zone: bool,
    /// In a zone, its blend weights in the first block and the next; outside one, 1 and 1
    /// (multiplied as they are: exact).
    blend: [R; 2],
}

/// The coefficients at global indices `first + k`, `0 ≤ k_a < count_a ≤` [`WIDTH`], of one
/// band.
pub(crate) struct Window<'w, 't, T, R, const D: usize> {
    wavelet: &'w Wavelet<'t, T>,
    /// The first block along each axis (slot 0).
    base: [i32; D],
    along: [[Along<R>; WIDTH]; D],
    count: [usize; D],
    /// Whether every coefficient lies in slot 0 or 1 along each axis (always, for tiles at
    /// least `WIDTH − 1 + 2h` wide: the shipped tiles and the demo's), so that each of the
    /// up to 2ᴰ blocks resolves its placement once, into `offsets`. Otherwise (tiles of 4 and
    /// 6, of 12 and 14 when blended, or a window that wraps around `i32`) each coefficient
    /// resolves its blocks' placements itself.
    cached: bool,
    /// The blocks (numbered by their slots, bit `a` along axis `a`) whose `offsets` are filled.
    ready: u8,
    /// Per block, axis and offset `k_a`: the part of the tile's flat index that the
    /// coefficient at offset `k_a` along axis `a` contributes when read in that block
    /// (filled for every offset; read only where the block reaches it).
    offsets: [[[u32; WIDTH]; D]; 8],
}

impl<'w, 't, T: TileData<D>, R: Real, const D: usize> Window<'w, 't, T, R, D> {
    /// The window of `wavelet`'s coefficients from global index `first`, `count` along each
    /// axis (at most [`WIDTH`]; more are not resolved, and read as offset `k mod WIDTH`).
    #[inline(never)]
    pub(crate) fn new(wavelet: &'w Wavelet<'t, T>, first: [i32; D], count: [usize; D]) -> Self {
        let (n, h) = (T::SIZE, wavelet.half_width::<D>());
        let mut window = Window {
            wavelet,
            base: [0; D],
            along: [[Along {
                block: 0,
                slot: 0,
                local: 0,
                zone: false,
                blend: [R::ONE; 2],
            }; WIDTH]; D],
            count: count.map(|c| c.min(WIDTH)),
            cached: true,
            ready: 0,
            offsets: [[[0; WIDTH]; D]; 8],
        };
        for (a, &first) in first.iter().enumerate() {
            for k in 0..window.count[a] {
                let (block, local, zone) = first_block(first.wrapping_add(k as i32), n, h);
                if k == 0 {
                    window.base[a] = block;
                }
                let slot = block.wrapping_sub(window.base[a]) as u32 as usize;
                window.cached &= slot + zone as usize <= 1;
                let along = &mut window.along[a][k % WIDTH];
                (along.block, along.slot, along.local, along.zone) = (block, slot, local, zone);
                if zone {
                    along.blend = [blend_weight(local, n, h), blend_weight(local - n, n, h)];
                }
            }
        }
        window
    }

    /// The coefficient at offsets `k`: `Σ_b t_b ω_x ω_y ω_z` over the (up to 2ᴰ) blocks `b`
    /// that reach it, each read in its placement and weighted by its blend weights (rounded
    /// in that order), in the blocks' order (x fastest).
    #[inline]
    pub(crate) fn coefficient(&mut self, k: [usize; D]) -> R {
        // The axes in a blend zone, and the coefficient's first block (its slots).
        let (mut zones, mut first) = (0, 0);
        for (a, &k) in k.iter().enumerate() {
            let along = &self.along[a][k % WIDTH];
            zones |= (along.zone as usize) << a;
            first |= along.slot << a;
        }
        if !self.cached {
            return self.alone(k, zones);
        }
        // The block m past the first: a zone's first slot is 0, so its slots are first | m.
        self.blended(k, zones, |window, m| {
            let block = (first | m) % 8;
            if window.ready >> block & 1 == 0 {
                window.resolve(block);
            }
            let offsets = &window.offsets[block];
            (0..D).fold(0, |i, a| i + offsets[a][k[a] % WIDTH] as usize)
        })
    }

    /// `Σ_m t_m ω_x ω_y ω_z` over each subset `m` of the zone axes in increasing order (x
    /// fastest), `t_m` the tile at `index(self, m)`, the flat index of the coefficient at
    /// offsets `k` in the block `m` past its first (bit `a` along axis `a`).
    #[inline]
    fn blended(
        &mut self,
        k: [usize; D],
        zones: usize,
        mut index: impl FnMut(&mut Self, usize) -> usize,
    ) -> R {
        let mut value = R::ZERO;
        let mut m = 0;
        loop {
            let i = index(self, m);
            let mut c: R = self.wavelet.tile().flat(i);
            if zones != 0 {
                // An axis outside a zone weighs 1 (`blend`'s default), exactly: no branch per
                // axis.
                for (a, &k) in k.iter().enumerate() {
                    c = c.mul_fraction(self.along[a][k % WIDTH].blend[m >> a & 1]);
                }
            }
            value = value.saturating_add(c);
            if m == zones {
                return value;
            }
            m = m.wrapping_sub(zones) & zones;
        }
    }

    /// Resolves the placement of the block in slots `block` (bit `a` along axis `a`) into its
    /// offsets, for every offset of the window the block reaches. Out of line: a sample calls
    /// it once per block.
    #[inline(never)]
    fn resolve(&mut self, block: usize) {
        let n = T::SIZE;
        let place = self.wavelet.placement(core::array::from_fn(|a| {
            self.base[a].wrapping_add((block >> a & 1) as i32)
        }));
        for a in 0..D {
            let axis = place.axis(a, n);
            // The coefficient's local index in this block plus a multiple of n: its local
            // index in its first block plus n, less n per slot this block lies past it. Every
            // offset is filled; those the block does not reach are never read (`coefficient`
            // reads a coefficient's first block and, in a zone, the next).
            let back = (block >> a & 1) * n;
            for (o, along) in self.offsets[block % 8][a].iter_mut().zip(&self.along[a]) {
                *o = axis.offset(along.local + (along.slot + 1) * n - back, n) as u32;
            }
        }
        self.ready |= 1 << block;
    }

    /// [`coefficient`](Self::coefficient) with each block's placement resolved on its own:
    /// the windows whose blocks cannot be cached by slot.
    #[inline(never)]
    fn alone(&mut self, k: [usize; D], zones: usize) -> R {
        let n = T::SIZE;
        self.blended(k, zones, |window, m| {
            let along: [&Along<R>; D] = core::array::from_fn(|a| &window.along[a][k[a] % WIDTH]);
            let place = window.wavelet.placement(core::array::from_fn(|a| {
                along[a].block.wrapping_add((m >> a & 1) as i32)
            }));
            let local = core::array::from_fn(|a| along[a].local - (m >> a & 1) * n);
            tile_index(local, &place, n)
        })
    }
}

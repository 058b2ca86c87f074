//! Rows of a grid through a wavelet band, bit for bit as [`Wavelet::evaluate`] samples each
//! point, with the work the rows' samples share done once.
//!
//! Along a row only x changes, so every sample reads the same three coefficient indices along
//! y (and z), in the same blocks, with the same weights; neighbouring samples read mostly the
//! same indices along x. A sample's sum is `evaluate`'s: block by block, and in each block, for
//! each x index, the column of 3 (3D: 9) coefficients summed along z, then y, weighted by its x
//! weight (`add_block`, with the same saturating operations). The column's sum involves only
//! y and z, so the row computes it once per x index and block, into a small cache of columns,
//! and each block's placement once, into a cache of blocks; a sample then adds three weighted
//! columns per block it reaches. Fetching a coefficient (a placement hash, the block's cyclic
//! shift and orientation per axis, a remainder) is most of a point sample's cost under
//! [`Tiling::Blended`](super::Tiling::Blended); the row pays it once per column and block.
//!
//! Samples go sixteen at a time (`LANES`): their first coefficients and weights as lanes,
//! then each run of samples with the same first coefficient summed entry by entry across its
//! lanes, so the compiler vectorises both; only the loops are interchanged, each sample's
//! operations and their order are `evaluate`'s.
//!
//! Consecutive rows that read the same y/z coefficients with the same z weights (a z-slice's
//! rows until the first y coefficient moves: 2 rows for a band with a coefficient every 2
//! samples) go together, up to [`GROUP`]: one sweep along x for all of them, each line of
//! coefficients read once and weighted by every row's y weights, the x weights computed once.
//!
//! The caches are fixed arrays on the stack (about 2 KB): no allocation, and any order of
//! x values is correct (a grid with a negative or zero step, or one that jumps between
//! blocks), only slower when x moves by more than the cache holds.

use super::{
    AxisMap, TileData, Wavelet, axis_span, blend_axis, blend_weight, bspline3, bspline3_lanes,
    exclude, members, zone_at,
};
use crate::Real;
use crate::batch::LANES;

/// Columns held: consecutive samples of a row read three consecutive x indices, in at most two
/// blocks; 8 x indices × 2 blocks is more than a row ever needs at once.
const SLOTS: usize = 16;

/// Blocks along x held (keyed by the block's parity: a sample's coefficients reach at most two
/// neighbouring blocks).
const BLOCKS: usize = 2;

/// One block along x: for each subset `s` of the row's crossing y/z axes (bit 0: y reads the
/// next block, bit 1: z), how the block it names reads x, and the y/z parts of the tile index
/// of the row's 3 × 3 coefficients (`base[s][jy][jz]`).
#[derive(Clone, Copy)]
struct Block {
    key: Option<i32>,
    x: [AxisMap; 4],
    base: [[[usize; 3]; 3]; 4],
}

/// Rows summed together at most: consecutive rows that share their y/z coefficients (in a
/// z-slice, the rows until the first y coefficient moves) read each line of coefficients
/// once for all of them, and compute their x weights once. One in WebAssembly, where V8's
/// code for groups of 2 or 4 rows was slower than row by row (measured: bench/README.md,
/// "wavelet rows as lanes and in groups").
pub(crate) const GROUP: usize = if cfg!(target_arch = "wasm32") { 1 } else { 4 };

/// The column cache: slot `k` holds the column at one x index of one block along x
/// (`keys[k]`): `values[4k + s][r]` for each subset `s` of the crossing y/z axes and row `r`
/// of the group, the block's 3 (3D: 9) coefficients there weighted by the row's y and z
/// weights as `add_block` sums them.
struct Columns<R> {
    /// `key(g, b)` of the column each slot holds; initially keys that map to other slots, so
    /// no lookup matches them.
    keys: [u64; SLOTS],
    values: [[R; GROUP]; 4 * SLOTS],
}

/// The y weights of a group's rows, as lanes: `[side][jy][row]` (0 for rows past the group's).
type GroupWeights<R> = [[[R; GROUP]; 3]; 2];

/// The slot of x index `g` in block `b` (distinct for the three x indices and two blocks of
/// one span), and its key.
#[inline]
fn slot(g: i32, b: i32) -> (usize, u64) {
    let slot = ((g as u32 as usize % (SLOTS / 2)) * 2 + (b & 1) as usize) % SLOTS;
    (slot, (g as u32 as u64) << 32 | b as u32 as u64)
}

/// What the samples of a row with the same first x coefficient share
/// ([`Wavelet::span_setup`]).
struct Span<R> {
    first: Option<i32>,
    /// Whether their coefficients reach a second block along x.
    two: bool,
    /// With `two`: the factor of each x weight in the first block (`[0]`) and the next:
    /// `sided`'s blend weight, 0 for a coefficient outside the block.
    factors: [[R; 3]; 2],
    /// How many entries of `blocks` are used.
    count: usize,
    /// The blocks to sum, in `block_sums`'s order: the x side (0 or 1) and the index in
    /// `Columns::values` of each of the three columns for the block's subset of crossing y/z
    /// axes.
    blocks: [(u8, [u8; 3]); 8],
}

/// What stays fixed along a row: its y/z blocks, local indices, crossing axes and weights.
#[derive(Clone, Copy)]
struct Row<R, const D: usize> {
    /// The first block along each axis (x unused).
    block: [i32; D],
    /// The local index of the first coefficient along each axis (x unused).
    local0: [usize; D],
    /// Bits 1.. : the y/z axes whose coefficients reach a second block.
    crossing: usize,
    /// Each axis's weights in the first block (`[0]`) and the next (`[1]`), blended where the
    /// axis crosses, 0 for a coefficient outside the block's reach (x unused).
    sides: [[[[R; 1]; 3]; D]; 2],
}

impl<R: Real, const D: usize> Row<R, D> {
    /// A row at the origin's block, no axis crossing, every weight 0.
    fn new() -> Self {
        Row {
            block: [0; D],
            local0: [0; D],
            crossing: 0,
            sides: [[[[R::ZERO]; 3]; D]; 2],
        }
    }

    /// Whether `self` reads the same y/z coefficients as `other`, weighted the same along z:
    /// the same blocks, local indices and crossing axes, and in 3D the same z weights
    /// (`==`, so ±0 alike: a line starts at +0, and adding ±0 to a sum changes no bit).
    fn shares(&self, other: &Self) -> bool {
        let z = |row: &Self| row.sides.map(|side| side[D - 1]);
        self.block == other.block
            && self.local0 == other.local0
            && self.crossing == other.crossing
            && (D == 2 || z(self) == z(other))
    }
}

/// Adds `column` weighted by each lane's x weight (times `factor`, the block's blend weight,
/// where the span reaches two blocks) to the lane's sum, as `add_block` does. Factors are in
/// [0, 1]: `mul_fraction` is exact for 0 and 1.
#[inline(always)]
fn accumulate<R: Real>(sums: &mut [R], weights: &[R], column: R, factor: Option<R>) {
    match factor {
        Some(f) => {
            for (sum, &w) in sums.iter_mut().zip(weights) {
                *sum = sum.saturating_add(w.mul_fraction(f).mul_fraction(column));
            }
        }
        None => {
            for (sum, &w) in sums.iter_mut().zip(weights) {
                *sum = sum.saturating_add(w.mul_fraction(column));
            }
        }
    }
}

impl<T> Wavelet<'_, T> {
    /// Writes, through `put`, the band at `(x_i, rest[1], …)` into `out[r · len + i]` for
    /// each row `r` (its `rest` being `rests[r]`, `rest[0]` ignored) and every `i` below
    /// `len = out.len() / rests.len()`: bit for bit `evaluate` at each point. `x(first)` gives
    /// the [`LANES`] coordinates `x_first, x_(first + 1), …` (past `len` too, unused). The rows, at
    /// most [`GROUP`], are consecutive rows of a grid; those that share their y/z
    /// coefficients are summed together.
    #[inline]
    pub(crate) fn fill_rows<R: Real, const D: usize>(
        &self,
        rests: &[[R; D]],
        x: impl Fn(usize) -> [R; LANES],
        out: &mut [R],
        put: impl Fn(&mut R, R),
    ) where
        T: TileData<D>,
    {
        const { assert!(D == 2 || D == 3, "wavelet tiles are 2D or 3D") };
        let (n, h) = (T::SIZE, self.half_width::<D>());
        let Some(len) = out.len().checked_div(rests.len()) else {
            return;
        };
        let mut rows = [Row::new(); GROUP];
        for (row, rest) in rows.iter_mut().zip(rests) {
            *row = self.row_setup(rest, n, h);
        }
        let count = rests.len().min(GROUP);
        let mut r0 = 0;
        while r0 < count {
            let mut r1 = r0 + 1;
            while r1 < count && rows[r1].shares(&rows[r0]) {
                r1 += 1;
            }
            let group = rows.get(r0..r1).unwrap_or_default();
            if let Some(out) = out.get_mut(r0 * len..r1 * len) {
                self.fill_group(group, &x, out, &put);
            }
            r0 = r1;
        }
    }

    /// [`fill_rows`](Self::fill_rows) for rows that share their y/z blocks, local indices,
    /// crossing axes and z weights (`Row::shares`): one x sweep, each column's lines read
    /// once for every row.
    #[inline]
    fn fill_group<R: Real, const D: usize>(
        &self,
        rows: &[Row<R, D>],
        x: &impl Fn(usize) -> [R; LANES],
        out: &mut [R],
        put: &impl Fn(&mut R, R),
    ) where
        T: TileData<D>,
    {
        let (n, h) = (T::SIZE, self.half_width::<D>());
        let Some(len) = out.len().checked_div(rows.len()) else {
            return;
        };
        let unused = AxisMap {
            stride: 0,
            flip: false,
            shift: 0,
        };
        let mut blocks = [Block {
            key: None,
            x: [unused; 4],
            base: [[[0; 3]; 3]; 4],
        }; BLOCKS];
        let mut columns = Columns {
            keys: core::array::from_fn(|k| {
                // x index k/2 + 1 and block parity k & 1: the slot after k's pair.
                slot(((k / 2 + 1) % (SLOTS / 2)) as i32, (k & 1) as i32).1
            }),
            values: [[R::ZERO; GROUP]; 4 * SLOTS],
        };
        let mut wy = [[[R::ZERO; GROUP]; 3]; 2];
        for (g, row) in rows.iter().enumerate().take(GROUP) {
            for (wy, side) in wy.iter_mut().zip(&row.sides) {
                for (wy, w) in wy.iter_mut().zip(&side[1]) {
                    wy[g] = w[0];
                }
            }
        }
        let mut span = Span::<R> {
            first: None,
            two: false,
            factors: [[R::ONE; 3]; 2],
            count: 0,
            blocks: [(0, [0; 3]); 8],
        };
        // Sixteen samples at a time: their first coefficients and weights as lanes (the
        // compiler vectorises them), then each run of samples with the same first coefficient
        // (a span) summed lane by lane, entry by entry, which it vectorises too. Each sample's
        // operations are `evaluate`'s, in its order: only the loops are interchanged.
        let (mut firsts, mut weights) = ([0i32; LANES], [[R::ZERO; LANES]; 3]);
        for c in 0..len.div_ceil(LANES) {
            let start = c * LANES;
            let width = (len - start).min(LANES);
            let mut x_lanes = x(start);
            // Lanes past the row's end repeat its last sample (never written).
            if let Some(&last) = x_lanes.get(width.wrapping_sub(1)) {
                for v in x_lanes.iter_mut().skip(width) {
                    *v = last;
                }
            }
            bspline3_lanes(&x_lanes, &mut firsts, &mut weights);
            let mut a = 0;
            while a < width {
                let first = firsts[a % LANES];
                let mut b = a + 1;
                while b < width && firsts[b % LANES] == first {
                    b += 1;
                }
                if span.first != Some(first) {
                    let caches = (&mut blocks, &mut columns);
                    self.set_span(&mut span, (rows, &wy), first, caches, n, h);
                }
                let lanes = a..b.min(LANES);
                for g in 0..rows.len().min(GROUP) {
                    let at = g * len + start;
                    let outs = out.get_mut(at + a..at + b).unwrap_or_default();
                    let column = |k: u8| columns.values[k as usize % (4 * SLOTS)][g];
                    // The x weights in each block: `evaluate`'s (`sided`), with the
                    // coefficients outside a block weighing 0 (`exclude`).
                    let factor =
                        |mx: u8, j: usize| span.two.then(|| span.factors[mx as usize & 1][j]);
                    if lanes.len() >= LANES / 2 {
                        // A long run: every lane (whole vectors, the extra lanes unused).
                        let mut sums = [R::ZERO; LANES];
                        for &(mx, at) in span.blocks.iter().take(span.count) {
                            for (j, &k) in at.iter().enumerate() {
                                accumulate(&mut sums, &weights[j], column(k), factor(mx, j));
                            }
                        }
                        for (o, &sum) in outs.iter_mut().zip(&sums[lanes.clone()]) {
                            put(o, sum.canonical());
                        }
                    } else {
                        // A short run (fine bands: a span every sample or two): lane by lane.
                        for (o, l) in outs.iter_mut().zip(lanes.clone()) {
                            let mut sum = [R::ZERO];
                            for &(mx, at) in span.blocks.iter().take(span.count) {
                                for (j, &k) in at.iter().enumerate() {
                                    let w = core::slice::from_ref(&weights[j][l % LANES]);
                                    accumulate(&mut sum, w, column(k), factor(mx, j));
                                }
                            }
                            put(o, sum[0].canonical());
                        }
                    }
                }
                a = b;
            }
        }
    }

    /// Sets `span` for the samples whose first x coefficient is `first`, fetching the
    /// columns it reads that the cache does not hold.
    #[inline(always)]
    fn set_span<R: Real, const D: usize>(
        &self,
        span: &mut Span<R>,
        (rows, wy): (&[Row<R, D>], &GroupWeights<R>),
        first: i32,
        (blocks, columns): (&mut [Block; BLOCKS], &mut Columns<R>),
        n: usize,
        h: usize,
    ) where
        T: TileData<D>,
    {
        let Some(row) = rows.first() else {
            return;
        };
        let (bx, l0, two) = axis_span(first, n, h);
        if two {
            self.span_setup(span, (rows, wy), first, (bx, l0, two), blocks, columns, n);
            return;
        }
        // Most spans: one block along x, three columns (each holding every subset of the
        // crossing y/z axes).
        let mut at = [0u8; 3];
        for (jx, at) in at.iter_mut().enumerate() {
            let (slot, key) = slot(first.wrapping_add(jx as i32), bx);
            if columns.keys[slot] != key {
                let l_plus_n = l0 + jx + n;
                self.fetch_column(columns, slot, key, blocks, (rows, wy), bx, l_plus_n, n);
            }
            *at = (4 * slot) as u8;
        }
        (span.first, span.two) = (Some(first), false);
        // Every subset of the crossing y/z axes, largest first (`block_sums`).
        let yz = row.crossing >> 1 & 3;
        let (mut s, mut count) = (yz, 0);
        loop {
            span.blocks[count % 8] = (0, at.map(|k| k + s as u8));
            count += 1;
            if s == 0 {
                break;
            }
            s = (s - 1) & yz;
        }
        span.count = count;
    }

    /// Sets `span` for the samples whose first x coefficient is `first`: whether they reach
    /// a second block along x, their x weights' factors in each block, and the blocks they sum
    /// (every subset of the crossing axes, largest first, as `block_sums`), each with its
    /// three columns, fetched here if missing.
    #[allow(
        clippy::too_many_arguments,
        reason = "the row's state, passed apart to borrow"
    )]
    #[inline]
    fn span_setup<R: Real, const D: usize>(
        &self,
        span: &mut Span<R>,
        (rows, wy): (&[Row<R, D>], &GroupWeights<R>),
        first: i32,
        (bx, l0, two): (i32, usize, bool),
        blocks: &mut [Block; BLOCKS],
        columns: &mut Columns<R>,
        n: usize,
    ) where
        T: TileData<D>,
    {
        let h = self.half_width::<D>();
        let Some(row) = rows.first() else {
            return;
        };
        span.first = Some(first);
        span.two = two;
        span.count = 0;
        if two {
            // `sided`'s blend weights (1 where blocks abut), and 0 outside each block.
            let bits = members(1, [l0], n, h);
            for (side, factors) in span.factors.iter_mut().enumerate() {
                for (j, f) in factors.iter_mut().enumerate() {
                    *f = if bits[side][0] >> j & 1 == 0 {
                        R::ZERO
                    } else if h > 0 {
                        blend_weight(l0 + j + n - side * n, n, h)
                    } else {
                        R::ONE
                    };
                }
            }
        }
        // The three columns of each block along x, each fetched (for every subset of the
        // crossing y/z axes at once) if the cache does not hold it.
        let mut at = [[0u8; 3]; 2];
        for (mx, at) in at.iter_mut().enumerate().take(1 + two as usize) {
            let b = bx.wrapping_add(mx as i32);
            for (jx, at) in at.iter_mut().enumerate() {
                let (slot, key) = slot(first.wrapping_add(jx as i32), b);
                if columns.keys[slot] != key {
                    // The local index in block b, plus n: l0 + jx − n·mx + n.
                    let l_plus_n = l0 + jx + n - n * mx;
                    self.fetch_column(columns, slot, key, blocks, (rows, wy), b, l_plus_n, n);
                }
                *at = (4 * slot) as u8;
            }
        }
        let crossing = row.crossing | two as usize;
        for m in (0..=crossing).rev().filter(|m| m & !crossing == 0) {
            let (mx, s) = (m & 1, (m >> 1) & 3);
            if let Some(entry) = span.blocks.get_mut(span.count) {
                *entry = (mx as u8, at[mx].map(|k| k + s as u8));
                span.count += 1;
            }
        }
    }

    /// Fetches into `slot` (now `key`'s) the column at local index `l_plus_n − n` of block
    /// `b` along x for each row, for every subset of the rows' crossing y/z axes, setting the
    /// block up first if the block cache does not hold it. The rows share their lines of
    /// coefficients along z (2D: their coefficients), each read once.
    #[allow(
        clippy::too_many_arguments,
        reason = "the row's state, passed apart to borrow"
    )]
    #[inline]
    fn fetch_column<R: Real, const D: usize>(
        &self,
        columns: &mut Columns<R>,
        slot: usize,
        key: u64,
        blocks: &mut [Block; BLOCKS],
        (rows, wy): (&[Row<R, D>], &GroupWeights<R>),
        b: i32,
        l_plus_n: usize,
        n: usize,
    ) where
        T: TileData<D>,
    {
        let Some(row) = rows.first() else {
            return;
        };
        let block = &mut blocks[(b & 1) as usize % BLOCKS];
        if block.key != Some(b) {
            self.block_setup(block, row, b, n);
        }
        columns.keys[slot] = key;
        let yz = row.crossing >> 1;
        // The tile's scale, once for the column's reads.
        let unit = self.tile.unit::<R>();
        for t in (0..4usize).filter(|t| t & !yz == 0) {
            let x = block.x[t & 3].offset(l_plus_n, n);
            // `add_block`'s column: lines along z, then along y, each coefficient outside
            // the block's reach weighing 0 (`exclude`).
            let wz = &row.sides[t >> (D - 2) & 1][D - 1];
            let mut lines = [R::ZERO; 3];
            for (line, base) in lines.iter_mut().zip(&block.base[t & 3]) {
                *line = if D == 3 {
                    let mut line = R::ZERO;
                    for (&b, wz) in base.iter().zip(wz) {
                        line = line
                            .saturating_add(wz[0].mul_fraction(self.tile.flat_with(x + b, unit)));
                    }
                    line
                } else {
                    self.tile.flat_with(x + base[0], unit)
                };
            }
            let mut column = [R::ZERO; GROUP];
            // One row (fine bands' rows rarely share): no lanes, whose loop over `GROUP`
            // rows cost the benchmark's default multiband grid 7% (bench/README.md).
            if rows.len() == 1 {
                for (&line, wy) in lines.iter().zip(&wy[t & 1]) {
                    column[0] = column[0].saturating_add(wy[0].mul_fraction(line));
                }
            } else {
                // Every row of the group as a lane (rows past it weigh 0, unused).
                for (&line, wy) in lines.iter().zip(&wy[t & 1]) {
                    for (column, &wy) in column.iter_mut().zip(wy) {
                        *column = column.saturating_add(wy.mul_fraction(line));
                    }
                }
            }
            columns.values[(4 * slot + (t & 3)) % (4 * SLOTS)] = column;
        }
    }

    /// The row's y/z blocks, local indices, crossing axes, weights and members.
    #[inline]
    fn row_setup<R: Real, const D: usize>(&self, rest: &[R; D], n: usize, h: usize) -> Row<R, D>
    where
        T: TileData<D>,
    {
        let mut row = Row::new();
        let axes = rest.iter().zip(row.block.iter_mut().zip(&mut row.local0));
        for (a, (&coordinate, (block, local0))) in axes.enumerate().skip(1) {
            let (first, weights) = bspline3(coordinate);
            let (b, l0, two) = axis_span(first, n, h);
            (*block, *local0) = (b, l0);
            row.crossing |= (two as usize) << a;
            // `sided`'s weights, 0 outside each block (`exclude`): this axis's, in each side.
            let mut axis = [[weights.map(|w| [w])]; 2];
            if two {
                if h > 0 {
                    for (s, [side]) in axis.iter_mut().enumerate() {
                        blend_axis(side, s, zone_at(l0, n, h));
                    }
                }
                exclude(&mut axis, members(1, [l0], n, h));
            }
            for (side, [weights]) in row.sides.iter_mut().zip(axis) {
                if let Some(w) = side.get_mut(a) {
                    *w = weights;
                }
            }
        }
        row
    }

    /// Block `b` along x: for each subset of the row's crossing y/z axes, how the block it
    /// names reads x and the y/z parts of the tile index of the row's coefficients in it.
    #[inline(never)]
    fn block_setup<R: Real, const D: usize>(
        &self,
        block: &mut Block,
        row: &Row<R, D>,
        b: i32,
        n: usize,
    ) where
        T: TileData<D>,
    {
        block.key = Some(b);
        let yz = row.crossing >> 1;
        for s in (0..4usize).filter(|s| s & !yz == 0) {
            let mut at = row.block;
            at[0] = b;
            for (a, at) in at.iter_mut().enumerate().skip(1) {
                *at = at.wrapping_add((s >> (a - 1) & 1) as i32);
            }
            let place = self.placement(at);
            for jy in 0..3 {
                for jz in 0..if D == 3 { 3 } else { 1 } {
                    let mut offset = 0;
                    for (a, j) in [(1, jy), (2, jz)] {
                        if a < D {
                            // The local index in its block plus n: local0 + j − n·side + n.
                            let side = s >> (a - 1) & 1;
                            let l_plus_n = row.local0[a] + j + n - n * side;
                            offset += place.axis(a, n).offset(l_plus_n, n);
                        }
                    }
                    block.base[s & 3][jy][jz] = offset;
                }
            }
            block.x[s & 3] = place.axis(0, n);
        }
    }
}

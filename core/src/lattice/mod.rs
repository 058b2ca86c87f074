//! Lattice noises: a value or a gradient at every integer point, hashed from the point's
//! coordinates, blended across each cell by a fade curve.
//!
//! | type | paper | hash | gradients | fade |
//! |---|---|---|---|---|
//! | [`Perlin`] | Perlin 2002; pbrt §10.6.1 | [`Permutation`](crate::hash::Permutation), x innermost | Perlin's 12 cube edges (+4 repeats) | quintic |
//! | [`TabledPerlin`] | as [`Perlin`], plus a per-seed table for the point kernel | | | |
//! | [`OriginalPerlin`] | Perlin 1985 | permutation, x innermost | a table of 256 random unit vectors | cubic |
//! | [`ValueNoise`] | pbrt §10.6 intro; Lewis 1989 §2 | permutation, x innermost | none: a value in `[-1, 1]` per point | quintic |
//! | [`WhiteNoise`] | Lewis 1989 §2.2 | [`CellHash`](crate::hash::CellHash) into a prime-length table ([`table_value`]) | none: constant per cell | none |
//! | [`CubicValueNoise`] | Lewis 1989 §2.3 | as [`WhiteNoise`], 4ᴰ points | none: [`WhiteNoise`]'s values | Catmull-Rom |
//! | [`CNoise`] | Olano 2005 §3.2 | permutation, last axis innermost | cube corners `(±1, ±1, …)` | quintic |
//! | [`MNoise`] | Olano 2005 §3.3 | [`Bbs`](crate::hash::Bbs) `x² mod M`, last axis innermost | cube corners | quintic |
//! | [`MixedMNoise`] | Olano 2005 §3.4 | as [`MNoise<61>`], its two innermost steps from one 2D table | cube corners | quintic |
//!
//! [`Periodic`] wraps any of them to integer periods per axis.
//!
//! Every type implements [`Noise`](crate::Noise) for 1 to 4 dimensions and every
//! [`Real`]; the gradient noises also implement
//! [`NoiseGradient`](crate::NoiseGradient).
//!
//! # Output bounds
//!
//! For a gradient noise, `n(f) = Σ_c W_c(f) g_c·(f − c)` with weights `W_c ≥ 0` summing to 1.
//! When every gradient component satisfies `|g_a| ≤ 1`,
//! `|n| ≤ Σ_a Σ_c W_c |f_a − c_a| = Σ_a [(1 − s_a) f_a + s_a (1 − f_a)] ≤ D/2`
//! (each bracket is at most ½, reached at `f_a = ½`). With unit gradients, Jensen's inequality
//! gives `|n| ≤ (Σ_c W_c |f − c|²)^½ ≤ √D/2`. Both are tight: a cell whose corner gradients
//! all point outward reaches them at its centre. Whether a noise's hash produces such a cell
//! depends on the noise, so the measured maxima are in each type's docs; the
//! [`Noise::amplitude_bound`]s are the proved bounds plus 2⁻¹⁰ for rounding (I16F16 rounds each
//! product to 2⁻¹⁶).
//!
//! [`Noise::amplitude_bound`]: crate::Noise::amplitude_bound

mod corner;
mod cubic;
pub(crate) mod kernel;
mod mixed;
mod original;
mod periodic;
pub(crate) mod perlin;
mod value;
mod white;

pub use corner::{CNoise, MNoise};
pub use cubic::CubicValueNoise;
pub use mixed::{MixedMNoise, MixedTurbulence};
pub use original::OriginalPerlin;
pub use periodic::Periodic;
pub use perlin::{Perlin, TabledPerlin};
pub use value::ValueNoise;
pub use white::{VALUES, WhiteNoise, table_value};

use crate::batch::{self, Grid, LANES};
use crate::{Error, Real};
use kernel::{
    Fade, MAX_CORNERS, corner_offset, interpolate, interpolate_with_gradient, minus_one,
    split_point,
};

/// What distinguishes one lattice noise from another: how corners are hashed, what a corner
/// contributes at an offset from it (a gradient's dot product, or a value), and the fade
/// curve. The sampling is one body for every noise and any number of points ([`blend`]).
pub(crate) trait Lattice<const D: usize> {
    /// The fade curve.
    type Fade: Fade;
    /// What a corner's hash selects: a gradient vector, or a value. Looked up once per cell
    /// where several points share the cell.
    type Corner<R: Real>: Copy;
    /// The hash of each corner of `cell`, indexed by corner bit mask.
    fn corner_hashes(&self, cell: [i32; D]) -> [u32; MAX_CORNERS];
    /// The corner that hash `h` selects.
    fn corner<R: Real>(&self, h: u32) -> Self::Corner<R>;
    /// Corner `c`'s contribution at offset `d` from it: `g · d` (`Σ_a d_a·g_a` in axis order),
    /// or the corner's value.
    fn contribution<R: Real>(&self, c: &Self::Corner<R>, d: &[R; D]) -> R;
    /// The gradient of the contribution with respect to the point: the gradient vector of a
    /// gradient noise, zero for a value noise (for [`sample_lattice_with_gradient`]).
    fn gradient<R: Real>(&self, h: u32) -> [R; D];

    /// `contribution(corner(h), d)`, for a corner only one point uses. A lattice may override
    /// it with a cheaper form (sums of signed offsets instead of products with ±1) whose values
    /// are the same but for the sign of a zero, which sampling canonicalises.
    #[inline]
    fn dot<R: Real>(&self, h: u32, d: &[R; D]) -> R {
        self.contribution(&self.corner(h), d)
    }

    /// The noise at `p` ([`Noise::sample`](crate::Noise::sample)): [`sample_lattice`], unless
    /// the lattice has a faster kernel for this number type and target with the same results
    /// bit for bit (Perlin 2D/3D in `f32` with SSE2).
    #[inline]
    fn sample_point<R: Real>(&self, p: [R; D]) -> R
    where
        Self: Sized,
    {
        sample_lattice(self, p)
    }

    /// Whether [`sample_point`](Self::sample_point), lane by lane, is faster than the body for
    /// lanes in unrelated cells (true where `sample_point` has a vector kernel); scattered lanes
    /// (fractal octaves coarser than a lane per cell, arbitrary points) then take it. Either
    /// gives the same values.
    #[inline]
    fn point_kernel_for_scattered_lanes<R: Real>() -> bool {
        false
    }

    /// [`corner_hashes`](Self::corner_hashes) of every lane's cell, as `h[corner][lane]`.
    /// Table-free hashes override it with loops over lanes that vectorise.
    #[inline]
    fn corner_hashes_lanes(&self, cell: &[[i32; LANES]; D]) -> [[u32; LANES]; MAX_CORNERS] {
        let mut h = [[0u32; LANES]; MAX_CORNERS];
        for l in 0..LANES {
            let corners = self.corner_hashes(crate::batch::lane(cell, l));
            for (hm, c) in h.iter_mut().zip(corners).take(1 << D) {
                hm[l] = c;
            }
        }
        h
    }
}

/// A reference to a lattice is that lattice (so `Periodic<&Perlin, D>` shares one table).
impl<L: Lattice<D>, const D: usize> Lattice<D> for &L {
    type Fade = L::Fade;
    type Corner<R: Real> = L::Corner<R>;
    #[inline]
    fn corner_hashes(&self, cell: [i32; D]) -> [u32; MAX_CORNERS] {
        (**self).corner_hashes(cell)
    }
    #[inline]
    fn corner<R: Real>(&self, h: u32) -> Self::Corner<R> {
        (**self).corner(h)
    }
    #[inline]
    fn contribution<R: Real>(&self, c: &Self::Corner<R>, d: &[R; D]) -> R {
        (**self).contribution(c, d)
    }
    #[inline]
    fn gradient<R: Real>(&self, h: u32) -> [R; D] {
        (**self).gradient(h)
    }
    #[inline]
    fn dot<R: Real>(&self, h: u32, d: &[R; D]) -> R {
        (**self).dot(h, d)
    }
    #[inline]
    fn sample_point<R: Real>(&self, p: [R; D]) -> R {
        (**self).sample_point(p)
    }
    #[inline]
    fn point_kernel_for_scattered_lanes<R: Real>() -> bool {
        L::point_kernel_for_scattered_lanes::<R>()
    }
    #[inline]
    fn corner_hashes_lanes(&self, cell: &[[i32; LANES]; D]) -> [[u32; LANES]; MAX_CORNERS] {
        (**self).corner_hashes_lanes(cell)
    }
}

/// The lattice body, for `N` points at once (1 for a point sample, [`LANES`] for the batch
/// paths): point `l`'s value from its fractions `f(a, l)` in its cell, its faded fractions
/// `s(a, l)`, and `contribution(m, l, d)`, the contribution of its cell's corner `m` at offset
/// `d` from that corner. The corners' contributions are blended by multilinear interpolation
/// along axis 0, then 1, … (Perlin's order), and the result is canonical (no −0).
///
/// Every sampling path calls this, so they give the same values bit for bit by construction:
/// they differ only in where the corners come from (hashed per point, or once for points that
/// share a cell). With `N` lanes the compiler vectorises the body across lanes; where `f`, `s`
/// or the corners do not depend on `l` (the axes of a grid row other than axis 0), it sees
/// constants of the lane loop and computes their products once.
#[inline]
fn blend<R: Real, const D: usize, const N: usize>(
    f: impl Fn(usize, usize) -> R,
    s: impl Fn(usize, usize) -> R,
    contribution: impl Fn(usize, usize, &[R; D]) -> R,
) -> [R; N] {
    core::array::from_fn(|l| {
        let fl: [R; D] = core::array::from_fn(|a| f(a, l));
        let f1 = minus_one(&fl);
        let mut v = [R::ZERO; MAX_CORNERS];
        for (m, vm) in v.iter_mut().enumerate().take(1 << D) {
            *vm = contribution(m, l, &corner_offset(&fl, &f1, m));
        }
        let t: [R; D] = core::array::from_fn(|a| s(a, l));
        interpolate(v, &t).canonical()
    })
}

/// Samples a lattice noise at `p`: [`blend`] for one point, its corners hashed.
#[inline]
pub(crate) fn sample_lattice<L: Lattice<D>, R: Real, const D: usize>(lattice: &L, p: [R; D]) -> R {
    let (cell, f) = split_point(p);
    let h = lattice.corner_hashes(cell);
    let [v] = blend::<R, D, 1>(
        |a, _| f[a],
        |a, _| L::Fade::fade(f[a]),
        |m, _, d| lattice.dot(h[m], d),
    );
    v
}

/// The most cells along axis 0 that [`column_lanes`] takes: a chunk of [`LANES`] points along
/// a grid row spans at most 3 cells when the step is below 2/15 of a cell.
const MAX_COLUMN_CELLS: usize = 3;
const _: () = assert!(MAX_COLUMN_CELLS == 3, "Axis0Cells::of counts up to 3 cells");

/// Where the lanes of a chunk lie when their cells differ only along axis 0: lane `l` is in
/// cell `first + (offset[l], 0, …)`, `offset[l] < cells`.
#[derive(Clone, Copy)]
struct Column<'a, const D: usize> {
    first: [i32; D],
    offset: &'a [u32; LANES],
    cells: usize,
}

/// The cells of a chunk's lanes along axis 0: lane `l` is in cell `first + offset[l]`, and
/// the lanes span `cells` cells (0: more than [`MAX_COLUMN_CELLS`], `first` and `offset`
/// unused).
#[derive(Clone, Copy)]
struct Axis0Cells {
    first: i32,
    offset: [u32; LANES],
    cells: usize,
}

impl Axis0Cells {
    #[inline]
    fn of(cell: &[i32; LANES]) -> Self {
        // Along a grid row the cells are monotonic, so the first is at one end. Lanes below it
        // (not a row) wrap to offsets far beyond the limit and leave the column path.
        let first = cell[0].min(cell[LANES - 1]);
        let offset = cell.map(|c| c.wrapping_sub(first) as u32);
        // Branch-free tests that vectorise (SSE2 has no 32-bit minimum or maximum).
        let fits = offset
            .iter()
            .fold(true, |ok, &o| ok & (o < MAX_COLUMN_CELLS as u32));
        let any = offset.iter().fold(0, |bits, &o| bits | o);
        Self {
            first,
            offset,
            cells: match (fits, any) {
                (false, _) => 0,
                (true, 0) => 1,
                (true, 1) => 2,
                // Offsets 0 and 2, or 0, 1 and 2.
                (true, _) => 3,
            },
        }
    }
}

/// [`blend`] for lanes in a [`Column`]: the corners of its `K` cells are hashed and looked up
/// once, and each lane takes those of its own cell. `K = 1` (every lane in one cell, a grid
/// finer than [`LANES`] points per cell) is the common case.
#[inline]
fn column_lanes<L: Lattice<D>, R: Real, const D: usize, const K: usize>(
    lattice: &L,
    column: &Column<'_, D>,
    f: impl Fn(usize, usize) -> R,
    s: impl Fn(usize, usize) -> R,
) -> [R; LANES] {
    let mut corners = [[lattice.corner(0); MAX_CORNERS]; K];
    for (k, ck) in corners.iter_mut().enumerate() {
        let mut cell = column.first;
        // No overflow: the column's last cell is a lane's cell.
        cell[0] = cell[0].wrapping_add(k as i32);
        let h = lattice.corner_hashes(cell);
        for (cm, &hm) in ck.iter_mut().zip(&h).take(1 << D) {
            *cm = lattice.corner(hm);
        }
    }
    blend::<R, D, LANES>(f, s, |m, l, d| {
        let mut v = lattice.contribution(&corners[0][m], d);
        for (k, ck) in corners.iter().enumerate().skip(1) {
            let vk = lattice.contribution(&ck[m], d);
            if column.offset[l] == k as u32 {
                v = vk;
            }
        }
        v
    })
}

/// [`column_lanes`] for the column's number of cells: one cell inline, several out of line
/// ([`several_cells`]).
#[inline]
fn column<L: Lattice<D>, R: Real, const D: usize>(
    lattice: &L,
    column: &Column<'_, D>,
    f: impl Fn(usize, usize) -> R,
    s: impl Fn(usize, usize) -> R,
) -> [R; LANES] {
    if column.cells == 1 {
        column_lanes::<L, R, D, 1>(lattice, column, f, s)
    } else {
        several_cells(lattice, column, f, s)
    }
}

/// [`column_lanes`] for a column of 2 or more cells. Out of line, so that its code does not
/// change how the compiler lays out the one-cell path around it (inlined, with the dispatch on
/// the number of cells, it cost the one-cell path instructions: `bench/README.md`).
#[inline(never)]
fn several_cells<L: Lattice<D>, R: Real, const D: usize>(
    lattice: &L,
    column: &Column<'_, D>,
    f: impl Fn(usize, usize) -> R,
    s: impl Fn(usize, usize) -> R,
) -> [R; LANES] {
    if column.cells == 2 {
        column_lanes::<L, R, D, 2>(lattice, column, f, s)
    } else {
        column_lanes::<L, R, D, MAX_COLUMN_CELLS>(lattice, column, f, s)
    }
}

/// [`blend`] for lanes in unrelated cells: the point kernel lane by lane where the lattice has
/// a faster one, else [`hashed_lanes`].
#[inline]
fn scattered_lanes<L: Lattice<D>, R: Real, const D: usize>(
    lattice: &L,
    p: &[[R; LANES]; D],
    cell: &[[i32; LANES]; D],
    f: &[[R; LANES]; D],
    s: &[[R; LANES]; D],
) -> [R; LANES] {
    if L::point_kernel_for_scattered_lanes::<R>() {
        core::array::from_fn(|l| lattice.sample_point(batch::lane(p, l)))
    } else {
        hashed_lanes(lattice, cell, f, s)
    }
}

/// [`blend`] with each lane's corners hashed on their own. Out of line, like
/// [`several_cells`]; one call per chunk of 16 lanes costs next to nothing.
#[inline(never)]
fn hashed_lanes<L: Lattice<D>, R: Real, const D: usize>(
    lattice: &L,
    cell: &[[i32; LANES]; D],
    f: &[[R; LANES]; D],
    s: &[[R; LANES]; D],
) -> [R; LANES] {
    let h = lattice.corner_hashes_lanes(cell);
    blend::<R, D, LANES>(
        |a, l| f[a][l],
        |a, l| s[a][l],
        |m, l, d| lattice.dot(h[m][l], d),
    )
}

/// [`sample_lattice`] for [`LANES`] points ([`Noise::sample_lanes`](crate::Noise::sample_lanes)):
/// the lanes' cells decide where the corners come from ([`column_lanes`] or
/// [`scattered_lanes`]), and [`blend`] does the rest.
#[inline]
pub(crate) fn sample_lattice_lanes<L: Lattice<D>, R: Real, const D: usize>(
    lattice: &L,
    p: &[[R; LANES]; D],
    out: &mut [R; LANES],
) {
    const { assert!(D >= 1 && D <= 4, "lattice noises have 1 to 4 dimensions") };
    // Written in place: returned by value from a helper, the two arrays were copied by a
    // call to `memcpy` per chunk (bench/README.md, 2026-11-30 (night)).
    let mut cell = [[0i32; LANES]; D];
    let mut f = [[R::ZERO; LANES]; D];
    for a in 0..D {
        R::split_lanes(&p[a], &mut cell[a], &mut f[a]);
    }
    let s = f.map(|fa| fa.map(L::Fade::fade));
    // Lanes along a row have their extreme cells at the ends: a row over more cells than a
    // column takes is recognised there, before the lanes are looked at.
    let ends = (cell[0][LANES - 1] as i64 - cell[0][0] as i64).unsigned_abs();
    let column_of = || {
        let uniform = cell[1..].iter().all(|ca| ca.iter().all(|&c| c == ca[0]));
        let axis0 = Axis0Cells::of(&cell[0]);
        (uniform && axis0.cells > 0).then_some(axis0)
    };
    *out = match (ends < MAX_COLUMN_CELLS as u64).then(column_of).flatten() {
        Some(axis0) => {
            let c = Column {
                first: core::array::from_fn(|a| if a == 0 { axis0.first } else { cell[a][0] }),
                offset: &axis0.offset,
                cells: axis0.cells,
            };
            column(lattice, &c, |a, l| f[a][l], |a, l| s[a][l])
        }
        None => scattered_lanes(lattice, p, &cell, &f, &s),
    };
}

/// Chunks of [`LANES`] columns that [`fill_grid_lattice`] takes through the rows together, so
/// that each row's split and fade along the axes other than 0, and its dispatch, serve all of
/// them (8 rather than 4: fewer instructions per sample, `bench/README.md`); the block's
/// axis-0 data is then 8 · 192 bytes of stack in `f32` and I16F16.
const CHUNKS_PER_BLOCK: usize = 8;

/// Axis 0 of one chunk of a grid: every lane's cell, fraction and faded fraction.
#[derive(Clone, Copy)]
struct ChunkAxis0<R> {
    cell: [i32; LANES],
    f: [R; LANES],
    s: [R; LANES],
}

/// [`Noise::fill_grid`](crate::Noise::fill_grid) for a lattice: blocks of
/// [`CHUNKS_PER_BLOCK`] column chunks of [`LANES`] points outermost, so each chunk's split and
/// fade along axis 0 serve every row; the other axes, constant along a row, are split and faded
/// once per row and block ([`row_axes`]). A block whose chunks each lie in one cell (a grid of
/// 16 or more samples per cell, aligned with the cells) is taken chunk by chunk, each chunk's
/// corners hashed once per row; any other block goes to [`runs_of_block`], and the next block
/// starts where it stopped (at a cell's first column). The values are
/// those of [`sample_lattice_lanes`] (the same operations on the same numbers).
pub(crate) fn fill_grid_lattice<L: Lattice<D>, R: Real, const D: usize>(
    lattice: &L,
    grid: &Grid<R, D>,
    out: &mut [R],
) -> Result<(), Error> {
    batch::check_len(grid.len(), out.len())?;
    let width = grid.size[0];
    if width == 0 || grid.is_empty() {
        return Ok(());
    }
    let rows = out.len() / width;
    let mut block = 0;
    while block < width {
        let chunks = (width - block).div_ceil(LANES).min(CHUNKS_PER_BLOCK);
        let mut x = [ChunkAxis0 {
            cell: [0; LANES],
            f: [R::ZERO; LANES],
            s: [R::ZERO; LANES],
        }; CHUNKS_PER_BLOCK];
        for (k, xk) in x.iter_mut().enumerate().take(chunks) {
            let x = grid.lanes(0, block + k * LANES);
            R::split_lanes(&x, &mut xk.cell, &mut xk.f);
            xk.s = xk.f.map(L::Fade::fade);
        }
        let aligned = x
            .iter()
            .take(chunks)
            .all(|xk| xk.cell.iter().all(|&c| c == xk.cell[0]));
        if !aligned {
            // Chunks that straddle cells: runs of columns aligned with the cells instead
            // (their own split of the block, once per block: the chunk loop below is faster
            // over these per-chunk arrays than over the runs' padded ones). The next block
            // starts where the runs stopped, at a cell's first column.
            block += runs_of_block(lattice, grid, block, out);
            continue;
        }
        for row in 0..rows {
            let along = row_axes::<L, R, D>(grid, row);
            for (k, xk) in x.iter().enumerate().take(chunks) {
                let start = block + k * LANES;
                let f = |a: usize, l| if a == 0 { xk.f[l] } else { along[a].1 };
                let s = |a: usize, l| if a == 0 { xk.s[l] } else { along[a].2 };
                let c = Column {
                    first: core::array::from_fn(|a| if a == 0 { xk.cell[0] } else { along[a].0 }),
                    offset: &[0; LANES],
                    cells: 1,
                };
                let v = column_lanes::<L, R, D, 1>(lattice, &c, f, s);
                // In range by construction (`get_mut` keeps it provably panic-free).
                let at = row * width + start;
                if let Some(dst) = out.get_mut(at..at + LANES.min(width - start)) {
                    batch::store_lanes(dst, &v);
                }
            }
        }
        block += BLOCK;
    }
    Ok(())
}

/// Axes 1.. of grid row `row`: (cell, fraction, faded fraction), the same for every point of
/// the row; axis 0 unused.
#[inline]
fn row_axes<L: Lattice<D>, R: Real, const D: usize>(
    grid: &Grid<R, D>,
    row: usize,
) -> [(i32, R, R); D] {
    let first = grid.row_start(row);
    let mut along = [(0i32, R::ZERO, R::ZERO); D];
    for (a, along_a) in along.iter_mut().enumerate().skip(1) {
        let (c, fa) = first[a].split();
        *along_a = (c, fa, L::Fade::fade(fa));
    }
    along
}

/// The shortest run of columns in one cell that [`runs_of_block`] samples on its own (16 lanes
/// computed, the run's stored): below it, 16 lanes as a column of cells or scattered cost less
/// per stored value.
const MIN_RUN: usize = 7;

/// Columns `start..start + len` of a block: in one cell (`one_cell`), or up to [`LANES`]
/// columns that [`window_lanes`] samples.
#[derive(Clone, Copy)]
struct Run {
    start: u8,
    len: u8,
    one_cell: bool,
}

/// The columns of a block.
const BLOCK: usize = LANES * CHUNKS_PER_BLOCK;

/// [`fill_grid_lattice`] for the block of columns from `block` when its chunks of 16 columns
/// do not each lie in one cell (a step that is not a power-of-two fraction of a cell, an origin
/// off the lattice): the block is cut into runs of columns in one cell, each sampled as 16
/// lanes from its first column (the corners hashed once per row; the lanes past the run
/// computed and dropped), and, where cells change faster than [`MIN_RUN`] columns, windows of
/// 16 columns ([`window_lanes`]). A run that the block's end cuts short and whose cell goes on
/// is left to the next block, which starts with it: returns the columns done (at least 1).
/// Out of line, so that its code does not change how the compiler lays out the aligned
/// blocks' loop.
#[inline(never)]
fn runs_of_block<L: Lattice<D>, R: Real, const D: usize>(
    lattice: &L,
    grid: &Grid<R, D>,
    block: usize,
    out: &mut [R],
) -> usize {
    let width = grid.size[0];
    let Some(columns) = width.checked_sub(block).map(|c| c.min(BLOCK)) else {
        return BLOCK;
    };
    let rows = out.len().checked_div(width).unwrap_or(0);
    // One chunk of padding, so that a run starting anywhere in the block reads 16 lanes.
    let mut cell = [0i32; BLOCK + LANES];
    let mut fx = [R::ZERO; BLOCK + LANES];
    let mut sx = [R::ZERO; BLOCK + LANES];
    let chunks = columns.div_ceil(LANES) + 1;
    for (k, ((ck, fk), sk)) in cell
        .as_chunks_mut::<LANES>()
        .0
        .iter_mut()
        .zip(fx.as_chunks_mut::<LANES>().0)
        .zip(sx.as_chunks_mut::<LANES>().0)
        .take(chunks)
        .enumerate()
    {
        let x = grid.lanes(0, block + k * LANES);
        R::split_lanes(&x, ck, fk);
        *sk = fk.map(L::Fade::fade);
    }
    let mut runs = [Run {
        start: 0,
        len: 0,
        one_cell: false,
    }; BLOCK];
    let mut count = 0;
    let mut i = 0;
    // The columns this block takes: all, or up to the cell it leaves to the next.
    let mut done = columns;
    while i < columns {
        let Some(window) = lanes_at(&cell, i) else {
            break;
        };
        let left = columns - i;
        let lead = window.iter().take_while(|&&c| c == window[0]).count();
        // The cell goes on past the block's end (its lead, counted up to 16, is longer than
        // what is left): it is left to the next block, which then starts with it (a cell cut
        // in two would cost two runs' lanes), unless nothing in the block comes before it or
        // the row ends here.
        if lead > left && i > 0 && block + columns < width {
            done = i;
            break;
        }
        let run = if lead >= MIN_RUN.min(left) {
            Run {
                start: i as u8,
                len: lead.min(left) as u8,
                one_cell: true,
            }
        } else {
            Run {
                start: i as u8,
                len: LANES.min(left) as u8,
                one_cell: false,
            }
        };
        i += run.len as usize;
        if let Some(r) = runs.get_mut(count) {
            *r = run;
            count += 1;
        }
    }
    for row in 0..rows {
        let along = row_axes::<L, R, D>(grid, row);
        for run in runs.iter().take(count) {
            // At most BLOCK, so the windows are provably in the padded arrays.
            let at = (run.start as usize).min(BLOCK);
            let (Some(cw), Some(fw), Some(sw)) =
                (lanes_at(&cell, at), lanes_at(&fx, at), lanes_at(&sx, at))
            else {
                continue;
            };
            let v = if run.one_cell {
                let c = Column {
                    first: core::array::from_fn(|a| if a == 0 { cw[0] } else { along[a].0 }),
                    offset: &[0; LANES],
                    cells: 1,
                };
                column_lanes::<L, R, D, 1>(
                    lattice,
                    &c,
                    |a, l| if a == 0 { fw[l] } else { along[a].1 },
                    |a, l| if a == 0 { sw[l] } else { along[a].2 },
                )
            } else {
                window_lanes(lattice, cw, fw, sw, &along)
            };
            // In range by construction (`get_mut` keeps it provably panic-free).
            let at = row * width + block + at;
            if let Some(dst) = out.get_mut(at..at + run.len as usize) {
                batch::store_lanes(dst, &v);
            }
        }
    }
    done
}

/// The [`LANES`] values of `v` from index `at`, as an array.
#[inline]
fn lanes_at<T>(v: &[T; BLOCK + LANES], at: usize) -> Option<&[T; LANES]> {
    v.get(at..at + LANES)?.try_into().ok()
}

/// A window of 16 columns of a grid row whose cells change too often for runs: a column of up
/// to 3 cells, or hashed lane by lane. Out of line, so that its code does not change how the
/// compiler lays out the runs in one cell.
#[inline(never)]
fn window_lanes<L: Lattice<D>, R: Real, const D: usize>(
    lattice: &L,
    cell: &[i32; LANES],
    f: &[R; LANES],
    s: &[R; LANES],
    along: &[(i32, R, R); D],
) -> [R; LANES] {
    let axis0 = Axis0Cells::of(cell);
    if axis0.cells > 0 {
        let c = Column {
            first: core::array::from_fn(|a| if a == 0 { axis0.first } else { along[a].0 }),
            offset: &axis0.offset,
            cells: axis0.cells,
        };
        column(
            lattice,
            &c,
            |a, l| if a == 0 { f[l] } else { along[a].1 },
            |a, l| if a == 0 { s[l] } else { along[a].2 },
        )
    } else {
        let cell = core::array::from_fn(|a| if a == 0 { *cell } else { [along[a].0; LANES] });
        let f = core::array::from_fn(|a| if a == 0 { *f } else { [along[a].1; LANES] });
        let s = core::array::from_fn(|a| if a == 0 { *s } else { [along[a].2; LANES] });
        hashed_lanes(lattice, &cell, &f, &s)
    }
}

/// Samples a lattice noise and its analytic gradient at `p`: the value is [`sample_lattice`]'s.
#[inline]
pub(crate) fn sample_lattice_with_gradient<L: Lattice<D>, R: Real, const D: usize>(
    lattice: &L,
    p: [R; D],
) -> (R, [R; D]) {
    let (cell, f) = split_point(p);
    let h = lattice.corner_hashes(cell);
    let f1 = minus_one(&f);
    let mut dots = [R::ZERO; MAX_CORNERS];
    let mut grads = [[R::ZERO; D]; MAX_CORNERS];
    for m in 0..(1 << D) {
        dots[m] = lattice.dot(h[m], &corner_offset(&f, &f1, m));
        grads[m] = lattice.gradient(h[m]);
    }
    let s = f.map(L::Fade::fade);
    let ds = f.map(L::Fade::fade_derivative);
    interpolate_with_gradient(dots, &grads, &s, &ds)
}

/// The corner items of a gradient lattice in `$d` dimensions: a corner is its gradient, and its
/// contribution the dot product with the offset, exact products by `R::$mul` (`mul_unit` where
/// every component is 0 or ±1 in every number type, `mul_rn` otherwise).
macro_rules! gradient_corners {
    ($d:tt, $mul:ident) => {
        type Corner<R: crate::Real> = [R; $d];
        #[inline]
        fn corner<R: crate::Real>(&self, h: u32) -> [R; $d] {
            self.gradient(h)
        }
        #[inline]
        fn contribution<R: crate::Real>(&self, g: &[R; $d], d: &[R; $d]) -> R {
            crate::lattice::kernel::sum_of_products(d, g, R::$mul)
        }
    };
}
pub(crate) use gradient_corners;

/// Implements `Noise` and `NoiseGradient` for a lattice type, in every dimension it has a
/// `Lattice` for. `$bound(&self, D)` is the amplitude bound.
macro_rules! lattice_noise_impls {
    ($ty:ty, [$($generics:tt)*], $bound:expr) => {
        impl<R: crate::Real, const D: usize, $($generics)*> crate::Noise<R, D> for $ty
        where
            $ty: crate::lattice::Lattice<D>,
        {
            #[inline]
            fn sample(&self, p: [R; D]) -> R {
                crate::lattice::Lattice::<D>::sample_point(self, p)
            }
            fn amplitude_bound(&self) -> f32 {
                $bound(self, D)
            }
            #[inline]
            fn sample_lanes(
                &self,
                p: &[[R; crate::batch::LANES]; D],
                out: &mut [R; crate::batch::LANES],
            ) {
                crate::lattice::sample_lattice_lanes(self, p, out);
            }
            fn fill_grid(
                &self,
                grid: &crate::batch::Grid<R, D>,
                out: &mut [R],
            ) -> Result<(), crate::Error> {
                crate::lattice::fill_grid_lattice(self, grid, out)
            }
        }

        impl<R: crate::Real, const D: usize, $($generics)*> crate::NoiseGradient<R, D> for $ty
        where
            $ty: crate::lattice::Lattice<D>,
        {
            #[inline]
            fn sample_with_gradient(&self, p: [R; D]) -> (R, [R; D]) {
                crate::lattice::sample_lattice_with_gradient(self, p)
            }
        }
    };
}
pub(crate) use lattice_noise_impls;

/// What rounding may add to a bound that holds in exact arithmetic: the bounds here are tight
/// (a cell with outward gradients reaches them at its centre), and I16F16's products round to
/// 2⁻¹⁶, so an evaluation may exceed them by a few ulps. The measured worst |I16F16 − f32| of any lattice noise is 18·2⁻¹⁶ (4D
/// mNoise); 2⁻¹⁰ = 64·2⁻¹⁶ covers it with room.
pub(crate) const ROUNDING: f32 = 1.0 / 1024.0;

/// The bound `D/2` for gradients whose components lie in `[-1, 1]` (see the module docs).
pub(crate) fn half_dims(dims: usize) -> f32 {
    dims as f32 * 0.5 + ROUNDING
}

/// Adds `±x` as bit `bit` of `h` says (set: subtract).
#[inline]
pub(crate) fn signed<R: Real>(h: u32, bit: u32, x: R) -> R {
    x.negate_if(h >> bit)
}

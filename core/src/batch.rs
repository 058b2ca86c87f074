//! Batch evaluation: filling a caller's buffer with a grid or an array of points.
//!
//! Every [`Noise`] has three batch methods, provided by the trait:
//!
//! * [`Noise::fill_grid`]: a regular 2D or 3D (or 1D, 4D) [`Grid`], written row-major with axis 0
//!   fastest;
//! * [`Noise::fill_points`]: points given as one slice per axis (structure of arrays);
//! * [`Noise::sample_lanes`]: the kernel both use, [`LANES`] points at once.
//!
//! The batch results are **bit-identical** to calling [`Noise::sample`] at each point (tested in
//! `tests/tests/batch.rs` for every noise, number type and dimension). What makes them faster is
//! the layout: the lattice noises override `sample_lanes` with kernels that run each step of the
//! point algorithm (split, hash, dot products, fade, interpolation) over all lanes before the
//! next step, in fixed-size arrays, so the compiler turns those loops into SIMD instructions
//! (SSE2 on x86-64, `simd128` on wasm32, Helium or nothing on microcontrollers, where the same
//! code simply runs as loops). Fractal sums call their noise's `sample_lanes` once per octave.
//! Wavelet noise resolves a block's orientation once for all lanes and gathers each lane's
//! coefficients. Noises without an override (multiband) evaluate lane by lane. Projected
//! noise has its own grid method, [`ProjectedNoise::fill_grid_projected`](crate::ProjectedNoise::fill_grid_projected)
//! (one normal for the whole grid).
//!
//! On a grid a batch is several times faster than point sampling, even where the point path is
//! a hand-vectorised kernel (Perlin on x86-64): per-axis work is shared across a row, and a
//! chunk in one cell hashes its corners once. Figures against the peer crates are in
//! `bench/README.md`.
//!
//! Nothing here allocates: the lanes live on the stack (a 4D lattice chunk holds 16 × [`LANES`]
//! corner values, 1 KiB in `f32`).
//!
//! # Examples
//!
//! ```
//! use bandnoise::{Noise, batch::Grid, lattice::Perlin};
//!
//! let perlin = Perlin::new(0);
//! // 64 × 32 samples, 1/16 of a cell apart, starting at (0.5, 2.0).
//! let grid = Grid::new([0.5f32, 2.0], [0.0625, 0.0625], [64, 32]);
//! let mut image = [0.0f32; 64 * 32];
//! perlin.fill_grid(&grid, &mut image).unwrap();
//! assert_eq!(image[3 * 64 + 5], perlin.sample(grid.point([5, 3])));
//!
//! // A buffer of the wrong size is an error, not a panic.
//! assert!(perlin.fill_grid(&grid, &mut image[..10]).is_err());
//! ```

use crate::{Error, Noise, Real};

/// The number of points the batch kernels evaluate together. 16 `f32` lanes fill four SSE2 or
/// `simd128` registers (two AVX registers); the per-chunk stack stays small enough for
/// microcontrollers.
pub const LANES: usize = 16;

/// A regular grid of points: point `index` has coordinates `origin[a] + index[a] · step[a]`.
///
/// In floats the product and sum are IEEE `×` and `+` (`index[a]` converted to the float type
/// exactly up to 2²⁴). In fixed point the index converts saturating at 32767, the product wraps
/// (a wrapped coordinate is still a lattice coordinate: lattice noises are periodic with a
/// period dividing 2¹⁶) and the sum saturates. [`Grid::point`] computes exactly this, so
/// `fill_grid` equals sampling at `grid.point(index)`, bit for bit.
///
/// # Examples
///
/// ```
/// use bandnoise::batch::Grid;
///
/// // A 1024² slice of 3D space at z = 0.37.
/// let g = Grid::new([0.0f32, 0.0, 0.37], [1.0 / 16.0, 1.0 / 16.0, 0.0], [1024, 1024, 1]);
/// assert_eq!(g.len(), 1024 * 1024);
/// assert_eq!(g.point([16, 32, 0]), [1.0, 2.0, 0.37]);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grid<R, const D: usize> {
    /// The coordinates of point `[0, …, 0]`.
    pub origin: [R; D],
    /// The distance between neighbouring points along each axis.
    pub step: [R; D],
    /// The number of points along each axis.
    pub size: [usize; D],
}

impl<R: Real, const D: usize> Grid<R, D> {
    /// A grid of `size[0] × size[1] × …` points.
    #[must_use]
    pub const fn new(origin: [R; D], step: [R; D], size: [usize; D]) -> Self {
        Self { origin, step, size }
    }

    /// The number of points, saturating at `usize::MAX` (no buffer has that many).
    #[must_use]
    pub fn len(&self) -> usize {
        self.size.iter().fold(1usize, |n, &s| n.saturating_mul(s))
    }

    /// Whether the grid has no points.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.size.contains(&0)
    }

    /// The coordinate of index `i` along `axis`.
    #[inline]
    pub(crate) fn coordinate(&self, axis: usize, i: usize) -> R {
        self.at(axis, R::from_i32(i.min(i32::MAX as usize) as i32))
    }

    /// The coordinate along `axis` of the index `i` converted to `R`: the one formula of
    /// [`coordinate`](Self::coordinate) and [`lanes`](Self::lanes).
    #[inline(always)]
    fn at(&self, axis: usize, i: R) -> R {
        self.origin[axis].saturating_add(i.wrapping_mul(self.step[axis]))
    }

    /// [`coordinate`](Self::coordinate) of the [`LANES`] indices `first, first + 1, …` along
    /// `axis`, bit for bit. Up to index 32767 every number type holds the indices exactly
    /// (I16F16's largest integer), so `first + l` is the sum of `first` and `l` converted
    /// once: lanes of additions, where converting each index from `usize` through the clamp
    /// was most of a batch's work on coordinates (`bench/README.md`). Beyond, index by index.
    #[inline]
    pub(crate) fn lanes(&self, axis: usize, first: usize) -> [R; LANES] {
        const EXACT: usize = (1 << 15) - LANES;
        if first <= EXACT {
            let base = R::from_i32(first as i32);
            core::array::from_fn(|l| self.at(axis, base + R::from_i32(l as i32)))
        } else {
            core::array::from_fn(|l| self.coordinate(axis, first.saturating_add(l)))
        }
    }

    /// The point at `index` (see the type's docs for the arithmetic).
    #[must_use]
    pub fn point(&self, index: [usize; D]) -> [R; D] {
        core::array::from_fn(|a| self.coordinate(a, index[a]))
    }

    /// The number of rows, the grid's lines of points along axis 0 (0 for an empty grid).
    #[must_use]
    pub fn rows(&self) -> usize {
        if self.is_empty() {
            return 0;
        }
        self.size
            .iter()
            .skip(1)
            .fold(1usize, |n, &s| n.saturating_mul(s))
    }

    /// Row `row` as a grid of its own: its points along axis 0, one along each other axis
    /// (rows are numbered with axis 1 fastest, as the grid's values are laid out). Its values
    /// are the full grid's row, bit for bit: its origin is the row's first point, except along
    /// axis 0, where it is the grid's. For filling a large grid a bounded buffer at a time.
    /// Rows from [`rows`](Self::rows) on repeat the grid's rows (numbers are taken modulo
    /// `rows()`); an empty grid's rows are empty.
    ///
    /// # Examples
    ///
    /// ```
    /// use bandnoise::prelude::*;
    ///
    /// let noise = Perlin::new(3);
    /// let grid = Grid::new([0.37f32, -0.61, 2.3], [0.0731, 0.113, -0.29], [7, 5, 3]);
    /// let mut whole = vec![0.0f32; grid.len()];
    /// noise.fill_grid(&grid, &mut whole)?;
    /// assert_eq!(grid.rows(), 15);
    /// let mut row = [0.0f32; 7];
    /// for (r, expected) in whole.chunks(7).enumerate() {
    ///     noise.fill_grid(&grid.row(r), &mut row)?;
    ///     assert_eq!(row.map(f32::to_bits), <[f32; 7]>::try_from(expected)?.map(f32::to_bits));
    /// }
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    #[must_use]
    pub fn row(&self, row: usize) -> Self {
        let mut origin = self.row_start(row);
        let mut size = [1usize; D];
        if let (Some(o), Some(s), Some(&o0), Some(&s0)) = (
            origin.first_mut(),
            size.first_mut(),
            self.origin.first(),
            self.size.first(),
        ) {
            (*o, *s) = (o0, if self.is_empty() { 0 } else { s0 });
        }
        Self {
            origin,
            step: self.step,
            size,
        }
    }

    /// The first point of row `row` (rows are numbered with axis 1 fastest): its coordinates
    /// along axes 1.. are those of every point of the row. The grid must not be empty.
    pub(crate) fn row_start(&self, row: usize) -> [R; D] {
        let mut index = [0usize; D];
        let mut rest = row;
        for (i, &size) in index.iter_mut().zip(&self.size).skip(1) {
            // Sizes are non-zero here; `checked_` keeps a zero from being a panic path.
            *i = rest.checked_rem(size).unwrap_or(0);
            rest = rest.checked_div(size).unwrap_or(0);
        }
        self.point(index)
    }
}

/// Checks `out` against `grid` and calls `row(start, values)` for each row of the grid: the
/// row's first point and its part of `out` (nothing for an empty grid). The walk every
/// row-based `fill_grid` shares.
#[inline]
pub(crate) fn for_each_row<R: Real, const D: usize>(
    grid: &Grid<R, D>,
    out: &mut [R],
    mut row: impl FnMut([R; D], &mut [R]),
) -> Result<(), Error> {
    for_each_rows::<R, D, 1>(grid, out, |starts, row_out| {
        if let [start] = starts {
            row(*start, row_out);
        }
    })
}

/// [`for_each_row`] `G` rows at a time: calls `rows(starts, values)` with the first points of
/// up to `G` consecutive rows and their part of `out`.
#[inline]
pub(crate) fn for_each_rows<R: Real, const D: usize, const G: usize>(
    grid: &Grid<R, D>,
    out: &mut [R],
    mut rows: impl FnMut(&[[R; D]], &mut [R]),
) -> Result<(), Error> {
    check_len(grid.len(), out.len())?;
    let row_len = grid.size[0];
    if row_len == 0 || grid.is_empty() {
        return Ok(());
    }
    let mut starts = [[R::ZERO; D]; G];
    for (k, values) in out.chunks_mut(row_len.saturating_mul(G)).enumerate() {
        let count = values.len() / row_len;
        for (g, start) in starts.iter_mut().enumerate().take(count) {
            *start = grid.row_start(k * G + g);
        }
        rows(starts.get(..count).unwrap_or_default(), values);
    }
    Ok(())
}

/// Evaluates `noise` over `grid` into `out` (see [`Noise::fill_grid`]).
pub(crate) fn fill_grid<N: Noise<R, D> + ?Sized, R: Real, const D: usize>(
    noise: &N,
    grid: &Grid<R, D>,
    out: &mut [R],
) -> Result<(), Error> {
    // The other axes hold the row's coordinates; each chunk computes its own along axis 0.
    let mut lanes = [[R::ZERO; LANES]; D];
    let mut values = [R::ZERO; LANES];
    for_each_row(grid, out, |start, row_out| {
        for (lane, &x) in lanes.iter_mut().zip(&start).skip(1) {
            *lane = [x; LANES];
        }
        for (c, chunk) in row_out.chunks_mut(LANES).enumerate() {
            lanes[0] = grid.lanes(0, c * LANES);
            noise.sample_lanes(&lanes, &mut values);
            store_lanes(chunk, &values);
        }
    })
}

/// [`fill_grid`] for a noise without a lane body: each row's points one by one, through
/// `sample`, the same values in the same order. For the OpenSimplex noises whose lanes are
/// point samples (4D) this is faster than `fill_grid`'s chunks of 16 with the same
/// instructions: measured, not explained (bench/README.md); cellular noise, whose lanes are
/// point samples too, takes its points' time in `fill_grid`.
pub(crate) fn fill_grid_pointwise<N: Noise<R, D> + ?Sized, R: Real, const D: usize>(
    noise: &N,
    grid: &Grid<R, D>,
    out: &mut [R],
) -> Result<(), Error> {
    fill_grid_by(grid, out, |p| noise.sample(p))
}

/// Fills `out` over `grid` with `sample` of each point, row by row, each row's points
/// computed as [`Grid::lanes`] computes them (so as [`Grid::point`]).
pub(crate) fn fill_grid_by<R: Real, const D: usize>(
    grid: &Grid<R, D>,
    out: &mut [R],
    sample: impl Fn([R; D]) -> R,
) -> Result<(), Error> {
    for_each_row(grid, out, |start, row_out| {
        let mut p = start;
        for (c, chunk) in row_out.chunks_mut(LANES).enumerate() {
            let xs = grid.lanes(0, c * LANES);
            for (o, &x) in chunk.iter_mut().zip(&xs) {
                p[0] = x;
                *o = sample(p);
            }
        }
    })
}

/// Evaluates `noise` at the points `points[0][i], points[1][i], …` into `out[i]`
/// (see [`Noise::fill_points`]).
pub(crate) fn fill_points<N: Noise<R, D> + ?Sized, R: Real, const D: usize>(
    noise: &N,
    points: [&[R]; D],
    out: &mut [R],
) -> Result<(), Error> {
    check_points(&points, out.len())?;
    let mut lanes = [[R::ZERO; LANES]; D];
    let mut values = [R::ZERO; LANES];
    let mut axes = points.map(|axis| axis.chunks(LANES));
    for chunk in out.chunks_mut(LANES) {
        for (lane, axis) in lanes.iter_mut().zip(&mut axes) {
            // A short last chunk leaves the previous chunk's points in the unused lanes:
            // they are evaluated and dropped. (Copies by `zip`: no length to check.)
            for (l, &x) in lane.iter_mut().zip(axis.next().unwrap_or(&[])) {
                *l = x;
            }
        }
        noise.sample_lanes(&lanes, &mut values);
        store_lanes(chunk, &values);
    }
    Ok(())
}

/// [`fill_points`] for a noise without a lane body: the points one by one, through `sample`
/// (for the same noises as [`fill_grid_pointwise`], and for the same reason).
pub(crate) fn fill_points_pointwise<N: Noise<R, D> + ?Sized, R: Real, const D: usize>(
    noise: &N,
    points: [&[R]; D],
    out: &mut [R],
) -> Result<(), Error> {
    check_points(&points, out.len())?;
    for (i, o) in out.iter_mut().enumerate() {
        *o = noise.sample(core::array::from_fn(|a| points[a][i]));
    }
    Ok(())
}

/// Copies the first `out.len()` (at most [`LANES`]) values of `v`: a whole chunk as a copy of
/// fixed size (a few vector moves, where a copy of variable length calls `memcpy`).
#[inline]
pub(crate) fn store_lanes<R: Real>(out: &mut [R], v: &[R; LANES]) {
    match <&mut [R; LANES]>::try_from(&mut *out) {
        Ok(whole) => *whole = *v,
        Err(_) => {
            for (o, &x) in out.iter_mut().zip(v) {
                *o = x;
            }
        }
    }
}

/// [`Error::BufferLength`] unless every axis of `points` has `len` elements.
fn check_points<R, const D: usize>(points: &[&[R]; D], len: usize) -> Result<(), Error> {
    for axis in points {
        check_len(axis.len(), len)?;
    }
    Ok(())
}

pub(crate) fn check_len(expected: usize, found: usize) -> Result<(), Error> {
    if expected == found {
        Ok(())
    } else {
        Err(Error::BufferLength { expected, found })
    }
}

/// Transposes lane `l` of a structure of arrays into a point.
#[inline]
pub(crate) fn lane<R: Copy, const D: usize>(p: &[[R; LANES]; D], l: usize) -> [R; D] {
    core::array::from_fn(|a| p[a][l])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::I16F16;

    /// `Grid::lanes` is `Grid::coordinate` of each index, bit for bit, on both sides of the
    /// exact-sum limit and far beyond it (where fixed point saturates and the clamp to
    /// `i32::MAX` applies), for each number type.
    #[test]
    fn lanes_are_the_coordinates() {
        let firsts = [
            0,
            16,
            1000,
            (1 << 15) - 2 * LANES,
            (1 << 15) - LANES - 1,
            (1 << 15) - LANES,
            (1 << 15) - LANES + 1,
            1 << 15,
            (1 << 24) - 8,
            i32::MAX as usize - 20,
            i32::MAX as usize - 3,
            usize::MAX - 5,
        ];
        macro_rules! check {
            ($t:ty, $from:expr, $bits:expr) => {
                let origins = [-4.123, 0.0, 0.37, 1000.5, -30000.0];
                let steps = [0.0737, 1.0 / 16.0, -0.29, 3.0, 0.0];
                for (&o, &s) in origins.iter().zip(&steps) {
                    let g: Grid<$t, 2> =
                        Grid::new([$from(o), $from(s)], [$from(s), $from(o)], [1, 1]);
                    for &first in &firsts {
                        for axis in 0..2 {
                            let lanes = g.lanes(axis, first);
                            for (l, &x) in lanes.iter().enumerate() {
                                let c = g.coordinate(axis, first.saturating_add(l));
                                assert_eq!($bits(x), $bits(c), "{o} {s} {first} {axis} {l}");
                            }
                        }
                    }
                }
            };
        }
        check!(f32, |v: f64| v as f32, f32::to_bits);
        check!(f64, |v: f64| v, f64::to_bits);
        check!(I16F16, I16F16::from_num, I16F16::to_bits);
    }
}

//! Lattice noises: a value or a gradient at every integer point, hashed from the point's
//! coordinates, blended across each cell by a fade curve.
//!
//! | type | paper | hash | gradients | fade |
//! |---|---|---|---|---|
//! | [`Perlin`] | Perlin 2002; pbrt §10.6.1 | [`Permutation`](crate::hash::Permutation), x innermost | Perlin's 12 cube edges (+4 repeats) | quintic |
//! | [`TabledPerlin`] | as [`Perlin`], plus a per-seed table for the point kernel | | | |
//! | [`OriginalPerlin`] | Perlin 1985 | permutation, x innermost | a table of 256 random unit vectors | cubic |
//! | [`ValueNoise`] | pbrt §10.6 intro; Lewis 1989 §2 | permutation, x innermost | none: a value in `[-1, 1]` per point | quintic |
//! | [`CNoise`] | Olano 2005 §3.2 | permutation, last axis innermost | cube corners `(±1, ±1, …)` | quintic |
//! | [`MNoise`] | Olano 2005 §3.3 | [`Bbs`](crate::hash::Bbs) `x² mod M`, last axis innermost | cube corners | quintic |
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
pub(crate) mod kernel;
mod original;
mod periodic;
pub(crate) mod perlin;
mod value;

pub use corner::{CNoise, MNoise};
pub use original::OriginalPerlin;
pub use periodic::Periodic;
pub use perlin::{Perlin, TabledPerlin};
pub use value::ValueNoise;

use crate::batch::{self, Grid, LANES};
use crate::{Error, Real};
use kernel::{
    Fade, MAX_CORNERS, corner_offset, fade_all, interpolate, interpolate_with_gradient, minus_one,
    split_point,
};

/// What distinguishes one gradient noise from another: how corners are hashed, which gradient a
/// hash selects, and the fade curve. The sampling itself is shared ([`sample_gradient`]).
pub(crate) trait GradientLattice<const D: usize> {
    /// The fade curve.
    type Fade: Fade;
    /// The hash of each corner of `cell`, indexed by corner bit mask.
    fn corner_hashes(&self, cell: [i32; D]) -> [u32; MAX_CORNERS];
    /// `gradient(h) · d`.
    fn dot<R: Real>(&self, h: u32, d: &[R; D]) -> R;
    /// The gradient vector selected by `h`.
    fn gradient<R: Real>(&self, h: u32) -> [R; D];

    /// The noise at `p` ([`Noise::sample`](crate::Noise::sample)): [`sample_gradient`], unless
    /// the lattice has a faster kernel for this number type and target with the same results
    /// bit for bit (Perlin 2D/3D in `f32` with SSE2).
    #[inline]
    fn sample_point<R: Real>(&self, p: [R; D]) -> R
    where
        Self: Sized,
    {
        sample_gradient(self, p)
    }

    /// Whether [`sample_point`](Self::sample_point), lane by lane, is faster than the lane
    /// kernel for lanes in several cells (true where `sample_point` has a vector kernel); the
    /// lanes of [`sample_gradient_lanes`] (fractal octaves finer than a chunk, scattered points)
    /// then take it. Either gives the same values.
    #[inline]
    fn point_kernel_for_scattered_lanes<R: Real>() -> bool {
        false
    }

    /// `dot(h, d)` given the gradient `g = gradient(h)`: `Σ_a d_a·g_a` in axis order. Equal to
    /// `dot` except, possibly, for the sign of a zero (every gradient here has components whose
    /// products are exact, and the missing terms of `dot` are the zero components), which
    /// sampling canonicalises; the batch test checks the results bit for bit.
    #[inline]
    fn dot_with<R: Real>(&self, g: &[R; D], d: &[R; D]) -> R {
        kernel::sum_of_products(d, g, R::mul_rn)
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
impl<L: GradientLattice<D>, const D: usize> GradientLattice<D> for &L {
    type Fade = L::Fade;
    #[inline]
    fn corner_hashes(&self, cell: [i32; D]) -> [u32; MAX_CORNERS] {
        (**self).corner_hashes(cell)
    }
    #[inline]
    fn dot<R: Real>(&self, h: u32, d: &[R; D]) -> R {
        (**self).dot(h, d)
    }
    #[inline]
    fn gradient<R: Real>(&self, h: u32) -> [R; D] {
        (**self).gradient(h)
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
    fn dot_with<R: Real>(&self, g: &[R; D], d: &[R; D]) -> R {
        (**self).dot_with(g, d)
    }
    #[inline]
    fn corner_hashes_lanes(&self, cell: &[[i32; LANES]; D]) -> [[u32; LANES]; MAX_CORNERS] {
        (**self).corner_hashes_lanes(cell)
    }
}

/// Samples a gradient noise at `p`.
#[inline]
pub(crate) fn sample_gradient<L: GradientLattice<D>, R: Real, const D: usize>(
    lattice: &L,
    p: [R; D],
) -> R {
    let (cell, f) = split_point(p);
    let h = lattice.corner_hashes(cell);
    let f1 = minus_one(&f);
    let mut dots = [R::ZERO; MAX_CORNERS];
    for (m, dot) in dots.iter_mut().enumerate().take(1 << D) {
        *dot = lattice.dot(h[m], &corner_offset(&f, &f1, m));
    }
    interpolate(dots, &fade_all::<L::Fade, R, D>(f)).canonical()
}

/// [`sample_gradient`] for [`LANES`] points: the same steps, each over all lanes before the
/// next (split, hash, dot products, fade, interpolation), so the arithmetic vectorises.
/// Bit-identical to `sample_gradient` lane by lane: every lane computes the same operations on
/// the same values in the same order.
#[inline]
pub(crate) fn sample_gradient_lanes<L: GradientLattice<D>, R: Real, const D: usize>(
    lattice: &L,
    p: &[[R; LANES]; D],
    out: &mut [R; LANES],
) {
    let (cell, f) = split_lanes(p);
    let s = f.map(|fa| fa.map(L::Fade::fade));
    *out = if cell.iter().all(|ca| ca.iter().all(|&c| c == ca[0])) {
        one_cell_lanes(
            lattice,
            cell.map(|ca| ca[0]),
            |a, l| f[a][l],
            |a, l| s[a][l],
        )
    } else if L::point_kernel_for_scattered_lanes::<R>() {
        core::array::from_fn(|l| lattice.sample_point(batch::lane(p, l)))
    } else {
        lanes_in_several_cells(lattice, &cell, &f, &s)
    };
}

/// The lanes of [`sample_gradient_lanes`] when all of them lie in one cell `cell` (a grid finer
/// than [`LANES`] samples per cell, along a row): the corners are hashed and their gradients
/// looked up once; then each lane runs the point kernel's dot products and interpolation, one
/// straight-line body that the compiler vectorises across lanes.
///
/// `f(a, l)` and `s(a, l)` are lane `l`'s fraction and faded fraction along axis `a`. Where they
/// do not depend on `l` (the axes of a grid row other than axis 0), the compiler sees constants
/// of the lane loop and computes their products with the gradients once.
#[inline]
fn one_cell_lanes<L: GradientLattice<D>, R: Real, const D: usize>(
    lattice: &L,
    cell: [i32; D],
    f: impl Fn(usize, usize) -> R,
    s: impl Fn(usize, usize) -> R,
) -> [R; LANES] {
    let h = lattice.corner_hashes(cell);
    let mut g = [[R::ZERO; D]; MAX_CORNERS];
    for (m, gm) in g.iter_mut().enumerate().take(1 << D) {
        *gm = lattice.gradient(h[m]);
    }
    core::array::from_fn(|l| {
        let fl: [R; D] = core::array::from_fn(|a| f(a, l));
        let f1 = minus_one(&fl);
        let mut v = [R::ZERO; MAX_CORNERS];
        for (m, vm) in v.iter_mut().enumerate().take(1 << D) {
            *vm = lattice.dot_with(&g[m], &corner_offset(&fl, &f1, m));
        }
        let t: [R; D] = core::array::from_fn(|a| s(a, l));
        interpolate(v, &t).canonical()
    })
}

/// The lanes of [`sample_gradient_lanes`] when they lie in several cells: one hash chain and
/// one gradient per lane. Kept out of line so that its code does not change how the compiler
/// lays out the one-cell path (inlined, it cost the 2D grid kernel 4 instructions per sample);
/// one call per chunk of 16 lanes costs next to nothing.
#[inline(never)]
fn lanes_in_several_cells<L: GradientLattice<D>, R: Real, const D: usize>(
    lattice: &L,
    cell: &[[i32; LANES]; D],
    f: &[[R; LANES]; D],
    s: &[[R; LANES]; D],
) -> [R; LANES] {
    let f1 = f.map(|fa| fa.map(|x| x - R::ONE));
    let mut v = [[R::ZERO; LANES]; MAX_CORNERS];
    let h = lattice.corner_hashes_lanes(cell);
    for (m, vm) in v.iter_mut().enumerate().take(1 << D) {
        for (l, vml) in vm.iter_mut().enumerate() {
            *vml = lattice.dot(h[m][l], &lane_offset(f, &f1, m, l));
        }
    }
    interpolate_lanes(&mut v, s);
    v[0].map(R::canonical)
}

/// [`corner_offset`] for lane `l`: the offset from corner `m` to the lane's point, given the
/// lanes' fractions `f` and `f1 = f − 1`.
#[inline]
fn lane_offset<R: Real, const D: usize>(
    f: &[[R; LANES]; D],
    f1: &[[R; LANES]; D],
    m: usize,
    l: usize,
) -> [R; D] {
    core::array::from_fn(|a| if m >> a & 1 == 0 { f[a][l] } else { f1[a][l] })
}

/// Chunks of [`LANES`] columns that [`fill_grid_gradient`] takes through the rows together, so
/// that each row's split and fade along the axes other than 0 serve all of them.
const CHUNKS_PER_BLOCK: usize = 4;

/// Axis 0 of one chunk of a grid: every lane's cell, fraction and faded fraction, and whether
/// the lanes share one cell.
#[derive(Clone, Copy)]
struct ChunkAxis0<R> {
    cell: [i32; LANES],
    f: [R; LANES],
    s: [R; LANES],
    one_cell: bool,
}

/// [`Noise::fill_grid`](crate::Noise::fill_grid) for a gradient lattice: blocks of
/// [`CHUNKS_PER_BLOCK`] column chunks of [`LANES`] points outermost, so each chunk's split and
/// fade along axis 0 serve every row; the other axes, constant along a row, are split and faded
/// once per row and block. The values are those of [`sample_gradient_lanes`] (the same
/// operations on the same numbers).
pub(crate) fn fill_grid_gradient<L: GradientLattice<D>, R: Real, const D: usize>(
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
    for block in (0..width).step_by(LANES * CHUNKS_PER_BLOCK) {
        let chunks = (width - block).div_ceil(LANES).min(CHUNKS_PER_BLOCK);
        let mut x = [ChunkAxis0 {
            cell: [0; LANES],
            f: [R::ZERO; LANES],
            s: [R::ZERO; LANES],
            one_cell: false,
        }; CHUNKS_PER_BLOCK];
        for (k, xk) in x.iter_mut().enumerate().take(chunks) {
            let coordinates = core::array::from_fn(|l| grid.coordinate(0, block + k * LANES + l));
            R::split_lanes(&coordinates, &mut xk.cell, &mut xk.f);
            xk.s = xk.f.map(L::Fade::fade);
            xk.one_cell = xk.cell.iter().all(|&c| c == xk.cell[0]);
        }
        for row in 0..rows {
            // Axes 1..: (cell, fraction, faded fraction) of the row; axis 0 unused.
            let mut along = [(0i32, R::ZERO, R::ZERO); D];
            let first = grid.row_start(row);
            for (a, along_a) in along.iter_mut().enumerate().skip(1) {
                let (c, fa) = first[a].split();
                *along_a = (c, fa, L::Fade::fade(fa));
            }
            for (k, xk) in x.iter().enumerate().take(chunks) {
                let start = block + k * LANES;
                let v = if xk.one_cell {
                    let cell =
                        core::array::from_fn(|a| if a == 0 { xk.cell[0] } else { along[a].0 });
                    let f = |a: usize, l| if a == 0 { xk.f[l] } else { along[a].1 };
                    let s = |a: usize, l| if a == 0 { xk.s[l] } else { along[a].2 };
                    one_cell_lanes(lattice, cell, f, s)
                } else {
                    let cell =
                        core::array::from_fn(
                            |a| if a == 0 { xk.cell } else { [along[a].0; LANES] },
                        );
                    let f =
                        core::array::from_fn(|a| if a == 0 { xk.f } else { [along[a].1; LANES] });
                    let s =
                        core::array::from_fn(|a| if a == 0 { xk.s } else { [along[a].2; LANES] });
                    lanes_in_several_cells(lattice, &cell, &f, &s)
                };
                // In range by construction (`get_mut` keeps it provably panic-free).
                let at = row * width + start;
                if let Some(dst) = out.get_mut(at..at + LANES.min(width - start)) {
                    batch::store_lanes(dst, &v);
                }
            }
        }
    }
    Ok(())
}

/// [`split_point`] over lanes: cells and fractions, axis by axis.
#[inline]
pub(crate) fn split_lanes<R: Real, const D: usize>(
    p: &[[R; LANES]; D],
) -> ([[i32; LANES]; D], [[R; LANES]; D]) {
    const { assert!(D >= 1 && D <= 4, "lattice noises have 1 to 4 dimensions") };
    let mut cell = [[0i32; LANES]; D];
    let mut f = [[R::ZERO; LANES]; D];
    for a in 0..D {
        R::split_lanes(&p[a], &mut cell[a], &mut f[a]);
    }
    (cell, f)
}

/// [`interpolate`] over lanes: the result is left in `v[0]`.
#[inline]
pub(crate) fn interpolate_lanes<R: Real, const D: usize>(
    v: &mut [[R; LANES]; MAX_CORNERS],
    t: &[[R; LANES]; D],
) {
    let mut n = 1 << D;
    for ta in t {
        n >>= 1;
        for j in 0..n {
            for l in 0..LANES {
                v[j][l] = kernel::lerp(ta[l], v[2 * j][l], v[2 * j + 1][l]);
            }
        }
    }
}

/// Samples a gradient noise and its analytic gradient at `p`.
#[inline]
pub(crate) fn sample_gradient_with_gradient<L: GradientLattice<D>, R: Real, const D: usize>(
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
    let s = fade_all::<L::Fade, R, D>(f);
    let ds = f.map(L::Fade::fade_derivative);
    interpolate_with_gradient(dots, &grads, &s, &ds)
}

/// Implements `Noise` and `NoiseGradient` for a gradient lattice type, in every dimension it
/// has a `GradientLattice` for. `$bound(&self, D)` is the amplitude bound.
macro_rules! gradient_noise_impls {
    ($ty:ty, [$($generics:tt)*], $bound:expr) => {
        impl<R: crate::Real, const D: usize, $($generics)*> crate::Noise<R, D> for $ty
        where
            $ty: crate::lattice::GradientLattice<D>,
        {
            #[inline]
            fn sample(&self, p: [R; D]) -> R {
                crate::lattice::GradientLattice::<D>::sample_point(self, p)
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
                crate::lattice::sample_gradient_lanes(self, p, out);
            }
            fn fill_grid(
                &self,
                grid: &crate::batch::Grid<R, D>,
                out: &mut [R],
            ) -> Result<(), crate::Error> {
                crate::lattice::fill_grid_gradient(self, grid, out)
            }
        }

        impl<R: crate::Real, const D: usize, $($generics)*> crate::NoiseGradient<R, D> for $ty
        where
            $ty: crate::lattice::GradientLattice<D>,
        {
            #[inline]
            fn sample_with_gradient(&self, p: [R; D]) -> (R, [R; D]) {
                crate::lattice::sample_gradient_with_gradient(self, p)
            }
        }
    };
}
pub(crate) use gradient_noise_impls;

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
    if h >> bit & 1 == 0 { x } else { -x }
}

//! The batch API (`fill_grid`, `fill_points`, `sample_lanes`) is bit-identical to `sample` for
//! every noise, number type and dimension, including the inputs that leave the vectorised
//! paths (non-finite, huge, cells beyond 2²⁴), and refuses buffers of the wrong length.

use bandnoise::Error;
use bandnoise::batch::{Grid, LANES};
use bandnoise::fractal::{Fractal, Octaves};
use bandnoise::prelude::*;
use bandnoise::wavelet::{
    Bands, Distribution, Multiband, TILE2, TILE2_I16, TILE3, TILE3_I16, Tile2, Tile3, TileData,
    Tiling, Wavelet,
};
use bandnoise_tests::{AllTypes, Lattice, Rng};

/// The exact bits of a value of any of the three types (`to_f64` is exact for all three).
fn bits<R: Real>(v: R) -> u64 {
    v.to_f64().to_bits()
}

/// Coordinates that stress the split and hash paths: ordinary values, values next to cell
/// boundaries, −0.0, cells beyond the f32-exact hash range, huge and non-finite values.
fn coordinate(rng: &mut Rng) -> f32 {
    match rng.next_u64() % 16 {
        0 => f32::NAN,
        1 => f32::INFINITY,
        2 => f32::NEG_INFINITY,
        3 => -0.0,
        4 => -1e-30,
        5 => rng.f64_in(-3e9, 3e9) as f32,
        6 => rng.f64_in(-2e7, 2e7) as f32,
        7 => rng.i32_in(-40_000, 40_000) as f32,
        _ => rng.f64_in(-300.0, 300.0) as f32,
    }
}

/// `fill_points` and `fill_grid` against `sample`, bit for bit.
fn check<R: Real, const D: usize, N: Noise<R, D>>(name: &str, noise: &N, rng: &mut Rng) {
    // Points: 16 chunks, some entirely ordinary (the vectorised split), some with one special
    // lane, and a short last chunk.
    let count = 16 * LANES + 5;
    let mut axes: [Vec<R>; D] = core::array::from_fn(|_| Vec::with_capacity(count));
    for i in 0..count {
        let special = (i / LANES).is_multiple_of(3);
        for axis in &mut axes {
            let x = if special {
                coordinate(rng)
            } else {
                rng.f64_in(-300.0, 300.0) as f32
            };
            axis.push(R::from_f32(x));
        }
    }
    let slices: [&[R]; D] = core::array::from_fn(|a| &axes[a][..]);
    let mut out = vec![R::ZERO; count];
    noise.fill_points(slices, &mut out).unwrap();
    for (i, v) in out.iter().enumerate() {
        let p: [R; D] = core::array::from_fn(|a| axes[a][i]);
        assert_eq!(bits(*v), bits(noise.sample(p)), "{name} {D}D points: {p:?}");
    }

    // Points along a row (the lanes' cells differ along axis 0 only, 1 to 4 of them): the
    // column kernels of `sample_lanes`.
    let origin: [f32; D] = core::array::from_fn(|_| rng.f64_in(-100.0, 100.0) as f32);
    for step in [0.01f32, 0.06, 0.1, 0.13, 0.2] {
        let axes: [Vec<R>; D] = core::array::from_fn(|a| {
            (0..4 * LANES)
                .map(|i| {
                    R::from_f32(if a == 0 {
                        origin[0] + i as f32 * step
                    } else {
                        origin[a]
                    })
                })
                .collect()
        });
        let slices: [&[R]; D] = core::array::from_fn(|a| &axes[a][..]);
        let mut out = vec![R::ZERO; 4 * LANES];
        noise.fill_points(slices, &mut out).unwrap();
        for (i, v) in out.iter().enumerate() {
            let p: [R; D] = core::array::from_fn(|a| axes[a][i]);
            assert_eq!(bits(*v), bits(noise.sample(p)), "{name} {D}D row: {p:?}");
        }
    }

    // Grids: a row that is not a multiple of LANES, a row shorter than LANES, a far origin, and
    // rows of several blocks of chunks, with steps that put a chunk's lanes in many cells, in
    // up to 3 (below 2/15 of a cell) and, finer than 1/16, in one or two (and, over 400
    // columns, runs of a cell cut by a block's end, which the next block then starts with);
    // and rows aligned with the cells (origin on the lattice along axis 0, a step of 1/16 or
    // 1/32: every chunk in one cell), which take the chunk loop rather than runs.
    for (size0, far, max_step, aligned) in [
        (37, false, 0.7, None),
        (5, false, 0.7, None),
        (LANES, true, 0.7, None),
        (150, false, 0.7, None),
        (150, false, 0.13, None),
        (150, false, 0.06, None),
        (400, false, 0.09, None),
        (300, false, 0.3, Some(1.0 / 16.0)),
        (150, false, 0.3, Some(-1.0 / 32.0)),
    ] {
        let size: [usize; D] = core::array::from_fn(|a| if a == 0 { size0 } else { 3 });
        let origin = core::array::from_fn(|a| {
            R::from_f32(if far {
                coordinate(rng)
            } else if aligned.is_some() && a == 0 {
                rng.f64_in(-100.0, 100.0).round() as f32
            } else {
                rng.f64_in(-100.0, 100.0) as f32
            })
        });
        let step = core::array::from_fn(|a| {
            R::from_f32(match aligned {
                Some(step) if a == 0 => step,
                _ => rng.f64_in(-max_step, max_step) as f32,
            })
        });
        let grid = Grid::new(origin, step, size);
        let mut out = vec![R::ZERO; grid.len()];
        noise.fill_grid(&grid, &mut out).unwrap();
        let mut index = [0usize; D];
        for v in &out {
            let p = grid.point(index);
            assert_eq!(
                bits(*v),
                bits(noise.sample(p)),
                "{name} {D}D grid: {index:?} {p:?}"
            );
            for a in 0..D {
                index[a] += 1;
                if index[a] < size[a] {
                    break;
                }
                index[a] = 0;
            }
        }
    }
}

fn check_all_types<const D: usize, N: AllTypes<D>>(name: &str, noise: &N, rng: &mut Rng) {
    check::<f32, D, N>(name, noise, rng);
    check::<f64, D, N>(name, noise, rng);
    check::<I16F16, D, N>(name, noise, rng);
}

#[test]
fn lattice_noises_in_batch_equal_point_evaluation() {
    let mut rng = Rng::from_env(71);
    for seed in [0, 5] {
        for (name, noise) in Lattice::all(seed) {
            check_all_types::<1, _>(name, &noise, &mut rng);
            check_all_types::<2, _>(name, &noise, &mut rng);
            check_all_types::<3, _>(name, &noise, &mut rng);
            check_all_types::<4, _>(name, &noise, &mut rng);
        }
    }
}

fn check_fractals<R: Real, const D: usize>(rng: &mut Rng)
where
    Perlin: Noise<R, D>,
    TabledPerlin: Noise<R, D>,
    MNoise<61>: Noise<R, D>,
{
    for kind in [Kind::Fbm, Kind::Turbulence, Kind::Ridged] {
        let perlin = Fractal::new(Perlin::new(1), Octaves::new(6, 2.0, 0.5).unwrap(), kind);
        check::<R, D, _>("fractal perlin", &perlin, rng);
        let m = Fractal::new(
            MNoise::<61>::new(2),
            Octaves::new(4, 1.9, 0.6).unwrap(),
            kind,
        );
        check::<R, D, _>("fractal mnoise", &m, rng);
    }
}

#[test]
fn fractal_sums_in_batch_equal_point_evaluation() {
    let mut rng = Rng::from_env(72);
    check_fractals::<f32, 2>(&mut rng);
    check_fractals::<f32, 3>(&mut rng);
    check_fractals::<f64, 3>(&mut rng);
    check_fractals::<I16F16, 2>(&mut rng);
    check_fractals::<I16F16, 3>(&mut rng);
}

#[test]
fn wavelet_noise_in_batch_equals_point_evaluation() {
    let mut rng = Rng::from_env(73);
    check_all_types::<2, _>("wavelet", &Wavelet::new(3, &TILE2), &mut rng);
    check_all_types::<3, _>("wavelet", &Wavelet::new(3, &TILE3), &mut rng);
    check_all_types::<3, _>("wavelet i16", &Wavelet::new(3, &TILE3_I16), &mut rng);
    let periodic = Wavelet::new(6, &TILE2).with_tiling(Tiling::Periodic);
    check_all_types::<2, _>("wavelet periodic", &periodic, &mut rng);
    let blended = Wavelet::new(6, &TILE2).with_tiling(Tiling::Blended);
    check_all_types::<2, _>("wavelet blended", &blended, &mut rng);
    let blended = Wavelet::new(6, &TILE3_I16).with_tiling(Tiling::Blended);
    check_all_types::<3, _>("wavelet blended i16", &blended, &mut rng);
    // A 3D tile whose side is not a power of two: a point sample reads each block through
    // `Tile3::cube` (on x86-64 and AArch64), with checked indices, where the batch path reads
    // flat indices; blended (12 has room for the zones) and varied.
    static ODD: Tile3<12> = Tile3::generate(5);
    check_all_types::<3, _>("wavelet 12³", &Wavelet::new(2, &ODD), &mut rng);
    let varied = Wavelet::new(2, &ODD).with_tiling(Tiling::Varied);
    check_all_types::<3, _>("wavelet 12³ varied", &varied, &mut rng);
    // Fine grids: whole chunks inside one block (the vectorised path), and across borders.
    // Rows whose coefficients reach into the next block along y or z (every lane alike).
    for fine in [
        Grid::new([-40.3f32, 7.1, 2.0], [0.01, 0.37, 0.0], [300, 4, 1]),
        Grid::new([-40.3f32, 31.2, 0.37], [0.01, 0.2, 0.0], [300, 4, 1]),
    ] {
        for band in [
            Wavelet::new(1, &TILE3),
            Wavelet::new(1, &TILE3).with_tiling(Tiling::Periodic),
            Wavelet::new(1, &TILE3).with_tiling(Tiling::Blended),
        ] {
            let mut out = vec![0.0f32; fine.len()];
            band.fill_grid(&fine, &mut out).unwrap();
            for (k, v) in out.iter().enumerate() {
                let p = fine.point([k % 300, k / 300, 0]);
                assert_eq!(
                    v.to_bits(),
                    band.sample(p).to_bits(),
                    "wavelet fine grid at {p:?}"
                );
            }
        }
    }
    let multi = Multiband::new(1, &TILE3, Bands::default(), Distribution::Uniform);
    check_all_types::<3, _>("multiband", &multi, &mut rng);
    let fbm = Fractal::fbm(Wavelet::new(4, &TILE2), Octaves::default());
    check::<f32, 2, _>("fractal wavelet", &fbm, &mut rng);
}

/// Grids whose rows cross wavelet block borders and corners (blocks `n` coefficients wide):
/// rows in blend zones along y and z, x running over a border, backwards, standing still, and
/// in strides longer than a row's column cache (`band/row.rs`), against `sample`.
fn check_rows<R: Real, const D: usize, N: Noise<R, D>>(name: &str, noise: &N, n: f32) {
    // Stacks of slices, and one slice with a finer step along y (3D: the demo's grid).
    let shapes = [(0.25f32, 22usize), (0.07, 1)];
    let starts = [(n - 5.3, n - 5.1), (-n - 4.9, 2.6), (3.4, -n + 3.3)];
    for ((y0, z0), (y_step, depth)) in starts.into_iter().flat_map(|s| shapes.map(|h| (s, h))) {
        for (x0, step) in [
            (n - 9.7, 0.37f32),
            (n + 9.1, -0.29),
            (n - 3.2, 0.0),
            (-n - 8.8, 1.3),
            (2.0 * n - 60.0, 11.7),
            (n - 0.6, 0.013),
        ] {
            let origin: [R; D] = core::array::from_fn(|a| R::from_f32([x0, y0, z0][a]));
            let steps: [R; D] = core::array::from_fn(|a| R::from_f32([step, y_step, 0.5][a]));
            let size: [usize; D] = core::array::from_fn(|a| [77, 44, depth][a]);
            let grid = Grid::new(origin, steps, size);
            let mut out = vec![R::ZERO; grid.len()];
            noise.fill_grid(&grid, &mut out).unwrap();
            for (k, v) in out.iter().enumerate() {
                let index: [usize; D] =
                    core::array::from_fn(|a| [k % 77, k / 77 % 44, k / 77 / 44][a]);
                let p = grid.point(index);
                assert_eq!(bits(*v), bits(noise.sample(p)), "{name} {D}D row at {p:?}");
            }
        }
    }
}

/// [`check_rows`] for a band in each tiling.
fn check_band_rows<R: Real, const D: usize, T: TileData<D> + 'static>(
    name: &str,
    band: Wavelet<'static, T>,
) where
    Wavelet<'static, T>: Noise<R, D>,
{
    for tiling in [Tiling::Blended, Tiling::Varied, Tiling::Periodic] {
        let name = format!("{name} {tiling:?}");
        check_rows::<R, D, _>(&name, &band.with_tiling(tiling), T::SIZE as f32);
    }
}

#[test]
fn wavelet_rows_across_block_corners_equal_point_evaluation() {
    check_band_rows::<f32, 2, _>("f32", Wavelet::new(3, &TILE2));
    check_band_rows::<f64, 2, _>("f64", Wavelet::new(4, &TILE2));
    check_band_rows::<I16F16, 2, _>("I16F16", Wavelet::new(5, &TILE2_I16));
    check_band_rows::<f32, 3, _>("f32", Wavelet::new(3, &TILE3));
    check_band_rows::<I16F16, 3, _>("I16F16", Wavelet::new(6, &TILE3_I16));
    // A tile too small for blend zones (11 coefficients or fewer: shifted blocks abut).
    static SMALL: Tile2<8> = Tile2::generate(2);
    check_band_rows::<f32, 2, _>("small tile", Wavelet::new(1, &SMALL));
    // Multiband noise: every band's row through the band's kernel, summed in `sample`'s order;
    // bands finer and coarser than the grid, both distributions.
    let bands = Bands::new(-2, &[0.3, 0.0, 1.0, 0.5, 0.25, 0.7]).unwrap();
    for distribution in [Distribution::Gaussian, Distribution::Uniform] {
        let m2 = Multiband::new(2, &TILE2, bands, distribution);
        check_rows::<f32, 2, _>("multiband", &m2, 16.0);
        check_rows::<I16F16, 2, _>("multiband", &m2, 16.0);
        let m3 = Multiband::new(3, &TILE3_I16, bands, distribution);
        check_rows::<f32, 3, _>("multiband", &m3, 8.0);
        check_rows::<f64, 3, _>("multiband", &m3, 8.0);
    }
}

#[test]
fn buffers_of_the_wrong_length_are_refused() {
    let perlin = Perlin::new(0);
    let grid = Grid::new([0.0f32; 2], [0.5; 2], [10, 7]);
    let mut out = vec![1.0f32; 69];
    assert_eq!(
        perlin.fill_grid(&grid, &mut out),
        Err(Error::BufferLength {
            expected: 70,
            found: 69
        })
    );
    assert!(out.iter().all(|&v| v == 1.0), "untouched on error");
    let xs = [0.0f32; 4];
    let ys = [0.0f32; 3];
    assert!(perlin.fill_points([&xs, &ys], &mut [0.0; 4]).is_err());
    assert!(perlin.fill_points([&xs, &xs], &mut [0.0; 3]).is_err());
    // An empty grid fills an empty buffer; a grid whose size overflows needs usize::MAX.
    let empty = Grid::new([0.0f32; 2], [0.5; 2], [0, 7]);
    assert_eq!(perlin.fill_grid(&empty, &mut []), Ok(()));
    let huge = Grid::new([0.0f32; 3], [0.5; 3], [usize::MAX, 2, 1]);
    assert_eq!(huge.len(), usize::MAX);
    assert!(perlin.fill_grid(&huge, &mut out).is_err());
}

#[test]
fn reduce_lanes_equals_reduce_over_the_fast_range() {
    use bandnoise::hash::Bbs;
    fn exhaustive<const M: u32>() {
        let fast = 16_777_216 - 8192;
        let mut x = [0i32; LANES];
        let mut start = -fast;
        while start <= fast {
            for (l, v) in x.iter_mut().enumerate() {
                *v = (start + l as i32).min(fast);
            }
            let r = Bbs::<M>::reduce_lanes(&x);
            for l in 0..LANES {
                assert_eq!(r[l], Bbs::<M>::reduce(x[l]), "M = {M}, x = {}", x[l]);
            }
            start += LANES as i32;
        }
        // Out of the fast range: the fallback.
        let far = [i32::MIN, i32::MAX, fast + 1, -fast - 1].repeat(4);
        let far: [i32; LANES] = far.try_into().unwrap();
        assert_eq!(Bbs::<M>::reduce_lanes(&far), far.map(Bbs::<M>::reduce));
    }
    exhaustive::<61>();
    exhaustive::<4093>();
    exhaustive::<2>();
}

/// A noise whose own batch methods write a marker, to see which implementation a call reaches.
struct Marked;

impl Noise<f32, 2> for Marked {
    fn sample(&self, _: [f32; 2]) -> f32 {
        0.0
    }
    fn amplitude_bound(&self) -> f32 {
        42.0
    }
    fn fill_grid(&self, _: &Grid<f32, 2>, out: &mut [f32]) -> Result<(), Error> {
        out.fill(42.0);
        Ok(())
    }
    fn fill_points(&self, _: [&[f32]; 2], out: &mut [f32]) -> Result<(), Error> {
        out.fill(-42.0);
        Ok(())
    }
}

/// Through a reference (as in `Fractal::fbm(&perlin, …)` or generic code taking `&N`), the
/// batch methods reach the noise's own kernels, not the trait's lane-by-lane defaults.
#[test]
fn references_forward_the_batch_kernels() {
    let by_ref = &&Marked;
    let grid = Grid::new([0.0f32; 2], [0.1; 2], [5, 3]);
    let mut out = [0.0f32; 15];
    by_ref.fill_grid(&grid, &mut out).unwrap();
    assert!(out.iter().all(|&v| v == 42.0));
    by_ref
        .fill_points([&[0.0; 15], &[0.0; 15]], &mut out)
        .unwrap();
    assert!(out.iter().all(|&v| v == -42.0));
}

/// `Grid::row` past the last row repeats the rows (modulo `rows()`), and an empty grid's rows
/// are empty, whichever axis is empty.
#[test]
fn rows_past_the_last_repeat_and_empty_grids_have_empty_rows() {
    let grid = Grid::new([0.37f32, -0.61, 2.3], [0.0731, 0.113, -0.29], [7, 5, 3]);
    assert_eq!(grid.rows(), 15);
    for r in 0..15 {
        let (a, b) = (grid.row(r), grid.row(r + 15));
        assert_eq!((a.origin, a.step, a.size), (b.origin, b.step, b.size));
        assert_eq!(a.size, [7, 1, 1]);
    }
    for size in [[0, 5, 3], [7, 0, 3], [7, 5, 0]] {
        let empty = Grid::new([0.37f32, -0.61, 2.3], [0.0731, 0.113, -0.29], size);
        assert_eq!(empty.rows(), 0);
        assert!(
            empty.row(0).is_empty() && empty.row(4).is_empty(),
            "{size:?}"
        );
    }
}

//! The workloads of the peer benchmark: the same 1024-wide grid, 1/16 of a lattice cell between
//! samples (z = 0.37 for 3D), evaluated by bandnoise (point by point and with
//! [`Noise::fill_grid`]) and by the peer crates `noise` 0.9, `fastnoise-lite` 1.1,
//! `noise-functions` 0.8 and `libnoise` 1.2.
//!
//! Every workload writes each sample into the same output buffer, so all pay the same memory
//! traffic. `benches/peers.rs` times them with criterion and prints the ratio table;
//! `src/bin/callgrind.rs` runs one under callgrind for instruction counts
//! (`scripts/bench-peers.sh` does both).

use bandnoise::Noise;
use bandnoise::batch::Grid;
use bandnoise::fractal::{Fractal, Octaves};
use bandnoise::lattice::{MNoise, Perlin, TabledPerlin, ValueNoise};
use bandnoise::wavelet::{TILE2, TILE3, Wavelet};

/// Samples per row (and rows in the timed grid).
pub const N: usize = 1024;
/// Distance between samples, in lattice cells.
pub const STEP: f32 = 1.0 / 16.0;
/// The fixed third coordinate of the 3D workloads.
pub const Z: f32 = 0.37;

/// What a workload computes (a row of the table).
pub const FUNCTIONS: [&str; 10] = [
    "perlin-2d",
    "perlin-3d",
    "tabled-perlin-2d",
    "tabled-perlin-3d",
    "mnoise-2d",
    "mnoise-3d",
    "value-2d",
    "wavelet-2d",
    "wavelet-3d",
    "fbm6-perlin-3d",
];

/// Who computes it (a column of the table). The first two are bandnoise.
pub const IMPLEMENTATIONS: [&str; 6] = [
    "bandnoise",
    "bandnoise-batch",
    "noise",
    "fastnoise-lite",
    "noise-functions",
    "libnoise",
];

/// A workload: fills `rows` rows of the grid into `out` (`rows · N` values).
pub type Run = Box<dyn Fn(usize, &mut [f32])>;

/// Point evaluation over the 2D grid.
fn points2(rows: usize, out: &mut [f32], f: impl Fn(f32, f32) -> f32) {
    for (j, row) in out.chunks_exact_mut(N).take(rows).enumerate() {
        let y = j as f32 * STEP;
        for (i, o) in row.iter_mut().enumerate() {
            *o = f(i as f32 * STEP, y);
        }
    }
}

/// The grid for bandnoise's batch path: the same coordinates as [`points2`].
fn grid2(rows: usize) -> Grid<f32, 2> {
    Grid::new([0.0; 2], [STEP; 2], [N, rows])
}

fn grid3(rows: usize) -> Grid<f32, 3> {
    Grid::new([0.0, 0.0, Z], [STEP, STEP, 0.0], [N, rows, 1])
}

fn batch2<No: Noise<f32, 2> + 'static>(noise: No) -> Run {
    Box::new(move |rows, out| noise.fill_grid(&grid2(rows), &mut out[..rows * N]).unwrap())
}

fn batch3<No: Noise<f32, 3> + 'static>(noise: No) -> Run {
    Box::new(move |rows, out| noise.fill_grid(&grid3(rows), &mut out[..rows * N]).unwrap())
}

fn point2<No: Noise<f32, 2> + 'static>(noise: No) -> Run {
    Box::new(move |rows, out| points2(rows, out, |x, y| noise.sample([x, y])))
}

fn point3<No: Noise<f32, 3> + 'static>(noise: No) -> Run {
    Box::new(move |rows, out| points2(rows, out, |x, y| noise.sample([x, y, Z])))
}

/// A libnoise generator over the 2D grid (libnoise computes in f64).
fn libnoise2<G: libnoise::Generator<2> + 'static>(n: G) -> Run {
    Box::new(move |rows, out| points2(rows, out, |x, y| n.sample([x as f64, y as f64]) as f32))
}

/// A libnoise generator over the 3D grid's plane `z = Z`.
fn libnoise3<G: libnoise::Generator<3> + 'static>(n: G) -> Run {
    Box::new(move |rows, out| {
        points2(rows, out, |x, y| {
            n.sample([x as f64, y as f64, Z as f64]) as f32
        })
    })
}

/// The workload `function` by `implementation`, if that implementation has it.
#[must_use]
pub fn workload(function: &str, implementation: &str) -> Option<Run> {
    use fastnoise_lite::{FastNoiseLite, FractalType, NoiseType};
    use noise::{MultiFractal, NoiseFn};
    use noise_functions::Noise as _;

    let fast = |kind: NoiseType, octaves: Option<i32>| {
        let mut n = FastNoiseLite::new();
        n.set_noise_type(Some(kind));
        n.set_frequency(Some(1.0));
        if let Some(o) = octaves {
            n.set_fractal_type(Some(FractalType::FBm));
            n.set_fractal_octaves(Some(o));
        }
        n
    };
    let fbm = || Fractal::fbm(Perlin::new(0), Octaves::new(6, 2.0, 0.5).unwrap());
    let run: Run = match (function, implementation) {
        ("perlin-2d", "bandnoise") => point2(Perlin::new(0)),
        ("perlin-2d", "bandnoise-batch") => batch2(Perlin::new(0)),
        ("perlin-3d", "bandnoise") => point3(Perlin::new(0)),
        ("perlin-3d", "bandnoise-batch") => batch3(Perlin::new(0)),
        ("tabled-perlin-2d", "bandnoise") => point2(TabledPerlin::new(0)),
        ("tabled-perlin-2d", "bandnoise-batch") => batch2(TabledPerlin::new(0)),
        ("tabled-perlin-3d", "bandnoise") => point3(TabledPerlin::new(0)),
        ("tabled-perlin-3d", "bandnoise-batch") => batch3(TabledPerlin::new(0)),
        ("mnoise-2d", "bandnoise") => point2(MNoise::<61>::new(0)),
        ("mnoise-2d", "bandnoise-batch") => batch2(MNoise::<61>::new(0)),
        ("mnoise-3d", "bandnoise") => point3(MNoise::<61>::new(0)),
        ("mnoise-3d", "bandnoise-batch") => batch3(MNoise::<61>::new(0)),
        ("value-2d", "bandnoise") => point2(ValueNoise::new(0)),
        ("value-2d", "bandnoise-batch") => batch2(ValueNoise::new(0)),
        ("wavelet-2d", "bandnoise") => point2(Wavelet::new(0, &TILE2)),
        ("wavelet-2d", "bandnoise-batch") => batch2(Wavelet::new(0, &TILE2)),
        ("wavelet-3d", "bandnoise") => point3(Wavelet::new(0, &TILE3)),
        ("wavelet-3d", "bandnoise-batch") => batch3(Wavelet::new(0, &TILE3)),
        ("fbm6-perlin-3d", "bandnoise") => point3(fbm()),
        ("fbm6-perlin-3d", "bandnoise-batch") => batch3(fbm()),

        ("perlin-2d", "noise") => {
            let n = noise::Perlin::new(0);
            Box::new(move |rows, out| points2(rows, out, |x, y| n.get([x as f64, y as f64]) as f32))
        }
        ("perlin-3d", "noise") => {
            let n = noise::Perlin::new(0);
            Box::new(move |rows, out| {
                points2(rows, out, |x, y| {
                    n.get([x as f64, y as f64, Z as f64]) as f32
                })
            })
        }
        ("value-2d", "noise") => {
            let n = noise::Value::new(0);
            Box::new(move |rows, out| points2(rows, out, |x, y| n.get([x as f64, y as f64]) as f32))
        }
        ("fbm6-perlin-3d", "noise") => {
            let n = noise::Fbm::<noise::Perlin>::new(0)
                .set_octaves(6)
                .set_lacunarity(2.0)
                .set_persistence(0.5);
            Box::new(move |rows, out| {
                points2(rows, out, |x, y| {
                    n.get([x as f64, y as f64, Z as f64]) as f32
                })
            })
        }

        ("perlin-2d", "fastnoise-lite") => {
            let n = fast(NoiseType::Perlin, None);
            Box::new(move |rows, out| points2(rows, out, |x, y| n.get_noise_2d(x, y)))
        }
        ("perlin-3d", "fastnoise-lite") => {
            let n = fast(NoiseType::Perlin, None);
            Box::new(move |rows, out| points2(rows, out, |x, y| n.get_noise_3d(x, y, Z)))
        }
        ("value-2d", "fastnoise-lite") => {
            let n = fast(NoiseType::Value, None);
            Box::new(move |rows, out| points2(rows, out, |x, y| n.get_noise_2d(x, y)))
        }
        ("fbm6-perlin-3d", "fastnoise-lite") => {
            let n = fast(NoiseType::Perlin, Some(6));
            Box::new(move |rows, out| points2(rows, out, |x, y| n.get_noise_3d(x, y, Z)))
        }

        ("perlin-2d", "noise-functions") => Box::new(move |rows, out| {
            points2(rows, out, |x, y| noise_functions::Perlin.sample2([x, y]))
        }),
        ("perlin-3d", "noise-functions") => Box::new(move |rows, out| {
            points2(rows, out, |x, y| noise_functions::Perlin.sample3([x, y, Z]))
        }),
        ("value-2d", "noise-functions") => Box::new(move |rows, out| {
            points2(rows, out, |x, y| noise_functions::Value.sample2([x, y]))
        }),
        ("fbm6-perlin-3d", "noise-functions") => {
            let n = noise_functions::Perlin.fbm(6, 0.5, 2.0);
            Box::new(move |rows, out| points2(rows, out, |x, y| n.sample3([x, y, Z])))
        }

        ("perlin-2d", "libnoise") => libnoise2(libnoise::Source::<2>::perlin(0)),
        ("perlin-3d", "libnoise") => libnoise3(libnoise::Source::<3>::perlin(0)),
        ("value-2d", "libnoise") => libnoise2(libnoise::Source::<2>::value(0)),
        ("fbm6-perlin-3d", "libnoise") => libnoise3(libnoise::Generator::fbm(
            libnoise::Source::<3>::perlin(0),
            6,
            1.0,
            2.0,
            0.5,
        )),
        _ => return None,
    };
    Some(run)
}

/// The function whose fastest peer a bandnoise-only function is compared with: mNoise, wavelet
/// noise and Perlin noise with its per-seed table (`TabledPerlin`) against the peers' Perlin
/// noise of the same dimension.
#[must_use]
pub fn peer_function(function: &str) -> &str {
    match function {
        "tabled-perlin-2d" | "mnoise-2d" | "wavelet-2d" => "perlin-2d",
        "tabled-perlin-3d" | "mnoise-3d" | "wavelet-3d" => "perlin-3d",
        f => f,
    }
}

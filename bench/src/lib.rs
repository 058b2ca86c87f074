//! The workloads of the peer benchmark: a 1024-wide grid (z = 0.37 for 3D, and w = 0.61 for
//! 4D) evaluated by bandnoise (point by point and with [`Noise::fill_grid`]) and by the peer
//! crates `noise` 0.9, `fastnoise-lite` 1.1, `noise-functions` 0.8 and `libnoise` 1.2, on each
//! of the [`LAYOUTS`]: 1/16 of a lattice cell between samples from the origin (every chunk of
//! 16 samples of a row in one cell), and a grid as a user has one, whose step is not a
//! power-of-two fraction of a cell and whose origin is off the lattice.
//!
//! Every workload writes each sample into the same output buffer, so all pay the same memory
//! traffic. `benches/peers.rs` times them with criterion and prints the ratio table;
//! `src/bin/callgrind.rs` runs one under callgrind for instruction counts
//! (`scripts/bench-peers.sh` does both).

use bandnoise::batch::Grid;
use bandnoise::cellular::Cellular;
use bandnoise::fractal::{Fractal, Octaves};
use bandnoise::impulse::SparseConvolution;
use bandnoise::lattice::{
    CubicValueNoise, MNoise, MixedMNoise, MixedTurbulence, Perlin, TabledPerlin, ValueNoise,
};
use bandnoise::simplex::{Flow, OpenSimplex2, OpenSimplex2S, Simplex};
use bandnoise::wavelet::{Multiband, TILE2, TILE3, Wavelet};
use bandnoise::{Noise, ProjectedNoise};

/// Samples per row (and rows in the timed grid).
pub const N: usize = 1024;
/// The fixed third coordinate of the 3D and 4D workloads.
pub const Z: f32 = 0.37;
/// The fixed fourth coordinate of the 4D workloads.
pub const W: f32 = 0.61;

/// Where a grid's samples are: sample `(i, j)` is at `origin + (i, j) · step`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Layout {
    /// The name in the tables and on the command line.
    pub name: &'static str,
    /// The coordinates of sample `(0, 0)`.
    pub origin: [f32; 2],
    /// The distance between neighbouring samples, in lattice cells.
    pub step: f32,
}

/// The grids every workload runs on. `sixteenth` is the benchmark's historical grid (its rows'
/// chunks of 16 samples each lie in one cell, which the batch kernels exploit);
/// `off-lattice` is what a user has: a step of 0.0737 cells (a chunk of 16 samples spans 1.1
/// cells, so nearly every chunk straddles a cell boundary) from an origin inside a cell.
pub const LAYOUTS: [Layout; 2] = [
    Layout {
        name: "sixteenth",
        origin: [0.0, 0.0],
        step: 1.0 / 16.0,
    },
    Layout {
        name: "off-lattice",
        origin: [3.217, -5.683],
        step: 0.0737,
    },
];

/// The layout named `name`.
#[must_use]
pub fn layout(name: &str) -> Option<Layout> {
    LAYOUTS.into_iter().find(|l| l.name == name)
}

/// What a workload computes (a row of the table).
pub const FUNCTIONS: [&str; 34] = [
    "perlin-2d",
    "perlin-3d",
    "perlin-4d",
    "tabled-perlin-2d",
    "tabled-perlin-3d",
    "tabled-perlin-4d",
    "mnoise-2d",
    "mnoise-3d",
    "mnoise-4d",
    "mixed-mnoise-3d",
    "mixed-mnoise-4d",
    "mnoise-3d-tilted",
    "mixed-mnoise-3d-tilted",
    "turbulence4-mnoise-3d-tilted",
    "turbulence4-mixed-3d-tilted",
    "value-2d",
    "value-cubic-2d",
    "wavelet-2d",
    "wavelet-3d",
    "wavelet-projected-axis",
    "wavelet-projected-oblique",
    "multiband-2d",
    "fbm6-perlin-3d",
    "sparse-2d",
    "sparse-3d",
    "simplex-2d",
    "simplex-3d",
    "flow-2d",
    "opensimplex2-2d",
    "opensimplex2-3d",
    "opensimplex2s-2d",
    "opensimplex2s-3d",
    "cellular-2d",
    "cellular-3d",
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

/// The workload a runner binary's command line `args` names, `FUNCTION IMPLEMENTATION [ROWS]
/// [LAYOUT]` (`ROWS` required unless `rows` gives its default; `LAYOUT` one of the names of
/// [`LAYOUTS`], `layout_name` when left out): the workload and its row count (at least 1, at
/// most [`N`]).
///
/// # Errors
///
/// A message saying what is wrong, starting with the usage line `usage`.
pub fn command_line(
    usage: &str,
    args: &[String],
    rows: Option<usize>,
    layout_name: &str,
) -> Result<(Run, usize), String> {
    let (Some(function), Some(implementation)) = (args.get(1), args.get(2)) else {
        return Err(usage.into());
    };
    let rows = match (args.get(3), rows) {
        (Some(r), _) => r
            .parse::<usize>()
            .map_err(|_| format!("{usage}: ROWS must be a number"))?,
        (None, Some(rows)) => rows,
        (None, None) => return Err(usage.into()),
    };
    let name = args.get(4).map_or(layout_name, String::as_str);
    let Some(layout) = layout(name) else {
        let names: Vec<&str> = LAYOUTS.iter().map(|l| l.name).collect();
        return Err(format!("{usage}: LAYOUT is one of {names:?}"));
    };
    let run = workload(function, implementation, layout)
        .ok_or_else(|| format!("no workload {function} for {implementation}"))?;
    Ok((run, rows.clamp(1, N)))
}

/// Whether a benchmark binary measures and prints its tables: `cargo bench` passes `--bench`.
/// Run by `cargo test` (no `--bench`, as criterion decides its test mode), or with `--test` or
/// `--list`, each workload runs once and nothing is timed (CI's "run once").
pub fn measuring() -> bool {
    let args: Vec<String> = std::env::args().collect();
    let has = |flag: &str| args.iter().any(|a| a == flag);
    has("--bench") && !has("--test") && !has("--list")
}

/// The seconds `run` takes to fill `rows` rows of `out`.
pub fn seconds(run: &Run, rows: usize, out: &mut [f32]) -> f64 {
    let start = std::time::Instant::now();
    run(rows, out);
    std::hint::black_box(&*out);
    start.elapsed().as_secs_f64()
}

/// The `q`-quantile of `v` (sorted in place), nearest rank.
pub fn quantile(v: &mut [f64], q: f64) -> f64 {
    v.sort_by(f64::total_cmp);
    v[((v.len() - 1) as f64 * q).round() as usize]
}

impl Layout {
    /// Point evaluation of `f` at every sample of `rows` rows (the same coordinates as
    /// [`Layout::grid`]).
    pub fn points(self, rows: usize, out: &mut [f32], f: impl Fn(f32, f32) -> f32) {
        for (j, row) in out.chunks_exact_mut(N).take(rows).enumerate() {
            let y = self.origin[1] + j as f32 * self.step;
            for (i, o) in row.iter_mut().enumerate() {
                *o = f(self.origin[0] + i as f32 * self.step, y);
            }
        }
    }

    /// The grid of `rows` rows for bandnoise's batch path, in `D` dimensions (the axes past 1
    /// at [`Z`] and [`W`]).
    fn grid<const D: usize>(self, rows: usize) -> Grid<f32, D> {
        Grid::new(
            at::<D>(self.origin[0], self.origin[1]),
            core::array::from_fn(|a| if a < 2 { self.step } else { 0.0 }),
            core::array::from_fn(|a| match a {
                0 => N,
                1 => rows,
                _ => 1,
            }),
        )
    }

    /// [`Noise::fill_grid`] of `noise` over the grid, in `D` dimensions.
    pub fn batch<No: Noise<f32, D> + 'static, const D: usize>(self, noise: No) -> Run {
        Box::new(move |rows, out| {
            noise
                .fill_grid(&self.grid::<D>(rows), &mut out[..rows * N])
                .unwrap()
        })
    }

    /// Point evaluation of `noise` over the grid, in `D` dimensions.
    pub fn point<No: Noise<f32, D> + 'static, const D: usize>(self, noise: No) -> Run {
        Box::new(move |rows, out| self.points(rows, out, |x, y| noise.sample(at::<D>(x, y))))
    }

    /// Point evaluation of `noise` over the grid tilted out of the plane `z = Z`
    /// (`z = Z + 0.29·x + 0.53·y`), in 3D: every sample has its own `z`, so no work on `z` can
    /// be hoisted out of the loop over a row (the `-tilted` rows).
    pub fn point_tilted<No: Noise<f32, 3> + 'static>(self, noise: No) -> Run {
        Box::new(move |rows, out| {
            self.points(rows, out, |x, y| {
                noise.sample([x, y, Z + 0.29 * x + 0.53 * y])
            })
        })
    }

    /// Point evaluation of `noise` projected along `normal` over the grid, in 3D.
    pub fn projected<No: ProjectedNoise<f32> + 'static>(self, noise: No, normal: [f32; 3]) -> Run {
        Box::new(move |rows, out| {
            self.points(rows, out, |x, y| {
                noise.sample_projected(at::<3>(x, y), normal)
            })
        })
    }

    /// [`ProjectedNoise::fill_grid_projected`] of `noise` along `normal` over the grid.
    pub fn projected_batch<No: ProjectedNoise<f32> + 'static>(
        self,
        noise: No,
        normal: [f32; 3],
    ) -> Run {
        Box::new(move |rows, out| {
            noise
                .fill_grid_projected(&self.grid::<3>(rows), normal, &mut out[..rows * N])
                .unwrap()
        })
    }

    /// A peer's 2D function of `f32` coordinates.
    fn peer2(self, f: impl Fn(f32, f32) -> f32 + 'static) -> Run {
        Box::new(move |rows, out| self.points(rows, out, &f))
    }

    /// A peer's function of `f64` coordinates in `D` dimensions (`noise`, `libnoise`).
    fn peer_f64<const D: usize>(self, f: impl Fn([f64; D]) -> f64 + 'static) -> Run {
        Box::new(move |rows, out| {
            self.points(rows, out, |x, y| f(at::<D>(x, y).map(f64::from)) as f32)
        })
    }
}

/// The point `(x, y)` of a grid row in `D` dimensions: the axes past 1 at [`Z`] and [`W`].
fn at<const D: usize>(x: f32, y: f32) -> [f32; D] {
    let p = [x, y, Z, W];
    core::array::from_fn(|a| p[a])
}

/// The workload `function` by `implementation` on `layout`, if that implementation has it.
#[must_use]
pub fn workload(function: &str, implementation: &str, layout: Layout) -> Option<Run> {
    use fastnoise_lite::{
        CellularDistanceFunction, CellularReturnType, FastNoiseLite, FractalType, NoiseType,
    };
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
    // Olano's turbulence (4 octaves, lacunarity 2), octave by octave.
    let turbulence = || Fractal::turbulence(MNoise::new(0), Octaves::new(4, 2.0, 0.5).unwrap());
    // The speed goal's configuration: 3 impulses in every cell (Peachey's count).
    let sparse3 = || SparseConvolution::<3>::new(0).with_fixed_count(3).unwrap();
    // The default bands (0–4, weights halving) over the default 2D tile and tiling.
    let multiband = || Multiband::new(0, &TILE2, Default::default(), Default::default());
    let l = layout;
    let run: Run = match (function, implementation) {
        ("perlin-2d", "bandnoise") => l.point::<_, 2>(Perlin::new(0)),
        ("perlin-2d", "bandnoise-batch") => l.batch::<_, 2>(Perlin::new(0)),
        ("perlin-3d", "bandnoise") => l.point::<_, 3>(Perlin::new(0)),
        ("perlin-3d", "bandnoise-batch") => l.batch::<_, 3>(Perlin::new(0)),
        ("perlin-4d", "bandnoise") => l.point::<_, 4>(Perlin::new(0)),
        ("perlin-4d", "bandnoise-batch") => l.batch::<_, 4>(Perlin::new(0)),
        ("tabled-perlin-2d", "bandnoise") => l.point::<_, 2>(TabledPerlin::new(0)),
        ("tabled-perlin-2d", "bandnoise-batch") => l.batch::<_, 2>(TabledPerlin::new(0)),
        ("tabled-perlin-3d", "bandnoise") => l.point::<_, 3>(TabledPerlin::new(0)),
        ("tabled-perlin-3d", "bandnoise-batch") => l.batch::<_, 3>(TabledPerlin::new(0)),
        ("tabled-perlin-4d", "bandnoise") => l.point::<_, 4>(TabledPerlin::new(0)),
        ("tabled-perlin-4d", "bandnoise-batch") => l.batch::<_, 4>(TabledPerlin::new(0)),
        ("mnoise-2d", "bandnoise") => l.point::<_, 2>(MNoise::new(0)),
        ("mnoise-2d", "bandnoise-batch") => l.batch::<_, 2>(MNoise::new(0)),
        ("mnoise-3d", "bandnoise") => l.point::<_, 3>(MNoise::new(0)),
        ("mnoise-3d", "bandnoise-batch") => l.batch::<_, 3>(MNoise::new(0)),
        ("mnoise-4d", "bandnoise") => l.point::<_, 4>(MNoise::new(0)),
        ("mnoise-4d", "bandnoise-batch") => l.batch::<_, 4>(MNoise::new(0)),
        ("mixed-mnoise-3d", "bandnoise") => l.point::<_, 3>(MixedMNoise::new(0)),
        ("mixed-mnoise-3d", "bandnoise-batch") => l.batch::<_, 3>(MixedMNoise::new(0)),
        ("mixed-mnoise-4d", "bandnoise") => l.point::<_, 4>(MixedMNoise::new(0)),
        ("mixed-mnoise-4d", "bandnoise-batch") => l.batch::<_, 4>(MixedMNoise::new(0)),
        ("mnoise-3d-tilted", "bandnoise") => l.point_tilted(MNoise::new(0)),
        ("mixed-mnoise-3d-tilted", "bandnoise") => l.point_tilted(MixedMNoise::new(0)),
        ("turbulence4-mnoise-3d-tilted", "bandnoise") => l.point_tilted(turbulence()),
        ("turbulence4-mixed-3d-tilted", "bandnoise") => {
            l.point_tilted(MixedTurbulence::<4>::new(0))
        }
        ("value-2d", "bandnoise") => l.point::<_, 2>(ValueNoise::new(0)),
        ("value-2d", "bandnoise-batch") => l.batch::<_, 2>(ValueNoise::new(0)),
        ("value-cubic-2d", "bandnoise") => l.point::<_, 2>(CubicValueNoise::new(0)),
        ("value-cubic-2d", "bandnoise-batch") => l.batch::<_, 2>(CubicValueNoise::new(0)),
        ("wavelet-2d", "bandnoise") => l.point::<_, 2>(Wavelet::new(0, &TILE2)),
        ("wavelet-2d", "bandnoise-batch") => l.batch::<_, 2>(Wavelet::new(0, &TILE2)),
        ("wavelet-3d", "bandnoise") => l.point::<_, 3>(Wavelet::new(0, &TILE3)),
        ("wavelet-3d", "bandnoise-batch") => l.batch::<_, 3>(Wavelet::new(0, &TILE3)),
        ("wavelet-projected-axis", "bandnoise") => {
            l.projected(Wavelet::new(0, &TILE3), [0.0, 0.0, 1.0])
        }
        ("wavelet-projected-oblique", "bandnoise") => {
            l.projected(Wavelet::new(0, &TILE3), [0.48, 0.6, 0.64])
        }
        ("wavelet-projected-axis", "bandnoise-batch") => {
            l.projected_batch(Wavelet::new(0, &TILE3), [0.0, 0.0, 1.0])
        }
        ("wavelet-projected-oblique", "bandnoise-batch") => {
            l.projected_batch(Wavelet::new(0, &TILE3), [0.48, 0.6, 0.64])
        }
        ("multiband-2d", "bandnoise") => l.point::<_, 2>(multiband()),
        ("multiband-2d", "bandnoise-batch") => l.batch::<_, 2>(multiband()),
        ("fbm6-perlin-3d", "bandnoise") => l.point::<_, 3>(fbm()),
        ("fbm6-perlin-3d", "bandnoise-batch") => l.batch::<_, 3>(fbm()),
        ("sparse-2d", "bandnoise") => l.point::<_, 2>(SparseConvolution::<2>::new(0)),
        ("sparse-2d", "bandnoise-batch") => l.batch::<_, 2>(SparseConvolution::<2>::new(0)),
        ("sparse-3d", "bandnoise") => l.point::<_, 3>(sparse3()),
        ("sparse-3d", "bandnoise-batch") => l.batch::<_, 3>(sparse3()),
        ("flow-2d", "bandnoise") => l.point::<_, 2>(Flow::new(0).with_angle(0.3).unwrap()),
        ("flow-2d", "bandnoise-batch") => l.batch::<_, 2>(Flow::new(0).with_angle(0.3).unwrap()),
        ("simplex-2d", "bandnoise") => l.point::<_, 2>(Simplex::new(0)),
        ("simplex-2d", "bandnoise-batch") => l.batch::<_, 2>(Simplex::new(0)),
        ("simplex-3d", "bandnoise") => l.point::<_, 3>(Simplex::new(0)),
        ("simplex-3d", "bandnoise-batch") => l.batch::<_, 3>(Simplex::new(0)),
        ("simplex-2d", "noise") => {
            let n = noise::Simplex::new(0);
            l.peer_f64::<2>(move |p| n.get(p))
        }
        ("simplex-3d", "noise") => {
            let n = noise::Simplex::new(0);
            l.peer_f64::<3>(move |p| n.get(p))
        }
        // FastNoise Lite's OpenSimplex2 is simplex noise in 2D (its 3D is a rotated BCC
        // lattice, another algorithm, so it has no 3D row here).
        ("simplex-2d", "fastnoise-lite") => {
            let n = fast(NoiseType::OpenSimplex2, None);
            l.peer2(move |x, y| n.get_noise_2d(x, y))
        }
        ("simplex-2d", "noise-functions") => {
            l.peer2(|x, y| noise_functions::Simplex.sample2([x, y]))
        }
        ("simplex-3d", "noise-functions") => {
            l.peer2(|x, y| noise_functions::Simplex.sample3([x, y, Z]))
        }
        ("simplex-2d", "libnoise") => {
            let n = libnoise::Source::<2>::simplex(0);
            l.peer_f64::<2>(move |p| libnoise::Generator::sample(&n, p))
        }
        ("simplex-3d", "libnoise") => {
            let n = libnoise::Source::<3>::simplex(0);
            l.peer_f64::<3>(move |p| libnoise::Generator::sample(&n, p))
        }
        // OpenSimplex2 and 2S: FastNoise Lite's are the same algorithms in their standard
        // orientation (its own hash and gradient sets), computed in f32.
        ("opensimplex2-2d", "bandnoise") => l.point::<_, 2>(OpenSimplex2::new(0)),
        ("opensimplex2-2d", "bandnoise-batch") => l.batch::<_, 2>(OpenSimplex2::new(0)),
        ("opensimplex2-3d", "bandnoise") => l.point::<_, 3>(OpenSimplex2::new(0)),
        ("opensimplex2-3d", "bandnoise-batch") => l.batch::<_, 3>(OpenSimplex2::new(0)),
        ("opensimplex2s-2d", "bandnoise") => l.point::<_, 2>(OpenSimplex2S::new(0)),
        ("opensimplex2s-2d", "bandnoise-batch") => l.batch::<_, 2>(OpenSimplex2S::new(0)),
        ("opensimplex2s-3d", "bandnoise") => l.point::<_, 3>(OpenSimplex2S::new(0)),
        ("opensimplex2s-3d", "bandnoise-batch") => l.batch::<_, 3>(OpenSimplex2S::new(0)),
        ("opensimplex2-2d" | "opensimplex2s-2d", "fastnoise-lite") => {
            let kind = if function == "opensimplex2-2d" {
                NoiseType::OpenSimplex2
            } else {
                NoiseType::OpenSimplex2S
            };
            let n = fast(kind, None);
            l.peer2(move |x, y| n.get_noise_2d(x, y))
        }
        ("opensimplex2-3d" | "opensimplex2s-3d", "fastnoise-lite") => {
            let kind = if function == "opensimplex2-3d" {
                NoiseType::OpenSimplex2
            } else {
                NoiseType::OpenSimplex2S
            };
            let n = fast(kind, None);
            l.peer2(move |x, y| n.get_noise_3d(x, y, Z))
        }
        // Cellular noise: F1, Euclidean, jitter 1 in every implementation (the peers'
        // defaults differ: FastNoise Lite's is the squared distance, `noise`'s the cell value).
        ("cellular-2d", "bandnoise") => l.point::<_, 2>(Cellular::new(0)),
        ("cellular-2d", "bandnoise-batch") => l.batch::<_, 2>(Cellular::new(0)),
        ("cellular-3d", "bandnoise") => l.point::<_, 3>(Cellular::new(0)),
        ("cellular-3d", "bandnoise-batch") => l.batch::<_, 3>(Cellular::new(0)),
        ("cellular-2d" | "cellular-3d", "fastnoise-lite") => {
            let mut n = fast(NoiseType::Cellular, None);
            n.set_cellular_distance_function(Some(CellularDistanceFunction::Euclidean));
            n.set_cellular_return_type(Some(CellularReturnType::Distance));
            if function == "cellular-2d" {
                l.peer2(move |x, y| n.get_noise_2d(x, y))
            } else {
                l.peer2(move |x, y| n.get_noise_3d(x, y, Z))
            }
        }
        ("cellular-2d", "noise-functions") => {
            l.peer2(|x, y| noise_functions::CellDistance::default().sample2([x, y]))
        }
        ("cellular-3d", "noise-functions") => {
            l.peer2(|x, y| noise_functions::CellDistance::default().sample3([x, y, Z]))
        }
        ("cellular-2d", "noise") => {
            let n =
                noise::Worley::new(0).set_return_type(noise::core::worley::ReturnType::Distance);
            l.peer_f64::<2>(move |p| n.get(p))
        }
        ("cellular-3d", "noise") => {
            let n =
                noise::Worley::new(0).set_return_type(noise::core::worley::ReturnType::Distance);
            l.peer_f64::<3>(move |p| n.get(p))
        }
        ("cellular-2d", "libnoise") => {
            let n = libnoise::Source::<2>::worley(0);
            l.peer_f64::<2>(move |p| libnoise::Generator::sample(&n, p))
        }
        ("cellular-3d", "libnoise") => {
            let n = libnoise::Source::<3>::worley(0);
            l.peer_f64::<3>(move |p| libnoise::Generator::sample(&n, p))
        }

        ("perlin-2d", "noise") => {
            let n = noise::Perlin::new(0);
            l.peer_f64::<2>(move |p| n.get(p))
        }
        ("perlin-3d", "noise") => {
            let n = noise::Perlin::new(0);
            l.peer_f64::<3>(move |p| n.get(p))
        }
        ("perlin-4d", "noise") => {
            let n = noise::Perlin::new(0);
            l.peer_f64::<4>(move |p| n.get(p))
        }
        ("value-2d", "noise") => {
            let n = noise::Value::new(0);
            l.peer_f64::<2>(move |p| n.get(p))
        }
        ("fbm6-perlin-3d", "noise") => {
            let n = noise::Fbm::<noise::Perlin>::new(0)
                .set_octaves(6)
                .set_lacunarity(2.0)
                .set_persistence(0.5);
            l.peer_f64::<3>(move |p| n.get(p))
        }

        ("perlin-2d", "fastnoise-lite") => {
            let n = fast(NoiseType::Perlin, None);
            l.peer2(move |x, y| n.get_noise_2d(x, y))
        }
        ("perlin-3d", "fastnoise-lite") => {
            let n = fast(NoiseType::Perlin, None);
            l.peer2(move |x, y| n.get_noise_3d(x, y, Z))
        }
        ("value-2d", "fastnoise-lite") => {
            let n = fast(NoiseType::Value, None);
            l.peer2(move |x, y| n.get_noise_2d(x, y))
        }
        // Catmull-Rom interpolation of lattice values, as CubicValueNoise.
        ("value-cubic-2d", "fastnoise-lite") => {
            let n = fast(NoiseType::ValueCubic, None);
            l.peer2(move |x, y| n.get_noise_2d(x, y))
        }
        ("fbm6-perlin-3d", "fastnoise-lite") => {
            let n = fast(NoiseType::Perlin, Some(6));
            l.peer2(move |x, y| n.get_noise_3d(x, y, Z))
        }

        ("perlin-2d", "noise-functions") => l.peer2(|x, y| noise_functions::Perlin.sample2([x, y])),
        ("perlin-3d", "noise-functions") => {
            l.peer2(|x, y| noise_functions::Perlin.sample3([x, y, Z]))
        }
        ("perlin-4d", "noise-functions") => {
            l.peer2(|x, y| noise_functions::Perlin.sample4([x, y, Z, W]))
        }
        ("value-2d", "noise-functions") => l.peer2(|x, y| noise_functions::Value.sample2([x, y])),
        ("value-cubic-2d", "noise-functions") => {
            l.peer2(|x, y| noise_functions::ValueCubic.sample2([x, y]))
        }
        ("fbm6-perlin-3d", "noise-functions") => {
            let n = noise_functions::Perlin.fbm(6, 0.5, 2.0);
            l.peer2(move |x, y| n.sample3([x, y, Z]))
        }

        ("perlin-2d", "libnoise") => {
            let n = libnoise::Source::<2>::perlin(0);
            l.peer_f64::<2>(move |p| libnoise::Generator::sample(&n, p))
        }
        ("perlin-3d", "libnoise") => {
            let n = libnoise::Source::<3>::perlin(0);
            l.peer_f64::<3>(move |p| libnoise::Generator::sample(&n, p))
        }
        ("perlin-4d", "libnoise") => {
            let n = libnoise::Source::<4>::perlin(0);
            l.peer_f64::<4>(move |p| libnoise::Generator::sample(&n, p))
        }
        ("value-2d", "libnoise") => {
            let n = libnoise::Source::<2>::value(0);
            l.peer_f64::<2>(move |p| libnoise::Generator::sample(&n, p))
        }
        ("fbm6-perlin-3d", "libnoise") => {
            let n = libnoise::Generator::fbm(libnoise::Source::<3>::perlin(0), 6, 1.0, 2.0, 0.5);
            l.peer_f64::<3>(move |p| libnoise::Generator::sample(&n, p))
        }
        _ => return None,
    };
    Some(run)
}

/// The function whose fastest peer a bandnoise-only function is compared with: mNoise, wavelet
/// noise (projected noise too, against 3D) and Perlin noise with its per-seed table
/// (`TabledPerlin`) against the peers' Perlin noise of the same dimension.
#[must_use]
pub fn peer_function(function: &str) -> &str {
    match function {
        "tabled-perlin-2d" | "mnoise-2d" | "wavelet-2d" | "multiband-2d" | "sparse-2d" => {
            "perlin-2d"
        }
        "tabled-perlin-4d" | "mnoise-4d" | "mixed-mnoise-4d" => "perlin-4d",
        "flow-2d" => "simplex-2d",
        "tabled-perlin-3d"
        | "mnoise-3d"
        | "mixed-mnoise-3d"
        | "mnoise-3d-tilted"
        | "mixed-mnoise-3d-tilted"
        | "wavelet-3d"
        | "wavelet-projected-axis"
        | "wavelet-projected-oblique"
        | "sparse-3d" => "perlin-3d",
        f => f,
    }
}

//! ns/sample of 2D and 3D Perlin and mNoise, in f32 and I16F16, over a 1024² grid.
//!
//! `cargo bench -p bandnoise-tests --bench lattice`; criterion reports the time per grid and the
//! throughput in samples/s (ns/sample = 1e9 / throughput). The grid spans 64 lattice cells per
//! side (1/16 cell per sample), with z fixed at 0.37 for 3D.

use bandnoise::prelude::*;
use criterion::{Criterion, Throughput, criterion_group, criterion_main};

const N: usize = 1024;
const STEP: f32 = 1.0 / 16.0;

/// Samples `noise` at `point(x, y)` over the 1024² grid.
fn grid<R: Real, const D: usize, No: Noise<R, D>>(noise: &No, point: impl Fn(R, R) -> [R; D]) -> R {
    bandnoise_tests::grid_sum(N, STEP, |x, y| noise.sample(point(x, y)))
}

fn grid2<R: Real, No: Noise<R, 2>>(noise: &No) -> R {
    grid(noise, |x, y| [x, y])
}

fn grid3<R: Real, No: Noise<R, 3>>(noise: &No) -> R {
    let z = R::from_f32(0.37);
    grid(noise, move |x, y| [x, y, z])
}

fn lattice(c: &mut Criterion) {
    let mut g = c.benchmark_group("grid-1024x1024");
    g.throughput(Throughput::Elements((N * N) as u64));
    g.sample_size(10);
    let perlin = Perlin::new(0);
    let mnoise = MNoise::<61>::new(0);
    g.bench_function("perlin-2d-f32", |b| b.iter(|| grid2::<f32, _>(&perlin)));
    g.bench_function("perlin-2d-i16f16", |b| {
        b.iter(|| grid2::<I16F16, _>(&perlin))
    });
    g.bench_function("perlin-3d-f32", |b| b.iter(|| grid3::<f32, _>(&perlin)));
    g.bench_function("perlin-3d-i16f16", |b| {
        b.iter(|| grid3::<I16F16, _>(&perlin))
    });
    g.bench_function("mnoise-2d-f32", |b| b.iter(|| grid2::<f32, _>(&mnoise)));
    g.bench_function("mnoise-2d-i16f16", |b| {
        b.iter(|| grid2::<I16F16, _>(&mnoise))
    });
    g.bench_function("mnoise-3d-f32", |b| b.iter(|| grid3::<f32, _>(&mnoise)));
    g.bench_function("mnoise-3d-i16f16", |b| {
        b.iter(|| grid3::<I16F16, _>(&mnoise))
    });
    g.finish();
}

criterion_group!(benches, lattice);
criterion_main!(benches);

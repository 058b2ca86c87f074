//! Checks every noise family's test runs the same way: fixed point against `f32`, the analytic
//! gradient against central differences, and the batch paths against `sample`, bit for bit.

use bandnoise::batch::Grid;
use bandnoise::{I16F16, Noise, NoiseGradient};

use crate::{Rng, to_f32};

/// The largest `|I16F16 − f32|` of `noise` over `n` random points of exact coordinates in
/// `(−range, range)^D` (both types see the same point).
pub fn fixed_vs_f32<N, const D: usize>(noise: &N, n: usize, range: i32, rng: &mut Rng) -> f32
where
    N: Noise<I16F16, D> + Noise<f32, D>,
{
    (0..n)
        .map(|_| {
            let p: [I16F16; D] = rng.exact_point(range);
            let q: I16F16 = noise.sample(p);
            let f: f32 = noise.sample(to_f32(p));
            (q.to_num::<f32>() - f).abs()
        })
        .fold(0.0, f32::max)
}

/// The largest difference between the analytic gradient of `noise` in `f64` and central
/// differences of step `h`, over `n` random points of `(−range, range)^D`, and the largest
/// gradient component seen (the scale to judge the difference against); asserts on the way
/// that the gradient's value is `sample`'s bit for bit in `f64`, `f32` and I16F16.
pub fn gradient_error<N, const D: usize>(
    noise: &N,
    n: usize,
    range: f64,
    h: f64,
    rng: &mut Rng,
) -> (f64, f64)
where
    N: NoiseGradient<f64, D> + NoiseGradient<f32, D> + NoiseGradient<I16F16, D>,
{
    let (mut worst, mut largest) = (0.0f64, 0.0f64);
    for _ in 0..n {
        let p: [f64; D] = core::array::from_fn(|_| rng.f64_in(-range, range));
        let (v, g) = noise.sample_with_gradient(p);
        assert_eq!(v.to_bits(), noise.sample(p).to_bits(), "f64 value at {p:?}");
        for a in 0..D {
            let (mut hi, mut lo) = (p, p);
            hi[a] += h;
            lo[a] -= h;
            let numeric = (noise.sample(hi) - noise.sample(lo)) / (2.0 * h);
            worst = worst.max((numeric - g[a]).abs());
            largest = largest.max(g[a].abs());
        }
        let f = p.map(|x| x as f32);
        assert_eq!(
            noise.sample_with_gradient(f).0.to_bits(),
            noise.sample(f).to_bits(),
            "f32 value at {f:?}"
        );
        let q = p.map(I16F16::from_num);
        assert_eq!(
            noise.sample_with_gradient(q).0,
            noise.sample(q),
            "I16F16 value at {q:?}"
        );
    }
    (worst, largest)
}

/// `fill_grid` over grids of several steps from a random origin (off the lattice), and
/// `fill_points` over scattered points, in `f32` and I16F16: each value is `sample`'s bit for
/// bit.
pub fn batches_match<N, const D: usize>(noise: &N, steps: &[f32], rng: &mut Rng)
where
    N: Noise<f32, D> + Noise<I16F16, D>,
{
    let size: [usize; D] = core::array::from_fn(|a| [37, 5, 3, 2][a]);
    let index = |i: usize| -> [usize; D] {
        let mut rest = i;
        core::array::from_fn(|a| {
            let k = rest % size[a];
            rest /= size[a];
            k
        })
    };
    for &step in steps {
        let origin: [f32; D] = core::array::from_fn(|_| rng.f64_in(-100.0, 100.0) as f32);
        let spacing: [f32; D] = core::array::from_fn(|a| step * [1.0, 0.7, 1.3, 0.9][a]);
        let grid = Grid::new(origin, spacing, size);
        let mut out = vec![0.0f32; grid.len()];
        noise.fill_grid(&grid, &mut out).unwrap();
        for (i, v) in out.iter().enumerate() {
            let p = grid.point(index(i));
            assert_eq!(v.to_bits(), noise.sample(p).to_bits(), "{step} {p:?}");
        }
        let q = |x: f32| I16F16::from_num(x);
        let grid = Grid::new(origin.map(q), spacing.map(q), size);
        let mut out = vec![I16F16::ZERO; grid.len()];
        noise.fill_grid(&grid, &mut out).unwrap();
        for (i, v) in out.iter().enumerate() {
            let p = grid.point(index(i));
            assert_eq!(*v, noise.sample(p), "{step} {p:?}");
        }
    }
    let axes: Vec<Vec<f32>> = (0..D)
        .map(|_| (0..100).map(|_| rng.f64_in(-1e3, 1e3) as f32).collect())
        .collect();
    let mut out = vec![0.0f32; 100];
    noise
        .fill_points(core::array::from_fn(|a| axes[a].as_slice()), &mut out)
        .unwrap();
    for (i, o) in out.iter().enumerate() {
        let v: f32 = noise.sample(core::array::from_fn(|a| axes[a][i]));
        assert_eq!(o.to_bits(), v.to_bits());
    }
}

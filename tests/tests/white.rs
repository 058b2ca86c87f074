//! Lattice white noise (Lewis 1989 §2.2) and its Catmull-Rom interpolant:
//!
//! * the tables: the Gaussian quantiles against `erfc`, the moments of both distributions;
//! * white noise: one value per cell, the table's entries equally likely, neighbours and seeds
//!   uncorrelated, the same bits in every number type;
//! * cubic value noise against an independent `f64` transcription of the Catmull-Rom tensor
//!   product (the textbook cubic `(−t³ + 2t² − t)/2, …` over the 4ᴰ lattice values), through the
//!   lattice values, C¹ across cell borders, within its bound (and the largest value seen),
//!   fixed point and `f32` against `f64`, gradients against central differences, batches;
//! * bad input.

use bandnoise::lattice::{CubicValueNoise, VALUES, WhiteNoise, table_value};
use bandnoise::wavelet::Distribution;

const DISTRIBUTIONS: [Distribution; 2] = [Distribution::Uniform, Distribution::Gaussian];
use bandnoise::{I16F16, Noise, NoiseGradient};
use bandnoise_tests::{BAD_F32, Rng, agree, correlation};

/// `Φ(x)`, the standard normal distribution function.
fn phi(x: f64) -> f64 {
    0.5 * libm::erfc(-x / core::f64::consts::SQRT_2)
}

#[test]
fn gaussian_table_holds_the_quantiles() {
    for k in 0..VALUES {
        let v = table_value(Distribution::Gaussian, k);
        let p = (k as f64 + 0.5) / VALUES as f64;
        // The quantile lies within half a step (2⁻¹³) of the stored value.
        let step = 0.5 / 4096.0;
        let (lo, hi) = (f64::from(v) / 4096.0 - step, f64::from(v) / 4096.0 + step);
        assert!(phi(lo) <= p && p <= phi(hi), "k {k}: {v} for p {p}");
    }
}

#[test]
fn tables_have_the_documented_moments() {
    for (d, variance, largest) in [
        (
            Distribution::Uniform,
            (1.0 - 1.0 / (VALUES * VALUES) as f64) / 3.0,
            1.0,
        ),
        (Distribution::Gaussian, 0.9987, 3.2964),
    ] {
        let t: Vec<f64> = (0..VALUES)
            .map(|k| f64::from(table_value(d, k)) / 4096.0)
            .collect();
        let mean = t.iter().sum::<f64>() / VALUES as f64;
        let var = t.iter().map(|v| v * v).sum::<f64>() / VALUES as f64;
        assert!(mean.abs() < 1e-12, "{d:?} mean {mean}");
        assert!((var - variance).abs() < 1e-4, "{d:?} variance {var}");
        let top = t.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        assert!((top - largest).abs() < 1e-3, "{d:?} largest {top}");
        assert_eq!(
            f64::from(WhiteNoise::new(0).with_distribution(d).largest()),
            top
        );
    }
}

#[test]
fn white_noise_is_one_uncorrelated_value_per_cell() {
    let mut rng = Rng::from_env(11);
    for d in DISTRIBUTIONS {
        let white = WhiteNoise::new(5).with_distribution(d);
        // One value across each cell, the cell's, in every number type.
        // Cells far out (f32 and f64), and within I16F16's range (every type).
        for i in 0..10_000 {
            let range = if i % 2 == 0 { 1 << 20 } else { 1 << 14 };
            let cell = [rng.i32_in(-range, range), rng.i32_in(-range, range)];
            let v: f64 = white.cell_value(cell);
            let inside = [0, 1].map(|a| f64::from(cell[a]) + rng.f64_in(0.0, 0.9)); // f32 rounds within the cell
            assert_eq!(white.sample(inside), v);
            assert_eq!(f64::from(white.sample(inside.map(|x| x as f32))), v);
            if cell.iter().all(|c| c.abs() < 1 << 15) {
                let q: I16F16 = white.sample(inside.map(I16F16::from_num));
                assert_eq!(q.to_num::<f64>(), v);
            }
        }
        // Each table entry equally likely: over 2²⁰ cells, a chi-square over the 1021 entries
        // (1020 degrees of freedom: mean 1020, sd 45; 1020 + 5 sd = 1246).
        let table: Vec<i16> = (0..VALUES).map(|k| table_value(d, k)).collect();
        let mut counts = vec![0u32; VALUES];
        let side = 1024;
        let mut grid = vec![0.0; side * side];
        for j in 0..side {
            for i in 0..side {
                let v: f64 = white.cell_value([i as i32 - 300, j as i32 + 77]);
                grid[j * side + i] = v;
                // The first entry holding this value (Gaussian tables repeat values rarely).
                let q = (v * 4096.0) as i16;
                counts[table.iter().position(|&t| t == q).unwrap()] += 1;
            }
        }
        if d == Distribution::Uniform {
            let expected = (side * side) as f64 / VALUES as f64;
            let chi2: f64 = counts
                .iter()
                .map(|&c| (f64::from(c) - expected).powi(2) / expected)
                .sum();
            assert!(chi2 < 1246.0, "{d:?}: chi-square {chi2}");
        }
        // Neighbours along each axis and diagonally: uncorrelated.
        for (di, dj) in [(1, 0), (0, 1), (1, 1)] {
            let (mut a, mut b) = (Vec::new(), Vec::new());
            for j in 0..side - 1 {
                for i in 0..side - 1 {
                    a.push(grid[j * side + i]);
                    b.push(grid[(j + dj) * side + i + di]);
                }
            }
            let r = correlation(&a, &b);
            assert!(r.abs() < 0.005, "{d:?} ({di}, {dj}): r = {r}");
        }
        // Seeds: uncorrelated.
        let other = WhiteNoise::new(6).with_distribution(d);
        let b: Vec<f64> = (0..side * side)
            .map(|k| other.cell_value([(k % side) as i32 - 300, (k / side) as i32 + 77]))
            .collect();
        let r = correlation(&grid, &b);
        assert!(r.abs() < 0.005, "{d:?} seeds: r = {r}");
    }
}

/// The textbook Catmull-Rom weights at `t` for the points −1, 0, 1, 2, and their derivatives.
fn catmull_rom(t: f64) -> ([f64; 4], [f64; 4]) {
    let (t2, t3) = (t * t, t * t * t);
    (
        [
            (-t3 + 2.0 * t2 - t) / 2.0,
            (3.0 * t3 - 5.0 * t2 + 2.0) / 2.0,
            (-3.0 * t3 + 4.0 * t2 + t) / 2.0,
            (t3 - t2) / 2.0,
        ],
        [
            (-3.0 * t2 + 4.0 * t - 1.0) / 2.0,
            (9.0 * t2 - 10.0 * t) / 2.0,
            (-9.0 * t2 + 8.0 * t + 1.0) / 2.0,
            (3.0 * t2 - 2.0 * t) / 2.0,
        ],
    )
}

/// The cubic interpolant at `p` and its gradient, from the lattice values by definition.
fn reference<const D: usize>(white: &WhiteNoise, p: [f64; D]) -> (f64, [f64; D]) {
    let cell = p.map(|x| x.floor());
    let weights: [([f64; 4], [f64; 4]); D] = core::array::from_fn(|a| catmull_rom(p[a] - cell[a]));
    let (mut value, mut gradient) = (0.0, [0.0; D]);
    for k in 0..4usize.pow(D as u32) {
        let digits: [usize; D] = core::array::from_fn(|a| (k >> (2 * a)) & 3);
        let lattice: [i32; D] = core::array::from_fn(|a| cell[a] as i32 + digits[a] as i32 - 1);
        let v: f64 = white.cell_value(lattice);
        let w: f64 = (0..D).map(|a| weights[a].0[digits[a]]).product();
        value += w * v;
        for (b, g) in gradient.iter_mut().enumerate() {
            let dw: f64 = (0..D)
                .map(|a| {
                    if a == b {
                        weights[a].1[digits[a]]
                    } else {
                        weights[a].0[digits[a]]
                    }
                })
                .product();
            *g += dw * v;
        }
    }
    (value, gradient)
}

fn check_against_reference<const D: usize>(n: usize, rng: &mut Rng) -> f64
where
    CubicValueNoise: NoiseGradient<f64, D> + Noise<f32, D>,
    WhiteNoise: Noise<f64, D>,
{
    let mut largest = 0.0f64;
    for d in DISTRIBUTIONS {
        for seed in [0, 1234] {
            let noise = CubicValueNoise::new(seed).with_distribution(d);
            let bound = f64::from(noise.amplitude_bound::<D>());
            for _ in 0..n {
                let p: [f64; D] = core::array::from_fn(|_| rng.f64_in(-1e4, 1e4));
                let (v, g) = noise.sample_with_gradient(p);
                let (rv, rg) = reference(&noise.lattice_values(), p);
                let scale = f64::from(noise.lattice_values().largest());
                assert!((v - rv).abs() < 1e-12 * scale, "{d:?} {p:?}: {v} vs {rv}");
                for a in 0..D {
                    assert!((g[a] - rg[a]).abs() < 1e-11 * scale, "{d:?} {p:?} axis {a}");
                }
                assert!(v.abs() <= bound, "{d:?} {p:?}: {v} over {bound}");
                if d == Distribution::Uniform {
                    largest = largest.max(v.abs());
                }
            }
        }
    }
    largest
}

#[test]
fn cubic_value_noise_is_the_catmull_rom_interpolant() {
    let mut rng = Rng::from_env(12);
    let l1 = check_against_reference::<1>(100_000, &mut rng);
    let l2 = check_against_reference::<2>(100_000, &mut rng);
    let l3 = check_against_reference::<3>(20_000, &mut rng);
    let l4 = check_against_reference::<4>(2_000, &mut rng);
    println!("largest |n| seen (uniform): 1D {l1:.4}, 2D {l2:.4}, 3D {l3:.4}, 4D {l4:.4}");
    // The overshoot is real (Catmull-Rom's negative lobes): past the lattice values' 1 − 1/N.
    assert!(l1 > 1.0 && l2 > 1.0, "{l1} {l2}");
}

#[test]
fn cubic_value_noise_passes_through_the_lattice_values_and_is_c1() {
    let mut rng = Rng::from_env(13);
    let noise = CubicValueNoise::new(9);
    let white = noise.lattice_values();
    for _ in 0..10_000 {
        let cell = [rng.i32_in(-30_000, 30_000), rng.i32_in(-30_000, 30_000)];
        let at = cell.map(f64::from);
        let v: f64 = white.cell_value(cell);
        assert_eq!(noise.sample(at), v);
        assert_eq!(f64::from(noise.sample(at.map(|x| x as f32))), v);
        let q: I16F16 = noise.sample(at.map(I16F16::from_num));
        assert_eq!(q.to_num::<f64>(), v);
        // Across the border x = cell[0]: value and gradient continuous.
        let y = at[1] + rng.f64_in(0.0, 1.0);
        let e = 1e-9;
        let (l, gl) = noise.sample_with_gradient([at[0] - e, y]);
        let (r, gr) = noise.sample_with_gradient([at[0] + e, y]);
        assert!((l - r).abs() < 1e-8, "{cell:?}: {l} vs {r}");
        assert!((gl[0] - gr[0]).abs() < 1e-7 && (gl[1] - gr[1]).abs() < 1e-7);
    }
}

#[test]
fn cubic_value_noise_in_fixed_point_and_f32_follows_f64() {
    let mut rng = Rng::from_env(14);
    fn worst<const D: usize>(noise: &CubicValueNoise, n: usize, rng: &mut Rng) -> (f64, f64)
    where
        CubicValueNoise: Noise<f64, D> + Noise<f32, D> + Noise<I16F16, D>,
    {
        let (mut fixed, mut single) = (0.0f64, 0.0f64);
        for _ in 0..n {
            let p: [I16F16; D] = rng.exact_point(200);
            let exact: f64 = noise.sample(p.map(|x| x.to_num::<f64>()));
            let q: I16F16 = noise.sample(p);
            let f: f32 = noise.sample(p.map(|x| x.to_num::<f32>()));
            fixed = fixed.max((q.to_num::<f64>() - exact).abs());
            single = single.max((f64::from(f) - exact).abs());
        }
        (fixed, single)
    }
    for d in DISTRIBUTIONS {
        let noise = CubicValueNoise::new(2).with_distribution(d);
        let e = [
            worst::<1>(&noise, 20_000, &mut rng),
            worst::<2>(&noise, 20_000, &mut rng),
            worst::<3>(&noise, 5_000, &mut rng),
            worst::<4>(&noise, 1_000, &mut rng),
        ];
        println!("{d:?}: |I16F16 − f64|, |f32 − f64| by dimension: {e:?}");
        for (fixed, single) in e {
            // Below 2⁻¹¹ (measured: 1.4e-4): the bound's rounding margin (2⁻⁷) holds with room.
            assert!(fixed < 1.0 / 2048.0, "{d:?}: fixed {fixed}");
            assert!(single < 2e-6, "{d:?}: f32 {single}");
        }
    }
}

#[test]
fn gradients_batches_and_bad_input() {
    let mut rng = Rng::from_env(15);
    let noise = CubicValueNoise::new(4);
    let (err, largest) = agree::gradient_error::<_, 2>(&noise, 2_000, 100.0, 1e-6, &mut rng);
    assert!(err < 1e-6 * largest.max(1.0), "2D: {err} of {largest}");
    let (err, largest) = agree::gradient_error::<_, 3>(&noise, 500, 100.0, 1e-6, &mut rng);
    assert!(err < 1e-6 * largest.max(1.0), "3D: {err} of {largest}");
    agree::batches_match::<_, 2>(&noise, &[0.0737, 1.3], &mut rng);
    agree::batches_match::<_, 3>(&noise, &[0.0737], &mut rng);
    let white = WhiteNoise::new(4).with_distribution(Distribution::Gaussian);
    agree::batches_match::<_, 2>(&white, &[0.0737, 1.3], &mut rng);
    for x in BAD_F32 {
        for p in [[x, 0.5], [0.5, x], [x, x]] {
            let v: f32 = noise.sample(p);
            assert!(
                v.is_finite() && v.abs() <= noise.amplitude_bound::<2>(),
                "{p:?}"
            );
            let (_, g) = noise.sample_with_gradient(p);
            assert!(g.iter().all(|d| d.is_finite()), "{p:?}");
            let w: f32 = white.sample(p);
            assert!(
                w.is_finite() && w.abs() <= white.amplitude_bound::<2>(),
                "{p:?}"
            );
        }
    }
    // Non-finite coordinates sample the origin.
    assert_eq!(
        noise.sample([f32::NAN, f32::NAN]),
        noise.sample([0.0f32, 0.0])
    );
    let q: I16F16 = noise.sample([I16F16::MAX, I16F16::MIN]);
    assert!(q.to_num::<f32>().abs() <= noise.amplitude_bound::<2>());
}

//! Sparse convolution noise (Lewis 1989, §4) measured as a user gets it: the default density,
//! weights and counts unless a test says otherwise, random points or grids whose step is not a
//! power-of-two fraction of a cell and whose origin is off the lattice.
//!
//! * variance 1 and mean 0 from Campbell's theorem (`λ E[w²] ∫h²`), over 10⁶ samples;
//! * the power spectrum is the kernel's `|H(f)|²/∫h²` (within 1 dB wherever it is above 1% of
//!   its peak), in 2D (a 2D FFT) and 3D (a 3D FFT);
//! * the amplitudes approach a Gaussian as the density grows (Kolmogorov–Smirnov distance);
//! * fixed point follows `f32`.

use bandnoise::impulse::{Kernel, SparseConvolution, Weights};
use bandnoise::{I16F16, Noise};
use bandnoise_tests::Rng;
use rustfft::{FftPlanner, num_complex::Complex};

const KERNELS: [Kernel; 2] = [Kernel::Cosine, Kernel::CatmullRom];

/// `n` samples at uniformly random points of `[−4096, 4096)^D` (so almost surely more than two
/// kernel radii apart: independent).
fn samples<const D: usize>(noise: &SparseConvolution<D>, n: usize, rng: &mut Rng) -> Vec<f64>
where
    SparseConvolution<D>: Noise<f32, D>,
{
    (0..n)
        .map(|_| noise.sample(core::array::from_fn(|_| rng.f64_in(-4096.0, 4096.0) as f32)) as f64)
        .collect()
}

fn mean_variance(v: &[f64]) -> (f64, f64) {
    let mean = v.iter().sum::<f64>() / v.len() as f64;
    let var = v.iter().map(|x| (x - mean) * (x - mean)).sum::<f64>() / v.len() as f64;
    (mean, var)
}

/// The Kolmogorov–Smirnov distance between the samples and N(0, 1).
fn ks_to_normal(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    let n = v.len() as f64;
    v.iter()
        .enumerate()
        .map(|(i, &x)| {
            let cdf = 0.5 * (1.0 + libm::erf(x / std::f64::consts::SQRT_2));
            (cdf - i as f64 / n)
                .abs()
                .max((cdf - (i + 1) as f64 / n).abs())
        })
        .fold(0.0, f64::max)
}

fn variance_case<const D: usize>(noise: SparseConvolution<D>, label: &str, rng: &mut Rng)
where
    SparseConvolution<D>: Noise<f32, D>,
{
    let (mean, var) = mean_variance(&samples(&noise, 1_000_000, rng));
    println!(
        "{D}D {label:<38} density {:>5.2}: mean {mean:+.4}, variance {var:.4}",
        noise.density()
    );
    assert!(
        (var - 1.0).abs() <= 0.02 && mean.abs() <= 0.01,
        "{D}D {label}: mean {mean}, variance {var}"
    );
}

/// Variance 1 ± 0.02 and mean 0 ± 0.01 over 10⁶ samples, from Campbell's theorem alone: for
/// both kernels, the default density and a sparse one, and the fixed-count, sign-weighted
/// process (whose variance the same formula gives).
#[test]
fn variance_one_and_mean_zero_from_campbell() {
    let mut rng = Rng::from_env(18);
    for kernel in KERNELS {
        for density in [1.0, SparseConvolution::<2>::DEFAULT_DENSITY] {
            let two = SparseConvolution::<2>::new(5).with_kernel(kernel);
            let two = two.with_density(density).unwrap();
            variance_case(two, &format!("{kernel:?}"), &mut rng);
            let three = SparseConvolution::<3>::new(5).with_kernel(kernel);
            let three = three.with_density(density).unwrap();
            variance_case(three, &format!("{kernel:?}"), &mut rng);
        }
        let fixed = SparseConvolution::<3>::new(9)
            .with_kernel(kernel)
            .with_fixed_count(3)
            .unwrap()
            .with_weights(Weights::Sign);
        variance_case(
            fixed,
            &format!("{kernel:?}, 3 per cell, ±1 weights"),
            &mut rng,
        );
    }
}

/// Lewis: at ten impulses per kernel and above the noise is "usually not distinguishable" from
/// convolved white noise. The KS distance of the amplitudes to N(0, 1) at 1, 3, 10 and 30
/// impulses per kernel (2·10⁵ independent samples each: the distance's own noise is about
/// 0.002), at most 0.02 from 10 on for Lewis's kernel with the default (±1) weights. (With
/// uniform weights, 3D at 10 is 0.024: why ±1 is the default.)
#[test]
fn amplitudes_become_gaussian_with_density() {
    let mut rng = Rng::from_env(19);
    for kernel in KERNELS {
        for weights in [Weights::Uniform, Weights::Sign] {
            let mut row2 = Vec::new();
            let mut row3 = Vec::new();
            for density in [1.0, 3.0, 10.0, 30.0] {
                let two = SparseConvolution::<2>::new(3)
                    .with_kernel(kernel)
                    .with_weights(weights)
                    .with_density(density)
                    .unwrap();
                let three = SparseConvolution::<3>::new(3)
                    .with_kernel(kernel)
                    .with_weights(weights)
                    .with_density(density)
                    .unwrap();
                let ks2 = ks_to_normal(samples(&two, 200_000, &mut rng));
                let ks3 = ks_to_normal(samples(&three, 200_000, &mut rng));
                row2.push(ks2);
                row3.push(ks3);
                if kernel == Kernel::Cosine && weights == Weights::default() && density >= 10.0 {
                    assert!(
                        ks2 <= 0.02 && ks3 <= 0.02,
                        "{weights:?} {density}: {ks2} {ks3}"
                    );
                }
            }
            println!(
                "KS at 1, 3, 10, 30 per kernel, {kernel:?}, {weights:?}: 2D {row2:.4?}, 3D {row3:.4?}"
            );
        }
    }
}

/// The kernel's Fourier transform at `q` cycles per unit: the Hankel transform
/// `2π ∫ h(r) J₀(2πqr) r dr` in 2D, `4π ∫ h(r) sinc(2πqr) r² dr` in 3D.
fn kernel_transform(kernel: Kernel, d: usize, q: f64) -> f64 {
    let n = 4000;
    let tau = 2.0 * std::f64::consts::PI;
    (0..n)
        .map(|i| {
            let r = (i as f64 + 0.5) / n as f64;
            let h = kernel.exact(r * r).0;
            let x = tau * q * r;
            if d == 2 {
                tau * h * libm::j0(x) * r
            } else {
                let sinc = if x == 0.0 { 1.0 } else { x.sin() / x };
                2.0 * tau * h * sinc * r * r
            }
        })
        .sum::<f64>()
        / n as f64
}

/// A `side^D` grid's periodogram under a separable Hann window, as the spectral density of
/// the field (variance = ∫ S): `S(f) ≈ |F|² Δ^D / Σ w²`.
fn spectral_density(grid: &[f64], side: usize, d: usize, spacing: f64) -> Vec<f64> {
    let mean = grid.iter().sum::<f64>() / grid.len() as f64;
    let window: Vec<f64> = (0..side)
        .map(|i| {
            let t = std::f64::consts::PI * (i as f64 + 0.5) / side as f64;
            t.sin() * t.sin()
        })
        .collect();
    let weight = |i: usize| {
        (0..d)
            .map(|a| window[(i / side.pow(a as u32)) % side])
            .product::<f64>()
    };
    let mut data: Vec<Complex<f64>> = grid
        .iter()
        .enumerate()
        .map(|(i, &v)| Complex::new((v - mean) * weight(i), 0.0))
        .collect();
    let fft = FftPlanner::<f64>::new().plan_fft_forward(side);
    let mut line = vec![Complex::new(0.0, 0.0); side];
    for a in 0..d {
        let stride = side.pow(a as u32);
        for start in 0..grid.len() {
            // Each line along axis a once: its first element has coordinate 0 along a.
            if !(start / stride).is_multiple_of(side) {
                continue;
            }
            for (k, l) in line.iter_mut().enumerate() {
                *l = data[start + k * stride];
            }
            fft.process(&mut line);
            for (k, l) in line.iter().enumerate() {
                data[start + k * stride] = *l;
            }
        }
    }
    let sum_w2: f64 = (0..grid.len()).map(|i| weight(i).powi(2)).sum();
    data.iter()
        .map(|c| c.norm_sqr() * spacing.powi(d as i32) / sum_w2)
        .collect()
}

/// The radially averaged spectral density in rings `ring` cycles per unit wide, against the
/// kernel's `|H(f)|²/∫h²` (the spectrum of the normalised noise, by Parseval variance 1).
/// Returns the largest difference in dB over the rings where the analytic density is above
/// 1% of its peak, and prints both.
fn compare_spectrum(
    kernel: Kernel,
    d: usize,
    density: &[f64],
    side: usize,
    spacing: f64,
    ring: f64,
) -> f64 {
    let bin = 1.0 / (side as f64 * spacing);
    let rings = (0.5 / spacing / ring) as usize;
    // |H(f)|²/∫h² on a fine table of frequencies, read at each bin's frequency, so each ring
    // compares the same bins' averages.
    let power = Kernel::power(kernel, d);
    let step = 0.002;
    let analytic: Vec<f64> = (0..=(rings as f64 * ring / step) as usize + 1)
        .map(|i| kernel_transform(kernel, d, i as f64 * step).powi(2) / power)
        .collect();
    let peak = analytic.iter().copied().fold(0.0, f64::max);
    let (mut got, mut want, mut count) = (vec![0.0; rings], vec![0.0; rings], vec![0usize; rings]);
    for (i, &s) in density.iter().enumerate() {
        let mut f2 = 0.0;
        for a in 0..d {
            let k = (i / side.pow(a as u32)) % side;
            let k = if k > side / 2 {
                k as f64 - side as f64
            } else {
                k as f64
            };
            f2 += (k * bin).powi(2);
        }
        let f = f2.sqrt();
        // The lowest bins hold what the mean's removal and the window leave of the mean.
        if f < 2.5 * bin {
            continue;
        }
        let r = (f / ring) as usize;
        if r < rings {
            let t = f / step;
            let j = t as usize;
            let a = analytic[j] + (analytic[j + 1] - analytic[j]) * (t - j as f64);
            got[r] += s;
            want[r] += a;
            count[r] += 1;
        }
    }
    let mut worst = 0.0f64;
    for r in 0..rings {
        if count[r] == 0 || want[r] / (count[r] as f64) < 0.01 * peak {
            continue;
        }
        let (g, w) = (got[r] / count[r] as f64, want[r] / count[r] as f64);
        let db = 10.0 * (g / w).log10();
        println!(
            "{d}D {kernel:?} f {:.3}: measured {g:.5}, |H|²/∫h² {w:.5} ({db:+.2} dB, {} bins)",
            (r as f64 + 0.5) * ring,
            count[r]
        );
        worst = worst.max(db.abs());
    }
    worst
}

/// The radially averaged power spectrum follows the kernel's: within 1 dB wherever the
/// analytic spectrum is above 1% of its peak. 2D: 16 grids of 512² (seeds 0–15), step 0.0937
/// units; 3D: 3 grids of 128³, step 0.1937 (Nyquist 2.6 cycles per unit, where the kernels'
/// spectra are below 10⁻⁵ of their peak). Neither step is a power-of-two fraction of a cell,
/// and the grids' origins are off the lattice.
#[test]
fn spectrum_is_the_kernels() {
    for kernel in KERNELS {
        let spacing = 0.0937;
        // 2D.
        let side = 512;
        let mut mean_density = vec![0.0; side * side];
        let seeds = 16;
        for seed in 0..seeds {
            let noise = SparseConvolution::<2>::new(seed).with_kernel(kernel);
            let grid: Vec<f64> = (0..side * side)
                .map(|i| {
                    let p = [
                        0.31 + (i % side) as f32 * spacing as f32,
                        -7.77 + (i / side) as f32 * spacing as f32,
                    ];
                    noise.sample(p) as f64
                })
                .collect();
            for (m, s) in mean_density
                .iter_mut()
                .zip(spectral_density(&grid, side, 2, spacing))
            {
                *m += s / seeds as f64;
            }
        }
        let worst = compare_spectrum(kernel, 2, &mean_density, side, spacing, 0.05);
        assert!(worst <= 1.0, "2D {kernel:?}: {worst} dB");

        // 3D.
        let (side, spacing) = (128, 0.1937);
        let mut mean_density = vec![0.0; side * side * side];
        let seeds = 3;
        for seed in 0..seeds {
            let noise = SparseConvolution::<3>::new(seed).with_kernel(kernel);
            let grid: Vec<f64> = (0..side * side * side)
                .map(|i| {
                    let p = [
                        0.31 + (i % side) as f32 * spacing as f32,
                        -7.77 + (i / side % side) as f32 * spacing as f32,
                        2.05 + (i / side / side) as f32 * spacing as f32,
                    ];
                    noise.sample(p) as f64
                })
                .collect();
            for (m, s) in mean_density
                .iter_mut()
                .zip(spectral_density(&grid, side, 3, spacing))
            {
                *m += s / seeds as f64;
            }
        }
        let worst = compare_spectrum(kernel, 3, &mean_density, side, spacing, 0.05);
        assert!(worst <= 1.0, "3D {kernel:?}: {worst} dB");
    }
}

/// Fixed point follows `f32` (both kernels, 2D and 3D, random points): the largest
/// difference, printed, is below 2e-3 (the kernels' I16F16 error, 1e-4, over the impulses
/// within reach, times the scale).
#[test]
fn fixed_point_follows_f32() {
    let mut rng = Rng::from_env(20);
    for kernel in KERNELS {
        let two = SparseConvolution::<2>::new(1).with_kernel(kernel);
        let three = SparseConvolution::<3>::new(1).with_kernel(kernel);
        let (mut w2, mut w3) = (0.0f32, 0.0f32);
        for _ in 0..20_000 {
            let p: [I16F16; 3] = rng.exact_point(200);
            let f = bandnoise_tests::to_f32(p);
            let q2: I16F16 = two.sample([p[0], p[1]]);
            let f2: f32 = two.sample([f[0], f[1]]);
            w2 = w2.max((q2.to_num::<f32>() - f2).abs());
            let q3: I16F16 = three.sample(p);
            let f3: f32 = three.sample(f);
            w3 = w3.max((q3.to_num::<f32>() - f3).abs());
        }
        println!("{kernel:?}: |I16F16 − f32| ≤ {w2:.1e} (2D), {w3:.1e} (3D)");
        assert!(w2 < 2e-3 && w3 < 2e-3, "{kernel:?} {w2} {w3}");
    }
}

/// The analytic gradient is the derivative (central differences in `f64`, 2D and 3D, both
/// kernels), and its value is `sample`'s bit for bit in every number type.
#[test]
fn gradient_is_the_derivative() {
    use bandnoise::NoiseGradient;
    let mut rng = Rng::from_env(21);
    for kernel in KERNELS {
        let noise = SparseConvolution::<3>::new(4).with_kernel(kernel);
        let two = SparseConvolution::<2>::new(4).with_kernel(kernel);
        let mut worst = 0.0f64;
        for _ in 0..2000 {
            let p: [f64; 3] = core::array::from_fn(|_| rng.f64_in(-50.0, 50.0));
            let (v, g) = noise.sample_with_gradient(p);
            assert_eq!(v.to_bits(), noise.sample(p).to_bits());
            let h = 1e-6;
            for a in 0..3 {
                let (mut hi, mut lo) = (p, p);
                hi[a] += h;
                lo[a] -= h;
                let numeric = (noise.sample(hi) - noise.sample(lo)) / (2.0 * h);
                worst = worst.max((numeric - g[a]).abs());
            }
            let q: [I16F16; 2] = [I16F16::from_num(p[0]), I16F16::from_num(p[1])];
            assert_eq!(two.sample_with_gradient(q).0, two.sample(q));
            let f = [p[0] as f32, p[1] as f32];
            assert_eq!(
                two.sample_with_gradient(f).0.to_bits(),
                two.sample(f).to_bits()
            );
        }
        println!("{kernel:?}: |analytic − numeric gradient| ≤ {worst:.1e}");
        assert!(worst < 1e-6, "{kernel:?}: {worst}");
    }
}

/// The batch paths are `sample` bit for bit: grids of several steps (chunks within one or two
/// cells per axis share their cells' impulses) and scattered points (walked one by one), both
/// kernels, Poisson and fixed counts, both weights, f32 and I16F16.
#[test]
fn batches_are_sample_bit_for_bit() {
    use bandnoise::batch::Grid;
    let configs = |seed| {
        let base = SparseConvolution::<3>::new(seed);
        [
            base.clone(),
            base.clone()
                .with_kernel(Kernel::CatmullRom)
                .with_density(3.0)
                .unwrap(),
            base.clone()
                .with_fixed_count(2)
                .unwrap()
                .with_weights(Weights::Uniform),
        ]
    };
    let mut rng = Rng::from_env(22);
    for noise in configs(3) {
        for step in [0.0737f32, 0.01, 0.3, 1.7] {
            let origin = [rng.f64_in(-100.0, 100.0) as f32, -5.683, 0.37];
            let grid = Grid::new(origin, [step, step * 0.7, step], [37, 5, 3]);
            let mut out = vec![0.0f32; grid.len()];
            noise.fill_grid(&grid, &mut out).unwrap();
            for (i, v) in out.iter().enumerate() {
                let p = grid.point([i % 37, i / 37 % 5, i / 185]);
                assert_eq!(v.to_bits(), noise.sample(p).to_bits(), "{step} {p:?}");
            }
            let q = |x: f32| I16F16::from_num(x);
            let grid = Grid::new(origin.map(q), [q(step), q(step * 0.7), q(step)], [37, 5, 3]);
            let mut out = vec![I16F16::ZERO; grid.len()];
            noise.fill_grid(&grid, &mut out).unwrap();
            for (i, v) in out.iter().enumerate() {
                let p = grid.point([i % 37, i / 37 % 5, i / 185]);
                assert_eq!(*v, noise.sample(p), "{step} {p:?}");
            }
        }
        let xs: Vec<f32> = (0..100).map(|_| rng.f64_in(-1e3, 1e3) as f32).collect();
        let ys: Vec<f32> = (0..100).map(|_| rng.f64_in(-1e3, 1e3) as f32).collect();
        let zs: Vec<f32> = (0..100).map(|_| rng.f64_in(-1.0, 1.0) as f32).collect();
        let mut out = vec![0.0f32; 100];
        noise.fill_points([&xs, &ys, &zs], &mut out).unwrap();
        for i in 0..100 {
            let v: f32 = noise.sample([xs[i], ys[i], zs[i]]);
            assert_eq!(out[i].to_bits(), v.to_bits());
        }
    }
    // 2D, the default.
    let noise = SparseConvolution::<2>::new(8);
    let grid = Grid::new([3.217f32, -5.683], [0.0737, 0.0737], [64, 8]);
    let mut out = vec![0.0f32; grid.len()];
    noise.fill_grid(&grid, &mut out).unwrap();
    for (i, v) in out.iter().enumerate() {
        let p = grid.point([i % 64, i / 64]);
        assert_eq!(v.to_bits(), noise.sample(p).to_bits(), "{p:?}");
    }
}

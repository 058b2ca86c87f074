//! Sparse convolution noise (Lewis 1989, §4) measured as a user gets it: the default density,
//! weights and counts unless a test says otherwise, random points or grids whose step is not a
//! power-of-two fraction of a cell and whose origin is off the lattice.
//!
//! * variance 1 and mean 0 from Campbell's theorem (`λ E[w²] ∫h²`), over 10⁶ samples;
//! * the power spectrum is the kernel's `|H(f)|²/∫h²` (within 1 dB wherever it is above 1% of
//!   its peak), in 2D (a 2D FFT) and 3D (a 3D FFT);
//! * the amplitudes approach a Gaussian as the density grows (Kolmogorov–Smirnov distance);
//! * fixed point follows `f32`.

use bandnoise::Noise;
use bandnoise::impulse::{Kernel, SparseConvolution, Weights};
use bandnoise_tests::Rng;
use bandnoise_tests::agree;
use bandnoise_tests::spectral::{
    self, ks_to_normal, mean_variance, radial_transform, spectral_density,
};

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

/// The spectrum of the normalised noise: the kernel's `|H(f)|²/∫h²` (by Parseval, variance
/// 1), compared ring by ring within 1 dB wherever it is above 1% of its peak.
fn compare_spectrum(kernel: Kernel, d: usize, density: &[f64], side: usize, spacing: f64) -> f64 {
    let power = kernel.power(d);
    spectral::compare_spectrum(
        &format!("{d}D {kernel:?}"),
        d,
        density,
        (side, spacing, 0.05),
        |q| radial_transform(d, 1.0, |r| kernel.exact(r * r).0, q).powi(2) / power,
        None,
    )
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
        let worst = compare_spectrum(kernel, 2, &mean_density, side, spacing);
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
        let worst = compare_spectrum(kernel, 3, &mean_density, side, spacing);
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
        let w2 = agree::fixed_vs_f32(&two, 20_000, 200, &mut rng);
        let w3 = agree::fixed_vs_f32(&three, 20_000, 200, &mut rng);
        println!("{kernel:?}: |I16F16 − f32| ≤ {w2:.1e} (2D), {w3:.1e} (3D)");
        assert!(w2 < 2e-3 && w3 < 2e-3, "{kernel:?} {w2} {w3}");
    }
}

/// The analytic gradient is the derivative (central differences in `f64`, 2D and 3D, both
/// kernels), and its value is `sample`'s bit for bit in every number type.
#[test]
fn gradient_is_the_derivative() {
    let mut rng = Rng::from_env(21);
    for kernel in KERNELS {
        let three = SparseConvolution::<3>::new(4).with_kernel(kernel);
        let two = SparseConvolution::<2>::new(4).with_kernel(kernel);
        let (w3, _) = agree::gradient_error(&three, 2000, 50.0, 1e-6, &mut rng);
        let (w2, _) = agree::gradient_error(&two, 2000, 50.0, 1e-6, &mut rng);
        let worst = w2.max(w3);
        println!("{kernel:?}: |analytic − numeric gradient| ≤ {worst:.1e}");
        assert!(worst < 1e-6, "{kernel:?}: {worst}");
    }
}

/// The batch paths are `sample` bit for bit: grids of several steps (chunks within one or two
/// cells per axis share their cells' impulses) and scattered points (walked one by one), both
/// kernels, Poisson and fixed counts, both weights, f32 and I16F16.
#[test]
fn batches_are_sample_bit_for_bit() {
    let mut rng = Rng::from_env(22);
    let base = SparseConvolution::<3>::new(3);
    let configs = [
        base.clone(),
        base.clone()
            .with_kernel(Kernel::CatmullRom)
            .with_density(3.0)
            .unwrap(),
        base.with_fixed_count(2)
            .unwrap()
            .with_weights(Weights::Uniform),
    ];
    for noise in &configs {
        agree::batches_match(noise, &[0.0737, 0.01, 0.3, 1.7], &mut rng);
    }
    // 2D, the default.
    agree::batches_match(&SparseConvolution::<2>::new(8), &[0.0737], &mut rng);
}

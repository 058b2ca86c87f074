//! The survey's §6 analysis of a noise image (Lagae et al. 2010, "A Survey of Procedural
//! Noise Functions", §6): the periodogram averaged over blocks (Bartlett's method), its radial
//! average (power against frequency), and the histogram of standardised values against the
//! standard normal density.
//!
//! A package of its own, beside the `bandnoise` command (`cli/`), so that the test profile
//! can build the command unoptimised while the statistical tests' spectra
//! (`bandnoise-tests`) keep an optimised transform.

use std::f64::consts::PI;

/// The 2D power spectrum `|F(kx, ky)|²` of a `side × side` grid (row by row; `side` any
/// size rustfft plans for), by rows then columns: the one 2D transform of the host code (the
/// analysis here, and the statistical tests through `bandnoise-tests`; the browser demo keeps
/// its own `f32` transform without `sin`/`cos` for its size budget).
pub fn power(grid: &[f64], side: usize) -> Vec<f64> {
    use rustfft::{FftPlanner, num_complex::Complex};
    let fft = FftPlanner::<f64>::new().plan_fft_forward(side);
    let mut data: Vec<Complex<f64>> = grid.iter().map(|&v| Complex::new(v, 0.0)).collect();
    for row in data.chunks_mut(side) {
        fft.process(row);
    }
    let mut column = vec![Complex::new(0.0, 0.0); side];
    for x in 0..side {
        for y in 0..side {
            column[y] = data[y * side + x];
        }
        fft.process(&mut column);
        for y in 0..side {
            data[y * side + x] = column[y];
        }
    }
    data.iter().map(|c| c.norm_sqr()).collect()
}

/// The values' mean and (population) standard deviation.
pub fn mean_and_std_dev(values: &[f32]) -> (f64, f64) {
    let n = values.len() as f64;
    let mean = values.iter().map(|&v| f64::from(v)).sum::<f64>() / n;
    let variance = values
        .iter()
        .map(|&v| (f64::from(v) - mean).powi(2))
        .sum::<f64>()
        / n;
    (mean, variance.sqrt())
}

/// What [`analyse`] finds.
pub struct Analysis {
    /// The values' mean and standard deviation.
    pub mean: f64,
    pub std_dev: f64,
    /// The Bartlett-averaged periodogram, `block × block`, DC in the centre, `|F|²/B²` per
    /// block (so white noise of variance σ² is flat at σ²).
    pub periodogram: Vec<f64>,
    pub block: usize,
    /// The radially averaged power: `(frequency in cycles per unit, mean power)` for each ring
    /// of one frequency step, from the first ring past DC to the Nyquist frequency.
    pub spectrum: Vec<(f64, f64)>,
    /// The histogram of standardised values: `(bin centre z, density, N(0, 1) density at z)`
    /// over `[-4, 4]`; values outside are counted in `outside`.
    pub histogram: Vec<(f64, f64, f64)>,
    pub outside: usize,
}

/// The analysis of a `side × side` image (row-major) sampled every `step` units, with the
/// periodogram averaged over the `(side / block)²` blocks of `block × block`.
pub fn analyse(values: &[f32], side: usize, step: f64, block: usize, bins: usize) -> Analysis {
    let n = values.len() as f64;
    let (mean, std_dev) = mean_and_std_dev(values);
    // Bartlett: the mean of the blocks' periodograms, each block's mean removed.
    let mut periodogram = vec![0.0; block * block];
    let blocks = side / block;
    for by in 0..blocks {
        for bx in 0..blocks {
            let mut b: Vec<f64> = (0..block * block)
                .map(|i| {
                    f64::from(values[(by * block + i / block) * side + bx * block + i % block])
                })
                .collect();
            let m = b.iter().sum::<f64>() / b.len() as f64;
            b.iter_mut().for_each(|v| *v -= m);
            for (acc, p) in periodogram.iter_mut().zip(power(&b, block)) {
                *acc += p;
            }
        }
    }
    let scale = 1.0 / ((blocks * blocks) as f64 * (block * block) as f64);
    // Centre DC: swap quadrants.
    let mut centred = vec![0.0; block * block];
    let h = block / 2;
    for y in 0..block {
        for x in 0..block {
            centred[((y + h) % block) * block + (x + h) % block] =
                periodogram[y * block + x] * scale;
        }
    }
    // Radial average over rings of one frequency step, 1/(block · step) cycles per unit.
    let df = 1.0 / (block as f64 * step);
    let mut rings = vec![(0.0f64, 0usize); h + 1];
    for y in 0..block {
        for x in 0..block {
            let (fx, fy) = (x as f64 - h as f64, y as f64 - h as f64);
            let r = (fx * fx + fy * fy).sqrt().round() as usize;
            if (1..=h).contains(&r) {
                rings[r].0 += centred[y * block + x];
                rings[r].1 += 1;
            }
        }
    }
    let spectrum = rings
        .iter()
        .enumerate()
        .skip(1)
        .map(|(r, (sum, count))| (r as f64 * df, sum / (*count).max(1) as f64))
        .collect();
    // Histogram of z = (v − mean)/σ over [-4, 4].
    let width = 8.0 / bins as f64;
    let mut counts = vec![0usize; bins];
    let mut outside = 0;
    for &v in values {
        let z = if std_dev > 0.0 {
            (f64::from(v) - mean) / std_dev
        } else {
            0.0
        };
        let bin = ((z + 4.0) / width).floor();
        if (0.0..bins as f64).contains(&bin) {
            counts[bin as usize] += 1;
        } else {
            outside += 1;
        }
    }
    let histogram = counts
        .iter()
        .enumerate()
        .map(|(i, &c)| {
            let z = -4.0 + (i as f64 + 0.5) * width;
            let normal = (-z * z / 2.0).exp() / (2.0 * PI).sqrt();
            (z, c as f64 / (n * width), normal)
        })
        .collect();
    Analysis {
        mean,
        std_dev,
        periodogram: centred,
        block,
        spectrum,
        histogram,
        outside,
    }
}

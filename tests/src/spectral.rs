//! Statistics the noise tests share: moments, the distance to a Gaussian, the spectral density
//! of a grid in any dimension, and radial Fourier transforms to compare it with.

use rustfft::{FftPlanner, num_complex::Complex};

/// The mean and the variance of `v`.
pub fn mean_variance(v: &[f64]) -> (f64, f64) {
    let mean = v.iter().sum::<f64>() / v.len() as f64;
    let var = v.iter().map(|x| (x - mean) * (x - mean)).sum::<f64>() / v.len() as f64;
    (mean, var)
}

/// The Kolmogorov–Smirnov distance between the samples and N(0, 1).
pub fn ks_to_normal(mut v: Vec<f64>) -> f64 {
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

/// The `d`-dimensional Fourier transform at `q` cycles per unit of the radial function `h`
/// of support `radius`, by the midpoint rule over the radius: `2 ∫ h cos(2πqr) dr` in 1D,
/// `2π ∫ h(r) J₀(2πqr) r dr` in 2D, `4π ∫ h(r) sinc(2πqr) r² dr` in 3D,
/// `(2π/q) ∫ h(r) J₁(2πqr) r² dr` in 4D.
pub fn radial_transform(d: usize, radius: f64, h: impl Fn(f64) -> f64, q: f64) -> f64 {
    let n = 4000;
    let tau = 2.0 * std::f64::consts::PI;
    (0..n)
        .map(|i| {
            let r = radius * (i as f64 + 0.5) / n as f64;
            let x = tau * q * r;
            radius / n as f64
                * h(r)
                * match d {
                    1 => 2.0 * x.cos(),
                    2 => tau * libm::j0(x) * r,
                    3 => {
                        let sinc = if x == 0.0 { 1.0 } else { x.sin() / x };
                        2.0 * tau * sinc * r * r
                    }
                    _ => {
                        // J₁(x)/x → ½ at 0.
                        let j = if x == 0.0 { 0.5 } else { libm::j1(x) / x };
                        tau * tau * j * r * r * r
                    }
                }
        })
        .sum::<f64>()
}

/// A `side^D` grid's periodogram under a separable Hann window, as the spectral density of
/// the field (variance = ∫ S): `S(f) ≈ |F|² Δ^D / Σ w²`.
pub fn spectral_density(grid: &[f64], side: usize, d: usize, spacing: f64) -> Vec<f64> {
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

/// The radially averaged spectral density `density` of a `side^d` grid (from
/// [`spectral_density`]) in rings `ring` cycles per unit wide, against `analytic(f)`, the
/// spectral density expected at `f` cycles per unit. Prints both per ring (labelled `label`,
/// with `shown(f)` beside them: another spectrum to compare by eye, such as a requested one)
/// and returns the largest difference in dB over the rings where the analytic density is
/// above 1% of its peak.
pub fn compare_spectrum(
    label: &str,
    d: usize,
    density: &[f64],
    (side, spacing, ring): (usize, f64, f64),
    analytic: impl Fn(f64) -> f64,
    shown: Option<(&str, &dyn Fn(f64) -> f64)>,
) -> f64 {
    let bin = 1.0 / (side as f64 * spacing);
    let rings = (0.5 / spacing / ring) as usize;
    // The analytic density on a fine table of frequencies, read at each bin's frequency, so
    // each ring compares the same bins' averages.
    let step = 0.002;
    let table: Vec<f64> = (0..=(rings as f64 * ring / step) as usize + 1)
        .map(|i| analytic(i as f64 * step))
        .collect();
    let peak = table.iter().copied().fold(0.0, f64::max);
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
            let a = table[j] + (table[j + 1] - table[j]) * (t - j as f64);
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
        let f = (r as f64 + 0.5) * ring;
        let (g, w) = (got[r] / count[r] as f64, want[r] / count[r] as f64);
        let db = 10.0 * (g / w).log10();
        let extra = shown.map_or(String::new(), |(name, s)| format!(", {name} {:.5}", s(f)));
        println!(
            "{label} f {f:.3}: measured {g:.5}, expected {w:.5} ({db:+.2} dB, {} bins){extra}",
            count[r]
        );
        worst = worst.max(db.abs());
    }
    worst
}

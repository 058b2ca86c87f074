//! Wavelet noise filtered by the sample's footprint (Cook & DeRose 2005, §3.1, §4.1): one
//! sample per pixel through `sample_filtered` against a supersampled, box-filtered reference.

use bandnoise::batch::Grid;
use bandnoise::prelude::*;
use bandnoise::wavelet::{TILE2_I16, TILE3_I16, Tile2};

/// Pixels per side.
const SIDE: usize = 512;
/// Supersamples per pixel and axis.
const SUPER: usize = 16;
/// Bands −1 to 8.
const BANDS: usize = 10;
/// The distance between pixel centres: band `b` has `2^(b+1) · SPACING` coefficients per pixel
/// (from 0.017 for band −1 to 8.6 for band 8), not a power of two.
const SPACING: f32 = 1.0 / (64.0 * 0.93);
/// The image's corner, off the lattice.
const ORIGIN: [f32; 2] = [3.217, -5.683];

/// A pixel's centre.
fn centre(i: usize, j: usize) -> [f32; 2] {
    [
        ORIGIN[0] + (i as f32 + 0.5) * SPACING,
        ORIGIN[1] + (j as f32 + 0.5) * SPACING,
    ]
}

/// The pixels of `noise` averaged over `SUPER²` supersamples each (the centres of a regular
/// grid of sub-pixels): a box filter.
fn reference(noise: &Multiband<'_, Tile2<64>>) -> Vec<f64> {
    let sub = SPACING / SUPER as f32;
    let mut out = vec![0.0f64; SIDE * SIDE];
    let mut fine = vec![0.0f32; SIDE * SUPER * SUPER];
    for j in 0..SIDE {
        let grid = Grid {
            origin: [
                ORIGIN[0] + 0.5 * sub,
                ORIGIN[1] + j as f32 * SPACING + 0.5 * sub,
            ],
            step: [sub, sub],
            size: [SIDE * SUPER, SUPER],
        };
        noise.fill_grid(&grid, &mut fine).unwrap();
        for (i, o) in out[j * SIDE..][..SIDE].iter_mut().enumerate() {
            let sum: f64 = (0..SUPER)
                .flat_map(|r| &fine[r * SIDE * SUPER + i * SUPER..][..SUPER])
                .map(|&v| v as f64)
                .sum();
            *o = sum / (SUPER * SUPER) as f64;
        }
    }
    out
}

/// One sample per pixel, plainly and filtered with the pixel spacing as the footprint.
fn one_sample(noise: &Multiband<'_, Tile2<64>>) -> (Vec<f64>, Vec<f64>) {
    let (mut plain, mut filtered) = (vec![], vec![]);
    for j in 0..SIDE {
        for i in 0..SIDE {
            let p = centre(i, j);
            plain.push(noise.sample(p) as f64);
            let f: f32 = noise.sample_filtered(p, [SPACING, 0.0], [0.0, SPACING]);
            filtered.push(f as f64);
        }
    }
    (plain, filtered)
}

fn mse(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| (x - y).powi(2)).sum::<f64>() / a.len() as f64
}

/// 10-band noise rendered at one sample per pixel, with the footprint equal to the pixel
/// spacing, is at least 3× closer (mean squared error) to a 16×16-supersampled box-filtered
/// reference than plain sampling.
///
/// Each band is a one-band `Multiband` (variance 1); a Gaussian multiband sum is
/// `Σ w_b M_b / √(Σ w_b²)` of those, with the same band offsets, so the reference, the plain
/// and the filtered images of any weighting are those combinations of the bands' (checked
/// against the 10-band noise itself for flat weights, where they agree to rounding).
#[test]
fn filtering_by_footprint_beats_plain_sampling_against_a_supersampled_reference() {
    let one = |b: usize| {
        let bands = Bands::new(b as i32 - 1, &[1.0]).unwrap();
        Multiband::new(7, &TILE2, bands, Distribution::Gaussian)
    };
    let mut images = vec![];
    for b in 0..BANDS {
        let band = one(b);
        let r = reference(&band);
        let (p, f) = one_sample(&band);
        let var = r.iter().map(|x| x * x).sum::<f64>() / r.len() as f64;
        println!(
            "band {} ({:.3} coefficients per pixel): box-filtered variance {var:.4}, squared \
             error plain {:.2e}, filtered {:.2e}",
            b as i32 - 1,
            2f32.powi(b as i32) * SPACING,
            mse(&p, &r),
            mse(&f, &r)
        );
        // Averaging over the pixel never does worse than a point sample; where the box is
        // narrow it changes little either way.
        assert!(mse(&f, &r) <= mse(&p, &r).max(1e-6), "band {b}");
        images.push((r, p, f));
    }
    let combine = |w: &[f32; BANDS], k: usize| -> Vec<f64> {
        let norm = w.iter().map(|x| (*x as f64).powi(2)).sum::<f64>().sqrt();
        (0..SIDE * SIDE)
            .map(|i| {
                (0..BANDS)
                    .map(|b| {
                        let (r, p, f) = &images[b];
                        w[b] as f64 * [r, p, f][k][i]
                    })
                    .sum::<f64>()
                    / norm
            })
            .collect()
    };
    let flat = [1.0f32; BANDS];
    let pink: [f32; BANDS] = core::array::from_fn(|b| 0.5f32.sqrt().powi(b as i32));
    let halving: [f32; BANDS] = core::array::from_fn(|b| 0.5f32.powi(b as i32));
    // The 10-band noise itself agrees with the combination of its bands.
    let ten = Multiband::new(
        7,
        &TILE2,
        Bands::new(-1, &flat).unwrap(),
        Distribution::Gaussian,
    );
    let (p, f) = one_sample(&ten);
    let (cp, cf) = (combine(&flat, 1), combine(&flat, 2));
    assert!(mse(&p, &cp) < 1e-9 && mse(&f, &cf) < 1e-9);
    for (name, w) in [("flat", flat), ("1/f", pink), ("halving", halving)] {
        let (r, p, f) = (combine(&w, 0), combine(&w, 1), combine(&w, 2));
        let (plain, filtered) = (mse(&p, &r), mse(&f, &r));
        println!(
            "{name} weights: mean squared error against the reference (variance {:.4}): plain \
             {plain:.5}, filtered {filtered:.5}, {:.1}× lower",
            r.iter().map(|x| x * x).sum::<f64>() / r.len() as f64,
            plain / filtered
        );
        assert!(filtered * 3.0 <= plain, "{name}: {filtered} vs {plain}");
    }
}

/// The contract: a zero, tiny or NaN footprint is `sample`, bit for bit; an infinite or huge
/// one gives 0; any footprint stays within the bound; fixed point follows f32; 3D and the
/// single band behave alike. Likewise for infinite noise's footprints.
#[test]
fn filtered_wavelet_noise_keeps_its_contract() {
    let mut rng = bandnoise_tests::Rng::from_env(180);
    let m2 = Multiband::new(3, &TILE2, Bands::default(), Distribution::Gaussian);
    let m3 = Multiband::new(3, &TILE3, Bands::default(), Distribution::Uniform);
    let band = Wavelet::new(3, &TILE2);
    let fixed = Multiband::new(3, &TILE2_I16, Bands::default(), Distribution::Gaussian);
    let (mut worst, mut worst_infinite) = (0.0f64, 0.0f64);
    for _ in 0..20_000 {
        let p: [f32; 3] = core::array::from_fn(|_| rng.f64_in(-200.0, 200.0) as f32);
        let q = [p[0], p[1]];
        let zero = [0.0; 2];
        let nan = [f32::NAN, 0.0];
        assert_eq!(
            m2.sample_filtered(q, zero, zero).to_bits(),
            m2.sample(q).to_bits()
        );
        assert_eq!(
            m2.sample_filtered(q, nan, nan).to_bits(),
            m2.sample(q).to_bits()
        );
        assert_eq!(band.sample_filtered(q, [0.1, 0.2], nan), band.sample(q));
        let inf = [f32::INFINITY, 0.0];
        assert_eq!(m2.sample_filtered(q, inf, zero), 0.0);
        assert_eq!(band.sample_filtered(q, [4.0, 0.0], zero), 0.0);
        let footprint = rng.f64_in(0.0, 1.0).powi(4) as f32;
        let (dx, dy) = ([footprint, 0.0], [0.0, footprint * 0.7]);
        let v = m2.sample_filtered(q, dx, dy);
        assert!(v.abs() <= Noise::<f32, 2>::amplitude_bound(&m2), "{v}");
        let w = m3.sample_filtered(p, [footprint, 0.0, 0.0], [0.0, 0.0, footprint]);
        assert!(w.abs() <= 1.0, "{w}");
        let b = band.sample_filtered(q, dx, dy);
        assert!(b.abs() <= band.amplitude_bound::<2>());
        // Fixed point, at a point and footprint exact in both types.
        let qx = q.map(|x| I16F16::from_num((x * 256.0).round() / 256.0));
        let fx = I16F16::from_num((footprint * 4096.0).round() / 4096.0);
        let (dxq, dyq) = ([fx, I16F16::ZERO], [I16F16::ZERO, fx]);
        let vq = fixed.sample_filtered(qx, dxq, dyq);
        let to = |a: [I16F16; 2]| a.map(|x| x.to_num::<f32>());
        let vf: f32 = fixed.sample_filtered(to(qx), to(dxq), to(dyq));
        worst = worst.max((vq.to_num::<f64>() - vf as f64).abs());
        // Infinite noise: a footprint that is not positive and finite counts as 1; any other
        // stays within the bound, and fixed point follows f32.
        for bad in [0.0, -2.0, f32::NAN, f32::INFINITY] {
            assert_eq!(m2.sample_infinite(q, bad), m2.sample_infinite(q, 1.0));
        }
        let z = m3.sample_infinite(p, footprint * 8.0);
        assert!(z.abs() <= 1.0);
        let z = m2.sample_infinite(q, footprint);
        assert!(z.abs() <= m2.infinite_bound::<2>(), "{z}");
        // Footprints from 1/2 (finer ones scale |p| ≤ 200 past I16F16's range in the finest
        // band, where fixed point wraps) to 8.
        let zoom = I16F16::from_num(((0.5 + 7.5 * footprint) * 4096.0).round() / 4096.0);
        let zq = fixed.sample_infinite(qx, zoom);
        let zf: f32 = fixed.sample_infinite(to(qx), zoom.to_num::<f32>());
        worst_infinite = worst_infinite.max((zq.to_num::<f64>() - zf as f64).abs());
    }
    println!("infinite multiband 2D: max |I16F16 − f32| = {worst_infinite:.2e}");
    // Found by the fuzz target: zoomed out so far that only a band of weight 3e-20 is left,
    // whose square is subnormal; normalising it must not overflow.
    let tiny = Bands::new(-1, &[1.2354384e-38, -4.1720522e-21, 5.6541e-41]).unwrap();
    let m = Multiband::new(1, &TILE3_I16, tiny, Distribution::Gaussian);
    let z = m.sample_infinite([1.9262965e31f32, -9.856597e24, 3.59e-43], 2f32.powi(41));
    assert!(z.is_finite() && z.abs() <= m.infinite_bound::<3>(), "{z}");
    assert!(worst_infinite < 2e-3);
    println!("filtered multiband 2D: max |I16F16 − f32| = {worst:.2e}");
    assert!(worst < 2e-3);
}

/// Infinite noise (§5.4) along a zoom path over 2^10: the variance stays within ±5% of 1 at
/// every zoom level (2·10⁴ points at each of 41 levels, a quarter octave apart), and from one
/// frame to the next of a zoom of one octave per second at 60 frames per second, no point's
/// value changes by more than the noise's own change between neighbouring pixels of the frame
/// (the value at a point moves as the bands' weights shift by one place per octave, so the
/// change per frame is proportional to the zoom per frame). The bands are six halving ones from
/// −8, relative to a footprint of 1 (the finest, band −3, has ¼ coefficient per pixel).
#[test]
fn infinite_noise_keeps_its_variance_and_has_no_jumps_along_a_zoom() {
    let mut rng = bandnoise_tests::Rng::from_env(181);
    let bands = Bands::fractal(-8, 6, 0.5).unwrap();
    let m2 = Multiband::new(5, &TILE2, bands, Distribution::Gaussian);
    let m3 = Multiband::new(5, &TILE3, bands, Distribution::Gaussian);
    for (name, two) in [("2D", true), ("3D", false)] {
        let sample = |p: [f64; 3], footprint: f64| -> f64 {
            if two {
                m2.sample_infinite([p[0], p[1]], footprint)
            } else {
                m3.sample_infinite(p, footprint)
            }
        };
        let mut worst = 0.0f64;
        for level in 0..=40 {
            let footprint = 2f64.powf(-(level as f64) / 4.0);
            let mut sum2 = 0.0;
            for _ in 0..20_000 {
                // Points over many of the coarsest band's coefficients at this zoom (band −8
                // has one per 128 pixels).
                let p: [f64; 3] = core::array::from_fn(|_| rng.f64_in(-1e5, 1e5) * footprint);
                sum2 += sample(p, footprint).powi(2);
            }
            let var = sum2 / 20_000.0;
            worst = worst.max((var - 1.0).abs());
            assert!(
                (var - 1.0).abs() < 0.05,
                "{name} footprint {footprint}: variance {var}"
            );
        }
        // A frame of 32² pixels around a centre, zoomed in 2^(1/60) per frame.
        let centre = [12.34, -5.67, 0.37];
        let (mut jump, mut step) = (0.0f64, 0.0f64);
        let mut ratio_worst = 0.0f64;
        for frame in 0..600 {
            let w0 = 2f64.powf(-frame as f64 / 60.0);
            let w1 = 2f64.powf(-(frame + 1) as f64 / 60.0);
            let (mut frame_jump, mut frame_step) = (0.0f64, 0.0f64);
            for j in 0..32 {
                for i in 0..32 {
                    let p = [
                        centre[0] + (i as f64 - 16.0) * w0,
                        centre[1] + (j as f64 - 16.0) * w0,
                        centre[2],
                    ];
                    let v = sample(p, w0);
                    frame_jump = frame_jump.max((sample(p, w1) - v).abs());
                    let right = [p[0] + w0, p[1], p[2]];
                    frame_step = frame_step.max((sample(right, w0) - v).abs());
                }
            }
            jump = jump.max(frame_jump);
            step = step.max(frame_step);
            ratio_worst = ratio_worst.max(frame_jump / frame_step);
            assert!(
                frame_jump <= frame_step,
                "{name} frame {frame}: jump {frame_jump} > step {frame_step}"
            );
        }
        println!(
            "infinite {name}: variance within {:.1}% of 1 over 2^10 of zoom; largest \
             frame-to-frame change at a point {jump:.3}, largest change between neighbouring \
             pixels {step:.3} (worst frame's ratio {ratio_worst:.2})",
            worst * 100.0
        );
    }
}

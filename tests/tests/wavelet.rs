//! Wavelet noise against the paper (Cook & DeRose 2005): band variances and means, the band
//! limit (Fig. 8) measured with an FFT, projection against slicing (Fig. 8e/8f), seams between
//! tile blocks, quantization, fixed point and bad input. Each test prints its figures.

use bandnoise::prelude::*;
use bandnoise::wavelet::*;
use bandnoise_tests::{Rng, low_frequency_fraction};

/// Average of `f(p)²` and of `f(p)` over `count` random points in `[-200, 200)^D`.
fn moments<const D: usize>(rng: &mut Rng, count: usize, f: impl Fn([f32; D]) -> f32) -> (f64, f64) {
    let (mut m1, mut m2) = (0.0, 0.0);
    for _ in 0..count {
        let v = f(core::array::from_fn(|_| rng.f64_in(-200.0, 200.0) as f32)) as f64;
        m1 += v;
        m2 += v * v;
    }
    (m2 / count as f64, m1 / count as f64)
}

fn random_normal(rng: &mut Rng) -> [f32; 3] {
    loop {
        let v: [f32; 3] = core::array::from_fn(|_| rng.f64_in(-1.0, 1.0) as f32);
        let l2 = v.iter().map(|x| x * x).sum::<f32>();
        if l2 > 0.01 && l2 <= 1.0 {
            return v.map(|x| x / l2.sqrt());
        }
    }
}

#[test]
fn band_variances_and_means_match_the_paper() {
    let mut rng = Rng::from_env(30);
    // 1. Sampling a band reproduces its tile's exact variance (computed at generation).
    let (b2, b3) = (Wavelet::new(1, &TILE2), Wavelet::new(1, &TILE3));
    let (p2, p3) = (
        b2.with_tiling(Tiling::Periodic),
        b3.with_tiling(Tiling::Periodic),
    );
    let (s2, m2) = moments::<2>(&mut rng, 400_000, |p| p2.sample(p));
    let (s3, m3) = moments::<3>(&mut rng, 400_000, |p| p3.sample(p));
    let (v2, v3) = (
        b2.with_tiling(Tiling::Varied),
        b3.with_tiling(Tiling::Varied),
    );
    let (w2, _) = moments::<2>(&mut rng, 400_000, |p| v2.sample(p));
    let (w3, _) = moments::<3>(&mut rng, 400_000, |p| v3.sample(p));
    // The default tiling.
    let (l2, l3) = (b2, b3);
    let (e2, _) = moments::<2>(&mut rng, 400_000, |p| l2.sample(p));
    let (e3, _) = moments::<3>(&mut rng, 400_000, |p| l3.sample(p));
    println!(
        "default tiles: sampled variance 2D {s2:.4} (exact {:.4}), 3D {s3:.4} (exact {:.4}); means {m2:+.4} {m3:+.4}",
        TILE2.variance(),
        TILE3.variance()
    );
    println!(
        "  with varied tiling: 2D {w2:.4} ({:+.1}%), 3D {w3:.4} ({:+.1}%): seams lose the band's negative neighbour correlation",
        (w2 / s2 - 1.0) * 100.0,
        (w3 / s3 - 1.0) * 100.0
    );
    println!(
        "  with blended tiling (the default): 2D {e2:.4} ({:+.1}%), 3D {e3:.4} ({:+.1}%)",
        (e2 / s2 - 1.0) * 100.0,
        (e3 / s3 - 1.0) * 100.0
    );
    assert!((s2 / TILE2.variance() as f64 - 1.0).abs() < 0.02);
    assert!((s3 / TILE3.variance() as f64 - 1.0).abs() < 0.02);
    assert!(m2.abs() < 0.01 && m3.abs() < 0.01);

    // 2. The construction's average variance over many tiles, against the paper.
    let seeds = 1..=24u32;
    let count = seeds.clone().count() as f64;
    let (mut v2, mut v3, mut vp, mut mp) = (0.0, 0.0, 0.0, 0.0);
    for s in seeds {
        v2 += Tile2::<64>::generate(s).variance() as f64;
        let t3 = Box::new(Tile3::<32>::generate(s));
        v3 += t3.variance() as f64;
        if s <= 6 {
            // Projected: sampled over random normals (no closed form here).
            let b = Wavelet::new(s, &*t3).with_tiling(Tiling::Periodic);
            let normals: Vec<[f32; 3]> = (0..20_000).map(|_| random_normal(&mut rng)).collect();
            let i = std::cell::Cell::new(0);
            let (a, m) = moments::<3>(&mut rng, 20_000, |p| {
                let n = normals[i.get()];
                i.set(i.get() + 1);
                b.sample_projected(p, n)
            });
            vp += a / t3.variance() as f64 * 0.25; // ratio to this tile's 3D variance, over 4..
            mp += m;
        }
    }
    let (v2, v3) = (v2 / count, v3 / count);
    let ratio = vp / 1.5; // six tiles, each weighted 0.25: mean ratio = vp / 1.5
    let vp = ratio * v3;
    println!(
        "2D band: variance {v2:.4} (paper 0.265, {:+.1}%)",
        (v2 / 0.265 - 1.0) * 100.0
    );
    println!(
        "3D band: variance {v3:.4} (paper 0.210, {:+.1}%)",
        (v3 / 0.210 - 1.0) * 100.0
    );
    println!(
        "projected: variance {vp:.4} = {ratio:.3} × 3D (paper 0.296, {:+.1}%), mean {:+.4}",
        (vp / 0.296 - 1.0) * 100.0,
        mp / 6.0
    );
    // 2D and projected reproduce the paper. 3D is 7% below the paper's 0.210, which is the
    // figure of the printed generator's odd 65³ tile (erratum 1): see
    // `the_papers_3d_variance_is_that_of_the_printed_codes_odd_tile`.
    assert!((v2 / 0.265 - 1.0).abs() < 0.03, "2D variance {v2}");
    assert!((vp / 0.296 - 1.0).abs() < 0.03, "projected variance {vp}");
    assert!(
        (v3 / VARIANCE_3D as f64 - 1.0).abs() < 0.03,
        "3D variance {v3}"
    );
    for (measured, constant) in [(v2, VARIANCE_2D), (vp, VARIANCE_PROJECTED)] {
        assert!((measured / constant as f64 - 1.0).abs() < 0.03);
    }
    assert!((mp / 6.0).abs() < 0.01);
}

/// One band sampled on a 256² grid, `spacing` apart.
fn grid(side: usize, spacing: f64, f: impl Fn(f64, f64) -> f64) -> Vec<f64> {
    let mut g = Vec::with_capacity(side * side);
    for y in 0..side {
        for x in 0..side {
            g.push(f(x as f64 * spacing + 0.123, y as f64 * spacing + 0.456));
        }
    }
    g
}

#[test]
fn one_band_is_band_limited_where_perlin_is_not() {
    // In coefficient units a band holds frequencies between 1/4 and 1/2 cycle per unit; Perlin
    // noise at half the frequency (p/2) has its nominal band there too. Power below half the
    // lower edge (1/8) is what should not be there (Fig. 8a against 8d).
    let (side, spacing, cutoff) = (256, 0.5, 0.125);
    let band = Wavelet::new(0, &TILE2).with_tiling(Tiling::Periodic);
    let perlin = Perlin::new(0);
    let w = low_frequency_fraction(
        &grid(side, spacing, |x, y| band.sample([x, y])),
        side,
        spacing,
        cutoff,
    );
    let p = low_frequency_fraction(
        &grid(side, spacing, |x, y| perlin.sample([x / 2.0, y / 2.0])),
        side,
        spacing,
        cutoff,
    );
    println!(
        "power below 1/8 cycle per unit: wavelet {:.3}%, Perlin {:.3}%",
        w * 100.0,
        p * 100.0
    );
    assert!(w < 0.001, "wavelet band leaks {w}");
    assert!(w * 20.0 < p, "wavelet {w} is not far below Perlin {p}");
}

#[test]
fn projection_keeps_a_plane_band_limited_where_slicing_does_not() {
    // The plane z = 3.3 through 3D noise (Fig. 8e against 8f).
    let (side, spacing, cutoff) = (256, 0.5, 0.125);
    let band = Wavelet::new(0, &TILE3).with_tiling(Tiling::Periodic);
    let sliced = low_frequency_fraction(
        &grid(side, spacing, |x, y| band.sample([x, y, 3.3])),
        side,
        spacing,
        cutoff,
    );
    let projected = low_frequency_fraction(
        &grid(side, spacing, |x, y| {
            band.sample_projected([x, y, 3.3], [0.0, 0.0, 1.0])
        }),
        side,
        spacing,
        cutoff,
    );
    let perlin = Perlin::new(0);
    let perlin_slice = low_frequency_fraction(
        &grid(side, spacing, |x, y| {
            perlin.sample([x / 2.0, y / 2.0, 1.65])
        }),
        side,
        spacing,
        cutoff,
    );
    println!(
        "plane through 3D noise, power below 1/8: wavelet slice {:.2}%, wavelet projected {:.3}%, Perlin slice {:.2}%",
        sliced * 100.0,
        projected * 100.0,
        perlin_slice * 100.0
    );
    // Not zero: the paper's double-width basis approximates the exact quintic kernel (eq. 36),
    // and eq. 33's exact orthogonality needs an integer z₀ (here 6.6 coefficients).
    assert!(projected < 0.01, "projected leaks {projected}");
    assert!(
        projected * 5.0 < sliced,
        "projection {projected} does not beat slicing {sliced}"
    );
}

#[test]
fn varied_tiling_is_continuous_across_block_borders_and_barely_leaks() {
    let band = Wavelet::new(9, &TILE2).with_tiling(Tiling::Varied);
    let periodic = band.with_tiling(Tiling::Periodic);
    let n = 64.0f64;
    let mut rng = Rng::from_env(31);
    let mut worst_jump = 0.0f64;
    let mut differs = 0;
    for _ in 0..20_000 {
        // A point on a block border along x (and anywhere along y).
        let b = rng.i32_in(-50, 50) as f64 * n;
        let y = rng.f64_in(-500.0, 500.0);
        let e = 1e-6;
        let (l, r): (f64, f64) = (band.sample([b - e, y]), band.sample([b + e, y]));
        worst_jump = worst_jump.max((l - r).abs());
        let inside = [b + n / 2.0, y];
        let (a, c): (f64, f64) = (band.sample(inside), periodic.sample(inside));
        differs += (a != c) as u32;
    }
    println!(
        "largest jump across a block border over 2e-6: {worst_jump:.2e}; blocks differing from the periodic tile: {differs} of 20000"
    );
    // The gradient of a band is bounded by a few units per coefficient: a jump would be O(1).
    assert!(worst_jump < 1e-4);
    assert!(differs > 15_000, "orientations are not varied");

    // What the borders cost in band limit.
    let (side, spacing, cutoff) = (256, 0.5, 0.125);
    let small: Box<Tile2<16>> = Box::new(Tile2::generate(5)); // many borders in the grid
    let varied = Wavelet::new(3, &*small).with_tiling(Tiling::Varied);
    let plain = varied.with_tiling(Tiling::Periodic);
    let fv = low_frequency_fraction(
        &grid(side, spacing, |x, y| varied.sample([x, y])),
        side,
        spacing,
        cutoff,
    );
    let fp = low_frequency_fraction(
        &grid(side, spacing, |x, y| plain.sample([x, y])),
        side,
        spacing,
        cutoff,
    );
    println!(
        "16² tile, power below 1/8: varied {:.3}%, periodic {:.3}%",
        fv * 100.0,
        fp * 100.0
    );
    assert!(fv < 0.02, "seams leak {fv}");
}

#[test]
fn quantized_tiles_are_within_half_a_step() {
    let mut rng = Rng::from_env(32);
    let (f, q) = (Wavelet::new(1, &TILE3), Wavelet::new(1, &TILE3_I16));
    let step = 1.0 / (1u32 << TILE3_I16.shift()) as f64;
    let mut worst = 0.0f64;
    for _ in 0..100_000 {
        let p: [f32; 3] = core::array::from_fn(|_| rng.f64_in(-100.0, 100.0) as f32);
        let (a, b): (f32, f32) = (f.sample(p), q.sample(p));
        worst = worst.max((a - b).abs() as f64);
    }
    let (f2, q2) = (Wavelet::new(1, &TILE2), Wavelet::new(1, &TILE2_I16));
    for _ in 0..100_000 {
        let p: [f32; 2] = core::array::from_fn(|_| rng.f64_in(-100.0, 100.0) as f32);
        let (a, b): (f32, f32) = (f2.sample(p), q2.sample(p));
        worst = worst.max((a - b).abs() as f64);
    }
    println!(
        "quantization: shift {} (3D) / {} (2D), worst |i16 − f32| = {worst:.2e} (half a step: {:.2e})",
        TILE3_I16.shift(),
        TILE2_I16.shift(),
        step / 2.0
    );
    // Each coefficient is within half a step; a sample's weights sum to 1 per axis, and to at
    // most √2·cos(π/32) (1.4074) in a blend zone, where two blocks' coefficients add.
    let gain = 2f64.sqrt() * (std::f64::consts::PI / 32.0).cos();
    assert!(worst <= step / 2.0 * gain.powi(3) + 1e-6);
}

#[test]
fn fixed_point_follows_f32() {
    let mut rng = Rng::from_env(33);
    let band = Wavelet::new(4, &TILE3_I16);
    let multi = Multiband::new(4, &TILE3_I16, Bands::default(), Distribution::Gaussian);
    let (mut w_band, mut w_proj, mut w_multi) = (0.0f64, 0.0f64, 0.0f64);
    for _ in 0..20_000 {
        let p: [I16F16; 3] = rng.exact_point(200);
        let pf = p.map(|x| x.to_num::<f32>());
        let n = random_normal(&mut rng);
        let nf = n.map(I16F16::from_num);
        let d = |a: I16F16, b: f32| (a.to_num::<f64>() - b as f64).abs();
        w_band = w_band.max(d(band.sample(p), band.sample(pf)));
        w_proj = w_proj.max(d(
            band.sample_projected(p, nf),
            band.sample_projected(pf, n),
        ));
        w_multi = w_multi.max(d(multi.sample(p), multi.sample(pf)));
    }
    println!(
        "max |I16F16 − f32|: band {w_band:.2e}, projected {w_proj:.2e}, multiband {w_multi:.2e}"
    );
    assert!(w_band <= 1.0 / 2048.0 && w_proj <= 1.0 / 256.0 && w_multi <= 1.0 / 256.0);
}

#[test]
fn multiband_has_variance_one_and_a_flat_uniform_distribution() {
    let mut rng = Rng::from_env(34);
    let bands = Bands::new(-1, &[1.0, 0.7, 0.5, 0.3]).unwrap();
    let g2 = Multiband::new(2, &TILE2, bands, Distribution::Gaussian);
    let g3 = Multiband::new(2, &TILE3, bands, Distribution::Gaussian);
    let u3 = Multiband::new(2, &TILE3, bands, Distribution::Uniform);
    // The default tiling (blended), 10⁶ samples each (issue 17 point 2).
    let (v2, _) = moments::<2>(&mut rng, 1_000_000, |p| g2.sample(p));
    let (v3, _) = moments::<3>(&mut rng, 1_000_000, |p| g3.sample(p));
    let (vu, mu) = moments::<3>(&mut rng, 300_000, |p| u3.sample(p));
    let (vp, _) = moments::<3>(&mut rng, 200_000, |p| {
        g3.sample_projected(p, [0.6, 0.0, 0.8])
    });
    let (vz, _) = moments::<3>(&mut rng, 200_000, |p| {
        g3.sample_projected(p, [0.0, 0.0, 1.0])
    });
    println!(
        "multiband variance: 2D {v2:.4}, 3D {v3:.4}, projected oblique {vp:.3}, along z {vz:.3}; \
         uniform: variance {vu:.4} (1/3 = 0.3333), mean {mu:+.4}"
    );
    let (w2, w3) = (
        g2.with_tiling(Tiling::Varied),
        g3.with_tiling(Tiling::Varied),
    );
    let (w2, _) = moments::<2>(&mut rng, 300_000, |p| w2.sample(p));
    let (w3, _) = moments::<3>(&mut rng, 300_000, |p| w3.sample(p));
    println!("  varied tiling: 2D {w2:.3}, 3D {w3:.3} (its borders add variance)");
    for v in [v2, v3] {
        assert!((v - 1.0).abs() < 0.01, "variance {v}");
    }
    for v in [vp, vz] {
        assert!((v - 1.0).abs() < 0.08, "projected variance {v}");
    }
    assert!((vu - 1.0 / 3.0).abs() < 0.02 && mu.abs() < 0.02);
    // The uniform histogram: ten bins of (-1, 1), each near 10%.
    let mut bins = [0u32; 10];
    for _ in 0..200_000 {
        let p: [f32; 3] = core::array::from_fn(|_| rng.f64_in(-300.0, 300.0) as f32);
        let v: f32 = u3.sample(p);
        bins[(((v + 1.0) * 5.0) as usize).min(9)] += 1;
    }
    println!(
        "uniform histogram (10 bins, %): {:?}",
        bins.map(|b| b as f64 / 2000.0)
    );
    assert!(
        bins.iter()
            .all(|&b| (b as f64 / 200_000.0 - 0.1).abs() < 0.02)
    );
}

#[test]
fn bad_input_gives_documented_results() {
    let band = Wavelet::new(0, &TILE3);
    let multi = Multiband::new(0, &TILE3, Bands::default(), Distribution::Gaussian);
    let zero = Multiband::new(
        0,
        &TILE3,
        Bands::new(0, &[0.0, 0.0]).unwrap(),
        Distribution::Uniform,
    );
    let empty = Multiband::new(
        0,
        &TILE2,
        Bands::new(0, &[]).unwrap(),
        Distribution::Gaussian,
    );
    let specials = [
        f32::NAN,
        f32::INFINITY,
        f32::NEG_INFINITY,
        -0.0,
        1e30,
        -1e30,
        f32::from_bits(1),
    ];
    for &s in &specials {
        for p in [[s, 0.5, 0.5], [0.5, s, 0.5], [0.5, 0.5, s]] {
            let v: f32 = band.sample(p);
            assert!(
                v.is_finite() && v.abs() <= Noise::<f32, 3>::amplitude_bound(&band),
                "{p:?}"
            );
            let m: f32 = multi.sample(p);
            assert!(m.is_finite() && m.abs() <= Noise::<f32, 3>::amplitude_bound(&multi));
            assert!(multi.sample_projected(p, [0.0, 1.0, 0.0]).is_finite());
            if s.is_nan() || s.is_infinite() {
                let q = p.map(|x| {
                    if x.is_nan() || x.is_infinite() {
                        0.0
                    } else {
                        x
                    }
                });
                assert_eq!(v, band.sample(q), "non-finite coordinates sample 0");
            }
        }
        // Normals: zero or non-finite ones project along z; any other keeps its direction,
        // however large or small.
        let p = [0.3, 0.7, 1.1];
        for n in [[0.0, 0.0, 0.0], [s, 0.0, 1.0], [0.0, 0.0, 1e-30]] {
            let v: f32 = band.sample_projected(p, n);
            if n[0].is_finite() && n[0].abs() > 1.0 {
                assert_eq!(unit_normal(n)[0], s.signum(), "{n:?}");
                assert_eq!(v, band.sample_projected(p, unit_normal(n)), "{n:?}");
            } else if n[0] != 0.0 && n[0].is_finite() {
                // A subnormal tilt keeps its direction: an oblique normal, summed coefficient
                // by coefficient, within rounding of the block sums along z.
                assert_eq!(unit_normal(n)[0], n[0], "{n:?}");
                let z: f32 = band.sample_projected(p, [0.0, 0.0, 1.0]);
                assert!((v - z).abs() <= 1e-5, "{n:?}: {v} against {z} along z");
            } else {
                let z = [0.0, 0.0, 1.0];
                assert_eq!(v, band.sample_projected(p, z), "{n:?} projects along z");
            }
        }
    }
    assert_eq!(
        band.sample_projected([0.3f32, 0.7, 1.1], [0.0, 3.0, 4.0]),
        band.sample_projected([0.3, 0.7, 1.1], [0.0, 0.6, 0.8])
    );
    // All weights zero, or none: 0, not a division by zero.
    assert_eq!(zero.sample([0.1f32, 0.2, 0.3]), 0.0);
    assert_eq!(
        zero.sample_projected([0.1f32, 0.2, 0.3], [1.0, 0.0, 0.0]),
        0.0
    );
    assert_eq!(empty.sample([0.1f32, 0.2]), 0.0);
    // Fixed point at its extremes.
    let fx = [I16F16::MIN, I16F16::MAX, I16F16::DELTA];
    let _: I16F16 = band.sample(fx);
    let _: I16F16 = band.sample_projected(fx, [I16F16::MAX, I16F16::MIN, I16F16::ZERO]);
    let _: I16F16 = multi.sample(fx);
    // Configuration errors.
    assert!(matches!(
        Bands::new(0, &[1.0; 17]),
        Err(bandnoise::Error::TooManyBands { count: 17, max: 16 })
    ));
    assert!(matches!(
        Bands::new(0, &[1.0, f32::INFINITY]),
        Err(bandnoise::Error::BandWeight { index: 1, .. })
    ));
    assert!(matches!(
        Bands::new(9, &[1.0]),
        Err(bandnoise::Error::FirstBand(9))
    ));
}

#[test]
fn tiles_built_at_compile_time_equal_tiles_built_at_run_time() {
    static SMALL: Tile3<8> = Tile3::generate(11);
    let runtime = Tile3::<8>::generate(11);
    assert_eq!(SMALL, runtime);
    assert_eq!(*Box::new(Tile3::<32>::generate(DEFAULT_TILE_SEED)), TILE3);
    // Different seeds, different tiles.
    assert_ne!(Tile2::<16>::generate(1), Tile2::<16>::generate(2));
}

#[test]
fn default_tiles_have_the_documented_sizes() {
    let sizes = [
        ("TILE2", core::mem::size_of_val(&TILE2)),
        ("TILE3", core::mem::size_of_val(&TILE3)),
        ("TILE2_I16", core::mem::size_of_val(&TILE2_I16)),
        ("TILE3_I16", core::mem::size_of_val(&TILE3_I16)),
    ];
    println!("flash bytes of the default tiles: {sizes:?}");
    // Coefficients plus a few bytes of metadata (bound, variance, shift).
    for ((_, bytes), coefficients) in
        sizes
            .iter()
            .zip([64 * 64 * 4, 32 * 32 * 32 * 4, 64 * 64 * 2, 32 * 32 * 32 * 2])
    {
        assert!(*bytes >= coefficients && *bytes <= coefficients + 16);
    }
}

/// Regression: found by the fuzz target `wavelet` (artifact crash-9676ea98…): weights near
/// 1e-23 underflowed Σw² in f32 and the normalisation blew up.
#[test]
fn tiny_and_huge_band_weights_normalise() {
    for weights in [
        [-2.6470584e-23f32, -1.594851e-23, 8.8e-44],
        [1e6, 1e6, -1e6],
        [1e-30, 0.0, 0.0],
    ] {
        let bands = Bands::new(-1, &weights).unwrap();
        let m = Multiband::new(0, &TILE3_I16, bands, Distribution::Gaussian);
        let p = [f32::from_bits(4294966783), 0.37, 1.5];
        let v: f32 = m.sample(p);
        assert!(
            v.is_finite() && v.abs() <= Noise::<f32, 3>::amplitude_bound(&m),
            "{weights:?}: {v}"
        );
        let w = m.sample_projected(p, [0.0, 1.0, 0.0]);
        assert!(w.is_finite() && w.abs() <= m.projected_bound());
    }
    // Scale does not matter: the normalised noise is the same for weights ×1e-20 and ×1.
    let a = Multiband::new(
        0,
        &TILE3_I16,
        Bands::new(0, &[1.0, 0.5]).unwrap(),
        Distribution::Gaussian,
    );
    let b = Multiband::new(
        0,
        &TILE3_I16,
        Bands::new(0, &[1e-20, 0.5e-20]).unwrap(),
        Distribution::Gaussian,
    );
    let (x, y): (f32, f32) = (a.sample([0.3, 0.4, 0.5]), b.sample([0.3, 0.4, 0.5]));
    assert!((x - y).abs() < 1e-6, "{x} vs {y}");
}

/// Cook & DeRose's Appendix 1 `GenerateNoiseTile` transcribed as printed, in `f64` and
/// independently of `core` (own Gaussian source, own loops over a flat `x + y·n + z·n²` array),
/// with errata 2–5 of `../shared/papers/README.md` applied but **not erratum 1**: the printed
/// `if (n/2) n++;` makes every requested size of 2 or more one larger, so a requested even size
/// becomes odd. Returns the tile's side and coefficients.
mod printed {
    use bandnoise_tests::Rng;

    /// The printed analysis filter, `a_k` for `k = −16..15` (erratum 3: symmetric).
    const A: [f64; 32] = [
        0.000334, -0.001528, 0.000410, 0.003546, -0.000938, -0.008233, 0.002172, 0.019120,
        -0.005040, -0.044412, 0.011655, 0.103311, -0.025936, -0.243780, 0.033979, 0.655340,
        0.655340, 0.033979, -0.243780, -0.025936, 0.103311, 0.011655, -0.044412, -0.005040,
        0.019120, 0.002172, -0.008233, -0.000938, 0.003546, 0.000410, -0.001528, 0.000334,
    ];

    fn modulo(x: i64, n: i64) -> usize {
        x.rem_euclid(n) as usize
    }

    /// Polar Box–Muller: mean 0, variance 1 (erratum 4).
    fn gauss(rng: &mut Rng) -> f64 {
        loop {
            let (u, v) = (rng.f64_in(-1.0, 1.0), rng.f64_in(-1.0, 1.0));
            let s = u * u + v * v;
            if s > 0.0 && s < 1.0 {
                return u * (-2.0 * s.ln() / s).sqrt();
            }
        }
    }

    /// `Downsample`: `n/2` outputs, 32 taps `2i−16 ≤ k < 2i+16` (erratum 2), `Mod(k, n)`.
    fn downsample(from: &[f64], to: &mut [f64], base: usize, n: usize, stride: usize) {
        for i in 0..n / 2 {
            let mut s = 0.0;
            for k in 2 * i as i64 - 16..2 * i as i64 + 16 {
                s +=
                    A[(k - 2 * i as i64 + 16) as usize] * from[base + modulo(k, n as i64) * stride];
            }
            to[base + i * stride] = s;
        }
    }

    /// `Upsample`: `n` outputs from `Mod(k, n/2)`, refinement `¼ ¾ ¾ ¼`.
    fn upsample(from: &[f64], to: &mut [f64], base: usize, n: usize, stride: usize) {
        const P: [f64; 4] = [0.25, 0.75, 0.75, 0.25];
        for i in 0..n as i64 {
            let mut s = 0.0;
            for k in i / 2..=i / 2 + 1 {
                s += P[(i - 2 * k + 2) as usize] * from[base + modulo(k, n as i64 / 2) * stride];
            }
            to[base + i as usize * stride] = s;
        }
    }

    pub fn tile3(requested: usize, rng: &mut Rng) -> (usize, Vec<f64>) {
        let n = if requested / 2 != 0 {
            requested + 1
        } else {
            requested
        };
        let mut noise: Vec<f64> = (0..n * n * n).map(|_| gauss(rng)).collect();
        let (mut t1, mut t2) = (vec![0.0; n * n * n], vec![0.0; n * n * n]);
        for a in 0..n {
            for b in 0..n {
                let i = a * n + b * n * n; // each x row
                downsample(&noise, &mut t1, i, n, 1);
                upsample(&t1, &mut t2, i, n, 1);
            }
        }
        for a in 0..n {
            for b in 0..n {
                let i = a + b * n * n; // each y row
                downsample(&t2, &mut t1, i, n, n);
                upsample(&t1, &mut t2, i, n, n);
            }
        }
        for a in 0..n {
            for b in 0..n {
                let i = a + b * n; // each z row
                downsample(&t2, &mut t1, i, n, n * n);
                upsample(&t1, &mut t2, i, n, n * n);
            }
        }
        for (v, c) in noise.iter_mut().zip(&t2) {
            *v -= c;
        }
        // Erratum 5: add a copy shifted by an odd offset in every axis, index by index.
        let offset = if (n / 2) % 2 == 0 { n / 2 + 1 } else { n / 2 };
        let at = |x: usize, y: usize, z: usize| (x % n) + (y % n) * n + (z % n) * n * n;
        let shifted: Vec<f64> = (0..n * n * n)
            .map(|i| noise[at(i % n + offset, i / n % n + offset, i / (n * n) + offset)])
            .collect();
        for (v, s) in noise.iter_mut().zip(&shifted) {
            *v += s;
        }
        (n, noise)
    }

    /// The average over `x` of the variance of `N(x) = Σ n_i B(x − i)`:
    /// `Σ_δ E[n_i n_{i+δ}] G(δx) G(δy) G(δz)` with the quadratic B-spline overlap integrals
    /// `G(0) = 11/20`, `G(±1) = 13/60`, `G(±2) = 1/120` (no sampling noise).
    pub fn average_variance(n: usize, t: &[f64]) -> f64 {
        const G: [f64; 5] = [
            1.0 / 120.0,
            13.0 / 60.0,
            11.0 / 20.0,
            13.0 / 60.0,
            1.0 / 120.0,
        ];
        let mut total = 0.0;
        for (dz, gz) in G.iter().enumerate() {
            for (dy, gy) in G.iter().enumerate() {
                for (dx, gx) in G.iter().enumerate() {
                    let mut c = 0.0;
                    for z in 0..n {
                        for y in 0..n {
                            for x in 0..n {
                                let (xs, ys, zs) = (
                                    (x + n + dx - 2) % n,
                                    (y + n + dy - 2) % n,
                                    (z + n + dz - 2) % n,
                                );
                                c += t[x + y * n + z * n * n] * t[xs + ys * n + zs * n * n];
                            }
                        }
                    }
                    total += gx * gy * gz * c / (n * n * n) as f64;
                }
            }
        }
        total
    }
}

#[test]
fn the_papers_3d_variance_is_that_of_the_printed_codes_odd_tile() {
    // The paper's 0.210 for a 3D band is not what its construction gives on an even tile (0.196,
    // here and in `band_variances_and_means_match_the_paper`). Its printed generator, taken
    // literally, makes a requested 64³ tile 65³ (`if (n/2) n++`, erratum 1); on an odd tile the
    // coarse part wraps with period n/2 ≠ n/2 + ½, is not removed along one plane per axis, and
    // raises the variance to the paper's figure. An even tile from the same transcription
    // reproduces bandnoise's own construction: two independent implementations agree.
    let mut rng = Rng::from_env(33);
    let mut average = |requested: usize, tiles: usize| {
        let mut sum = 0.0;
        let mut side = 0;
        for _ in 0..tiles {
            let (n, t) = printed::tile3(requested, &mut rng);
            side = n;
            sum += printed::average_variance(n, &t);
        }
        (side, sum / tiles as f64)
    };
    let (odd, v_odd) = average(64, 3);
    let (even, v_even) = average(31, 3);
    println!(
        "printed code, {odd}³ tile (64 requested): 3D band variance {v_odd:.4} (paper 0.210, {:+.1}%)",
        (v_odd / 0.210 - 1.0) * 100.0
    );
    println!(
        "printed code, {even}³ tile (31 requested): {v_even:.4} (bandnoise's VARIANCE_3D {VARIANCE_3D}, {:+.1}%)",
        (v_even / VARIANCE_3D as f64 - 1.0) * 100.0
    );
    assert_eq!((odd, even), (65, 32));
    assert!((v_odd / 0.210 - 1.0).abs() < 0.03, "odd tile {v_odd}");
    assert!(
        (v_even / VARIANCE_3D as f64 - 1.0).abs() < 0.03,
        "even tile {v_even}"
    );
    // The two figures are apart by more than either tolerance: the test tells them apart.
    assert!(v_odd / v_even > 1.05);
}

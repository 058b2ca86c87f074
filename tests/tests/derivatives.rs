//! Analytic gradients against central differences, and the value they return against `sample`.

use bandnoise::prelude::*;
use bandnoise::wavelet::Tiling;
use bandnoise_tests::{Lattice, Rng};

/// Step of the central differences: small enough that the truncation error `h²/6·|n'''|` stays
/// near 1e-4, large enough that f32 rounding `ε·|n|/h` stays near 3e-5.
const H: f32 = 1.0 / 512.0;

fn check<const D: usize>(noise: &Lattice, name: &str, rng: &mut Rng) -> f64
where
    Lattice: Noise<f32, D>,
    Perlin: NoiseGradient<f32, D>,
    TabledPerlin: NoiseGradient<f32, D>,
    OriginalPerlin: NoiseGradient<f32, D>,
    CNoise: NoiseGradient<f32, D>,
    MNoise<61>: NoiseGradient<f32, D>,
    MNoise<4093>: NoiseGradient<f32, D>,
{
    let mut worst = 0.0f64;
    for _ in 0..20_000 {
        let p: [f32; D] = core::array::from_fn(|_| rng.f64_in(-100.0, 100.0) as f32);
        // The original noise is only C¹: its second derivative jumps at cell faces, where a
        // central difference is off by h/4 · jump. Keep its points 2h away from faces; the
        // C² noises are tested everywhere.
        if matches!(noise, Lattice::Original(_))
            && p.iter()
                .any(|x| (x - x.floor()).min(x.ceil() - x) < 2.0 * H)
        {
            continue;
        }
        let (value, gradient) = noise.sample_with_gradient(p);
        let plain: f32 = noise.sample(p);
        assert_eq!(
            value.to_bits(),
            plain.to_bits(),
            "{name} {D}D value differs from sample"
        );
        for a in 0..D {
            let (mut hi, mut lo) = (p, p);
            hi[a] += H;
            lo[a] -= H;
            let (nh, nl): (f32, f32) = (noise.sample(hi), noise.sample(lo));
            // The actual spacing after rounding the coordinates.
            let central = (nh - nl) as f64 / (hi[a] - lo[a]) as f64;
            let err = (gradient[a] as f64 - central).abs();
            worst = worst.max(err);
            assert!(
                err <= 1e-3,
                "{name} {D}D ∂/∂x{a} at {p:?}: {} vs {central}",
                gradient[a]
            );
        }
    }
    println!("{name:>10} {D}D: max |analytic − central difference| = {worst:.2e}");
    worst
}

#[test]
fn analytic_gradients_match_central_differences_in_f32() {
    let mut rng = Rng::from_env(6);
    for (name, noise) in Lattice::gradient_noises(11) {
        check::<1>(&noise, name, &mut rng);
        check::<2>(&noise, name, &mut rng);
        check::<3>(&noise, name, &mut rng);
        check::<4>(&noise, name, &mut rng);
    }
}

#[test]
fn fixed_point_gradients_follow_f32() {
    let mut rng = Rng::from_env(7);
    let noise = MNoise::<61>::new(4);
    let perlin = Perlin::new(4);
    let mut worst = 0.0f64;
    for _ in 0..20_000 {
        let p: [I16F16; 3] = rng.exact_point(200);
        let pf = p.map(|x| x.to_num::<f32>());
        for (fx, fl) in [
            (
                noise.sample_with_gradient(p),
                noise.sample_with_gradient(pf),
            ),
            (
                perlin.sample_with_gradient(p),
                perlin.sample_with_gradient(pf),
            ),
        ] {
            for a in 0..3 {
                worst = worst.max((fx.1[a].to_num::<f64>() - fl.1[a] as f64).abs());
            }
        }
    }
    println!("max |I16F16 − f32| of 3D gradients: {worst:.2e}");
    assert!(worst <= 1.0 / 512.0);
}

/// Central difference of `f` along each axis, in f64 with a step of 1e-6.
fn central<const D: usize>(f: impl Fn([f64; D]) -> f64, p: [f64; D]) -> [f64; D] {
    const STEP: f64 = 1e-6;
    core::array::from_fn(|a| {
        let (mut hi, mut lo) = (p, p);
        hi[a] += STEP;
        lo[a] -= STEP;
        (f(hi) - f(lo)) / (hi[a] - lo[a])
    })
}

/// Value noise (plain and periodic) and fractal sums of every kind have analytic gradients
/// equal to central differences, and values equal to `sample`. Fractal sums of `|n|` have kinks
/// where an octave's noise is 0 (and ridged ones where a weight reaches its clamp): points whose
/// central difference straddles one are skipped, octave by octave.
#[test]
fn value_noise_and_fractal_gradients_match_central_differences() {
    let mut rng = Rng::from_env(170);
    let value = ValueNoise::new(3);
    let periodic = bandnoise::lattice::Periodic::new(ValueNoise::new(3), [5, 7, 3]).unwrap();
    let perlin = Perlin::new(3);
    let octaves = Octaves::new(4, 1.99, 0.5).unwrap();
    let (mut worst, mut skipped) = (0.0f64, 0usize);
    for _ in 0..20_000 {
        let p: [f64; 3] = core::array::from_fn(|_| rng.f64_in(-50.0, 50.0));
        let check = |name: &str, (v, g): (f64, [f64; 3]), plain: f64, c: [f64; 3]| {
            assert_eq!(v.to_bits(), plain.to_bits(), "{name}: value at {p:?}");
            let err = (0..3).fold(0.0f64, |e, a| e.max((g[a] - c[a]).abs()));
            assert!(err < 1e-5, "{name} at {p:?}: {g:?} vs {c:?}");
            err
        };
        worst = worst.max(check(
            "value",
            value.sample_with_gradient(p),
            value.sample(p),
            central(|q| value.sample(q), p),
        ));
        worst = worst.max(check(
            "periodic value",
            periodic.sample_with_gradient(p),
            periodic.sample(p),
            central(|q| periodic.sample(q), p),
        ));
        // Each octave's noise and, for ridged sums, twice its term (the next weight).
        let (mut f, mut w, mut kinked, mut clamped) = (1.0f64, 1.0f64, false, false);
        for _ in 0..octaves.count() {
            let n: f64 = perlin.sample(p.map(|x| x * f));
            kinked |= n.abs() < 1e-4 * f;
            let r = (1.0 - n.abs()).powi(2) * w;
            clamped |= (2.0 * r - 1.0).abs() < 1e-4 * f || (2.0 * r).abs() < 1e-4 * f;
            w = (2.0 * r).clamp(0.0, 1.0);
            f *= 1.99f32 as f64;
        }
        for kind in [Kind::Fbm, Kind::Turbulence, Kind::Ridged] {
            if (kind != Kind::Fbm && kinked) || (kind == Kind::Ridged && clamped) {
                skipped += 1;
                continue;
            }
            let sum = Fractal::new(&perlin, octaves, kind);
            let name = format!("{kind:?}");
            worst = worst.max(check(
                &name,
                sum.sample_with_gradient(p),
                sum.sample(p),
                central(|q| sum.sample(q), p),
            ));
        }
    }
    println!(
        "value noise and fractal sums (f64): max |analytic − central difference| = {worst:.2e}; {skipped} kinked samples skipped"
    );
}

/// Wavelet bands (2D, 3D, every tiling) have analytic gradients equal to central differences
/// (a band is C¹, so a central difference straddling a coefficient boundary is off by at most
/// step × the jump of the second derivative: far below the tolerance), and values equal to
/// `sample`, bit for bit.
#[test]
fn wavelet_gradients_match_central_differences() {
    let mut rng = Rng::from_env(171);
    let mut worst = 0.0f64;
    for tiling in [Tiling::Varied, Tiling::Blended, Tiling::Periodic] {
        let b2 = Wavelet::new(5, &TILE2).with_tiling(tiling);
        let b3 = Wavelet::new(5, &TILE3).with_tiling(tiling);
        for _ in 0..10_000 {
            let p: [f64; 3] = core::array::from_fn(|_| rng.f64_in(-300.0, 300.0));
            let (v, g) = b3.sample_with_gradient(p);
            let plain: f64 = b3.sample(p);
            assert_eq!(v.to_bits(), plain.to_bits(), "3D value at {p:?}");
            let c = central(|q| b3.sample(q), p);
            let q = [p[0], p[1]];
            let (v2, g2) = b2.sample_with_gradient(q);
            let plain2: f64 = b2.sample(q);
            assert_eq!(v2.to_bits(), plain2.to_bits(), "2D value at {q:?}");
            let c2 = central(|r| b2.sample(r), q);
            for (a, b) in g.iter().zip(c).chain(g2.iter().zip(c2)) {
                worst = worst.max((a - b).abs());
                assert!((a - b).abs() < 1e-5, "{tiling:?} at {p:?}: {a} vs {b}");
            }
        }
    }
    println!("wavelet bands (f64): max |analytic − central difference| = {worst:.2e}");
    // Fixed point follows f32.
    let b = Wavelet::new(5, &TILE3);
    let mut worst_fixed = 0.0f64;
    for _ in 0..10_000 {
        let p: [I16F16; 3] = rng.exact_point(200);
        let (_, gq) = b.sample_with_gradient(p);
        let (_, gf) = b.sample_with_gradient(p.map(|x| x.to_num::<f32>()));
        for (q, f) in gq.iter().zip(gf) {
            worst_fixed = worst_fixed.max((q.to_num::<f64>() - f as f64).abs());
        }
    }
    println!("wavelet 3D gradient: max |I16F16 − f32| = {worst_fixed:.2e}");
    assert!(worst_fixed < 2e-3);
}

/// Multiband noise (both distributions, bands below and above band 0) has analytic gradients
/// equal to central differences, and values equal to `sample`. The uniform distribution's `erf`
/// is a C¹ cubic Hermite interpolant, so its gradient is that of the function computed.
#[test]
fn multiband_gradients_match_central_differences() {
    let mut rng = Rng::from_env(172);
    let mut worst = 0.0f64;
    for distribution in [Distribution::Gaussian, Distribution::Uniform] {
        for bands in [Bands::default(), Bands::new(-3, &[1.0, 0.7, 0.3]).unwrap()] {
            let m2 = Multiband::new(4, &TILE2, bands, distribution);
            let m3 = Multiband::new(4, &TILE3, bands, distribution);
            for _ in 0..3000 {
                let p: [f64; 3] = core::array::from_fn(|_| rng.f64_in(-100.0, 100.0));
                let (v, g) = m3.sample_with_gradient(p);
                assert_eq!(v.to_bits(), m3.sample(p).to_bits());
                let c = central(|q| m3.sample(q), p);
                let q = [p[0], p[1]];
                let (v2, g2) = m2.sample_with_gradient(q);
                assert_eq!(v2.to_bits(), m2.sample(q).to_bits());
                let c2 = central(|r| m2.sample(r), q);
                for (a, b) in g.iter().zip(c).chain(g2.iter().zip(c2)) {
                    // Relative to the gradient's size: the highest band's frequency is 2^5.
                    let err = (a - b).abs() / b.abs().max(1.0);
                    worst = worst.max(err);
                    assert!(err < 1e-4, "{distribution:?} at {p:?}: {a} vs {b}");
                }
            }
        }
    }
    println!("multiband (f64): max relative |analytic − central difference| = {worst:.2e}");
}

/// Projected bands and projected multiband noise (every tiling; axis-aligned, oblique and
/// random normals; both distributions) have analytic gradients equal to central differences,
/// the normal held fixed, and values equal to `sample_projected`, bit for bit.
#[test]
fn projected_gradients_match_central_differences() {
    let mut rng = Rng::from_env(173);
    let normals = |rng: &mut Rng| {
        [
            [0.0, 0.0, 1.0],
            [0.6, 0.0, -0.8],
            [1.0, 1.0, 1.0],
            core::array::from_fn(|_| rng.f64_in(-1.0, 1.0)),
        ]
    };
    let mut worst = 0.0f64;
    for tiling in [Tiling::Varied, Tiling::Blended, Tiling::Periodic] {
        let band = Wavelet::new(5, &TILE3).with_tiling(tiling);
        for _ in 0..1500 {
            let p: [f64; 3] = core::array::from_fn(|_| rng.f64_in(-300.0, 300.0));
            for n in normals(&mut rng) {
                let (v, g) = band.sample_projected_with_gradient(p, n);
                let plain: f64 = band.sample_projected(p, n);
                assert_eq!(
                    v.to_bits(),
                    plain.to_bits(),
                    "{tiling:?} value at {p:?}, {n:?}"
                );
                let c = central(|q| band.sample_projected(q, n), p);
                for (a, b) in g.iter().zip(c) {
                    worst = worst.max((a - b).abs());
                    assert!(
                        (a - b).abs() < 1e-5,
                        "{tiling:?} at {p:?}, {n:?}: {g:?} vs {c:?}"
                    );
                }
            }
        }
    }
    println!("projected bands (f64): max |analytic − central difference| = {worst:.2e}");
    // Fixed point follows f32 (a projected sample adds up to 8³ rounded products).
    let band = Wavelet::new(5, &TILE3);
    let (mut worst_fixed, mut worst_value) = (0.0f64, 0.0f64);
    for _ in 0..3000 {
        let p: [I16F16; 3] = rng.exact_point(200);
        let n: [I16F16; 3] = core::array::from_fn(|_| I16F16::from_num(rng.f64_in(-1.0, 1.0)));
        let (vq, gq) = band.sample_projected_with_gradient(p, n);
        let to_f32 = |x: [I16F16; 3]| x.map(|c| c.to_num::<f32>());
        let (vf, gf) = band.sample_projected_with_gradient(to_f32(p), to_f32(n));
        worst_value = worst_value.max((vq.to_num::<f64>() - vf as f64).abs());
        for (q, f) in gq.iter().zip(gf) {
            worst_fixed = worst_fixed.max((q.to_num::<f64>() - f as f64).abs());
        }
    }
    println!(
        "projected band: max |I16F16 − f32| of the gradient {worst_fixed:.2e}, of the value \
         {worst_value:.2e}"
    );
    assert!(worst_fixed < 1e-3 && worst_value < 1e-3);
    let mut worst = 0.0f64;
    for distribution in [Distribution::Gaussian, Distribution::Uniform] {
        let m = Multiband::new(4, &TILE3, Bands::default(), distribution);
        for _ in 0..500 {
            let p: [f64; 3] = core::array::from_fn(|_| rng.f64_in(-100.0, 100.0));
            for n in normals(&mut rng) {
                let (v, g) = m.sample_projected_with_gradient(p, n);
                assert_eq!(v.to_bits(), m.sample_projected(p, n).to_bits());
                let c = central(|q| m.sample_projected(q, n), p);
                for (a, b) in g.iter().zip(c) {
                    let err = (a - b).abs() / b.abs().max(1.0);
                    worst = worst.max(err);
                    assert!(
                        err < 1e-4,
                        "{distribution:?} at {p:?}, {n:?}: {g:?} vs {c:?}"
                    );
                }
            }
        }
    }
    println!(
        "projected multiband (f64): max relative |analytic − central difference| = {worst:.2e}"
    );
}

/// In f32, the analytic gradients of wavelet bands and multiband noise (2D, 3D, projected,
/// default tiling) are within 1e-3 of central differences (taken in f64 at the same point,
/// where f32's own rounding does not swamp them), relative to the gradient's length where it
/// exceeds 1. Bands are sampled over |p| < 100, multiband noise over |p| < 10: its finest band
/// has frequency 2^5, and f32 rounds that band's coordinate `2^5 p + offset` to its ulp
/// (2⁻¹² of a coefficient near 3200), so at |p| = 100 the analytic gradient, exact for the
/// point f32 samples, is 2e-3 from the f64 central difference at `p` (under 4e-4 at |p| = 10).
#[test]
fn wavelet_gradients_in_f32_are_within_1e_3_of_central_differences() {
    let mut rng = Rng::from_env(174);
    let b2 = Wavelet::new(5, &TILE2);
    let b3 = Wavelet::new(5, &TILE3);
    let m2 = Multiband::new(4, &TILE2, Bands::default(), Distribution::Gaussian);
    let m3 = Multiband::new(4, &TILE3, Bands::default(), Distribution::Gaussian);
    let mut worst = [0.0f64; 6];
    let mut record = |k: usize, g: &[f32], c: &[f64]| {
        let norm = c.iter().map(|x| x * x).sum::<f64>().sqrt().max(1.0);
        for (a, b) in g.iter().zip(c) {
            worst[k] = worst[k].max((*a as f64 - b).abs() / norm);
        }
    };
    for _ in 0..3000 {
        let p: [f32; 3] = core::array::from_fn(|_| rng.f64_in(-100.0, 100.0) as f32);
        let p64 = p.map(f64::from);
        let n: [f32; 3] = core::array::from_fn(|_| rng.f64_in(-1.0, 1.0) as f32);
        let n64 = n.map(f64::from);
        let q = [p[0], p[1]];
        let q64 = [p64[0], p64[1]];
        record(
            0,
            &b2.sample_with_gradient(q).1,
            &central(|r| b2.sample(r), q64),
        );
        record(
            1,
            &b3.sample_with_gradient(p).1,
            &central(|r| b3.sample(r), p64),
        );
        let g = b3.sample_projected_with_gradient(p, n).1;
        record(2, &g, &central(|r| b3.sample_projected(r, n64), p64));
        // Multiband noise over a tenth of the range: its finest band samples 2^5 p.
        let p = p.map(|x| x / 10.0);
        let p64 = p.map(f64::from);
        let (q, q64) = ([p[0], p[1]], [p64[0], p64[1]]);
        record(
            3,
            &m2.sample_with_gradient(q).1,
            &central(|r| m2.sample(r), q64),
        );
        record(
            4,
            &m3.sample_with_gradient(p).1,
            &central(|r| m3.sample(r), p64),
        );
        let g = m3.sample_projected_with_gradient(p, n).1;
        record(5, &g, &central(|r| m3.sample_projected(r, n64), p64));
    }
    let names = [
        "band 2D",
        "band 3D",
        "band projected",
        "multiband 2D",
        "multiband 3D",
    ];
    for (name, w) in names.iter().chain(&["multiband projected"]).zip(worst) {
        println!("{name} (f32): max |analytic − central difference| = {w:.2e}");
        assert!(w < 1e-3, "{name}: {w}");
    }
}

//! Analytic gradients against central differences, and the value they return against `sample`.

use bandnoise::prelude::*;
use bandnoise_tests::{Lattice, Rng};

/// Step of the central differences: small enough that the truncation error `h²/6·|n'''|` stays
/// near 1e-4, large enough that f32 rounding `ε·|n|/h` stays near 3e-5.
const H: f32 = 1.0 / 512.0;

fn check<const D: usize>(noise: &Lattice, name: &str, rng: &mut Rng) -> f64
where
    Lattice: Noise<f32, D>,
    Perlin: NoiseGradient<f32, D>,
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
        let (value, gradient) = noise.sample_with_gradient(p).expect("a gradient noise");
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

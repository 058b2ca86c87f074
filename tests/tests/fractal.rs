//! Fractal sums: equal to the sum written out by hand, pbrt's footprint clamping, bounded output
//! for any settings the constructors accept, and errors for those they refuse.

use bandnoise::prelude::*;
use bandnoise::{Error, fractal::Kind};
use bandnoise_tests::{Lattice, Rng};

fn perlin_at(p: [f32; 3], freq: f32) -> f32 {
    Perlin::new(0).sample(p.map(|x| x * freq))
}

#[test]
fn fbm_turbulence_and_ridged_are_the_written_out_sums() {
    let octaves = Octaves::new(5, 1.99, 0.5).unwrap();
    let mut rng = Rng::from_env(9);
    for _ in 0..10_000 {
        let p: [f32; 3] = core::array::from_fn(|_| rng.f64_in(-20.0, 20.0) as f32);
        let (mut fbm, mut turb, mut ridged) = (0.0f32, 0.0f32, 0.0f32);
        let (mut freq, mut amp, mut weight) = (1.0f32, 1.0f32, 1.0f32);
        for _ in 0..5 {
            let n = perlin_at(p, freq);
            fbm += amp * n;
            turb += amp * n.abs();
            let r = (1.0 - n.abs()) * (1.0 - n.abs()) * weight;
            weight = (2.0 * r).clamp(0.0, 1.0);
            ridged += amp * r;
            freq *= 1.99;
            amp *= 0.5;
        }
        let sample = |k: Kind| -> f32 { Fractal::new(Perlin::new(0), octaves, k).sample(p) };
        assert_eq!(sample(Kind::Fbm).to_bits(), (fbm + 0.0).to_bits());
        assert_eq!(sample(Kind::Turbulence).to_bits(), turb.to_bits());
        assert_eq!(sample(Kind::Ridged).to_bits(), ridged.to_bits());
    }
}

/// A footprint giving `n = −1 − ½·log2(len²)` octaves.
fn footprint_for(n: f32) -> [f32; 3] {
    [(-(n + 1.0)).exp2(), 0.0, 0.0]
}

#[test]
fn footprint_clamps_octaves_as_pbrt_does() {
    let octaves = Octaves::new(6, 1.99, 0.5).unwrap();
    let fbm = Fractal::fbm(Perlin::new(0), octaves);
    let turb = Fractal::turbulence(Perlin::new(0), octaves);
    let p = [0.3f32, 1.7, -2.2];
    let o = |i: i32| perlin_at(p, 1.99f32.powi(i));
    let zero = [0.0f32; 3];

    // n = 2.5: octaves 0 and 1 in full, octave 2 faded by smoothstep(0.3, 0.7, 0.5) = 0.5.
    let fp = footprint_for(2.5);
    let want = o(0) + 0.5 * o(1) + 0.25 * 0.5 * o(2);
    assert!((fbm.sample_filtered(p, fp, zero) - want).abs() < 1e-6);
    // Turbulence: the faded octave is lerp(0.5, 0.2, |n|); octaves 3, 4, 5 add 0.2 each.
    let want = o(0).abs()
        + 0.5 * o(1).abs()
        + 0.25 * (0.2 + 0.5 * (o(2).abs() - 0.2))
        + 0.2 * (0.125 + 0.0625 + 0.03125);
    assert!((turb.sample_filtered(p, fp, zero) - want).abs() < 1e-6);

    // The larger of the two footprints decides.
    assert_eq!(
        fbm.sample_filtered(p, zero, fp),
        fbm.sample_filtered(p, fp, zero)
    );
    // A zero footprint keeps every octave; an infinite one none (turbulence: all means).
    assert_eq!(fbm.sample_filtered(p, zero, zero), fbm.sample(p));
    let inf = [f32::INFINITY, 0.0, 0.0];
    assert_eq!(fbm.sample_filtered(p, inf, zero), 0.0);
    assert!((turb.sample_filtered(p, inf, zero) - 0.2 * 1.96875).abs() < 1e-6);
    // NaN footprints are unknown: no filtering.
    assert_eq!(
        fbm.sample_filtered(p, [f32::NAN; 3], [f32::NAN; 3]),
        fbm.sample(p)
    );
    // Fixed point takes the same octave decisions.
    let fx = Fractal::fbm(Perlin::new(0), Octaves::new(6, 1.99, 0.5).unwrap());
    let pf = p.map(I16F16::from_num);
    let v = fx.sample_filtered(
        pf,
        footprint_for(2.5).map(I16F16::from_num),
        [I16F16::ZERO; 3],
    );
    assert!((v.to_num::<f32>() - fbm.sample_filtered(p, fp, zero)).abs() < 2e-3);
}

#[test]
fn sums_stay_within_their_bound_for_every_accepted_setting() {
    let mut rng = Rng::from_env(10);
    for (name, noise) in Lattice::all(1) {
        for _ in 0..40 {
            let count = rng.i32_in(1, 31) as u32;
            let lacunarity = rng.f64_in(0.01, 16.0) as f32;
            let gain = rng.f64_in(-1.0, 1.0) as f32;
            for kind in [Kind::Fbm, Kind::Turbulence, Kind::Ridged] {
                let f = Fractal::new(&noise, Octaves::new(count, lacunarity, gain).unwrap(), kind);
                let g = Fractal::new(&noise, Octaves::new(count, lacunarity, gain).unwrap(), kind);
                let bound = Noise::<f32, 3>::amplitude_bound(&f);
                for _ in 0..50 {
                    let p: [f32; 3] = core::array::from_fn(|_| rng.f64_in(-3e4, 3e4) as f32);
                    let d = [rng.f64_in(0.0, 1.0) as f32, 0.0, 0.0];
                    for v in [f.sample(p), f.sample_filtered(p, d, d)] {
                        assert!(
                            v.is_finite() && v.abs() <= bound,
                            "{name} {kind:?} {count} {lacunarity} {gain}: {v} > {bound}"
                        );
                    }
                    let pf = p.map(I16F16::from_num);
                    let df = d.map(I16F16::from_num);
                    for v in [g.sample(pf), g.sample_filtered(pf, df, df)] {
                        assert!(
                            v.to_num::<f32>().abs() <= bound,
                            "{name} {kind:?} fixed: {v} > {bound}"
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn fixed_point_fractals_never_overflow() {
    let f = Fractal::fbm(MNoise::<61>::new(0), Octaves::new(30, 16.0, 1.0).unwrap());
    for x in [I16F16::MIN, I16F16::MAX, I16F16::ZERO, I16F16::DELTA] {
        let _ = f.sample([x, x, x]);
        let _ = f.sample_filtered([x, x], [I16F16::MAX; 2], [I16F16::MIN; 2]);
    }
}

#[test]
fn bad_settings_are_refused_with_a_clear_error() {
    assert_eq!(
        Octaves::new(0, 2.0, 0.5),
        Err(Error::OctaveCount { count: 0, max: 30 })
    );
    assert_eq!(
        Octaves::new(31, 2.0, 0.5),
        Err(Error::OctaveCount { count: 31, max: 30 })
    );
    for bad in [0.0, -1.0, 16.5, f32::INFINITY] {
        assert_eq!(Octaves::new(4, bad, 0.5), Err(Error::Lacunarity(bad)));
    }
    assert!(matches!(
        Octaves::new(4, f32::NAN, 0.5),
        Err(Error::Lacunarity(_))
    ));
    for bad in [1.5, -1.5, f32::NEG_INFINITY] {
        assert_eq!(Octaves::new(4, 2.0, bad), Err(Error::Gain(bad)));
    }
    let e = Fractal::turbulence(Perlin::new(0), Octaves::default()).with_clamped_mean(-1.0);
    assert_eq!(e.unwrap_err(), Error::ClampedMean(-1.0));
    assert_eq!(
        Error::Gain(2.0).to_string(),
        "gain 2 must be finite and in [-1, 1]"
    );
    let d = Octaves::default();
    assert_eq!((d.count(), d.lacunarity(), d.gain()), (6, 1.99, 0.5));
}

//! Wavelet noise with arbitrary coordinates, normals and band lists (weights zero, NaN, huge):
//! no panic; refused configurations are errors; accepted ones give finite values within their
//! documented bounds (uniform distributions within [-1, 1]).
#![no_main]

use arbitrary::Arbitrary;
use bandnoise::wavelet::{
    Bands, Distribution, Multiband, TILE2_I16, TILE3_I16, Wavelet, unit_normal,
};
use bandnoise::{I16F16, Noise};
use libfuzzer_sys::fuzz_target;

#[derive(Arbitrary, Debug)]
struct Input {
    seed: u32,
    coords: [u32; 3],
    normal: [u32; 3],
    first: i32,
    weights: Vec<f32>,
    uniform: bool,
}

fuzz_target!(|input: Input| {
    let p = input.coords.map(f32::from_bits);
    let n = input.normal.map(f32::from_bits);
    let q = input.coords.map(|b| I16F16::from_bits(b as i32));
    let nq = input.normal.map(|b| I16F16::from_bits(b as i32));
    let band3 = Wavelet::new(&TILE3_I16, input.seed);
    let band2 = Wavelet::new(&TILE2_I16, input.seed);
    let b3 = Noise::<f32, 3>::amplitude_bound(&band3);
    for v in [band3.sample(p), band2.sample([p[0], p[1]])] {
        assert!(v.is_finite() && v.abs() <= b3.max(Noise::<f32, 2>::amplitude_bound(&band2)));
    }
    let proj = band3.sample_projected(p, n);
    assert!(proj.is_finite() && proj.abs() <= 3.0 * b3, "{proj}");
    let _: I16F16 = band3.sample(q);
    let _: I16F16 = band3.sample_projected(q, nq);
    let u = unit_normal(n);
    let len2: f32 = u.iter().map(|x| x * x).sum();
    assert!((len2 - 1.0).abs() < 1e-4, "{n:?} → {u:?}");

    let distribution = if input.uniform {
        Distribution::Uniform
    } else {
        Distribution::Gaussian
    };
    match Bands::new(input.first, &input.weights) {
        Err(_) => {
            // Refused: too many bands, a weight not finite or above 1e6, or a first band out of
            // range. Check it was one of those.
            let bad_weight = input
                .weights
                .iter()
                .any(|w| !w.is_finite() || w.abs() > 1e6);
            assert!(input.weights.len() > 16 || bad_weight || !(-24..=8).contains(&input.first));
        }
        Ok(bands) => {
            let m = Multiband::new(&TILE3_I16, input.seed, bands, distribution);
            let bound = Noise::<f32, 3>::amplitude_bound(&m);
            let v: f32 = m.sample(p);
            assert!(v.is_finite() && v.abs() <= bound, "{v} > {bound}");
            let w = m.sample_projected(p, n);
            assert!(w.is_finite() && w.abs() <= m.projected_bound(), "{w}");
            if input.uniform {
                assert!(v.abs() <= 1.0 && w.abs() <= 1.0);
            }
            let _: I16F16 = m.sample(q);
            let _: I16F16 = m.sample_projected(q, nq);
        }
    }
});

//! Fractal sums with arbitrary octave counts, lacunarity, gain, coordinates and footprints:
//! refused settings are errors; accepted ones never panic and stay within their bound (for every
//! noise the runtime description names, `Base::ALL`, in I16F16 and f32); filtered sums are
//! symmetric in their footprints, and NaN or ±∞ coordinates sample 0 there.
#![no_main]

use arbitrary::Arbitrary;
use bandnoise::fractal::{Fractal, Kind, Octaves};
use bandnoise::lattice::{MNoise, Perlin};
use bandnoise::spec::{Base, Spec};
use bandnoise::{FilteredNoise, I16F16, Noise};
use libfuzzer_sys::fuzz_target;

#[derive(Arbitrary, Debug)]
struct Input {
    count: u32,
    lacunarity: f32,
    gain: f32,
    kind: u8,
    base: u8,
    coords: [u32; 3],
    dpdx: [u32; 3],
    dpdy: [u32; 3],
}

fuzz_target!(|input: Input| {
    let kind = [Kind::Fbm, Kind::Turbulence, Kind::Ridged][input.kind as usize % 3];
    let p = input.coords.map(f32::from_bits);
    let (dx, dy) = (
        input.dpdx.map(f32::from_bits),
        input.dpdy.map(f32::from_bits),
    );
    let q = input.coords.map(|b| I16F16::from_bits(b as i32));
    let (qx, qy) = (
        input.dpdx.map(|b| I16F16::from_bits(b as i32)),
        input.dpdy.map(|b| I16F16::from_bits(b as i32)),
    );
    let Ok(octaves) = Octaves::new(input.count, input.lacunarity, input.gain) else {
        let (l, g) = (input.lacunarity, input.gain);
        assert!(
            input.count == 0
                || input.count > 30
                || !(l > 0.0 && l <= 16.0)
                || !(-1.0..=1.0).contains(&g)
        );
        return;
    };
    let fixed = Octaves::new(input.count, input.lacunarity, input.gain).expect("same checks");
    let f = Fractal::new(Perlin::new(1), octaves, kind);
    let bound = Noise::<f32, 3>::amplitude_bound(&f);
    let filtered = f.sample_filtered(p, dx, dy);
    for v in [f.sample(p), filtered] {
        assert!(v.is_finite() && v.abs() <= bound, "{v} > {bound}");
    }
    // The footprint is symmetric in dpdx and dpdy, NaN components included.
    assert_eq!(filtered.to_bits(), f.sample_filtered(p, dy, dx).to_bits());
    // NaN and ±∞ coordinates sample 0 along their axis.
    let p0 = p.map(|c| if c.is_finite() { c } else { 0.0 });
    assert_eq!(filtered.to_bits(), f.sample_filtered(p0, dx, dy).to_bits());
    let g = Fractal::new(MNoise::<61>::new(2), fixed, kind);
    let gb = Noise::<I16F16, 3>::amplitude_bound(&g);
    let filtered = g.sample_filtered(q, qx, qy);
    for v in [g.sample(q), filtered] {
        assert!(v.to_num::<f32>().abs() <= gb, "{v} > {gb}");
    }
    assert_eq!(filtered, g.sample_filtered(q, qy, qx));
    // The same sum of any described noise.
    let base = Base::ALL[usize::from(input.base) % Base::ALL.len()];
    if let Ok(n) = Spec::new(base, 1).with_fractal(kind, octaves).build::<3>() {
        let v: f32 = n.sample(p);
        let b = Noise::<f32, 3>::amplitude_bound(&n);
        assert!(v.is_finite() && v.abs() <= b, "{base}: {v} > {b}");
        let v: I16F16 = n.sample(q);
        let b = Noise::<I16F16, 3>::amplitude_bound(&n);
        assert!(v.to_num::<f32>().abs() <= b, "{base}: {v} > {b}");
    }
});

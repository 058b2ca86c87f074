//! Every impulse noise of the runtime description (`bandnoise::spec::Base`, so one added there
//! is fuzzed unasked) and Wiener noise, with arbitrary settings (density as any f32 bit
//! pattern, counts, kernels, weights; Wiener noise's covariance; Gabor noise's frequency,
//! bandwidth, direction and magnitude as any bit patterns, its orientation and envelope) and
//! arbitrary bit patterns as coordinates and seeds, 1D–4D, in f32 and I16F16:
//! settings are refused for a documented reason or build; samples never panic, are never NaN
//! or -0.0, lie within the documented bound; the gradient's value is the sample's; the batch
//! path equals `sample` bit for bit; fixed point follows f32 where the input is exact in both
//! (and, for Gabor noise, within I16F16's range in kernel radii);
//! Gabor noise's surface sampling and filtering stay within their bounds for any normal and
//! footprint (filtering symmetric in the footprint's two vectors).
#![no_main]

use arbitrary::Arbitrary;
use bandnoise::batch::LANES;
use bandnoise::impulse::{
    Envelope, Gabor, Kernel, MAX_FIXED, MIN_DENSITY, Orientation, RADIUS_TIMES_BANDWIDTH, Weights,
};
use bandnoise::spec::{Base, Spec};
use bandnoise::wiener::Covariance;
use bandnoise::{Error, FilteredNoise, I16F16, Noise, NoiseGradient, ProjectedNoise};
use libfuzzer_sys::fuzz_target;

#[derive(Arbitrary, Debug)]
struct Input {
    /// An index into the impulse noises of `Base::ALL` and Wiener noise.
    base: u8,
    seed: u32,
    /// The density's bits, or (if `fixed`) the count per cell.
    density: u32,
    fixed: bool,
    /// Peachey's kernel, or Wiener noise's band-pass covariance.
    catmull_rom: bool,
    uniform: bool,
    bits: [u32; 4],
    /// Gabor noise: frequency, bandwidth, direction and magnitude bits, orientation, envelope.
    gabor: [u32; 6],
    orientation: u8,
    truncated: bool,
}

fn dim<const D: usize>(spec: &Spec, floats: [f32; 4], fixed: [I16F16; 4], exact: bool)
where
    bandnoise::spec::SpecNoise<D>: NoiseGradient<f32, D> + NoiseGradient<I16F16, D> + Noise<f64, D>,
{
    let noise = match spec.build::<D>() {
        Ok(n) => n,
        Err(Error::Density { density, max, .. }) => {
            // The spec's range is the widest (4D); each dimension's own is narrower.
            assert!(density > max, "{spec} refused in {D}D");
            return;
        }
        Err(Error::Dimension { .. }) => {
            assert!(!spec.base().has_dimension(D), "{spec} refused in {D}D");
            return;
        }
        Err(Error::Direction) => {
            // A direction whose first D components are (nearly) 0.
            let direction = spec.direction();
            let length: f64 = direction.iter().take(D).map(|&c| c as f64 * c as f64).sum();
            assert!(length < 1e-60, "{spec} refused in {D}D");
            return;
        }
        Err(e) => panic!("{spec} in {D}D: {e}"),
    };
    let p: [f32; D] = core::array::from_fn(|a| floats[a]);
    let q: [I16F16; D] = core::array::from_fn(|a| fixed[a]);
    let bound = Noise::<f32, D>::amplitude_bound(&noise);
    let v: f32 = noise.sample(p);
    assert!(
        !v.is_nan() && v.abs() <= bound,
        "{spec} {D}D {p:?}: {v} (bound {bound})"
    );
    assert_ne!(v.to_bits(), (-0.0f32).to_bits());
    let (gv, g) = noise.sample_with_gradient(p);
    assert_eq!(gv.to_bits(), v.to_bits(), "{spec} {D}D {p:?}");
    assert!(g.iter().all(|d| d.is_finite()), "{spec} {p:?}: {g:?}");
    let w: I16F16 = noise.sample(q);
    assert!(
        w.to_num::<f32>().abs() <= bound,
        "{spec} {D}D fixed {q:?}: {w}"
    );
    assert_eq!(noise.sample_with_gradient(q).0, w);
    let lanes: [[f32; LANES]; D] =
        core::array::from_fn(|a| core::array::from_fn(|l| p[a] + l as f32 * 0.25));
    let mut out = [0.0f32; LANES];
    noise.sample_lanes(&lanes, &mut out);
    for (l, o) in out.iter().enumerate() {
        let x: [f32; D] = core::array::from_fn(|a| lanes[a][l]);
        assert_eq!(
            o.to_bits(),
            noise.sample(x).to_bits(),
            "{spec} {D}D batch {x:?}"
        );
    }
    // Gabor noise takes the point to cell units, which wraps in I16F16 from 2^15 kernel radii
    // (its docs, "Fixed point"): from there fixed point reads other cells than f32 (found by
    // this target at a = 127.6, x = 255.2).
    let in_cells = spec.base() != Base::Gabor || {
        let to_cells = f64::from(spec.spectrum().1) / RADIUS_TIMES_BANDWIDTH;
        q.iter()
            .all(|x| x.to_num::<f64>().abs() * to_cells < 32767.0)
    };
    if exact && in_cells {
        // Fixed point against f64 at the same point (f64 is the same noise, its roundings
        // far below; f32's own rounding of the point in cell units, up to 2⁻⁹ cell at 2¹⁵
        // cells, is not fixed point's error: against f32 this check failed at x = 125.25,
        // 25,000 cells, with fixed point within 0.01 of f64 and f32 off by 1.2).
        //
        // Each impulse in reach (at most 3^D·cap of them; Wiener noise: lattice points, at
        // most (2r)^D) is off by at most 1e-4 (the table's I16F16 error) plus its squared
        // distance's rounding times the table's slope (2⁻¹⁵·10), scaled by 1/σ: in all at
        // most that times amplitude_bound.
        //
        // Gabor noise adds, per impulse, the harmonic's error: a cosine table's (1e-4) per
        // axis (kernels along the noise's direction join one share per axis, each with its
        // turn's and products' roundings) and its phase's rounding in fixed point (the
        // offset's 2⁻¹⁶ per axis times the turns per kernel radius, the wave vector's and the
        // sum's roundings), times 2π; the truncated envelope jumps by 0.05 at the rim, which
        // a rounding can cross.
        let qd: [f64; D] = core::array::from_fn(|a| fixed[a].to_num::<f64>());
        let vd: f64 = noise.sample(qd);
        let mut per_impulse = 1e-4 + 10.0 / 32768.0;
        if spec.base() == Base::Gabor {
            let (f0, a) = spec.spectrum();
            let turns = f0 as f64 * RADIUS_TIMES_BANDWIDTH / a as f64;
            let phase = (turns * (D as f64 + 1.0) + 2.0 * D as f64 + 2.0) / 65536.0;
            let table = D as f64 * (1e-4 + 4.0 / 65536.0);
            per_impulse += (table + std::f64::consts::TAU * phase) as f32;
            if spec.envelope() == Envelope::Truncated {
                per_impulse += 0.05;
            }
        }
        let tolerance = per_impulse * bound + 1.0 / 4096.0;
        assert!(
            (w.to_num::<f64>() - vd).abs() <= f64::from(tolerance),
            "{spec} {D}D {q:?}: {w} vs {vd} (tolerance {tolerance})"
        );
    }
}

/// The impulse settings of `input` on `spec`: `None` where they are refused (for the
/// documented reason).
fn impulse_settings(mut spec: Spec, input: &Input) -> Option<Spec> {
    if input.catmull_rom {
        let kernel = spec.with_kernel(Kernel::CatmullRom);
        if spec.base() == Base::Sparse {
            spec = kernel.expect("sparse noise");
        } else {
            assert_eq!(kernel, Err(Error::NotImpulse(spec.base().name())));
        }
    }
    if input.uniform {
        spec = spec
            .with_weights(Weights::Uniform)
            .expect("an impulse noise");
    }
    let set = if input.fixed {
        spec.with_fixed_count(input.density)
    } else {
        spec.with_density(f32::from_bits(input.density))
    };
    match set {
        Ok(s) => Some(s),
        Err(Error::ImpulseCount { count, max }) => {
            assert!(count == 0 || count > max, "{count} refused");
            assert_eq!(max, MAX_FIXED);
            None
        }
        Err(Error::Density { density, min, max }) => {
            assert!(!(min..=max).contains(&density), "{density} refused");
            assert_eq!(min, MIN_DENSITY);
            None
        }
        Err(e) => panic!("{spec}: {e}"),
    }
}

/// Gabor noise's settings from `input`: `None` where they are refused (for the documented
/// reason).
fn gabor_settings(mut spec: Spec, input: &Input) -> Option<Spec> {
    let [f, a, x, y, z, k] = input.gabor.map(f32::from_bits);
    match spec.with_spectrum(f, a) {
        Ok(s) => spec = s,
        Err(Error::Bandwidth(b)) => {
            assert!(!(1.0 / 256.0..=256.0).contains(&b), "{b} refused");
            return None;
        }
        Err(Error::Frequency { frequency, .. }) => {
            assert!(
                !(0.0..=64.0 * a).contains(&frequency),
                "{frequency} refused"
            );
            return None;
        }
        Err(e) => panic!("{e}"),
    }
    match spec.with_direction(&[x, y, z]) {
        Ok(s) => spec = s,
        Err(Error::Direction) => {
            let finite = [x, y, z].iter().all(|c| c.is_finite());
            let length = [x, y, z].iter().map(|&c| c as f64 * c as f64).sum::<f64>();
            assert!(
                !finite || !(1e-60..).contains(&length),
                "{x} {y} {z} refused"
            );
            return None;
        }
        Err(e) => panic!("{e}"),
    }
    match spec.with_magnitude(k) {
        Ok(s) => spec = s,
        Err(Error::Magnitude(m)) => {
            assert!(!(-1024.0..=1024.0).contains(&m), "{m} refused");
            return None;
        }
        Err(e) => panic!("{e}"),
    }
    let orientations = [
        Orientation::Anisotropic,
        Orientation::Isotropic,
        Orientation::Hybrid,
    ];
    spec = spec
        .with_orientation(orientations[usize::from(input.orientation) % 3])
        .expect("Gabor noise");
    if input.truncated {
        spec = spec
            .with_envelope(Envelope::Truncated)
            .expect("Gabor noise");
    }
    Some(spec)
}

fuzz_target!(|input: Input| {
    let bases: Vec<Base> = Base::ALL
        .into_iter()
        .filter(|&b| b.is_impulse() || b == Base::Wiener)
        .collect();
    let Some(&base) = bases.get(usize::from(input.base) % bases.len().max(1)) else {
        return;
    };
    let mut spec = Spec::new(base, input.seed);
    if base == Base::Wiener {
        if input.catmull_rom {
            spec = spec
                .with_covariance(Covariance::BandPass)
                .expect("Wiener noise");
        }
        assert_eq!(spec.with_density(1.0), Err(Error::NotImpulse("wiener")));
    } else {
        if base == Base::Gabor {
            let Some(set) = gabor_settings(spec, &input) else {
                return;
            };
            spec = set;
        } else {
            assert_eq!(
                spec.with_spectrum(1.0, 1.0),
                Err(Error::NotGabor(base.name()))
            );
        }
        let Some(set) = impulse_settings(spec, &input) else {
            return;
        };
        spec = set;
    }
    let floats = input.bits.map(f32::from_bits);
    let fixed = input.bits.map(|b| I16F16::from_bits(b as i32));
    let exact = fixed.iter().all(|x| x.to_bits().unsigned_abs() < 256 << 16);
    dim::<1>(&spec, floats, fixed, exact);
    dim::<2>(&spec, floats, fixed, exact);
    dim::<3>(&spec, floats, fixed, exact);
    dim::<4>(&spec, floats, fixed, exact);
    if base == Base::Gabor {
        surface_and_filtered(&spec, floats, fixed);
    }
});

/// Gabor noise's surface sampling (any normal) and filtering (any footprint), f32 and
/// I16F16: a value within the bound, never NaN or −0.0; filtering symmetric in its two
/// footprint vectors.
fn surface_and_filtered(spec: &Spec, floats: [f32; 4], fixed: [I16F16; 4]) {
    let (f0, a) = spec.spectrum();
    let d = spec.direction();
    let typed = |dims: usize| {
        let mut direction = [0.0f32; 3];
        direction[..dims].copy_from_slice(&d[..dims]);
        (Gabor::<3>::new(spec.seed()).with_spectrum(f0, a), direction)
    };
    let (three, direction) = typed(3);
    let three = three
        .expect("checked by the spec")
        .with_orientation(spec.orientation())
        .with_envelope(spec.envelope())
        .with_weights(spec.weights());
    if let Ok(g) = three.with_direction(direction) {
        let bound = ProjectedNoise::<f32>::projected_bound(&g);
        let p = [floats[0], floats[1], floats[2]];
        let n = [floats[3], floats[1], floats[0]];
        let v: f32 = g.sample_projected(p, n);
        assert!(
            !v.is_nan() && v.abs() <= bound,
            "{spec} surface {p:?} {n:?}: {v}"
        );
        assert_ne!(v.to_bits(), (-0.0f32).to_bits());
        let q = [fixed[0], fixed[1], fixed[2]];
        let m = [fixed[3], fixed[1], fixed[0]];
        let w: I16F16 = g.sample_projected(q, m);
        assert!(
            w.to_num::<f32>().abs() <= bound,
            "{spec} surface {q:?} {m:?}: {w}"
        );
    }
    let two = Gabor::<2>::new(spec.seed())
        .with_spectrum(f0, a)
        .expect("checked by the spec")
        .with_orientation(spec.orientation())
        .with_envelope(spec.envelope())
        .with_weights(spec.weights());
    if let Ok(g) = two.with_direction([d[0], d[1]]) {
        let bound = Noise::<f32, 2>::amplitude_bound(&g);
        let (p, dx, dy) = (
            [floats[0], floats[1]],
            [floats[2], floats[3]],
            [floats[1], floats[2]],
        );
        let v: f32 = g.sample_filtered(p, dx, dy);
        assert!(
            !v.is_nan() && v.abs() <= bound,
            "{spec} filtered {p:?} {dx:?} {dy:?}: {v}"
        );
        assert_ne!(v.to_bits(), (-0.0f32).to_bits());
        assert_eq!(v.to_bits(), g.sample_filtered(p, dy, dx).to_bits());
        let (q, qx, qy) = (
            [fixed[0], fixed[1]],
            [fixed[2], fixed[3]],
            [fixed[1], fixed[2]],
        );
        let w: I16F16 = g.sample_filtered(q, qx, qy);
        assert!(
            w.to_num::<f32>().abs() <= bound,
            "{spec} filtered {q:?}: {w}"
        );
        assert_eq!(w, g.sample_filtered(q, qy, qx));
    }
}

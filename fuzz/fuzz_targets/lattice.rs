//! Every lattice noise of the runtime description (`bandnoise::spec::Base`, so a lattice noise
//! added there is fuzzed unasked), simplex noise, white and cubic value noise (either
//! distribution) and cellular noise (its output, metric and jitter from the input; a cell value is not compared across number types, since rounding can
//! change which point is nearest), sampled through the description (bit for bit the typed
//! noise: api-tests/tests/spec.rs), 1D–4D, in f32 and I16F16, with arbitrary bit patterns as
//! coordinates and seeds: no panic, never NaN or -0.0, within the documented bound; fixed point
//! and f32 agree within 2⁻¹¹ (simplex noise 2⁻¹⁰: its scale and its kernel's fourth power
//! amplify fixed point's roundings) where the input is exact in both; gradients are finite; the batch
//! path (`sample_lanes`) equals `sample` bit for bit. Periodic noise with arbitrary periods:
//! refused outside 1..=65536 (and for simplex and cellular noise; lattice, white and cubic
//! value noise take one), otherwise within the bound and periodic
//! bit for bit in fixed point. Curl noise over simplex and Perlin noise: finite, bounded.
//! OpenSimplex2 and OpenSimplex2S (seed and orientation from the input): within their bounds,
//! batches equal to points, gradients finite. The textures (settings from the input's bits:
//! refused out of range, otherwise within their ranges, colours in `[0, 1]`, batches equal to
//! points).
#![no_main]

use arbitrary::Arbitrary;
use bandnoise::batch::LANES;
use bandnoise::cellular::{Metric, Output};
use bandnoise::fractal::{Fractal, Octaves};
use bandnoise::lattice::{MNoise, MixedMNoise, MixedTurbulence, Perlin, TabledPerlin};
use bandnoise::simplex::{Flow, Improve, OpenSimplex2, OpenSimplex2S, Simplex};
use bandnoise::spec::{Base, Spec, SpecNoise};
use bandnoise::texture::{Marble, PolkaDots, Texture, Windy, Wood, Wrinkled};
use bandnoise::vector::{Components, Curl2, Curl3, VectorNoise, Warp};
use bandnoise::wavelet::Distribution;
use bandnoise::{FilteredNoise, I16F16, Noise, NoiseGradient};
use libfuzzer_sys::fuzz_target;

#[derive(Arbitrary, Debug)]
struct Input {
    /// Which noise: an index into `Base::ALL` (the lattice ones; the wavelet target has the
    /// others), so a lattice noise added to the description is fuzzed here unasked.
    base: u8,
    seed: u32,
    bits: [u32; 4],
    periods: [u32; 3],
}

/// One dimension of `noise`: bounded, never NaN or -0.0, the batch path equal to the point
/// path, fixed point and f32 close where the input is exact in both.
fn dim<const D: usize, N>(noise: &N, floats: [f32; 4], fixed: [I16F16; 4], exact: f32)
where
    N: Noise<f32, D> + Noise<I16F16, D>,
{
    let p: [f32; D] = core::array::from_fn(|a| floats[a]);
    let q: [I16F16; D] = core::array::from_fn(|a| fixed[a]);
    let bound = Noise::<f32, D>::amplitude_bound(noise);
    let v: f32 = noise.sample(p);
    assert!(
        !v.is_nan() && v.abs() <= bound,
        "{D}D f32 {p:?}: {v} (bound {bound})"
    );
    assert_ne!(v.to_bits(), (-0.0f32).to_bits());
    let w: I16F16 = noise.sample(q);
    assert!(w.to_num::<f32>().abs() <= bound, "{D}D fixed {q:?}: {w}");
    // The batch path equals the point path bit for bit: the input in lane 0, its neighbours a
    // quarter cell apart in the other lanes (a mixed chunk for specials).
    let lanes: [[f32; LANES]; D] =
        core::array::from_fn(|a| core::array::from_fn(|l| p[a] + l as f32 * 0.25));
    let mut out = [0.0f32; LANES];
    noise.sample_lanes(&lanes, &mut out);
    for (l, o) in out.iter().enumerate() {
        let x: [f32; D] = core::array::from_fn(|a| lanes[a][l]);
        let s: f32 = noise.sample(x);
        assert_eq!(o.to_bits(), s.to_bits(), "{D}D f32 batch {x:?}");
    }
    let lanes: [[I16F16; LANES]; D] = core::array::from_fn(|a| {
        core::array::from_fn(|l| q[a].wrapping_add(I16F16::from_bits((l as i32) << 14)))
    });
    let mut out = [I16F16::ZERO; LANES];
    noise.sample_lanes(&lanes, &mut out);
    for (l, o) in out.iter().enumerate() {
        let x: [I16F16; D] = core::array::from_fn(|a| lanes[a][l]);
        let s: I16F16 = noise.sample(x);
        assert_eq!(*o, s, "{D}D fixed batch {x:?}");
    }
    if exact > 0.0 {
        let qf: [f32; D] = core::array::from_fn(|a| fixed[a].to_num::<f32>());
        let vf: f32 = noise.sample(qf);
        assert!(
            (w.to_num::<f32>() - vf).abs() <= exact,
            "{D}D {q:?}: {w} vs {vf}"
        );
    }
}

/// The noise of `spec` in every dimension; `exact` is fixed point's tolerance against `f32`
/// where the input is exact in both (0: not exact).
fn check(spec: &Spec, floats: [f32; 4], fixed: [I16F16; 4], exact: f32) {
    let built = (
        spec.build::<1>(),
        spec.build::<2>(),
        spec.build::<3>(),
        spec.build::<4>(),
    );
    let (Ok(n1), Ok(n2), Ok(n3), Ok(n4)) = built else {
        panic!("{spec}: every lattice noise has 1D to 4D");
    };
    dim::<1, _>(&n1, floats, fixed, exact);
    dim::<2, _>(&n2, floats, fixed, exact);
    dim::<3, _>(&n3, floats, fixed, exact);
    dim::<4, _>(&n4, floats, fixed, exact);
    gradients(&n2, &n3, floats, fixed);
}

fn gradients(two: &SpecNoise<2>, three: &SpecNoise<3>, floats: [f32; 4], fixed: [I16F16; 4]) {
    let (v, g) = three.sample_with_gradient([floats[0], floats[1], floats[2]]);
    assert!(
        v.is_finite() && g.iter().all(|d| d.is_finite()),
        "{floats:?}: {v} {g:?}"
    );
    let (_, g) = two.sample_with_gradient([fixed[0], fixed[1]]);
    // Gradient components are bounded by a few units per lattice cell.
    assert!(g.iter().all(|d| d.abs() < I16F16::from_num(64)));
}

/// `spec` wrapped to `periods`: refused for a documented reason, or bounded and periodic.
fn periodic(spec: &Spec, periods: [u32; 3], floats: [f32; 4], fixed: [I16F16; 4]) {
    let Ok(n) = spec.with_period(&periods).and_then(|s| s.build::<3>()) else {
        assert!(
            periods.iter().any(|&p| p == 0 || p > 65536),
            "{periods:?} refused"
        );
        return;
    };
    let p = [floats[0], floats[1], floats[2]];
    let bound = Noise::<f32, 3>::amplitude_bound(&n);
    let v: f32 = n.sample(p);
    assert!(!v.is_nan() && v.abs() <= bound, "{periods:?} {p:?}: {v}");
    let q = [fixed[0], fixed[1], fixed[2]];
    let w: I16F16 = n.sample(q);
    assert!(w.to_num::<f32>().abs() <= bound);
    // n(q + P) == n(q) along each axis, where q + P fits I16F16.
    for a in 0..3 {
        let shift = I16F16::checked_from_num(periods[a]);
        if let Some(moved) = shift.and_then(|s| q[a].checked_add(s)) {
            let mut r = q;
            r[a] = moved;
            assert_eq!(
                Noise::<I16F16, 3>::sample(&n, r),
                w,
                "{periods:?} {q:?} axis {a}"
            );
        }
    }
}

/// Cellular noise for `seed` with the output, metric and jitter `bits` pick.
fn cellular(seed: u32, bits: [u32; 3]) -> Spec {
    let spec = Spec::new(Base::Cellular, seed);
    let jitter = (bits[2] % 65_537) as f32 / 65_536.0;
    spec.with_output(Output::ALL[bits[0] as usize % 4])
        .and_then(|s| s.with_metric(Metric::ALL[bits[1] as usize % 4]))
        .and_then(|s| s.with_jitter(jitter))
        .expect("cellular settings in range")
}

/// Perlin with its per-seed table is Perlin, bit for bit, where the table's kernel runs (f32 2D,
/// 3D and 4D; on x86-64 a different kernel from `Perlin`'s).
fn tabled(seed: u32, floats: [f32; 4]) {
    let (perlin, tabled) = (Perlin::new(seed), TabledPerlin::new(seed));
    let [x, y, z, _] = floats;
    let (a, b): (f32, f32) = (perlin.sample([x, y]), tabled.sample([x, y]));
    assert_eq!(a.to_bits(), b.to_bits(), "2D {x} {y}");
    let (a, b): (f32, f32) = (perlin.sample([x, y, z]), tabled.sample([x, y, z]));
    assert_eq!(a.to_bits(), b.to_bits(), "3D {x} {y} {z}");
    let (a, b): (f32, f32) = (perlin.sample(floats), tabled.sample(floats));
    assert_eq!(a.to_bits(), b.to_bits(), "4D {floats:?}");
}

/// mNoise from Olano's table is the computed mNoise, bit for bit, in 2D–4D in f32 and I16F16,
/// and so is its turbulence (3D, 4 octaves) the fractal sum's.
fn mixed(seed: u32, floats: [f32; 4], fixed: [I16F16; 4]) {
    let (computed, mixed) = (MNoise::<61>::new(seed), MixedMNoise::new(seed));
    let [x, y, z, w] = floats;
    for (a, b) in [
        (computed.sample([x, y]), mixed.sample([x, y])),
        (computed.sample([x, y, z]), mixed.sample([x, y, z])),
        (computed.sample(floats), mixed.sample(floats)),
    ] {
        let (a, b): (f32, f32) = (a, b);
        assert_eq!(a.to_bits(), b.to_bits(), "{floats:?}");
    }
    let q = [fixed[0], fixed[1], fixed[2]];
    let (a, b): (I16F16, I16F16) = (computed.sample(q), mixed.sample(q));
    assert_eq!(a, b, "{fixed:?}");
    let (a, b): (I16F16, I16F16) = (computed.sample(fixed), mixed.sample(fixed));
    assert_eq!(a, b, "{fixed:?}");
    let octaves = Octaves::new(4, 2.0, 0.5).expect("valid octaves");
    let sum = Fractal::turbulence(computed, octaves);
    let together = MixedTurbulence::<4>::new(seed);
    let (a, b): (I16F16, I16F16) = (sum.sample(q), together.sample(q));
    assert_eq!(a, b, "turbulence {fixed:?}");
    let (a, b): (f32, f32) = (sum.sample([x, y, w]), together.sample([x, y, w]));
    assert_eq!(a.to_bits(), b.to_bits(), "turbulence {floats:?}");
}

/// Perlin noise warped by simplex noise with an amplitude from the input's bits: refused unless
/// finite and within ±1024, otherwise within Perlin's bound with a finite gradient.
fn warp(seed: u32, amplitude: f32, floats: [f32; 4], fixed: [I16F16; 4]) {
    let field = Components::new([Simplex::new(seed ^ 3), Simplex::new(seed ^ 4)]);
    let Ok(w) = Warp::new(Perlin::new(seed), field, amplitude) else {
        assert!(
            amplitude.is_nan() || amplitude.abs() > 1024.0,
            "{amplitude} refused"
        );
        return;
    };
    let bound = w.amplitude_bound::<2>();
    let v: f32 = w.sample([floats[0], floats[1]]);
    let (_, g) = w.sample_with_gradient([floats[0], floats[1]]);
    assert!(v.is_finite() && v.abs() <= bound && g.iter().all(|c| c.is_finite()));
    let q: I16F16 = w.sample([fixed[0], fixed[1]]);
    assert!(q.to_num::<f32>().abs() <= bound, "{fixed:?}: {q}");
}

/// Flow noise at an angle from the input's bits: refused unless finite, otherwise within its
/// bound with a finite gradient, fixed point near f32 where the input is exact in both, and
/// the batch path equal to the point path.
fn flow(seed: u32, angle: f32, floats: [f32; 4], fixed: [I16F16; 4], exact: f32) {
    let Ok(f) = Flow::new(seed).with_angle(angle) else {
        assert!(!angle.is_finite(), "{angle} refused");
        return;
    };
    dim::<2, _>(&f, floats, fixed, exact);
    let (v, g) = f.sample_with_gradient([floats[0], floats[1]]);
    assert!(
        v.is_finite() && g.iter().all(|c| c.is_finite()),
        "{floats:?}"
    );
}

/// The textures in 2D and 3D: pbrt's, Lewis's and Olano's with their defaults, polka dots of a
/// radius and chance, marble and wood of a scale, variation, rings and amount from the input's
/// bits (refused unless in range); each within its range with colours in `[0, 1]` and batches
/// equal to points. (Fixed point is not compared with f32: the wood's rings, the dots' edges
/// and the marble's sine turn small differences into large ones.)
fn textures(seed: u32, bits: [u32; 3], floats: [f32; 4], fixed: [I16F16; 4]) {
    fn both<T: Texture<f32, 2> + Texture<f32, 3> + Texture<I16F16, 2> + Texture<I16F16, 3>>(
        t: &T,
        floats: [f32; 4],
        fixed: [I16F16; 4],
    ) {
        dim::<2, _>(t, floats, fixed, 0.0);
        dim::<3, _>(t, floats, fixed, 0.0);
        let p = [floats[0], floats[1], floats[2]];
        let q = [fixed[0], fixed[1], fixed[2]];
        assert!(t.color(p).iter().all(|c| (0.0..=1.0).contains(c)), "{p:?}");
        assert!(t.color(q).iter().all(|c| *c >= 0 && *c <= 1), "{q:?}");
        let unit: f32 = t.pattern(p);
        assert!((0.0..=1.0).contains(&unit), "{p:?}: {unit}");
    }
    both(&Windy::new(seed), floats, fixed);
    both(&Wrinkled::new(seed), floats, fixed);
    both(&Marble::new(seed), floats, fixed);
    both(&Marble::olano(seed), floats, fixed);
    both(&Wood::new(seed), floats, fixed);
    both(&Wood::olano(seed), floats, fixed);
    let [a, b, c] = bits.map(f32::from_bits);
    let d = f32::from_bits(seed.rotate_left(7));
    match PolkaDots::new(seed)
        .with_radius(a)
        .and_then(|t| t.with_chance(b))
    {
        Ok(dots) => {
            both(&dots, floats, fixed);
            let footprint = [floats[3], floats[2]];
            let v: f32 = dots.sample_filtered([floats[0], floats[1]], footprint, footprint);
            assert!((0.0..=1.0).contains(&v), "{floats:?}: {v}");
            let q = [fixed[0], fixed[1]];
            let w: I16F16 = dots.sample_filtered(q, [fixed[3], fixed[2]], [fixed[2], fixed[3]]);
            assert!(w >= 0 && w <= 1, "{fixed:?}: {w}");
        }
        Err(_) => assert!(!((0.0..=0.5).contains(&a) && (0.0..=1.0).contains(&b))),
    }
    match Marble::with_noise(Perlin::new(seed), c, d) {
        Ok(marble) => both(&marble, floats, fixed),
        Err(_) => assert!(!(c.abs() <= 1024.0 && d.abs() <= 1024.0)),
    }
    match Wood::with_noise(Perlin::new(seed), c, d) {
        Ok(wood) => both(&wood, floats, fixed),
        Err(_) => assert!(!((1.0 / 65536.0..=1024.0).contains(&c) && d.abs() <= 1024.0)),
    }
}

/// OpenSimplex2 and OpenSimplex2S in 1D–4D for a seed and orientation from the input: within
/// their bounds in both number types, the batch path equal to the point path, the gradient
/// finite. (Fixed point is not compared with f32: both can fall on either side of the
/// reference's small jumps.)
fn open_simplex(seed: u32, bits: u32, floats: [f32; 4], fixed: [I16F16; 4]) {
    let improve = [Improve::Standard, Improve::XY, Improve::XZ][bits as usize % 3];
    let seed = i64::from(seed) << 32 | i64::from(bits);
    let fast = OpenSimplex2::new(seed).improving(improve);
    let smooth = OpenSimplex2S::new(seed).improving(improve);
    dim::<1, _>(&fast, floats, fixed, 0.0);
    dim::<2, _>(&fast, floats, fixed, 0.0);
    dim::<3, _>(&fast, floats, fixed, 0.0);
    dim::<4, _>(&fast, floats, fixed, 0.0);
    dim::<1, _>(&smooth, floats, fixed, 0.0);
    dim::<2, _>(&smooth, floats, fixed, 0.0);
    dim::<3, _>(&smooth, floats, fixed, 0.0);
    dim::<4, _>(&smooth, floats, fixed, 0.0);
    let (v, g) = fast.sample_with_gradient(floats);
    let (w, h) = smooth.sample_with_gradient([floats[0], floats[1], floats[2]]);
    assert!(
        [v, w].iter().chain(&g).chain(&h).all(|c| c.is_finite()),
        "{floats:?}"
    );
}

/// Curl noise over simplex noise (2D) and three Perlin noises (3D): finite, and in fixed
/// point bounded by the potentials' gradients (a few units per cell).
fn curl(seed: u32, floats: [f32; 4], fixed: [I16F16; 4]) {
    let flow = Curl2::new(Simplex::new(seed));
    let flow3 = Curl3::new(
        Perlin::new(seed),
        Perlin::new(seed ^ 1),
        Perlin::new(seed ^ 2),
    );
    let v: [f32; 2] = flow.sample_vector([floats[0], floats[1]]);
    let w: [f32; 3] = flow3.sample_vector([floats[0], floats[1], floats[2]]);
    assert!(
        v.iter().chain(&w).all(|c| c.is_finite()),
        "{floats:?}: {v:?} {w:?}"
    );
    let v: [I16F16; 2] = flow.sample_vector([fixed[0], fixed[1]]);
    let w: [I16F16; 3] = flow3.sample_vector([fixed[0], fixed[1], fixed[2]]);
    let limit = I16F16::from_num(64);
    assert!(
        v.iter().chain(&w).all(|c| c.abs() < limit),
        "{fixed:?}: {v:?} {w:?}"
    );
}

fuzz_target!(|input: Input| {
    let base = Base::ALL[usize::from(input.base) % Base::ALL.len()];
    let values = matches!(base, Base::White | Base::ValueCubic);
    if !base.is_lattice() && !values && !matches!(base, Base::Simplex | Base::Cellular) {
        return;
    }
    let floats = input.bits.map(f32::from_bits);
    let fixed = input.bits.map(|b| I16F16::from_bits(b as i32));
    // Fixed-point inputs that f32 holds exactly: |x| < 256 (24 significant bits).
    let exact = fixed.iter().all(|x| x.to_bits().unsigned_abs() < 256 << 16);
    let spec = if base == Base::Cellular {
        cellular(input.seed, input.periods)
    } else if values {
        let d = [Distribution::Uniform, Distribution::Gaussian][input.periods[0] as usize % 2];
        Spec::new(base, input.seed)
            .with_distribution(d)
            .expect("a distribution for white and cubic value noise")
    } else {
        Spec::new(base, input.seed)
    };
    let tolerance = match (exact, base) {
        (false, _) => 0.0,
        (true, Base::Simplex) => 1.0 / 1024.0,
        // A cell value jumps where fixed point's rounding makes another point the nearest.
        (true, Base::Cellular) if spec.output() == Output::CellValue => 0.0,
        (true, _) => 1.0 / 2048.0,
    };
    check(&spec, floats, fixed, tolerance);
    if base == Base::Simplex {
        assert!(spec.with_period(&input.periods).is_err());
        curl(input.seed, floats, fixed);
        warp(input.seed, f32::from_bits(input.periods[1]), floats, fixed);
        let angle = f32::from_bits(input.periods[2]);
        flow(input.seed, angle, floats, fixed, tolerance);
        open_simplex(input.seed, input.periods[0], floats, fixed);
    } else if base == Base::Cellular {
        assert!(spec.with_period(&input.periods).is_err());
    } else {
        periodic(&spec, input.periods, floats, fixed);
    }
    if base == Base::Perlin {
        tabled(input.seed, floats);
        textures(input.seed, input.periods, floats, fixed);
    }
    if base == Base::MNoise {
        mixed(input.seed, floats, fixed);
    }
});

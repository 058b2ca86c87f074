//! The runtime description (`bandnoise::spec`): every variant samples the typed noise it
//! describes bit for bit, the text form round-trips, bad text is an error with a position (never
//! a panic), and every noise type of the crate is described.

use bandnoise::cellular::{Cellular, Metric, Output};
use bandnoise::impulse::{Envelope, Gabor, Orientation};
use bandnoise::impulse::{Kernel, SparseConvolution, Weights};
use bandnoise::lattice::{CubicValueNoise, WhiteNoise};
use bandnoise::prelude::*;
use bandnoise::spec::{Base, ParseError, Spec, SpecNoise};
use bandnoise::spec::{I16Tiles, Tiles};
use bandnoise::wavelet::{Bands, Distribution, Multiband, TILE2_I16, TILE3_I16, Tiling};
use bandnoise::wiener::{Covariance, WienerNoise};
use bandnoise::{Error, batch::Grid};
use bandnoise_tests::{AllTypes, Rng};

/// A noise in `D` dimensions with gradients, in every number type.
trait Checked<const D: usize>: AllTypes<D> + NoiseGradient<f32, D> + NoiseGradient<I16F16, D> {}
impl<const D: usize, T: AllTypes<D> + NoiseGradient<f32, D> + NoiseGradient<I16F16, D>> Checked<D>
    for T
{
}

/// `built` against `typed`: samples in every number type, gradients, a grid and points.
fn same<const D: usize>(
    what: &str,
    built: &impl Checked<D>,
    typed: &impl Checked<D>,
    rng: &mut Rng,
) {
    for _ in 0..300 {
        let p: [f32; D] = core::array::from_fn(|_| rng.f64_in(-300.0, 300.0) as f32);
        let (a, b): (f32, f32) = (built.sample(p), typed.sample(p));
        assert_eq!(a.to_bits(), b.to_bits(), "{what} f32 at {p:?}");
        let q = p.map(f64::from);
        let (a, b): (f64, f64) = (built.sample(q), typed.sample(q));
        assert_eq!(a.to_bits(), b.to_bits(), "{what} f64 at {p:?}");
        let r = p.map(I16F16::from_num);
        let (a, b): (I16F16, I16F16) = (built.sample(r), typed.sample(r));
        assert_eq!(a, b, "{what} I16F16 at {p:?}");
        let (a, b) = (
            NoiseGradient::<f32, D>::sample_with_gradient(built, p),
            NoiseGradient::<f32, D>::sample_with_gradient(typed, p),
        );
        assert_eq!(a, b, "{what} gradient at {p:?}");
        let (a, b) = (
            NoiseGradient::<I16F16, D>::sample_with_gradient(built, r),
            NoiseGradient::<I16F16, D>::sample_with_gradient(typed, r),
        );
        assert_eq!(a, b, "{what} I16F16 gradient at {p:?}");
    }
    same_grid_and_bound(what, built, typed);
}

/// `built` and `typed` fill an off-lattice grid (step not a power-of-two fraction of a cell)
/// with the same bits in f32, and have the same bound.
fn same_grid_and_bound<const D: usize>(
    what: &str,
    built: &impl Noise<f32, D>,
    typed: &impl Noise<f32, D>,
) {
    let grid = Grid::<f32, D>::new(
        [-3.3; D],
        [0.37; D],
        core::array::from_fn(|a| [40, 3, 2, 2][a]),
    );
    let (mut a, mut b) = (vec![0.0f32; grid.len()], vec![0.0f32; grid.len()]);
    built.fill_grid(&grid, &mut a).expect("sized");
    typed.fill_grid(&grid, &mut b).expect("sized");
    assert_eq!(
        a.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
        b.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
        "{what} grid"
    );
    assert_eq!(
        built.amplitude_bound(),
        typed.amplitude_bound(),
        "{what} bound"
    );
}

const KINDS: [Kind; 3] = [Kind::Fbm, Kind::Turbulence, Kind::Ridged];

/// A lattice noise: plain, periodic, summed, and summed over periodic.
fn lattice<const D: usize, N: Checked<D> + Clone>(base: Base, seed: u32, n: N, rng: &mut Rng)
where
    SpecNoise<D>: Checked<D>,
    Fractal<N>: Checked<D>,
    Periodic<N, D>: Checked<D>,
    Fractal<Periodic<N, D>>: Checked<D>,
{
    let spec = Spec::new(base, seed);
    let what = format!("{spec} {D}D");
    same(&what, &spec.build::<D>().expect("valid"), &n, rng);
    let octaves = Octaves::new(4, 2.0, 0.5).expect("valid");
    let period: [u32; D] = core::array::from_fn(|a| [3, 256, 1000, 7][a]);
    let periodic = spec.with_period(&period).expect("valid");
    same(
        &format!("{periodic} {D}D"),
        &periodic.build::<D>().expect("valid"),
        &Periodic::new(n.clone(), period).expect("valid"),
        rng,
    );
    for kind in KINDS {
        let summed = spec.with_fractal(kind, octaves);
        same(
            &format!("{summed} {D}D"),
            &summed.build::<D>().expect("valid"),
            &Fractal::new(n.clone(), octaves, kind),
            rng,
        );
        let both = periodic.with_fractal(kind, octaves);
        same(
            &format!("{both} {D}D"),
            &both.build::<D>().expect("valid"),
            &Fractal::new(
                Periodic::new(n.clone(), period).expect("valid"),
                octaves,
                kind,
            ),
            rng,
        );
    }
}

/// Every lattice base in `D` dimensions.
fn every_lattice<const D: usize>(rng: &mut Rng)
where
    SpecNoise<D>: Checked<D>,
    Perlin: Checked<D>,
    OriginalPerlin: Checked<D>,
    ValueNoise: Checked<D>,
    CNoise: Checked<D>,
    MNoise<61>: Checked<D>,
    MNoise<4093>: Checked<D>,
    Fractal<Perlin>: Checked<D>,
    Fractal<OriginalPerlin>: Checked<D>,
    Fractal<ValueNoise>: Checked<D>,
    Fractal<CNoise>: Checked<D>,
    Fractal<MNoise<61>>: Checked<D>,
    Fractal<MNoise<4093>>: Checked<D>,
    Periodic<Perlin, D>: Checked<D>,
    Periodic<OriginalPerlin, D>: Checked<D>,
    Periodic<ValueNoise, D>: Checked<D>,
    Periodic<CNoise, D>: Checked<D>,
    Periodic<MNoise<61>, D>: Checked<D>,
    Periodic<MNoise<4093>, D>: Checked<D>,
    Fractal<Periodic<Perlin, D>>: Checked<D>,
    Fractal<Periodic<OriginalPerlin, D>>: Checked<D>,
    Fractal<Periodic<ValueNoise, D>>: Checked<D>,
    Fractal<Periodic<CNoise, D>>: Checked<D>,
    Fractal<Periodic<MNoise<61>, D>>: Checked<D>,
    Fractal<Periodic<MNoise<4093>, D>>: Checked<D>,
{
    for seed in [0, 9] {
        lattice::<D, _>(Base::Perlin, seed, Perlin::new(seed), rng);
        lattice::<D, _>(Base::OriginalPerlin, seed, OriginalPerlin::new(seed), rng);
        lattice::<D, _>(Base::Value, seed, ValueNoise::new(seed), rng);
        lattice::<D, _>(Base::CNoise, seed, CNoise::new(seed), rng);
        lattice::<D, _>(Base::MNoise, seed, MNoise::new(seed), rng);
        lattice::<D, _>(Base::MNoise4093, seed, MNoise::<4093>::seeded(seed), rng);
    }
}

#[test]
fn every_lattice_spec_samples_its_typed_noise_bit_for_bit() {
    let mut rng = Rng::from_env(180);
    every_lattice::<1>(&mut rng);
    every_lattice::<2>(&mut rng);
    every_lattice::<3>(&mut rng);
    every_lattice::<4>(&mut rng);
}

#[test]
fn wavelet_specs_sample_their_typed_noise_bit_for_bit() {
    let mut rng = Rng::from_env(181);
    let octaves = Octaves::default();
    for tiling in [Tiling::Varied, Tiling::Blended, Tiling::Periodic] {
        let spec = Spec::new(Base::Wavelet, 4)
            .with_tiling(tiling)
            .expect("wavelet");
        let (w2, w3) = (
            Wavelet::new(4, &TILE2).with_tiling(tiling),
            Wavelet::new(4, &TILE3).with_tiling(tiling),
        );
        same("wavelet 2D", &spec.build::<2>().expect("2D"), &w2, &mut rng);
        same("wavelet 3D", &spec.build::<3>().expect("3D"), &w3, &mut rng);
        for kind in KINDS {
            let summed = spec.with_fractal(kind, octaves);
            let f2 = Fractal::new(w2, octaves, kind);
            let f3 = Fractal::new(w3, octaves, kind);
            same(
                "summed wavelet 2D",
                &summed.build::<2>().expect("2D"),
                &f2,
                &mut rng,
            );
            same(
                "summed wavelet 3D",
                &summed.build::<3>().expect("3D"),
                &f3,
                &mut rng,
            );
        }
    }
}

/// Multiband noise over both tile sets, every distribution and tiling, plain and summed.
#[test]
fn multiband_specs_sample_their_typed_noise_bit_for_bit() {
    let mut rng = Rng::from_env(184);
    let octaves = Octaves::new(3, 2.0, 0.5).expect("valid");
    let bands = Bands::new(-2, &[0.5, 1.0, 0.25, -0.125]).expect("valid");
    for distribution in [Distribution::Gaussian, Distribution::Uniform] {
        for tiling in [Tiling::Varied, Tiling::Blended, Tiling::Periodic] {
            let spec = Spec::new(Base::Multiband, 6)
                .with_bands(bands)
                .and_then(|s| s.with_distribution(distribution))
                .and_then(|s| s.with_tiling(tiling))
                .expect("multiband");
            let text = spec.to_string();
            assert_eq!(text.parse::<Spec>(), Ok(spec));
            let m2 = Multiband::new(6, &TILE2, bands, distribution).with_tiling(tiling);
            let m3 = Multiband::new(6, &TILE3, bands, distribution).with_tiling(tiling);
            same(&text, &spec.build::<2>().expect("2D"), &m2, &mut rng);
            same(&text, &spec.build::<3>().expect("3D"), &m3, &mut rng);
            let q2 = Multiband::new(6, &TILE2_I16, bands, distribution).with_tiling(tiling);
            let q3 = Multiband::new(6, &TILE3_I16, bands, distribution).with_tiling(tiling);
            let built2 = spec.build_with::<2, I16Tiles>().expect("2D");
            let built3 = spec.build_with::<3, I16Tiles>().expect("3D");
            same(&text, &built2, &q2, &mut rng);
            same(&text, &built3, &q3, &mut rng);
            let summed = spec.with_fractal(Kind::Ridged, octaves);
            same(
                &summed.to_string(),
                &summed.build::<3>().expect("3D"),
                &Fractal::new(m3, octaves, Kind::Ridged),
                &mut rng,
            );
        }
    }
    // The defaults are Multiband's own, and the I16 set holds the quantized default tiles.
    let default = Spec::new(Base::Multiband, 1);
    assert_eq!(default.bands(), Bands::default());
    assert_eq!(default.distribution(), Distribution::default());
    assert!(core::ptr::eq(I16Tiles::three(), &TILE3_I16));
    assert_eq!(
        default.to_string(),
        "multiband seed=1 first=0 bands=1,0.5,0.25,0.125,0.0625 distribution=gaussian \
         tiling=blended"
    );
    // No bands is the zero noise, and round-trips.
    let none = default
        .with_bands(Bands::new(3, &[]).expect("valid"))
        .expect("multiband");
    assert_eq!(none.to_string().parse::<Spec>(), Ok(none));
    let zero: f32 = none.build::<2>().expect("2D").sample([0.3, 0.4]);
    assert_eq!(zero, 0.0);
}

/// Random specs of every shape.
fn random_spec(rng: &mut Rng) -> Spec {
    let base = Base::ALL[rng.next_u64() as usize % Base::ALL.len()];
    let mut spec = Spec::new(base, rng.next_u64() as u32);
    if base.is_periodic() && rng.next_u64().is_multiple_of(2) {
        let axes = 1 + rng.next_u64() as usize % 4;
        let period: Vec<u32> = (0..axes)
            .map(|_| 1 + (rng.next_u64() % 65536) as u32)
            .collect();
        spec = spec.with_period(&period).expect("valid periods");
    }
    if base.is_wavelet() && rng.next_u64().is_multiple_of(2) {
        spec = spec.with_tiling(Tiling::Periodic).expect("wavelet");
    }
    if base == Base::Multiband {
        let weights: Vec<f32> = (0..rng.next_u64() % 17)
            .map(|_| rng.f64_in(-2.0, 2.0) as f32)
            .collect();
        let first = (rng.next_u64() % 33) as i32 - 24;
        let bands = Bands::new(first, &weights).expect("in range");
        spec = spec.with_bands(bands).expect("multiband");
        if rng.next_u64().is_multiple_of(2) {
            spec = spec
                .with_distribution(Distribution::Uniform)
                .expect("multiband");
        }
    }
    if base == Base::Gabor {
        let a = rng.f64_in(1.0 / 256.0, 256.0) as f32;
        let f = rng.f64_in(0.0, 64.0 * a as f64) as f32;
        spec = spec.with_spectrum(f, a).expect("in range");
        let components = 1 + rng.next_u64() as usize % 3;
        let direction: Vec<f32> = (0..components)
            .map(|_| rng.f64_in(-2.0, 2.0) as f32)
            .collect();
        spec = spec
            .with_direction(&direction)
            .expect("almost surely non-zero");
        let orientations = [
            Orientation::Anisotropic,
            Orientation::Isotropic,
            Orientation::Hybrid,
        ];
        spec = spec
            .with_orientation(orientations[rng.next_u64() as usize % 3])
            .expect("gabor");
        if rng.next_u64().is_multiple_of(2) {
            spec = spec.with_envelope(Envelope::Truncated).expect("gabor");
        }
        spec = spec
            .with_magnitude(rng.f64_in(-1024.0, 1024.0) as f32)
            .expect("in range");
    }
    if base.is_impulse() {
        if base == Base::Sparse && rng.next_u64().is_multiple_of(2) {
            spec = spec.with_kernel(Kernel::CatmullRom).expect("sparse");
        }
        if rng.next_u64().is_multiple_of(2) {
            spec = spec.with_weights(Weights::Uniform).expect("sparse");
        }
        spec = if rng.next_u64().is_multiple_of(2) {
            spec.with_fixed_count(1 + (rng.next_u64() % 32) as u32)
        } else {
            spec.with_density(rng.f64_in(0.01, 64.0) as f32)
        }
        .expect("in range");
    }
    if base.texture_settings().is_some() && rng.next_u64().is_multiple_of(2) {
        let [a, b] = match base {
            Base::PolkaDots => [rng.f64_in(0.0, 0.5), rng.f64_in(0.0, 1.0)],
            Base::Wood | Base::WoodOlano => [rng.f64_in(0.01, 1024.0), rng.f64_in(-1024.0, 1024.0)],
            _ => [rng.f64_in(-1024.0, 1024.0), rng.f64_in(-1024.0, 1024.0)],
        };
        spec = spec.with_texture([a as f32, b as f32]).expect("in range");
    }
    if base == Base::Flow && rng.next_u64().is_multiple_of(2) {
        spec = spec
            .with_angle(rng.f64_in(-100.0, 100.0) as f32)
            .expect("finite")
            .with_flow_sum(rng.f64_in(0.0, 16.0) as f32, rng.f64_in(-16.0, 16.0) as f32)
            .expect("in range");
    }
    if spec.period().is_none() && rng.next_u64().is_multiple_of(4) {
        spec = spec
            .with_warp(rng.f64_in(-1024.0, 1024.0) as f32)
            .expect("in range");
    }
    if base == Base::Wiener && rng.next_u64().is_multiple_of(2) {
        spec = spec.with_covariance(Covariance::BandPass).expect("wiener");
    }
    if rng.next_u64().is_multiple_of(2) {
        let kind = KINDS[rng.next_u64() as usize % 3];
        let octaves = Octaves::new(
            1 + (rng.next_u64() % 30) as u32,
            rng.f64_in(0.01, 16.0) as f32,
            rng.f64_in(-1.0, 1.0) as f32,
        )
        .expect("in range");
        spec = spec.with_fractal(kind, octaves);
    }
    spec
}

#[test]
fn text_round_trips() {
    let mut rng = Rng::from_env(182);
    for _ in 0..20_000 {
        let spec = random_spec(&mut rng);
        let text = spec.to_string();
        let back: Spec = text.parse().unwrap_or_else(|e| panic!("{text:?}: {e}"));
        assert_eq!(back, spec, "{text}");
        assert_eq!(back.to_string(), text);
    }
    // Settings in any order, extra spaces, defaults filled in.
    let e: ParseError = "  fbm perlin".parse::<Spec>().unwrap_err();
    assert_eq!(e.position(), 2, "'fbm' is not a noise name");
    // The message lists every name the parser takes.
    for base in Base::ALL {
        assert!(
            e.expected().contains(&format!(" {},", base.name()))
                || e.expected().contains(&format!(" {})", base.name()))
                || e.expected().contains(&format!("({},", base.name())),
            "{} missing from {:?}",
            base.name(),
            e.expected()
        );
    }
    let b: Spec = "perlin  gain=0.25 fbm   seed=3 ".parse().expect("valid");
    assert_eq!(
        b,
        Spec::new(Base::Perlin, 3)
            .with_fractal(Kind::Fbm, Octaves::new(6, 1.99, 0.25).expect("valid"))
    );
    assert_eq!(
        b.to_string(),
        "perlin seed=3 fbm octaves=6 lacunarity=1.99 gain=0.25"
    );
    assert_eq!("value".parse::<Spec>(), Ok(Spec::new(Base::Value, 0)));
    assert_eq!(Spec::default().to_string(), "perlin seed=0");
}

#[test]
fn bad_text_names_the_position_and_what_was_expected() {
    let cases: &[(&str, usize, &str)] = &[
        ("", 0, "a noise name"),
        ("   ", 3, "a noise name"),
        ("blobs", 0, "a noise name"),
        ("Perlin", 0, "a noise name"),
        ("perlin seed", 11, "a seed"),
        ("perlin seed=", 12, "a seed"),
        ("perlin seed=x", 12, "a seed"),
        ("perlin seed=4294967296", 12, "a seed"),
        ("perlin seed=1 seed=2", 14, "each setting at most once"),
        ("perlin colour=red", 7, "a setting"),
        ("perlin period=0", 14, "1 to 4 periods"),
        ("perlin period=1,2,3,4,5", 22, "1 to 4 periods"),
        ("perlin period=1,,2", 16, "1 to 4 periods"),
        ("perlin period=65537", 14, "1 to 4 periods"),
        ("wavelet period=4", 15, "1 to 4 periods"),
        ("perlin tiling=periodic", 7, "tiling only for wavelet"),
        ("wavelet tiling=tiled", 15, "a tiling"),
        ("perlin octaves=4", 15, "a fractal kind"),
        ("perlin fbm=1", 10, "a space after the fractal kind"),
        ("perlin fbm turbulence", 11, "each setting at most once"),
        ("perlin fbm octaves=0", 19, "octave settings in range"),
        ("perlin fbm octaves=31", 19, "octave settings in range"),
        ("perlin fbm lacunarity=inf", 22, "a lacunarity"),
        ("perlin fbm lacunarity=1e3", 22, "a lacunarity"),
        ("perlin fbm lacunarity=17", 22, "octave settings in range"),
        ("perlin fbm gain=NaN", 16, "a gain"),
        ("perlin fbm gain=-1.5", 16, "octave settings in range"),
        ("perlin fbm gain=.", 16, "a gain"),
        ("perlin\tseed=1", 0, "a noise name"),
        ("perlin bands=1", 7, "bands only for multiband"),
        ("wavelet first=0", 8, "bands only for multiband"),
        (
            "value distribution=uniform",
            6,
            "distribution only for multiband",
        ),
        ("multiband distribution=normal", 23, "a distribution"),
        ("multiband first=9", 16, "bands in range"),
        ("multiband first=x", 16, "a first band"),
        ("multiband bands=1,,2", 18, "up to 16 band weights"),
        ("multiband bands=1,nan", 18, "up to 16 band weights"),
        ("multiband bands=1,2e7", 18, "up to 16 band weights"),
        ("multiband bands=2000000", 16, "bands in range"),
        (
            "multiband bands=1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1",
            48,
            "up to 16 band weights",
        ),
    ];
    for &(text, position, expected) in cases {
        let e = text
            .parse::<Spec>()
            .expect_err(&format!("{text:?} should be refused"));
        assert_eq!(e.position(), position, "{text:?}: {e}");
        assert!(e.expected().starts_with(expected), "{text:?}: {e}");
        assert!(
            e.to_string()
                .starts_with(&format!("at byte {position}: expected "))
        );
    }
    // A refused value carries the configuration error.
    let e = "perlin fbm octaves=0".parse::<Spec>().unwrap_err();
    assert_eq!(e.refused(), Some(Error::OctaveCount { count: 0, max: 30 }));
}

#[test]
fn arbitrary_text_never_panics() {
    let mut rng = Rng::from_env(183);
    let alphabet = b"perlinvaluwtcsmo0123456789=,.- fbdgqyr\t\xff";
    for _ in 0..100_000 {
        // Mutations of valid texts, and random strings over the text form's alphabet.
        let mut bytes = random_spec(&mut rng).to_string().into_bytes();
        for _ in 0..rng.next_u64() % 4 {
            let i = rng.next_u64() as usize % (bytes.len() + 1);
            let c = alphabet[rng.next_u64() as usize % alphabet.len()];
            match rng.next_u64() % 3 {
                0 if i < bytes.len() => bytes[i] = c,
                1 if i < bytes.len() => {
                    bytes.remove(i);
                }
                _ => bytes.insert(i, c),
            }
        }
        let text = String::from_utf8_lossy(&bytes);
        if let Ok(spec) = text.parse::<Spec>() {
            // Whatever parses prints to a text that parses to the same spec.
            assert_eq!(spec.to_string().parse::<Spec>(), Ok(spec), "{text:?}");
        }
    }
}

#[test]
fn build_refuses_dimensions_the_noise_lacks() {
    let w = Spec::new(Base::Wavelet, 0);
    assert_eq!(
        w.build::<1>().unwrap_err(),
        Error::Dimension {
            noise: "wavelet",
            dims: 1
        }
    );
    assert!(w.build::<4>().is_err());
    assert_eq!(
        w.with_period(&[4]).unwrap_err(),
        Error::NotPeriodic("wavelet")
    );
    let p = Spec::new(Base::Perlin, 0)
        .with_period(&[4, 4])
        .expect("valid");
    assert_eq!(
        p.build::<3>().unwrap_err(),
        Error::PeriodAxes { axes: 2, dims: 3 }
    );
    assert_eq!(p.period(), Some(&[4, 4][..]));
    assert!(Spec::new(Base::Perlin, 0).with_period(&[]).is_err());
    assert_eq!(
        Spec::new(Base::Value, 0)
            .with_tiling(Tiling::Periodic)
            .unwrap_err(),
        Error::NotWavelet("value")
    );
    // Every base builds in each of its dimensions.
    for base in Base::ALL {
        let s = Spec::new(base, 1);
        assert_eq!(s.build::<1>().is_ok(), base.has_dimension(1), "{base}");
        assert_eq!(s.build::<2>().is_ok(), base.has_dimension(2), "{base}");
        assert_eq!(s.build::<3>().is_ok(), base.has_dimension(3), "{base}");
        assert_eq!(s.build::<4>().is_ok(), base.has_dimension(4), "{base}");
        assert_eq!(s.to_string().parse::<Spec>(), Ok(s));
    }
}

/// Every type in core that implements `Noise` is described by a spec, or says why not. The
/// list of types comes from the source (each `impl … Noise<…> for T` and each use of the
/// lattice noises' impl macro), so a new noise without a description fails here.
#[test]
fn every_noise_type_in_core_is_described() {
    let described: &[(&str, &str)] = &[
        ("Perlin", "perlin"),
        ("OriginalPerlin", "original"),
        ("ValueNoise", "value"),
        ("CNoise", "cnoise"),
        ("MNoise", "mnoise, mnoise4093"),
        ("Periodic", "period="),
        ("Fractal", "fbm, turbulence, ridged"),
        ("Warp", "warp="),
        ("Wavelet", "wavelet"),
        ("Multiband", "multiband"),
        ("SparseConvolution", "sparse"),
        ("WienerNoise", "wiener"),
        ("Gabor", "gabor"),
        ("Simplex", "simplex"),
        ("Cellular", "cellular"),
        ("WhiteNoise", "white"),
        ("CubicValueNoise", "value-cubic"),
        ("OpenSimplex2", "opensimplex2"),
        ("OpenSimplex2S", "opensimplex2s"),
        ("Flow", "flow"),
        ("FlowSum", "flow fbm"),
        ("Windy", "windy"),
        ("Wrinkled", "wrinkled"),
        ("Marble", "marble, marble-olano"),
        ("Wood", "wood, wood-olano"),
        ("PolkaDots", "polka-dots"),
    ];
    // Types that implement Noise but are not noises of their own.
    let not_noises: &[(&str, &str)] = &[
        (
            "TabledPerlin",
            "Perlin's values with a speed table: described as perlin",
        ),
        ("SpecNoise", "the description itself"),
        (
            "Differenced",
            "private: a texture's gradient by central differences, in the description",
        ),
        (
            "Layers",
            "private: a spec's base and periodic wrap, under its fractal sum",
        ),
        (
            "Zero",
            "private: the dispatch's value for dimensions build refuses",
        ),
        ("&N", "a reference to a noise"),
        (
            "Curl2",
            "a vector noise (VectorNoise): the description names scalar noises",
        ),
        (
            "Curl3",
            "a vector noise (VectorNoise): the description names scalar noises",
        ),
        (
            "Components",
            "a vector noise (VectorNoise): the description names scalar noises",
        ),
        (
            "MixedMNoise",
            "mNoise's values from Olano's table: described as mnoise",
        ),
        (
            "MixedTurbulence",
            "Olano's turbulence, bit for bit `mnoise turbulence octaves=N lacunarity=2 gain=0.5`",
        ),
    ];
    let mut found = std::collections::BTreeSet::new();
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/../core/src");
    let mut dirs = vec![std::path::PathBuf::from(root)];
    while let Some(dir) = dirs.pop() {
        for entry in std::fs::read_dir(&dir).expect("core/src") {
            let path = entry.expect("entry").path();
            if path.is_dir() {
                dirs.push(path);
                continue;
            }
            let text = std::fs::read_to_string(&path).expect("source");
            for line in text.lines() {
                let line = line.trim();
                let ty = if line.starts_with("impl")
                    && line.contains("Noise<")
                    && line.contains(" for ")
                {
                    line.rsplit(" for ").next().map(str::to_string)
                } else {
                    line.strip_prefix("lattice_noise_impls!(")
                        .or_else(|| line.strip_prefix("spec_noise_entry_points!("))
                        .or_else(|| line.strip_prefix("open_simplex_impls!("))
                        .map(str::to_string)
                };
                if let Some(ty) = ty {
                    let name: String = ty
                        .trim_start_matches("crate::")
                        .chars()
                        .take_while(|c| c.is_alphanumeric() || *c == '&')
                        .collect();
                    if !name.is_empty() && name != "$ty" {
                        found.insert(if name.starts_with('&') {
                            "&N".to_string()
                        } else {
                            name
                        });
                    }
                }
            }
        }
    }
    for name in ["Perlin", "Fractal", "Wavelet", "Multiband", "SpecNoise"] {
        assert!(found.contains(name), "the scan finds {name}: {found:?}");
    }
    for name in &found {
        let known =
            described.iter().any(|(t, _)| t == name) || not_noises.iter().any(|(t, _)| t == name);
        assert!(
            known,
            "{name} implements Noise but is not described by bandnoise::spec"
        );
    }
    // Every described base name parses.
    for (ty, names) in described {
        if matches!(*ty, "Periodic" | "Fractal" | "Warp") {
            continue;
        }
        for name in names.split(", ") {
            assert!(name.parse::<Spec>().is_ok(), "{name}");
        }
    }
}

/// `spec` built for `D` dimensions samples `typed` bit for bit: values and gradients, f32 and
/// I16F16, at 200 random points; the same amplitude bound.
fn same_bits<const D: usize, N>(spec: &Spec, typed: &N, rng: &mut Rng)
where
    N: NoiseGradient<f32, D> + NoiseGradient<I16F16, D>,
    SpecNoise<D>: NoiseGradient<f32, D> + NoiseGradient<I16F16, D>,
{
    let built = spec.build::<D>().expect("builds");
    for _ in 0..200 {
        let q: [I16F16; D] = rng.exact_point(100);
        let f = bandnoise_tests::to_f32(q);
        assert_eq!(
            built.sample(f).to_bits(),
            typed.sample(f).to_bits(),
            "{spec}"
        );
        assert_eq!(built.sample(q), typed.sample(q), "{spec}");
        let (a, b) = (built.sample_with_gradient(f), typed.sample_with_gradient(f));
        assert_eq!(a.0.to_bits(), b.0.to_bits());
        assert_eq!(a.1.map(f32::to_bits), b.1.map(f32::to_bits));
    }
    assert_eq!(
        Noise::<f32, D>::amplitude_bound(&built),
        Noise::<f32, D>::amplitude_bound(typed)
    );
}

/// A sparse spec samples the typed noise it names bit for bit (value and gradient, f32 and
/// I16F16, 1D–4D), and its settings are refused for other noises and out of range.
#[test]
fn sparse_specs_sample_their_typed_noise_bit_for_bit() {
    let mut rng = Rng::from_env(186);
    let spec: Spec = "sparse seed=9 kernel=catmull-rom weights=uniform density=3"
        .parse()
        .expect("valid");
    let typed = |s| {
        SparseConvolution::<3>::new(s)
            .with_kernel(Kernel::CatmullRom)
            .with_weights(Weights::Uniform)
    };
    same_bits::<3, _>(&spec, &typed(9).with_density(3.0).unwrap(), &mut rng);
    let spec: Spec = "sparse seed=4 count=2".parse().expect("valid");
    let fixed = |s| SparseConvolution::<2>::new(s).with_fixed_count(2).unwrap();
    same_bits::<2, _>(&spec, &fixed(4), &mut rng);
    same_bits::<1, _>(
        &Spec::new(Base::Sparse, 1),
        &SparseConvolution::<1>::new(1),
        &mut rng,
    );
    same_bits::<4, _>(
        &Spec::new(Base::Sparse, 1),
        &SparseConvolution::<4>::new(1),
        &mut rng,
    );
    // The text prints every setting.
    assert_eq!(
        Spec::new(Base::Sparse, 5).to_string(),
        "sparse seed=5 kernel=cosine weights=sign density=10"
    );
    // Refusals.
    let e = "perlin density=3".parse::<Spec>().unwrap_err();
    assert_eq!(e.refused(), Some(Error::NotImpulse("perlin")));
    assert_eq!(e.position(), 7);
    let e = "sparse density=3 count=2".parse::<Spec>().unwrap_err();
    assert_eq!(e.position(), 17, "{e}");
    let e = "sparse count=0".parse::<Spec>().unwrap_err();
    assert!(
        matches!(e.refused(), Some(Error::ImpulseCount { count: 0, .. })),
        "{e}"
    );
    let e = "sparse density=nan".parse::<Spec>().unwrap_err();
    assert_eq!(e.position(), 15, "{e}");
    assert!(Spec::new(Base::Sparse, 0).with_period(&[4]).is_err());
    // 150 per kernel is within 4D's range, not 2D's (32 per cell).
    let dense = Spec::new(Base::Sparse, 0)
        .with_density(150.0)
        .expect("4D allows it");
    assert!(dense.build::<4>().is_ok());
    assert!(matches!(
        dense.build::<2>().unwrap_err(),
        Error::Density { density: 150.0, .. }
    ));
}

/// A simplex spec samples the typed noise bit for bit (value and gradient, f32 and I16F16,
/// 1D–4D, and under a fractal sum), and refuses a period (its lattice is skewed).
#[test]
fn simplex_specs_sample_their_typed_noise_bit_for_bit() {
    let mut rng = Rng::from_env(188);
    let spec: Spec = "simplex seed=9".parse().expect("valid");
    same_bits::<1, _>(&spec, &Simplex::new(9), &mut rng);
    same_bits::<2, _>(&spec, &Simplex::new(9), &mut rng);
    same_bits::<3, _>(&spec, &Simplex::new(9), &mut rng);
    same_bits::<4, _>(&spec, &Simplex::new(9), &mut rng);
    let fbm: Spec = "simplex seed=9 fbm octaves=5".parse().expect("valid");
    same_bits::<3, _>(
        &fbm,
        &Fractal::fbm(Simplex::new(9), Octaves::new(5, 1.99, 0.5).unwrap()),
        &mut rng,
    );
    assert_eq!(spec.to_string(), "simplex seed=9");
    let e = "simplex period=4,4".parse::<Spec>().unwrap_err();
    assert_eq!(e.refused(), Some(Error::NotPeriodic("simplex")));
    assert_eq!(
        Spec::new(Base::Simplex, 0).with_period(&[4]).unwrap_err(),
        Error::NotPeriodic("simplex")
    );
}

/// OpenSimplex2 and OpenSimplex2S specs sample the typed noises bit for bit (value and
/// gradient, f32 and I16F16, 1D–4D, every orientation, under a fractal sum); `improve=` prints
/// and reads back, and is refused for other noises; no period.
#[test]
fn open_simplex_specs_sample_their_typed_noise_bit_for_bit() {
    let mut rng = Rng::from_env(190);
    for (text, improve) in [
        ("standard", Improve::Standard),
        ("xy", Improve::XY),
        ("xz", Improve::XZ),
    ] {
        let fast: Spec = format!("opensimplex2 seed=9 improve={text}")
            .parse()
            .expect("valid");
        let typed = OpenSimplex2::new(9).improving(improve);
        same_bits::<1, _>(&fast, &typed, &mut rng);
        same_bits::<2, _>(&fast, &typed, &mut rng);
        same_bits::<3, _>(&fast, &typed, &mut rng);
        same_bits::<4, _>(&fast, &typed, &mut rng);
        assert_eq!(
            fast.to_string(),
            format!("opensimplex2 seed=9 improve={text}")
        );
        let smooth: Spec = format!("opensimplex2s seed=4294967295 improve={text}")
            .parse()
            .expect("valid");
        let typed = OpenSimplex2S::new(4_294_967_295).improving(improve);
        same_bits::<2, _>(&smooth, &typed, &mut rng);
        same_bits::<3, _>(&smooth, &typed, &mut rng);
        same_bits::<4, _>(&smooth, &typed, &mut rng);
        assert_eq!(smooth.improve(), improve);
    }
    let fbm: Spec = "opensimplex2s seed=2 improve=xy ridged octaves=4"
        .parse()
        .expect("valid");
    same_bits::<3, _>(
        &fbm,
        &Fractal::ridged(
            OpenSimplex2S::new(2).improving(Improve::XY),
            Octaves::new(4, 1.99, 0.5).unwrap(),
        ),
        &mut rng,
    );
    assert_eq!(
        "opensimplex2".parse::<Spec>().unwrap().to_string(),
        "opensimplex2 seed=0 improve=standard"
    );
    let e = "simplex improve=xy".parse::<Spec>().unwrap_err();
    assert_eq!(e.refused(), Some(Error::NotOpenSimplex("simplex")));
    assert_eq!(
        Spec::new(Base::Perlin, 0)
            .with_improve(Improve::XZ)
            .unwrap_err(),
        Error::NotOpenSimplex("perlin")
    );
    assert!("opensimplex2 improve=yz".parse::<Spec>().is_err());
    assert_eq!(
        "opensimplex2 period=4"
            .parse::<Spec>()
            .unwrap_err()
            .refused(),
        Some(Error::NotPeriodic("opensimplex2"))
    );
}

/// A cellular spec samples the typed noise bit for bit (value and gradient, f32 and I16F16,
/// 1D–4D, every output and metric, and under a fractal sum); its settings print and read back,
/// and are refused for other noises and out of range.
#[test]
fn cellular_specs_sample_their_typed_noise_bit_for_bit() {
    let mut rng = Rng::from_env(189);
    for output in Output::ALL {
        for metric in Metric::ALL {
            let text = format!(
                "cellular seed=9 output={} metric={} jitter=0.75",
                output.name(),
                metric.name()
            );
            let spec: Spec = text.parse().expect("valid");
            assert_eq!(spec.to_string(), text);
            let typed = Cellular::new(9)
                .with_output(output)
                .with_metric(metric)
                .with_jitter(0.75)
                .unwrap();
            same_bits::<2, _>(&spec, &typed, &mut rng);
            same_bits::<3, _>(&spec, &typed, &mut rng);
        }
    }
    let spec = Spec::new(Base::Cellular, 4);
    same_bits::<1, _>(&spec, &Cellular::new(4), &mut rng);
    same_bits::<4, _>(&spec, &Cellular::new(4), &mut rng);
    assert_eq!(
        spec.to_string(),
        "cellular seed=4 output=f1 metric=euclidean jitter=1"
    );
    let fbm: Spec = "cellular seed=9 fbm octaves=3".parse().expect("valid");
    same_bits::<2, _>(
        &fbm,
        &Fractal::fbm(Cellular::new(9), Octaves::new(3, 1.99, 0.5).unwrap()),
        &mut rng,
    );
    // A jitter that is not a multiple of 2⁻¹⁶ is rounded, and prints as rounded.
    let odd: Spec = "cellular jitter=0.3".parse().expect("valid");
    assert_eq!(
        odd.jitter(),
        Cellular::new(0).with_jitter(0.3).unwrap().jitter()
    );
    assert_eq!(odd.to_string().parse::<Spec>().unwrap(), odd);
    for (text, refused) in [
        ("cellular jitter=1.5", Error::Jitter(1.5)),
        ("cellular jitter=-0.25", Error::Jitter(-0.25)),
        ("perlin metric=manhattan", Error::NotCellular("perlin")),
        ("simplex output=f2", Error::NotCellular("simplex")),
        ("cellular period=4,4", Error::NotPeriodic("cellular")),
    ] {
        let e = text.parse::<Spec>().unwrap_err();
        assert_eq!(e.refused(), Some(refused), "{text}");
    }
    for text in [
        "cellular output=f3",
        "cellular metric=minkowski",
        "cellular jitter=x",
    ] {
        let e = text.parse::<Spec>().unwrap_err();
        assert_eq!(e.refused(), None, "{text}");
        assert!(e.position() > 0, "{text}");
    }
    assert_eq!(
        Spec::new(Base::Perlin, 0).with_jitter(0.5).unwrap_err(),
        Error::NotCellular("perlin")
    );
}

/// White and cubic value specs sample their typed noises bit for bit (1D–4D, both
/// distributions, and under a fractal sum); the distribution prints (uniform by default, not
/// multiband's Gaussian), reads back, and is refused for other noises; no period.
#[test]
fn white_and_cubic_specs_sample_their_typed_noise_bit_for_bit() {
    let mut rng = Rng::from_env(190);
    for d in [Distribution::Uniform, Distribution::Gaussian] {
        let white = WhiteNoise::new(3).with_distribution(d);
        let cubic = CubicValueNoise::new(3).with_distribution(d);
        for (spec, name) in [
            (Spec::new(Base::White, 3), "white"),
            (Spec::new(Base::ValueCubic, 3), "value-cubic"),
        ] {
            let spec = spec.with_distribution(d).unwrap();
            let text = format!(
                "{name} seed=3 distribution={}",
                if d == Distribution::Uniform {
                    "uniform"
                } else {
                    "gaussian"
                }
            );
            assert_eq!(spec.to_string(), text);
            assert_eq!(text.parse::<Spec>().unwrap(), spec);
            if name == "white" {
                same_bits::<1, _>(&spec, &white, &mut rng);
                same_bits::<2, _>(&spec, &white, &mut rng);
                same_bits::<3, _>(&spec, &white, &mut rng);
                same_bits::<4, _>(&spec, &white, &mut rng);
            } else {
                same_bits::<1, _>(&spec, &cubic, &mut rng);
                same_bits::<2, _>(&spec, &cubic, &mut rng);
                same_bits::<3, _>(&spec, &cubic, &mut rng);
                same_bits::<4, _>(&spec, &cubic, &mut rng);
            }
        }
    }
    assert_eq!(
        Spec::new(Base::White, 0).to_string(),
        "white seed=0 distribution=uniform"
    );
    let fbm: Spec = "value-cubic seed=9 fbm octaves=4".parse().expect("valid");
    same_bits::<2, _>(
        &fbm,
        &Fractal::fbm(CubicValueNoise::new(9), Octaves::new(4, 1.99, 0.5).unwrap()),
        &mut rng,
    );
    // Periodic: each lattice coordinate wrapped (`lattice::Periodic`).
    let tile: Spec = "white seed=3 period=4,9 distribution=gaussian"
        .parse()
        .expect("valid");
    let white = WhiteNoise::new(3).with_distribution(Distribution::Gaussian);
    same_bits::<2, _>(&tile, &Periodic::new(white, [4, 9]).unwrap(), &mut rng);
    let tile: Spec = "value-cubic seed=3 period=5,6,7 ridged octaves=3 lacunarity=2"
        .parse()
        .expect("valid");
    same_bits::<3, _>(
        &tile,
        &Fractal::ridged(
            Periodic::new(CubicValueNoise::new(3), [5, 6, 7]).unwrap(),
            Octaves::new(3, 2.0, 0.5).unwrap(),
        ),
        &mut rng,
    );
    assert_eq!(
        tile.to_string(),
        "value-cubic seed=3 period=5,6,7 distribution=uniform ridged octaves=3 lacunarity=2 gain=0.5"
    );
    for (text, refused) in [
        ("perlin distribution=uniform", Error::NotMultiband("perlin")),
        ("simplex period=4", Error::NotPeriodic("simplex")),
        ("white bands=1", Error::NotMultiband("white")),
    ] {
        let e = text.parse::<Spec>().unwrap_err();
        assert_eq!(e.refused(), Some(refused), "{text}");
    }
    let e = "white distribution=cauchy".parse::<Spec>().unwrap_err();
    assert_eq!(e.refused(), None);
}

/// A Wiener spec samples the typed noise it names bit for bit (value and gradient, f32 and
/// I16F16, 1D–4D, both covariances), and a covariance is refused for other noises.
#[test]
fn wiener_specs_sample_their_typed_noise_bit_for_bit() {
    let mut rng = Rng::from_env(187);
    let band: Spec = "wiener seed=9 covariance=band-pass".parse().expect("valid");
    fn typed<const D: usize>(seed: u32) -> WienerNoise<D> {
        WienerNoise::new(seed).with_covariance(Covariance::BandPass)
    }
    same_bits::<1, _>(&band, &typed(9), &mut rng);
    same_bits::<2, _>(&band, &typed(9), &mut rng);
    same_bits::<3, _>(&band, &typed(9), &mut rng);
    same_bits::<4, _>(&band, &typed(9), &mut rng);
    let low = Spec::new(Base::Wiener, 2);
    same_bits::<2, _>(&low, &WienerNoise::new(2), &mut rng);
    same_bits::<3, _>(&low, &WienerNoise::new(2), &mut rng);
    assert_eq!(low.to_string(), "wiener seed=2 covariance=low-pass");
    let e = "perlin covariance=band-pass".parse::<Spec>().unwrap_err();
    assert_eq!(e.refused(), Some(Error::NotWiener("perlin")));
    assert_eq!(e.position(), 7);
    let e = "wiener covariance=high-pass".parse::<Spec>().unwrap_err();
    assert_eq!(e.position(), 18, "{e}");
    assert!(matches!(
        low.with_period(&[4]),
        Err(Error::NotPeriodic("wiener"))
    ));
    assert!("wiener density=3".parse::<Spec>().is_err());
}

/// A Gabor spec samples the typed noise it names bit for bit (value and gradient, f32 and
/// I16F16, 1D–3D, every variant), its settings read in any order (frequency and bandwidth are
/// checked together), and they are refused for other noises and out of range.
#[test]
fn gabor_specs_sample_their_typed_noise_bit_for_bit() {
    let mut rng = Rng::from_env(188);
    let spec: Spec = "gabor seed=9 bandwidth=0.5 frequency=30 direction=1,2 \
                      orientation=isotropic envelope=truncated weights=uniform density=40 \
                      magnitude=0.5"
        .parse()
        .expect("valid: 30 ≤ 64 × 0.5, whatever the order");
    fn typed<const D: usize>(seed: u32) -> Gabor<D> {
        Gabor::<D>::new(seed)
            .with_spectrum(30.0, 0.5)
            .unwrap()
            .with_direction(core::array::from_fn(|a| [1.0, 2.0, 0.0][a]))
            .unwrap()
            .with_orientation(Orientation::Isotropic)
            .with_envelope(Envelope::Truncated)
            .with_weights(Weights::Uniform)
            .with_density(40.0)
            .unwrap()
            .with_magnitude(0.5)
            .unwrap()
    }
    same_bits::<1, _>(&spec, &typed(9), &mut rng);
    same_bits::<2, _>(&spec, &typed(9), &mut rng);
    same_bits::<3, _>(&spec, &typed(9), &mut rng);
    let plain = Spec::new(Base::Gabor, 3);
    same_bits::<2, _>(&plain, &Gabor::<2>::new(3), &mut rng);
    let hybrid = plain
        .with_orientation(Orientation::Hybrid)
        .unwrap()
        .with_fixed_count(3)
        .unwrap();
    let typed_hybrid = Gabor::<3>::new(3)
        .with_orientation(Orientation::Hybrid)
        .with_fixed_count(3)
        .unwrap();
    same_bits::<3, _>(&hybrid, &typed_hybrid, &mut rng);
    assert_eq!(
        plain.to_string(),
        "gabor seed=3 frequency=1 bandwidth=0.8 direction=1,0,0 orientation=anisotropic \
         envelope=hann magnitude=1 weights=sign density=16"
    );
    // Refusals, each at its position and for its reason.
    let e = "perlin frequency=2".parse::<Spec>().unwrap_err();
    assert_eq!(e.refused(), Some(Error::NotGabor("perlin")));
    assert_eq!(e.position(), 7);
    let e = "gabor kernel=cosine".parse::<Spec>().unwrap_err();
    assert_eq!(
        (e.position(), e.refused()),
        (6, Some(Error::NotImpulse("gabor")))
    );
    let e = "gabor frequency=60 bandwidth=0.5"
        .parse::<Spec>()
        .unwrap_err();
    assert!(matches!(e.refused(), Some(Error::Frequency { .. })), "{e}");
    assert_eq!(e.position(), 16, "{e}");
    let e = "gabor bandwidth=0".parse::<Spec>().unwrap_err();
    assert_eq!(
        (e.position(), e.refused()),
        (16, Some(Error::Bandwidth(0.0)))
    );
    let e = "gabor direction=0,0".parse::<Spec>().unwrap_err();
    assert_eq!((e.position(), e.refused()), (16, Some(Error::Direction)));
    let e = "gabor direction=1,0,0,0".parse::<Spec>().unwrap_err();
    assert_eq!(e.position(), 22, "{e}");
    let e = "gabor orientation=sideways".parse::<Spec>().unwrap_err();
    assert_eq!(e.position(), 18, "{e}");
    let e = "gabor magnitude=2000".parse::<Spec>().unwrap_err();
    assert_eq!(
        (e.position(), e.refused()),
        (16, Some(Error::Magnitude(2000.0)))
    );
    // A direction along z has no 2D form; Gabor noise has no 4D form.
    let z = Spec::new(Base::Gabor, 0)
        .with_direction(&[0.0, 0.0, 1.0])
        .unwrap();
    assert_eq!(z.build::<2>().unwrap_err(), Error::Direction);
    assert!(z.build::<3>().is_ok());
    assert!(matches!(
        Spec::new(Base::Gabor, 0).build::<4>().unwrap_err(),
        Error::Dimension {
            noise: "gabor",
            dims: 4
        }
    ));
    assert!(Spec::new(Base::Gabor, 0).with_period(&[4]).is_err());
}

/// With the `serde` feature a spec is its text form: a JSON string that round-trips, and a bad
/// string fails with the parser's message.
#[test]
fn serde_writes_and_reads_the_text_form() {
    let mut rng = Rng::from_env(185);
    for _ in 0..2_000 {
        let spec = random_spec(&mut rng);
        let json = serde_json::to_string(&spec).expect("serialises");
        assert_eq!(json, format!("\"{spec}\""));
        let back: Spec = serde_json::from_str(&json).expect("deserialises");
        assert_eq!(back, spec);
    }
    let config = r#"{"terrain": "perlin seed=7 fbm octaves=4", "clouds": "multiband seed=2"}"#;
    let map: std::collections::BTreeMap<String, Spec> =
        serde_json::from_str(config).expect("valid");
    assert_eq!(map["clouds"], Spec::new(Base::Multiband, 2));
    let err = serde_json::from_str::<Spec>("\"perlin seed=x\"").unwrap_err();
    assert!(
        err.to_string()
            .starts_with("at byte 12: expected a seed in 0..=4294967295"),
        "{err}"
    );
    assert!(serde_json::from_str::<Spec>("7").is_err());
}

/// The programs that loop over "every noise" take the list from the description
/// (`Base::ALL`), so a noise added there is checked, proved, fuzzed, tested and rendered
/// without touching them. A program that goes back to a list of its own fails here.
#[test]
fn consumers_take_their_noises_from_the_description() {
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/..");
    let consumers = [
        ("checks/src/lib.rs", "firmware, wasm and host checksums"),
        (
            "firmware/cortex-m/src/bin/nopanic_spec.rs",
            "the no-panic proof",
        ),
        ("fuzz/fuzz_targets/lattice.rs", "the lattice fuzz target"),
        ("fuzz/fuzz_targets/fractal.rs", "the fractal fuzz target"),
        ("fuzz/fuzz_targets/spec.rs", "the description's fuzz target"),
        ("tests/src/lib.rs", "the test helper Lattice"),
        ("gallery/src/main.rs", "the gallery"),
        ("wasm/src/params.rs", "the browser demo"),
        (
            "bench/benches/spec.rs",
            "the benchmark of every described noise",
        ),
    ];
    for (path, what) in consumers {
        let text = std::fs::read_to_string(format!("{root}/{path}")).expect(path);
        assert!(
            text.contains("Base::ALL") || text.contains("parse::<Spec>"),
            "{what} ({path}) does not take its noises from bandnoise::spec"
        );
    }
    // Every base is a lattice noise the helper knows, or one of the other families.
    for base in Base::ALL {
        if base.is_lattice() {
            let _ = bandnoise_tests::Lattice::of(base, 0);
        } else {
            assert!(
                base.is_wavelet()
                    || base.is_impulse()
                    || base.is_texture()
                    || matches!(
                        base,
                        Base::Wiener
                            | Base::Simplex
                            | Base::Cellular
                            | Base::White
                            | Base::ValueCubic
                            | Base::OpenSimplex2
                            | Base::OpenSimplex2S
                            | Base::Flow
                    ),
                "{base}"
            );
        }
    }
}

/// `spec` built for `D` dimensions samples `typed` (a noise without an analytic gradient) bit
/// for bit in f32, f64 and I16F16, on a grid, with the same bound; its gradient is the central
/// difference `(n(p + h·eₐ) − n(p − h·eₐ)) · 512`, `h = 2⁻¹⁰`, of the typed noise.
fn same_values<const D: usize, N>(spec: &Spec, typed: &N, rng: &mut Rng)
where
    N: Noise<f32, D> + Noise<f64, D> + Noise<I16F16, D>,
    SpecNoise<D>: NoiseGradient<f32, D> + NoiseGradient<I16F16, D> + Noise<f64, D>,
{
    let built = spec.build::<D>().expect("builds");
    for _ in 0..200 {
        let q: [I16F16; D] = rng.exact_point(100);
        let f = bandnoise_tests::to_f32(q);
        let v: f32 = typed.sample(f);
        assert_eq!(built.sample(f).to_bits(), v.to_bits(), "{spec} at {f:?}");
        let d = f.map(f64::from);
        let (a, b): (f64, f64) = (built.sample(d), typed.sample(d));
        assert_eq!(a.to_bits(), b.to_bits(), "{spec} f64");
        assert_eq!(built.sample(q), typed.sample(q), "{spec} I16F16");
        let h = 1.0 / 1024.0;
        let slope: [f32; D] = core::array::from_fn(|a| {
            let (mut ahead, mut behind) = (f, f);
            ahead[a] += h;
            behind[a] -= h;
            let (x, y): (f32, f32) = (typed.sample(ahead), typed.sample(behind));
            (x - y) * 512.0
        });
        let (value, gradient) = built.sample_with_gradient(f);
        assert_eq!(value.to_bits(), v.to_bits());
        assert_eq!(
            gradient.map(f32::to_bits),
            slope.map(f32::to_bits),
            "{spec}"
        );
        let hq = I16F16::from_bits(64);
        let slope: [I16F16; D] = core::array::from_fn(|a| {
            let (mut ahead, mut behind) = (q, q);
            ahead[a] = ahead[a].saturating_add(hq);
            behind[a] = behind[a].saturating_sub(hq);
            let (x, y): (I16F16, I16F16) = (typed.sample(ahead), typed.sample(behind));
            x.saturating_sub(y).saturating_mul(I16F16::from_num(512))
        });
        assert_eq!(
            built.sample_with_gradient(q).1,
            slope,
            "{spec} I16F16 gradient"
        );
    }
    same_grid_and_bound(&spec.to_string(), &built, typed);
}

/// Flow noise's spec samples `Flow` bit for bit (with its analytic gradient); its `fbm` sum is
/// Perlin and Neyret's `FlowSum` (spin, advection), its other sums plain fractal sums; the
/// settings print, read back, and are refused for other noises and out of range.
#[test]
fn flow_specs_sample_their_typed_noise_bit_for_bit() {
    let mut rng = Rng::from_env(191);
    let flow: Spec = "flow seed=3 angle=1.25".parse().expect("valid");
    assert_eq!(
        flow.to_string(),
        "flow seed=3 angle=0.25 spin=2 advection=0"
    );
    let typed = Flow::new(3).with_angle(0.25).unwrap();
    same_bits::<2, _>(&flow, &typed, &mut rng);
    let sum: Spec =
        "flow seed=3 angle=0.25 fbm octaves=5 lacunarity=2 gain=0.5 spin=1 advection=0.5"
            .parse()
            .expect("valid");
    let octaves = Octaves::new(5, 2.0, 0.5).unwrap();
    let typed_sum = FlowSum::new(typed.clone(), octaves)
        .with_spin(1.0)
        .unwrap()
        .with_advection(0.5)
        .unwrap();
    same_values::<2, _>(&sum, &typed_sum, &mut rng);
    assert_eq!(sum.to_string().parse::<Spec>(), Ok(sum));
    let turbulence: Spec = "flow seed=3 angle=0.25 turbulence octaves=3"
        .parse()
        .unwrap();
    same_bits::<2, _>(
        &turbulence,
        &Fractal::turbulence(typed, Octaves::new(3, 1.99, 0.5).unwrap()),
        &mut rng,
    );
    assert!(matches!(flow.build::<3>(), Err(Error::Dimension { .. })));
    let e = "perlin angle=0.5".parse::<Spec>().unwrap_err();
    assert_eq!(
        e.refused(),
        Some(Error::NoSetting {
            noise: "perlin",
            setting: "angle"
        })
    );
    assert_eq!(e.position(), 7);
    let e = "flow advection=1 spin=17".parse::<Spec>().unwrap_err();
    assert_eq!(e.refused(), Some(Error::FlowSetting(17.0)));
    assert_eq!(e.position(), 22);
    assert!("flow angle=nan".parse::<Spec>().is_err());
    assert_eq!(
        Spec::new(Base::Flow, 0).with_angle(f32::INFINITY),
        Err(Error::FlowAngle(f32::INFINITY))
    );
}

/// The textures' specs sample the typed textures bit for bit, 1D–4D, with their defaults and
/// with settings; the settings print, read back, and are refused for other noises and out of
/// range (at the position of the value refused).
#[test]
fn texture_specs_sample_their_typed_textures_bit_for_bit() {
    let mut rng = Rng::from_env(192);
    fn all_dims<N>(spec: &Spec, typed: &N, rng: &mut Rng)
    where
        N: Noise<f32, 1> + Noise<f64, 1> + Noise<I16F16, 1>,
        N: Noise<f32, 2> + Noise<f64, 2> + Noise<I16F16, 2>,
        N: Noise<f32, 3> + Noise<f64, 3> + Noise<I16F16, 3>,
        N: Noise<f32, 4> + Noise<f64, 4> + Noise<I16F16, 4>,
    {
        same_values::<1, _>(spec, typed, rng);
        same_values::<2, _>(spec, typed, rng);
        same_values::<3, _>(spec, typed, rng);
        same_values::<4, _>(spec, typed, rng);
        assert_eq!(spec.to_string().parse::<Spec>().as_ref(), Ok(spec));
        assert!(spec.base().is_texture());
    }
    let parse = |t: &str| t.parse::<Spec>().expect("valid");
    all_dims(&parse("windy seed=4"), &Windy::new(4), &mut rng);
    all_dims(&parse("wrinkled seed=5"), &Wrinkled::new(5), &mut rng);
    all_dims(&parse("marble seed=6"), &Marble::new(6), &mut rng);
    all_dims(&parse("marble-olano seed=6"), &Marble::olano(6), &mut rng);
    all_dims(&parse("wood seed=7"), &Wood::new(7), &mut rng);
    all_dims(&parse("wood-olano seed=7"), &Wood::olano(7), &mut rng);
    all_dims(&parse("polka-dots seed=8"), &PolkaDots::new(8), &mut rng);
    let marble = parse("marble seed=6 variation=0.5 scale=3");
    assert_eq!(marble.to_string(), "marble seed=6 scale=3 variation=0.5");
    let typed = Marble::with_noise(Marble::new(6).noise().clone(), 3.0, 0.5).unwrap();
    all_dims(&marble, &typed, &mut rng);
    let wood = parse("wood-olano seed=1 rings=5 amount=-0.25");
    let typed = Wood::with_noise(Wood::olano(1).noise().clone(), 5.0, -0.25).unwrap();
    all_dims(&wood, &typed, &mut rng);
    let dots = parse("polka-dots seed=2 chance=0.75 radius=0.2");
    let typed = PolkaDots::new(2)
        .with_radius(0.2)
        .unwrap()
        .with_chance(0.75)
        .unwrap();
    all_dims(&dots, &typed, &mut rng);
    assert_eq!(
        parse("polka-dots").to_string(),
        "polka-dots seed=0 radius=0.35 chance=0.5"
    );
    // Settings for other noises, and out of range.
    let e = "marble rings=2".parse::<Spec>().unwrap_err();
    assert_eq!(
        e.refused(),
        Some(Error::NoSetting {
            noise: "marble",
            setting: "rings"
        })
    );
    assert_eq!(e.position(), 7);
    let e = "polka-dots radius=0.1 chance=1.5"
        .parse::<Spec>()
        .unwrap_err();
    assert!(matches!(
        e.refused(),
        Some(Error::TextureSetting { name: "chance", .. })
    ));
    assert_eq!(e.position(), 29);
    let e = "wood rings=0".parse::<Spec>().unwrap_err();
    assert!(matches!(
        e.refused(),
        Some(Error::TextureSetting { name: "rings", .. })
    ));
    assert_eq!(e.position(), 11);
    assert!(matches!(
        Spec::new(Base::Windy, 0).with_texture([1.0, 1.0]),
        Err(Error::NoSetting { noise: "windy", .. })
    ));
    assert!("windy period=4".parse::<Spec>().is_err());
}

/// A warped spec is `Warp` of the (summed) noise by `Components` of OpenSimplex2 noises seeded
/// `seed · 2⁸ + a + 1`, bit for bit (value and gradient); the amplitude prints last, reads back,
/// and is refused out of range and with a period, in either order.
#[test]
fn warped_specs_sample_their_typed_noise_bit_for_bit() {
    let mut rng = Rng::from_env(193);
    let spec: Spec = "perlin seed=2 warp=0.8 fbm octaves=5 lacunarity=2 gain=0.5"
        .parse()
        .expect("valid");
    assert_eq!(
        spec.to_string(),
        "perlin seed=2 fbm octaves=5 lacunarity=2 gain=0.5 warp=0.8"
    );
    let field = Components::new([OpenSimplex2::new(513), OpenSimplex2::new(514)]);
    let typed = Warp::new(
        Fractal::fbm(Perlin::new(2), Octaves::new(5, 2.0, 0.5).unwrap()),
        field,
        0.8,
    )
    .unwrap();
    same_bits::<2, _>(&spec, &typed, &mut rng);
    let cells: Spec = "cellular seed=1 output=f2-f1 warp=-0.25".parse().unwrap();
    let field = Components::new([
        OpenSimplex2::new(257),
        OpenSimplex2::new(258),
        OpenSimplex2::new(259),
    ]);
    let typed = Warp::new(
        Cellular::new(1).with_output(Output::F2MinusF1),
        field,
        -0.25,
    )
    .unwrap();
    same_bits::<3, _>(&cells, &typed, &mut rng);
    for (text, refused, at) in [
        ("perlin period=4 warp=1", Error::WarpedPeriod, 21),
        ("perlin warp=1 period=4", Error::WarpedPeriod, 21),
        ("perlin warp=2000", Error::WarpAmplitude(2000.0), 12),
    ] {
        let e = text.parse::<Spec>().unwrap_err();
        assert_eq!((e.refused(), e.position()), (Some(refused), at), "{text}");
    }
    assert_eq!(
        Spec::new(Base::Value, 0)
            .with_warp(1.0)
            .unwrap()
            .with_period(&[4]),
        Err(Error::WarpedPeriod)
    );
}

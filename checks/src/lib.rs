//! Checksums of a fixed set of samples of every bandnoise noise, in `I16F16` and `f32`: every
//! [`Base`] of the runtime description in each of its dimensions, composed descriptions, and
//! what a description does not name.
//!
//! The same function runs on the host (where build scripts turn it into the expected values),
//! in firmware under QEMU and in wasm32 in Chromium; equal checksums mean bit-identical results.
//! Each checksum folds the raw bits of 64 samples at fixed pseudo-random points into FNV-1a.
#![no_std]
#![forbid(unsafe_code)]
#![deny(missing_docs)]

pub mod count;
pub mod led;

use bandnoise::cellular::{Metric, Output};
use bandnoise::fractal::{Kind, Octaves};
use bandnoise::hash::{CellHash, CellRng, Poisson};
use bandnoise::impulse::{Envelope, Gabor, Orientation, Weights};
use bandnoise::lattice::{MixedMNoise, MixedTurbulence, Perlin, TabledPerlin};
use bandnoise::simplex::{Flow, FlowSum, Improve, OpenSimplex2, OpenSimplex2S, Simplex};
use bandnoise::spec::{Base, I16Tiles, Spec, SpecNoise};
use bandnoise::texture::{ColorMap, Marble, PolkaDots, Texture, Windy, Wood, Wrinkled};
use bandnoise::vector::{Components, Curl2, Curl3, VectorNoise, Warp};
use bandnoise::wavelet::{Bands, Distribution, Multiband, TILE2_I16, TILE3_I16, Tiling, Wavelet};
use bandnoise::wiener::Covariance;
use bandnoise::{
    FilteredNoise, I16F16, Noise, NoiseGradient, ProjectedNoise, ProjectedNoiseGradient, Real,
};

/// Samples per checksum.
pub const POINTS: u32 = 64;

/// The number of checksums [`checksums`] produces.
pub const COUNT: usize = 2 * (BASE_CHECKS + COMPOSED + OTHER.len());

/// Raw bits of a sample, the same for every number type's meaning of "bit-identical".
pub trait Bits: Real {
    /// The value's bits.
    fn bits(self) -> u32;
}
impl Bits for f32 {
    fn bits(self) -> u32 {
        self.to_bits()
    }
}
impl Bits for I16F16 {
    fn bits(self) -> u32 {
        self.to_bits() as u32
    }
}

/// FNV-1a over 32-bit words.
#[derive(Clone, Copy)]
struct Fnv(u32);
impl Fnv {
    fn new() -> Self {
        Fnv(0x811C_9DC5)
    }
    fn add(&mut self, word: u32) {
        for b in word.to_le_bytes() {
            self.0 = (self.0 ^ b as u32).wrapping_mul(0x0100_0193);
        }
    }
}

/// A point in `(-range, range)^D` from a counter, exactly representable in I16F16 and f32
/// (multiples of 2⁻¹⁶ below 256).
fn point<R: Real, const D: usize>(i: u32, range: i32) -> [R; D] {
    let mut p = [R::ZERO; D];
    for (a, c) in p.iter_mut().enumerate() {
        let mut h = i.wrapping_mul(0x9E37_79B9) ^ (a as u32).wrapping_mul(0x85EB_CA6B);
        h ^= h >> 15;
        h = h.wrapping_mul(0x2C1B_3C6D);
        h ^= h >> 12;
        let bits = (h % ((2 * range as u32) << 16)) as i32 - (range << 16);
        *c = R::from_ratio(bits, 16);
    }
    p
}

fn checksum<R: Bits, const D: usize>(noise: &impl Noise<R, D>, range: i32) -> u32 {
    let mut f = Fnv::new();
    for i in 0..POINTS {
        f.add(noise.sample(point::<R, D>(i, range)).bits());
    }
    f.0
}

/// The checksum of `spec` in `dims` dimensions over `(-range, range)^D`, with the quantized
/// wavelet tiles (the `f32` ones would not fit a microcontroller's flash); `u32::MAX` if the
/// spec does not build in `dims` dimensions (never for the lists below).
fn spec_checksum<R: Bits>(spec: &Spec, dims: usize, range: i32) -> u32 {
    // Out of line: inlined, each dimension's built noise took its own stack slot, and the
    // Cortex-M0's 16 KiB of RAM did not hold them all.
    #[inline(never)]
    fn one<R: Bits, const D: usize>(spec: &Spec, range: i32) -> u32
    where
        SpecNoise<D, I16Tiles>: Noise<R, D>,
    {
        spec.build_with::<D, I16Tiles>()
            .map_or(u32::MAX, |n| checksum::<R, D>(&n, range))
    }
    match dims {
        1 => one::<R, 1>(spec, range),
        2 => one::<R, 2>(spec, range),
        3 => one::<R, 3>(spec, range),
        _ => one::<R, 4>(spec, range),
    }
}

/// The seed of each base's checksums: 1 for the lattice noises, 3 for the wavelet noises.
const fn seed(base: Base) -> u32 {
    if base.is_wavelet() { 3 } else { 1 }
}

/// Every base in each of its dimensions, in the order of the checksums.
fn bases_and_dims() -> impl Iterator<Item = (Base, usize)> {
    Base::ALL.into_iter().flat_map(|base| {
        (1..=4)
            .filter(move |&d| base.has_dimension(d))
            .map(move |d| (base, d))
    })
}

/// How many checksums [`Base::ALL`] gives: one per base and dimension it has (as
/// [`bases_and_dims`], in `const`).
const BASE_CHECKS: usize = {
    let mut n = 0;
    let mut i = 0;
    while i < Base::ALL.len() {
        let mut d = 1;
        while d <= 4 {
            if Base::ALL[i].has_dimension(d) {
                n += 1;
            }
            d += 1;
        }
        i += 1;
    }
    n
};

/// Multiband noise with three bands from -1 and uniform values (also sampled projected).
fn uniform_multiband() -> Spec {
    let bands = Bands::new(-1, &[0.5, 1.0, 0.5]).unwrap_or_default();
    let spec = Spec::new(Base::Multiband, 3);
    // Refused only for another base.
    spec.with_bands(bands)
        .and_then(|s| s.with_distribution(Distribution::Uniform))
        .unwrap_or(spec)
}

/// Composed descriptions (fractal sums, periodic wraps, non-default settings): a name, the
/// spec, its dimensions and the range of the points.
const COMPOSED: usize = 18;

/// Entry `i` of [`composed`]. Out of line, so the whole list is on the stack only while it
/// is built, not while a checksum runs (the Cortex-M's 16 KiB of RAM: with the list held
/// across the loop, its 15th entry overflowed them).
#[inline(never)]
fn composed_entry(i: usize) -> (&'static str, Spec, usize, i32) {
    composed()[i % COMPOSED]
}

fn composed() -> [(&'static str, Spec, usize, i32); COMPOSED] {
    let octaves = Octaves::default();
    let periodic = |base, seed, period: &[u32]| {
        // In range: refused only for a wavelet base or periods outside 1..=65536.
        Spec::new(base, seed)
            .with_period(period)
            .unwrap_or(Spec::new(base, seed))
    };
    let band_pass = Spec::new(Base::Wiener, 2);
    // Accepted for Wiener noise.
    let band_pass = band_pass
        .with_covariance(Covariance::BandPass)
        .unwrap_or(band_pass);
    let gabor = |orientation, envelope, frequency| {
        let plain = Spec::new(Base::Gabor, 5);
        // Accepted for Gabor noise, in range.
        plain
            .with_orientation(orientation)
            .and_then(|s| s.with_envelope(envelope))
            .and_then(|s| s.with_spectrum(frequency, 0.5))
            .unwrap_or(plain)
    };
    let gabor_fixed = gabor(Orientation::Hybrid, Envelope::Hann, 1.0);
    // Accepted for Gabor noise.
    let gabor_fixed = gabor_fixed
        .with_fixed_count(3)
        .and_then(|s| s.with_weights(Weights::Uniform))
        .unwrap_or(gabor_fixed);
    let cellular = |output, metric, jitter| {
        let plain = Spec::new(Base::Cellular, 6);
        // Accepted for cellular noise, the jitter in range.
        plain
            .with_output(output)
            .and_then(|s| s.with_metric(metric))
            .and_then(|s| s.with_jitter(jitter))
            .unwrap_or(plain)
    };
    let gaussian_cubic = Spec::new(Base::ValueCubic, 7);
    // Accepted for cubic value noise.
    let gaussian_cubic = gaussian_cubic
        .with_distribution(Distribution::Gaussian)
        .unwrap_or(gaussian_cubic);
    let warped = Spec::new(Base::Perlin, 2).with_fractal(Kind::Fbm, octaves);
    // In range, and the noise not periodic.
    let warped = warped.with_warp(0.5).unwrap_or(warped);
    let flow = Spec::new(Base::Flow, 3);
    // Flow noise's settings, in range.
    let flow = flow
        .with_angle(0.3)
        .and_then(|s| s.with_flow_sum(2.0, 0.5))
        .unwrap_or(flow)
        .with_fractal(Kind::Fbm, octaves);
    let varied = |base| {
        // Accepted for a wavelet base.
        Spec::new(base, 3)
            .with_tiling(Tiling::Varied)
            .unwrap_or(Spec::new(base, 3))
    };
    [
        (
            "fbm perlin 3D",
            Spec::new(Base::Perlin, 2).with_fractal(Kind::Fbm, octaves),
            3,
            100,
        ),
        (
            "turbulence mnoise 3D",
            Spec::new(Base::MNoise, 2).with_fractal(Kind::Turbulence, octaves),
            3,
            100,
        ),
        ("multiband uniform 3D", uniform_multiband(), 3, 100),
        ("varied wavelet 2D", varied(Base::Wavelet), 2, 200),
        ("varied multiband 3D", varied(Base::Multiband), 3, 100),
        (
            "periodic perlin 3D",
            periodic(Base::Perlin, 4, &[5, 256, 1000]),
            3,
            2000,
        ),
        (
            "periodic value 2D",
            periodic(Base::Value, 4, &[3, 300]),
            2,
            2000,
        ),
        (
            "periodic value-cubic 2D",
            periodic(Base::ValueCubic, 4, &[3, 300]),
            2,
            2000,
        ),
        ("warped fbm perlin 2D", warped, 2, 200),
        ("advected flow fbm 2D", flow, 2, 200),
        ("band-pass wiener 2D", band_pass, 2, 200),
        ("band-pass wiener 3D", band_pass, 3, 200),
        (
            "isotropic truncated gabor 2D",
            gabor(Orientation::Isotropic, Envelope::Truncated, 3.0),
            2,
            200,
        ),
        (
            "isotropic gabor 3D",
            gabor(Orientation::Isotropic, Envelope::Hann, 2.0),
            3,
            100,
        ),
        ("hybrid fixed-count gabor 3D", gabor_fixed, 3, 100),
        (
            "manhattan f2-f1 cellular 2D",
            cellular(Output::F2MinusF1, Metric::Manhattan, 0.8),
            2,
            2000,
        ),
        (
            "chebyshev value cellular 3D",
            cellular(Output::CellValue, Metric::Chebyshev, 0.5),
            3,
            200,
        ),
        ("gaussian value-cubic 3D", gaussian_cubic, 3, 200),
    ]
}

/// Checksums of what is not a noise description: Gabor surface noise and filtering, projected
/// sampling, wavelet gradients, filtering and infinite noise, the cell hash and generator, the
/// kernels' `exp` and `cos`, [`TabledPerlin`] (Perlin's values through its table),
/// OpenSimplex2 and OpenSimplex2S in each orientation with gradients, and the textures'
/// patterns, colour maps and filtered dots (their values are also among the descriptions).
const OTHER: [&str; 15] = [
    "gabor surface",
    "gabor filtered",
    "multiband projected",
    "varied multiband projected",
    "wavelet gradients",
    "wavelet filtered",
    "wavelet infinite",
    "cell hash and generator",
    "exp and cos",
    "tabled perlin 2D",
    "tabled perlin 3D",
    "tabled perlin 4D",
    "simplex gradients, curl, flow, warp, mixed mnoise",
    "opensimplex2, opensimplex2s",
    "textures",
];

/// Gabor surface noise (isotropic: each impulse's direction turned into the plane) and Gabor
/// noise filtered by a footprint (each kernel filtered analytically). Out of line, for the
/// Cortex-M0's stack (see [`spec_checksum`]).
#[inline(never)]
fn gabor_checksums<R: Bits>() -> [u32; 2] {
    let gabor = Gabor::<3>::new(5).with_orientation(Orientation::Isotropic);
    let mut surface = Fnv::new();
    for i in 0..POINTS / 4 {
        let n = point::<R, 3>(i + 1000, 1);
        surface.add(gabor.sample_projected(point::<R, 3>(i, 100), n).bits());
    }
    let plane = Gabor::<2>::new(5).with_orientation(Orientation::Isotropic);
    let mut filtered = Fnv::new();
    for i in 0..POINTS / 4 {
        let [dx, dy] = [point::<R, 2>(i + 2000, 1), point::<R, 2>(i + 3000, 1)];
        filtered.add(plane.sample_filtered(point::<R, 2>(i, 100), dx, dy).bits());
    }
    [surface.0, filtered.0]
}

/// The checksums of the runtime description: every base in each of its dimensions, and the
/// composed descriptions (a [`Parts`] bit).
pub const DESCRIPTIONS: Parts = 1;
/// The checksums of what the description does not name (`OTHER`; a [`Parts`] bit).
pub const OTHERS: Parts = 2;
/// Which checksums a program computes: [`DESCRIPTIONS`], [`OTHERS`] or both (`3`). The
/// Cortex-M0's fixed-point checks run as two programs, one per part: its 256 KiB of flash do
/// not hold both parts' code.
pub type Parts = u8;

/// Checksums for every noise in one number type, in a fixed order (see [`names`]), of the
/// parts in `PARTS` (the others' slots are left as they are).
fn all<R: Bits, const PARTS: Parts>(out: &mut [u32]) {
    let (described, others) = out.split_at_mut(DESCRIBED);
    if PARTS & DESCRIPTIONS != 0 {
        descriptions::<R>(described);
    }
    if PARTS & OTHERS != 0 {
        not_described::<R>(others);
    }
}

/// How many checksums sample a runtime description (the first of each number type's half):
/// every base in each of its dimensions, then the composed descriptions.
pub const DESCRIBED: usize = BASE_CHECKS + COMPOSED;

/// Description `i` of the checksums (`i < DESCRIBED`): the spec, its dimensions and the
/// range of the points, `(-range, range)^dims`. For callers that rebuild the checksums from
/// the spec's text (the C library's example).
pub fn described(i: usize) -> Option<(Spec, usize, i32)> {
    if i < BASE_CHECKS {
        let (base, dims) = bases_and_dims().nth(i)?;
        Some((Spec::new(base, seed(base)), dims, BASE_RANGE))
    } else if i < DESCRIBED {
        let (_, spec, dims, range) = composed_entry(i - BASE_CHECKS);
        Some((spec, dims, range))
    } else {
        None
    }
}

/// The range of the base noises' checksum points.
const BASE_RANGE: i32 = 200;

/// The checksums of the runtime description in one number type.
fn descriptions<R: Bits>(out: &mut [u32]) {
    let mut k = 0;
    let mut push = |v: u32| {
        if let Some(slot) = out.get_mut(k) {
            *slot = v;
        }
        k += 1;
    };
    // Every base in each of its dimensions: a noise added to `Base` is checked here unasked.
    for (base, dims) in bases_and_dims() {
        push(spec_checksum::<R>(
            &Spec::new(base, seed(base)),
            dims,
            BASE_RANGE,
        ));
    }
    for i in 0..COMPOSED {
        let (_, spec, dims, range) = composed_entry(i);
        push(spec_checksum::<R>(&spec, dims, range));
    }
}

/// The checksums of what the description does not name, in one number type.
fn not_described<R: Bits>(out: &mut [u32]) {
    let mut k = 0;
    let mut push = |v: u32| {
        if let Some(slot) = out.get_mut(k) {
            *slot = v;
        }
        k += 1;
    };
    let [surface, filtered] = gabor_checksums::<R>();
    push(surface);
    push(filtered);
    let spec = uniform_multiband();
    for tiling in [Tiling::default(), Tiling::Varied] {
        let multi = Multiband::new(spec.seed(), &TILE3_I16, spec.bands(), spec.distribution())
            .with_tiling(tiling);
        let mut f = Fnv::new();
        for i in 0..POINTS / 4 {
            let n = point::<R, 3>(i + 1000, 1);
            f.add(multi.sample_projected(point::<R, 3>(i, 100), n).bits());
        }
        push(f.0);
    }
    // Wavelet gradients in the default tiling: a 2D and a 3D band, the 3D band projected, and
    // projected multiband noise (each value and slope).
    let mut f = Fnv::new();
    let band2 = Wavelet::new(spec.seed(), &TILE2_I16);
    let band3 = Wavelet::new(spec.seed(), &TILE3_I16);
    let multi = Multiband::new(spec.seed(), &TILE3_I16, spec.bands(), spec.distribution());
    let mut add = |(v, g): (R, [R; 3])| g.iter().chain([&v]).for_each(|x| f.add(x.bits()));
    for i in 0..POINTS / 4 {
        let (p, n) = (point::<R, 3>(i, 100), point::<R, 3>(i + 1000, 1));
        let (v, g) = band2.sample_with_gradient([p[0], p[1]]);
        add((v, [g[0], g[1], R::ZERO]));
        add(band3.sample_with_gradient(p));
        add(band3.sample_projected_with_gradient(p, n));
        add(multi.sample_projected_with_gradient(p, n));
    }
    push(f.0);
    // Filtered by footprints from none to past the finest band (3D multiband noise; the
    // Cortex-M0's 256 KiB hold no second copy of the widened basis).
    let mut f = Fnv::new();
    for i in 0..POINTS / 4 {
        let width = R::from_ratio(i as i32, 6);
        let (dx, dy) = ([width, R::ZERO, R::ZERO], [R::ZERO, width, width]);
        f.add(multi.sample_filtered(point::<R, 3>(i, 100), dx, dy).bits());
    }
    push(f.0);
    // Infinite noise at footprints from 2^-8 to 8 (3D multiband noise).
    let mut f = Fnv::new();
    for i in 0..POINTS / 4 {
        let footprint = R::from_ratio(i as i32 * 137 % 32768 + 1, 8);
        f.add(
            multi
                .sample_infinite(point::<R, 3>(i, 100), footprint)
                .bits(),
        );
    }
    push(f.0);
    // The cell hash and the cell generator: a hash, two uniforms and a Poisson count per cell.
    let mut f = Fnv::new();
    let hash = CellHash::new(5);
    let poisson = Poisson::new(3.5).ok();
    for i in 0..POINTS as i32 {
        let cell = [i * 7919 - 250_000, i.wrapping_mul(-104_729), i];
        f.add(hash.hash(cell));
        let mut rng = CellRng::new(&hash, cell);
        f.add(rng.uniform::<R>().bits());
        f.add(rng.signed_uniform::<R>().bits());
        f.add(poisson.as_ref().map_or(u32::MAX, |p| rng.poisson(p)));
    }
    push(f.0);
    // The kernels' e^-x and cos 2πx (Real::exp_neg, Real::cos_turns), from -1 to 17 and over
    // ±64 turns.
    let mut f = Fnv::new();
    for i in 0..16 * POINTS as i32 {
        f.add(R::from_ratio(i * 19 % 18_432 - 1024, 10).exp_neg().bits());
        f.add(
            R::from_ratio(i * 7919 % 131_072 - 65_536, 10)
                .cos_turns()
                .bits(),
        );
    }
    push(f.0);
    // Perlin with its table: on x86-64 the table's kernel, elsewhere Perlin's, so the host's
    // expected values check one against the other.
    let tabled = TabledPerlin::new(1);
    push(checksum::<R, 2>(&tabled, 200));
    push(checksum::<R, 3>(&tabled, 200));
    push(checksum::<R, 4>(&tabled, 200));
    push(vector_checksum::<R>());
    push(open_simplex_checksum::<R>());
    push(texture_checksum::<R>());
}

/// The textures: pbrt's windy waves, wrinkled, marble and polka dots (also filtered, by
/// footprints from 0 to past a cell), Lewis's wood, Olano's wood and marble (2D), each value
/// and pattern, and the colour maps (linear and B-spline).
/// Out of line, for the Cortex-M0's stack.
#[inline(never)]
fn texture_checksum<R: Bits>() -> u32 {
    let mut f = Fnv::new();
    let (windy, wrinkled) = (Windy::new(2), Wrinkled::new(2));
    let (marble, olano_marble) = (Marble::new(2), Marble::olano(2));
    let (wood, olano_wood, dots) = (Wood::new(2), Wood::olano(2), PolkaDots::new(2));
    fn add<R: Bits, T: Texture<R, 2>>(f: &mut Fnv, t: &T, p: [R; 2]) {
        f.add(t.sample(p).bits());
        f.add(t.pattern(p).bits());
    }
    for i in 0..POINTS / 4 {
        let p = point::<R, 2>(i, 100);
        add(&mut f, &windy, p);
        add(&mut f, &wrinkled, p);
        add(&mut f, &marble, p);
        add(&mut f, &olano_marble, p);
        add(&mut f, &wood, p);
        add(&mut f, &olano_wood, p);
        add(&mut f, &dots, p);
        let w = R::from_ratio(i as i32 * 29 % 80, 6);
        f.add(dots.sample_filtered(p, [w, R::ZERO], [R::ZERO, w]).bits());
        let t = R::from_ratio(i as i32 * 2731 % 1200 - 100, 10);
        for map in [ColorMap::MARBLE, ColorMap::WOOD] {
            map.map(t).iter().for_each(|c| f.add(c.bits()));
        }
    }
    f.0
}

/// OpenSimplex2 and OpenSimplex2S in 2D–4D and each orientation (values; 3D gradients, whose
/// chain rule runs through the turn). Out of line, for the Cortex-M0's stack.
#[inline(never)]
fn open_simplex_checksum<R: Bits>() -> u32 {
    let mut f = Fnv::new();
    for (k, improve) in [Improve::Standard, Improve::XY, Improve::XZ]
        .into_iter()
        .enumerate()
    {
        let fast = OpenSimplex2::new(-3 - k as i64).improving(improve);
        let smooth = OpenSimplex2S::new(k as i64 * 0x1234_5678_9ABC).improving(improve);
        for i in 0..POINTS / 8 {
            let p = point::<R, 4>(i + 64 * k as u32, 100);
            f.add(fast.sample([p[0], p[1]]).bits());
            f.add(smooth.sample([p[0], p[1]]).bits());
            f.add(fast.sample(p).bits());
            f.add(smooth.sample(p).bits());
            let (v, g) = fast.sample_with_gradient([p[0], p[1], p[2]]);
            g.iter().chain([&v]).for_each(|x| f.add(x.bits()));
            let (v, g) = smooth.sample_with_gradient([p[0], p[1], p[2]]);
            g.iter().chain([&v]).for_each(|x| f.add(x.bits()));
        }
    }
    f.0
}

/// Simplex noise's gradients (2D–4D, each value and slope), curl noise (2D over simplex
/// noise, 3D over three Perlin noises), flow noise at an angle (value and slope) and its
/// advected fBm, Perlin noise
/// warped by two simplex noises (value and slope), and mNoise from Olano's table (3D, 4D) and
/// its 4-octave turbulence. Out of line, for the Cortex-M0's stack.
#[inline(never)]
fn vector_checksum<R: Bits>() -> u32 {
    let mut f = Fnv::new();
    let simplex = Simplex::new(3);
    let flow = Curl2::new(simplex.clone());
    let flow3 = Curl3::new(Perlin::new(1), Perlin::new(2), Perlin::new(3));
    let turning = Flow::new(3).with_angle(0.3).unwrap_or_default();
    let advected = Octaves::new(4, 2.0, 0.5)
        .ok()
        .and_then(|o| FlowSum::new(turning.clone(), o).with_advection(0.4).ok());
    let field = Components::new([Simplex::new(4), Simplex::new(5)]);
    let warp = Warp::new(Perlin::new(1), field, 1.5).ok();
    let (mixed, turbulence) = (MixedMNoise::new(2), MixedTurbulence::<4>::new(2));
    for i in 0..POINTS / 4 {
        let p = point::<R, 4>(i, 100);
        let (v, g) = turning.sample_with_gradient([p[0], p[1]]);
        g.iter().chain([&v]).for_each(|x| f.add(x.bits()));
        if let Some(sum) = &advected {
            f.add(sum.sample([p[0], p[1]]).bits());
        }
        if let Some(w) = &warp {
            let (v, g) = w.sample_with_gradient([p[0], p[1]]);
            g.iter().chain([&v]).for_each(|x| f.add(x.bits()));
        }
        f.add(mixed.sample([p[0], p[1], p[2]]).bits());
        f.add(mixed.sample(p).bits());
        f.add(turbulence.sample([p[0], p[1], p[2]]).bits());
        let (v, g) = simplex.sample_with_gradient([p[0], p[1]]);
        g.iter().chain([&v]).for_each(|x| f.add(x.bits()));
        let (v, g) = simplex.sample_with_gradient([p[0], p[1], p[2]]);
        g.iter().chain([&v]).for_each(|x| f.add(x.bits()));
        let (v, g) = simplex.sample_with_gradient(p);
        g.iter().chain([&v]).for_each(|x| f.add(x.bits()));
        flow.sample_vector([p[0], p[1]])
            .iter()
            .for_each(|x| f.add(x.bits()));
        flow3
            .sample_vector([p[0], p[1], p[2]])
            .iter()
            .for_each(|x| f.add(x.bits()));
    }
    f.0
}

/// What a checksum samples: a base noise in some dimensions, or a named check. (Not the
/// spec's text, whose floats would bring float formatting into the firmware.)
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Name {
    /// [`Spec::new`] of the base with its seed, sampled in this many dimensions.
    Base(Base, usize),
    /// A composed description, projected sampling, the cell hash, or the tabled Perlin noise.
    Other(&'static str),
}

impl core::fmt::Display for Name {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Name::Base(base, dims) => write!(f, "{base} {dims}D"),
            Name::Other(name) => f.write_str(name),
        }
    }
}

/// The name of each checksum, in order (the same for both number types).
pub fn names() -> [Name; COUNT] {
    let mut names = [Name::Other(""); COUNT];
    let one = bases_and_dims()
        .map(|(base, dims)| Name::Base(base, dims))
        .chain(composed().map(|(name, ..)| Name::Other(name)))
        .chain(OTHER.map(Name::Other));
    for (slot, name) in names.iter_mut().zip(one) {
        *slot = name;
    }
    let (fixed, float) = names.split_at_mut(COUNT / 2);
    float.copy_from_slice(fixed);
    names
}

/// Whether checksum `i` is of I16F16 (the first half) or f32 (the second half).
pub const fn is_fixed(i: usize) -> bool {
    i < COUNT / 2
}

/// Compares [`checksums`] with `expected` (the host's), calling `report(number type, name,
/// got, expected)` for each difference; returns how many differ.
pub fn compare(expected: &[u32; COUNT], report: impl FnMut(&str, Name, u32, u32)) -> usize {
    compare_part::<true, true, { DESCRIPTIONS | OTHERS }>(expected, report).1
}

/// [`compare`] for the I16F16 checksums if `FIXED`, the f32 ones if `FLOAT`, of the
/// [`Parts`] in `PARTS`: a program that compares one number type, or one part, links the code
/// of that one only (the Cortex-M0's 256 KiB of flash do not hold it all). Returns how many
/// were compared and how many differ.
pub fn compare_part<const FIXED: bool, const FLOAT: bool, const PARTS: Parts>(
    expected: &[u32; COUNT],
    mut report: impl FnMut(&str, Name, u32, u32),
) -> (usize, usize) {
    let mut out = [0u32; COUNT];
    let (fixed, float) = out.split_at_mut(COUNT / 2);
    if FIXED {
        all::<I16F16, PARTS>(fixed);
    }
    if FLOAT {
        all::<f32, PARTS>(float);
    }
    let (mut compared, mut differ) = (0, 0);
    for (i, (g, e)) in out.iter().zip(expected).enumerate() {
        let part = if i % (COUNT / 2) < BASE_CHECKS + COMPOSED {
            DESCRIPTIONS
        } else {
            OTHERS
        };
        if !(if is_fixed(i) { FIXED } else { FLOAT }) || PARTS & part == 0 {
            continue;
        }
        compared += 1;
        if g != e {
            differ += 1;
            report(if is_fixed(i) { "I16F16" } else { "f32" }, name(i), *g, *e);
        }
    }
    (compared, differ)
}

/// The name of checksum `i`. Out of line: the list of every name (4 KB on a Cortex-M) is on
/// the stack only while a mismatch is reported, not under the checksums' own frames (the
/// chips' 16 KiB of RAM).
#[inline(never)]
fn name(i: usize) -> Name {
    names()[i % COUNT]
}

/// Every checksum: I16F16 first, then f32.
pub fn checksums() -> [u32; COUNT] {
    let mut out = [0u32; COUNT];
    let (fixed, float) = out.split_at_mut(COUNT / 2);
    all::<I16F16, { DESCRIPTIONS | OTHERS }>(fixed);
    all::<f32, { DESCRIPTIONS | OTHERS }>(float);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_base_is_checked_in_each_of_its_dimensions() {
        let names = names();
        for base in Base::ALL {
            for dims in 1..=4 {
                let checked = names.contains(&Name::Base(base, dims));
                assert_eq!(checked, base.has_dimension(dims), "{base} {dims}D");
            }
        }
        let c = checksums();
        assert_eq!(c.len(), COUNT);
        assert!(c.iter().all(|&v| v != u32::MAX), "every spec builds");
    }
}

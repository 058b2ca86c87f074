//! Checksums of a fixed set of samples of every bandnoise noise, in `I16F16` and `f32`.
//!
//! The same function runs on the host (where build scripts turn it into the expected values),
//! in firmware under QEMU and in wasm32 in Chromium; equal checksums mean bit-identical results.
//! Each checksum folds the raw bits of 64 samples at fixed pseudo-random points into FNV-1a.
#![no_std]
#![forbid(unsafe_code)]
#![deny(missing_docs)]

pub mod count;
pub mod led;

use bandnoise::fractal::{Fractal, Octaves};
use bandnoise::hash::{CellHash, CellRng, Poisson};
use bandnoise::lattice::{
    CNoise, MNoise, OriginalPerlin, Periodic, Perlin, TabledPerlin, ValueNoise,
};
use bandnoise::wavelet::{Bands, Distribution, Multiband, TILE2_I16, TILE3_I16, Wavelet};
use bandnoise::{I16F16, Noise, ProjectedNoise, Real};

/// Samples per checksum.
pub const POINTS: u32 = 64;

/// The number of checksums [`checksums`] produces.
pub const COUNT: usize = 2 * (6 * 4 + 11);

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

/// Checksums for every noise in one number type, in a fixed order (see [`NAMES`]).
fn all<R: Bits>(out: &mut [u32]) {
    let mut k = 0;
    let mut push = |v: u32| {
        out[k] = v;
        k += 1;
    };
    macro_rules! dims {
        ($n:expr) => {{
            let n = $n;
            push(checksum::<R, 1>(&n, 200));
            push(checksum::<R, 2>(&n, 200));
            push(checksum::<R, 3>(&n, 200));
            push(checksum::<R, 4>(&n, 200));
        }};
    }
    dims!(Perlin::new(1));
    dims!(OriginalPerlin::new(1));
    dims!(ValueNoise::new(1));
    dims!(CNoise::new(1));
    dims!(MNoise::<61>::seeded(1));
    dims!(MNoise::<4093>::seeded(1));
    let octaves = Octaves::default();
    push(checksum::<R, 3>(
        &Fractal::fbm(Perlin::new(2), octaves),
        100,
    ));
    push(checksum::<R, 3>(
        &Fractal::turbulence(MNoise::<61>::seeded(2), octaves),
        100,
    ));
    push(checksum::<R, 2>(&Wavelet::new(3, &TILE2_I16), 200));
    push(checksum::<R, 3>(&Wavelet::new(3, &TILE3_I16), 200));
    let bands = Bands::new(-1, &[0.5, 1.0, 0.5]).unwrap_or_default();
    let multi = Multiband::new(3, &TILE3_I16, bands, Distribution::Uniform);
    push(checksum::<R, 3>(&multi, 100));
    let mut f = Fnv::new();
    for i in 0..POINTS / 4 {
        let n = point::<R, 3>(i + 1000, 1);
        f.add(multi.sample_projected(point::<R, 3>(i, 100), n).bits());
    }
    push(f.0);
    if let Ok(p) = Periodic::new(Perlin::new(4), [5, 256, 1000]) {
        push(checksum::<R, 3>(&p, 2000));
    }
    if let Ok(p) = Periodic::new(ValueNoise::new(4), [3, 300]) {
        push(checksum::<R, 2>(&p, 2000));
    }
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
    // Perlin with its table: on x86-64 the table's kernel, elsewhere Perlin's, so the host's
    // expected values check one against the other.
    let tabled = TabledPerlin::new(1);
    push(checksum::<R, 2>(&tabled, 200));
    push(checksum::<R, 3>(&tabled, 200));
}

/// The name of each checksum, in order.
pub const NAMES: [&str; COUNT] = {
    const ONE: [&str; COUNT / 2] = [
        "perlin 1D",
        "perlin 2D",
        "perlin 3D",
        "perlin 4D",
        "original 1D",
        "original 2D",
        "original 3D",
        "original 4D",
        "value 1D",
        "value 2D",
        "value 3D",
        "value 4D",
        "cnoise 1D",
        "cnoise 2D",
        "cnoise 3D",
        "cnoise 4D",
        "mnoise61 1D",
        "mnoise61 2D",
        "mnoise61 3D",
        "mnoise61 4D",
        "mnoise4093 1D",
        "mnoise4093 2D",
        "mnoise4093 3D",
        "mnoise4093 4D",
        "fbm perlin 3D",
        "turbulence mnoise 3D",
        "wavelet 2D",
        "wavelet 3D",
        "multiband uniform 3D",
        "multiband projected",
        "periodic perlin 3D",
        "periodic value 2D",
        "cell hash and generator",
        "tabled perlin 2D",
        "tabled perlin 3D",
    ];
    let mut names = [""; COUNT];
    let mut i = 0;
    while i < COUNT / 2 {
        names[i] = ONE[i]; // I16F16
        names[i + COUNT / 2] = ONE[i]; // f32
        i += 1;
    }
    names
};

/// Whether checksum `i` is of I16F16 (the first half) or f32 (the second half).
pub const fn is_fixed(i: usize) -> bool {
    i < COUNT / 2
}

/// Compares [`checksums`] with `expected` (the host's), calling `report(number type, name,
/// got, expected)` for each difference; returns how many differ.
pub fn compare(expected: &[u32; COUNT], mut report: impl FnMut(&str, &str, u32, u32)) -> usize {
    let mut differ = 0;
    for (i, (g, e)) in checksums().iter().zip(expected).enumerate() {
        if g != e {
            differ += 1;
            report(if is_fixed(i) { "I16F16" } else { "f32" }, NAMES[i], *g, *e);
        }
    }
    differ
}

/// Every checksum: I16F16 first, then f32.
pub fn checksums() -> [u32; COUNT] {
    let mut out = [0u32; COUNT];
    let (fixed, float) = out.split_at_mut(COUNT / 2);
    all::<I16F16>(fixed);
    all::<f32>(float);
    out
}

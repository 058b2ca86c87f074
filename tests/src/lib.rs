//! Shared helpers for bandnoise's integration tests and benchmarks: a seeded generator whose seed
//! can be replayed from the environment, an enum over every lattice noise so a test can loop over
//! all of them, and small statistics.

pub mod agree;
pub mod spectral;

use bandnoise::Error;
use bandnoise::batch::{Grid, LANES};
use bandnoise::prelude::*;
use bandnoise::spec::Base;

/// SplitMix64, for test inputs.
#[derive(Clone, Debug)]
pub struct Rng(u64);

impl Rng {
    /// A generator for `default`, or for `BANDNOISE_TEST_SEED` when that is set (to replay a
    /// failure). Prints the seed so a failing run names it.
    pub fn from_env(default: u64) -> Self {
        let seed = std::env::var("BANDNOISE_TEST_SEED")
            .ok()
            .and_then(|s| s.parse().ok())
            .unwrap_or(default);
        println!("test seed {seed} (replay with BANDNOISE_TEST_SEED={seed})");
        Rng(seed)
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in `[lo, hi)`.
    pub fn f64_in(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * ((self.next_u64() >> 11) as f64 / (1u64 << 53) as f64)
    }

    /// Uniform integer in `[lo, hi)`.
    pub fn i32_in(&mut self, lo: i32, hi: i32) -> i32 {
        (lo as i64 + (self.next_u64() % (hi as i64 - lo as i64) as u64) as i64) as i32
    }

    /// A coordinate that `I16F16`, `f32` and `f64` all hold exactly: a multiple of 2⁻¹⁶ in
    /// `(-range, range)` with `range ≤ 256`.
    pub fn exact_coord(&mut self, range: i32) -> I16F16 {
        assert!(
            range <= 256,
            "beyond 256, f32 cannot hold every multiple of 2^-16"
        );
        I16F16::from_bits(self.i32_in(-(range << 16) + 1, range << 16))
    }

    /// A point of exact coordinates.
    pub fn exact_point<const D: usize>(&mut self, range: i32) -> [I16F16; D] {
        core::array::from_fn(|_| self.exact_coord(range))
    }
}

/// Coordinates every noise must take without a panic and give a documented value for: NaN,
/// the infinities, the largest magnitudes, a subnormal and negative zero.
pub const BAD_F32: [f32; 7] = [
    f32::NAN,
    f32::INFINITY,
    f32::NEG_INFINITY,
    3e38,
    -3e38,
    1e-40,
    -0.0,
];

/// The same point in another number type (exact for points from [`Rng::exact_point`]).
pub fn to_f32<const D: usize>(p: [I16F16; D]) -> [f32; D] {
    p.map(|x| x.to_num::<f32>())
}

/// The same point in f64.
pub fn to_f64<const D: usize>(p: [I16F16; D]) -> [f64; D] {
    p.map(|x| x.to_num::<f64>())
}

/// Every lattice noise of the kernel, so a test can loop over all of them.
#[derive(Clone, Debug)]
pub enum Lattice {
    /// Perlin's improved noise (boxed: 512 bytes, the others a few).
    Perlin(Box<Perlin>),
    /// Perlin's improved noise with its per-seed table (boxed: 32.5 KiB on x86-64).
    Tabled(Box<TabledPerlin>),
    /// Perlin's original noise.
    Original(OriginalPerlin),
    /// Value noise.
    Value(ValueNoise),
    /// Olano's cNoise.
    C(CNoise),
    /// Olano's mNoise, the paper's M = 61.
    M61(MNoise<61>),
    /// mNoise with the largest modulus exact in f32.
    M4093(MNoise<4093>),
}

impl Lattice {
    /// Every lattice noise for `seed`, with its name: each lattice [`Base`] of the runtime
    /// description (its text name), then [`TabledPerlin`] (Perlin's noise through its table).
    pub fn all(seed: u32) -> Vec<(&'static str, Lattice)> {
        let mut all: Vec<_> = Base::ALL
            .into_iter()
            .filter(|b| b.is_lattice())
            .map(|b| (b.name(), Lattice::of(b, seed)))
            .collect();
        all.push((
            "tabled perlin",
            Lattice::Tabled(Box::new(TabledPerlin::new(seed))),
        ));
        all
    }

    /// The typed noise of a lattice `base` for `seed`.
    ///
    /// # Panics
    ///
    /// For a base that is not a lattice noise, and for a lattice base this helper does not
    /// know yet: every test that loops over [`Lattice::all`] fails until it is added here.
    pub fn of(base: Base, seed: u32) -> Lattice {
        match base {
            Base::Perlin => Lattice::Perlin(Box::new(Perlin::new(seed))),
            Base::OriginalPerlin => Lattice::Original(OriginalPerlin::new(seed)),
            Base::Value => Lattice::Value(ValueNoise::new(seed)),
            Base::CNoise => Lattice::C(CNoise::new(seed)),
            Base::MNoise => Lattice::M61(MNoise::new(seed)),
            Base::MNoise4093 => Lattice::M4093(MNoise::seeded(seed)),
            other => panic!("{other} is not a lattice noise of the test helper `Lattice`"),
        }
    }

    /// The gradient noises (everything but value noise).
    pub fn gradient_noises(seed: u32) -> Vec<(&'static str, Lattice)> {
        Self::all(seed)
            .into_iter()
            .filter(|(_, n)| !matches!(n, Lattice::Value(_)))
            .collect()
    }
}

macro_rules! delegate {
    ($self:ident, $n:ident => $e:expr) => {
        match $self {
            Lattice::Perlin($n) => {
                let $n: &Perlin = $n;
                $e
            }
            Lattice::Tabled($n) => {
                let $n: &TabledPerlin = $n;
                $e
            }
            Lattice::Original($n) => $e,
            Lattice::Value($n) => $e,
            Lattice::C($n) => $e,
            Lattice::M61($n) => $e,
            Lattice::M4093($n) => $e,
        }
    };
}

impl<R: Real, const D: usize> Noise<R, D> for Lattice
where
    Perlin: Noise<R, D>,
    TabledPerlin: Noise<R, D>,
    OriginalPerlin: Noise<R, D>,
    ValueNoise: Noise<R, D>,
    CNoise: Noise<R, D>,
    MNoise<61>: Noise<R, D>,
    MNoise<4093>: Noise<R, D>,
{
    fn sample(&self, p: [R; D]) -> R {
        delegate!(self, n => n.sample(p))
    }
    fn amplitude_bound(&self) -> f32 {
        delegate!(self, n => Noise::<R, D>::amplitude_bound(n))
    }
    fn sample_lanes(&self, p: &[[R; LANES]; D], out: &mut [R; LANES]) {
        delegate!(self, n => n.sample_lanes(p, out))
    }
    // Forwarded too, so tests through this enum reach each noise's own grid kernel.
    fn fill_grid(&self, grid: &Grid<R, D>, out: &mut [R]) -> Result<(), Error> {
        delegate!(self, n => n.fill_grid(grid, out))
    }
    fn fill_points(&self, points: [&[R]; D], out: &mut [R]) -> Result<(), Error> {
        delegate!(self, n => n.fill_points(points, out))
    }
}

impl<R: Real, const D: usize> NoiseGradient<R, D> for Lattice
where
    Perlin: NoiseGradient<R, D>,
    TabledPerlin: NoiseGradient<R, D>,
    OriginalPerlin: NoiseGradient<R, D>,
    ValueNoise: NoiseGradient<R, D>,
    CNoise: NoiseGradient<R, D>,
    MNoise<61>: NoiseGradient<R, D>,
    MNoise<4093>: NoiseGradient<R, D>,
{
    fn sample_with_gradient(&self, p: [R; D]) -> (R, [R; D]) {
        delegate!(self, n => n.sample_with_gradient(p))
    }
}

/// Samples `f(x, y)` over an `n × n` grid `step` apart and sums the results (for benchmarks:
/// the sum keeps the work from being optimised away).
pub fn grid_sum<R: Real>(n: usize, step: f32, f: impl Fn(R, R) -> R) -> R {
    let step = R::from_f32(step);
    let mut acc = R::ZERO;
    let mut y = R::ZERO;
    for _ in 0..n {
        let mut x = R::ZERO;
        for _ in 0..n {
            acc = acc.saturating_add(f(std::hint::black_box(x), std::hint::black_box(y)));
            x = x + step;
        }
        y = y + step;
    }
    acc
}

/// Pearson correlation of two equally long samples.
pub fn correlation(a: &[f64], b: &[f64]) -> f64 {
    assert_eq!(a.len(), b.len());
    let n = a.len() as f64;
    let (ma, mb) = (a.iter().sum::<f64>() / n, b.iter().sum::<f64>() / n);
    let (mut sab, mut saa, mut sbb) = (0.0, 0.0, 0.0);
    for (x, y) in a.iter().zip(b) {
        sab += (x - ma) * (y - mb);
        saa += (x - ma) * (x - ma);
        sbb += (y - mb) * (y - mb);
    }
    sab / (saa * sbb).sqrt()
}

/// Runs `$body` once for every dimension 1..=4 with `const $d: usize` bound to it.
#[macro_export]
macro_rules! for_each_dim {
    ($f:ident ( $($args:expr),* )) => {{
        $f::<1>($($args),*);
        $f::<2>($($args),*);
        $f::<3>($($args),*);
        $f::<4>($($args),*);
    }};
}

/// A noise in `D` dimensions for all three number types (a bound for tests generic over `D`).
pub trait AllTypes<const D: usize>: Noise<f32, D> + Noise<f64, D> + Noise<I16F16, D> {}
impl<const D: usize, T: Noise<f32, D> + Noise<f64, D> + Noise<I16F16, D>> AllTypes<D> for T {}

/// The README's example, compiled and run as a doctest so it stays true.
#[doc = include_str!("../../README.md")]
mod readme {}

/// The guide's example (`docs/guide.md`), compiled and run as a doctest.
#[doc = include_str!("../../docs/guide.md")]
mod guide {}

/// The power spectrum `|F(kx, ky)|²` of a square grid of samples (side a power of two, row
/// by row), optionally under a separable Hann window (for fields that are not periodic over the
/// grid: without it, the jump between the grid's opposite edges spreads power everywhere).
pub fn power_spectrum(grid: &[f64], side: usize, hann: bool) -> Vec<f64> {
    assert_eq!(grid.len(), side * side);
    let window: Vec<f64> = (0..side)
        .map(|i| {
            if hann {
                let t = std::f64::consts::PI * (i as f64 + 0.5) / side as f64;
                t.sin() * t.sin()
            } else {
                1.0
            }
        })
        .collect();
    let windowed: Vec<f64> = grid
        .iter()
        .enumerate()
        .map(|(i, &v)| v * window[i % side] * window[i / side])
        .collect();
    bandnoise_analysis::power(&windowed, side)
}

/// The signed frequency of FFT bin `k` of `side` bins, in cycles per unit for samples
/// `spacing` units apart.
pub fn bin_frequency(k: usize, side: usize, spacing: f64) -> f64 {
    let k = if k > side / 2 {
        k as f64 - side as f64
    } else {
        k as f64
    };
    k / (side as f64 * spacing)
}

/// The fraction of a square grid's power (side a power of two, the mean excluded) in the
/// frequency bins `(x, y)` that `select` picks. `hann` as in [`power_spectrum`].
pub fn power_fraction(
    grid: &[f64],
    side: usize,
    hann: bool,
    select: impl Fn(usize, usize) -> bool,
) -> f64 {
    let mean = grid.iter().sum::<f64>() / grid.len() as f64;
    let centred: Vec<f64> = grid.iter().map(|v| v - mean).collect();
    let power = power_spectrum(&centred, side, hann);
    let (mut picked, mut total) = (0.0, 0.0);
    for y in 0..side {
        for x in 0..side {
            if x == 0 && y == 0 {
                continue;
            }
            let p = power[y * side + x];
            total += p;
            if select(x, y) {
                picked += p;
            }
        }
    }
    picked / total
}

/// The fraction of a square grid's power (samples `spacing` units apart, side a power of two,
/// the mean excluded) below `cutoff` cycles per unit radially. `hann` as in [`power_spectrum`].
pub fn low_frequency_fraction_windowed(
    grid: &[f64],
    side: usize,
    spacing: f64,
    cutoff: f64,
    hann: bool,
) -> f64 {
    power_fraction(grid, side, hann, |x, y| {
        let (fx, fy) = (
            bin_frequency(x, side, spacing),
            bin_frequency(y, side, spacing),
        );
        fx.hypot(fy) < cutoff
    })
}

/// Radially binned power of a square grid of samples (side a power of two), `spacing` units
/// apart: the fraction of the power below `cutoff` cycles per unit, the mean (DC bin) excluded,
/// without a window (for grids over which the field is periodic).
pub fn low_frequency_fraction(grid: &[f64], side: usize, spacing: f64, cutoff: f64) -> f64 {
    low_frequency_fraction_windowed(grid, side, spacing, cutoff, false)
}

/// A number type's bad inputs, for the bad-input tests (`api-tests/tests/contract.rs`,
/// `bad_input.rs`): the values a sweep of the public API from outside the crate found worth
/// trying.
pub trait Special: Real + std::fmt::Display {
    /// The type's name, for messages.
    const NAME: &'static str;
    /// Bad coordinates, each with the coordinate it is documented to sample where the
    /// [`Noise`] contract says so (NaN, ±∞ and −0.0 sample 0).
    fn specials() -> Vec<(Self, Option<Self>)>;
    /// Whether the value is `-0.0` (which no sample may return).
    fn is_negative_zero(self) -> bool;
    /// The nearest value to `x` (for random points in a moderate range).
    fn from_f64(x: f64) -> Self;
    /// The bits of the value as an `f64` (injective for all three types), to compare results
    /// bit for bit.
    fn bits(self) -> u64 {
        self.to_f64().to_bits()
    }
}

macro_rules! float_specials {
    ($t:ty, $extra:expr) => {
        impl Special for $t {
            const NAME: &'static str = stringify!($t);
            fn specials() -> Vec<(Self, Option<Self>)> {
                let two31 = 2_147_483_648.0;
                let tiny = <$t>::from_bits(1);
                let mut v = vec![
                    (<$t>::NAN, Some(0.0)),
                    (<$t>::INFINITY, Some(0.0)),
                    (<$t>::NEG_INFINITY, Some(0.0)),
                    (-0.0, Some(0.0)),
                    (1e30, None),
                    (-1e30, None),
                    (f32::MAX as $t, None),
                    (f32::MIN as $t, None),
                    (f32::MIN_POSITIVE as $t, None),
                    (tiny, None),
                    (-tiny, None),
                    (two31, None),
                    (-two31, None),
                ];
                v.extend($extra);
                v
            }
            fn is_negative_zero(self) -> bool {
                self == 0.0 && self.is_sign_negative()
            }
            fn from_f64(x: f64) -> Self {
                x as $t
            }
        }
    };
}
float_specials!(f32, Vec::<(f32, Option<f32>)>::new());
float_specials!(
    f64,
    [
        (f64::MAX, None),
        (f64::MIN, None),
        (f64::MIN_POSITIVE, None),
        (f32::from_bits(1) as f64, None),
    ]
);

impl Special for I16F16 {
    const NAME: &'static str = "I16F16";
    fn specials() -> Vec<(Self, Option<Self>)> {
        [I16F16::MAX, I16F16::MIN, I16F16::DELTA, -I16F16::DELTA]
            .into_iter()
            .map(|x| (x, None))
            .collect()
    }
    fn is_negative_zero(self) -> bool {
        false
    }
    fn from_f64(x: f64) -> Self {
        I16F16::saturating_from_num(x)
    }
}

//! # bandnoise
//!
//! Procedural noise that is band-limited, the same on every target, and never panics: from a
//! Cortex-M0 without an FPU to a browser tab.
//!
//! Graphics research has spent forty years making noise better: Perlin's 1985 gradient noise and
//! its 2002 improvement, Olano's table-free modified noise (2005), Cook and DeRose's wavelet noise
//! (2005). bandnoise implements them from the papers, once, over one numeric trait, so the same
//! noise runs in `f32`, `f64` and fixed point ([`I16F16`]).
//!
//! * [`Real`]: the sealed numeric trait (`f32`, `f64`, [`I16F16`]).
//! * [`Noise`], [`NoiseGradient`]: the sampling traits every noise implements.
//! * [`hash`]: Olano's Blum-Blum-Shub hash, Perlin's permutation, a well-mixed cell hash and a
//!   cell's own random numbers.
//! * [`lattice`]: Perlin (improved and original), value noise, Olano's cNoise and mNoise, 1D–4D,
//!   and any of them periodic ([`Periodic`](lattice::Periodic)); Lewis's lattice white noise
//!   and its Catmull-Rom interpolant.
//! * [`simplex`]: simplex noise (Perlin 2001, Gustavson 2005), 1D–4D, continuous, with its
//!   analytic gradient.
//! * [`cellular`]: Worley's cellular noise, 1D–4D: `F1`, `F2`, `F2 − F1` or the cell's value
//!   in four metrics, exact (a pruned search, equal to brute force), with analytic gradients.
//! * [`vector`]: curl noise (Bridson et al. 2007) from any noise's analytic gradient.
//! * [`fractal`]: fBm, turbulence and ridged sums over any noise, with pbrt's anti-aliasing.
//! * [`impulse`]: Lewis's sparse convolution noise and Lagae et al.'s Gabor noise: random
//!   impulses per cell convolved with a kernel, normalised by Campbell's theorem.
//! * [`wiener`]: Lewis's Wiener-interpolated lattice noise.
//! * [`wavelet`]: Cook and DeRose's wavelet noise: band-limited bands over tiles computed at
//!   compile time, projected onto surfaces, summed into multiband noise.
//! * [`texture`]: pbrt's windy waves, wrinkled, marble and polka dots, Lewis's solid wood,
//!   Olano's wood and marble, with colour maps.
//! * [`batch`]: grids and point arrays in one call, vectorised, bit-identical to `sample`.
//! * [`levels`]: noise values as `u8`, `u16` and `i16` for LED, display and audio code, with
//!   no division per sample.
//! * [`spec`]: a noise as a value with a text form (`perlin seed=7 fbm octaves=4`), for
//!   callers that cannot name Rust types; sampling it gives the typed noise's bits.
//!
//! # Example
//!
//! ```
//! use bandnoise::{I16F16, Noise, fractal::{Fractal, Octaves}, lattice::{MNoise, Perlin}};
//!
//! // Perlin's reference value, bit for bit.
//! assert_eq!(Perlin::new(0).sample([3.14f64, 42.0, 7.0]), 0.13691995878400012);
//!
//! // Olano's mNoise in fixed point: no tables, no floating point.
//! let m = MNoise::<61>::new(1);
//! let v: I16F16 = m.sample([I16F16::from_num(1.5), I16F16::from_num(2.25)]);
//! assert!(v.abs() <= I16F16::ONE);
//!
//! // Any noise in a fractal sum.
//! let fbm = Fractal::fbm(m, Octaves::default());
//! let _: f32 = fbm.sample([0.1, 0.2, 0.3]);
//! ```
//!
//! # Seeds
//!
//! Every noise takes a `u32` seed, first, in `new` (`MNoise::<M>::seeded` for a modulus other
//! than Olano's 61). Every `new` is `const` except [`Multiband::new`](wavelet::Multiband::new),
//! which normalises its band weights at run time, and
//! [`SparseConvolution::new`](impulse::SparseConvolution::new) and
//! [`Gabor::new`](impulse::Gabor::new), which tabulate their Poisson counts and normalise their
//! variance, [`WienerNoise::new`](wiener::WienerNoise::new) and
//! [`MixedTurbulence::new`](lattice::MixedTurbulence::new). How the seed enters:
//!
//! | noise | the seed … | seed 0 |
//! |---|---|---|
//! | [`Perlin`](lattice::Perlin), [`TabledPerlin`](lattice::TabledPerlin), [`Simplex`](simplex::Simplex), [`OriginalPerlin`](lattice::OriginalPerlin), [`ValueNoise`](lattice::ValueNoise), [`CNoise`](lattice::CNoise) | reshuffles the permutation (Fisher–Yates driven by SplitMix64 of the seed) | Perlin's 2002 table |
//! | [`MNoise`](lattice::MNoise), [`MixedMNoise`](lattice::MixedMNoise), [`MixedTurbulence`](lattice::MixedTurbulence) | translates the lattice by `o ∈ [0, M)⁴` and flips gradient axes by a 4-bit mask (SplitMix64 of the seed) | Olano's noise, untouched |
//! | [`Wavelet`](wavelet::Wavelet) | picks each tile-sized block's orientation (48 in 3D, 8 in 2D) by a hash of the block and the seed | one orientation hash like any other |
//! | [`Multiband`](wavelet::Multiband) | as [`Wavelet`](wavelet::Wavelet), and translates each band by a hash of the seed and the band | as any other seed |
//! | [`CellHash`](hash::CellHash) | is mixed into the start of every cell's hash chain | as any other seed |
//! | [`SparseConvolution`](impulse::SparseConvolution), [`Gabor`](impulse::Gabor) | is its [`CellHash`](hash::CellHash)'s seed: every cell's impulses change | as any other seed |
//! | [`Cellular`](cellular::Cellular) | is its [`CellHash`](hash::CellHash)'s seed: every cell's feature point and value change | as any other seed |
//! | [`WhiteNoise`](lattice::WhiteNoise), [`CubicValueNoise`](lattice::CubicValueNoise) | is its [`CellHash`](hash::CellHash)'s seed: every cell's table entry changes | as any other seed |
//!
//! Different seeds give decorrelated noise (tested: |correlation| < 0.05 on a 256² grid).
//!
//! # Guarantees
//!
//! * `#![no_std]`, no allocation, `#![forbid(unsafe_code)]`.
//! * Sampling is total: every input, NaN and infinities included, gives a documented value and
//!   never a panic (see [`Noise`]).
//! * `f32` and `f64` results use only IEEE `+ − × ÷` (and `libm` where more is needed), so they
//!   are bit-identical on every target; fixed point is integer arithmetic and bit-identical
//!   everywhere. Where a target has a hand-vectorised kernel (in `f32`: Perlin 2D/3D/4D on
//!   x86-64 with SSE2 and in WebAssembly with `simd128`, simplex corners and cellular noise's
//!   near cells on x86-64; all of them in one module, `arch`, chosen by `cfg`), it performs
//!   the same operations in the same order: the values are the same.
#![no_std]
#![forbid(unsafe_code)]
#![deny(missing_docs)]

mod arch;
pub mod batch;
pub mod cellular;
mod decimal;
mod error;
pub mod fractal;
pub mod hash;
pub mod impulse;
pub mod lattice;
pub mod levels;
mod noise;
mod radial;
mod real;
pub mod simplex;
pub mod spec;
mod special;
#[cfg(test)]
mod testing;
pub mod texture;
pub mod vector;
pub mod wavelet;
pub mod wiener;

pub use error::Error;
pub use noise::{FilteredNoise, Noise, NoiseGradient, ProjectedNoise, ProjectedNoiseGradient};
pub use real::{I16F16, Real};

/// The traits and types most programs need: `use bandnoise::prelude::*;`.
pub mod prelude {
    pub use crate::batch::Grid;
    pub use crate::cellular::Cellular;
    pub use crate::fractal::{Fractal, Kind, Octaves};
    pub use crate::impulse::{Gabor, SparseConvolution};
    pub use crate::lattice::{
        CNoise, CubicValueNoise, MNoise, MixedMNoise, MixedTurbulence, OriginalPerlin, Periodic,
        Perlin, TabledPerlin, ValueNoise, WhiteNoise,
    };
    pub use crate::simplex::{Flow, FlowSum, Improve, OpenSimplex2, OpenSimplex2S, Simplex};
    pub use crate::texture::{ColorMap, Marble, PolkaDots, Texture, Windy, Wood, Wrinkled};
    pub use crate::vector::{Components, Curl2, Curl3, VectorNoise, Warp};
    pub use crate::wavelet::{Bands, Distribution, Multiband, TILE2, TILE3, Wavelet};
    pub use crate::{
        FilteredNoise, I16F16, Noise, NoiseGradient, ProjectedNoise, ProjectedNoiseGradient, Real,
    };
}

//! A noise as a value: which noise, its seed and settings, an optional periodic wrap and an
//! optional fractal sum, with a compact text form for the callers that cannot name Rust types
//! (C, JavaScript, the command line, configuration files).
//!
//! A [`Spec`] is plain data (`Copy`, no allocation, no tables). [`Spec::build`] checks it against
//! a dimension and builds the typed noises it names into a [`SpecNoise`], which samples with
//! exactly the bits of the typed noise it describes (every entry point of
//! [`NoiseGradient`], batches included), through one `match` per sample or batch.
//!
//! The layers nest in the only order the crate's types allow: a base noise, wrapped by
//! [`Periodic`] (lattice noises only), summed by [`Fractal`], its domain warped by [`Warp`].
//! Any other shape cannot be written.
//!
//! # Text form
//!
//! A base name, then settings separated by spaces, in any order, each at most once:
//!
//! ```text
//! perlin seed=7 period=16,16 fbm octaves=6 lacunarity=2 gain=0.5
//! wavelet seed=3 tiling=periodic
//! multiband seed=5 first=-1 bands=0.5,1,0.5 distribution=uniform
//! mnoise seed=1 ridged octaves=4 lacunarity=1.99 gain=0.5
//! sparse seed=2 kernel=catmull-rom density=3
//! wiener seed=4 covariance=band-pass
//! gabor seed=5 frequency=2 bandwidth=0.5 direction=1,1 orientation=anisotropic
//! simplex seed=9 fbm octaves=5
//! cellular seed=2 output=f2-f1 metric=manhattan jitter=0.8
//! value-cubic seed=6 distribution=gaussian
//! opensimplex2s seed=8 improve=xy fbm octaves=4
//! flow seed=3 angle=0.25 fbm octaves=5 spin=2 advection=0.5
//! marble seed=1 scale=2 variation=0.4
//! polka-dots seed=7 radius=0.3 chance=0.6
//! perlin seed=2 fbm octaves=5 warp=0.8
//! ```
//!
//! | setting | value | default |
//! |---|---|---|
//! | `seed=` | `0..=4294967295` | 0 |
//! | `period=` | 1 to 4 periods in `1..=65536`, comma-separated, one per axis (lattice, white and cubic value noise: [`Base::is_periodic`]) | not periodic |
//! | `tiling=` | `blended`, `varied` or `periodic` (wavelet and multiband noise, [`Tiling`]) | `blended` |
//! | `first=` | the first band of multiband noise, `-24..=8` ([`Bands`]) | 0 |
//! | `bands=` | up to 16 band weights, comma-separated (multiband noise) | `1,0.5,0.25,0.125,0.0625` |
//! | `distribution=` | `gaussian` or `uniform` (multiband, white and value-cubic noise, [`Distribution`]) | `gaussian` (multiband), `uniform` (white, value-cubic) |
//! | `density=` | impulses per kernel volume, `0.01` to the dimension's [`SparseConvolution::max_density`] (sparse and Gabor noise, Poisson counts) | `10` (sparse), `16` (Gabor) |
//! | `count=` | impulses in every cell, `1..=32` (sparse and Gabor noise, instead of a density) | Poisson counts |
//! | `kernel=` | `cosine` or `catmull-rom` (sparse noise, [`Kernel`]) | `cosine` |
//! | `weights=` | `sign` or `uniform` (sparse and Gabor noise, [`Weights`]) | `sign` |
//! | `frequency=` | Gabor's `F₀`, cycles per unit, `0` to `64 ×` the bandwidth ([`Gabor`]) | `1` |
//! | `bandwidth=` | Gabor's `a`, `1/256` to `256` | `0.8` |
//! | `direction=` | Gabor's anisotropic direction: 1 to 3 components, comma-separated (the rest 0); a build uses the first `D` | `1,0,0` |
//! | `orientation=` | `anisotropic`, `isotropic` or `hybrid` (Gabor noise, [`Orientation`]) | `anisotropic` |
//! | `envelope=` | `hann` or `truncated` (Gabor noise, [`Envelope`]) | `hann` |
//! | `magnitude=` | Gabor's `K`, its standard deviation, within `±1024` | `1` |
//! | `output=` | `f1`, `f2`, `f2-f1` or `value` (cellular noise, [`Output`]) | `f1` |
//! | `metric=` | `euclidean`, `squared`, `manhattan` or `chebyshev` (cellular noise, [`Metric`]) | `euclidean` |
//! | `jitter=` | how far cellular noise's points stray from their cells' centres, `0` to `1` ([`Cellular::with_jitter`]) | `1` |
//! | `covariance=` | `low-pass` or `band-pass` (Wiener noise, [`Covariance`]) | `low-pass` |
//! | `improve=` | `standard`, `xy` or `xz`: the plane the lattice is turned to serve (OpenSimplex2 and OpenSimplex2S, [`Improve`]) | `standard` |
//! | `scale=`, `variation=` | marble's ([`Marble::with_noise`]; `marble`, `marble-olano`) | `1`, `0.2` (`marble`); `1`, `1.5` (`marble-olano`) |
//! | `rings=`, `amount=` | wood's ([`Wood::with_noise`]; `wood`, `wood-olano`) | `2`, `0.3` |
//! | `radius=`, `chance=` | polka dots' ([`PolkaDots::with_radius`], [`PolkaDots::with_chance`]) | `0.35`, `0.5` |
//! | `angle=` | flow noise's angle in turns, any finite value, kept in `[0, 1)` ([`Flow::with_angle`]) | `0` |
//! | `spin=`, `advection=` | flow noise's `fbm` sum, Perlin and Neyret's flow fBm ([`FlowSum`]): `0..=16`, `±16` | `2`, `0` |
//! | `warp=` | the amplitude of a domain warp by independent OpenSimplex2 noises, within `±1024`, not with a period ([`Spec::with_warp`]) | no warp |
//! | `fbm`, `turbulence`, `ridged` | a fractal sum of that [`Kind`] | no sum |
//! | `octaves=`, `lacunarity=`, `gain=` | [`Octaves`] settings (need a kind) | [`Octaves::default`] |
//!
//! The textures ([`Base::is_texture`]) and flow noise's fBm have no analytic gradient: a built
//! spec's [`NoiseGradient::sample_with_gradient`] gives them central differences (step
//! 2⁻¹⁰), as a renderer bump-maps a texture.
//!
//! Printing ([`Display`](core::fmt::Display)) writes the base, the seed, and every setting of
//! each layer present, so a printed spec keeps its meaning if a default changes; parsing the
//! printed text gives the same spec back (floats print in the shortest form that reads back
//! exactly). Numbers are plain decimals (`-0.5`, `2`, `.25`; no exponent, `inf` or `nan`) of at
//! most 100 digits, read to the nearest `f32` (ties to even, as `f32::from_str`). Bad text is a
//! [`ParseError`] naming the byte position and what was expected, never a panic (the firmware's
//! `nopanic-text` proves it, for reading and for printing).
//!
//! # Examples
//!
//! ```
//! use bandnoise::prelude::*;
//! use bandnoise::spec::{Base, Spec};
//!
//! let spec: Spec = "perlin seed=7 period=16,16 fbm octaves=4 lacunarity=2 gain=0.5".parse()?;
//! let noise = spec.build::<2>()?;
//! let typed = Fractal::fbm(
//!     Periodic::new(Perlin::new(7), [16, 16])?,
//!     Octaves::new(4, 2.0, 0.5)?,
//! );
//! let p = [0.3f32, 5.7];
//! assert_eq!(noise.sample(p).to_bits(), typed.sample(p).to_bits());
//!
//! // The same spec in Rust, and its text.
//! let built = Spec::new(Base::Perlin, 7)
//!     .with_period(&[16, 16])?
//!     .with_fractal(Kind::Fbm, Octaves::new(4, 2.0, 0.5)?);
//! assert_eq!(built, spec);
//! assert_eq!(
//!     format!("{spec}"),
//!     "perlin seed=7 period=16,16 fbm octaves=4 lacunarity=2 gain=0.5"
//! );
//!
//! // Errors say where and what.
//! let err = "perlin seed=-1".parse::<Spec>().unwrap_err();
//! assert_eq!(err.position(), 12);
//! assert_eq!(format!("{err}"), "at byte 12: expected a seed in 0..=4294967295");
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use core::fmt;
use core::str::FromStr;

use crate::batch::{Grid, LANES};
use crate::cellular::{Cellular, Metric, Output};
use crate::decimal;
use crate::fractal::{Fractal, Kind, Octaves};
use crate::impulse::{
    self, Envelope, Gabor, GaborParameters, Impulses, Kernel, Orientation, SparseConvolution,
    Weights,
};
use crate::lattice::{
    CNoise, CubicValueNoise, MNoise, MixedTurbulence, OriginalPerlin, Periodic, Perlin, ValueNoise,
    WhiteNoise,
};
use crate::simplex::{Flow, FlowSum, Improve, OpenSimplex2, OpenSimplex2S, Simplex};
use crate::texture::{Marble, PolkaDots, Windy, Wood, Wrinkled};
use crate::vector::{Components, Warp};
use crate::wavelet::{
    Bands, DEFAULT_BANDS, Distribution, MAX_BANDS, Multiband, QuantizedTile2, QuantizedTile3,
    TILE2, TILE2_I16, TILE3, TILE3_I16, Tile2, Tile3, TileData, TileVariance, Tiling, Wavelet,
};
use crate::wiener::{Covariance, WienerNoise};
use crate::{Error, Noise, NoiseGradient, Real};

/// The noise a [`Spec`] starts from.
///
/// [`TabledPerlin`](crate::lattice::TabledPerlin) has no entry: it is [`Perlin`]'s noise, bit
/// for bit, with a speed table, and a description names noises, not their storage.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Base {
    /// [`Perlin`]: Perlin's improved noise, 1D–4D. Text: `perlin`.
    Perlin,
    /// [`OriginalPerlin`]: Perlin's 1985 noise, 1D–4D. Text: `original`.
    OriginalPerlin,
    /// [`ValueNoise`], 1D–4D. Text: `value`.
    Value,
    /// [`CNoise`]: Olano's cNoise, 1D–4D. Text: `cnoise`.
    CNoise,
    /// [`MNoise<61>`](MNoise): Olano's mNoise with his modulus, 1D–4D. Text: `mnoise`.
    MNoise,
    /// [`MNoise<4093>`](MNoise): the largest modulus exact in `f32`, 1D–4D. Text: `mnoise4093`.
    MNoise4093,
    /// [`Wavelet`]: one band over a [`Tiles`] set's tile (by default [`TILE2`] in 2D,
    /// [`TILE3`] in 3D), 2D and 3D. Text: `wavelet`.
    Wavelet,
    /// [`Multiband`] wavelet noise over the same tiles, 2D and 3D. Text: `multiband`.
    Multiband,
    /// [`SparseConvolution`]: Lewis's sparse convolution noise, 1D–4D. Text: `sparse`.
    Sparse,
    /// [`WienerNoise`]: Lewis's Wiener-interpolated noise, 1D–4D. Text: `wiener`.
    Wiener,
    /// [`Gabor`]: Lagae et al.'s Gabor noise, 1D–3D. Text: `gabor`.
    Gabor,
    /// [`Simplex`]: simplex noise (Perlin 2001, Gustavson 2005), 1D–4D. Text: `simplex`.
    Simplex,
    /// [`Cellular`]: Worley's cellular noise, 1D–4D. Text: `cellular`.
    Cellular,
    /// [`WhiteNoise`]: Lewis's lattice white noise, 1D–4D. Text: `white`.
    White,
    /// [`CubicValueNoise`]: value noise with Catmull-Rom interpolation, 1D–4D. Text:
    /// `value-cubic`.
    ValueCubic,
    /// [`OpenSimplex2`]: KdotJPG's OpenSimplex2, 1D–4D (the seed as an `i64`). Text:
    /// `opensimplex2`.
    OpenSimplex2,
    /// [`OpenSimplex2S`]: KdotJPG's OpenSimplex2S, 1D–4D. Text: `opensimplex2s`.
    OpenSimplex2S,
    /// [`Flow`]: Perlin and Neyret's flow noise, 2D; its `fbm` sum is their flow fBm
    /// ([`FlowSum`]). Text: `flow`.
    Flow,
    /// [`Windy`]: pbrt's windy waves over Perlin noise, 1D–4D. Text: `windy`.
    Windy,
    /// [`Wrinkled`]: pbrt's wrinkled texture over Perlin noise, 1D–4D. Text: `wrinkled`.
    Wrinkled,
    /// [`Marble`]: pbrt's marble over fBm of Perlin noise, 1D–4D. Text: `marble`.
    Marble,
    /// [`Marble::olano`]: Olano's marble over his mNoise turbulence, 1D–4D. Text:
    /// `marble-olano`.
    MarbleOlano,
    /// [`Wood`]: Lewis's wood over fBm of Perlin noise, 1D–4D. Text: `wood`.
    Wood,
    /// [`Wood::olano`]: Olano's wood over his mNoise turbulence, 1D–4D. Text: `wood-olano`.
    WoodOlano,
    /// [`PolkaDots`]: pbrt's polka dots, 1D–4D. Text: `polka-dots`.
    PolkaDots,
}

impl Base {
    /// Every base, in the order of the enum.
    pub const ALL: [Base; 25] = [
        Base::Perlin,
        Base::OriginalPerlin,
        Base::Value,
        Base::CNoise,
        Base::MNoise,
        Base::MNoise4093,
        Base::Wavelet,
        Base::Multiband,
        Base::Sparse,
        Base::Wiener,
        Base::Gabor,
        Base::Simplex,
        Base::Cellular,
        Base::White,
        Base::ValueCubic,
        Base::OpenSimplex2,
        Base::OpenSimplex2S,
        Base::Flow,
        Base::Windy,
        Base::Wrinkled,
        Base::Marble,
        Base::MarbleOlano,
        Base::Wood,
        Base::WoodOlano,
        Base::PolkaDots,
    ];

    /// The name in the text form.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Base::Perlin => "perlin",
            Base::OriginalPerlin => "original",
            Base::Value => "value",
            Base::CNoise => "cnoise",
            Base::MNoise => "mnoise",
            Base::MNoise4093 => "mnoise4093",
            Base::Wavelet => "wavelet",
            Base::Multiband => "multiband",
            Base::Sparse => "sparse",
            Base::Wiener => "wiener",
            Base::Gabor => "gabor",
            Base::Simplex => "simplex",
            Base::Cellular => "cellular",
            Base::White => "white",
            Base::ValueCubic => "value-cubic",
            Base::OpenSimplex2 => "opensimplex2",
            Base::OpenSimplex2S => "opensimplex2s",
            Base::Flow => "flow",
            Base::Windy => "windy",
            Base::Wrinkled => "wrinkled",
            Base::Marble => "marble",
            Base::MarbleOlano => "marble-olano",
            Base::Wood => "wood",
            Base::WoodOlano => "wood-olano",
            Base::PolkaDots => "polka-dots",
        }
    }

    /// Whether the noise is defined in `dims` dimensions.
    #[must_use]
    pub const fn has_dimension(self, dims: usize) -> bool {
        match self {
            Base::Wavelet | Base::Multiband => dims == 2 || dims == 3,
            Base::Gabor => dims >= 1 && dims <= 3,
            Base::Flow => dims == 2,
            _ => dims >= 1 && dims <= 4,
        }
    }

    /// Whether the noise can be wrapped by [`Periodic`] (the lattice noises that interpolate
    /// a cell's corners).
    #[must_use]
    pub const fn is_lattice(self) -> bool {
        // Named, not excluded: a base added later is not periodic until it says so.
        matches!(
            self,
            Base::Perlin
                | Base::OriginalPerlin
                | Base::Value
                | Base::CNoise
                | Base::MNoise
                | Base::MNoise4093
        )
    }

    /// Whether the noise takes a period (`period=`, [`Spec::with_period`]): the lattice
    /// noises, white noise and cubic value noise (each lattice coordinate wrapped before it is
    /// hashed).
    #[must_use]
    pub const fn is_periodic(self) -> bool {
        self.is_lattice() || matches!(self, Base::White | Base::ValueCubic)
    }

    /// Whether the noise is made of random impulses (and has impulse settings: density,
    /// count, weights).
    #[must_use]
    pub const fn is_impulse(self) -> bool {
        matches!(self, Base::Sparse | Base::Gabor)
    }

    /// Whether the noise's values have a [`Distribution`] setting.
    #[must_use]
    pub const fn has_distribution(self) -> bool {
        matches!(self, Base::Multiband | Base::White | Base::ValueCubic)
    }

    /// Whether the noise has an OpenSimplex2 lattice orientation ([`Improve`]).
    #[must_use]
    pub const fn is_open_simplex(self) -> bool {
        matches!(self, Base::OpenSimplex2 | Base::OpenSimplex2S)
    }

    /// Whether the noise is a texture ([`crate::texture`]): a pattern in `[0, 1]`
    /// (windy and wrinkled: a height) over a noise, with no analytic gradient.
    #[must_use]
    pub const fn is_texture(self) -> bool {
        self.texture_settings().is_some() || matches!(self, Base::Windy | Base::Wrinkled)
    }

    /// The names of a texture's two settings in the text form, if it has them
    /// ([`Spec::with_texture`]).
    #[must_use]
    pub const fn texture_settings(self) -> Option<[&'static str; 2]> {
        match self {
            Base::Marble | Base::MarbleOlano => Some(["scale", "variation"]),
            Base::Wood | Base::WoodOlano => Some(["rings", "amount"]),
            Base::PolkaDots => Some(["radius", "chance"]),
            _ => None,
        }
    }

    /// Whether the noise reads a wavelet tile (and has a [`Tiling`]).
    #[must_use]
    pub const fn is_wavelet(self) -> bool {
        matches!(self, Base::Wavelet | Base::Multiband)
    }
}

impl fmt::Display for Base {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A noise as a value (module docs): a [`Base`] and its seed, an optional period per axis,
/// the wavelet tiling, multiband noise's bands and distribution, and an optional fractal sum.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spec {
    base: Base,
    seed: u32,
    /// The periods, in the first `axes` entries; `axes == 0`: not periodic.
    period: [u32; 4],
    axes: u8,
    tiling: Tiling,
    /// Multiband noise's bands and distribution; the defaults for every other base.
    bands: Bands,
    distribution: Distribution,
    /// Sparse convolution noise's kernel, weights, density and fixed count (0: Poisson counts
    /// at `density`); the defaults for every other base.
    kernel: Kernel,
    weights: Weights,
    density: f32,
    per_cell: u8,
    /// Wiener noise's covariance; the default for every other base.
    covariance: Covariance,
    /// Gabor noise's settings; the defaults for every other base.
    gabor: GaborParameters,
    /// A texture's two settings ([`Base::texture_settings`]), checked; the defaults for
    /// every other base.
    texture: [f32; 2],
    /// Flow noise's angle (reduced to `[0, 1)`), and its fBm's spin and advection.
    flow: [f32; 3],
    /// Cellular noise's output, metric and jitter (checked); the defaults for every other base.
    output: Output,
    metric: Metric,
    jitter: f32,
    /// OpenSimplex2's orientation; the default for every other base.
    improve: Improve,
    fractal: Option<(Kind, Octaves)>,
    /// The warp's amplitude, if the noise is warped.
    warp: Option<f32>,
}

impl Spec {
    /// `base` with `seed`, no period, the default tiling and no fractal sum.
    #[must_use]
    pub const fn new(base: Base, seed: u32) -> Self {
        Self {
            base,
            seed,
            period: [0; 4],
            axes: 0,
            tiling: Tiling::Blended,
            bands: DEFAULT_BANDS,
            distribution: match base {
                Base::White | Base::ValueCubic => Distribution::Uniform,
                _ => Distribution::Gaussian,
            },
            kernel: Kernel::Cosine,
            weights: Weights::Sign,
            density: match base {
                Base::Gabor => Gabor::<1>::DEFAULT_DENSITY,
                _ => impulse::DEFAULT_DENSITY,
            },
            per_cell: 0,
            covariance: Covariance::LowPass,
            gabor: GaborParameters::DEFAULT,
            output: Output::F1,
            metric: Metric::Euclidean,
            jitter: 1.0,
            improve: Improve::Standard,
            texture: match base {
                Base::Marble => [1.0, 0.2],
                Base::MarbleOlano => [1.0, 1.5],
                Base::Wood | Base::WoodOlano => [2.0, 0.3],
                Base::PolkaDots => [0.35, 0.5],
                _ => [0.0; 2],
            },
            flow: [0.0, 2.0, 0.0],
            fractal: None,
            warp: None,
        }
    }

    /// The same description with another seed.
    #[must_use]
    pub const fn with_seed(mut self, seed: u32) -> Self {
        self.seed = seed;
        self
    }

    /// The same noise wrapped with `period` (one entry per axis, 1 to 4 of them) by
    /// [`Periodic`].
    ///
    /// # Errors
    ///
    /// [`Error::NotPeriodic`] for the noises that do not take one ([`Base::is_periodic`]; wavelet noise: use
    /// [`Tiling::Periodic`]; simplex noise, whose lattice is not aligned with the axes),
    /// [`Error::PeriodAxes`] for no period or more than 4, [`Error::Period`] for a period
    /// outside `1..=65536`.
    pub fn with_period(mut self, period: &[u32]) -> Result<Self, Error> {
        if !self.base.is_periodic() {
            return Err(Error::NotPeriodic(self.base.name()));
        }
        if self.warp.is_some() {
            return Err(Error::WarpedPeriod);
        }
        if period.is_empty() || period.len() > 4 {
            return Err(Error::PeriodAxes {
                axes: period.len(),
                dims: 4,
            });
        }
        let mut all = [0; 4];
        for (axis, (&p, slot)) in period.iter().zip(&mut all).enumerate() {
            if !(1..=Periodic::<(), 1>::MAX_PERIOD).contains(&p) {
                return Err(Error::Period { axis, period: p });
            }
            *slot = p;
        }
        self.period = all;
        self.axes = period.len() as u8;
        Ok(self)
    }

    /// The same noise with wavelet `tiling`.
    ///
    /// # Errors
    ///
    /// [`Error::NotWavelet`] unless the base is [`Base::Wavelet`] or [`Base::Multiband`].
    pub fn with_tiling(mut self, tiling: Tiling) -> Result<Self, Error> {
        if !self.base.is_wavelet() {
            return Err(Error::NotWavelet(self.base.name()));
        }
        self.tiling = tiling;
        Ok(self)
    }

    /// The same multiband noise with `bands`.
    ///
    /// # Errors
    ///
    /// [`Error::NotMultiband`] unless the base is [`Base::Multiband`].
    pub fn with_bands(mut self, bands: Bands) -> Result<Self, Error> {
        if self.base != Base::Multiband {
            return Err(Error::NotMultiband(self.base.name()));
        }
        self.bands = bands;
        Ok(self)
    }

    /// The same multiband, white or cubic value noise with values of `distribution`.
    ///
    /// # Errors
    ///
    /// [`Error::NotMultiband`] unless the base is [`Base::Multiband`], [`Base::White`] or
    /// [`Base::ValueCubic`].
    pub fn with_distribution(mut self, distribution: Distribution) -> Result<Self, Error> {
        if !self.base.has_distribution() {
            return Err(Error::NotMultiband(self.base.name()));
        }
        self.distribution = distribution;
        Ok(self)
    }

    /// Sparse convolution or Gabor noise with `density` impulses per kernel volume (Poisson
    /// counts), replacing a fixed count.
    ///
    /// # Errors
    ///
    /// [`Error::NotImpulse`] unless the base is made of impulses; [`Error::Density`] unless
    /// `density` is finite and in `[0.01, 32·π²/2]` (the largest 4D density; building checks
    /// the dimension's own, [`SparseConvolution::max_density`]).
    pub fn with_density(mut self, density: f32) -> Result<Self, Error> {
        self.impulse_setting()?;
        let max = SparseConvolution::<4>::max_density();
        if !(impulse::MIN_DENSITY..=max).contains(&density) {
            return Err(Error::Density {
                density,
                min: impulse::MIN_DENSITY,
                max,
            });
        }
        self.density = density;
        self.per_cell = 0;
        Ok(self)
    }

    /// Sparse convolution or Gabor noise with exactly `per_cell` impulses in every cell.
    ///
    /// # Errors
    ///
    /// [`Error::NotImpulse`] unless the base is made of impulses; [`Error::ImpulseCount`]
    /// unless `1 ≤ per_cell ≤` [`MAX_FIXED`](impulse::MAX_FIXED).
    pub fn with_fixed_count(mut self, per_cell: u32) -> Result<Self, Error> {
        self.impulse_setting()?;
        Impulses::fixed(per_cell)?;
        self.per_cell = per_cell as u8;
        Ok(self)
    }

    /// Sparse convolution noise with `kernel`.
    ///
    /// # Errors
    ///
    /// [`Error::NotImpulse`] unless the base is [`Base::Sparse`].
    pub fn with_kernel(mut self, kernel: Kernel) -> Result<Self, Error> {
        if self.base != Base::Sparse {
            return Err(Error::NotImpulse(self.base.name()));
        }
        self.kernel = kernel;
        Ok(self)
    }

    /// Sparse convolution or Gabor noise with impulse weights drawn as `weights` says.
    ///
    /// # Errors
    ///
    /// [`Error::NotImpulse`] unless the base is made of impulses.
    pub fn with_weights(mut self, weights: Weights) -> Result<Self, Error> {
        self.impulse_setting()?;
        self.weights = weights;
        Ok(self)
    }

    fn impulse_setting(&self) -> Result<(), Error> {
        if self.base.is_impulse() {
            Ok(())
        } else {
            Err(Error::NotImpulse(self.base.name()))
        }
    }

    /// The sparse convolution noise this describes in `D` dimensions.
    fn sparse<const D: usize>(&self) -> Result<SparseConvolution<D>, Error> {
        let noise = SparseConvolution::<D>::new(self.seed)
            .with_kernel(self.kernel)
            .with_weights(self.weights);
        if self.per_cell > 0 {
            noise.with_fixed_count(u32::from(self.per_cell))
        } else {
            noise.with_density(self.density)
        }
    }

    /// Gabor noise with frequency `F₀` and bandwidth `a` (see [`Gabor::with_spectrum`]).
    ///
    /// # Errors
    ///
    /// [`Error::NotGabor`] unless the base is [`Base::Gabor`]; [`Error::Bandwidth`] and
    /// [`Error::Frequency`] as [`Gabor::with_spectrum`].
    pub fn with_spectrum(mut self, frequency: f32, bandwidth: f32) -> Result<Self, Error> {
        self.gabor_setting()?;
        GaborParameters::check_spectrum(frequency, bandwidth)?;
        self.gabor.frequency = frequency;
        self.gabor.bandwidth = bandwidth;
        Ok(self)
    }

    /// Gabor noise with the anisotropic `direction` (1 to 3 components; the others 0; a
    /// build in `D` dimensions uses the first `D`, and refuses a zero vector).
    ///
    /// # Errors
    ///
    /// [`Error::NotGabor`] unless the base is [`Base::Gabor`]; [`Error::Direction`] for no
    /// component or more than 3, a component that is not finite, or a zero vector.
    pub fn with_direction(mut self, direction: &[f32]) -> Result<Self, Error> {
        self.gabor_setting()?;
        if direction.is_empty() || direction.len() > 3 {
            return Err(Error::Direction);
        }
        let mut all = [0.0; 3];
        for (slot, &c) in all.iter_mut().zip(direction) {
            *slot = c;
        }
        let parameters = GaborParameters {
            direction: all,
            ..self.gabor
        };
        parameters.unit_direction::<3>()?;
        self.gabor = parameters;
        Ok(self)
    }

    /// Gabor noise with kernels oriented as `orientation` says.
    ///
    /// # Errors
    ///
    /// [`Error::NotGabor`] unless the base is [`Base::Gabor`].
    pub fn with_orientation(mut self, orientation: Orientation) -> Result<Self, Error> {
        self.gabor_setting()?;
        self.gabor.orientation = orientation;
        Ok(self)
    }

    /// Gabor noise with the envelope `envelope`.
    ///
    /// # Errors
    ///
    /// [`Error::NotGabor`] unless the base is [`Base::Gabor`].
    pub fn with_envelope(mut self, envelope: Envelope) -> Result<Self, Error> {
        self.gabor_setting()?;
        self.gabor.envelope = envelope;
        Ok(self)
    }

    /// Gabor noise with magnitude `K` (its standard deviation).
    ///
    /// # Errors
    ///
    /// [`Error::NotGabor`] unless the base is [`Base::Gabor`]; [`Error::Magnitude`] unless
    /// `|K| ≤ 1024`.
    pub fn with_magnitude(mut self, magnitude: f32) -> Result<Self, Error> {
        self.gabor_setting()?;
        GaborParameters::check_magnitude(magnitude)?;
        self.gabor.magnitude = magnitude;
        Ok(self)
    }

    fn gabor_setting(&self) -> Result<(), Error> {
        if self.base == Base::Gabor {
            Ok(())
        } else {
            Err(Error::NotGabor(self.base.name()))
        }
    }

    /// The Gabor noise this describes in `D` dimensions, built in one step (the builders'
    /// chain would move the noise through the stack at each step: too much for a
    /// microcontroller's checksum program).
    fn gabor<const D: usize>(&self) -> Result<Gabor<D>, Error> {
        let impulses = if self.per_cell > 0 {
            Impulses::fixed(u32::from(self.per_cell))?
        } else {
            Gabor::<D>::check_density(self.density)?;
            Impulses::poisson_checked(Gabor::<D>::per_cell(self.density), self.weights)
        };
        Gabor::build(self.seed, &self.gabor, impulses.with_weights(self.weights))
    }

    /// Gabor noise's frequency and bandwidth, `(F₀, a)` (the defaults for other bases).
    #[must_use]
    pub const fn spectrum(&self) -> (f32, f32) {
        (self.gabor.frequency, self.gabor.bandwidth)
    }

    /// Gabor noise's direction, three components (the default for other bases).
    #[must_use]
    pub const fn direction(&self) -> [f32; 3] {
        self.gabor.direction
    }

    /// Gabor noise's orientation (the default for other bases).
    #[must_use]
    pub const fn orientation(&self) -> Orientation {
        self.gabor.orientation
    }

    /// Gabor noise's envelope (the default for other bases).
    #[must_use]
    pub const fn envelope(&self) -> Envelope {
        self.gabor.envelope
    }

    /// Gabor noise's magnitude (the default for other bases).
    #[must_use]
    pub const fn magnitude(&self) -> f32 {
        self.gabor.magnitude
    }

    /// Cellular noise returning `output`.
    ///
    /// # Errors
    ///
    /// [`Error::NotCellular`] unless the base is [`Base::Cellular`].
    pub fn with_output(mut self, output: Output) -> Result<Self, Error> {
        self.cellular_only()?;
        self.output = output;
        Ok(self)
    }

    /// Cellular noise measuring distances with `metric`.
    ///
    /// # Errors
    ///
    /// [`Error::NotCellular`] unless the base is [`Base::Cellular`].
    pub fn with_metric(mut self, metric: Metric) -> Result<Self, Error> {
        self.cellular_only()?;
        self.metric = metric;
        Ok(self)
    }

    /// Cellular noise with `jitter` (see [`Cellular::with_jitter`]).
    ///
    /// # Errors
    ///
    /// [`Error::NotCellular`] unless the base is [`Base::Cellular`]; [`Error::Jitter`] unless
    /// `0 ≤ jitter ≤ 1`.
    pub fn with_jitter(mut self, jitter: f32) -> Result<Self, Error> {
        self.cellular_only()?;
        // Checked (and rounded) as the noise will be, so `build` cannot fail on it.
        self.jitter = Cellular::new(0).with_jitter(jitter)?.jitter();
        Ok(self)
    }

    fn cellular_only(&self) -> Result<(), Error> {
        if self.base == Base::Cellular {
            Ok(())
        } else {
            Err(Error::NotCellular(self.base.name()))
        }
    }

    /// Cellular noise's output (the default for other bases).
    #[must_use]
    pub const fn output(&self) -> Output {
        self.output
    }

    /// Cellular noise's metric (the default for other bases).
    #[must_use]
    pub const fn metric(&self) -> Metric {
        self.metric
    }

    /// Cellular noise's jitter (the default for other bases).
    #[must_use]
    pub const fn jitter(&self) -> f32 {
        self.jitter
    }

    /// OpenSimplex2 or OpenSimplex2S with its lattice turned for `improve`.
    ///
    /// # Errors
    ///
    /// [`Error::NotOpenSimplex`] unless the base is [`Base::OpenSimplex2`] or
    /// [`Base::OpenSimplex2S`].
    pub fn with_improve(mut self, improve: Improve) -> Result<Self, Error> {
        if !self.base.is_open_simplex() {
            return Err(Error::NotOpenSimplex(self.base.name()));
        }
        self.improve = improve;
        Ok(self)
    }

    /// OpenSimplex2's orientation (the default for other bases).
    #[must_use]
    pub const fn improve(&self) -> Improve {
        self.improve
    }

    /// A texture with its two settings (the names [`Base::texture_settings`] gives): marble's
    /// scale and variation ([`Marble::with_noise`]), wood's rings and amount
    /// ([`Wood::with_noise`]), polka dots' radius and chance ([`PolkaDots::with_radius`],
    /// [`PolkaDots::with_chance`]).
    ///
    /// # Errors
    ///
    /// [`Error::NoSetting`] for a noise without texture settings; the texture's
    /// [`Error::TextureSetting`] for a value out of its range.
    pub fn with_texture(mut self, settings: [f32; 2]) -> Result<Self, Error> {
        let [a, b] = settings;
        match self.base {
            Base::Marble | Base::MarbleOlano => {
                Marble::with_noise((), a, b)?;
            }
            Base::Wood | Base::WoodOlano => {
                Wood::with_noise((), a, b)?;
            }
            Base::PolkaDots => {
                PolkaDots::new(0).with_radius(a)?.with_chance(b)?;
            }
            _ => {
                return Err(Error::NoSetting {
                    noise: self.base.name(),
                    setting: "scale, variation, rings, amount, radius or chance",
                });
            }
        }
        self.texture = settings;
        Ok(self)
    }

    /// A texture's two settings ([`with_texture`](Self::with_texture); zeros for other
    /// bases).
    #[must_use]
    pub const fn texture(&self) -> [f32; 2] {
        self.texture
    }

    /// Flow noise with its gradients turned by `turns` ([`Flow::with_angle`]; kept reduced
    /// to `[0, 1)`).
    ///
    /// # Errors
    ///
    /// [`Error::NoSetting`] unless the base is [`Base::Flow`]; [`Error::FlowAngle`] unless
    /// `turns` is finite.
    pub fn with_angle(mut self, turns: f32) -> Result<Self, Error> {
        self.flow_only("angle")?;
        self.flow[0] = Flow::new(0).with_angle(turns)?.angle();
        Ok(self)
    }

    /// Flow noise whose `fbm` sum turns octave `i` by `angle · spinⁱ` and advects each
    /// octave by `advection` ([`FlowSum::with_spin`], [`FlowSum::with_advection`]; defaults 2
    /// and 0). Turbulence and ridged sums of flow noise are plain sums of octaves at one
    /// angle, which these do not change.
    ///
    /// # Errors
    ///
    /// [`Error::NoSetting`] unless the base is [`Base::Flow`]; [`Error::FlowSetting`] unless
    /// `0 ≤ spin ≤ 16` and `|advection| ≤ 16`.
    pub fn with_flow_sum(mut self, spin: f32, advection: f32) -> Result<Self, Error> {
        self.flow_only("spin")?;
        let m = FlowSum::MAX_SETTING;
        if !(0.0..=m).contains(&spin) {
            return Err(Error::FlowSetting(spin));
        }
        if !(-m..=m).contains(&advection) {
            return Err(Error::FlowSetting(advection));
        }
        self.flow[1] = spin;
        self.flow[2] = advection;
        Ok(self)
    }

    fn flow_only(&self, setting: &'static str) -> Result<(), Error> {
        if self.base == Base::Flow {
            Ok(())
        } else {
            Err(Error::NoSetting {
                noise: self.base.name(),
                setting,
            })
        }
    }

    /// Flow noise's angle in turns, and its fBm's spin and advection (the defaults for
    /// other bases).
    #[must_use]
    pub const fn flow(&self) -> [f32; 3] {
        self.flow
    }

    /// Wiener noise with `covariance`.
    ///
    /// # Errors
    ///
    /// [`Error::NotWiener`] unless the base is [`Base::Wiener`].
    pub fn with_covariance(mut self, covariance: Covariance) -> Result<Self, Error> {
        if self.base != Base::Wiener {
            return Err(Error::NotWiener(self.base.name()));
        }
        self.covariance = covariance;
        Ok(self)
    }

    /// The same noise (summed, if it is) with its domain warped by `amplitude` times a
    /// displacement of `D` independent [`OpenSimplex2`] noises ([`Warp`] over
    /// [`Components`]; component `a` seeded `seed · 2⁸ + a + 1`): Lewis's stochastic
    /// deformation, smooth and without a lattice's axis-aligned artefacts. The gradient is
    /// the chain rule's.
    ///
    /// # Errors
    ///
    /// [`Error::WarpAmplitude`] unless `amplitude` is finite and within ±1024;
    /// [`Error::WarpedPeriod`] for a periodic noise (the displacement does not repeat).
    pub fn with_warp(mut self, amplitude: f32) -> Result<Self, Error> {
        Warp::new((), (), amplitude)?;
        if self.axes > 0 {
            return Err(Error::WarpedPeriod);
        }
        self.warp = Some(amplitude);
        Ok(self)
    }

    /// The warp's amplitude, if the noise is warped.
    #[must_use]
    pub const fn warp(&self) -> Option<f32> {
        self.warp
    }

    /// The same noise summed by a [`Fractal`] of `kind` with `octaves`.
    #[must_use]
    pub const fn with_fractal(mut self, kind: Kind, octaves: Octaves) -> Self {
        self.fractal = Some((kind, octaves));
        self
    }

    /// The base noise.
    #[must_use]
    pub const fn base(&self) -> Base {
        self.base
    }

    /// The seed.
    #[must_use]
    pub const fn seed(&self) -> u32 {
        self.seed
    }

    /// The periods per axis, if the noise is periodic.
    #[must_use]
    pub fn period(&self) -> Option<&[u32]> {
        match self.axes {
            0 => None,
            n => self.period.get(..usize::from(n)),
        }
    }

    /// The wavelet tiling (only meaningful for [`Base::Wavelet`] and [`Base::Multiband`]).
    #[must_use]
    pub const fn tiling(&self) -> Tiling {
        self.tiling
    }

    /// Multiband noise's bands ([`Bands::default`] for the other bases).
    #[must_use]
    pub const fn bands(&self) -> Bands {
        self.bands
    }

    /// Multiband noise's distribution ([`Distribution::Gaussian`] for the other bases).
    #[must_use]
    pub const fn distribution(&self) -> Distribution {
        self.distribution
    }

    /// Sparse convolution noise's kernel (the default for other bases).
    #[must_use]
    pub const fn kernel(&self) -> Kernel {
        self.kernel
    }

    /// Sparse convolution or Gabor noise's weights (the default for other bases).
    #[must_use]
    pub const fn weights(&self) -> Weights {
        self.weights
    }

    /// Sparse convolution or Gabor noise's density in impulses per kernel volume, or its
    /// fixed count per cell (`Err`).
    pub const fn density(&self) -> Result<f32, u32> {
        if self.per_cell > 0 {
            Err(self.per_cell as u32)
        } else {
            Ok(self.density)
        }
    }

    /// Wiener noise's covariance (the default for other bases).
    #[must_use]
    pub const fn covariance(&self) -> Covariance {
        self.covariance
    }

    /// The fractal sum, if any.
    #[must_use]
    pub const fn fractal(&self) -> Option<(Kind, Octaves)> {
        self.fractal
    }

    /// The noise this describes, in `D` dimensions, with the default (`f32`) wavelet tiles.
    ///
    /// # Errors
    ///
    /// [`Error::Dimension`] when the base has no `D`-dimensional form (wavelet noise is 2D or
    /// 3D); [`Error::PeriodAxes`] when a period is given for other than `D` axes.
    pub fn build<const D: usize>(&self) -> Result<SpecNoise<D>, Error> {
        self.build_with::<D, F32Tiles>()
    }

    /// The noise this describes, in `D` dimensions, with the wavelet tiles of `S`: firmware
    /// passes [`I16Tiles`] (72 KiB rather than 144 KiB of coefficients), and only the tiles
    /// of `S` are linked in.
    ///
    /// # Errors
    ///
    /// As [`build`](Self::build).
    pub fn build_with<const D: usize, S: Tiles>(&self) -> Result<SpecNoise<D, S>, Error> {
        if !self.base.has_dimension(D) {
            return Err(Error::Dimension {
                noise: self.base.name(),
                dims: D,
            });
        }
        let period = match self.period() {
            None => None,
            Some(p) if p.len() == D => Some(Periodic::new(
                (),
                core::array::from_fn(|a| p.get(a).copied().unwrap_or(1)),
            )?),
            Some(p) => {
                return Err(Error::PeriodAxes {
                    axes: p.len(),
                    dims: D,
                });
            }
        };
        let mut fractal = self
            .fractal
            .map(|(kind, octaves)| Fractal::new((), octaves, kind));
        let s = self.seed;
        let [a, b] = self.texture;
        let base = match self.base {
            Base::Perlin => Any::Perlin(Perlin::new(s)),
            Base::OriginalPerlin => Any::Original(OriginalPerlin::new(s)),
            Base::Value => Any::Value(ValueNoise::new(s)),
            Base::CNoise => Any::C(CNoise::new(s)),
            Base::MNoise => Any::M61(MNoise::new(s)),
            Base::MNoise4093 => Any::M4093(MNoise::seeded(s)),
            Base::Wavelet if D == 2 => {
                Any::Wavelet2(Wavelet::new(s, S::two()).with_tiling(self.tiling))
            }
            Base::Wavelet => Any::Wavelet3(Wavelet::new(s, S::three()).with_tiling(self.tiling)),
            Base::Multiband if D == 2 => Any::Multiband2(
                Multiband::new(s, S::two(), self.bands, self.distribution).with_tiling(self.tiling),
            ),
            Base::Multiband => Any::Multiband3(
                Multiband::new(s, S::three(), self.bands, self.distribution)
                    .with_tiling(self.tiling),
            ),
            Base::Sparse => match D {
                1 => Any::Sparse1(self.sparse::<1>()?),
                2 => Any::Sparse2(self.sparse::<2>()?),
                3 => Any::Sparse3(self.sparse::<3>()?),
                _ => Any::Sparse4(self.sparse::<4>()?),
            },
            Base::Wiener => match D {
                1 => Any::Wiener1(WienerNoise::new(s).with_covariance(self.covariance)),
                2 => Any::Wiener2(WienerNoise::new(s).with_covariance(self.covariance)),
                3 => Any::Wiener3(WienerNoise::new(s).with_covariance(self.covariance)),
                _ => Any::Wiener4(WienerNoise::new(s).with_covariance(self.covariance)),
            },
            Base::Simplex => Any::Simplex(Simplex::new(s)),
            Base::OpenSimplex2 => {
                Any::OpenSimplex2(OpenSimplex2::new(i64::from(s)).improving(self.improve))
            }
            Base::OpenSimplex2S => {
                Any::OpenSimplex2S(OpenSimplex2S::new(i64::from(s)).improving(self.improve))
            }
            Base::Flow => {
                let [angle, spin, advection] = self.flow;
                let flow = Flow::new(s).with_angle(angle)?;
                match self.fractal {
                    // Flow noise's fBm is Perlin and Neyret's, in place of the plain sum.
                    Some((Kind::Fbm, octaves)) => {
                        fractal = None;
                        Any::FlowSum(
                            FlowSum::new(flow, octaves)
                                .with_spin(spin)?
                                .with_advection(advection)?,
                        )
                    }
                    _ => Any::Flow(flow),
                }
            }
            Base::Windy => Any::Windy(Windy::new(s)),
            Base::Wrinkled => Any::Wrinkled(Wrinkled::new(s)),
            Base::Marble => Any::Marble(Marble::with_noise(Marble::new(s).noise().clone(), a, b)?),
            Base::MarbleOlano => {
                Any::MarbleOlano(Marble::with_noise(Marble::olano(s).noise().clone(), a, b)?)
            }
            Base::Wood => Any::Wood(Wood::with_noise(Wood::new(s).noise().clone(), a, b)?),
            Base::WoodOlano => {
                Any::WoodOlano(Wood::with_noise(Wood::olano(s).noise().clone(), a, b)?)
            }
            Base::PolkaDots => Any::PolkaDots(PolkaDots::new(s).with_radius(a)?.with_chance(b)?),
            Base::White | Base::ValueCubic => {
                let white = WhiteNoise::new(s).with_distribution(self.distribution);
                if self.base == Base::White {
                    Any::White(white)
                } else {
                    Any::Cubic(CubicValueNoise::interpolating(white))
                }
            }
            Base::Cellular => Any::Cellular(
                Cellular::new(s)
                    .with_output(self.output)
                    .with_metric(self.metric)
                    .with_jitter(self.jitter)?,
            ),
            Base::Gabor => match D {
                1 => Any::Gabor1(self.gabor::<1>()?),
                2 => Any::Gabor2(self.gabor::<2>()?),
                _ => Any::Gabor3(self.gabor::<3>()?),
            },
        };
        let warp = match self.warp {
            None => None,
            Some(amplitude) => {
                let seed = i64::from(self.seed) << 8;
                let components = core::array::from_fn(|a| OpenSimplex2::new(seed + a as i64 + 1));
                Some(Warp::new((), Components::new(components), amplitude)?)
            }
        };
        Ok(SpecNoise {
            spec: *self,
            layers: Layers { base, period },
            fractal,
            warp,
        })
    }
}

impl Default for Spec {
    /// `perlin seed=0`.
    fn default() -> Self {
        Self::new(Base::Perlin, 0)
    }
}

impl fmt::Display for Spec {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} seed={}", self.base, self.seed)?;
        if let Some(period) = self.period() {
            f.write_str(" period=")?;
            for (i, p) in period.iter().enumerate() {
                if i > 0 {
                    f.write_str(",")?;
                }
                write!(f, "{p}")?;
            }
        }
        if self.base == Base::Multiband {
            write!(f, " first={} bands=", self.bands.first())?;
            for (i, w) in self.bands.weights().iter().enumerate() {
                if i > 0 {
                    f.write_str(",")?;
                }
                decimal::write_f32(f, *w)?;
            }
        }
        if self.base.has_distribution() {
            f.write_str(match self.distribution {
                Distribution::Gaussian => " distribution=gaussian",
                Distribution::Uniform => " distribution=uniform",
            })?;
        }
        if self.base == Base::Gabor {
            let g = &self.gabor;
            f.write_str(" frequency=")?;
            decimal::write_f32(f, g.frequency)?;
            f.write_str(" bandwidth=")?;
            decimal::write_f32(f, g.bandwidth)?;
            f.write_str(" direction=")?;
            for (i, c) in g.direction.iter().enumerate() {
                if i > 0 {
                    f.write_str(",")?;
                }
                decimal::write_f32(f, *c)?;
            }
            f.write_str(match g.orientation {
                Orientation::Anisotropic => " orientation=anisotropic",
                Orientation::Isotropic => " orientation=isotropic",
                Orientation::Hybrid => " orientation=hybrid",
            })?;
            f.write_str(match g.envelope {
                Envelope::Hann => " envelope=hann",
                Envelope::Truncated => " envelope=truncated",
            })?;
            f.write_str(" magnitude=")?;
            decimal::write_f32(f, g.magnitude)?;
        }
        if self.base == Base::Sparse {
            f.write_str(match self.kernel {
                Kernel::Cosine => " kernel=cosine",
                Kernel::CatmullRom => " kernel=catmull-rom",
            })?;
        }
        if self.base.is_impulse() {
            f.write_str(match self.weights {
                Weights::Sign => " weights=sign",
                Weights::Uniform => " weights=uniform",
            })?;
            match self.density() {
                Ok(d) => {
                    f.write_str(" density=")?;
                    decimal::write_f32(f, d)?;
                }
                Err(n) => write!(f, " count={n}")?,
            }
        }
        if self.base == Base::Cellular {
            write!(
                f,
                " output={} metric={} jitter=",
                self.output.name(),
                self.metric.name()
            )?;
            decimal::write_f32(f, self.jitter)?;
        }
        if self.base.is_open_simplex() {
            f.write_str(match self.improve {
                Improve::Standard => " improve=standard",
                Improve::XY => " improve=xy",
                Improve::XZ => " improve=xz",
            })?;
        }
        if let Some(names) = self.base.texture_settings() {
            for (name, v) in names.into_iter().zip(self.texture) {
                write!(f, " {name}=")?;
                decimal::write_f32(f, v)?;
            }
        }
        if self.base == Base::Flow {
            for (name, v) in ["angle", "spin", "advection"].into_iter().zip(self.flow) {
                write!(f, " {name}=")?;
                decimal::write_f32(f, v)?;
            }
        }
        if self.base == Base::Wiener {
            f.write_str(match self.covariance {
                Covariance::LowPass => " covariance=low-pass",
                Covariance::BandPass => " covariance=band-pass",
            })?;
        }
        if self.base.is_wavelet() {
            f.write_str(match self.tiling {
                Tiling::Varied => " tiling=varied",
                Tiling::Blended => " tiling=blended",
                Tiling::Periodic => " tiling=periodic",
            })?;
        }
        if let Some((kind, o)) = self.fractal {
            write!(f, " {} octaves={} lacunarity=", kind_name(kind), o.count())?;
            decimal::write_f32(f, o.lacunarity())?;
            f.write_str(" gain=")?;
            decimal::write_f32(f, o.gain())?;
        }
        if let Some(amplitude) = self.warp {
            f.write_str(" warp=")?;
            decimal::write_f32(f, amplitude)?;
        }
        Ok(())
    }
}

fn kind_name(kind: Kind) -> &'static str {
    match kind {
        Kind::Fbm => "fbm",
        Kind::Turbulence => "turbulence",
        Kind::Ridged => "ridged",
    }
}

/// With the `serde` feature, a spec is its text form in any serde format: a string such as
/// `"perlin seed=7 fbm octaves=4 lacunarity=2 gain=0.5"`, which a configuration file or a
/// JSON message can hold and a person can read; a bad string is the parser's error, position
/// and all. No allocation either way.
#[cfg(feature = "serde")]
impl serde::Serialize for Spec {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_str(self)
    }
}

#[cfg(feature = "serde")]
impl<'de> serde::Deserialize<'de> for Spec {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Text;
        impl serde::de::Visitor<'_> for Text {
            type Value = Spec;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a noise description such as \"perlin seed=7 fbm octaves=4\"")
            }
            fn visit_str<E: serde::de::Error>(self, text: &str) -> Result<Spec, E> {
                text.parse().map_err(E::custom)
            }
        }
        deserializer.deserialize_str(Text)
    }
}

/// Why a text is not a [`Spec`]: the byte position, what was expected there, and the
/// configuration error when the text was well formed but its value was refused.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ParseError {
    position: usize,
    expected: &'static str,
    refused: Option<Error>,
}

impl ParseError {
    /// The byte offset in the text where the problem is.
    #[must_use]
    pub const fn position(&self) -> usize {
        self.position
    }

    /// What the parser expected there.
    #[must_use]
    pub const fn expected(&self) -> &'static str {
        self.expected
    }

    /// The configuration error, when a well-formed value was refused (an octave count of 0).
    #[must_use]
    pub const fn refused(&self) -> Option<Error> {
        self.refused
    }
}

impl fmt::Display for ParseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "at byte {}: expected {}", self.position, self.expected)?;
        if let Some(e) = self.refused {
            write!(f, " ({e})")?;
        }
        Ok(())
    }
}

impl core::error::Error for ParseError {}

/// What the base name position accepts.
const EXPECTED_BASE: &str = "a noise name (perlin, original, value, cnoise, mnoise, mnoise4093, \
     wavelet, multiband, sparse, wiener, gabor, simplex, cellular, white, value-cubic, \
     opensimplex2, opensimplex2s, flow, windy, wrinkled, marble, marble-olano, wood, wood-olano, \
     polka-dots)";
const EXPECTED_SETTING: &str = "a setting (seed=, period=, tiling=, first=, bands=, \
     distribution=, density=, count=, kernel=, weights=, covariance=, frequency=, bandwidth=, \
     direction=, orientation=, envelope=, magnitude=, output=, metric=, jitter=, improve=, \
     scale=, variation=, rings=, amount=, radius=, chance=, angle=, spin=, advection=, fbm, \
     turbulence, ridged, octaves=, lacunarity=, gain=, warp=)";

impl FromStr for Spec {
    type Err = ParseError;

    fn from_str(text: &str) -> Result<Self, ParseError> {
        let mut words = Words { text, at: 0 };
        let err = |position, expected| ParseError {
            position,
            expected,
            refused: None,
        };
        let (at, name) = words.next().ok_or(err(text.len(), EXPECTED_BASE))?;
        let base = Base::ALL
            .into_iter()
            .find(|b| b.name() == name)
            .ok_or(err(at, EXPECTED_BASE))?;
        let mut spec = Spec::new(base, 0);
        let mut seen = Seen::default();
        let mut kind = None;
        let (mut count, mut lacunarity, mut gain) = (None, None, None);
        let (mut first, mut weights) = (None, None);
        let (mut frequency, mut bandwidth) = (None, None);
        let mut texture: [Option<(usize, f32)>; 2] = [None, None];
        let (mut spin, mut advection) = (None, None);
        let defaults = Octaves::default();
        for (at, word) in words {
            let (key, value, value_at) = match split_at_byte(word, b'=') {
                Some((k, v)) => (k, Some(v), at + k.len() + 1),
                None => (word, None, at + word.len()),
            };
            let slot = match key {
                "seed" => &mut seen.seed,
                "period" => &mut seen.period,
                "tiling" => &mut seen.tiling,
                "first" => &mut seen.first,
                "bands" => &mut seen.bands,
                "distribution" => &mut seen.distribution,
                "density" => &mut seen.density,
                "count" => &mut seen.impulses,
                "kernel" => &mut seen.kernel,
                "weights" => &mut seen.weights,
                "covariance" => &mut seen.covariance,
                "frequency" => &mut seen.frequency,
                "bandwidth" => &mut seen.bandwidth,
                "direction" => &mut seen.direction,
                "orientation" => &mut seen.orientation,
                "envelope" => &mut seen.envelope,
                "magnitude" => &mut seen.magnitude,
                "output" => &mut seen.output,
                "metric" => &mut seen.metric,
                "jitter" => &mut seen.jitter,
                "improve" => &mut seen.improve,
                "scale" => &mut seen.scale,
                "variation" => &mut seen.variation,
                "rings" => &mut seen.rings,
                "amount" => &mut seen.amount,
                "radius" => &mut seen.radius,
                "chance" => &mut seen.chance,
                "angle" => &mut seen.angle,
                "spin" => &mut seen.spin,
                "advection" => &mut seen.advection,
                "warp" => &mut seen.warp,
                "fbm" | "turbulence" | "ridged" => &mut seen.kind,
                "octaves" => &mut seen.count,
                "lacunarity" => &mut seen.lacunarity,
                "gain" => &mut seen.gain,
                _ => return Err(err(at, EXPECTED_SETTING)),
            };
            if core::mem::replace(slot, true) {
                return Err(err(at, "each setting at most once"));
            }
            let needs_value = |expected| value.ok_or(err(value_at, expected));
            if matches!(key, "first" | "bands") && base != Base::Multiband {
                return Err(ParseError {
                    position: at,
                    expected: "bands only for multiband noise",
                    refused: Some(Error::NotMultiband(base.name())),
                });
            }
            if matches!(key, "density" | "count" | "weights") && !base.is_impulse() {
                return Err(ParseError {
                    position: at,
                    expected: "impulse settings only for sparse and Gabor noise",
                    refused: Some(Error::NotImpulse(base.name())),
                });
            }
            if key == "kernel" && base != Base::Sparse {
                return Err(ParseError {
                    position: at,
                    expected: "a kernel only for sparse noise",
                    refused: Some(Error::NotImpulse(base.name())),
                });
            }
            if matches!(
                key,
                "frequency" | "bandwidth" | "direction" | "orientation" | "envelope" | "magnitude"
            ) && base != Base::Gabor
            {
                return Err(ParseError {
                    position: at,
                    expected: "Gabor settings only for Gabor noise",
                    refused: Some(Error::NotGabor(base.name())),
                });
            }
            if matches!(key, "output" | "metric" | "jitter") && base != Base::Cellular {
                return Err(ParseError {
                    position: at,
                    expected: "cellular settings only for cellular noise",
                    refused: Some(Error::NotCellular(base.name())),
                });
            }
            if key == "improve" && !base.is_open_simplex() {
                return Err(ParseError {
                    position: at,
                    expected: "an orientation only for OpenSimplex2 and OpenSimplex2S",
                    refused: Some(Error::NotOpenSimplex(base.name())),
                });
            }
            if key == "covariance" && base != Base::Wiener {
                return Err(ParseError {
                    position: at,
                    expected: "a covariance only for Wiener noise",
                    refused: Some(Error::NotWiener(base.name())),
                });
            }
            if matches!(key, "density" | "count") && seen.density && seen.impulses {
                return Err(err(at, "a density or a count, not both"));
            }
            let refused = |position, expected, e| ParseError {
                position,
                expected,
                refused: Some(e),
            };
            match key {
                "density" => {
                    const E: &str = "a density in [0.01, 157.9] impulses per kernel volume";
                    let v = decimal::parse_f32(needs_value(E)?).ok_or(err(value_at, E))?;
                    spec = spec.with_density(v).map_err(|e| refused(value_at, E, e))?;
                }
                "count" => {
                    const E: &str = "a count in 1..=32 impulses per cell";
                    let v = needs_value(E)?;
                    let n = v.parse().map_err(|_| err(value_at, E))?;
                    spec = spec
                        .with_fixed_count(n)
                        .map_err(|e| refused(value_at, E, e))?;
                }
                "kernel" => {
                    const E: &str = "a kernel (cosine, catmull-rom)";
                    let kernel = match needs_value(E)? {
                        "cosine" => Kernel::Cosine,
                        "catmull-rom" => Kernel::CatmullRom,
                        _ => return Err(err(value_at, E)),
                    };
                    spec = spec.with_kernel(kernel).map_err(|e| refused(at, E, e))?;
                }
                "weights" => {
                    const E: &str = "weights (sign, uniform)";
                    let weights = match needs_value(E)? {
                        "sign" => Weights::Sign,
                        "uniform" => Weights::Uniform,
                        _ => return Err(err(value_at, E)),
                    };
                    spec = spec.with_weights(weights).map_err(|e| refused(at, E, e))?;
                }
                "output" => {
                    const E: &str = "an output (f1, f2, f2-f1, value)";
                    let v = needs_value(E)?;
                    let output = Output::ALL
                        .into_iter()
                        .find(|o| o.name() == v)
                        .ok_or(err(value_at, E))?;
                    spec = spec.with_output(output).map_err(|e| refused(at, E, e))?;
                }
                "metric" => {
                    const E: &str = "a metric (euclidean, squared, manhattan, chebyshev)";
                    let v = needs_value(E)?;
                    let metric = Metric::ALL
                        .into_iter()
                        .find(|m| m.name() == v)
                        .ok_or(err(value_at, E))?;
                    spec = spec.with_metric(metric).map_err(|e| refused(at, E, e))?;
                }
                "jitter" => {
                    const E: &str = "a jitter in [0, 1]";
                    let v = decimal::parse_f32(needs_value(E)?).ok_or(err(value_at, E))?;
                    spec = spec.with_jitter(v).map_err(|e| refused(value_at, E, e))?;
                }
                "scale" | "variation" | "rings" | "amount" | "radius" | "chance" => {
                    const E: &str = "a texture setting: a plain decimal";
                    let names = base.texture_settings().unwrap_or(["", ""]);
                    let Some(slot) = names.iter().position(|n| *n == key) else {
                        return Err(ParseError {
                            position: at,
                            expected: "a texture's own settings (marble: scale=, variation=; \
                                       wood: rings=, amount=; polka-dots: radius=, chance=)",
                            refused: Some(Error::NoSetting {
                                noise: base.name(),
                                setting: names_of(key),
                            }),
                        });
                    };
                    let v = decimal::parse_f32(needs_value(E)?).ok_or(err(value_at, E))?;
                    if let Some(t) = texture.get_mut(slot) {
                        *t = Some((value_at, v));
                    }
                }
                "warp" => {
                    const E: &str = "a warp amplitude within ±1024, for a noise without a period";
                    let v = decimal::parse_f32(needs_value(E)?).ok_or(err(value_at, E))?;
                    spec = spec.with_warp(v).map_err(|e| refused(value_at, E, e))?;
                }
                "angle" => {
                    const E: &str = "an angle in turns: a plain decimal";
                    let v = decimal::parse_f32(needs_value(E)?).ok_or(err(value_at, E))?;
                    spec = spec.with_angle(v).map_err(|e| refused(at, E, e))?;
                }
                "spin" | "advection" => {
                    const E: &str = "a spin in [0, 16] or an advection within ±16";
                    let v = decimal::parse_f32(needs_value(E)?).ok_or(err(value_at, E))?;
                    // Checked as a pair at the end, so their order does not matter.
                    spec.flow_only(names_of(key))
                        .map_err(|e| refused(at, E, e))?;
                    let slot = if key == "spin" {
                        &mut spin
                    } else {
                        &mut advection
                    };
                    *slot = Some((value_at, v));
                }
                "improve" => {
                    const E: &str = "an orientation (standard, xy, xz)";
                    let improve = match needs_value(E)? {
                        "standard" => Improve::Standard,
                        "xy" => Improve::XY,
                        "xz" => Improve::XZ,
                        _ => return Err(err(value_at, E)),
                    };
                    spec = spec.with_improve(improve).map_err(|e| refused(at, E, e))?;
                }
                "covariance" => {
                    const E: &str = "a covariance (low-pass, band-pass)";
                    let covariance = match needs_value(E)? {
                        "low-pass" => Covariance::LowPass,
                        "band-pass" => Covariance::BandPass,
                        _ => return Err(err(value_at, E)),
                    };
                    spec = spec
                        .with_covariance(covariance)
                        .map_err(|e| refused(at, E, e))?;
                }
                "frequency" => {
                    const E: &str = "a frequency: a plain decimal";
                    let v = needs_value(E)?;
                    frequency = Some((value_at, decimal::parse_f32(v).ok_or(err(value_at, E))?));
                }
                "bandwidth" => {
                    const E: &str = "a bandwidth: a plain decimal";
                    let v = needs_value(E)?;
                    bandwidth = Some((value_at, decimal::parse_f32(v).ok_or(err(value_at, E))?));
                }
                "direction" => {
                    const E: &str = "1 to 3 direction components, separated by commas";
                    let v = needs_value(E)?;
                    let mut d = [0.0f32; 3];
                    let mut n = 0;
                    let mut part_at = value_at;
                    for part in Parts(Some(v)) {
                        let slot = d.get_mut(n).ok_or(err(part_at, E))?;
                        *slot = decimal::parse_f32(part).ok_or(err(part_at, E))?;
                        n += 1;
                        part_at += part.len() + 1;
                    }
                    spec = spec
                        .with_direction(d.get(..n).unwrap_or(&[]))
                        .map_err(|e| refused(value_at, E, e))?;
                }
                "orientation" => {
                    const E: &str = "an orientation (anisotropic, isotropic, hybrid)";
                    let orientation = match needs_value(E)? {
                        "anisotropic" => Orientation::Anisotropic,
                        "isotropic" => Orientation::Isotropic,
                        "hybrid" => Orientation::Hybrid,
                        _ => return Err(err(value_at, E)),
                    };
                    spec = spec
                        .with_orientation(orientation)
                        .map_err(|e| refused(at, E, e))?;
                }
                "envelope" => {
                    const E: &str = "an envelope (hann, truncated)";
                    let envelope = match needs_value(E)? {
                        "hann" => Envelope::Hann,
                        "truncated" => Envelope::Truncated,
                        _ => return Err(err(value_at, E)),
                    };
                    spec = spec
                        .with_envelope(envelope)
                        .map_err(|e| refused(at, E, e))?;
                }
                "magnitude" => {
                    const E: &str = "a magnitude within ±1024";
                    let v = decimal::parse_f32(needs_value(E)?).ok_or(err(value_at, E))?;
                    spec = spec
                        .with_magnitude(v)
                        .map_err(|e| refused(value_at, E, e))?;
                }
                "seed" => {
                    const E: &str = "a seed in 0..=4294967295";
                    let v = needs_value(E)?;
                    spec.seed = v.parse().map_err(|_| err(value_at, E))?;
                }
                "period" => {
                    const E: &str = "1 to 4 periods in 1..=65536, separated by commas";
                    let v = needs_value(E)?;
                    let mut period = [0u32; 4];
                    let mut axes = 0;
                    let mut part_at = value_at;
                    for part in Parts(Some(v)) {
                        let slot = period.get_mut(axes).ok_or(err(part_at, E))?;
                        *slot = part.parse().map_err(|_| err(part_at, E))?;
                        axes += 1;
                        part_at += part.len() + 1;
                    }
                    spec = spec
                        .with_period(period.get(..axes).unwrap_or(&[]))
                        .map_err(|e| ParseError {
                            position: value_at,
                            expected: E,
                            refused: Some(e),
                        })?;
                }
                "tiling" => {
                    const E: &str = "a tiling (varied, blended, periodic)";
                    let tiling = match needs_value(E)? {
                        "varied" => Tiling::Varied,
                        "blended" => Tiling::Blended,
                        "periodic" => Tiling::Periodic,
                        _ => return Err(err(value_at, E)),
                    };
                    spec = spec.with_tiling(tiling).map_err(|e| ParseError {
                        position: at,
                        expected: "tiling only for wavelet noise",
                        refused: Some(e),
                    })?;
                }
                "first" => {
                    const E: &str = "a first band in -24..=8";
                    let v = needs_value(E)?;
                    first = Some((value_at, v.parse().map_err(|_| err(value_at, E))?));
                }
                "bands" => {
                    const E: &str = "up to 16 band weights, separated by commas";
                    let v = needs_value(E)?;
                    let mut w = [0.0f32; MAX_BANDS];
                    let mut n = 0;
                    let mut part_at = value_at;
                    // An empty list is no bands (the noise is 0).
                    for part in Parts(Some(v)).filter(|_| !v.is_empty()) {
                        let slot = w.get_mut(n).ok_or(err(part_at, E))?;
                        *slot = decimal::parse_f32(part).ok_or(err(part_at, E))?;
                        n += 1;
                        part_at += part.len() + 1;
                    }
                    weights = Some((value_at, w, n));
                }
                "distribution" => {
                    const E: &str = "a distribution (gaussian, uniform)";
                    let distribution = match needs_value(E)? {
                        "gaussian" => Distribution::Gaussian,
                        "uniform" => Distribution::Uniform,
                        _ => return Err(err(value_at, E)),
                    };
                    spec = spec
                        .with_distribution(distribution)
                        .map_err(|e| ParseError {
                            position: at,
                            expected: "distribution only for multiband, white and value-cubic noise",
                            refused: Some(e),
                        })?;
                }
                "fbm" | "turbulence" | "ridged" => {
                    if value.is_some() {
                        return Err(err(at + key.len(), "a space after the fractal kind"));
                    }
                    kind = Some((
                        at,
                        match key {
                            "fbm" => Kind::Fbm,
                            "turbulence" => Kind::Turbulence,
                            _ => Kind::Ridged,
                        },
                    ));
                }
                "octaves" => {
                    const E: &str = "an octave count in 1..=30";
                    let v = needs_value(E)?;
                    count = Some((value_at, v.parse().map_err(|_| err(value_at, E))?));
                }
                "lacunarity" => {
                    const E: &str = "a lacunarity in (0, 16]";
                    let v = needs_value(E)?;
                    lacunarity = Some((value_at, decimal::parse_f32(v).ok_or(err(value_at, E))?));
                }
                _ => {
                    const E: &str = "a gain in [-1, 1]";
                    let v = needs_value(E)?;
                    gain = Some((value_at, decimal::parse_f32(v).ok_or(err(value_at, E))?));
                }
            }
        }
        if first.is_some() || weights.is_some() {
            let at = [first.map(|f| f.0), weights.map(|w| w.0)]
                .into_iter()
                .flatten()
                .min()
                .unwrap_or(0);
            let bands = Bands::new(
                first.map_or(DEFAULT_BANDS.first(), |f| f.1),
                match &weights {
                    Some((_, w, n)) => w.get(..*n).unwrap_or(&[]),
                    None => DEFAULT_BANDS.weights(),
                },
            );
            let refused = |e| ParseError {
                position: at,
                expected: "bands in range",
                refused: Some(e),
            };
            spec = spec.with_bands(bands.map_err(refused)?).map_err(refused)?;
        }
        if frequency.is_some() || bandwidth.is_some() {
            // Checked together, so their order in the text does not matter.
            let (f0, a) = spec.spectrum();
            spec = spec
                .with_spectrum(frequency.map_or(f0, |f| f.1), bandwidth.map_or(a, |b| b.1))
                .map_err(|e| {
                    let at = match e {
                        Error::Bandwidth(_) => bandwidth.map(|b| b.0),
                        _ => frequency.map(|f| f.0),
                    };
                    ParseError {
                        position: at.unwrap_or(0),
                        expected: "a frequency in [0, 64 × bandwidth] and a bandwidth in \
                                   [1/256, 256]",
                        refused: Some(e),
                    }
                })?;
        }
        if texture.iter().any(Option::is_some) {
            let defaults = spec.texture();
            let values = [0, 1].map(|i| match texture.get(i) {
                Some(Some((_, v))) => *v,
                _ => defaults.get(i).copied().unwrap_or(0.0),
            });
            spec = spec.with_texture(values).map_err(|e| {
                // The position of the setting refused (the first one given when unclear).
                let which = match e {
                    Error::TextureSetting { name, .. } => base
                        .texture_settings()
                        .and_then(|n| n.iter().position(|s| *s == name)),
                    _ => None,
                };
                let at = which
                    .and_then(|i| texture.get(i).copied().flatten())
                    .or(texture.iter().flatten().next().copied())
                    .map_or(0, |t| t.0);
                ParseError {
                    position: at,
                    expected: "texture settings in range",
                    refused: Some(e),
                }
            })?;
        }
        if spin.is_some() || advection.is_some() {
            let [_, s0, a0] = spec.flow();
            let (s, a) = (spin.map_or(s0, |v| v.1), advection.map_or(a0, |v| v.1));
            spec = spec.with_flow_sum(s, a).map_err(|e| {
                let bad_spin = !(0.0..=FlowSum::MAX_SETTING).contains(&s);
                let at = if bad_spin { spin } else { advection };
                ParseError {
                    position: at.or(spin).map_or(0, |v| v.0),
                    expected: "a spin in [0, 16] and an advection within ±16",
                    refused: Some(e),
                }
            })?;
        }
        let first_octave_setting = [
            count.map(|c| c.0),
            lacunarity.map(|l| l.0),
            gain.map(|g| g.0),
        ]
        .into_iter()
        .flatten()
        .min();
        match kind {
            None => {
                if let Some(at) = first_octave_setting {
                    return Err(err(
                        at,
                        "a fractal kind (fbm, turbulence, ridged) before octave settings",
                    ));
                }
            }
            Some((kind_at, kind)) => {
                let c = count.map_or(defaults.count(), |c| c.1);
                let l = lacunarity.map_or(defaults.lacunarity(), |l| l.1);
                let g = gain.map_or(defaults.gain(), |g| g.1);
                let octaves = Octaves::new(c, l, g).map_err(|e| {
                    let at = match e {
                        Error::OctaveCount { .. } => count.map(|c| c.0),
                        Error::Lacunarity(_) => lacunarity.map(|l| l.0),
                        Error::Gain(_) => gain.map(|g| g.0),
                        _ => None,
                    };
                    ParseError {
                        position: at.unwrap_or(kind_at),
                        expected: "octave settings in range",
                        refused: Some(e),
                    }
                })?;
                spec = spec.with_fractal(kind, octaves);
            }
        }
        Ok(spec)
    }
}

/// A setting's name as a `'static` string, for [`Error::NoSetting`].
fn names_of(key: &str) -> &'static str {
    [
        "scale",
        "variation",
        "rings",
        "amount",
        "radius",
        "chance",
        "angle",
        "spin",
        "advection",
    ]
    .into_iter()
    .find(|n| *n == key)
    .unwrap_or("texture")
}

/// Which settings a text has given.
#[derive(Default)]
struct Seen {
    seed: bool,
    period: bool,
    tiling: bool,
    first: bool,
    bands: bool,
    distribution: bool,
    density: bool,
    impulses: bool,
    kernel: bool,
    weights: bool,
    covariance: bool,
    frequency: bool,
    bandwidth: bool,
    direction: bool,
    orientation: bool,
    envelope: bool,
    magnitude: bool,
    output: bool,
    metric: bool,
    jitter: bool,
    improve: bool,
    scale: bool,
    variation: bool,
    rings: bool,
    amount: bool,
    radius: bool,
    chance: bool,
    angle: bool,
    spin: bool,
    advection: bool,
    warp: bool,
    kind: bool,
    count: bool,
    lacunarity: bool,
    gain: bool,
}

/// The text before and after the first `byte` in `s`. The separators of the text form are
/// ASCII, so the split falls on a character boundary; searching bytes rather than `char`s
/// keeps the parser free of panic paths (`core`'s char searcher has a slice index the
/// optimiser cannot prove, which the firmware's no-panic proof would fail on).
fn split_at_byte(s: &str, byte: u8) -> Option<(&str, &str)> {
    let i = s.bytes().position(|b| b == byte)?;
    Some((s.get(..i)?, s.get(i + 1..)?))
}

/// The comma-separated parts of a list (one empty part for an empty list, as `split`).
struct Parts<'a>(Option<&'a str>);

impl<'a> Iterator for Parts<'a> {
    type Item = &'a str;
    fn next(&mut self) -> Option<&'a str> {
        let rest = self.0.take()?;
        match split_at_byte(rest, b',') {
            Some((part, tail)) => {
                self.0 = Some(tail);
                Some(part)
            }
            None => Some(rest),
        }
    }
}

/// The words of a text (split at ASCII spaces), with their byte offsets.
struct Words<'a> {
    text: &'a str,
    at: usize,
}

impl<'a> Iterator for Words<'a> {
    type Item = (usize, &'a str);
    fn next(&mut self) -> Option<(usize, &'a str)> {
        let rest = self.text.get(self.at..)?;
        let skip = rest.bytes().take_while(|&b| b == b' ').count();
        let trimmed = rest.get(skip..)?;
        let start = self.at + skip;
        let len = trimmed.bytes().take_while(|&b| b != b' ').count();
        self.at = start + len;
        if len == 0 {
            return None;
        }
        trimmed.get(..len).map(|w| (start, w))
    }
}

/// The wavelet tiles a [`SpecNoise`] reads: [`F32Tiles`] (the default), [`I16Tiles`], or a
/// user's own (a smaller tile for a web page, say).
///
/// # Examples
///
/// ```
/// use bandnoise::spec::{Spec, Tiles};
/// use bandnoise::wavelet::{DEFAULT_TILE_SEED, QuantizedTile2, QuantizedTile3, Tile2, Tile3};
/// use bandnoise::Noise;
///
/// /// 16² and 16³ tiles of `i16`: 8.5 KiB in all.
/// #[derive(Clone, Debug, PartialEq)]
/// struct Small;
/// static TWO: QuantizedTile2<16> = QuantizedTile2::quantize(&Tile2::generate(DEFAULT_TILE_SEED));
/// static THREE: QuantizedTile3<16> = QuantizedTile3::quantize(&Tile3::generate(DEFAULT_TILE_SEED));
/// impl Tiles for Small {
///     type Two = QuantizedTile2<16>;
///     type Three = QuantizedTile3<16>;
///     fn two() -> &'static Self::Two { &TWO }
///     fn three() -> &'static Self::Three { &THREE }
/// }
///
/// let spec: Spec = "multiband seed=2 bands=1,0.5".parse()?;
/// let noise = spec.build_with::<3, Small>()?;
/// let v: f32 = noise.sample([0.5, 1.5, 2.5]);
/// assert!(v.is_finite());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub trait Tiles: Clone + fmt::Debug + PartialEq + 'static {
    /// The 2D tile.
    type Two: TileData<2> + TileVariance + Clone + fmt::Debug + PartialEq + 'static;
    /// The 3D tile.
    type Three: TileData<3> + TileVariance + Clone + fmt::Debug + PartialEq + 'static;
    /// The 2D tile.
    fn two() -> &'static Self::Two;
    /// The 3D tile.
    fn three() -> &'static Self::Three;
}

/// The default tiles, [`TILE2`] and [`TILE3`] (`f32`, 16 KiB and 128 KiB).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct F32Tiles;

impl Tiles for F32Tiles {
    type Two = Tile2<64>;
    type Three = Tile3<32>;
    fn two() -> &'static Tile2<64> {
        &TILE2
    }
    fn three() -> &'static Tile3<32> {
        &TILE3
    }
}

/// The quantized default tiles, [`TILE2_I16`] and [`TILE3_I16`] (8 KiB and 64 KiB).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct I16Tiles;

impl Tiles for I16Tiles {
    type Two = QuantizedTile2<64>;
    type Three = QuantizedTile3<32>;
    fn two() -> &'static QuantizedTile2<64> {
        &TILE2_I16
    }
    fn three() -> &'static QuantizedTile3<32> {
        &TILE3_I16
    }
}

/// The typed noises a [`SpecNoise`] may hold.
#[derive(Clone, Debug)]
#[allow(
    clippy::large_enum_variant,
    reason = "no allocation: a built spec holds its noise inline, 512 bytes at most"
)]
enum Any<S: Tiles> {
    Perlin(Perlin),
    Original(OriginalPerlin),
    Value(ValueNoise),
    C(CNoise),
    M61(MNoise<61>),
    M4093(MNoise<4093>),
    Wavelet2(Wavelet<'static, S::Two>),
    Wavelet3(Wavelet<'static, S::Three>),
    Multiband2(Multiband<'static, S::Two>),
    Multiband3(Multiband<'static, S::Three>),
    Sparse1(SparseConvolution<1>),
    Sparse2(SparseConvolution<2>),
    Sparse3(SparseConvolution<3>),
    Sparse4(SparseConvolution<4>),
    Wiener1(WienerNoise<1>),
    Wiener2(WienerNoise<2>),
    Wiener3(WienerNoise<3>),
    Wiener4(WienerNoise<4>),
    Gabor1(Gabor<1>),
    Gabor2(Gabor<2>),
    Gabor3(Gabor<3>),
    Simplex(Simplex),
    OpenSimplex2(OpenSimplex2),
    OpenSimplex2S(OpenSimplex2S),
    Flow(Flow),
    FlowSum(FlowSum),
    Windy(Windy),
    Wrinkled(Wrinkled),
    Marble(Marble),
    MarbleOlano(Marble<MixedTurbulence<4>>),
    Wood(Wood),
    WoodOlano(Wood<MixedTurbulence<4>>),
    PolkaDots(PolkaDots),
    Cellular(Cellular),
    White(WhiteNoise),
    Cubic(CubicValueNoise),
}

/// A [`Spec`] built for `D` dimensions ([`Spec::build`]) over the wavelet tiles `S`: the
/// typed noises it names, sampled through the crate's own types, so every value is theirs bit
/// for bit.
#[derive(Clone, Debug)]
pub struct SpecNoise<const D: usize, S: Tiles = F32Tiles> {
    spec: Spec,
    layers: Layers<D, S>,
    /// The sum, built and validated once, wrapped around the layers at each call.
    fractal: Option<Fractal<()>>,
    /// The warp, wrapped around the sum (or the layers) at each call.
    warp: Option<Warp<(), Components<OpenSimplex2, D>>>,
}

/// The base noise and its periodic wrap: what a spec's fractal sum adds octaves of. The sum
/// is compiled once per dimension and number type over this dispatch (a `match` per octave),
/// not once per base noise, which keeps a program that builds specs at run time small.
#[derive(Clone, Debug)]
struct Layers<const D: usize, S: Tiles> {
    base: Any<S>,
    period: Option<Periodic<(), D>>,
}

impl<const D: usize, S: Tiles> SpecNoise<D, S> {
    /// The description this noise was built from.
    #[must_use]
    pub const fn spec(&self) -> &Spec {
        &self.spec
    }
}

/// One operation on the typed noise a [`SpecNoise`] describes. Generic over the noise rather
/// than a `dyn` call, so a program compiles, for each noise a spec can name, only the
/// operations it uses: firmware that only samples links no batch or gradient code (a `dyn`
/// vtable would link every method of every noise).
trait Op<R: Real, const D: usize> {
    type Out;
    fn run<N: NoiseGradient<R, D>>(self, n: &N) -> Self::Out;
}

/// The periodic layer of a spec around the lattice noise `n`.
fn with_period<R: Real, const D: usize, N: NoiseGradient<R, D>, O: Op<R, D>>(
    n: &N,
    period: Option<&Periodic<(), D>>,
    op: O,
) -> O::Out
where
    for<'a> Periodic<&'a N, D>: NoiseGradient<R, D>,
{
    match period {
        Some(wrap) => op.run(&wrap.with_noise(n)),
        None => op.run(n),
    }
}

/// The constant 0, which a [`SpecNoise`] never holds for a dimension its base lacks (`build`
/// refuses it), but which keeps the dispatch total.
struct Zero;

impl<R: Real, const D: usize> Noise<R, D> for Zero {
    fn sample(&self, _: [R; D]) -> R {
        R::ZERO
    }
    fn amplitude_bound(&self) -> f32 {
        0.0
    }
}

impl<R: Real, const D: usize> NoiseGradient<R, D> for Zero {
    fn sample_with_gradient(&self, _: [R; D]) -> (R, [R; D]) {
        (R::ZERO, [R::ZERO; D])
    }
}

/// A noise without an analytic gradient (the textures, flow fBm) with a gradient from
/// central differences: `(n(p + h·eₐ) − n(p − h·eₐ)) / 2h` with `h = 2⁻¹⁰` along each axis
/// `a` (exact in every number type; about 2⁻²⁰ of error from `f32`'s rounding per unit of
/// value, and `2⁻¹⁶ · 2⁹` in fixed point), as a renderer bump-maps a texture. Across a
/// texture's kinks (a ring's edge, a dot's rim) it is the slope of the chord.
struct Differenced<'a, N>(&'a N);

impl<R: Real, const D: usize, N: Noise<R, D>> Noise<R, D> for Differenced<'_, N> {
    #[inline]
    fn sample(&self, p: [R; D]) -> R {
        self.0.sample(p)
    }
    fn amplitude_bound(&self) -> f32 {
        self.0.amplitude_bound()
    }
    fn sample_lanes(&self, p: &[[R; LANES]; D], out: &mut [R; LANES]) {
        self.0.sample_lanes(p, out)
    }
    fn fill_grid(&self, grid: &Grid<R, D>, out: &mut [R]) -> Result<(), Error> {
        self.0.fill_grid(grid, out)
    }
    fn fill_points(&self, points: [&[R]; D], out: &mut [R]) -> Result<(), Error> {
        self.0.fill_points(points, out)
    }
}

impl<R: Real, const D: usize, N: Noise<R, D>> NoiseGradient<R, D> for Differenced<'_, N> {
    fn sample_with_gradient(&self, p: [R; D]) -> (R, [R; D]) {
        let h = R::from_ratio(1, 10);
        let inverse = R::from_ratio(512, 0);
        let gradient = core::array::from_fn(|a| {
            let mut q = p;
            let x = p[a];
            q[a] = x.saturating_add(h);
            let ahead = self.0.sample(q);
            q[a] = x.saturating_add(-h);
            let behind = self.0.sample(q);
            ahead.saturating_add(-behind).saturating_mul(inverse)
        });
        (self.0.sample(p), gradient)
    }
}

/// The operations: each entry point of [`NoiseGradient`].
struct Sample<R, const D: usize>([R; D]);
struct Bound;
struct Lanes<'a, R, const D: usize>(&'a [[R; LANES]; D], &'a mut [R; LANES]);
struct FillGrid<'a, R, const D: usize>(&'a Grid<R, D>, &'a mut [R]);
struct FillPoints<'a, R, const D: usize>([&'a [R]; D], &'a mut [R]);
struct Gradient<R, const D: usize>([R; D]);

impl<R: Real, const D: usize> Op<R, D> for Sample<R, D> {
    type Out = R;
    #[inline]
    fn run<N: NoiseGradient<R, D>>(self, n: &N) -> R {
        n.sample(self.0)
    }
}
impl<R: Real, const D: usize> Op<R, D> for Bound {
    type Out = f32;
    fn run<N: NoiseGradient<R, D>>(self, n: &N) -> f32 {
        n.amplitude_bound()
    }
}
impl<R: Real, const D: usize> Op<R, D> for Lanes<'_, R, D> {
    type Out = ();
    fn run<N: NoiseGradient<R, D>>(self, n: &N) {
        n.sample_lanes(self.0, self.1)
    }
}
impl<R: Real, const D: usize> Op<R, D> for FillGrid<'_, R, D> {
    type Out = Result<(), Error>;
    fn run<N: NoiseGradient<R, D>>(self, n: &N) -> Result<(), Error> {
        n.fill_grid(self.0, self.1)
    }
}
impl<R: Real, const D: usize> Op<R, D> for FillPoints<'_, R, D> {
    type Out = Result<(), Error>;
    fn run<N: NoiseGradient<R, D>>(self, n: &N) -> Result<(), Error> {
        n.fill_points(self.0, self.1)
    }
}
impl<R: Real, const D: usize> Op<R, D> for Gradient<R, D> {
    type Out = (R, [R; D]);
    fn run<N: NoiseGradient<R, D>>(self, n: &N) -> (R, [R; D]) {
        n.sample_with_gradient(self.0)
    }
}

/// `SpecNoise<D>` dispatches to the typed noise; `$wavelet` and `$multiband` name the
/// variants sampled in this dimension, if any.
macro_rules! spec_noise {
    ($d:literal, $sparse:ident, $wiener:ident, [$($gabor:ident)?], [$($flow:ident, $flow_sum:ident)?] $(, $wavelet:ident, $multiband:ident)?) => {
        impl<S: Tiles> Layers<$d, S> {
            /// Runs `op` on the (possibly periodic) base noise.
            fn visit<R: Real, O: Op<R, $d>>(&self, op: O) -> O::Out {
                let period = self.period.as_ref();
                match &self.base {
                    Any::Perlin(n) => with_period(n, period, op),
                    Any::Original(n) => with_period(n, period, op),
                    Any::Value(n) => with_period(n, period, op),
                    Any::C(n) => with_period(n, period, op),
                    Any::M61(n) => with_period(n, period, op),
                    Any::M4093(n) => with_period(n, period, op),
                    Any::Simplex(n) => op.run(n),
                    Any::OpenSimplex2(n) => op.run(n),
                    Any::OpenSimplex2S(n) => op.run(n),
                    Any::Windy(n) => op.run(&Differenced(n)),
                    Any::Wrinkled(n) => op.run(&Differenced(n)),
                    Any::Marble(n) => op.run(&Differenced(n)),
                    Any::MarbleOlano(n) => op.run(&Differenced(n)),
                    Any::Wood(n) => op.run(&Differenced(n)),
                    Any::WoodOlano(n) => op.run(&Differenced(n)),
                    Any::PolkaDots(n) => op.run(&Differenced(n)),
                    $(Any::$flow(n) => op.run(n),
                    Any::$flow_sum(n) => op.run(&Differenced(n)),)?
                    Any::Cellular(n) => op.run(n),
                    Any::White(n) => with_period(n, period, op),
                    Any::Cubic(n) => with_period(n, period, op),
                    Any::$sparse(n) => op.run(n),
                    Any::$wiener(n) => op.run(n),
                    $(Any::$gabor(n) => op.run(n),)?
                    $(Any::$wavelet(n) => op.run(n),
                    Any::$multiband(n) => op.run(n),)?
                    #[allow(unreachable_patterns, reason = "the other dimensions")]
                    Any::Wavelet2(_) | Any::Wavelet3(_) | Any::Multiband2(_) | Any::Multiband3(_)
                    | Any::Sparse1(_) | Any::Sparse2(_) | Any::Sparse3(_) | Any::Sparse4(_)
                    | Any::Wiener1(_) | Any::Wiener2(_) | Any::Wiener3(_) | Any::Wiener4(_)
                    | Any::Gabor1(_) | Any::Gabor2(_) | Any::Gabor3(_)
                    | Any::Flow(_) | Any::FlowSum(_) => {
                        op.run(&Zero)
                    }
                }
            }
        }

        impl<S: Tiles> SpecNoise<$d, S> {
            /// Runs `op` on the typed noise this spec describes.
            fn visit<R: Real, O: Op<R, $d>>(&self, op: O) -> O::Out {
                match (&self.warp, &self.fractal) {
                    (None, None) => self.layers.visit(op),
                    (None, Some(sum)) => op.run(&sum.with_noise(&self.layers)),
                    (Some(warp), None) => op.run(&warp.with_noise(&self.layers)),
                    (Some(warp), Some(sum)) => {
                        op.run(&warp.with_noise(sum.with_noise(&self.layers)))
                    }
                }
            }
        }

        spec_noise_entry_points!(Layers, $d);
        spec_noise_entry_points!(SpecNoise, $d);
    };
}

/// The entry points of [`NoiseGradient`] for `$ty`, each one call of its `visit`.
macro_rules! spec_noise_entry_points {
    ($ty:ident, $d:literal) => {
        impl<R: Real, S: Tiles> Noise<R, $d> for $ty<$d, S> {
            #[inline]
            fn sample(&self, p: [R; $d]) -> R {
                self.visit(Sample(p))
            }
            fn amplitude_bound(&self) -> f32 {
                self.visit::<R, _>(Bound)
            }
            fn sample_lanes(&self, p: &[[R; LANES]; $d], out: &mut [R; LANES]) {
                self.visit(Lanes(p, out))
            }
            fn fill_grid(&self, grid: &Grid<R, $d>, out: &mut [R]) -> Result<(), Error> {
                self.visit(FillGrid(grid, out))
            }
            fn fill_points(&self, points: [&[R]; $d], out: &mut [R]) -> Result<(), Error> {
                self.visit(FillPoints(points, out))
            }
        }

        impl<R: Real, S: Tiles> NoiseGradient<R, $d> for $ty<$d, S> {
            fn sample_with_gradient(&self, p: [R; $d]) -> (R, [R; $d]) {
                self.visit(Gradient(p))
            }
        }
    };
}

spec_noise!(1, Sparse1, Wiener1, [Gabor1], []);
spec_noise!(
    2,
    Sparse2,
    Wiener2,
    [Gabor2],
    [Flow, FlowSum],
    Wavelet2,
    Multiband2
);
spec_noise!(3, Sparse3, Wiener3, [Gabor3], [], Wavelet3, Multiband3);
spec_noise!(4, Sparse4, Wiener4, [], []);

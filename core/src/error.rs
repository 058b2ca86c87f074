//! Configuration errors. Building a noise can fail; sampling one never does.

use core::fmt;

use crate::decimal::Shortest;

/// Why a configuration was refused.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum Error {
    /// An octave count outside `1..=max`.
    OctaveCount {
        /// The count asked for.
        count: u32,
        /// The largest count allowed.
        max: u32,
    },
    /// A lacunarity that is not finite or not in `(0, 16]`.
    Lacunarity(f32),
    /// A gain that is not finite or not in `[-1, 1]`.
    Gain(f32),
    /// An output range for [`Levels`](crate::levels::Levels) that is not finite, not
    /// increasing once read as I16F16, or beyond I16F16's ±32768.
    Levels {
        /// The low end given.
        lo: f32,
        /// The high end given.
        hi: f32,
    },
    /// A clamped-octave mean that is not finite or not in `[0, 4]`.
    ClampedMean(f32),
    /// More wavelet bands than a band list holds.
    TooManyBands {
        /// The number of bands asked for.
        count: usize,
        /// The most a band list holds.
        max: usize,
    },
    /// A band weight that is not finite or exceeds 10⁶ in magnitude.
    BandWeight {
        /// The band's position in the list.
        index: usize,
        /// The weight given.
        value: f32,
    },
    /// A first band outside `-24..=8` (frequencies from 2⁻²⁴ to 2⁸ cycles per unit).
    FirstBand(i32),
    /// A period outside `1..=65536` cells (see [`Periodic`](crate::lattice::Periodic)).
    Period {
        /// The axis.
        axis: usize,
        /// The period given.
        period: u32,
    },
    /// A Poisson mean that is not finite or not in `(0, 32]` (see
    /// [`Poisson`](crate::hash::Poisson)).
    PoissonMean(f32),
    /// An impulse density (impulses per kernel volume) that is not finite or not in
    /// `[min, max]` (see [`SparseConvolution`](crate::impulse::SparseConvolution)).
    Density {
        /// The density given.
        density: f32,
        /// The smallest density allowed.
        min: f32,
        /// The largest density allowed in this dimension.
        max: f32,
    },
    /// A fixed impulse count per cell outside `1..=max` (see
    /// [`Impulses::fixed`](crate::impulse::Impulses::fixed)).
    ImpulseCount {
        /// The count given.
        count: u32,
        /// The largest count allowed.
        max: u32,
    },
    /// A Gabor bandwidth `a` that is not finite or not in `[1/256, 256]` (see
    /// [`Gabor`](crate::impulse::Gabor)).
    Bandwidth(f32),
    /// A Gabor frequency `F₀` that is not finite, negative, or above `max_ratio` times the
    /// bandwidth (see [`Gabor`](crate::impulse::Gabor)).
    Frequency {
        /// The frequency given.
        frequency: f32,
        /// The bandwidth it was checked against.
        bandwidth: f32,
        /// The largest ratio of frequency to bandwidth.
        max_ratio: f32,
    },
    /// A Gabor direction with a component that is not finite, or of length 0 (see
    /// [`Gabor`](crate::impulse::Gabor)).
    Direction,
    /// A Gabor magnitude `K` that is not finite or beyond ±1024.
    Magnitude(f32),
    /// A domain-warp amplitude that is not finite or beyond ±1024 (see
    /// [`Warp::new`](crate::vector::Warp::new)).
    WarpAmplitude(f32),
    /// A warp and a period asked for together (see [`Spec::with_warp`]): the displacement does
    /// not repeat, so the warped noise would not.
    ///
    /// [`Spec::with_warp`]: crate::spec::Spec::with_warp
    WarpedPeriod,
    /// A flow-noise angle that is not finite (see
    /// [`Flow::with_angle`](crate::simplex::Flow::with_angle)).
    FlowAngle(f32),
    /// A flow fBm's spin not in `[0, 16]` or advection beyond ±16 (see
    /// [`FlowSum`](crate::simplex::FlowSum)).
    FlowSetting(f32),
    /// A cellular noise jitter that is not in `[0, 1]` (see
    /// [`Cellular::with_jitter`](crate::cellular::Cellular::with_jitter)).
    Jitter(f32),
    /// A cellular setting (output, metric, jitter) asked for another noise.
    NotCellular(&'static str),
    /// An OpenSimplex2 orientation ([`Improve`](crate::simplex::Improve)) asked for another
    /// noise.
    NotOpenSimplex(&'static str),
    /// A texture or flow setting asked for a noise that does not have it (see
    /// [`Spec`](crate::spec::Spec)): the noise's name and the setting's.
    NoSetting {
        /// The noise's name in the text form.
        noise: &'static str,
        /// The setting's name in the text form.
        setting: &'static str,
    },
    /// A noise asked for in a dimension it does not have (see [`Spec::build`]).
    ///
    /// [`Spec::build`]: crate::spec::Spec::build
    Dimension {
        /// The noise's name in the text form.
        noise: &'static str,
        /// The dimension asked for.
        dims: usize,
    },
    /// Periods given for a number of axes other than the noise's dimensions (see
    /// [`Spec`](crate::spec::Spec)).
    PeriodAxes {
        /// The number of periods given.
        axes: usize,
        /// The number of axes (at most 4 for a spec without a dimension yet).
        dims: usize,
    },
    /// A periodic wrap asked for a noise that is not on the integer lattice (wavelet noise
    /// repeats with [`Tiling::Periodic`](crate::wavelet::Tiling::Periodic); simplex noise's
    /// lattice is skewed, so its periods do not lie along the axes).
    NotPeriodic(&'static str),
    /// A wavelet setting (the tiling) asked for another noise.
    NotWavelet(&'static str),
    /// A multiband setting asked for another noise: bands (multiband noise only) or a
    /// distribution (multiband, white and cubic value noise).
    NotMultiband(&'static str),
    /// An impulse setting (density, count, kernel, weights) asked for a noise that is not
    /// made of impulses.
    NotImpulse(&'static str),
    /// A covariance asked for a noise that is not Wiener-interpolated.
    NotWiener(&'static str),
    /// A Gabor setting (frequency, bandwidth, direction, orientation, envelope, magnitude)
    /// asked for another noise.
    NotGabor(&'static str),
    /// A colour map with too few or too many colours (see
    /// [`ColorMap::new`](crate::texture::ColorMap::new)).
    ColorCount {
        /// The number of colours given.
        count: usize,
        /// The fewest the interpolation needs.
        min: usize,
        /// The most a map takes.
        max: usize,
    },
    /// A texture setting out of its range: its name, the value given, and the range (see
    /// [`texture`](crate::texture)).
    TextureSetting {
        /// The setting.
        name: &'static str,
        /// The value given.
        value: f32,
        /// The smallest value allowed.
        min: f32,
        /// The largest value allowed.
        max: f32,
    },
    /// A batch output buffer (or a point slice) whose length does not match the points asked
    /// for.
    BufferLength {
        /// The length required (`usize::MAX` for a grid whose size overflows `usize`).
        expected: usize,
        /// The length given.
        found: usize,
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::OctaveCount { count, max } => {
                write!(f, "octave count {count} is outside 1..={max}")
            }
            Error::Lacunarity(v) => write!(
                f,
                "lacunarity {} must be finite and in (0, 16]",
                Shortest(*v)
            ),
            Error::Gain(v) => write!(f, "gain {} must be finite and in [-1, 1]", Shortest(*v)),
            Error::ClampedMean(v) => {
                write!(
                    f,
                    "clamped-octave mean {} must be finite and in [0, 4]",
                    Shortest(*v)
                )
            }
            Error::TooManyBands { count, max } => {
                write!(f, "{count} wavelet bands given, at most {max} are allowed")
            }
            Error::BandWeight { index, value } => {
                write!(
                    f,
                    "band weight {} at {index} must be finite and at most 1e6 in magnitude",
                    Shortest(*value)
                )
            }
            Error::Levels { lo, hi } => write!(
                f,
                "output range [{}, {}] must be finite, increasing in I16F16 and within ±32768",
                Shortest(*lo),
                Shortest(*hi)
            ),
            Error::FirstBand(b) => write!(f, "first band {b} is outside -24..=8"),
            Error::Period { axis, period } => {
                write!(
                    f,
                    "period {period} along axis {axis} is outside 1..=65536 cells"
                )
            }
            Error::PoissonMean(m) => write!(
                f,
                "Poisson mean {} must be finite and in (0, 32]",
                Shortest(*m)
            ),
            Error::Density { density, min, max } => write!(
                f,
                "impulse density {} must be finite and in [{}, {}] impulses per kernel volume",
                Shortest(*density),
                Shortest(*min),
                Shortest(*max)
            ),
            Error::ImpulseCount { count, max } => {
                write!(f, "{count} impulses per cell given, 1..={max} are allowed")
            }
            Error::Bandwidth(a) => write!(
                f,
                "Gabor bandwidth {} must be finite and in [1/256, 256]",
                Shortest(*a)
            ),
            Error::Frequency {
                frequency,
                bandwidth,
                max_ratio,
            } => write!(
                f,
                "Gabor frequency {} must be finite and in [0, {} × bandwidth {}]",
                Shortest(*frequency),
                Shortest(*max_ratio),
                Shortest(*bandwidth)
            ),
            Error::Direction => {
                f.write_str("Gabor direction must have finite components and a length above 0")
            }
            Error::Magnitude(k) => write!(
                f,
                "Gabor magnitude {} must be finite and within ±1024",
                Shortest(*k)
            ),
            Error::WarpedPeriod => f.write_str(
                "a warped noise does not repeat: a warp and a period cannot be combined",
            ),
            Error::WarpAmplitude(a) => write!(
                f,
                "warp amplitude {} must be finite and within ±1024",
                Shortest(*a)
            ),
            Error::FlowAngle(a) => write!(f, "flow angle {} must be finite", Shortest(*a)),
            Error::FlowSetting(v) => write!(
                f,
                "flow spin must be in [0, 16] and advection within ±16, not {}",
                Shortest(*v)
            ),
            Error::Jitter(j) => write!(f, "cellular jitter {} must be in [0, 1]", Shortest(*j)),
            Error::NotCellular(noise) => write!(
                f,
                "{noise} noise has no cellular settings (output, metric and jitter are for cellular noise)"
            ),
            Error::NotOpenSimplex(noise) => write!(
                f,
                "{noise} noise has no lattice orientation (improve= is for OpenSimplex2 and OpenSimplex2S)"
            ),
            Error::NoSetting { noise, setting } => {
                write!(f, "{noise} noise has no {setting}= setting")
            }
            Error::Dimension { noise, dims } => {
                write!(f, "{noise} noise has no {dims}D form")
            }
            Error::PeriodAxes { axes, dims } => {
                write!(f, "{axes} periods given for {dims} axes")
            }
            Error::NotPeriodic(noise) => write!(
                f,
                "{noise} noise is not on the integer lattice and cannot be wrapped to a period"
            ),
            Error::NotWavelet(noise) => write!(f, "{noise} noise has no wavelet tiling"),
            Error::NotMultiband(noise) => {
                write!(
                    f,
                    "{noise} noise has no bands (multiband only) or distribution (multiband, white, value-cubic)"
                )
            }
            Error::NotImpulse(noise) => write!(
                f,
                "{noise} noise has no impulses (density, count, kernel and weights are for sparse noise)"
            ),
            Error::NotWiener(noise) => write!(
                f,
                "{noise} noise has no covariance (covariance is for Wiener noise)"
            ),
            Error::NotGabor(noise) => write!(
                f,
                "{noise} noise has no Gabor settings (frequency, bandwidth, direction, \
                 orientation, envelope and magnitude are for Gabor noise)"
            ),
            Error::ColorCount { count, min, max } => {
                write!(
                    f,
                    "{count} colours given, a colour map needs {min} to {max}"
                )
            }
            Error::TextureSetting {
                name,
                value,
                min,
                max,
            } => write!(
                f,
                "texture {name} {} must be finite and in [{}, {}]",
                Shortest(*value),
                Shortest(*min),
                Shortest(*max)
            ),
            Error::BufferLength { expected, found } => {
                write!(f, "buffer of length {found} given, {expected} needed")
            }
        }
    }
}

impl core::error::Error for Error {}

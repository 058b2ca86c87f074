//! Configuration errors. Building a noise can fail; sampling one never does.

use core::fmt;

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
    /// A clamped-octave mean that is not finite or not in `[0, 4]`.
    ClampedMean(f32),
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::OctaveCount { count, max } => {
                write!(f, "octave count {count} is outside 1..={max}")
            }
            Error::Lacunarity(v) => write!(f, "lacunarity {v} must be finite and in (0, 16]"),
            Error::Gain(v) => write!(f, "gain {v} must be finite and in [-1, 1]"),
            Error::ClampedMean(v) => {
                write!(f, "clamped-octave mean {v} must be finite and in [0, 4]")
            }
        }
    }
}

impl core::error::Error for Error {}

//! Noise values as 8- and 16-bit integers, for LED, display and audio code: a linear map from
//! a range of values onto `0..=65535` (then `u8` and `i16` from it), with no division per
//! sample.
//!
//! LED and display firmware wants a brightness or a palette index, not a fraction; FastLED's
//! `inoise8` and `inoise16` return integers for that reason. bandnoise keeps its noise in
//! `f32` or I16F16 (the same noise in both) and maps it afterwards, so the integer output is
//! as smooth as the noise: [`Levels`] is set once from a range (usually the noise's
//! [`amplitude_bound`](crate::Noise::amplitude_bound)), then each value costs a subtraction,
//! a clamp, a shift and one 32-bit multiply (counted in `bench/README.md`).
//!
//! # The map
//!
//! [`Levels::new`]`(lo, hi)` first widens `[lo, hi]` to `[lo′, hi′]`: both ends are read as
//! I16F16 and rounded outward to multiples of `2^(r−16)`, the smallest `r ≥ 0` for which the
//! width `S = (hi′ − lo′)·2^(16−r)` is at most 2¹⁶. For the ranges of the crate's noises
//! (bounds of about 0.5 to 8) that widens each end by less than 2⁻¹³. Then, with `x` the
//! I16F16 bits of `v − lo′` clamped to `[0, hi′ − lo′]` (a float is read as I16F16 first,
//! NaN as 0),
//!
//! ```text
//! u16(v) = min(⌊(x >> r) · ⌈2³¹ / S⌉ / 2¹⁵⌋, 65535)
//! ```
//!
//! which is within two levels of `⌊(v − lo′)·65536 / (hi′ − lo′)⌋`, maps `lo′` (and below) to
//! 0, the midpoint `(lo′ + hi′)/2` to 32768 and `hi′` (and above) to 65535, and never
//! decreases as `v` grows. [`Levels::u8`] is its top byte and [`Levels::i16`] is it minus
//! 32768 (so a symmetric range maps 0 to 0). The product stays below 2³², so the map is the
//! same on every target, and a value in `f32` and the same value in I16F16 give the same
//! integer.
//!
//! # Example
//!
//! ```
//! use bandnoise::levels::Levels;
//! use bandnoise::prelude::*;
//!
//! let noise = Perlin::new(7);
//! // The noise's whole range: no value is clipped.
//! let levels = Levels::symmetric(noise.amplitude_bound::<2>())?;
//! let v: I16F16 = noise.sample([I16F16::from_num(3.7), I16F16::from_num(-1.2)]);
//! let brightness: u8 = levels.u8(v);
//! let f: f32 = noise.sample([3.7f32, -1.2]);
//! assert!(levels.u8(f).abs_diff(brightness) <= 1); // the same noise in f32
//! assert_eq!(levels.i16(0.0f32), 0);
//! assert_eq!(levels.u16(-100.0f32), 0); // saturates outside the range
//!
//! // More contrast: a narrower range, which clips the rare extremes.
//! let punchy = Levels::new(-0.5, 0.5)?;
//! assert_eq!(punchy.u8(0.75f32), 255);
//! # Ok::<(), bandnoise::Error>(())
//! ```

use crate::{Error, I16F16, Real};

/// A division-free map from a range of noise values to `u16`, `u8` and `i16` (module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Levels {
    /// `lo′`'s I16F16 bits.
    lo: i32,
    /// The input shift `r`.
    shift: u32,
    /// `S`, in `2..=65536`.
    width: u32,
    /// `⌈2³¹ / S⌉`.
    scale: u32,
}

impl Default for Levels {
    /// [`Levels::UNIT`].
    fn default() -> Self {
        Self::UNIT
    }
}

impl Levels {
    /// The map of `[-1, 1]`, the range of most of the crate's noises in their common
    /// dimensions: `Levels::new(-1.0, 1.0)`, as a constant.
    pub const UNIT: Levels = Levels {
        lo: -65_536,
        shift: 1,
        width: 65_536,
        scale: 32_768,
    };

    /// The map of `[lo, hi]` onto `0..=65535` (module docs: how the ends are rounded).
    ///
    /// # Errors
    ///
    /// [`Error::Levels`] unless `lo` and `hi` are finite, `lo < hi` once read as I16F16, and
    /// both lie within I16F16's range (±32768).
    pub fn new(lo: f32, hi: f32) -> Result<Self, Error> {
        let fixed =
            |v: f32| (v.is_finite() && v.abs() < 32_768.0).then(|| I16F16::from_f32(v).to_bits());
        let (Some(lo_bits), Some(hi_bits)) = (fixed(lo), fixed(hi)) else {
            return Err(Error::Levels { lo, hi });
        };
        if lo_bits >= hi_bits {
            return Err(Error::Levels { lo, hi });
        }
        let (lo_bits, hi_bits) = (i64::from(lo_bits), i64::from(hi_bits));
        let mut shift = 0;
        loop {
            // The ends rounded outward to multiples of 2^shift, and the width in those units.
            let lo_r = lo_bits >> shift;
            let hi_r = -((-hi_bits) >> shift);
            let width = (hi_r - lo_r).max(2);
            if width <= 1 << 16 {
                let width = width as u32;
                return Ok(Self {
                    lo: (lo_r << shift) as i32,
                    shift,
                    width,
                    scale: (1u32 << 31).div_ceil(width),
                });
            }
            shift += 1;
        }
    }

    /// The map of `[-bound, bound]` (a noise's
    /// [`amplitude_bound`](crate::Noise::amplitude_bound), so no value clips).
    ///
    /// # Errors
    ///
    /// As [`Levels::new`]`(-bound, bound)`: `bound` must be positive, finite and below 32768.
    pub fn symmetric(bound: f32) -> Result<Self, Error> {
        Self::new(-bound, bound)
    }

    /// `v` as `0..=65535` (module docs: the formula).
    #[must_use]
    #[inline]
    pub fn u16<R: Real>(&self, v: R) -> u16 {
        let bits = v.fixed_bits();
        // v − lo′ is exact as u32 (both are i32) when v ≥ lo′.
        let x = if bits < self.lo {
            0
        } else {
            bits.wrapping_sub(self.lo) as u32
        };
        let x = (x >> self.shift).min(self.width);
        // x ≤ S ≤ 2¹⁶ and S·⌈2³¹/S⌉ < 2³¹ + S: the product fits 32 bits.
        ((x * self.scale) >> 15).min(0xFFFF) as u16
    }

    /// `v` as `0..=255`: the top byte of [`Levels::u16`].
    #[must_use]
    #[inline]
    pub fn u8<R: Real>(&self, v: R) -> u8 {
        (self.u16(v) >> 8) as u8
    }

    /// `v` as `-32768..=32767`: [`Levels::u16`] minus 32768, so the range's midpoint maps to 0.
    #[must_use]
    #[inline]
    pub fn i16<R: Real>(&self, v: R) -> i16 {
        (self.u16(v) ^ 0x8000) as i16
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The exact `⌊(v − lo′)·65536 / (hi′ − lo′)⌋`, saturated, from the stored `lo′` and width.
    fn ideal(l: &Levels, bits: i32) -> i64 {
        let span = i64::from(l.width) << l.shift;
        let x = (i64::from(bits) - i64::from(l.lo)).clamp(0, span);
        (x * 65536 / span).min(65535)
    }

    #[test]
    fn every_value_maps_within_two_levels_and_in_order() {
        for (lo, hi) in [
            (-1.0f32, 1.0),
            (-0.7, 0.7),
            (0.0, 1.0),
            (-0.3, 0.9),
            (-7.96875, 7.96875),
            (-1.0e-4, 1.0e-4),
            (-30_000.0, 30_000.0),
            (-1.0, -0.999_97),
        ] {
            let l = Levels::new(lo, hi).unwrap();
            let span = i64::from(l.width) << l.shift;
            let (lo_bits, hi_bits) = (i64::from(l.lo), i64::from(l.lo) + span);
            assert!(lo_bits <= i64::from(I16F16::from_f32(lo).to_bits()));
            assert!(hi_bits >= i64::from(I16F16::from_f32(hi).to_bits()));
            assert_eq!(l.u16(I16F16::from_bits(lo_bits as i32)), 0);
            assert_eq!(
                l.u16(I16F16::from_bits(hi_bits.min(i32::MAX.into()) as i32)),
                65535
            );
            if (lo_bits + hi_bits) % 2 == 0 {
                let mid = I16F16::from_bits(((lo_bits + hi_bits) / 2) as i32);
                assert_eq!(l.u16(mid), 32768, "{lo} {hi}");
            }
            // Every input bit pattern across the range and a margin either side.
            let step = (span / 200_000).max(1);
            let mut last = 0;
            let mut bits = lo_bits - span / 8;
            while bits <= hi_bits + span / 8 {
                let b = bits.clamp(i32::MIN.into(), i32::MAX.into()) as i32;
                let got = l.u16(I16F16::from_bits(b));
                let want = ideal(&l, b);
                assert!(
                    (i64::from(got) - want).abs() <= 2,
                    "{lo} {hi}: {b} {got} {want}"
                );
                assert!(got >= last, "{lo} {hi}: not monotone at {b}");
                last = got;
                bits += step;
            }
        }
    }

    #[test]
    fn floats_map_as_their_fixed_point_value() {
        let l = Levels::symmetric(1.2).unwrap();
        for i in -100_000..100_000 {
            let bits = i * 1237;
            let q = I16F16::from_bits(bits);
            assert_eq!(l.u16(q.to_f32()), l.u16(q), "{bits}");
        }
        assert_eq!(l.u16(f32::NAN), 32768);
        assert_eq!(l.u16(f32::INFINITY), 65535);
        assert_eq!(l.u16(f32::NEG_INFINITY), 0);
        assert_eq!(l.u16(I16F16::MAX), 65535);
        assert_eq!(l.u16(I16F16::MIN), 0);
    }

    #[test]
    fn narrow_outputs_follow_u16() {
        let l = Levels::symmetric(0.9).unwrap();
        for bits in (-70_000..70_000).step_by(7) {
            let v = I16F16::from_bits(bits);
            assert_eq!(u16::from(l.u8(v)), l.u16(v) >> 8);
            assert_eq!(i32::from(l.i16(v)), i32::from(l.u16(v)) - 32768);
        }
        assert_eq!(l.i16(0.0f32), 0);
    }

    #[test]
    fn the_unit_range_is_its_constant() {
        assert_eq!(Levels::new(-1.0, 1.0), Ok(Levels::UNIT));
        assert_eq!(Levels::default(), Levels::UNIT);
    }

    #[test]
    fn bad_ranges_are_errors() {
        for (lo, hi) in [
            (1.0f32, 1.0),
            (1.0, -1.0),
            (f32::NAN, 1.0),
            (0.0, f32::INFINITY),
            (-40_000.0, 0.0),
            (0.0, 1.0e-6), // equal once read as I16F16
        ] {
            let refused = Levels::new(lo, hi);
            assert!(
                matches!(refused, Err(Error::Levels { lo: l, hi: h })
                    if l.to_bits() == lo.to_bits() && h.to_bits() == hi.to_bits()),
                "{lo} {hi}: {refused:?}"
            );
        }
        assert!(Levels::symmetric(0.0).is_err());
        assert!(Levels::symmetric(-1.0).is_err());
    }
}

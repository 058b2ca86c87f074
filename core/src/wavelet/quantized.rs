//! Tiles quantized to `i16` for flash-limited firmware: half the bytes of an `f32` tile.
//!
//! Each coefficient is stored as `q = round(n · 2^shift)` with the largest `shift` that keeps
//! every `|q| ≤ 32767`. A power-of-two scale makes the conversion exact and cheap in every
//! number type (`Real::from_ratio`): a shift in fixed point, an exact multiplication in floats.
//! The error of a coefficient is at most `2^-(shift+1)`, and so is the error of a noise value
//! (the B-spline weights are non-negative and sum to 1). For the default 3D tile the shift is 12:
//! at most 1.2e-4 (measured in `tests/tests/wavelet.rs`).

use crate::Real;

use super::band::TileData;
use super::tile::{Tile2, Tile3};

/// The largest shift with `round(max_abs · 2^shift) ≤ 32767`.
const fn shift_for(max_abs: f32) -> u32 {
    let mut shift = 0;
    while shift < 15 && (max_abs as f64) * ((1u32 << (shift + 1)) as f64) + 0.5 < 32767.0 {
        shift += 1;
    }
    shift
}

/// Rounds to nearest (ties away from zero).
const fn quantize(v: f32, shift: u32) -> i16 {
    let x = v as f64 * (1u32 << shift) as f64;
    (if x < 0.0 { x - 0.5 } else { x + 0.5 }) as i16
}

/// A 2D tile of `i16` coefficients with a power-of-two scale.
#[derive(Clone, Debug, PartialEq)]
pub struct QuantizedTile2<const N: usize> {
    data: [[i16; N]; N],
    shift: u32,
    max_abs: f32,
    variance: f32,
}

/// A 3D tile of `i16` coefficients with a power-of-two scale.
///
/// # Examples
///
/// ```
/// use bandnoise::wavelet::{QuantizedTile3, Tile3, Wavelet};
/// use bandnoise::{I16F16, Noise};
///
/// const TILE: Tile3<8> = Tile3::generate(3);
/// static SMALL: QuantizedTile3<8> = QuantizedTile3::quantize(&TILE);
/// let band = Wavelet::new(0, &SMALL);
/// let v: I16F16 = band.sample([I16F16::from_num(1.5), I16F16::ZERO, I16F16::ONE]);
/// let f: f32 = Wavelet::new(0, &TILE).sample([1.5, 0.0, 1.0]);
/// assert!((v.to_num::<f32>() - f).abs() < 1e-3);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct QuantizedTile3<const N: usize> {
    data: [[[i16; N]; N]; N],
    shift: u32,
    max_abs: f32,
    variance: f32,
}

impl<const N: usize> QuantizedTile2<N> {
    /// The band's exact variance averaged over space (that of the tile quantized).
    #[must_use]
    pub const fn variance(&self) -> f32 {
        self.variance
    }

    /// Quantizes `tile` (`const`).
    #[must_use]
    pub const fn quantize(tile: &Tile2<N>) -> Self {
        let shift = shift_for(tile.max_abs);
        let mut data = [[0i16; N]; N];
        let mut i = 0;
        while i < N * N {
            data[i / N][i % N] = quantize(tile.data[i / N][i % N], shift);
            i += 1;
        }
        Self {
            data,
            shift,
            max_abs: tile.max_abs + 1.0 / (2u32 << shift) as f32,
            variance: tile.variance,
        }
    }

    /// Coefficients are `q · 2^-shift`.
    #[must_use]
    pub const fn shift(&self) -> u32 {
        self.shift
    }

    /// `q` at flat index `x + N·y`: in range by construction; `get` keeps sampling provably
    /// panic-free.
    #[inline]
    fn read(&self, index: usize) -> i16 {
        let data = self.data.as_flattened();
        data.get(super::band::within(index, data.len()))
            .copied()
            .unwrap_or(0)
    }
}

impl<const N: usize> QuantizedTile3<N> {
    /// The band's exact variance averaged over space (that of the tile quantized).
    #[must_use]
    pub const fn variance(&self) -> f32 {
        self.variance
    }

    /// Quantizes `tile` (`const`).
    #[must_use]
    pub const fn quantize(tile: &Tile3<N>) -> Self {
        let shift = shift_for(tile.max_abs);
        let mut data = [[[0i16; N]; N]; N];
        let mut i = 0;
        while i < N * N * N {
            let (z, y, x) = (i / (N * N), (i / N) % N, i % N);
            data[z][y][x] = quantize(tile.data[z][y][x], shift);
            i += 1;
        }
        Self {
            data,
            shift,
            max_abs: tile.max_abs + 1.0 / (2u32 << shift) as f32,
            variance: tile.variance,
        }
    }

    /// Coefficients are `q · 2^-shift`.
    #[must_use]
    pub const fn shift(&self) -> u32 {
        self.shift
    }

    /// `q` at flat index `x + N·(y + N·z)`: in range by construction; `get` keeps sampling
    /// provably panic-free.
    #[inline]
    fn read(&self, index: usize) -> i16 {
        let data = self.data.as_flattened().as_flattened();
        data.get(super::band::within(index, data.len()))
            .copied()
            .unwrap_or(0)
    }
}

/// The [`TileData`] methods both quantized tiles share: every read through `read` (the
/// integer at a flat index) and the shift.
macro_rules! quantized_reads {
    () => {
        #[inline]
        fn flat<R: Real>(&self, index: usize) -> R {
            R::from_ratio(self.read(index).into(), self.shift)
        }
        #[inline]
        fn unit<R: Real>(&self) -> R {
            R::from_ratio(1, self.shift)
        }
        #[inline]
        fn flat_with<R: Real>(&self, index: usize, unit: R) -> R {
            R::from_ratio_unit(self.read(index).into(), self.shift, unit)
        }
        fn max_abs(&self) -> f32 {
            self.max_abs
        }
        #[inline]
        fn quantized_shift(&self) -> Option<u32> {
            Some(self.shift)
        }
        #[inline]
        fn raw(&self, index: usize) -> i16 {
            self.read(index)
        }
    };
}

impl<const N: usize> TileData<2> for QuantizedTile2<N> {
    const SIZE: usize = N;
    #[inline]
    fn get<R: Real>(&self, [x, y]: [usize; 2]) -> R {
        self.flat(x + N * y)
    }
    quantized_reads!();
}

impl<const N: usize> TileData<3> for QuantizedTile3<N> {
    const SIZE: usize = N;
    #[inline]
    fn get<R: Real>(&self, [x, y, z]: [usize; 3]) -> R {
        self.flat(x + N * (y + N * z))
    }
    quantized_reads!();
}

#[cfg(test)]
mod tests {
    use super::super::band::TileData;
    use super::super::{TILE2_I16, TILE3_I16};
    use crate::{I16F16, Real};

    /// `flat_with` with the tile's `unit` reads every coefficient as `flat` does, bit for bit,
    /// in each number type (the sampling paths read through it).
    #[test]
    fn reads_with_the_unit_are_reads() {
        fn check<R: Real, T: TileData<D>, const D: usize>(tile: &T, bits: impl Fn(R) -> u64) {
            let unit = tile.unit::<R>();
            for i in 0..T::SIZE.pow(D as u32) {
                assert_eq!(
                    bits(tile.flat_with(i, unit)),
                    bits(tile.flat(i)),
                    "index {i}"
                );
            }
        }
        check::<f32, _, 2>(&TILE2_I16, |v| v.to_bits().into());
        check::<f64, _, 2>(&TILE2_I16, f64::to_bits);
        check::<I16F16, _, 2>(&TILE2_I16, |v| v.to_bits() as u64);
        check::<f32, _, 3>(&TILE3_I16, |v| v.to_bits().into());
        check::<f64, _, 3>(&TILE3_I16, f64::to_bits);
        check::<I16F16, _, 3>(&TILE3_I16, |v| v.to_bits() as u64);
    }
}

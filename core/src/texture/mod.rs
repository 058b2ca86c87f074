//! Textures: noise put to use, as functions of a point, with colour maps.
//!
//! * [`Windy`]: pbrt's windy waves (§10.6.5): fBm waves scaled by a slower fBm wind strength.
//! * [`Wrinkled`]: pbrt's wrinkled bump texture (§10.6.4): turbulence, anti-aliased.
//! * [`Marble`]: pbrt's marble (§10.6.6): strata `sin(y + variation · fBm)` through a colour
//!   spline; [`Marble::olano`] is Olano's marble (Olano 2005 §4, Fig. 7c): the strata perturbed
//!   by his 3D turbulence from one 2D table ([`MixedTurbulence`]), Perlin's 1985 recipe.
//! * [`PolkaDots`]: pbrt's polka dots (§10.6.2): a dot in half of the cells, shifted at random
//!   within its cell.
//! * [`Wood`]: Lewis's solid wood (Lewis 1989 §5.1): `xtab[√(x² + y²) + η(p)]`, rings around
//!   the z axis perturbed by a noise; [`Wood::olano`] is Olano's wood (Fig. 7b), the rings
//!   perturbed by [`MixedTurbulence`].
//!
//! Each texture is a [`Noise`] (its scalar value: a height for the bump textures, a fraction
//! in `[0, 1]` for the others), so it samples in `f32`, `f64` and I16F16, fills grids and
//! keeps the sampling contract (a value for every input, never a panic); and a [`Texture`],
//! whose [`color`](Texture::color) maps its [`pattern`](Texture::pattern) through a
//! [`ColorMap`]. Where pbrt anti-aliases (its fBm and turbulence), the texture is a
//! [`FilteredNoise`](crate::FilteredNoise) over the same footprint.
//!
//! The textures take any noise where the papers name a noise (`Windy<N>`, `Marble<N>`,
//! `Wood<N>`); `new(seed)` gives the paper's (Perlin's improved noise for pbrt, pbrt's own
//! being the same function) with the paper's settings.
//!
//! [`MixedTurbulence`]: crate::lattice::MixedTurbulence
//! [`Noise`]: crate::Noise

mod color;
mod pbrt;
mod wood;

pub use color::{ColorMap, Interpolation, Rgb16, rgb};
pub use pbrt::{Marble, PolkaDots, Windy, Wrinkled};
pub use wood::Wood;

use crate::fractal::Setting;
use crate::{Error, Noise, Real};

/// A texture: a [`Noise`] whose value, as a fraction in `[0, 1]`, indexes a [`ColorMap`].
///
/// # Examples
///
/// ```
/// use bandnoise::texture::{Marble, Texture};
///
/// let marble = Marble::new(7);
/// let [r, g, b] = marble.color([0.25f32, 1.5, 0.75]);
/// assert!([r, g, b].iter().all(|c| (0.0..=1.0).contains(c)));
/// let pixel: [u8; 3] = marble.color_rgb8([0.25f32, 1.5, 0.75]);
/// # let _ = pixel;
/// ```
pub trait Texture<R: Real, const D: usize>: Noise<R, D> {
    /// The pattern at `p` in `[0, 1]`, the colour map's argument: the value itself for the
    /// textures whose value is a fraction, the height mapped into `[0, 1]` for the bump
    /// textures.
    #[must_use]
    fn pattern(&self, p: [R; D]) -> R;

    /// The colour map.
    #[must_use]
    fn color_map(&self) -> &ColorMap;

    /// The colour at `p`: red, green and blue in `[0, 1]`.
    #[must_use]
    fn color(&self, p: [R; D]) -> [R; 3] {
        self.color_map().map(self.pattern(p))
    }

    /// The colour at `p` as 8-bit components.
    #[must_use]
    fn color_rgb8(&self, p: [R; D]) -> [u8; 3] {
        self.color_map().map_rgb8(self.pattern(p))
    }
}

/// A texture setting, checked to be in `[min, max]` (and finite).
fn setting(name: &'static str, value: f32, min: f32, max: f32) -> Result<Setting, Error> {
    if (min..=max).contains(&value) {
        Ok(Setting::new(value))
    } else {
        Err(Error::TextureSetting {
            name,
            value,
            min,
            max,
        })
    }
}

/// `p` with every coordinate times `s` (wrapping in fixed point, as octave frequencies do:
/// a wrapped coordinate still lands on a lattice cell).
#[inline]
fn scaled<R: Real, const D: usize>(p: [R; D], s: R) -> [R; D] {
    p.map(|x| x.wrapping_mul(s))
}

/// `2⁶⁴ / 2π`, rounded: a whole number `n` of radians is `n · TURNS_Q64 mod 2⁶⁴` turns in
/// units of 2⁻⁶⁴, to within `|n| · 2⁻⁶⁵`.
const TURNS_Q64: u64 = 0x28be_60db_9391_054a;

/// `sin x` from the tabled cosine ([`Real::cos_turns`]): `cos 2π(x/2π − ¼)`. The turns of
/// `x`'s whole part are computed modulo 1 in 64-bit integers and those of its fraction in the
/// type, so the phase does not lose precision as `|x|` grows (a product `x · (1/2π)` in
/// I16F16 would be off by `|x| · 2⁻¹⁸` turns, 2·10⁻³ at `x = 500`). A non-finite `x` is 0
/// ([`Real::split`]).
#[inline]
fn sin<R: Real>(x: R) -> R {
    let (whole, frac) = x.split();
    let turns = (i64::from(whole) as u64)
        .wrapping_mul(TURNS_Q64)
        .wrapping_sub(1 << 62);
    // The turns to 2⁻⁴⁸ (exact in f64; the type rounds the sum): each part below 2²⁴.
    let high = R::from_ratio((turns >> 40) as i32, 24);
    let low = R::from_ratio((turns >> 16 & 0xff_ffff) as i32, 48);
    let per_turn = R::from_f64_nearest(1.0 / core::f64::consts::TAU);
    (high + low + frac.mul_fraction(per_turn)).cos_turns()
}

#[cfg(test)]
mod tests {
    use super::sin;
    use crate::{I16F16, Real};

    /// The phase keeps its precision far from 0 in every type: within the tabled cosine's
    /// error (and I16F16's rounding of the argument's fraction) of `f64::sin`.
    #[test]
    fn sine_is_accurate_at_any_magnitude() {
        for k in -2995..2995 {
            let x = f64::from(k) * 10.9375; // multiples of 2⁻⁴ up to ±32 758: exact in every type
            let exact = x.sin();
            assert!((sin(x) - exact).abs() < 1e-7, "{x}");
            assert!((f64::from(sin(x as f32)) - exact).abs() < 1e-6, "{x}");
            let fixed = sin(I16F16::from_num(x)).to_f64();
            assert!((fixed - exact).abs() < 2e-4, "{x}: {fixed} vs {exact}");
        }
        assert_eq!(sin(f32::NAN), 0.0);
        assert_eq!(sin(f64::INFINITY), 0.0);
        assert!(sin(I16F16::MAX).abs() <= I16F16::ONE);
    }
}

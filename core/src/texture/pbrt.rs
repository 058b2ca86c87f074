//! pbrt's noise textures (Pharr, Jakob & Humphreys, *Physically Based Rendering*, §10.6.2,
//! §10.6.4–§10.6.6), and Olano's marble.

use super::{ColorMap, Texture, scaled, setting, sin};
use crate::fractal::{Fractal, Octaves, Setting};
use crate::hash::{CellHash, CellRng};
use crate::lattice::{MixedTurbulence, Perlin};
use crate::{Error, FilteredNoise, I16F16, Noise, Real};

/// `0.1`, the scale pbrt's windy waves sample the wind at.
const TENTH: (f32, I16F16) = (0.1, I16F16::from_bits(6554));

/// `clamp(½ + gain · v, 0, 1)`: a height as a colour map's fraction.
#[inline]
fn unit_from_height<R: Real>(v: R, gain: R) -> R {
    R::from_ratio(1, 1)
        .saturating_add(gain.saturating_mul(v))
        .clamp_to(R::ZERO, R::ONE)
}

/// pbrt's windy waves (§10.6.5): `|fBm(p/10, 3 octaves)| · fBm(p, 6 octaves)`, waves whose
/// height follows a wind strength that varies ten times more slowly; pbrt's octaves (gain 0.5,
/// lacunarity 1.99) over any noise, Perlin's improved noise by default (pbrt's `Noise`).
///
/// Range: `|v| ≤ B₃ · B₆`, the two sums' bounds ([`Fractal`]'s proof); in practice much less
/// (0.61 at most over a 400² grid at the default seed). Its [`pattern`](Texture::pattern) is
/// `clamp(½ + 1.5 v, 0, 1)`, which clamps the highest crests (`|v| > ⅓`: 0.55% of points at the
/// default seed, `tests/tests/texture.rs`), coloured by [`ColorMap::WATER`].
///
/// # Examples
///
/// ```
/// use bandnoise::{FilteredNoise, Noise, texture::Windy};
///
/// let sea = Windy::new(3);
/// let bound = Noise::<f32, 2>::amplitude_bound(&sea);
/// let h: f32 = sea.sample([12.5, 40.25]);
/// assert!(h.abs() <= bound);
/// // Seen from afar (a footprint of 2 units per pixel), the fine waves are left out.
/// let far: f32 = sea.sample_filtered([12.5, 40.25], [2.0, 0.0], [0.0, 2.0]);
/// assert!(far.abs() <= bound);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Windy<N = Perlin> {
    /// The wind's sum, over the waves' noise (one noise, held once).
    wind: Fractal<()>,
    waves: Fractal<N>,
    colors: ColorMap,
}

impl Windy<Perlin> {
    /// pbrt's windy waves over [`Perlin::new(seed)`](Perlin::new).
    #[must_use]
    pub fn new(seed: u32) -> Self {
        Self::with_noise(Perlin::new(seed))
    }
}

impl<N> Windy<N> {
    /// pbrt's windy waves over `noise`.
    #[must_use]
    pub fn with_noise(noise: N) -> Self {
        Self {
            wind: Fractal::fbm((), Octaves::pbrt(3)),
            waves: Fractal::fbm(noise, Octaves::pbrt(6)),
            colors: ColorMap::WATER,
        }
    }
}

impl<N> Windy<N> {
    /// The same texture coloured by `colors`.
    #[must_use]
    pub fn with_colors(self, colors: ColorMap) -> Self {
        Self { colors, ..self }
    }
}

impl<N: Noise<R, D>, R: Real, const D: usize> Noise<R, D> for Windy<N> {
    #[inline]
    fn sample(&self, p: [R; D]) -> R {
        let tenth = R::from_setting(TENTH.0, TENTH.1);
        let wind = self
            .wind
            .with_noise(self.waves.noise())
            .sample(scaled(p, tenth));
        wind.abs().saturating_mul(self.waves.sample(p)).canonical()
    }

    fn amplitude_bound(&self) -> f32 {
        let wind = self.wind.with_noise(self.waves.noise());
        Noise::<R, D>::amplitude_bound(&wind) * Noise::<R, D>::amplitude_bound(&self.waves)
    }
}

impl<N: Noise<R, D>, R: Real, const D: usize> FilteredNoise<R, D> for Windy<N> {
    /// pbrt's: both sums anti-aliased by the footprint, the wind's scaled as its point is.
    fn sample_filtered(&self, p: [R; D], dpdx: [R; D], dpdy: [R; D]) -> R {
        let tenth = R::from_setting(TENTH.0, TENTH.1);
        let wind = self.wind.with_noise(self.waves.noise()).sample_filtered(
            scaled(p, tenth),
            scaled(dpdx, tenth),
            scaled(dpdy, tenth),
        );
        let waves = self.waves.sample_filtered(p, dpdx, dpdy);
        wind.abs().saturating_mul(waves).canonical()
    }
}

impl<N: Noise<R, D>, R: Real, const D: usize> Texture<R, D> for Windy<N> {
    fn pattern(&self, p: [R; D]) -> R {
        unit_from_height(self.sample(p), R::from_ratio(3, 1))
    }

    fn color_map(&self) -> &ColorMap {
        &self.colors
    }
}

/// pbrt's wrinkled texture (§10.6.4): turbulence `Σ 0.5ⁱ |noise(1.99ⁱ p)|` of 8 octaves
/// (pbrt's defaults) over any noise, Perlin's improved noise by default, for bump mapping;
/// [`FilteredNoise`] is pbrt's anti-aliased turbulence ([`Fractal::sample_filtered`]).
///
/// Range: `[0, B]`, the sum's bound. Its [`pattern`](Texture::pattern) is `min(⅔ v, 1)`
/// (turbulence exceeds 1.5 at under 0.1% of points at the default seed,
/// `tests/tests/texture.rs`), coloured by [`ColorMap::GREY`].
///
/// # Examples
///
/// ```
/// use bandnoise::{Noise, texture::Wrinkled};
///
/// let w = Wrinkled::new(1);
/// let v: f32 = w.sample([0.3, 0.6, 0.9]);
/// assert!(v >= 0.0 && v <= Noise::<f32, 3>::amplitude_bound(&w));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Wrinkled<N = Perlin> {
    turbulence: Fractal<N>,
    colors: ColorMap,
}

impl Wrinkled<Perlin> {
    /// pbrt's wrinkled texture over [`Perlin::new(seed)`](Perlin::new).
    #[must_use]
    pub fn new(seed: u32) -> Self {
        Self::with_noise(Perlin::new(seed), Octaves::pbrt(8))
    }
}

impl<N> Wrinkled<N> {
    /// Turbulence of `noise` with `octaves` (pbrt's `octaves` and `roughness`, which is the
    /// gain).
    #[must_use]
    pub fn with_noise(noise: N, octaves: Octaves) -> Self {
        Self {
            turbulence: Fractal::turbulence(noise, octaves),
            colors: ColorMap::GREY,
        }
    }

    /// The same texture coloured by `colors`.
    #[must_use]
    pub fn with_colors(self, colors: ColorMap) -> Self {
        Self { colors, ..self }
    }

    /// The turbulence sum.
    #[must_use]
    pub fn turbulence(&self) -> &Fractal<N> {
        &self.turbulence
    }
}

impl<N: Noise<R, D>, R: Real, const D: usize> Noise<R, D> for Wrinkled<N> {
    #[inline]
    fn sample(&self, p: [R; D]) -> R {
        self.turbulence.sample(p)
    }

    fn amplitude_bound(&self) -> f32 {
        Noise::<R, D>::amplitude_bound(&self.turbulence)
    }

    #[inline]
    fn sample_lanes(&self, p: &[[R; crate::batch::LANES]; D], out: &mut [R; crate::batch::LANES]) {
        self.turbulence.sample_lanes(p, out);
    }
}

impl<N: Noise<R, D>, R: Real, const D: usize> FilteredNoise<R, D> for Wrinkled<N> {
    fn sample_filtered(&self, p: [R; D], dpdx: [R; D], dpdy: [R; D]) -> R {
        self.turbulence.sample_filtered(p, dpdx, dpdy)
    }
}

impl<N: Noise<R, D>, R: Real, const D: usize> Texture<R, D> for Wrinkled<N> {
    fn pattern(&self, p: [R; D]) -> R {
        let two_thirds = R::from_setting(2.0 / 3.0, I16F16::from_bits(43691));
        self.sample(p)
            .saturating_mul(two_thirds)
            .clamp_to(R::ZERO, R::ONE)
    }

    fn color_map(&self) -> &ColorMap {
        &self.colors
    }
}

/// pbrt's marble (§10.6.6): strata along `y` perturbed by a noise,
/// `t = ½ + ½ sin(s·y + variation · noise(s·p))` for the scale `s`, coloured by a spline
/// through marble's colours ([`ColorMap::MARBLE`]). In 1D the strata run along `x`.
///
/// [`Marble::new`] is pbrt's: fBm of 8 octaves (gain 0.5, lacunarity 1.99) of Perlin's noise,
/// scale 1, variation 0.2. [`Marble::olano`] is Olano's (2005, Fig. 7c): the strata perturbed
/// by his 4-octave turbulence evaluated from one 2D table, Perlin's 1985
/// `sin(x + turbulence(p))`, scale 1 and variation 1.5 (turbulence's mean is near 0.35).
///
/// Range: `[0, 1]` (the sine is from [`Real::cos_turns`], within `[−1, 1]`). With a noise
/// that is a [`FilteredNoise`], the marble is one too: the noise anti-aliased by the footprint
/// scaled as the point is (pbrt's).
///
/// # Examples
///
/// ```
/// use bandnoise::{I16F16, Noise, texture::{Marble, Texture}};
///
/// let pbrt = Marble::new(0);
/// let t: f32 = pbrt.sample([0.5, 2.0, 1.0]);
/// assert!((0.0..=1.0).contains(&t));
/// let olano = Marble::olano(0);
/// let fixed: I16F16 = olano.sample([I16F16::from_num(0.5), I16F16::from_num(2)]);
/// assert!(fixed >= 0 && fixed <= 1);
/// let _rgb = olano.color([0.5f32, 2.0, 1.0]);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Marble<N = Fractal<Perlin>> {
    noise: N,
    scale: Setting,
    variation: Setting,
    colors: ColorMap,
}

impl Marble<Fractal<Perlin>> {
    /// pbrt's marble over [`Perlin::new(seed)`](Perlin::new) with pbrt's defaults.
    #[must_use]
    pub fn new(seed: u32) -> Self {
        Self {
            noise: Fractal::fbm(Perlin::new(seed), Octaves::pbrt(8)),
            scale: Setting::new(1.0),
            variation: Setting::new(0.2),
            colors: ColorMap::MARBLE,
        }
    }
}

impl Marble<MixedTurbulence<4>> {
    /// Olano's marble: [`MixedTurbulence::new(seed)`](MixedTurbulence::new), scale 1,
    /// variation 1.5.
    #[must_use]
    pub fn olano(seed: u32) -> Self {
        Self {
            noise: MixedTurbulence::new(seed),
            scale: Setting::new(1.0),
            variation: Setting::new(1.5),
            colors: ColorMap::MARBLE,
        }
    }
}

impl<N> Marble<N> {
    /// The largest scale and variation magnitude.
    pub const MAX_SETTING: f32 = 1024.0;

    /// Marble perturbed by `noise`, with pbrt's `scale` and `variation`.
    ///
    /// # Errors
    ///
    /// [`Error::TextureSetting`] unless both are finite and within ±1024.
    pub fn with_noise(noise: N, scale: f32, variation: f32) -> Result<Self, Error> {
        let m = Self::MAX_SETTING;
        Ok(Self {
            noise,
            scale: setting("scale", scale, -m, m)?,
            variation: setting("variation", variation, -m, m)?,
            colors: ColorMap::MARBLE,
        })
    }

    /// The same texture coloured by `colors`.
    #[must_use]
    pub fn with_colors(self, colors: ColorMap) -> Self {
        Self { colors, ..self }
    }

    /// The perturbing noise.
    #[must_use]
    pub fn noise(&self) -> &N {
        &self.noise
    }

    /// The scale.
    #[must_use]
    pub fn scale(&self) -> f32 {
        self.scale.value()
    }

    /// The variation.
    #[must_use]
    pub fn variation(&self) -> f32 {
        self.variation.value()
    }

    /// `½ + ½ sin(y + variation · n)` for the scaled point `q` and its noise `n`.
    #[inline]
    fn strata<R: Real, const D: usize>(&self, q: [R; D], n: R) -> R {
        let y = q[if D > 1 { 1 } else { 0 }];
        let m = y.saturating_add(self.variation.get::<R>().saturating_mul(n));
        (R::ONE + sin(m))
            .mul_fraction(R::from_ratio(1, 1))
            .canonical()
    }
}

impl<N: Noise<R, D>, R: Real, const D: usize> Noise<R, D> for Marble<N> {
    #[inline]
    fn sample(&self, p: [R; D]) -> R {
        let q = scaled(p, self.scale.get());
        self.strata(q, self.noise.sample(q))
    }

    fn amplitude_bound(&self) -> f32 {
        1.0
    }
}

impl<N: FilteredNoise<R, D>, R: Real, const D: usize> FilteredNoise<R, D> for Marble<N> {
    fn sample_filtered(&self, p: [R; D], dpdx: [R; D], dpdy: [R; D]) -> R {
        let s = self.scale.get();
        let q = scaled(p, s);
        let n = self
            .noise
            .sample_filtered(q, scaled(dpdx, s), scaled(dpdy, s));
        self.strata(q, n)
    }
}

impl<N: Noise<R, D>, R: Real, const D: usize> Texture<R, D> for Marble<N> {
    fn pattern(&self, p: [R; D]) -> R {
        self.sample(p)
    }

    fn color_map(&self) -> &ColorMap {
        &self.colors
    }
}

/// pbrt's polka dots (§10.6.2): cells of side 1 centred on the integer points, each holding a
/// dot with probability ½ (pbrt's), of radius 0.35 shifted at random by up to `0.5 − 0.35`
/// along each axis, so that it stays in its cell. The value is 1 inside a dot and 0 outside, in
/// any dimension (dots, balls).
///
/// pbrt draws the presence and the shift from Perlin noise at points offset from the cell
/// centre; here they come from the cell's own generator ([`CellRng`], seeded by the texture's
/// seed and the cell), so that neighbouring cells are independent and every seed differs. The
/// plain sample is a step at the dot's edge, as pbrt's; [`FilteredNoise`] anti-aliases it by a
/// footprint.
///
/// # Examples
///
/// ```
/// use bandnoise::{Noise, texture::PolkaDots};
///
/// let dots = PolkaDots::new(4).with_radius(0.25)?.with_chance(0.75)?;
/// let v: f32 = dots.sample([3.1, -7.9]);
/// assert!(v == 0.0 || v == 1.0);
/// assert!(PolkaDots::new(4).with_radius(0.6).is_err());
/// # Ok::<(), bandnoise::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct PolkaDots {
    hash: CellHash,
    radius: Setting,
    shift: Setting,
    /// A cell holds a dot when its first draw is below this (`chance · 2³²`).
    threshold: u64,
    colors: ColorMap,
}

impl PolkaDots {
    /// pbrt's polka dots: radius 0.35, a dot in half of the cells.
    #[must_use]
    pub fn new(seed: u32) -> Self {
        Self {
            hash: CellHash::new(seed),
            radius: Setting::new(0.35),
            shift: Setting::new(0.5 - 0.35),
            threshold: 1 << 31,
            colors: ColorMap::DOTS,
        }
    }

    /// The same dots with `radius` (shifted by up to `0.5 − radius`).
    ///
    /// # Errors
    ///
    /// [`Error::TextureSetting`] unless `0 ≤ radius ≤ 0.5`.
    pub fn with_radius(self, radius: f32) -> Result<Self, Error> {
        Ok(Self {
            radius: setting("radius", radius, 0.0, 0.5)?,
            shift: Setting::new(0.5 - radius),
            ..self
        })
    }

    /// The same dots, a dot in a cell with probability `chance`.
    ///
    /// # Errors
    ///
    /// [`Error::TextureSetting`] unless `0 ≤ chance ≤ 1`.
    pub fn with_chance(self, chance: f32) -> Result<Self, Error> {
        let chance = setting("chance", chance, 0.0, 1.0)?.value();
        // chance ≤ 1: the product is at most 2³², exact in f64.
        let threshold = (f64::from(chance) * 4_294_967_296.0) as u64;
        Ok(Self { threshold, ..self })
    }

    /// The same dots coloured by `colors`.
    #[must_use]
    pub fn with_colors(self, colors: ColorMap) -> Self {
        Self { colors, ..self }
    }

    /// The radius.
    #[must_use]
    pub fn radius(&self) -> f32 {
        self.radius.value()
    }

    /// The probability that a cell holds a dot.
    #[must_use]
    pub fn chance(&self) -> f32 {
        (self.threshold as f64 / 4_294_967_296.0) as f32
    }
}

impl PolkaDots {
    /// The squared distance from `p` to the dot of its cell, if the cell holds one.
    #[inline]
    fn dot<R: Real, const D: usize>(&self, p: [R; D]) -> Option<R> {
        // The cell whose centre is nearest (`⌊x + ½⌋`), and the offset from it in [−½, ½).
        let half = R::from_ratio(1, 1);
        let mut cell = [0i32; D];
        let mut d = [R::ZERO; D];
        for a in 0..D {
            let (c, f) = p[a].split();
            (cell[a], d[a]) = if f >= half {
                (c.wrapping_add(1), f - R::ONE)
            } else {
                (c, f)
            };
        }
        let mut rng = CellRng::new(&self.hash, cell);
        if u64::from(rng.next_u32()) >= self.threshold {
            return None;
        }
        let shift = self.shift.get::<R>();
        let mut d2 = R::ZERO;
        for x in d {
            // |x| ≤ ½ and |shift · u| < ½: the difference is below 1, its square too.
            let e = x - shift.mul_rn(rng.signed_uniform());
            d2 = d2 + e.mul_rn(e);
        }
        Some(d2)
    }

    /// The fraction of space the dots cover in `D` dimensions: `chance · V_D(r)`, the
    /// probability of a dot times its ball's volume (`2r`, `πr²`, `4πr³/3`, `π²r⁴/2`).
    fn coverage<const D: usize>(&self) -> f32 {
        let r = self.radius.value();
        let ball = match D {
            1 => 2.0 * r,
            2 => core::f32::consts::PI * r * r,
            3 => 4.0 / 3.0 * core::f32::consts::PI * r * r * r,
            _ => 0.5 * core::f32::consts::PI * core::f32::consts::PI * r * r * r * r,
        };
        self.chance() * ball
    }
}

impl<R: Real, const D: usize> Noise<R, D> for PolkaDots {
    fn sample(&self, p: [R; D]) -> R {
        let r = self.radius.get::<R>();
        match self.dot(p) {
            Some(d2) if d2 < r.mul_rn(r) => R::ONE,
            _ => R::ZERO,
        }
    }

    fn amplitude_bound(&self) -> f32 {
        1.0
    }
}

/// The dots anti-aliased by the footprint (pbrt leaves this as an exercise): with
/// `w = max(|dpdx|, |dpdy|)`, a dot's edge ramps from 1 to 0 over `w` (`½ + (r − d)/w`,
/// clamped: the covered fraction of a footprint of width `w` across a straight edge; across the
/// round edge it adds `πw²/12` to a 2D dot's area), and
/// footprints from ½ to 1 cell fade to the dots' mean coverage (`chance · V_D(r)`), which
/// footprints of a cell and wider give. A zero or unknown (NaN) footprint is the plain
/// sample; an infinite one the mean. Neighbouring cells' dots are not looked at: a dot stays
/// within its cell, and footprints wide enough to reach across fade to the mean.
impl<R: Real, const D: usize> FilteredNoise<R, D> for PolkaDots {
    fn sample_filtered(&self, p: [R; D], dpdx: [R; D], dpdy: [R; D]) -> R {
        let len2 = crate::fractal::footprint_len2(&dpdx, &dpdy);
        if len2.is_nan() || len2 == R::ZERO {
            return self.sample(p);
        }
        // √∞ is ∞ (floats); fixed point's root is at most 2^7.5 (no infinity to compare).
        let w = len2.sqrt();
        let mean = R::from_f32(self.coverage::<D>());
        if w >= R::ONE {
            return mean;
        }
        let half = R::from_ratio(1, 1);
        let edge = match self.dot(p) {
            Some(d2) => {
                // w ∈ (0, 1) and |r − d| < 1: the quotient is finite; clamped to [0, 1].
                (half + (self.radius.get::<R>() - d2.sqrt()).div(w)).clamp_to(R::ZERO, R::ONE)
            }
            None => R::ZERO,
        };
        // Fade to the mean over w ∈ [½, 1]: the weight 2w − 1 clamped to [0, 1].
        let fade = w + w - R::ONE;
        let v = if fade > R::ZERO {
            edge + fade.mul_fraction(mean - edge)
        } else {
            edge
        };
        v.canonical()
    }
}

impl<R: Real, const D: usize> Texture<R, D> for PolkaDots {
    fn pattern(&self, p: [R; D]) -> R {
        self.sample(p)
    }

    fn color_map(&self) -> &ColorMap {
        &self.colors
    }
}

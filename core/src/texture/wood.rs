//! Lewis's solid wood (Lewis 1989, §5.1), and Olano's wood.

use super::{ColorMap, Texture, setting};
use crate::fractal::{Fractal, Octaves, Setting};
use crate::lattice::{MixedTurbulence, Perlin};
use crate::{Error, FilteredNoise, Noise, Real};

/// Lewis's solid wood (Lewis 1989, §5.1): `wood(p) = xtab[√(p.x² + p.y²) + η(p)]`, rings
/// around the z axis whose radius a noise `η` perturbs. Here `xtab` is a colour map over one
/// ring (Lewis's "color variation across a radial section of a typical ring",
/// [`ColorMap::WOOD`]) and the value is the place within the ring,
/// `t = frac(rings · (r + amount · η(p)))` in `[0, 1)`, where `r` is the distance from the z
/// axis (`|x|` in 1D).
///
/// [`Wood::new`] perturbs the radius by fBm of 4 octaves (gain 0.5, lacunarity 1.99) of
/// Perlin's noise, 2 rings per unit, amount 0.3; [`Wood::olano`] is Olano's wood (2005,
/// Fig. 7b): the perturbation is his 4-octave turbulence evaluated from one 2D table, amount
/// 0.3. Lewis's refinements (a quasi-periodic `xtab`, a random monotonic remap of the radius
/// for years of slow and fast growth) are a colour map and a noise away.
///
/// With a noise that is a [`FilteredNoise`], the wood is one too (the noise anti-aliased; the
/// rings themselves are not). In fixed point the radius saturates beyond 32767 (then every
/// point is one place in a ring).
///
/// # Examples
///
/// ```
/// use bandnoise::{I16F16, Noise, texture::{Texture, Wood}};
///
/// let wood = Wood::new(2);
/// let t: f32 = wood.sample([0.7, -0.2, 3.0]);
/// assert!((0.0..1.0).contains(&t));
/// let olano = Wood::olano(2);
/// let q: I16F16 = olano.sample([I16F16::from_num(0.7), I16F16::from_num(-0.2)]);
/// assert!(q >= 0 && q < 1);
/// assert!(Wood::with_noise(Perlin::new(0), 0.0, 0.1).is_err());
/// # use bandnoise::lattice::Perlin;
/// let _rgb: [u8; 3] = wood.color_rgb8([0.7f32, -0.2, 3.0]);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Wood<N = Fractal<Perlin>> {
    noise: N,
    rings: Setting,
    amount: Setting,
    colors: ColorMap,
}

impl Wood<Fractal<Perlin>> {
    /// Lewis's wood over fBm of [`Perlin::new(seed)`](Perlin::new).
    #[must_use]
    pub fn new(seed: u32) -> Self {
        Self {
            noise: Fractal::fbm(Perlin::new(seed), Octaves::pbrt(4)),
            rings: Setting::new(2.0),
            amount: Setting::new(0.3),
            colors: ColorMap::WOOD,
        }
    }
}

impl Wood<MixedTurbulence<4>> {
    /// Olano's wood over [`MixedTurbulence::new(seed)`](MixedTurbulence::new).
    #[must_use]
    pub fn olano(seed: u32) -> Self {
        Self {
            noise: MixedTurbulence::new(seed),
            rings: Setting::new(2.0),
            amount: Setting::new(0.3),
            colors: ColorMap::WOOD,
        }
    }
}

impl<N> Wood<N> {
    /// The most rings per unit, and the largest amount's magnitude.
    pub const MAX_SETTING: f32 = 1024.0;

    /// Wood of `rings` rings per unit of radius, whose radius `noise` perturbs by
    /// `amount · η(p)`.
    ///
    /// # Errors
    ///
    /// [`Error::TextureSetting`] unless `2⁻¹⁶ ≤ rings ≤ 1024` and `|amount| ≤ 1024`.
    pub fn with_noise(noise: N, rings: f32, amount: f32) -> Result<Self, Error> {
        let m = Self::MAX_SETTING;
        Ok(Self {
            noise,
            rings: setting("rings", rings, 1.0 / 65536.0, m)?,
            amount: setting("amount", amount, -m, m)?,
            colors: ColorMap::WOOD,
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

    /// Rings per unit of radius.
    #[must_use]
    pub fn rings(&self) -> f32 {
        self.rings.value()
    }

    /// The perturbation's amount.
    #[must_use]
    pub fn amount(&self) -> f32 {
        self.amount.value()
    }

    /// The place in the ring at `p` whose noise is `n`.
    #[inline]
    fn ring<R: Real, const D: usize>(&self, p: [R; D], n: R) -> R {
        let r = if D > 1 {
            R::norm([p[0], p[1]])
        } else {
            p[0].abs()
        };
        let u = r.saturating_add(self.amount.get::<R>().saturating_mul(n));
        u.saturating_mul(self.rings.get()).split().1.canonical()
    }
}

impl<N: Noise<R, D>, R: Real, const D: usize> Noise<R, D> for Wood<N> {
    #[inline]
    fn sample(&self, p: [R; D]) -> R {
        self.ring(p, self.noise.sample(p))
    }

    fn amplitude_bound(&self) -> f32 {
        1.0
    }
}

impl<N: FilteredNoise<R, D>, R: Real, const D: usize> FilteredNoise<R, D> for Wood<N> {
    fn sample_filtered(&self, p: [R; D], dpdx: [R; D], dpdy: [R; D]) -> R {
        self.ring(p, self.noise.sample_filtered(p, dpdx, dpdy))
    }
}

impl<N: Noise<R, D>, R: Real, const D: usize> Texture<R, D> for Wood<N> {
    fn pattern(&self, p: [R; D]) -> R {
        self.sample(p)
    }

    fn color_map(&self) -> &ColorMap {
        &self.colors
    }
}

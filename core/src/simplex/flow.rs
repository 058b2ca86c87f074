//! Flow noise (Perlin and Neyret, "Flow Noise", SIGGRAPH 2001 technical sketch): 2D simplex
//! noise whose gradients rotate.
//!
//! Animating noise by moving through a third dimension makes it *roll*: features appear and
//! vanish. Perlin and Neyret instead turn every lattice gradient by the same angle over time:
//! the gradients stay uncorrelated with each other at every angle, so the noise keeps its
//! statistics while its features *swirl* in place, as in a flow. This needs gradients that
//! can turn by any angle, so the top 8 bits `h` of each corner's hash pick a direction
//! `h/256` of a turn (256 evenly spaced unit vectors, as Gustavson and McEwan's psrdnoise
//! picks an angle from its hash), and the animation adds `α`:
//! `g = (cos 2π(h/256 + α), sin 2π(h/256 + α))`, computed as the direction `h/256` (a table
//! of 256 cosines, built by `const fn`) turned by `α` (its cosine and sine taken once, when
//! the angle is set): four products per corner.
//!
//! The lattice, hash, kernel and analytic gradient are [`Simplex`](super::Simplex)'s in 2D;
//! with unit gradients of any direction the largest value is smaller than with Perlin's
//! (whose 2D gradients reach √2), so the scale is its own (below).

use super::{Gradients, simplex};
use crate::batch::LANES;
use crate::fractal::Octaves;
use crate::hash::prime::PrimeHash;
use crate::special::{cos_f64, q30};
use crate::{Error, I16F16, Real};

/// `cos 2π(h/256)` for `h` in `0..256`, Q2.30 (`sin 2π(h/256)` is entry `h − 64`).
static DIRECTIONS: [i32; 256] = {
    let mut t = [0i32; 256];
    let mut h = 0;
    while h < 256 {
        // cos_f64 takes a quarter turn: fold the others onto it.
        let (k, sign) = match h {
            0..=64 => (h, 1.0),
            65..=128 => (128 - h, -1.0),
            129..=192 => (h - 128, -1.0),
            _ => (256 - h, 1.0),
        };
        let c = sign * cos_f64(core::f64::consts::TAU * k as f64 / 256.0);
        t[h] = (c * (1u64 << 30) as f64 + if c < 0.0 { -0.5 } else { 0.5 }) as i32;
        h += 1;
    }
    t
};

/// The scale `⌊2¹⁶ / max⌋ · 2⁻¹⁶` that makes the largest value 1: `max = 0.161283` is the
/// largest `Σ (1 − 2|d|²)⁴ |d|` over the 2D simplex, the value when every corner's gradient
/// points along its offset (searched: `tests/tests/simplex.rs`).
const SCALE: i32 = 406_340;

/// Flow noise: 2D simplex noise with rotating gradients (module docs), continuous (C²) with
/// its analytic gradient, in every number type.
///
/// * **Angle**: the turn `α` added to every gradient's direction, in turns (1 is a full turn,
///   so `α` and `α + 1` give the same noise); set by [`with_angle`](Self::with_angle), 0 by
///   default. Animate by increasing it with time; Perlin and Neyret turn successive octaves of
///   a fractal sum at rates such as 1, 2, 4 (turbulence-like) or 1, 1, 1.
/// * **Seed**: [`Simplex`](super::Simplex)'s hash of the corners and the seed.
/// * **Range**: `|n| ≤ 1`: the scale sets the largest value over every choice of gradient
///   directions to 1 (module docs); [`Noise::amplitude_bound`] adds 2⁻¹⁰ for rounding and
///   the cosine table's error.
/// * **Directions**: the table's cosines are rounded to 2⁻³⁰ and `α`'s cosine and sine
///   ([`Real::cos_turns`], the same bits on every target) to the setting's precision (`f32`,
///   or 2⁻¹⁶ in fixed point), so the gradients are unit vectors within about 10⁻⁷ (`f32`) or
///   10⁻⁴ (fixed point).
/// * **Bad input**: as [`Simplex`](super::Simplex): a non-finite coordinate samples the
///   origin's cell.
///
/// ```
/// use bandnoise::{Noise, NoiseGradient, simplex::Flow};
///
/// let flow = Flow::new(3);
/// let later = flow.clone().with_angle(0.125).unwrap();
/// let (a, b): (f32, f32) = (flow.sample([0.3, 4.7]), later.sample([0.3, 4.7]));
/// assert!(a.abs() <= 1.001 && b.abs() <= 1.001 && a != b);
/// // A full turn is the same noise.
/// let (c, _): (f32, [f32; 2]) = flow.clone().with_angle(1.0).unwrap().sample_with_gradient([0.3, 4.7]);
/// assert_eq!(a, c);
/// ```
///
/// [`Noise::amplitude_bound`]: crate::Noise::amplitude_bound
#[derive(Clone, Debug, PartialEq)]
pub struct Flow {
    hash: PrimeHash,
    angle: f32,
    /// `cos 2πα` and `sin 2πα` as settings: `f32`, and rounded once to I16F16.
    turn: [(f32, I16F16); 2],
}

impl Flow {
    /// Flow noise for `seed`, at angle 0.
    #[must_use]
    pub const fn new(seed: u32) -> Self {
        Self {
            hash: PrimeHash::new(seed),
            angle: 0.0,
            turn: [(1.0, I16F16::ONE), (0.0, I16F16::ZERO)],
        }
    }

    /// The same noise with every gradient turned by `turns` (reduced to `[0, 1)`: only the
    /// fraction of a turn matters).
    ///
    /// # Errors
    ///
    /// [`Error::FlowAngle`] unless `turns` is finite.
    pub fn with_angle(mut self, turns: f32) -> Result<Self, Error> {
        if !turns.is_finite() {
            return Err(Error::FlowAngle(turns));
        }
        // The fraction of a turn: in [0, 1] (1 when a tiny negative rounds up, the same angle
        // as 0).
        let reduced = turns - libm::floorf(turns);
        self.angle = if reduced >= 1.0 { 0.0 } else { reduced };
        self.turn = turn_of(self.angle);
        Ok(self)
    }

    /// The angle, in turns, in `[0, 1)`.
    #[must_use]
    pub const fn angle(&self) -> f32 {
        self.angle
    }
}

impl Default for Flow {
    fn default() -> Self {
        Self::new(0)
    }
}

/// The direction `h/256` turned by the angle whose cosine and sine are `turn`.
#[inline(always)]
fn turned<R: Real>(h: u32, turn: &[(f32, I16F16); 2]) -> [R; 2] {
    let entry = |i: u32| q30::<R>(DIRECTIONS.get((i & 255) as usize).copied().unwrap_or(0));
    let (c, s) = (entry(h), entry(h.wrapping_sub(64)));
    let [ca, sa] = turn.map(|(f, q)| R::from_setting(f, q));
    // (c, s) turned by α; every factor within ±1, so the products fit every type.
    [
        c.mul_fraction(ca) - s.mul_fraction(sa),
        s.mul_fraction(ca) + c.mul_fraction(sa),
    ]
}

/// The cosine and sine of `turns` (in `[0, 1)`) as settings.
fn turn_of(turns: f32) -> [(f32, I16F16); 2] {
    let (cos, sin) = (turns.cos_turns(), (turns - 0.25).cos_turns());
    [cos, sin].map(|v| (v, I16F16::from_f32(v)))
}

/// Gradients turned by one angle (`turn`: its cosine and sine).
struct Turned<'a> {
    turn: &'a [(f32, I16F16); 2],
}

impl<R: Real> Gradients<R, 2> for Turned<'_> {
    #[inline(always)]
    fn gradient(&self, h: u32) -> [R; 2] {
        // The direction from the hash's top 8 bits.
        turned(h >> 24, self.turn)
    }
    #[inline(always)]
    fn times(d: R, g: R) -> R {
        // |g| ≤ 1 and |d| < 2: the product fits every type.
        d.mul_fraction(g)
    }
}

impl Flow {
    /// The simplex body at `N` points with this noise's hash and the gradients turned by
    /// `turn` (its own angle's, or a [`FlowSum`] octave's).
    #[inline(always)]
    fn body<R: Real, const N: usize, const GRADIENT: bool>(
        &self,
        turn: &[(f32, I16F16); 2],
        p: &[[R; N]; 2],
        value: &mut [R; N],
        gradient: &mut [[R; N]; 2],
    ) {
        let gradients = Turned { turn };
        simplex::<R, _, 2, N, GRADIENT>(&self.hash, &gradients, SCALE, p, value, gradient);
    }
}

impl<R: Real> crate::Noise<R, 2> for Flow {
    #[inline]
    fn sample(&self, p: [R; 2]) -> R {
        let (mut value, mut gradient) = ([R::ZERO], [[R::ZERO]; 2]);
        self.body::<R, 1, false>(&self.turn, &p.map(|x| [x]), &mut value, &mut gradient);
        value[0]
    }
    fn amplitude_bound(&self) -> f32 {
        1.0 + crate::lattice::ROUNDING
    }
    fn sample_lanes(&self, p: &[[R; LANES]; 2], out: &mut [R; LANES]) {
        let mut gradient = [[R::ZERO; LANES]; 2];
        self.body::<R, LANES, false>(&self.turn, p, out, &mut gradient);
    }
}

impl<R: Real> crate::NoiseGradient<R, 2> for Flow {
    #[inline]
    fn sample_with_gradient(&self, p: [R; 2]) -> (R, [R; 2]) {
        let (mut value, mut gradient) = ([R::ZERO], [[R::ZERO]; 2]);
        self.body::<R, 1, true>(&self.turn, &p.map(|x| [x]), &mut value, &mut gradient);
        (value[0], gradient.map(|g| g[0]))
    }
}

crate::noise::inherent_amplitude_bound!(Flow, []);

/// Perlin and Neyret's flow fBm: a fractal sum of [`Flow`] octaves whose gradients turn at
/// rates that grow (or shrink) from octave to octave, each octave's point *advected* by the
/// octaves before it ("pseudo-advection").
///
/// Octave `i` samples `Flow` at `fᵢ·p − advection · Σ_{j<i} aⱼ ∇nⱼ`, turned by `α · spinⁱ`, with
/// `fᵢ`, `aᵢ` the octaves' frequencies and amplitudes: the gradient of the sum so far pushes the
/// finer octaves downhill, so small features ride on large ones as in a flow (Perlin and Neyret:
/// "displacing value up is like shifting domain downhill"). The sum is `Σ aᵢ nᵢ`.
///
/// * **Spin**: how the turning rate changes per octave; Neyret's progressions are 2 (rates 1, 2,
///   4: turbulence), 1 (all alike) and ½ (1, ½, ¼: foam on waves). Default 2; `0 ≤ spin ≤ 16`.
/// * **Advection**: 0 (default: a plain fractal sum of turning octaves) to about 1 (strongly
///   advected; the psrdnoise examples use 0.13); `|advection| ≤ 16`.
/// * **Range**: `Σ |gain|ⁱ` times [`Flow`]'s bound.
/// * **Bad input**: as [`Flow`]; fixed point saturates the displaced coordinates.
///
/// ```
/// use bandnoise::{Noise, fractal::Octaves, simplex::{Flow, FlowSum}};
///
/// let flow = Flow::new(2).with_angle(0.1).unwrap();
/// let sum = FlowSum::new(flow, Octaves::new(5, 2.0, 0.5).unwrap())
///     .with_advection(0.5)
///     .unwrap();
/// let v: f32 = sum.sample([0.3, 4.7]);
/// assert!(v.abs() <= sum.amplitude_bound::<2>());
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct FlowSum {
    flow: Flow,
    octaves: Octaves,
    spin: f32,
    advection: (f32, I16F16),
    /// Each octave's turn, `α · spinⁱ`.
    turns: [[(f32, I16F16); 2]; Octaves::MAX as usize],
}

impl FlowSum {
    /// The largest spin and the largest advection's magnitude.
    pub const MAX_SETTING: f32 = 16.0;

    /// The flow fBm of `flow` (its seed and angle) with `octaves`, spin 2, no advection.
    #[must_use]
    pub fn new(flow: Flow, octaves: Octaves) -> Self {
        let mut sum = Self {
            flow,
            octaves,
            spin: 2.0,
            advection: (0.0, I16F16::ZERO),
            turns: [[(1.0, I16F16::ONE), (0.0, I16F16::ZERO)]; Octaves::MAX as usize],
        };
        sum.turn_octaves();
        sum
    }

    /// The same sum with octave `i` turned by `α · spinⁱ`.
    ///
    /// # Errors
    ///
    /// [`Error::FlowSetting`] unless `0 ≤ spin ≤ 16`.
    pub fn with_spin(mut self, spin: f32) -> Result<Self, Error> {
        if !(0.0..=Self::MAX_SETTING).contains(&spin) {
            return Err(Error::FlowSetting(spin));
        }
        self.spin = spin;
        self.turn_octaves();
        Ok(self)
    }

    /// The same sum with `advection`.
    ///
    /// # Errors
    ///
    /// [`Error::FlowSetting`] unless `|advection| ≤ 16`.
    pub fn with_advection(mut self, advection: f32) -> Result<Self, Error> {
        if !(-Self::MAX_SETTING..=Self::MAX_SETTING).contains(&advection) {
            return Err(Error::FlowSetting(advection));
        }
        self.advection = (advection, I16F16::from_f32(advection));
        Ok(self)
    }

    /// The same sum with the gradients turned by `turns` ([`Flow::with_angle`]).
    ///
    /// # Errors
    ///
    /// [`Error::FlowAngle`] unless `turns` is finite.
    pub fn with_angle(mut self, turns: f32) -> Result<Self, Error> {
        self.flow = self.flow.with_angle(turns)?;
        self.turn_octaves();
        Ok(self)
    }

    /// The octaves' angles `α · spinⁱ`, reduced to a fraction of a turn in `f64` (exact for
    /// spins that are powers of two) and rounded once to `f32`.
    fn turn_octaves(&mut self) {
        let alpha = f64::from(self.flow.angle);
        let mut rate = 1.0f64;
        for turn in &mut self.turns {
            let a = alpha * rate;
            let reduced = (a - libm::floor(a)) as f32;
            *turn = turn_of(if reduced >= 1.0 { 0.0 } else { reduced });
            rate *= f64::from(self.spin);
        }
    }

    /// The noise summed.
    #[must_use]
    pub const fn flow(&self) -> &Flow {
        &self.flow
    }

    /// The octave settings.
    #[must_use]
    pub const fn octaves(&self) -> &Octaves {
        &self.octaves
    }

    /// The spin.
    #[must_use]
    pub const fn spin(&self) -> f32 {
        self.spin
    }

    /// The advection.
    #[must_use]
    pub const fn advection(&self) -> f32 {
        self.advection.0
    }
}

impl<R: Real> crate::Noise<R, 2> for FlowSum {
    fn sample(&self, p: [R; 2]) -> R {
        let setting = |f: f32| R::from_setting(f, I16F16::from_f32(f));
        let (lacunarity, gain) = (
            setting(self.octaves.lacunarity()),
            setting(self.octaves.gain()),
        );
        let advection = R::from_setting(self.advection.0, self.advection.1);
        let (mut sum, mut slope) = (R::ZERO, [R::ZERO; 2]);
        let (mut frequency, mut amplitude) = (R::ONE, R::ONE);
        let count = self.octaves.count() as usize;
        for turn in self.turns.iter().take(count) {
            let q = core::array::from_fn(|a| {
                let x = p[a].wrapping_mul(frequency);
                x.saturating_add(-advection.saturating_mul(slope[a]))
            });
            let (mut value, mut gradient) = ([R::ZERO], [[R::ZERO]; 2]);
            let q = q.map(|x: R| [x]);
            self.flow
                .body::<R, 1, true>(turn, &q, &mut value, &mut gradient);
            sum = sum.saturating_add(amplitude.saturating_mul(value[0]));
            for (s, g) in slope.iter_mut().zip(gradient) {
                *s = s.saturating_add(amplitude.saturating_mul(g[0]));
            }
            frequency = frequency.saturating_mul(lacunarity);
            amplitude = amplitude.saturating_mul(gain);
        }
        sum.canonical()
    }

    /// [`Fractal`](crate::fractal::Fractal)'s bound for an fBm of [`Flow`] with these
    /// octaves: advection moves points, never values.
    fn amplitude_bound(&self) -> f32 {
        let fbm = crate::fractal::Fractal::fbm(&self.flow, self.octaves);
        crate::Noise::<R, 2>::amplitude_bound(&fbm)
    }
}

crate::noise::inherent_amplitude_bound!(FlowSum, []);

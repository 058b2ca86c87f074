//! Flow noise (Perlin and Neyret, "Flow Noise", SIGGRAPH 2001 technical sketch): 2D simplex
//! noise whose gradients rotate.
//!
//! Animating noise by moving through a third dimension makes it *roll*: features appear and
//! vanish. Perlin and Neyret instead turn every lattice gradient by the same angle over time:
//! the gradients stay uncorrelated with each other at every angle, so the noise keeps its
//! statistics while its features *swirl* in place, as in a flow. This needs gradients that
//! can turn by any angle, so each corner's hash picks a direction `h/256` of a turn (256
//! evenly spaced unit vectors, as Gustavson and McEwan's psrdnoise picks an angle from its
//! hash), and the animation adds `α`: `g = (cos 2π(h/256 + α), sin 2π(h/256 + α))`.
//!
//! The lattice, hash, kernel and analytic gradient are [`Simplex`](super::Simplex)'s in 2D;
//! with unit gradients of any direction the largest value is smaller than with Perlin's
//! (whose 2D gradients reach √2), so the scale is its own (below).

use super::{Gradients, simplex};
use crate::batch::LANES;
use crate::lattice::Perlin;
use crate::{Error, I16F16, Real};

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
/// * **Seed**: [`Simplex`](super::Simplex)'s (Perlin's permutation for the seed).
/// * **Range**: `|n| ≤ 1`: the scale sets the largest value over every choice of gradient
///   directions to 1 (module docs); [`Noise::amplitude_bound`] adds 2⁻¹⁰ for rounding and
///   the cosine table's error.
/// * **Directions** come from [`Real::cos_turns`] (a table with cubic Hermite steps, the same
///   bits on every target), so they are unit vectors within about 10⁻⁶.
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
    perlin: Perlin,
    angle: f32,
    angle_fixed: I16F16,
}

impl Flow {
    /// Flow noise for `seed`, at angle 0.
    #[must_use]
    pub const fn new(seed: u32) -> Self {
        Self {
            perlin: Perlin::new(seed),
            angle: 0.0,
            angle_fixed: I16F16::ZERO,
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
        self.angle_fixed = I16F16::from_f32(self.angle);
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

impl<R: Real> Gradients<R, 2> for Flow {
    #[inline(always)]
    fn gradient(&self, h: u32) -> [R; 2] {
        // h/256 + α < 2: the cosine reduces it to a fraction of a turn.
        let turn =
            R::from_ratio((h & 255) as i32, 8) + R::from_setting(self.angle, self.angle_fixed);
        let quarter = R::from_ratio(1, 2);
        [turn.cos_turns(), (turn - quarter).cos_turns()]
    }
    #[inline(always)]
    fn times(d: R, g: R) -> R {
        // |g| ≤ 1 and |d| < 2: the product fits every type.
        d.mul_fraction(g)
    }
}

impl<R: Real> crate::Noise<R, 2> for Flow {
    #[inline]
    fn sample(&self, p: [R; 2]) -> R {
        let (mut value, mut gradient) = ([R::ZERO], [[R::ZERO]; 2]);
        let p = p.map(|x| [x]);
        simplex::<R, _, 2, 1, false>(
            self.perlin.chain(),
            self,
            SCALE,
            &p,
            &mut value,
            &mut gradient,
        );
        value[0]
    }
    fn amplitude_bound(&self) -> f32 {
        1.0 + crate::lattice::ROUNDING
    }
    fn sample_lanes(&self, p: &[[R; LANES]; 2], out: &mut [R; LANES]) {
        let mut gradient = [[R::ZERO; LANES]; 2];
        simplex::<R, _, 2, LANES, false>(self.perlin.chain(), self, SCALE, p, out, &mut gradient);
    }
}

impl<R: Real> crate::NoiseGradient<R, 2> for Flow {
    #[inline]
    fn sample_with_gradient(&self, p: [R; 2]) -> (R, [R; 2]) {
        let (mut value, mut gradient) = ([R::ZERO], [[R::ZERO]; 2]);
        let p = p.map(|x| [x]);
        simplex::<R, _, 2, 1, true>(
            self.perlin.chain(),
            self,
            SCALE,
            &p,
            &mut value,
            &mut gradient,
        );
        (value[0], gradient.map(|g| g[0]))
    }
}

crate::noise::inherent_amplitude_bound!(Flow, []);

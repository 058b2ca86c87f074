//! Colour maps: a texture's pattern, a fraction in `[0, 1]`, to a colour.

use crate::{Error, Real};

/// How a [`ColorMap`] goes from one colour to the next.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Interpolation {
    /// Straight lines between evenly spaced colours: `n` colours, the first at 0, the last
    /// at 1.
    Linear,
    /// A uniform cubic B-spline with the colours as control points (`n − 3` segments over
    /// `[0, 1]`): smooth (twice continuously differentiable) and within the colours' convex
    /// hull, but it passes through none of them.
    ///
    /// pbrt's marble evaluates the same windows of four colours as Bézier segments (de
    /// Casteljau), which jumps where one window gives way to the next (its end is colour
    /// `k + 3`, the next window starts at colour `k + 1`), and reads past its table at
    /// `t = 1`; the B-spline over the same colours has neither fault.
    BSpline,
}

/// A colour: red, green and blue in `[0, 1)` as multiples of 2⁻¹⁶ (see [`rgb`]).
pub type Rgb16 = [u16; 3];

/// A colour given as fractions (`rgb(0.58, 0.58, 0.6)`), rounded to 2⁻¹⁶ and kept below 1
/// (1.0 becomes `65535 / 65536`), so a map's colours are exact in `f32`, `f64` and I16F16.
/// Not finite or negative components are 0.
///
/// ```
/// use bandnoise::texture::rgb;
///
/// assert_eq!(rgb(0.5, 1.0, 0.0), [32768, 65535, 0]);
/// ```
#[must_use]
pub const fn rgb(r: f32, g: f32, b: f32) -> Rgb16 {
    [unit(r), unit(g), unit(b)]
}

/// `v` rounded to 2⁻¹⁶, in `[0, 65535]` (NaN is 0: `as` saturates and maps NaN to 0).
const fn unit(v: f32) -> u16 {
    let scaled = v * 65536.0 + 0.5;
    if scaled >= 65535.0 {
        65535
    } else {
        scaled as u16
    }
}

/// A colour map: evenly spaced colours and how to go between them.
///
/// [`map`](Self::map) takes a fraction `t` (a texture's pattern) to a colour in the number
/// type of `t`, with the same operations in every type; a `t` outside `[0, 1]` is clamped to
/// it and a non-finite `t` is 0.
///
/// # Examples
///
/// ```
/// use bandnoise::texture::{ColorMap, Interpolation, rgb};
///
/// static STOPS: [[u16; 3]; 2] = [rgb(0.0, 0.0, 0.0), rgb(1.0, 0.5, 0.0)];
/// let map = ColorMap::new(&STOPS, Interpolation::Linear)?;
/// assert_eq!(map.map(0.5f32), [0.49999237, 0.25, 0.0]);
/// assert_eq!(map.map_rgb8(1.0f32), [255, 128, 0]);
/// assert_eq!(map.map(f32::NAN), [0.0; 3]);
/// # Ok::<(), bandnoise::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ColorMap {
    colors: &'static [Rgb16],
    interpolation: Interpolation,
}

impl ColorMap {
    /// The most colours a map takes (so that `t · (n − 1)` stays exact in fixed point).
    pub const MAX_COLORS: usize = 1024;

    /// A map through `colors`.
    ///
    /// # Errors
    ///
    /// [`Error::ColorCount`] for fewer than 2 colours ([`Interpolation::Linear`]) or 4
    /// ([`Interpolation::BSpline`]), or more than [`MAX_COLORS`](Self::MAX_COLORS).
    pub const fn new(
        colors: &'static [Rgb16],
        interpolation: Interpolation,
    ) -> Result<Self, Error> {
        let min = match interpolation {
            Interpolation::Linear => 2,
            Interpolation::BSpline => 4,
        };
        if colors.len() < min || colors.len() > Self::MAX_COLORS {
            return Err(Error::ColorCount {
                count: colors.len(),
                min,
                max: Self::MAX_COLORS,
            });
        }
        Ok(Self {
            colors,
            interpolation,
        })
    }

    /// A map whose colours and interpolation are known to be valid (the maps of this crate).
    const fn known(colors: &'static [Rgb16], interpolation: Interpolation) -> Self {
        Self {
            colors,
            interpolation,
        }
    }

    /// Black to white.
    pub const GREY: Self = Self::known(&GREY, Interpolation::Linear);
    /// pbrt's marble (§10.6.6): its nine colours, times its 1.5, as a B-spline.
    pub const MARBLE: Self = Self::known(&MARBLE, Interpolation::BSpline);
    /// A wood ring from pale early wood to dark late wood (Lewis's `xtab`): the pattern's wrap
    /// from 1 to 0 is the sharp border where a year's late wood meets the next year's early
    /// wood.
    pub const WOOD: Self = Self::known(&WOOD, Interpolation::Linear);
    /// Deep water to foam, for the windy waves' heights.
    pub const WATER: Self = Self::known(&WATER, Interpolation::Linear);
    /// Polka dots: a cream background (0) and red dots (1).
    pub const DOTS: Self = Self::known(&DOTS, Interpolation::Linear);

    /// The colours.
    #[must_use]
    pub const fn colors(&self) -> &'static [Rgb16] {
        self.colors
    }

    /// The interpolation.
    #[must_use]
    pub const fn interpolation(&self) -> Interpolation {
        self.interpolation
    }

    /// The colour at `t` (clamped to `[0, 1]`; a non-finite `t` is 0): each component in
    /// `[0, 1]`.
    #[must_use]
    pub fn map<R: Real>(&self, t: R) -> [R; 3] {
        let t = t.finite_or_zero().clamp_to(R::ZERO, R::ONE);
        // `segment` keeps every index below the length; `get` says so without a panic path.
        let c = |k: usize, a: usize| {
            R::from_ratio(self.colors.get(k).map_or(0, |c| i32::from(c[a])), 16)
        };
        match self.interpolation {
            Interpolation::Linear => {
                let (k, f) = segment(t, self.colors.len() - 1);
                core::array::from_fn(|a| c(k, a) + f.mul_fraction(c(k + 1, a) - c(k, a)))
            }
            Interpolation::BSpline => {
                let (k, f) = segment(t, self.colors.len() - 3);
                let w = bspline_weights(f);
                core::array::from_fn(|a| {
                    (0..4).fold(R::ZERO, |sum, j| sum + w[j].mul_fraction(c(k + j, a)))
                })
            }
        }
    }

    /// The colour at `t` as 8-bit components (each rounded to nearest from `255 · c`).
    #[must_use]
    pub fn map_rgb8<R: Real>(&self, t: R) -> [u8; 3] {
        // The component is in [0, 1]: the product is in [0, 255.5], and `as` saturates.
        self.map(t).map(|c| (c.to_f32() * 255.0 + 0.5) as u8)
    }
}

/// The segment of `t ∈ [0, 1]` among `n ≥ 1` equal ones, and the fraction within it (`t = 1`
/// is the end of the last segment).
#[inline]
fn segment<R: Real>(t: R, n: usize) -> (usize, R) {
    // n ≤ 1023 and t ≤ 1: the product is exact in fixed point and within range.
    let (k, f) = t.saturating_mul(R::from_i32(n as i32)).split();
    let k = k.max(0) as usize;
    if k >= n { (n - 1, R::ONE) } else { (k, f) }
}

/// The uniform cubic B-spline's four weights at `f ∈ [0, 1]`: `(1 − f)³/6`,
/// `(3f³ − 6f² + 4)/6`, `(−3f³ + 3f² + 3f + 1)/6` and `f³/6`, the third as 1 minus the others
/// so that they sum to 1 exactly.
#[inline]
fn bspline_weights<R: Real>(f: R) -> [R; 4] {
    let sixth = R::from_setting(1.0 / 6.0, fixed::types::I16F16::from_bits(10923));
    let g = R::ONE - f;
    let f2 = f.mul_fraction(f);
    let f3 = f2.mul_fraction(f);
    let w0 = g.mul_fraction(g).mul_fraction(g).mul_fraction(sixth);
    let w3 = f3.mul_fraction(sixth);
    // 3f³ − 6f² + 4 = 4 − 3f²(2 − f), and f²(2 − f) rises from 0 to 1 on [0, 1]: the
    // numerator is in [1, 4], every product within range.
    let two_minus = R::ONE + g;
    let w1 = (R::from_i32(4) - R::from_i32(3).mul_rn(f2.mul_rn(two_minus))).mul_rn(sixth);
    let w2 = R::ONE - w0 - w1 - w3;
    [w0, w1, w2, w3]
}

static GREY: [Rgb16; 2] = [rgb(0.0, 0.0, 0.0), rgb(1.0, 1.0, 1.0)];

static MARBLE: [Rgb16; 9] = {
    // pbrt's colours, times the 1.5 it applies to the spline's result.
    const fn x(r: f32, g: f32, b: f32) -> Rgb16 {
        rgb(1.5 * r, 1.5 * g, 1.5 * b)
    }
    [
        x(0.58, 0.58, 0.6),
        x(0.58, 0.58, 0.6),
        x(0.58, 0.58, 0.6),
        x(0.5, 0.5, 0.5),
        x(0.6, 0.59, 0.58),
        x(0.58, 0.58, 0.6),
        x(0.58, 0.58, 0.6),
        x(0.2, 0.2, 0.33),
        x(0.58, 0.58, 0.6),
    ]
};

static WOOD: [Rgb16; 5] = [
    rgb(0.87, 0.69, 0.45),
    rgb(0.84, 0.65, 0.41),
    rgb(0.78, 0.57, 0.34),
    rgb(0.62, 0.41, 0.21),
    rgb(0.45, 0.27, 0.12),
];

static WATER: [Rgb16; 4] = [
    rgb(0.02, 0.10, 0.25),
    rgb(0.05, 0.30, 0.50),
    rgb(0.35, 0.62, 0.75),
    rgb(0.92, 0.96, 0.98),
];

static DOTS: [Rgb16; 2] = [rgb(0.96, 0.92, 0.82), rgb(0.80, 0.12, 0.15)];

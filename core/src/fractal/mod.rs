//! Fractal sums of octaves over any noise (pbrt §10.6.3; Perlin 1985; Musgrave's ridged
//! multifractal in Ebert et al., *Texturing and Modeling*).
//!
//! `Σ_i gain^i · shape(noise(lacunarity^i · p))`, where the shape is the noise itself (fBm), its
//! absolute value (turbulence) or a ridge `(1 − |n|)²` weighted by the previous octave (ridged).
//! [`Fractal::sample_filtered`] is pbrt's anti-aliased form: it takes the sample's footprint and
//! drops the octaves above the Nyquist limit.

mod footprint;

use crate::batch::LANES;
use crate::{Error, FilteredNoise, I16F16, Noise, NoiseGradient, Real};
pub(crate) use footprint::footprint_len2;

use footprint::octaves_for;

/// A validated setting: its `f32` value, and that value rounded once to I16F16.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Setting {
    f: f32,
    q: I16F16,
}

impl Setting {
    pub(crate) fn new(f: f32) -> Self {
        Self {
            f,
            q: I16F16::from_f32(f),
        }
    }

    /// The larger magnitude of the setting and its rounding.
    fn largest(self) -> f32 {
        self.f.abs().max(self.q.to_f32().abs())
    }

    /// The setting as given.
    pub(crate) fn value(self) -> f32 {
        self.f
    }

    /// The setting in the number type `R`.
    #[inline]
    pub(crate) fn get<R: Real>(self) -> R {
        R::from_setting(self.f, self.q)
    }
}

/// The octave settings shared by every fractal sum.
///
/// Defaults: 6 octaves, lacunarity 1.99 and gain 0.5 (pbrt's; a lacunarity just under 2 keeps
/// the zeros of successive octaves from lining up on the lattice).
///
/// Settings are numbers, not of a number type: a sum samples in `f32`, `f64` or I16F16 as its
/// noise does, with the settings exact in floats and rounded to 2⁻¹⁶ in fixed point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Octaves {
    count: u32,
    lacunarity: Setting,
    gain: Setting,
}

impl Octaves {
    /// The most octaves a sum may have (beyond ~24 octaves f32 frequencies pass 2²⁴ and every
    /// sample lands on a lattice point anyway).
    pub const MAX: u32 = 30;

    /// Validated octave settings.
    ///
    /// # Errors
    ///
    /// [`Error::OctaveCount`] unless `1 ≤ count ≤ 30`; [`Error::Lacunarity`] unless
    /// `0 < lacunarity ≤ 16`; [`Error::Gain`] unless `-1 ≤ gain ≤ 1` (all finite). These limits
    /// keep every sum finite and bounded: `|sum| ≤ Σ |gain|^i · bound`.
    ///
    /// # Examples
    ///
    /// ```
    /// use bandnoise::{Error, fractal::Octaves};
    ///
    /// let o = Octaves::new(8, 2.0, 0.5).unwrap();
    /// assert_eq!(o.count(), 8);
    /// assert_eq!(Octaves::new(0, 2.0, 0.5), Err(Error::OctaveCount { count: 0, max: 30 }));
    /// assert!(Octaves::new(4, f32::NAN, 0.5).is_err());
    /// ```
    pub fn new(count: u32, lacunarity: f32, gain: f32) -> Result<Self, Error> {
        if count == 0 || count > Self::MAX {
            return Err(Error::OctaveCount {
                count,
                max: Self::MAX,
            });
        }
        if !(lacunarity > 0.0 && lacunarity <= 16.0) {
            return Err(Error::Lacunarity(lacunarity));
        }
        if !(-1.0..=1.0).contains(&gain) {
            return Err(Error::Gain(gain));
        }
        Ok(Self {
            count,
            lacunarity: Setting::new(lacunarity),
            gain: Setting::new(gain),
        })
    }

    /// The number of octaves.
    #[must_use]
    pub fn count(&self) -> u32 {
        self.count
    }

    /// The frequency ratio between octaves.
    #[must_use]
    pub fn lacunarity(&self) -> f32 {
        self.lacunarity.f
    }

    /// The amplitude ratio between octaves.
    #[must_use]
    pub fn gain(&self) -> f32 {
        self.gain.f
    }
}

impl Default for Octaves {
    fn default() -> Self {
        Self::pbrt(6)
    }
}

impl Octaves {
    /// pbrt's octaves (lacunarity 1.99, gain 0.5), `count` of them: `1 ≤ count ≤ 30` is the
    /// caller's to keep (the textures' fixed counts).
    pub(crate) fn pbrt(count: u32) -> Self {
        Self {
            count,
            lacunarity: Setting::new(1.99),
            gain: Setting::new(0.5),
        }
    }
}

/// How each octave's noise value enters the sum.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// Fractional Brownian motion: `Σ gain^i n_i`.
    Fbm,
    /// Perlin's turbulence: `Σ gain^i |n_i|`.
    Turbulence,
    /// Ridged multifractal: `r_i = (1 − |n_i|)² · w_i`, `Σ gain^i r_i`, with the weight
    /// `w_0 = 1`, `w_{i+1} = clamp(2 r_i, 0, 1)` so ridges carry detail and valleys stay smooth.
    Ridged,
}

/// A fractal sum of octaves of a noise `N`, itself a [`Noise`].
///
/// `N` may be any noise that keeps the [`Noise`] contract, a user's included: in fixed point
/// every sum, product and ridge square saturates, so a noise beyond the crate's ranges (whose
/// ridge term `(1 − |n|)²` leaves I16F16's range for `|n| > 182`) gives saturated values, never
/// wrapped ones.
///
/// # Examples
///
/// ```
/// use bandnoise::{FilteredNoise, Noise, fractal::{Fractal, Octaves}, lattice::Perlin};
///
/// let fbm = Fractal::fbm(Perlin::new(0), Octaves::default());
/// let v: f32 = fbm.sample([0.3, 0.7, 0.1]);
/// assert!(v.abs() <= Noise::<f32, 3>::amplitude_bound(&fbm));
///
/// // pbrt's anti-aliased form: a footprint of 1/16 keeps n = −1 + 4 = 3 octaves.
/// let far: f32 = fbm.sample_filtered([0.3, 0.7, 0.1], [0.0625, 0.0, 0.0], [0.0, 0.0625, 0.0]);
/// let three = Fractal::fbm(Perlin::new(0), Octaves::new(3, 1.99, 0.5).unwrap());
/// assert_eq!(far, three.sample([0.3, 0.7, 0.1]));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fractal<N> {
    noise: N,
    octaves: Octaves,
    kind: Kind,
    clamped_mean: Setting,
}

impl<N> Fractal<N> {
    /// A fractal sum of `kind`.
    #[must_use]
    pub fn new(noise: N, octaves: Octaves, kind: Kind) -> Self {
        Self {
            noise,
            octaves,
            kind,
            clamped_mean: Setting::new(0.2),
        }
    }

    /// Fractional Brownian motion.
    #[must_use]
    pub fn fbm(noise: N, octaves: Octaves) -> Self {
        Self::new(noise, octaves, Kind::Fbm)
    }

    /// Turbulence.
    #[must_use]
    pub fn turbulence(noise: N, octaves: Octaves) -> Self {
        Self::new(noise, octaves, Kind::Turbulence)
    }

    /// Ridged multifractal.
    #[must_use]
    pub fn ridged(noise: N, octaves: Octaves) -> Self {
        Self::new(noise, octaves, Kind::Ridged)
    }

    /// Sets the value [`sample_filtered`](Self::sample_filtered) adds for each clamped
    /// turbulence octave: the mean of `|noise|`, 0.2 by default (pbrt's figure for its Perlin
    /// noise; other noises have other means).
    ///
    /// # Errors
    ///
    /// [`Error::ClampedMean`] unless `0 ≤ mean ≤ 4`.
    pub fn with_clamped_mean(mut self, mean: f32) -> Result<Self, Error> {
        if !(0.0..=4.0).contains(&mean) {
            return Err(Error::ClampedMean(mean));
        }
        self.clamped_mean = Setting::new(mean);
        Ok(self)
    }

    /// The octave settings.
    #[must_use]
    pub fn octaves(&self) -> &Octaves {
        &self.octaves
    }

    /// The kind of sum.
    #[must_use]
    pub fn kind(&self) -> Kind {
        self.kind
    }

    /// The noise summed.
    #[must_use]
    pub fn noise(&self) -> &N {
        &self.noise
    }

    /// A sum of `noise` with these (validated) settings.
    pub(crate) fn with_noise<M>(&self, noise: M) -> Fractal<M> {
        Fractal {
            noise,
            octaves: self.octaves,
            kind: self.kind,
            clamped_mean: self.clamped_mean,
        }
    }

    /// Sums `full` octaves, then octave `full` with weight `partial` (if `full < count`), then
    /// adds the clamped-octave mean for the octaves after it (turbulence only; `add_clamped`).
    fn sum<R: Real, const D: usize>(&self, p: [R; D], full: u32, partial: R, add_clamped: bool) -> R
    where
        N: Noise<R, D>,
    {
        let p = p.map(|x| [x]);
        let [v] = self.sum_lanes(&p, full, partial, add_clamped, |q, n| {
            n[0] = self.noise.sample(q.map(|[x]| x));
        });
        v
    }

    /// [`sum`](Self::sum) over `L` points at once (structure of arrays), with `eval` sampling
    /// the noise at `L` points. The point path is this with `L = 1`, so the batch path is
    /// bit-identical to it by construction. Each step runs over all lanes, with the branch on
    /// the kind outside the lane loops.
    fn sum_lanes<R: Real, const L: usize, const D: usize>(
        &self,
        p: &[[R; L]; D],
        full: u32,
        partial: R,
        add_clamped: bool,
        mut eval: impl FnMut(&[[R; L]; D], &mut [R; L]),
    ) -> [R; L] {
        let lacunarity: R = self.octaves.lacunarity.get();
        let gain: R = self.octaves.gain.get();
        let clamped_mean: R = self.clamped_mean.get();
        let mut sum = [R::ZERO; L];
        let mut frequency = R::ONE;
        let mut amplitude = R::ONE;
        let mut weight = [R::ONE; L];
        let mut term = [R::ZERO; L];
        let last = if full < self.octaves.count {
            full + 1
        } else {
            full
        };
        for i in 0..last {
            // Wrapping in fixed point keeps the coordinate on the lattice; see Real::wrapping_mul.
            let q = p.map(|axis| axis.map(|x| x.wrapping_mul(frequency)));
            eval(&q, &mut term);
            match self.kind {
                Kind::Fbm => {}
                Kind::Turbulence => term = term.map(R::abs),
                Kind::Ridged => {
                    for (t, w) in term.iter_mut().zip(weight.iter_mut()) {
                        // Saturating: a user's noise beyond ±182 would overflow the square
                        // in fixed point (the crate's noises stay within ±2).
                        let r = R::ONE - t.abs();
                        let r = r.saturating_mul(r).saturating_mul(*w);
                        *w = r.saturating_add(r).clamp_to(R::ZERO, R::ONE);
                        *t = r;
                    }
                }
            }
            if i == full {
                term = match self.kind {
                    // pbrt: Lerp(smoothstep, 0.2, |n|) = 0.2 + w·(|n| − 0.2).
                    Kind::Turbulence if add_clamped => {
                        term.map(|t| clamped_mean + partial * (t - clamped_mean))
                    }
                    _ => term.map(|t| partial * t),
                };
            }
            for (s, t) in sum.iter_mut().zip(term) {
                *s = s.saturating_add(amplitude.saturating_mul(t));
            }
            frequency = frequency.saturating_mul(lacunarity);
            amplitude = amplitude.saturating_mul(gain);
        }
        if add_clamped && self.kind == Kind::Turbulence {
            for _ in last..self.octaves.count {
                let mean = amplitude.saturating_mul(clamped_mean);
                sum = sum.map(|s| s.saturating_add(mean));
                amplitude = amplitude.saturating_mul(gain);
            }
        }
        sum.map(R::canonical)
    }
}

/// The gradient by the chain rule, octave by octave: octave `i` samples the noise at
/// `fᵢ·p`, so its gradient is the noise's times `fᵢ`. Turbulence's `|n|` takes `sign(n)·∇n`
/// (`+∇n` where `n = 0`, a kink); a ridged term `r = (1 − |n|)²·w` takes
/// `−2(1 − |n|)·sign(n)·∇n·w + (1 − |n|)²·∇w`, with `∇w = 2∇r_prev` where the weight is not
/// clamped (0 where it is). The value is the same sequence of operations as
/// [`sample`](Noise::sample), so it is equal bit for bit.
impl<N: NoiseGradient<R, D>, R: Real, const D: usize> NoiseGradient<R, D> for Fractal<N> {
    fn sample_with_gradient(&self, p: [R; D]) -> (R, [R; D]) {
        let lacunarity: R = self.octaves.lacunarity.get();
        let gain: R = self.octaves.gain.get();
        let (mut sum, mut grad) = (R::ZERO, [R::ZERO; D]);
        let (mut frequency, mut amplitude) = (R::ONE, R::ONE);
        let (mut weight, mut dweight) = (R::ONE, [R::ZERO; D]);
        for _ in 0..self.octaves.count {
            let q = p.map(|x| x.wrapping_mul(frequency));
            let (n, g) = self.noise.sample_with_gradient(q);
            let g = g.map(|c| c.saturating_mul(frequency));
            let (term, dterm) = match self.kind {
                Kind::Fbm => (n, g),
                Kind::Turbulence => (n.abs(), if n < R::ZERO { g.map(|c| -c) } else { g }),
                Kind::Ridged => {
                    // As `sum_lanes`: r0 = 1 − |n|, r = r0²·w, next w = clamp(2r, 0, 1).
                    let r0 = R::ONE - n.abs();
                    let r = r0.saturating_mul(r0).saturating_mul(weight);
                    let dr0 = if n < R::ZERO { g } else { g.map(|c| -c) };
                    let two_r0_w = (r0 + r0).saturating_mul(weight);
                    let r0_sq = r0.saturating_mul(r0);
                    let dr: [R; D] = core::array::from_fn(|a| {
                        two_r0_w
                            .saturating_mul(dr0[a])
                            .saturating_add(r0_sq.saturating_mul(dweight[a]))
                    });
                    let twice = r.saturating_add(r);
                    weight = twice.clamp_to(R::ZERO, R::ONE);
                    dweight = if twice > R::ZERO && twice < R::ONE {
                        dr.map(|d| d.saturating_add(d))
                    } else {
                        [R::ZERO; D]
                    };
                    (r, dr)
                }
            };
            sum = sum.saturating_add(amplitude.saturating_mul(term));
            for (ga, d) in grad.iter_mut().zip(dterm) {
                *ga = ga.saturating_add(amplitude.saturating_mul(d));
            }
            frequency = frequency.saturating_mul(lacunarity);
            amplitude = amplitude.saturating_mul(gain);
        }
        (sum.canonical(), grad.map(R::canonical))
    }
}

crate::noise::inherent_amplitude_bound!(Fractal<N>, [N]);

impl<N: Noise<R, D>, R: Real, const D: usize> FilteredNoise<R, D> for Fractal<N> {
    /// The anti-aliased sum for a sample whose footprint in noise space is spanned by `dpdx`
    /// and `dpdy` (the change of `p` from one pixel to the next), as pbrt's `FBm` and
    /// `Turbulence` compute it.
    ///
    /// With `len² = max(|dpdx|², |dpdy|²)`, it sums `n = clamp(−1 − ½·log2(len²), 0, count)`
    /// octaves: `floor(n)` in full and the next faded in by `smoothstep(0.3, 0.7, n − floor(n))`.
    /// Turbulence replaces each dropped octave by the mean of `|noise|` (see
    /// [`with_clamped_mean`](Self::with_clamped_mean)): the faded octave is
    /// `lerp(w, mean, |n|)` and each octave after it adds `gain^i · mean`. (pbrt's printed loop
    /// adds the mean for the faded octave a second time; this does not.) Fbm and ridged octaves
    /// above the limit add nothing.
    ///
    /// The footprint is symmetric in `dpdx` and `dpdy`. A footprint vector with a NaN
    /// component is unknown and gives way to the other (IEEE `maxNum`); a zero footprint, or
    /// both unknown, sums every octave; an infinite one none.
    ///
    /// # Contract
    ///
    /// Never panics, for any coordinates and footprints (NaN, ±∞, huge, fixed point's extremes:
    /// octave frequencies wrap and sums saturate in fixed point); the result is finite in floats
    /// and within [`amplitude_bound`](Noise::amplitude_bound).
    fn sample_filtered(&self, p: [R; D], dpdx: [R; D], dpdy: [R; D]) -> R {
        let clamp = octaves_for(footprint_len2(&dpdx, &dpdy), self.octaves.count);
        self.sum(p, clamp.full, clamp.partial, true)
    }
}

impl<N: Noise<R, D>, R: Real, const D: usize> Noise<R, D> for Fractal<N> {
    #[inline]
    fn sample(&self, p: [R; D]) -> R {
        self.sum(p, self.octaves.count, R::ZERO, false)
    }

    #[inline]
    fn sample_lanes(&self, p: &[[R; LANES]; D], out: &mut [R; LANES]) {
        *out = self.sum_lanes(p, self.octaves.count, R::ZERO, false, |q, n| {
            self.noise.sample_lanes(q, n);
        });
    }

    /// `Σ_i |gain|^i · B`, with `B` the noise's bound for fBm and turbulence and
    /// `max(1, (B − 1)²)` for ridged terms.
    fn amplitude_bound(&self) -> f32 {
        let b = self.noise.amplitude_bound();
        let term = match self.kind {
            Kind::Fbm | Kind::Turbulence => b,
            Kind::Ridged => (b - 1.0) * (b - 1.0),
        }
        .max(match self.kind {
            Kind::Ridged => 1.0,
            _ => 0.0,
        })
        .max(self.clamped_mean.largest());
        // The larger of the gain and its fixed-point rounding, so the bound holds in every type.
        let g = self.octaves.gain.largest();
        let mut total = 0.0;
        let mut a = 1.0;
        for _ in 0..self.octaves.count {
            total += a * term;
            a *= g;
        }
        // Rounding in the sum of a fixed-point or f32 evaluation.
        total * (1.0 + 1e-5) + 1e-4
    }
}

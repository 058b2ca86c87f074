//! Wiener-interpolated lattice noise (Lewis 1989, §3): uncorrelated random values at the
//! integer lattice points, interpolated by the linear estimate that is optimal for a chosen
//! covariance.
//!
//! # Lewis's construction
//!
//! The estimate at `x` is a weighted sum of the lattice values `η_j` of a neighbourhood,
//! `η̂ = Σ a_j η_j` (eq. 2), whose weights minimise `E[(η − η̂)²]` (eq. 3). The orthogonality
//! principle gives `C a = c` (eq. 5), with `C_kj = C(t_j − t_k)` the covariance between the
//! data and `c_k = C(x − t_k)`, so `η̂ = ηᵀ C⁻¹ c` (eq. 6).
//!
//! bandnoise's neighbourhood is the `4^D` lattice points around `x`'s cell (offsets −1 to 2
//! along each axis). Because the lattice values are uncorrelated, the covariance must vanish
//! at every non-zero lattice offset, `C(√(i² + j² + k²)) = 0` (Lewis's lattice condition,
//! end of §3). Both [`Covariance`]s satisfy it, so the neighbourhood's matrix `C` is `C(0)·I`
//! and `C⁻¹` is `I/C(0)`: this is computed at compile time from the covariance's formula
//! (the matrix built entry by entry over the `4^D × 4^D` pairs) and asserted, and a sample is
//! the dot product `η̂ = Σ η_j C(x − t_j)/C(0)` over the lattice points within the
//! covariance's support (the others have `c_j = 0`).
//!
//! # What is realised
//!
//! The estimate is exact at the lattice points (`η̂(t_j) = η_j`) and smoother between them
//! than a process with covariance `C`: its covariance, averaged over the position within a
//! cell, is `σ_η² (h ⋆ h)` with `h = C/C(0)`, so its power spectrum is `σ_η² |Ĥ(f)|²`, the
//! requested spectrum `Ĉ(f)` squared (up to scale). The noise is normalised by that
//! closed form (`σ² = σ_η² ∫h²`), so its variance averaged over a cell is 1; it is
//! cyclostationary, like every interpolated lattice noise: the variance is
//! `σ_η² Σ_j h(x − t_j)²/σ²`, largest (`1/∫h²`: 4.5 in 2D, 9.3 in 3D for the low-pass
//! covariance) at the lattice points. Both the requested and realised covariance and spectrum
//! are measured in `tests/tests/wiener.rs`. This is the "artificially constrained" covariance
//! structure that led Lewis to sparse convolution (§4).
//!
//! # Lattice values
//!
//! Each lattice point's value is the sum of the four bytes of its [`CellHash`], centred:
//! `(b₀ + b₁ + b₂ + b₃ − 510)/512`, an approximately Gaussian value (Irwin-Hall; excess
//! kurtosis −0.3) with `σ_η² = 4 (256² − 1)/12 / 512²`, exact in every number type.

use crate::arch;
use crate::batch::{self, LANES};
use crate::hash::CellHash;
use crate::hash::chain::ChainHash;
use crate::radial::Profile;
use crate::wavelet::constmath;
use crate::{I16F16, Noise, NoiseGradient, Real};

/// A covariance of Wiener-interpolated noise: an isotropic function of the distance that
/// satisfies Lewis's lattice condition (0 at every non-zero lattice offset), evaluated from its
/// formula of the squared distance in each number type (no table: the errors are the type's
/// roundings, tested: 1e-6 in `f32`, 3e-4 in I16F16).
///
/// | covariance | support | spectrum |
/// |---|---|---|
/// | [`LowPass`](Self::LowPass) | radius 1: the `2^D` corners of the cell | low-pass |
/// | [`BandPass`](Self::BandPass) | radius 2: up to `4^D` points | band-pass, 0 at `f = 0`, peak near 0.8–1 cycle per cell |
///
/// # Examples
///
/// ```
/// use bandnoise::wiener::Covariance;
///
/// // Normalised to 1 at 0, and 0 at every other lattice point.
/// assert_eq!(Covariance::LowPass.at::<f32, 2>(0.0), 1.0);
/// for n in 1..=8 {
///     assert_eq!(Covariance::BandPass.at::<f32, 2>(n as f32), 0.0);
/// }
/// assert!(Covariance::BandPass.at::<f32, 2>(0.5) < 0.0);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Covariance {
    /// Wendland's compactly supported `ψ₃,₁(d) = (1 − d)⁴(4d + 1)` for `d < 1` (Wendland
    /// 1995): positive definite in up to three dimensions, `C²`, zero from `d = 1` on, so
    /// the lattice condition holds trivially and only the cell's `2^D` corners contribute.
    /// Low-pass.
    #[default]
    LowPass,
    /// An oscillating covariance of radius 2 that is 0 at `d = 1, √2, √3` (the lattice
    /// distances within its reach; `d = 2` is its rim) and integrates to 0, so its spectrum
    /// vanishes at the origin: a polynomial in `s = d²`,
    /// `(1 − s)(2 − s)(3 − s)/6 · (1 − s/4)⁸ · (1 + a₁s + a₂s² + a₃s³)`, `a₁` computed at
    /// compile time from `∫h = 0` in `D` dimensions and `a₂, a₃` chosen per dimension (a
    /// numerical search) to keep its spectrum non-negative. It is not exactly positive
    /// definite: its spectrum dips to −2.5e-4 of its peak (measured).
    BandPass,
}

impl Covariance {
    /// The radius of the support, in cells.
    #[must_use]
    pub const fn radius(self) -> u32 {
        match self {
            Covariance::LowPass => 1,
            Covariance::BandPass => 2,
        }
    }

    /// The covariance over `C(0)`, `h(√s)`, at squared distance `s` in `D` dimensions (1 to
    /// 4), evaluated from its formula in the number type: 0 from the rim on (and for NaN), 1
    /// for `s ≤ 0`.
    #[inline]
    #[must_use]
    pub fn at<R: Real, const D: usize>(self, s: R) -> R {
        self.evaluate::<R, D, false>(s).0
    }

    /// [`at`](Self::at) and its derivative with respect to `s`.
    #[inline]
    #[must_use]
    pub fn at_with_slope<R: Real, const D: usize>(self, s: R) -> (R, R) {
        self.evaluate::<R, D, true>(s)
    }

    /// [`at`](Self::at) of each lane, bit for bit: in `f32` the low-pass covariance's square
    /// roots come four lanes at a time where the target has a vector square root
    /// ([`arch::sqrt_lanes`]), so the batch loop over lanes vectorises.
    #[inline]
    pub(crate) fn at_lanes<R: Real, const D: usize>(self, s: &[R; LANES]) -> [R; LANES] {
        if self != Covariance::LowPass || !R::BINARY32 {
            return s.map(|s| self.at::<R, D>(s));
        }
        let mut roots = s.map(|s| s.to_f32());
        arch::sqrt_lanes(&mut roots);
        let rim = R::from_i32(1);
        core::array::from_fn(|l| {
            let s = s[l];
            if s.is_nan() || s >= rim {
                return R::ZERO;
            }
            low_pass::<R, false>(R::from_f32(roots[l])).0
        })
    }

    /// The value and, if `SLOPE`, the derivative in `s` (else 0), with `+ − ×` and (low-pass)
    /// one square root, the same operations in every number type. Every factor is below 12
    /// and every product below 500 in magnitude, so the products need no saturation
    /// (`mul_fraction`).
    #[inline]
    fn evaluate<R: Real, const D: usize, const SLOPE: bool>(self, s: R) -> (R, R) {
        let rim = R::from_i32((self.radius() * self.radius()) as i32);
        if s.is_nan() || s >= rim {
            return (R::ZERO, R::ZERO);
        }
        let s = if s > R::ZERO { s } else { R::ZERO };
        match self {
            Covariance::LowPass => low_pass::<R, SLOPE>(s.sqrt()),
            Covariance::BandPass => {
                let [c1, c2, c3] = band_pass_coefficients::<R, D>();
                let (u, v, w) = (R::ONE - s, R::from_i32(2) - s, R::from_i32(3) - s);
                let zeros = u.mul_fraction(v).mul_fraction(w);
                let poly = R::ONE + s.mul_fraction(c1 + s.mul_fraction(c2 + s.mul_fraction(c3)));
                let q = R::ONE - s.mul_fraction(R::from_ratio(1, 2));
                let q2 = q.mul_fraction(q);
                let q4 = q2.mul_fraction(q2);
                let q8 = q4.mul_fraction(q4);
                let sixth = R::from_setting(1.0 / 6.0, SIXTH);
                let head = zeros.mul_fraction(poly).mul_fraction(sixth);
                // At 0 (the lattice point itself) exactly 1, as the interpolation needs: the
                // rounded 1/6 would leave 1 ± 2⁻¹⁶ in fixed point.
                let value = if s > R::ZERO {
                    head.mul_fraction(q8)
                } else {
                    R::ONE
                };
                let slope = if SLOPE {
                    let dzeros = -(v.mul_fraction(w) + u.mul_fraction(w) + u.mul_fraction(v));
                    let dpoly = c1 + s.mul_fraction(c2 + c2 + s.mul_fraction(c3 + c3 + c3));
                    let dhead =
                        (dzeros.mul_fraction(poly) + zeros.mul_fraction(dpoly)).mul_fraction(sixth);
                    let q7 = q4.mul_fraction(q2).mul_fraction(q);
                    dhead.mul_fraction(q8) - (head + head).mul_fraction(q7)
                } else {
                    R::ZERO
                };
                (value, slope)
            }
        }
    }

    /// `h(√s)` and its derivative in `s`, in `f64`, from the formula, in `d` dimensions (1 to
    /// 4): what the tables hold and what tests compare with.
    #[must_use]
    pub const fn exact(self, d: usize, s: f64) -> (f64, f64) {
        profile(self, d).exact(s)
    }

    /// `∫ h(|x|)² dx` over `d`-dimensional space (`d` in 1..=4), by Simpson's rule: the
    /// realised variance per unit `σ_η²`, averaged over a cell (see the module docs).
    #[must_use]
    pub const fn power(self, d: usize) -> f64 {
        profile(self, d).integral(d, 2)
    }

    /// `∫ h(|x|) dx` over `d`-dimensional space: the requested spectrum at `f = 0`
    /// (0 for [`BandPass`](Self::BandPass), up to the quadrature's rounding).
    #[must_use]
    pub const fn integral(self, d: usize) -> f64 {
        profile(self, d).integral(d, 1)
    }
}

/// The radial profile of `covariance` in `d` dimensions.
const fn profile(covariance: Covariance, d: usize) -> Profile {
    match covariance {
        Covariance::LowPass => Profile::Wendland,
        Covariance::BandPass => Profile::BandPass(if d < 1 {
            1
        } else if d > 4 {
            4
        } else {
            d
        }),
    }
}

/// Whether the covariance matrix of the `4^D` lattice points around a cell, `C_kj = h(t_j −
/// t_k)`, is the identity: Lewis's lattice condition for this neighbourhood, so `C⁻¹ = I`.
const fn neighbourhood_is_identity(covariance: Covariance, d: usize) -> bool {
    let points = 1usize << (2 * d);
    let mut j = 0;
    while j < points {
        let mut k = 0;
        while k < points {
            // Squared distance between points j and k: base-4 digits are the offsets.
            let (mut s, mut a) = (0i64, 0);
            while a < d {
                let o = ((j >> (2 * a)) & 3) as i64 - ((k >> (2 * a)) & 3) as i64;
                s += o * o;
                a += 1;
            }
            let want = if j == k { 1.0 } else { 0.0 };
            if covariance.exact(d, s as f64).0 != want {
                return false;
            }
            k += 1;
        }
        j += 1;
    }
    true
}

const _: () = {
    let mut d = 1;
    while d <= 4 {
        assert!(neighbourhood_is_identity(Covariance::LowPass, d));
        assert!(neighbourhood_is_identity(Covariance::BandPass, d));
        d += 1;
    }
};

/// `σ = √(σ_η² ∫h²)` of `covariance` in `d` dimensions, at compile time.
const fn sigma(covariance: Covariance, d: usize) -> f64 {
    constmath::sqrt(VALUE_VARIANCE * covariance.power(d))
}

/// `1/σ` of `covariance` in `d` dimensions as `f32` and I16F16 (nearest), at compile time.
const fn scales(covariance: Covariance, d: usize) -> (f32, I16F16) {
    let scale = (1.0 / sigma(covariance, d)) as f32;
    (scale, fixed_of(scale))
}

/// `1/6` in I16F16.
const SIXTH: I16F16 = I16F16::from_bits(10_923);

/// The band-pass polynomial's `[a₁, a₂, a₃]` in `D` dimensions as `R` (floats: the `f32`
/// nearest each; fixed point: the I16F16 nearest).
#[inline]
fn band_pass_coefficients<R: Real, const D: usize>() -> [R; 3] {
    let [a1, a2, a3] = const { band_pass_f32(D) };
    let fixed = const {
        let [a1, a2, a3] = band_pass_f32(D);
        [fixed_of(a1), fixed_of(a2), fixed_of(a3)]
    };
    [
        R::from_setting(a1, fixed[0]),
        R::from_setting(a2, fixed[1]),
        R::from_setting(a3, fixed[2]),
    ]
}

/// The band-pass coefficients in `d` dimensions, as `f32`.
const fn band_pass_f32(d: usize) -> [f32; 3] {
    let [a1, a2, a3] = crate::radial::band_pass_coefficients(d);
    [a1 as f32, a2 as f32, a3 as f32]
}

/// The I16F16 nearest `x` (ties away from zero), at compile time.
const fn fixed_of(x: f32) -> I16F16 {
    let scaled = x as f64 * 65_536.0;
    I16F16::from_bits(if scaled < 0.0 {
        -((-scaled + 0.5) as i32)
    } else {
        (scaled + 0.5) as i32
    })
}

/// `σ_η²`: the variance of a lattice value, `4 (256² − 1)/12 / 512²`.
pub const VALUE_VARIANCE: f64 = 4.0 * 65_535.0 / 12.0 / 262_144.0;

/// The low-pass covariance (Wendland's `(1 − d)⁴(4d + 1)`) at `d = √s`, and if `SLOPE` its
/// derivative in `s`, `−10 (1 − d)³` (else 0).
#[inline]
fn low_pass<R: Real, const SLOPE: bool>(d: R) -> (R, R) {
    let e = R::ONE - d;
    let e3 = e.mul_fraction(e).mul_fraction(e);
    let value = e3.mul_fraction(e).mul_fraction(d + d + d + d + R::ONE);
    let slope = if SLOPE {
        e3.mul_fraction(R::from_i32(-10))
    } else {
        R::ZERO
    };
    (value, slope)
}

/// A lattice point's value from its hash: its four bytes summed, centred, over 512.
#[inline]
fn value<R: Real>(key: u32) -> R {
    let [a, b, c, d] = key.to_le_bytes();
    let sum = i32::from(a) + i32::from(b) + i32::from(c) + i32::from(d);
    R::from_ratio(sum - 510, 9)
}

/// Wiener-interpolated noise in `D` dimensions (1 to 4): Lewis's §3 (see the module docs).
///
/// The lattice is the integer grid: sample at `x · f` for features `1/f` units wide. The
/// default covariance is [`Covariance::LowPass`].
///
/// # Amplitude
///
/// Variance 1 averaged over a cell and mean 0 (closed form, see the module docs; tested over
/// 10⁶ samples). The lattice values are below 1 in magnitude and `|h| ≤ 1` at the at most
/// `(2r)^D` points within the support's radius `r`, so `|η̂| ≤ (2r)^D / σ`
/// ([`amplitude_bound`](Noise::amplitude_bound)).
///
/// # Examples
///
/// ```
/// use bandnoise::{I16F16, Noise, wiener::{Covariance, WienerNoise}};
///
/// let smooth = WienerNoise::<2>::new(7);
/// let v: f32 = smooth.sample([0.5, 1.25]);
/// assert!(v.abs() <= smooth.amplitude_bound());
///
/// // Band-pass, in fixed point.
/// let bands = WienerNoise::<3>::new(7).with_covariance(Covariance::BandPass);
/// let p = [0.5f32, 1.25, -2.0];
/// let q: I16F16 = bands.sample(p.map(I16F16::from_num));
/// assert!((q.to_num::<f32>() - bands.sample(p)).abs() < 2e-3);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct WienerNoise<const D: usize> {
    hash: CellHash,
    covariance: Covariance,
    /// `1/σ`, in floats and in fixed point.
    scale: f32,
    scale_fixed: I16F16,
}

impl<const D: usize> WienerNoise<D> {
    /// The noise for `seed`, with the low-pass covariance.
    #[must_use]
    pub fn new(seed: u32) -> Self {
        const { assert!(D >= 1 && D <= 4, "Wiener noise has 1 to 4 dimensions") };
        Self::build(CellHash::new(seed), Covariance::default())
    }

    fn build(hash: CellHash, covariance: Covariance) -> Self {
        // 1/σ at compile time, in both types.
        let (scale, scale_fixed) = match covariance {
            Covariance::LowPass => const { scales(Covariance::LowPass, D) },
            Covariance::BandPass => const { scales(Covariance::BandPass, D) },
        };
        Self {
            hash,
            covariance,
            scale,
            scale_fixed,
        }
    }

    /// The same noise (the same lattice values) with another covariance.
    #[must_use]
    pub fn with_covariance(self, covariance: Covariance) -> Self {
        Self::build(self.hash, covariance)
    }

    /// The covariance.
    #[must_use]
    pub fn covariance(&self) -> Covariance {
        self.covariance
    }

    /// The standard deviation of the unscaled sum averaged over a cell, `√(σ_η² ∫h²)`,
    /// which the noise divides by.
    #[must_use]
    pub fn sigma(&self) -> f64 {
        // At compile time, as the scale is: no quadrature per call.
        match self.covariance {
            Covariance::LowPass => const { sigma(Covariance::LowPass, D) },
            Covariance::BandPass => const { sigma(Covariance::BandPass, D) },
        }
    }

    /// The bound on `|sample(p)|` in every number type (see [Amplitude](Self#amplitude)).
    #[must_use]
    pub fn amplitude_bound(&self) -> f32 {
        let points = (2 * self.covariance.radius()).pow(D as u32) as f64;
        // A little above: the roundings of the sum and of the fixed-point scale.
        (points * self.scale as f64 * (1.0 + 1e-4)) as f32
    }

    /// Calls `visit(δ, s, η)` for each lattice point within the covariance's support of `p`:
    /// the offset from the point to `p`, its squared length and the point's value. The
    /// candidates are the `(2r)^D` points around `p`'s cell (offsets 0 and 1 along each axis for
    /// radius 1, −1 to 2 for radius 2), first axis slowest; those at squared distance `r²` or
    /// more are skipped before they are hashed. One flat loop (rather than the odometer of
    /// [`CellHash::near`], which shares hash prefixes) keeps the code small: the browser demo's
    /// size budget.
    #[inline]
    fn walk<R: Real>(&self, p: [R; D], mut visit: impl FnMut([R; D], R, R)) {
        let r = self.covariance.radius();
        // Points per axis, as a power of two, and the first offset.
        let (bits, low) = if r == 1 { (1u32, 0i32) } else { (2, -1) };
        let mut cells = [[0u32; 4]; D];
        let mut deltas = [[R::ZERO; 4]; D];
        let mut gaps = [[R::ZERO; 4]; D];
        for a in 0..D {
            let (c, f) = p[a].split();
            for k in 0..4 {
                let o = low + k as i32;
                let d = f - R::from_i32(o);
                cells[a][k] = c.wrapping_add(o) as u32;
                deltas[a][k] = d;
                gaps[a][k] = d.mul_rn(d);
            }
        }
        let reach = R::from_i32((r * r) as i32);
        let mask = (1usize << bits) - 1;
        for k in 0..1usize << (bits as usize * D) {
            // Each axis's offset index: its digit, axis 0 the most significant.
            let digits: [usize; D] =
                core::array::from_fn(|a| (k >> (bits as usize * (D - 1 - a))) & mask & 3);
            let mut s = R::ZERO;
            for (g, &i) in gaps.iter().zip(&digits) {
                s = s + g[i];
            }
            if s >= reach {
                continue;
            }
            let mut key = self.hash.start();
            for (c, &i) in cells.iter().zip(&digits) {
                key = self.hash.step(key, c[i]);
            }
            visit(
                core::array::from_fn(|a| deltas[a][digits[a]]),
                s,
                value(key),
            );
        }
    }
}

impl<const D: usize> WienerNoise<D> {
    /// [`Noise::sample`], out of line: one copy per number type keeps the code small (the
    /// browser demo's size budget) at the cost of a call.
    #[inline(never)]
    fn value<R: Real>(&self, p: [R; D]) -> R {
        let covariance = self.covariance;
        let mut total = R::ZERO;
        self.walk(p, |_, s, eta| {
            total = total + eta.mul_rn(covariance.at::<R, D>(s));
        });
        total
            .mul_rn(R::from_setting(self.scale, self.scale_fixed))
            .canonical()
    }
}

impl<R: Real, const D: usize> Noise<R, D> for WienerNoise<D> {
    #[inline]
    fn sample(&self, p: [R; D]) -> R {
        self.value(p)
    }

    fn amplitude_bound(&self) -> f32 {
        WienerNoise::amplitude_bound(self)
    }

    /// Lanes that differ only along axis 0, over at most 4 cells (a grid row's
    /// chunk), share their lattice points: each point's value is hashed once for all of them,
    /// and each lane sums the covariance over the same candidates in the same order as
    /// [`sample`](Noise::sample) (the candidates out of reach add the covariance's exact 0
    /// instead of being skipped, which leaves every sum's bits unchanged). Other lanes are
    /// sampled one by one. Bit-identical to `sample` either way.
    fn sample_lanes(&self, p: &[[R; LANES]; D], out: &mut [R; LANES]) {
        if !self.row_lanes(p, out) {
            for (l, o) in out.iter_mut().enumerate() {
                *o = self.value(batch::lane(p, l));
            }
        }
    }
}

/// The most cells, beyond the first, that a chunk of lanes may span along axis 0 and still
/// share its lattice points.
const SPAN: usize = 3;

impl<const D: usize> WienerNoise<D> {
    /// [`Noise::sample_lanes`]'s shared path: `false` (writing nothing) unless every axis but
    /// the first has one coordinate in all lanes and the lanes' cells along axis 0 span at
    /// most [`SPAN`] + 1 cells.
    fn row_lanes<R: Real>(&self, p: &[[R; LANES]; D], out: &mut [R; LANES]) -> bool {
        // Axes past the first: one coordinate (NaN, never equal to itself, goes lane by lane).
        for axis in p.iter().skip(1) {
            let first = axis[0];
            if axis.iter().any(|&x| x != first) {
                return false;
            }
        }
        let r = self.covariance.radius();
        let (bits, low) = if r == 1 { (1usize, 0i32) } else { (2, -1) };
        let points = 1usize << bits;
        let split = p[0].map(Real::split);
        let (lo, hi) = split
            .iter()
            .fold((i32::MAX, i32::MIN), |(lo, hi), &(c, _)| {
                (lo.min(c), hi.max(c))
            });
        if i64::from(hi) - i64::from(lo) > SPAN as i64 {
            return false;
        }
        // The other axes as the point walk has them: cells, offsets, squared offsets.
        let mut cells = [[0u32; 4]; D];
        let mut gaps = [[R::ZERO; 4]; D];
        for ((axis, cell), gap) in p.iter().zip(&mut cells).zip(&mut gaps).skip(1) {
            let (c, f) = axis[0].split();
            for (k, (cell, gap)) in cell.iter_mut().zip(gap.iter_mut()).enumerate() {
                let o = low + k as i32;
                let d = f - R::from_i32(o);
                *cell = c.wrapping_add(o) as u32;
                *gap = d.mul_rn(d);
            }
        }
        // The values of the box's lattice points: axis-0 cell `b` (from `lo + low`) by the
        // other axes' digits, first axis slowest (index `rest`).
        let rest_count = 1usize << (bits * (D - 1));
        let mut eta = [[R::ZERO; 64]; SPAN + 4];
        for (b, row) in eta.iter_mut().enumerate().take(SPAN + points) {
            let start = self
                .hash
                .step(self.hash.start(), lo.wrapping_add(low + b as i32) as u32);
            for (rest, slot) in row.iter_mut().enumerate().take(rest_count) {
                let mut key = start;
                for (a, cell) in cells.iter().enumerate().skip(1) {
                    let digit = (rest >> (bits * (D - 1 - a))) & (points - 1) & 3;
                    key = self.hash.step(key, cell[digit]);
                }
                *slot = value(key);
            }
        }
        let covariance = self.covariance;
        let rim = R::from_i32((r * r) as i32);
        // Each lane's axis-0 squared offsets (by offset, then lane) and its cell's place in
        // the box.
        let mut gaps0 = [[R::ZERO; LANES]; 4];
        for (l, &(_, f)) in split.iter().enumerate() {
            for (k, g) in gaps0.iter_mut().enumerate() {
                let d = f - R::from_i32(low + k as i32);
                g[l] = d.mul_rn(d);
            }
        }
        let at: [usize; LANES] = split.map(|(c, _)| (c.wrapping_sub(lo) as usize).min(SPAN));
        let mut totals = [R::ZERO; LANES];
        // Candidate by candidate, in the point walk's order, every lane at once: the squared
        // distances and the covariance over the lanes (a loop that vectorises), then each
        // lane's value times its lattice point's.
        for k in 0..points << (bits * (D - 1)) {
            let d0 = (k >> (bits * (D - 1))) & (points - 1) & 3;
            let rest = k & (rest_count - 1);
            let mut s = gaps0[d0].map(|g| R::ZERO + g);
            for (a, g) in gaps.iter().enumerate().skip(1) {
                let digit = (k >> (bits * (D - 1 - a))) & (points - 1) & 3;
                let g = g[digit];
                for x in s.iter_mut() {
                    *x = *x + g;
                }
            }
            // Out of every lane's reach: each would add the covariance's exact 0.
            if s.iter().all(|&x| x >= rim) {
                continue;
            }
            let h = covariance.at_lanes::<R, D>(&s);
            let column: [R; SPAN + 1] = core::array::from_fn(|i| {
                eta.get(i + d0)
                    .and_then(|row| row.get(rest))
                    .copied()
                    .unwrap_or(R::ZERO)
            });
            for ((t, &i), h) in totals.iter_mut().zip(&at).zip(h) {
                // `at` is at most SPAN (`get` says so to the compiler: no panic path).
                let eta = column.get(i).copied().unwrap_or(R::ZERO);
                *t = *t + eta.mul_rn(h);
            }
        }
        let scale = R::from_setting(self.scale, self.scale_fixed);
        for (o, t) in out.iter_mut().zip(totals) {
            *o = t.mul_rn(scale).canonical();
        }
        true
    }
}

/// The analytic gradient: `∇η̂ = Σ_j η_j · 2(x − t_j) · dh/ds`, from the covariance's table
/// ([`Covariance::at_with_slope`]); the value is [`sample`](Noise::sample)'s bit for bit.
impl<R: Real, const D: usize> NoiseGradient<R, D> for WienerNoise<D> {
    fn sample_with_gradient(&self, p: [R; D]) -> (R, [R; D]) {
        let covariance = self.covariance;
        let mut total = R::ZERO;
        let mut gradient = [R::ZERO; D];
        self.walk(p, |delta, s, eta| {
            let (h, slope) = covariance.at_with_slope::<R, D>(s);
            total = total + eta.mul_rn(h);
            let es = eta.mul_rn(slope);
            for (g, d) in gradient.iter_mut().zip(delta) {
                *g = g.saturating_add((es + es).mul_rn(d));
            }
        });
        let scale = R::from_setting(self.scale, self.scale_fixed);
        (
            total.mul_rn(scale).canonical(),
            gradient.map(|g| g.saturating_mul(scale).canonical()),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The evaluation's errors the [`Covariance`] docs state (values and slopes; `f64` is the
    /// formula itself), in every dimension.
    #[test]
    fn evaluation_follows_the_formulas() {
        fn check<const D: usize>(covariance: Covariance) {
            let rim = f64::from(covariance.radius() * covariance.radius());
            let (mut e64, mut e32, mut eq, mut s32, mut sq) = (0f64, 0f64, 0f64, 0f64, 0f64);
            for i in 0..=20_000 {
                let s = rim * i as f64 / 20_000.0;
                let (v, g) = covariance.exact(D, s);
                let (v64, g64) = covariance.at_with_slope::<f64, D>(s);
                e64 = e64.max((v64 - v).abs()).max((g64 - g).abs());
                let (v32, g32) = covariance.at_with_slope::<f32, D>(s as f32);
                let (v, g) = covariance.exact(D, f64::from(s as f32));
                e32 = e32.max((f64::from(v32) - v).abs());
                s32 = s32.max((f64::from(g32) - g).abs());
                let q = I16F16::from_num(s);
                let (vq, gq) = covariance.at_with_slope::<I16F16, D>(q);
                let (v, g) = covariance.exact(D, q.to_num::<f64>());
                eq = eq.max((vq.to_num::<f64>() - v).abs());
                sq = sq.max((gq.to_num::<f64>() - g).abs());
                assert_eq!(covariance.at::<f32, D>(s as f32), v32);
                assert_eq!(covariance.at::<I16F16, D>(q), vq);
            }
            // f64 takes the band-pass coefficients as f32, as every float type does.
            assert!(e64 < 1e-6, "{covariance:?} {D}: {e64}");
            assert!(e32 < 1e-6 && s32 < 2e-5, "{covariance:?} {D}: {e32} {s32}");
            assert!(eq < 3e-4 && sq < 3e-3, "{covariance:?} {D}: {eq} {sq}");
        }
        for covariance in [Covariance::LowPass, Covariance::BandPass] {
            check::<1>(covariance);
            check::<2>(covariance);
            check::<3>(covariance);
            check::<4>(covariance);
            assert_eq!(covariance.at::<f32, 2>(f32::NAN), 0.0);
            assert_eq!(covariance.at::<f32, 2>(-1.0), 1.0);
            assert_eq!(covariance.at::<I16F16, 3>(I16F16::MAX), I16F16::ZERO);
        }
    }

    /// The band-pass covariance integrates to 0 in its dimension (its `a₁`), and the slopes
    /// in the table are the formula's derivative.
    #[test]
    fn band_pass_has_no_mean() {
        for d in 1..=4 {
            let i = Covariance::BandPass.integral(d);
            assert!(i.abs() < 1e-9, "{d}: {i}");
            assert!(Covariance::LowPass.integral(d) > 0.1);
            for k in 1..400 {
                let s = k as f64 / 100.0;
                let e = 1e-6;
                let (_, slope) = Covariance::BandPass.exact(d, s);
                let numeric = (Covariance::BandPass.exact(d, s + e).0
                    - Covariance::BandPass.exact(d, s - e).0)
                    / (2.0 * e);
                assert!((slope - numeric).abs() < 1e-6, "{d} {s}");
            }
        }
    }

    /// The values are those of the lattice points at the lattice points (the interpolation is
    /// exact there), scaled.
    #[test]
    fn interpolates_the_lattice_values() {
        for covariance in [Covariance::LowPass, Covariance::BandPass] {
            let noise = WienerNoise::<2>::new(3).with_covariance(covariance);
            for (x, y) in [(0, 0), (5, -7), (-100, 33)] {
                let key = noise.hash.hash([x, y]);
                let want = value::<f64>(key) * noise.scale as f64;
                let got: f64 = noise.sample([x as f64, y as f64]);
                assert!((got - want).abs() < 1e-12, "{covariance:?} {x} {y}");
            }
        }
    }

    #[test]
    fn values_are_centred() {
        assert_eq!(value::<f32>(0), -510.0 / 512.0);
        assert_eq!(value::<f32>(u32::MAX), 510.0 / 512.0);
        assert_eq!(value::<f32>(0x8080_7F7F), 0.0);
    }
}

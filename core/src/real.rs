//! The one numeric trait every noise is written against.
//!
//! [`Real`] is sealed and implemented for `f32`, `f64` and [`I16F16`]. Each noise is written once,
//! generically, and the number type is chosen by the caller (a type, never a cargo feature, so two
//! crates in one build cannot change each other's results).
//!
//! # Rules the implementations keep
//!
//! * **Bit-identical floats on every target.** Kernels use only `+ − × ÷`, which IEEE 754 makes
//!   deterministic, and never `mul_add`. The few functions beyond them (`fmod`, `log2`) go through
//!   `libm`, never the platform's math library.
//! * **Fixed point never panics.** `fixed`'s operators panic on overflow in debug builds and wrap
//!   in release. Kernel code uses the plain operators only on values whose range is proved (a
//!   fraction in `[0, 1)`, a gradient component in `[-1, 1]`, a sum of a few of those); anything a
//!   user scales (octave frequencies, amplitudes, sums) goes through [`Real::saturating_add`],
//!   [`Real::saturating_mul`] or [`Real::wrapping_mul`], so debug and release agree.
//! * **Coordinates split into a cell and a fraction** ([`Real::split`]) before any arithmetic, so
//!   the kernel only ever computes with fractions in `[0, 1)` and fixed point cannot overflow
//!   whatever the coordinate.

use core::fmt::Debug;
use core::ops::{Add, Mul, Neg, Sub};

pub use fixed::types::I16F16;

/// The supertrait that seals [`Real`]; it also carries what only the kernels may call.
pub(crate) mod sealed {
    use fixed::types::I16F16;

    pub trait Sealed: Sized {
        /// Whether the type is IEEE binary32 (`f32`): the target kernels of
        /// [`arch`](crate::arch) are written for `f32` lanes, and a noise takes them when this
        /// constant says its samples are `f32` (then [`Real::to_f32`](crate::Real::to_f32) and
        /// [`Real::from_f32`](crate::Real::from_f32) are the identity).
        const BINARY32: bool;
        /// Whether the type is an IEEE binary float (`f32`, `f64`): each operation correctly
        /// rounded, so [`norm`](Self::norm) is the root of the squares summed in axis order,
        /// bit for bit whoever sums them in that order.
        const FLOAT: bool;
        /// `self · unit` for `unit` ∈ {−1, 0, 1}, exact (up to the sign of a zero), for gradient
        /// components read from a table. Floats multiply where there is an FPU (one instruction
        /// that reads the unit from the table) and flip or clear the sign bits where floats are
        /// emulated; fixed point multiplies the bits by `unit`'s integer part (a 32-bit
        /// multiply, where `mul_rn` needs 64 bits and a rounding). Other units are never passed
        /// (the callers' tables hold only these three).
        fn mul_unit(self, unit: Self) -> Self;
        /// `self.mul_rn(o)` without the saturation: the same bits wherever the rounded product
        /// fits the type, which the kernels guarantee by a factor in `[0, 1]` (a fraction, a
        /// fade, an interpolation or B-spline weight: the product cannot exceed the other
        /// factor) or by small factors (fixed point's quintic fade reaches `1 + 2⁻¹⁶`). Cheaper
        /// in fixed point: no saturation, and on ARMv6-M (no 32 × 32 → 64-bit multiply, so
        /// `mul_rn` calls `__aeabi_lmul`) both factors split into 16-bit halves, three 32-bit
        /// multiplies. Floats: `self * o`. Out of range it wraps (never a panic).
        fn mul_fraction(self, o: Self) -> Self;
        /// `-self` if `bit` (the low bit of its argument) is 1, else `self`: a gradient sign from
        /// a hash bit. On ARMv6-M fixed point flips without a branch (`(x ^ m) − m` with
        /// `m = −bit`); elsewhere, and for floats, it is `-`.
        fn negate_if(self, bit: u32) -> Self;
        /// `self`, or 0 when it is NaN or ±∞ (fixed point: always `self`).
        fn finite_or_zero(self) -> Self;
        /// A setting given as `f32` and rounded once to I16F16 when it was validated: floats
        /// take the `f32` (exactly), fixed point its rounding, so no sample converts a float.
        fn from_setting(f: f32, q: I16F16) -> Self;
        /// The bits of `self` as I16F16 (nearest, saturating; NaN is 0), for the integer
        /// outputs of [`levels`](crate::levels).
        fn fixed_bits(self) -> i32;
        /// The simplex lattice's skew (Perlin 2001; Gustavson 2005, "skewing"): each axis's
        /// `x_a + F·Σx`, split into its cell and its fraction in `[0, 1)` as
        /// [`split`](crate::Real::split) does, for `F = skew · 2⁻³¹` (`0 ≤ skew < 2³¹`).
        /// Floats compute `Σx` left to right, `s = Σx · F` and `x_a + s` in the type (a
        /// non-finite sum samples cell 0, as `split` does). Fixed point computes the skewed
        /// coordinate exactly to 2⁻¹⁶ in 64-bit integers (`⌊Σx·F⌋` in its bits), so no
        /// coordinate overflows: a skewed cell beyond I16F16's range is still a cell.
        fn skew_split<const D: usize>(p: [Self; D], skew: i32) -> ([i32; D], [Self; D]);
        /// The Euclidean length `√(Σ vₐ²)` (cellular noise's offsets, the wood texture's
        /// radius). Floats sum the squares left to right from 0 and take
        /// [`Real::sqrt`](crate::Real::sqrt) (∞ where the squares overflow). Fixed point sums
        /// the exact squares of the bits (2⁻³² units, in `u64`, saturating) and takes their
        /// integer square root (rounded to nearest, saturating at `MAX`), so a short vector
        /// keeps its length where rounded squares would lose it (a length of 2⁻⁹ has a
        /// square below 2⁻¹⁶) and a long one cannot overflow.
        fn norm<const D: usize>(v: [Self; D]) -> Self;
        /// `v` rounded to the type (nearest; fixed point saturates, NaN is 0), for offsets
        /// computed in `f64` (OpenSimplex2's rotated lattices).
        fn from_f64_nearest(v: f64) -> Self;
    }
    /// Whether this target emulates floats in software (Arm without the hard-float ABI, RISC-V
    /// without F): there a multiplication is a library call, and integer operations on the
    /// bits are cheaper.
    pub(crate) const SOFT_FLOAT: bool = cfg!(any(
        all(target_arch = "arm", not(target_abi = "eabihf")),
        all(
            any(target_arch = "riscv32", target_arch = "riscv64"),
            not(target_feature = "f")
        )
    ));

    macro_rules! mul_unit_float {
        ($t:ty, $bits:ty, $binary32:expr) => {
            impl Sealed for $t {
                const BINARY32: bool = $binary32;
                const FLOAT: bool = true;
                #[inline]
                fn mul_unit(self, unit: Self) -> Self {
                    if SOFT_FLOAT {
                        // unit's sign flips self's; a zero unit clears it (+0.0, which differs
                        // from self · 0 only in the sign of a zero).
                        let u = unit.to_bits();
                        let sign = u & !(<$bits>::MAX >> 1);
                        let keep = if u << 1 == 0 { 0 } else { <$bits>::MAX };
                        <$t>::from_bits((self.to_bits() ^ sign) & keep)
                    } else {
                        self * unit
                    }
                }
                #[inline]
                fn mul_fraction(self, o: Self) -> Self {
                    self * o
                }
                #[inline]
                fn negate_if(self, bit: u32) -> Self {
                    if bit & 1 == 0 { self } else { -self }
                }
                #[inline]
                fn finite_or_zero(self) -> Self {
                    // ∞ − ∞ and NaN − NaN are NaN, which compares unequal to 0.
                    if self - self == 0.0 { self } else { 0.0 }
                }
                #[inline]
                fn fixed_bits(self) -> i32 {
                    super::fixed_from_float(self).to_bits()
                }
                #[inline]
                fn from_setting(f: f32, _: I16F16) -> Self {
                    f as $t
                }
                #[inline]
                fn skew_split<const D: usize>(p: [Self; D], skew: i32) -> ([i32; D], [Self; D]) {
                    use crate::Real;
                    let mut sum = 0.0;
                    for x in p {
                        sum += x;
                    }
                    let s = sum * <$t>::from_ratio(skew, 31);
                    let mut cell = [0; D];
                    let mut frac = [0.0; D];
                    for a in 0..D {
                        (cell[a], frac[a]) = (p[a] + s).split();
                    }
                    (cell, frac)
                }
                #[inline]
                fn norm<const D: usize>(v: [Self; D]) -> Self {
                    let mut sum = 0.0;
                    for x in v {
                        sum += x * x;
                    }
                    crate::Real::sqrt(sum)
                }
                #[inline]
                fn from_f64_nearest(v: f64) -> Self {
                    v as $t
                }
            }
        };
    }
    mul_unit_float!(f32, u32, true);
    mul_unit_float!(f64, u64, false);
    impl Sealed for I16F16 {
        const BINARY32: bool = false;
        const FLOAT: bool = false;
        #[inline]
        fn mul_unit(self, unit: Self) -> Self {
            // unit's bits are ±2^16 or 0: `>> 16` gives ±1 or 0. The kernels pass fractions in
            // (−2, 2), so the product cannot wrap.
            I16F16::from_bits(self.to_bits().wrapping_mul(unit.to_bits() >> 16))
        }
        #[inline]
        fn mul_fraction(self, o: Self) -> Self {
            let (a, b) = (self.to_bits(), o.to_bits());
            #[cfg(bandnoise_armv6m)]
            let bits = super::mul_fraction_halves(a, b);
            // Where the rounded product fits `i32` (the caller's promise), no clamp is needed.
            #[cfg(not(bandnoise_armv6m))]
            let bits = ((a as i64 * b as i64 + (1 << 15)) >> 16) as i32;
            I16F16::from_bits(bits)
        }
        #[inline]
        fn negate_if(self, bit: u32) -> Self {
            // Kernels pass sums of a few fractions: −x never wraps. Branch-free on ARMv6-M
            // only: elsewhere (RV32IMC, counted) the branch is cheaper.
            if cfg!(bandnoise_armv6m) {
                let m = (bit & 1).wrapping_neg() as i32;
                I16F16::from_bits((self.to_bits() ^ m).wrapping_sub(m))
            } else if bit & 1 == 0 {
                self
            } else {
                -self
            }
        }
        #[inline]
        fn finite_or_zero(self) -> Self {
            self
        }
        #[inline]
        fn from_setting(_: f32, q: I16F16) -> Self {
            q
        }
        #[inline]
        fn fixed_bits(self) -> i32 {
            self.to_bits()
        }
        #[inline]
        fn from_f64_nearest(v: f64) -> Self {
            super::fixed_from_float(v)
        }
        #[inline]
        fn skew_split<const D: usize>(p: [Self; D], skew: i32) -> ([i32; D], [Self; D]) {
            // |Σ bits| < 2³³ and skew < 2³¹: the product fits i64.
            let mut sum = 0i64;
            for x in p {
                sum += i64::from(x.to_bits());
            }
            let s = (sum * i64::from(skew)) >> 31;
            let mut cell = [0; D];
            let mut frac = [I16F16::ZERO; D];
            for a in 0..D {
                let v = i64::from(p[a].to_bits()) + s;
                // |v| < 2³⁴: the cell fits i32 without wrapping.
                cell[a] = (v >> 16) as i32;
                frac[a] = I16F16::from_bits((v & 0xFFFF) as i32);
            }
            (cell, frac)
        }
        #[inline]
        fn norm<const D: usize>(v: [Self; D]) -> Self {
            // Each square is at most 2⁶²; the sum saturates (four of them reach 2⁶⁴), and a
            // root beyond I16F16's range saturates at MAX.
            let mut sum = 0u64;
            for x in v {
                let b = x.to_bits().unsigned_abs() as u64;
                sum = sum.saturating_add(b * b);
            }
            I16F16::from_bits(super::isqrt(sum).min(i32::MAX as u64) as i32)
        }
    }
}

/// The bits of I16F16 `a · b` rounded to nearest (ties up), wherever the result fits `i32`, in
/// 32-bit multiplies only (ARMv6-M's `muls`): with `a = ah·2^16 + al` and `b = bh·2^16 + bl`
/// (`ah = a >> 16` arithmetic, `al`, `bl` in `[0, 2^16)`), `a·b = (a·bh + ah·bl)·2^16 +
/// al·bl`; the rounding sees only `al·bl`, and `al·bl + 2^15 < 2^32`. The rest is exact
/// modulo 2³², so wrapping arithmetic gives the product whenever it fits.
#[cfg(any(test, bandnoise_armv6m))]
#[inline]
fn mul_fraction_halves(a: i32, b: i32) -> i32 {
    mul_halves(a, b, 1 << 15)
}

/// `⌊a·b / 2¹⁶⌋` modulo 2³² (I16F16's `wrapping_mul`) from 32-bit multiplies, as
/// [`mul_fraction_halves`] without its rounding.
#[cfg(any(test, bandnoise_armv6m))]
#[inline]
fn mul_floor_halves(a: i32, b: i32) -> i32 {
    mul_halves(a, b, 0)
}

/// I16F16's `saturating_mul` on ARMv6-M: where both factors are below 128 in magnitude the
/// product is below 2¹⁴ and cannot saturate, so [`mul_floor_halves`] gives it (the fractal
/// sums' amplitudes, gains, frequencies and octave values); otherwise the 64-bit product.
#[cfg(any(test, bandnoise_armv6m))]
#[inline]
fn saturating_mul_halves(a: i32, b: i32) -> i32 {
    if (a.unsigned_abs() | b.unsigned_abs()) < 1 << 23 {
        mul_floor_halves(a, b)
    } else {
        I16F16::from_bits(a)
            .saturating_mul(I16F16::from_bits(b))
            .to_bits()
    }
}

/// `⌊(a·b + round) / 2¹⁶⌋` modulo 2³² (`round` below 2¹⁶): with `ah = a >> 16` (arithmetic)
/// and `al`, `bl` in `[0, 2¹⁶)`, `a·b = (a·bh + ah·bl)·2¹⁶ + al·bl` exactly, and only
/// `al·bl + round < 2³²` is below the point.
#[cfg(any(test, bandnoise_armv6m))]
#[inline]
fn mul_halves(a: i32, b: i32, round: u32) -> i32 {
    let (ah, al) = (a >> 16, a as u32 & 0xFFFF);
    let (bh, bl) = (b >> 16, b as u32 & 0xFFFF);
    let low = al.wrapping_mul(bl).wrapping_add(round) >> 16;
    (a.wrapping_mul(bh))
        .wrapping_add(ah.wrapping_mul(bl as i32))
        .wrapping_add(low as i32)
}

/// A float as the nearest I16F16, saturating out of range, NaN as 0. `checked_from_num` has no
/// panic path (unlike `saturating_from_num`, which panics on NaN).
#[inline]
fn fixed_from_float<F: fixed::traits::ToFixed + Copy + PartialOrd + Default>(v: F) -> I16F16 {
    match I16F16::checked_from_num(v) {
        Some(x) => x,
        None if v > F::default() => I16F16::MAX,
        None if v < F::default() => I16F16::MIN,
        None => I16F16::ZERO,
    }
}

/// The arithmetic the noises need, for `f32`, `f64` and [`I16F16`].
///
/// The trait is sealed: the kernels' proofs of range (see the module docs) hold for these three
/// types only.
///
/// # Examples
///
/// ```
/// use bandnoise::{I16F16, Real};
///
/// // Every coordinate splits into a cell and a fraction in [0, 1).
/// assert_eq!((-1.25f32).split(), (-2, 0.75));
/// assert_eq!(I16F16::from_f32(-1.25).split(), (-2, I16F16::from_f32(0.75)));
/// // Non-finite coordinates are the origin.
/// assert_eq!(f32::NAN.split(), (0, 0.0));
/// ```
pub trait Real:
    sealed::Sealed
    + Copy
    + PartialEq
    + PartialOrd
    + Debug
    + Default
    + Send
    + Sync
    + 'static
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Neg<Output = Self>
{
    /// 0.
    const ZERO: Self;
    /// 1.
    const ONE: Self;
    /// −1.
    const NEG_ONE: Self;
    /// The largest finite value.
    const MAX: Self;

    /// Converts from `f32`: rounds to nearest, saturates at the type's range, NaN becomes 0.
    #[must_use]
    fn from_f32(v: f32) -> Self;
    /// Converts to `f32` (rounding to nearest).
    #[must_use]
    fn to_f32(self) -> f32;
    /// Converts to `f64` (exact for all three types).
    #[must_use]
    fn to_f64(self) -> f64;
    /// Converts a small integer, saturating at the type's range.
    #[must_use]
    fn from_i32(i: i32) -> Self;
    /// `num · 2^-shift`, exact whenever the result is representable (used for tables of
    /// gradients and lattice values, so that every number type starts from the same constants).
    ///
    /// Defined for every `shift`: otherwise floats round to nearest (a quotient below half the
    /// smallest subnormal is ±0) and fixed point rounds toward −∞ (so `2⁻¹⁷` is 0 and `−2⁻¹⁷`
    /// is `−2⁻¹⁶`); fixed point saturates when `num · 2^-shift` exceeds its range.
    ///
    /// ```
    /// use bandnoise::{I16F16, Real};
    ///
    /// assert_eq!(f32::from_ratio(-3, 2), -0.75);
    /// assert_eq!(f32::from_ratio(1, 126), f32::MIN_POSITIVE);
    /// assert_eq!(f64::from_ratio(-7, 70), -7.0 * 2f64.powi(-70));
    /// assert_eq!(I16F16::from_ratio(1, 80), I16F16::ZERO);
    /// assert_eq!(I16F16::from_ratio(1 << 20, 0), I16F16::MAX);
    /// ```
    #[must_use]
    fn from_ratio(num: i32, shift: u32) -> Self;

    /// [`from_ratio`](Self::from_ratio)`(num, shift)`, given `unit`, which must be
    /// `from_ratio(1, shift)`: the same value, for a loop over many numerators with one shift
    /// (a quantized wavelet tile's reads), where `unit` is computed once. Floats multiply by
    /// `unit` (the product `from_ratio` computes); fixed point shifts as `from_ratio` does
    /// (its `unit` rounds to 0 for a shift beyond 16).
    ///
    /// ```
    /// use bandnoise::{I16F16, Real};
    ///
    /// let unit = f32::from_ratio(1, 13);
    /// assert_eq!(f32::from_ratio_unit(-300, 13, unit), f32::from_ratio(-300, 13));
    /// let unit = I16F16::from_ratio(1, 20);
    /// assert_eq!(I16F16::from_ratio_unit(300, 20, unit), I16F16::from_ratio(300, 20));
    /// ```
    #[must_use]
    #[inline]
    fn from_ratio_unit(num: i32, shift: u32, unit: Self) -> Self {
        let _ = unit;
        Self::from_ratio(num, shift)
    }

    /// Splits a coordinate into its lattice cell `floor(x)` and the fraction `x − floor(x)` in
    /// `[0, 1)`.
    ///
    /// Defined for every input:
    /// * NaN and ±∞ give `(0, 0)`: a non-finite coordinate samples the origin.
    /// * `-0.0` gives `(0, 0)`.
    /// * A negative number so small that `x − floor(x)` rounds to 1 (e.g. `-1e-30`) gives the
    ///   next cell with fraction 0, the nearest representable point.
    /// * A cell outside `i32` wraps modulo 2³² (two's complement), like integer overflow in a
    ///   hash; such floats are integers anyway, so the fraction is 0.
    #[must_use]
    fn split(self) -> (i32, Self);

    /// [`split`](Self::split) of every lane, bit-identical to it, written so the compiler can
    /// vectorise it (the batch paths of [`crate::batch`] use it).
    #[inline]
    fn split_lanes(
        x: &[Self; crate::batch::LANES],
        cell: &mut [i32; crate::batch::LANES],
        frac: &mut [Self; crate::batch::LANES],
    ) {
        for l in 0..crate::batch::LANES {
            (cell[l], frac[l]) = x[l].split();
        }
    }

    /// Absolute value (saturating at `MAX` for fixed point's most negative value).
    #[must_use]
    fn abs(self) -> Self;
    /// Addition that saturates at the type's range in fixed point (plain IEEE `+` for floats).
    #[must_use]
    fn saturating_add(self, o: Self) -> Self;
    /// Multiplication that saturates in fixed point (plain IEEE `×` for floats).
    #[must_use]
    fn saturating_mul(self, o: Self) -> Self;
    /// Multiplication that wraps modulo the integer range in fixed point (plain IEEE `×` for
    /// floats). Scaling a coordinate by an octave frequency uses it: a wrapped fixed-point
    /// coordinate still lands on a lattice cell, so the result is defined.
    #[must_use]
    fn wrapping_mul(self, o: Self) -> Self;
    /// Multiplication rounded to nearest (ties up) in fixed point, plain IEEE `×` for floats.
    ///
    /// `fixed`'s `*` rounds toward −∞, a bias of −½ ulp per product that interpolation
    /// amplifies; the kernels use this instead wherever a product feeds the result. The
    /// operands' range is proved at each use, and the result saturates rather than wraps if a
    /// proof were ever wrong.
    #[must_use]
    fn mul_rn(self, o: Self) -> Self;
    /// Square root; negative inputs (and NaN) give 0. Floats use `libm` (correctly rounded, so
    /// identical everywhere); fixed point an integer square root, rounded to nearest (a
    /// truncated root biases sums of many kernel values).
    #[must_use]
    fn sqrt(self) -> Self;
    /// Division. Floats: IEEE `/`. Fixed point saturates, and a zero divisor gives `MAX` or
    /// `MIN` with the dividend's sign (0 for 0/0): callers guard against zero divisors anyway.
    #[must_use]
    fn div(self, o: Self) -> Self;
    /// Base-2 logarithm. For `x ≤ 0` (and NaN) it returns the most negative value of the type
    /// (−∞ for floats, `MIN` for fixed point); `+∞` gives `+∞`.
    #[must_use]
    fn log2(self) -> Self;
    /// Whether the value is NaN (never, for fixed point).
    #[must_use]
    fn is_nan(self) -> bool;
    /// Turns `-0.0` into `+0.0` and leaves every other value unchanged, so that results that are
    /// equal as numbers are equal bit for bit.
    #[must_use]
    fn canonical(self) -> Self;

    /// `e^{−self}` for `self ≥ 0` (the envelope of Gaussian kernels), from a const-built table
    /// with the same operations in every type (`special.rs` states the errors: 1.2e-7 in `f64`,
    /// 2e-7 in `f32`, 1e-4 in I16F16).
    ///
    /// Defined for every input: `self ≤ 0` gives 1 (the envelope's peak: kernels pass squared
    /// distances), `self ≥ 16` and `+∞` give 0 (`e^{−16}` is 1.1e-7), NaN gives 0. The result
    /// is in `[0, 1]`.
    ///
    /// # Examples
    ///
    /// ```
    /// use bandnoise::{I16F16, Real};
    ///
    /// assert!((2.0f32.exp_neg() - (-2.0f32).exp()).abs() < 3e-7);
    /// assert!((I16F16::from_num(2).exp_neg().to_num::<f32>() - 0.135_335).abs() < 1e-4);
    /// assert_eq!(f32::NAN.exp_neg(), 0.0);
    /// ```
    #[inline]
    #[must_use]
    fn exp_neg(self) -> Self {
        crate::special::exp_neg(self)
    }

    /// `cos 2π·self`: the cosine of `self` turns (the harmonic of Gabor kernels), from a
    /// const-built table with the same operations in every type (`special.rs` states the
    /// errors: 2e-8 in `f64`, 3e-7 in `f32`, 1e-4 in I16F16); exact at whole and half turns
    /// and at the zeros.
    ///
    /// Defined for every input: the whole turns are dropped exactly ([`split`](Self::split)),
    /// so NaN and ±∞ give 1, as does every float too large to have a fraction. The result is
    /// in `[−1, 1]`.
    ///
    /// # Examples
    ///
    /// ```
    /// use bandnoise::{I16F16, Real};
    ///
    /// assert!((0.125f32.cos_turns() - core::f32::consts::FRAC_1_SQRT_2).abs() < 3e-7);
    /// assert_eq!(0.25f32.cos_turns(), 0.0);
    /// assert_eq!(I16F16::from_num(-3).cos_turns(), I16F16::ONE);
    /// ```
    #[inline]
    #[must_use]
    fn cos_turns(self) -> Self {
        crate::special::cos_turns(self)
    }

    /// `self` clamped to `[lo, hi]`; NaN gives `lo`.
    #[inline]
    #[must_use]
    fn clamp_to(self, lo: Self, hi: Self) -> Self {
        if self >= lo {
            if self <= hi { self } else { hi }
        } else {
            lo
        }
    }
}

/// `num · 2^-shift` for shifts of 64 and more (beyond what `1u64 << shift` holds): exact in
/// `f64` down to 2⁻¹⁰²² (`ldexp` scales by powers of two), so the caller's conversion to its type
/// rounds once.
#[cold]
fn ratio_far(num: i32, shift: u32) -> f64 {
    // Past 1100 every `i32` quotient is below half of f64's smallest subnormal: ±0.
    libm::ldexp(num as f64, -(shift.min(1100) as i32))
}

/// Splits a float whose integer part does not fit `i32`, or that is not finite.
#[cold]
fn split_far(x: f64) -> (i32, f64) {
    if !x.is_finite() {
        return (0, 0.0);
    }
    // |x| >= 2^31 > 2^53 is false for f64 in general, so keep the fraction.
    let fl = libm::floor(x);
    let frac = x - fl;
    (low_bits(fl), frac)
}

/// The low 32 bits (two's complement) of the integer-valued finite `fl`: the cell modulo 2³²,
/// exactly, with integer operations (no `fmod` and its 128-bit division).
fn low_bits(fl: f64) -> i32 {
    if fl.abs() < 9_223_372_036_854_775_808.0 {
        // Below 2⁶³ the conversion is exact.
        return fl as i64 as i32;
    }
    // fl = m · 2^s with the 53-bit significand m and s ≥ 11: the low 32 bits of m << s.
    let bits = fl.to_bits();
    let m = (bits & ((1 << 52) - 1)) | 1 << 52;
    let s = ((bits >> 52) & 0x7FF) as u32 - 1075;
    let low = if s < 32 { (m << s) as u32 } else { 0 };
    (if fl < 0.0 { low.wrapping_neg() } else { low }) as i32
}

macro_rules! impl_real_float {
    ($t:ty, $log2:path, $sqrt:path) => {
        impl Real for $t {
            const ZERO: Self = 0.0;
            const ONE: Self = 1.0;
            const NEG_ONE: Self = -1.0;
            const MAX: Self = <$t>::MAX;

            #[inline]
            fn from_f32(v: f32) -> Self {
                v as $t
            }
            #[inline]
            fn to_f32(self) -> f32 {
                self as f32
            }
            #[inline]
            fn to_f64(self) -> f64 {
                self as f64
            }
            #[inline]
            fn from_i32(i: i32) -> Self {
                i as $t
            }
            #[inline]
            fn from_ratio(num: i32, shift: u32) -> Self {
                if shift < 64 {
                    // Multiplying by 2^−shift (a normal number of both types, built from its
                    // bits) rounds once, as dividing by 2^shift would: the same quotient of
                    // `num as $t`, exact whenever it is representable (see the trait). Not
                    // `/ (1u64 << shift) as $t`: a u64 → float conversion is about ten x86-64
                    // instructions and a call on soft-float targets, and this runs once per
                    // wavelet coefficient read.
                    let bias = (<$t>::MAX_EXP - 1) as u64;
                    let scale = <$t>::from_bits(
                        ((bias - shift as u64) << (<$t>::MANTISSA_DIGITS - 1)) as _,
                    );
                    num as $t * scale
                } else {
                    ratio_far(num, shift) as $t
                }
            }
            #[inline]
            fn from_ratio_unit(num: i32, shift: u32, unit: Self) -> Self {
                // `from_ratio`'s product, with its factor (`unit`) computed by the caller.
                if shift < 64 {
                    num as $t * unit
                } else {
                    ratio_far(num, shift) as $t
                }
            }
            // Out of line with the `small` feature: inlined at each of the many call sites it
            // cost the demo's wasm module 2 KB (for a call per coordinate).
            #[cfg_attr(feature = "small", inline(never))]
            #[cfg_attr(not(feature = "small"), inline)]
            fn split(self) -> (i32, Self) {
                /// In range, a truncating cast and one correction give floor() without libm;
                /// `as` is defined (saturating, NaN → 0) on every target.
                #[inline(always)]
                fn by_cast(x: $t) -> (i32, $t) {
                    if (-2_147_483_648.0..2_147_483_648.0).contains(&x) {
                        let t = x as i32;
                        let cell = if (t as $t) > x { t - 1 } else { t };
                        // Exact: both are in the same binade or the result is an integer.
                        let frac = x - cell as $t;
                        if frac >= 1.0 {
                            (cell.wrapping_add(1), 0.0)
                        } else {
                            // `+ 0.0` turns the -0.0 of -0.0 - 0.0 into +0.0.
                            (cell, frac + 0.0)
                        }
                    } else {
                        let (cell, frac) = split_far(x as f64);
                        (cell, frac as $t)
                    }
                }
                /// [`by_cast`] out of line, for coordinates beyond the x86 path.
                #[cold]
                #[inline(never)]
                fn far(x: $t) -> (i32, $t) {
                    by_cast(x)
                }
                // On x86, `as i32` saturates by clamping the float first (`maxss`, `minss`,
                // then a NaN check), and the cell goes back to a float for the fraction: a
                // long chain that every sample of a point path waits for. Within
                // `(-2^22, 2^22)`, adding `MAGIC = 1.5·2^mantissa` and subtracting it again
                // rounds to the nearest integer exactly, a float `r`; `floor` is `r` or
                // `r − 1`, and its integer is read from the bits of `floor + MAGIC`. Each
                // step is exact, so `frac` is `self − floor` rounded once, as in `by_cast`:
                // the same results bit for bit, in float additions and a compare
                // (bench/README.md). The choice of `1` or `0` is a select on a float compare:
                // where its condition was also used as an integer, the compiler branched on
                // it, a coin flip for the predictor. The rest of the range goes out of line,
                // so that the loops over axes that call this stay unrolled.
                const MAGIC: $t = 1.5 * (1u64 << (<$t>::MANTISSA_DIGITS - 1)) as $t;
                const LIMIT: $t = 4_194_304.0;
                if !cfg!(any(
                    target_arch = "x86_64",
                    all(target_arch = "x86", target_feature = "sse2")
                )) {
                    return by_cast(self);
                }
                if self.abs() < LIMIT {
                    let r = (self + MAGIC) - MAGIC;
                    let floor = r - if r > self { 1.0 } else { 0.0 };
                    // `(self + 0) − floor` is `(self − floor) + 0`, the fraction with `−0`
                    // made `+0` (`self − floor` is `−0` only for `self = −0`), but its `+ 0`
                    // runs beside the chain to the floor rather than after it.
                    let frac = (self + 0.0) - floor;
                    let cell = (floor + MAGIC).to_bits().wrapping_sub(MAGIC.to_bits()) as i32;
                    if frac >= 1.0 {
                        (cell.wrapping_add(1), 0.0)
                    } else {
                        (cell, frac)
                    }
                } else {
                    far(self)
                }
            }
            #[inline]
            fn split_lanes(
                x: &[Self; crate::batch::LANES],
                cell: &mut [i32; crate::batch::LANES],
                frac: &mut [Self; crate::batch::LANES],
            ) {
                // Every lane in `(-2^22, 2^22)` (checked without branches): adding
                // `MAGIC = 1.5·2^mantissa` rounds to an integer held in the low bits, read
                // without a float-to-int cast (whose saturation would not vectorise), then one
                // correction gives `floor` exactly; the rest is `split`'s in-range arithmetic, so
                // the results are the same bit for bit.
                const MAGIC: $t = 1.5 * (1u64 << (<$t>::MANTISSA_DIGITS - 1)) as $t;
                const LIMIT: $t = 4_194_304.0;
                let in_range = x.iter().fold(true, |ok, v| ok & (v.abs() < LIMIT));
                if in_range {
                    for l in 0..crate::batch::LANES {
                        let nearest =
                            ((x[l] + MAGIC).to_bits().wrapping_sub(MAGIC.to_bits())) as i32;
                        let c = nearest.wrapping_sub(((nearest as $t) > x[l]) as i32);
                        let f = x[l] - c as $t;
                        let up = f >= 1.0;
                        cell[l] = c.wrapping_add(up as i32);
                        frac[l] = if up { 0.0 } else { f + 0.0 };
                    }
                } else {
                    // Out of line: a lane this far out is rare, and with `split`'s code here
                    // the compiler stopped inlining this function.
                    #[cold]
                    #[inline(never)]
                    fn each(
                        x: &[$t; crate::batch::LANES],
                        cell: &mut [i32; crate::batch::LANES],
                        frac: &mut [$t; crate::batch::LANES],
                    ) {
                        for l in 0..crate::batch::LANES {
                            (cell[l], frac[l]) = x[l].split();
                        }
                    }
                    each(x, cell, frac);
                }
            }
            #[inline]
            fn abs(self) -> Self {
                if self < 0.0 { -self } else { self }
            }
            #[inline]
            fn saturating_add(self, o: Self) -> Self {
                self + o
            }
            #[inline]
            fn saturating_mul(self, o: Self) -> Self {
                self * o
            }
            #[inline]
            fn wrapping_mul(self, o: Self) -> Self {
                self * o
            }
            #[inline]
            fn mul_rn(self, o: Self) -> Self {
                self * o
            }
            #[inline]
            fn sqrt(self) -> Self {
                if self > 0.0 { $sqrt(self) } else { 0.0 }
            }
            #[inline]
            fn div(self, o: Self) -> Self {
                self / o
            }
            #[inline]
            fn log2(self) -> Self {
                if self > 0.0 {
                    $log2(self)
                } else {
                    <$t>::NEG_INFINITY
                }
            }
            #[inline]
            fn is_nan(self) -> bool {
                self != self
            }
            #[inline]
            fn canonical(self) -> Self {
                self + 0.0
            }
        }
    };
}

impl_real_float!(f32, libm::log2f, libm::sqrtf);
impl_real_float!(f64, libm::log2, libm::sqrt);

/// Base-2 logarithm of a positive I16F16 given by its raw bits, by the exact bit-by-bit
/// method (repeated squaring of the mantissa), so it needs no floating point at all.
fn log2_fixed_bits(bits: i32) -> i32 {
    debug_assert!(bits > 0);
    let msb = 31 - bits.leading_zeros() as i32; // bits in [2^msb, 2^(msb+1))
    let int_part = msb - 16;
    // Mantissa m = bits / 2^msb in [1, 2), held in Q1.30.
    let mut m: u64 = ((bits as u64) << 30) >> msb;
    let mut frac: i32 = 0;
    for k in (0..16).rev() {
        m = (m * m) >> 30;
        if m >= 2 << 30 {
            m >>= 1;
            frac |= 1 << k;
        }
    }
    (int_part << 16) | frac
}

/// `√v` rounded to nearest, by the digit-by-digit method (integers only, 24 steps for 48
/// bits) and the floor's remainder: `v − r² > r` means `v > (r + ½)² − ¼`, so `r + 1` is
/// nearer.
fn isqrt(v: u64) -> u64 {
    let (mut rem, mut root) = (v, 0u64);
    let mut bit = 1u64 << 62;
    while bit > v {
        bit >>= 2;
    }
    while bit != 0 {
        if rem >= root + bit {
            rem -= root + bit;
            root = (root >> 1) + bit;
        } else {
            root >>= 1;
        }
        bit >>= 2;
    }
    if rem > root { root + 1 } else { root }
}

impl Real for I16F16 {
    const ZERO: Self = I16F16::ZERO;
    const ONE: Self = I16F16::ONE;
    const NEG_ONE: Self = I16F16::NEG_ONE;
    const MAX: Self = I16F16::MAX;

    #[inline]
    fn from_f32(v: f32) -> Self {
        fixed_from_float(v)
    }
    #[inline]
    fn to_f32(self) -> f32 {
        self.to_num::<f32>()
    }
    #[inline]
    fn to_f64(self) -> f64 {
        self.to_num::<f64>()
    }
    #[inline]
    fn from_i32(i: i32) -> Self {
        I16F16::saturating_from_num(i)
    }
    #[inline]
    fn from_ratio(num: i32, shift: u32) -> Self {
        let bits = if shift <= 16 {
            (num as i64) << (16 - shift)
        } else {
            // Rounds toward −∞; a shift of 63 already leaves only the sign of an `i32`.
            (num as i64) >> (shift - 16).min(63)
        };
        I16F16::from_bits(bits.clamp(i32::MIN as i64, i32::MAX as i64) as i32)
    }
    #[inline]
    fn split(self) -> (i32, Self) {
        let bits = self.to_bits();
        (bits >> 16, I16F16::from_bits(bits & 0xFFFF))
    }
    #[inline]
    fn abs(self) -> Self {
        self.saturating_abs()
    }
    #[inline]
    fn saturating_add(self, o: Self) -> Self {
        I16F16::saturating_add(self, o)
    }
    #[inline]
    fn saturating_mul(self, o: Self) -> Self {
        // ARMv6-M has no 32 × 32 → 64-bit multiply: small factors take 32-bit ones.
        #[cfg(bandnoise_armv6m)]
        return I16F16::from_bits(saturating_mul_halves(self.to_bits(), o.to_bits()));
        #[cfg(not(bandnoise_armv6m))]
        I16F16::saturating_mul(self, o)
    }
    #[inline]
    fn wrapping_mul(self, o: Self) -> Self {
        #[cfg(bandnoise_armv6m)]
        return I16F16::from_bits(mul_floor_halves(self.to_bits(), o.to_bits()));
        #[cfg(not(bandnoise_armv6m))]
        I16F16::wrapping_mul(self, o)
    }
    #[inline]
    fn mul_rn(self, o: Self) -> Self {
        let wide = (self.to_bits() as i64 * o.to_bits() as i64 + (1 << 15)) >> 16;
        I16F16::from_bits(wide.clamp(i32::MIN as i64, i32::MAX as i64) as i32)
    }
    #[inline]
    fn sqrt(self) -> Self {
        let bits = self.to_bits();
        if bits <= 0 {
            return I16F16::ZERO;
        }
        // sqrt(b / 2^16) = sqrt(b · 2^16) / 2^16: integer square root of a 48-bit number.
        I16F16::from_bits(isqrt((bits as u64) << 16) as i32)
    }
    #[inline]
    fn div(self, o: Self) -> Self {
        if o == I16F16::ZERO {
            return match self.to_bits() {
                0 => I16F16::ZERO,
                b if b > 0 => I16F16::MAX,
                _ => I16F16::MIN,
            };
        }
        self.saturating_div(o)
    }
    #[inline]
    fn log2(self) -> Self {
        if self.to_bits() > 0 {
            I16F16::from_bits(log2_fixed_bits(self.to_bits()))
        } else {
            I16F16::MIN
        }
    }
    #[inline]
    fn is_nan(self) -> bool {
        false
    }
    #[inline]
    fn canonical(self) -> Self {
        self
    }
}

#[cfg(test)]
mod tests {
    use super::sealed::Sealed;
    use super::*;

    /// Floats' `from_ratio` (a product by 2^−shift built from its bits) is the quotient by
    /// 2^shift, bit for bit, for every shift below 64 and numerators of every magnitude
    /// (rounded to the type first, subnormal and zero results included).
    #[test]
    fn float_ratios_are_quotients_by_powers_of_two() {
        let mut x = 0x2545_f491u32;
        let random = core::iter::repeat_with(move || {
            x ^= x << 13;
            x ^= x >> 17;
            x ^= x << 5;
            x as i32 >> (x % 31)
        });
        let edges = [0, 1, -1, 3, -7, 65535, i32::MAX, i32::MIN, (1 << 24) + 1];
        for shift in 0..64u32 {
            for num in edges.into_iter().chain(random.take(200)) {
                let (a, b) = (
                    f32::from_ratio(num, shift),
                    num as f32 / (1u64 << shift) as f32,
                );
                assert_eq!(a.to_bits(), b.to_bits(), "f32 {num} / 2^{shift}");
                let (a, b) = (
                    f64::from_ratio(num, shift),
                    num as f64 / (1u64 << shift) as f64,
                );
                assert_eq!(a.to_bits(), b.to_bits(), "f64 {num} / 2^{shift}");
            }
        }
    }

    /// `low_bits` equals the remainder modulo 2³² that `fmod` gives, around every boundary.
    #[test]
    fn low_bits_is_the_cell_modulo_2_32() {
        for e in 30..1024 {
            let p = libm::ldexp(1.0, e);
            for v in [
                p,
                p + 1.0,
                p - 1.0,
                p * 1.5,
                p * 1.999_999_999,
                p + 4_294_967_297.0,
            ] {
                for x in [v, -v] {
                    let x = libm::floor(x);
                    let want = libm::fmod(x, 4_294_967_296.0) as i64 as i32;
                    assert_eq!(super::low_bits(x), want, "{x:e}");
                }
            }
        }
    }

    /// A small generator for the multiply tests (xorshift64, low 32 bits).
    fn xorshift(mut x: u64) -> impl FnMut() -> u32 {
        move || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x as u32
        }
    }

    /// `mul_fraction` (the form this target selects, and ARMv6-M's 16-bit halves) gives
    /// `mul_rn`'s bits wherever the product fits: every `self` in `[0, 2]` with `|o| < 2¹⁴`,
    /// every `self` in `[0, 1]` with any `o`, and any pair of factors below 2⁷.
    #[test]
    fn mul_fraction_is_mul_rn() {
        let mut next = xorshift(0x2545_f491_4f6c_dd1d);
        let check = |a: i32, b: i32| {
            let (fa, fb) = (I16F16::from_bits(a), I16F16::from_bits(b));
            let want = fa.mul_rn(fb).to_bits();
            assert_eq!(fa.mul_fraction(fb).to_bits(), want, "{a:#x} · {b:#x}");
            assert_eq!(mul_fraction_halves(a, b), want, "{a:#x} · {b:#x}");
        };
        let limit = (1 << 30) - 1;
        for a in [
            0, 1, 2, 0x7FFF, 0x8000, 0xFFFF, 0x1_0000, 0x1_0001, 0x1_FFFF, 0x2_0000,
        ] {
            for b in [0, 1, -1, 0xFFFF, 0x1_0000, -0x1_0000, 0x8000, limit, -limit] {
                check(a, b);
                check(-a, b);
            }
        }
        for _ in 0..1_000_000 {
            check(
                (next() & 0x3_FFFF).min(0x2_0000) as i32,
                (next() as i32) >> 1,
            );
            check((next() & 0x1_FFFF).min(0x1_0000) as i32, next() as i32);
            check((next() as i32) >> 9, (next() as i32) >> 9);
        }
    }

    /// The 32-bit forms of `wrapping_mul` and `saturating_mul` used on ARMv6-M give fixed's
    /// bits: any pairs (wrapping), small and large pairs either side of the fast path's limit.
    #[test]
    fn halves_are_fixed_products() {
        let mut next = xorshift(0x9e37_79b9_7f4a_7c15);
        let check = |a: i32, b: i32| {
            let (fa, fb) = (I16F16::from_bits(a), I16F16::from_bits(b));
            assert_eq!(
                mul_floor_halves(a, b),
                fa.wrapping_mul(fb).to_bits(),
                "{a:#x}·{b:#x}"
            );
            let sat = fa.saturating_mul(fb).to_bits();
            assert_eq!(saturating_mul_halves(a, b), sat, "{a:#x}·{b:#x}");
        };
        let edges = [
            0,
            1,
            -1,
            0xFFFF,
            0x1_0000,
            -0x1_0000,
            0x7F_FFFF,
            -0x7F_FFFF,
            0x80_0000,
            -0x80_0000,
            i32::MAX,
            i32::MIN,
        ];
        for a in edges {
            for b in edges {
                check(a, b);
            }
        }
        for _ in 0..1_000_000 {
            check(next() as i32, next() as i32);
            check((next() as i32) >> 8, (next() as i32) >> 8);
            check((next() as i32) >> 9, (next() as i32) >> 9);
            check((next() as i32) >> 12, next() as i32);
        }
    }

    /// `mul_unit` by −1, 0 and 1 equals `mul_rn` (as numbers) over the range the kernels pass.
    fn mul_unit_is_mul_rn<R: Real>(values: impl Iterator<Item = R>) {
        for x in values {
            for unit in [R::NEG_ONE, R::ZERO, R::ONE] {
                assert_eq!(
                    x.mul_unit(unit).canonical(),
                    x.mul_rn(unit).canonical(),
                    "{x:?} · {unit:?}"
                );
            }
        }
    }

    #[test]
    fn mul_unit_multiplies_by_units_exactly() {
        let fractions = (-2000..=2000).map(|i| i as f64 / 1000.0 + 1e-7);
        mul_unit_is_mul_rn(fractions.clone());
        mul_unit_is_mul_rn(fractions.clone().map(|x| x as f32));
        mul_unit_is_mul_rn(fractions.map(I16F16::from_num));
        mul_unit_is_mul_rn(
            [
                I16F16::from_bits(1),
                I16F16::from_bits(-1),
                I16F16::from_bits(0x1_ffff),
            ]
            .into_iter(),
        );
        assert_eq!(
            I16F16::from_num(0.75).mul_unit(I16F16::NEG_ONE),
            I16F16::from_num(-0.75)
        );
    }

    #[test]
    fn split_floats_edges() {
        assert_eq!(3.25f32.split(), (3, 0.25));
        assert_eq!((-3.25f64).split(), (-4, 0.75));
        assert_eq!((-0.0f32).split().1.to_bits(), 0.0f32.to_bits());
        assert_eq!((-1e-30f32).split(), (0, 0.0));
        assert_eq!(f32::NAN.split(), (0, 0.0));
        assert_eq!(f64::INFINITY.split(), (0, 0.0));
        assert_eq!(f32::NEG_INFINITY.split(), (0, 0.0));
        // The largest f32 below 2^31 and -2^31 itself stay in range.
        assert_eq!(2_147_483_520.0f32.split(), (2_147_483_520, 0.0));
        assert_eq!((-2_147_483_648.0f32).split(), (i32::MIN, 0.0));
        // f64 can hold a fraction at i32::MAX.
        assert_eq!(2_147_483_647.5f64.split(), (i32::MAX, 0.5));
        // Beyond i32 the cell wraps modulo 2^32.
        assert_eq!(2_147_483_648.0f32.split(), (i32::MIN, 0.0));
        assert_eq!(4_294_967_296.0f64.split(), (0, 0.0));
        assert_eq!((-4_294_967_297.0f64).split(), (-1, 0.0));
        let (_, f) = 1e30f32.split();
        assert_eq!(f, 0.0);
        let tiny = f32::from_bits(1); // smallest subnormal
        assert_eq!(tiny.split(), (0, tiny));
        assert_eq!((-tiny).split(), (0, 0.0));
    }

    /// `split` against its definition (`floor`, the fraction rounded once, a fraction that
    /// rounds to 1 carried), with libm's `floor`: over every binade of both types, at and
    /// beside integers, across the bounds of the x86 path (`±2²²`) and of `i32`. On x86 this
    /// checks the path by adding `1.5·2^mantissa`; elsewhere the truncating cast.
    #[test]
    fn split_is_floor_and_fraction() {
        macro_rules! check {
            ($t:ty, $floor:path, $x:expr) => {{
                let x: $t = $x;
                let floor = $floor(x);
                // Beyond `i32` the cell wraps (`split_floats_edges`).
                if floor.abs() < 2_147_483_648.0 {
                    let cell = floor as i64 as i32;
                    let frac = x - floor;
                    let want = if frac >= 1.0 {
                        (cell.wrapping_add(1), 0.0)
                    } else {
                        (cell, frac + 0.0)
                    };
                    let got = x.split();
                    assert!(
                        got.0 == want.0 && got.1.to_bits() == want.1.to_bits(),
                        "{x:e}: {got:?} against {want:?}"
                    );
                }
            }};
        }
        let mut state = 0x9E37_79B9_7F4A_7C15u64;
        let mut next = || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            state
        };
        for _ in 0..200_000 {
            let bits = next();
            check!(f32, libm::floorf, f32::from_bits((bits >> 32) as u32));
            check!(f64, libm::floor, f64::from_bits(bits));
            // Coordinates a sampler meets: below 2²⁴ in magnitude, every binade down to 2⁻⁴⁰.
            let e = (bits % 64) as i32 - 40;
            let m = (bits >> 8) as u32 as f64 / 4_294_967_296.0 + 1.0;
            let v = m * libm::exp2(f64::from(e)) * if bits & 128 == 0 { 1.0 } else { -1.0 };
            check!(f32, libm::floorf, v as f32);
            check!(f64, libm::floor, v);
        }
        for i in -4_194_310i32..=4_194_310 {
            if i.unsigned_abs() > 64 && i.unsigned_abs() < 4_194_300 && i % 97 != 0 {
                continue;
            }
            let x = i as f32;
            for v in [x, x.next_up(), x.next_down(), x + 0.5] {
                check!(f32, libm::floorf, v);
            }
            let x = f64::from(i);
            for v in [x, x.next_up(), x.next_down(), x + 0.5] {
                check!(f64, libm::floor, v);
            }
        }
        for v in [0.0, -0.0, 1e-45, -1e-45, 2_147_483_520.0, -2_147_483_648.0] {
            check!(f32, libm::floorf, v);
            check!(f64, libm::floor, f64::from(v));
        }
    }

    #[test]
    fn split_fixed() {
        assert_eq!(I16F16::MIN.split(), (-32768, I16F16::ZERO));
        assert_eq!(I16F16::MAX.split(), (32767, I16F16::from_bits(0xFFFF)));
        assert_eq!(I16F16::from_f32(-0.5).split(), (-1, I16F16::from_f32(0.5)));
    }

    #[test]
    fn fixed_log2_matches_f64() {
        for bits in (1..i32::MAX).step_by(7919) {
            let x = I16F16::from_bits(bits);
            let got = x.log2().to_f64();
            let want = libm::log2(x.to_f64());
            // Truncated to 16 fraction bits, plus the truncation of each squaring.
            assert!(
                (got - want).abs() <= 2.0 / 65536.0,
                "{bits}: {got} vs {want}"
            );
        }
        assert_eq!(I16F16::ZERO.log2(), I16F16::MIN);
        assert_eq!(I16F16::from_i32(-3).log2(), I16F16::MIN);
        assert_eq!(I16F16::ONE.log2(), I16F16::ZERO);
        assert_eq!(I16F16::from_i32(1024).log2(), I16F16::from_i32(10));
    }

    #[test]
    fn fixed_sqrt_and_div() {
        for bits in (0..i32::MAX).step_by(104_729) {
            let x = I16F16::from_bits(bits);
            let r = Real::sqrt(x).to_bits() as u64;
            let v = (bits as u64) << 16;
            // Rounded to nearest: r² − r < v ≤ r² + r.
            assert!((r * r < v + r || v == 0) && v <= r * r + r, "{bits}");
        }
        assert_eq!(Real::sqrt(I16F16::from_i32(-4)), I16F16::ZERO);
        assert_eq!(Real::sqrt(I16F16::from_i32(9)), I16F16::from_i32(3));
        assert_eq!(Real::div(I16F16::ONE, I16F16::ZERO), I16F16::MAX);
        assert_eq!(Real::div(-I16F16::ONE, I16F16::ZERO), I16F16::MIN);
        assert_eq!(Real::div(I16F16::ZERO, I16F16::ZERO), I16F16::ZERO);
        assert_eq!(Real::div(I16F16::MAX, I16F16::DELTA), I16F16::MAX);
        assert_eq!(Real::sqrt(-1.0f32), 0.0);
    }

    #[test]
    fn conversions_saturate() {
        assert_eq!(I16F16::from_f32(f32::NAN), I16F16::ZERO);
        assert_eq!(I16F16::from_f32(1e30), I16F16::MAX);
        assert_eq!(I16F16::from_f32(-1e30), I16F16::MIN);
        assert_eq!(I16F16::from_ratio(3, 2), I16F16::from_f32(0.75));
        assert_eq!(f32::from_ratio(-3, 2), -0.75);
        assert_eq!(Real::abs(I16F16::MIN), I16F16::MAX);
        assert_eq!(f32::NAN.clamp_to(0.0, 1.0), 0.0);
    }
}

//! Olano's Blum-Blum-Shub hash `x² mod M` (Olano 2005, "Modified Noise for Evaluation on Graphics
//! Hardware", §3.3).
//!
//! A real BBS generator uses `M = p·q` for large primes; Olano keeps one squaring step with a small
//! prime `M` so that every intermediate value is an exact small integer: with the paper's `M = 61`
//! and arguments reduced mod `M` before squaring, no value exceeds `60² = 3600`, which fits an `i16`
//! and is exact in `f32`. The largest prime whose square is exact in `f32` (below 2²⁴) is 4093.
//!
//! The same hash is computed two ways that agree for every input (tested exhaustively):
//! the integer path [`Bbs::hash`] and the all-float path [`Bbs::hash_f32`], which reduces with
//! Olano's five-instruction `i − floor(i/M)·M` as a GPU or SIMD unit would.

/// The hash `x² mod M` for a prime modulus `M` (default 61, the paper's).
///
/// Every function is total: any `i32` (negative, `i32::MIN`) and any `f32` (NaN and ±∞ hash
/// as 0) gives a value in `0..M`, never a panic; checked against a 64-bit reference by the fuzz
/// target `hash`.
///
/// `M` must lie in `2..=4093` so that the square of a reduced argument is exact in `f32`; this is
/// checked at compile time.
///
/// # Examples
///
/// ```
/// use bandnoise::hash::Bbs;
///
/// assert_eq!(Bbs::<61>::hash(10), 100 % 61);
/// assert_eq!(Bbs::<61>::hash(-1), 1); // reduced first: -1 ≡ 60, 60² = 3600 ≡ 1
/// type H = Bbs<61>;
/// let chained = H::hash(1 + H::hash(2 + H::hash(3) as i32) as i32);
/// assert_eq!(H::hash3(1, 2, 3), chained);
/// assert_eq!(Bbs::<4093>::hash_f32(-12345.0), Bbs::<4093>::hash(-12345) as f32);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Bbs<const M: u32 = 61>;

impl<const M: u32> Bbs<M> {
    const VALID: () = assert!(M >= 2 && M <= 4093, "Bbs modulus must be in 2..=4093");

    /// The modulus, which is also the period of the hash.
    pub const MODULUS: u32 = M;

    /// `x mod M` in `0..M` for any `i32` (Euclidean remainder).
    #[inline]
    #[must_use]
    pub const fn reduce(x: i32) -> u32 {
        let () = Self::VALID;
        x.rem_euclid(M as i32) as u32
    }

    /// `(c + offset) mod M` for any cell `c` and an `offset` in `0..M` (a seed's translation
    /// of the lattice), in `0..M`.
    ///
    /// On 32-bit targets (firmware, wasm32), where a signed division by a constant needs a
    /// 32 × 32 → 64-bit multiply (a library call on ARMv6-M): every cell of an I16F16 point
    /// lies in `−2¹⁵..2¹⁵`, and there ([`Self::SMALL`]) the biased sum `u = c + B + offset`,
    /// with `B` the least multiple of `M` from 2¹⁵, is non-negative and below 2¹⁷, and one
    /// 32-bit reciprocal multiply divides it exactly (the argument of [`Self::DIRECT`]): a
    /// multiply, a shift, a multiply and a subtraction instead of a signed division, its sign
    /// correction and a second reduction after the offset (about 11 instructions per axis on
    /// the Cortex-M0). Other cells, moduli without such a reciprocal, and 64-bit targets
    /// (whose division by a constant is one multiply, and where the two forms cost the same
    /// within 2%) reduce the cell first, then the offset sum. The forms give the same value
    /// for every input (tested exhaustively over the small range, at its edges and beyond).
    #[inline]
    #[must_use]
    pub(crate) const fn reduce_offset(c: i32, offset: u32) -> u32 {
        if cfg!(target_pointer_width = "64") {
            Self::reduce_offset_wide(c, offset)
        } else {
            Self::reduce_offset_narrow(c, offset)
        }
    }

    /// [`reduce_offset`](Self::reduce_offset) for 64-bit targets and large cells: the cell
    /// reduced, then offset and reduced once more.
    #[inline]
    const fn reduce_offset_wide(c: i32, offset: u32) -> u32 {
        let r = Self::reduce(c) + offset;
        if r >= M { r - M } else { r }
    }

    /// [`reduce_offset`](Self::reduce_offset) in 32-bit arithmetic.
    #[inline]
    const fn reduce_offset_narrow(c: i32, offset: u32) -> u32 {
        let () = Self::VALID;
        debug_assert!(offset < M);
        let (bias, shift, magic) = Self::SMALL;
        // For an I16F16 cell (an arithmetic shift by 16) the compiler proves this range.
        if magic != 0 && c >= -32768 && c < 32768 {
            // c + bias ≥ 0 since bias ≥ 2^15; the sum stays below 2^17 (see SMALL).
            let u = (c + bias as i32) as u32 + offset;
            return u - ((u * magic) >> shift) * M;
        }
        Self::reduce_offset_wide(c, offset)
    }

    /// `(B, s, m)` for [`Self::reduce_offset`]: `B` the least multiple of `M` from 2¹⁵, and a
    /// shift and reciprocal `m = ⌈2^s/M⌉` with which `(u·m) >> s = ⌊u/M⌋` for every
    /// `u ≤ B + 2¹⁵ − 1 + M − 1` (the largest biased sum) in 32-bit arithmetic, or `m = 0`
    /// where none exists. Exact when `u·e < 2^s` for the excess `e = m·M − 2^s`, and
    /// `u·m < 2³²` keeps the product in 32 bits. For `M = 61`: `B = 32818`, `s = 21`.
    const SMALL: (u32, u32, u32) = {
        let bias = 32768u32.div_ceil(M) * M;
        let max = (bias + 32767 + (M - 1)) as u64;
        let mut s = 32;
        let mut found = (bias, 0, 0);
        while s > 0 {
            s -= 1;
            let m = (1u64 << s).div_ceil(M as u64);
            let e = m * M as u64 - (1 << s);
            if max * m < 1 << 32 && max * e < 1 << s {
                found = (bias, s, m as u32);
                break;
            }
        }
        found
    };

    /// Both forms of [`reduce_offset`](Self::reduce_offset) against `rem_euclid` for every
    /// cell in `−2¹⁵..2¹⁵` (the reciprocal's range) and a few beyond, every offset: true when
    /// they all agree.
    #[doc(hidden)]
    #[must_use]
    pub fn reduce_offset_is_exact() -> bool {
        let beyond = [
            i32::MIN,
            i32::MIN + 1,
            -32769,
            32768,
            32769,
            i32::MAX - 1,
            i32::MAX,
        ];
        (0..M).all(|o| {
            (-32768..32768).chain(beyond).all(|c| {
                let want = (c as i64 + o as i64).rem_euclid(M as i64) as u32;
                Self::reduce_offset_narrow(c, o) == want && Self::reduce_offset_wide(c, o) == want
            })
        })
    }

    /// [`reduce`](Self::reduce) of every lane, equal to it for every input, vectorisable: while
    /// every `|x| < 2²⁴ − 8192` the quotient comes from an `f32` division, floored by a
    /// truncating cast and one correction, and the remainder is corrected once each way (the
    /// same argument as [`reduce_f32`](Self::reduce_f32)); otherwise lane by lane with `%`.
    /// Exhaustively tested against `reduce` over that range (`tests/tests/hash.rs`).
    #[inline]
    #[must_use]
    pub fn reduce_lanes(x: &[i32; crate::batch::LANES]) -> [u32; crate::batch::LANES] {
        let () = Self::VALID;
        const FAST: i32 = 16_777_216 - 8192;
        if x.iter().all(|&v| (-FAST..=FAST).contains(&v)) {
            x.map(|v| {
                let q = v as f32 / M as f32;
                let t = q as i32;
                let q = t - ((t as f32) > q) as i32;
                let r = v - q * M as i32;
                let r = if r < 0 { r + M as i32 } else { r };
                (if r >= M as i32 { r - M as i32 } else { r }) as u32
            })
        } else {
            x.map(Self::reduce)
        }
    }

    /// `ceil(log2(M))`.
    const BITS: u32 = u32::BITS - (M - 1).leading_zeros();
    /// Whether [`Self::mod_square`] can use a 32-bit reciprocal: with `s = 31 − BITS`, it needs
    /// `2^s ≥ M²` (error below one), i.e. `3·BITS ≤ 31`; then `v·⌈2^s/M⌉ ≤ M·2^s + M² < 2^32`.
    const RECIPROCAL: bool = 3 * Self::BITS <= 31;
    /// The shift and the reciprocal `ceil(2^s / M)`.
    const SHIFT: u32 = 31 - Self::BITS;
    const MAGIC: u32 = if Self::RECIPROCAL {
        ((1u64 << Self::SHIFT) as u32).div_ceil(M)
    } else {
        0
    };

    /// A shift `s` and reciprocal `m = ⌈2^s/M⌉` with which `(v·m) >> s` is exactly `⌊v/M⌋` for
    /// every `v ≤ (2M)²` in 32-bit arithmetic, or `m = 0` where no shift gives both. With the
    /// reciprocal's excess `e = m·M − 2^s < M`, `v·m / 2^s = ⌊v/M⌋ + (v mod M + v·e/2^s)/M`, so
    /// the quotient is exact when `v·e < 2^s`; and `v·m < 2^32` keeps it in 32 bits. The search
    /// takes the largest such shift (for `M = 61`: `s = 24`). Every `M` up to 131 has one (and
    /// powers of two); then a hash step squares its unreduced argument and divides once, by a
    /// multiply.
    const DIRECT: (u32, u32) = {
        let v = 4 * (M as u64) * (M as u64);
        let mut s = 32;
        let mut found = (0, 0);
        while s > 0 {
            s -= 1;
            let m = (1u64 << s).div_ceil(M as u64);
            let e = m * M as u64 - (1 << s);
            if v * m < 1 << 32 && v * e < 1 << s {
                found = (s, m as u32);
                break;
            }
        }
        found
    };

    /// `v mod M` for `v ≤ (2M)²` by [`Self::DIRECT`]'s reciprocal; call only where it exists.
    #[inline]
    #[must_use]
    const fn mod_direct(v: u32) -> u32 {
        let (shift, magic) = Self::DIRECT;
        v - ((v * magic) >> shift) * M
    }

    /// `v mod M` for `v ≤ M²` (a square of a reduced value).
    ///
    /// For `M ≤ 1024` (the moduli without [`Self::DIRECT`] use it): `q = (v · ⌈2^s/M⌉) >> s` is
    /// `⌊v/M⌋` or one more, because the reciprocal's error times `v < M² ≤ 2^s` stays below 1;
    /// one correction makes it exact. A 32-bit multiply replaces a division: chips without a
    /// divider (Cortex-M0) save most. Exhaustively tested against `%` (`tests/tests/hash.rs`).
    #[inline]
    #[must_use]
    const fn mod_square(v: u32) -> u32 {
        if Self::RECIPROCAL {
            let q = (v * Self::MAGIC) >> Self::SHIFT;
            let r = v.wrapping_sub(q * M);
            if r > v { r.wrapping_add(M) } else { r }
        } else {
            v % M
        }
    }

    /// One step of the hash for an argument in `0..=2M`: `(x mod M)² mod M`.
    /// The chains only ever add a reduced cell (at most `M` for the upper corner) to a previous
    /// hash (below `M`). `x² ≡ (x mod M)²`, so with [`Self::DIRECT`] the square of `x` itself
    /// is reduced once; otherwise one conditional subtraction reduces `x` first.
    #[inline]
    #[must_use]
    pub(crate) const fn step(x: u32) -> u32 {
        let () = Self::VALID;
        debug_assert!(x <= 2 * M);
        if Self::DIRECT.1 != 0 {
            return Self::mod_direct(x * x);
        }
        // r may equal M when x = 2M; M² mod M = 0 = (2M mod M)², so the result is still exact.
        let r = if x >= M { x - M } else { x };
        Self::mod_square(r * r)
    }

    /// `step` for every argument in `0..=2M`, against `%`: true when they all agree.
    #[doc(hidden)]
    #[must_use]
    pub fn step_is_exact() -> bool {
        (0..=2 * M).all(|x| Self::step(x) == (x % M) * (x % M) % M)
            && (0..=M * M).all(|v| Self::mod_square(v) == v % M)
    }

    /// `(x mod M)² mod M`, with `x` reduced into `0..M` before squaring so nothing overflows.
    #[inline]
    #[must_use]
    pub const fn hash(x: i32) -> u32 {
        let r = Self::reduce(x);
        (r * r) % M
    }

    /// `hash(x + hash(y))`, the 2D chain (the innermost hash takes the last axis).
    #[inline]
    #[must_use]
    pub const fn hash2(x: i32, y: i32) -> u32 {
        Self::step(Self::reduce(x) + Self::hash(y))
    }

    /// `hash(x + hash(y + hash(z)))`, Olano's 3D chain.
    #[inline]
    #[must_use]
    pub const fn hash3(x: i32, y: i32, z: i32) -> u32 {
        Self::step(Self::reduce(x) + Self::hash2(y, z))
    }

    /// `hash(x + hash(y + hash(z + hash(w))))`, the 4D chain.
    #[inline]
    #[must_use]
    pub const fn hash4(x: i32, y: i32, z: i32, w: i32) -> u32 {
        Self::step(Self::reduce(x) + Self::hash3(y, z, w))
    }

    /// `i mod M` in floating point, Olano's `i − floor(i/M)·M`, for an integer-valued `i`.
    ///
    /// `i/M` is rounded, so `floor` can be off by one next to a multiple of `M`; one correction
    /// each way fixes that. The product `floor(i/M)·M` can exceed `|i|` by up to `2M`, so the
    /// formula is exact while `|i| ≤ 2²⁴ − 8192` (every product stays below 2²⁴). Larger
    /// magnitudes use `fmod`, which is exact for every float. A non-integer `i` is floored first;
    /// NaN and ±∞ reduce to 0.
    #[inline]
    #[must_use]
    pub fn reduce_f32(i: f32) -> f32 {
        let () = Self::VALID;
        let m = M as f32;
        const FAST: f32 = 16_777_216.0 - 8192.0;
        if !(-FAST..=FAST).contains(&i) {
            if !i.is_finite() {
                return 0.0;
            }
            let r = libm::fmodf(i, m);
            return if r < 0.0 { r + m } else { r };
        }
        let i = libm::floorf(i);
        let r = i - libm::floorf(i / m) * m;
        if r < 0.0 {
            r + m
        } else if r >= m {
            r - m
        } else {
            r
        }
    }

    /// The hash computed entirely in `f32`: `reduce_f32(reduce_f32(i)²)`. Equal to
    /// `hash(i) as f32` for every integer `i32` that `f32` holds exactly, and defined (and
    /// exact against a 64-bit reference) for every `f32`.
    #[inline]
    #[must_use]
    pub fn hash_f32(i: f32) -> f32 {
        let r = Self::reduce_f32(i);
        Self::reduce_f32(r * r)
    }
}

//! Decimal text to `f32`, correctly rounded, with no panic path.
//!
//! The runtime description's text form ([`crate::spec`]) writes its floats with `f32`'s
//! `Display` (the shortest decimal that reads back to the same bits) and must read them back
//! exactly. `core`'s `f32::from_str` does that, but it keeps bounds-checked panics the
//! optimiser cannot remove (the firmware's no-panic proof fails on them) and about 20 KiB of
//! code and tables on a Cortex-M. The text form needs far less: plain decimal notation
//! (`-`, digits, one `.`), at most [`MAX_DIGITS`] digits, so the value is `D / 10^k` with `D`
//! and `10^k` below 2³³⁴, and exact integer arithmetic on fixed-size numbers rounds it:
//! normalise the quotient into `[1, 2)·2^e`, take the significand's bits by long division, and
//! round the remainder to nearest, ties to even (IEEE 754's default, as `from_str`). Speed is
//! not a concern: this runs once per setting, not per sample.

/// The most digits (before and after the point together) a number may have. `f32`'s
/// `Display` never writes more than 84 (39 before the point for `f32::MAX`, 45 after it for
/// the smallest subnormal), so every printed float reads back.
pub(crate) const MAX_DIGITS: usize = 100;

/// 32-bit limbs of the fixed-size integers: 12 × 32 = 384 bits hold `10^100 < 2³³³` and the
/// quotient loop's doubled remainder.
const LIMBS: usize = 12;

/// An unsigned integer below 2³⁸⁴, little-endian limbs. Every operation keeps within that
/// range for the inputs this module builds (at most [`MAX_DIGITS`] digits).
#[derive(Clone, Copy, PartialEq, Eq)]
struct Big([u32; LIMBS]);

impl Big {
    const fn small(v: u32) -> Big {
        let mut limbs = [0; LIMBS];
        limbs[0] = v;
        Big(limbs)
    }

    /// `self · m + a`.
    fn mul_add(&mut self, m: u32, a: u32) {
        let mut carry = u64::from(a);
        for limb in &mut self.0 {
            let t = u64::from(*limb) * u64::from(m) + carry;
            *limb = t as u32;
            carry = t >> 32;
        }
    }

    /// The number of significant bits (0 for zero).
    fn bits(&self) -> u32 {
        let mut n = 0;
        for (i, &limb) in self.0.iter().enumerate() {
            if limb != 0 {
                n = 32 * i as u32 + (32 - limb.leading_zeros());
            }
        }
        n
    }

    /// `self · 2^n`.
    fn shl(&mut self, n: u32) {
        let words = (n / 32) as usize;
        let bits = n % 32;
        let mut out = [0u32; LIMBS];
        for (i, slot) in out.iter_mut().enumerate().skip(words) {
            let lo = self.0.get(i - words).copied().unwrap_or(0);
            let below = match (i - words).checked_sub(1) {
                Some(j) if bits != 0 => self.0.get(j).copied().unwrap_or(0) >> (32 - bits),
                _ => 0,
            };
            *slot = (lo << bits) | below;
        }
        self.0 = out;
    }

    /// `self - other`, for `self >= other`.
    fn sub(&mut self, other: &Big) {
        let mut borrow = false;
        for (a, &b) in self.0.iter_mut().zip(&other.0) {
            let (d, o1) = a.overflowing_sub(b);
            let (d, o2) = d.overflowing_sub(u32::from(borrow));
            *a = d;
            borrow = o1 || o2;
        }
    }
}

impl PartialOrd for Big {
    fn partial_cmp(&self, other: &Big) -> Option<core::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Big {
    fn cmp(&self, other: &Big) -> core::cmp::Ordering {
        self.0.iter().rev().cmp(other.0.iter().rev())
    }
}

/// `s` as the nearest `f32` (ties to even), or `None` unless `s` is `-`, then digits with at
/// most one `.` among them (at least one digit, at most [`MAX_DIGITS`]), or the value rounds
/// beyond `f32::MAX`. No exponents, `inf` or `nan`: the text form does not write them.
pub(crate) fn parse_f32(s: &str) -> Option<f32> {
    let (negative, body) = match s.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, s),
    };
    let mut numerator = Big::small(0);
    let mut denominator = Big::small(1);
    let (mut digits, mut point) = (0usize, false);
    for b in body.bytes() {
        match b {
            b'0'..=b'9' => {
                digits += 1;
                if digits > MAX_DIGITS {
                    return None;
                }
                numerator.mul_add(10, u32::from(b - b'0'));
                if point {
                    denominator.mul_add(10, 0);
                }
            }
            b'.' if !point => point = true,
            _ => return None,
        }
    }
    if digits == 0 {
        return None;
    }
    let magnitude = if numerator == Big::small(0) {
        0.0
    } else {
        f32::from_bits(round_quotient(numerator, denominator)?)
    };
    Some(if negative { -magnitude } else { magnitude })
}

/// The bits of the `f32` nearest `a / b` (`a, b > 0`), or `None` past `f32::MAX`.
fn round_quotient(mut a: Big, mut b: Big) -> Option<u32> {
    // Scale to b <= a < 2b, so that a / b = (value / 2^e) lies in [1, 2).
    let mut e = a.bits() as i32 - b.bits() as i32;
    if e >= 0 {
        b.shl(e as u32);
    } else {
        a.shl(e.unsigned_abs());
    }
    if a < b {
        a.shl(1);
        e -= 1;
    }
    if e > 127 {
        return None;
    }
    // Significand bits: 24 for a normal number, fewer below 2^-126 (subnormal), none (or a
    // negative count) from 2^-150 down, where only the rounding below decides.
    let precision = if e >= -126 { 24 } else { e + 150 };
    if precision < 0 {
        return Some(0); // below 2^-150, half the smallest subnormal (2^-149): rounds to 0
    }
    // Long division: `q` takes the quotient's bits; the remainder stays below `b`, then
    // doubles for the next bit, so that at the end `a` compares with `b` as the discarded
    // fraction with one half.
    let mut q: u32 = 0;
    for _ in 0..precision {
        q <<= 1;
        if a >= b {
            a.sub(&b);
            q |= 1;
        }
        a.shl(1);
    }
    let round_up = match a.cmp(&b) {
        core::cmp::Ordering::Greater => true,
        core::cmp::Ordering::Equal => q & 1 == 1,
        core::cmp::Ordering::Less => false,
    };
    q += u32::from(round_up);
    let bits = if e >= -126 {
        // q in [2^23, 2^24]: the hidden bit's 2^23 moves into the exponent field, and a q
        // rounded up to 2^24 carries into it (up to the infinity's bits, refused below).
        (((e + 127) as u32) << 23) + (q - (1 << 23))
    } else {
        q // q · 2^-149: the subnormal with bits q (or, rounded up to 2^23, the smallest normal)
    };
    (bits < 0x7f80_0000).then_some(bits)
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use std::format;
    use std::string::String;

    fn std_parse(s: &str) -> Option<f32> {
        s.parse::<f32>().ok().filter(|v| v.is_finite())
    }

    fn same(s: &str) {
        let ours = parse_f32(s).map(f32::to_bits);
        assert_eq!(ours, std_parse(s).map(f32::to_bits), "{s}");
    }

    /// A small generator for the tests (xorshift64*).
    struct Rng(u64);
    impl Rng {
        fn next(&mut self) -> u64 {
            self.0 ^= self.0 >> 12;
            self.0 ^= self.0 << 25;
            self.0 ^= self.0 >> 27;
            self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
        }
    }

    #[test]
    fn printed_floats_read_back() {
        let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
        let edges = [
            0.0f32,
            -0.0,
            1.0,
            0.1,
            f32::MAX,
            f32::MIN,
            f32::MIN_POSITIVE,
            f32::from_bits(1),
            f32::from_bits(0x007f_ffff),
            16.0,
            0.5,
        ];
        let random = (0..200_000).map(|_| f32::from_bits(rng.next() as u32));
        for v in edges.into_iter().chain(random).filter(|v| v.is_finite()) {
            let text = format!("{v}");
            assert_eq!(
                parse_f32(&text).map(f32::to_bits),
                Some(v.to_bits()),
                "{text}"
            );
        }
    }

    #[test]
    fn random_decimals_round_as_from_str() {
        let mut rng = Rng(0x2545_f491_4f6c_dd1d);
        for _ in 0..100_000 {
            let len = 1 + rng.next() as usize % 60;
            let mut s = String::new();
            if rng.next() & 1 == 0 {
                s.push('-');
            }
            let point = rng.next() as usize % (len + 1);
            for i in 0..len {
                if i == point {
                    s.push('.');
                }
                // Long runs of zeros and nines reach the subnormals, the halfway cases and
                // f32::MAX's neighbourhood.
                let d = match rng.next() % 4 {
                    0 => b'0',
                    1 => b'9',
                    _ => b'0' + (rng.next() % 10) as u8,
                };
                s.push(d as char);
            }
            same(&s);
        }
    }

    #[test]
    fn halfway_cases_round_to_even() {
        // The exact midpoints between neighbouring floats (finite binary fractions, so their
        // decimal expansions are exact), and one unit of the last digit either side.
        let mut rng = Rng(7);
        for _ in 0..20_000 {
            // Exponents 2^-30..2^40: every midpoint is exact in 60 decimals.
            let exponent = 97 + (rng.next() % 70) as u32;
            let v = f32::from_bits(exponent << 23 | (rng.next() as u32 & 0x807f_ffff));
            let mid = (f64::from(v) + f64::from(f32::from_bits(v.to_bits() + 1))) / 2.0;
            let text = format!("{mid:.60}");
            let text = text.trim_end_matches('0');
            if text.bytes().filter(u8::is_ascii_digit).count() > MAX_DIGITS {
                continue;
            }
            same(text);
            same(&format!("{text}1"));
        }
    }

    #[test]
    fn bad_text_is_refused() {
        for s in [
            "", "-", ".", "-.", "1.2.3", "1e5", "inf", "nan", "+1", " 1", "1 ", "0x10",
        ] {
            assert_eq!(parse_f32(s), None, "{s:?}");
        }
        let long = "1".repeat(MAX_DIGITS + 1);
        assert_eq!(parse_f32(&long), None);
        assert!(
            parse_f32(&"1".repeat(MAX_DIGITS)).is_none(),
            "past f32::MAX"
        );
        assert_eq!(parse_f32("340282356779733661637539395458142568448"), None);
        same("340282356779733661637539395458142568447");
        assert_eq!(parse_f32("1."), Some(1.0));
        assert_eq!(parse_f32(".5"), Some(0.5));
        assert_eq!(parse_f32("-0").map(f32::to_bits), Some((-0.0f32).to_bits()));
    }
}

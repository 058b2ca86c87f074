//! Decimal text to and from `f32`, correctly rounded, with no panic path.
//!
//! The runtime description's text form ([`crate::spec`]) writes its floats as the shortest
//! decimal that reads back to the same bits, and must read them back exactly. `core`'s
//! `f32::from_str` and `f32`'s `Display` do that, but they keep bounds-checked panics the
//! optimiser cannot remove (the firmware's no-panic proof fails on them) and about 20 KiB of
//! code and tables on a Cortex-M.
//!
//! **Reading** needs far less: plain decimal notation
//! (`-`, digits, one `.`), at most [`MAX_DIGITS`] digits, so the value is `D / 10^k` with `D`
//! and `10^k` below 2³³⁴, and exact integer arithmetic on fixed-size numbers rounds it:
//! normalise the quotient into `[1, 2)·2^e`, take the significand's bits by long division, and
//! round the remainder to nearest, ties to even (IEEE 754's default, as `from_str`). Speed is
//! not a concern: this runs once per setting, not per sample.
//!
//! **Writing** ([`write_f32`]) writes what `f32`'s `Display` writes, found the plain way
//! rather than with Grisu or Ryū: the exact decimal expansion of the float (an integer
//! `m · 2^e`, or `m · 5^-e / 10^-e`, both below 2³⁸⁴), then for 1, 2, … significant digits
//! the expansion cut there and the cut plus one unit in its last place, the first length at
//! which either reads back (checked with the reader above, so the two always agree), the one
//! nearer the float when both do. Nine digits always suffice for an `f32`.

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

    /// `self / 10`, returning the remainder (the last decimal digit).
    fn div_rem_10(&mut self) -> u32 {
        let mut rem = 0u64;
        for limb in self.0.iter_mut().rev() {
            let t = (rem << 32) | u64::from(*limb);
            *limb = (t / 10) as u32;
            rem = t % 10;
        }
        rem as u32
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
    let mut digits = [0u8; MAX_DIGITS];
    let (mut len, mut point) = (0usize, None);
    for b in body.bytes() {
        match b {
            b'0'..=b'9' => {
                *digits.get_mut(len)? = b - b'0';
                len += 1;
            }
            b'.' if point.is_none() => point = Some(len),
            _ => return None,
        }
    }
    if len == 0 {
        return None;
    }
    let digits = digits.get(..len)?;
    let magnitude = value_of(digits, point.unwrap_or(len) as i32)?;
    Some(if negative { -magnitude } else { magnitude })
}

/// `0.d₁d₂…dₙ · 10^point` (`digits` most significant first, each `0..=9`) as the nearest
/// `f32`, or `None` past `f32::MAX`. The reader passes at most [`MAX_DIGITS`] digits and
/// `0 <= point <= n`, the writer at most 9 digits and `|point| <= 46`, so both terms of the
/// quotient stay below 10¹⁰⁰.
fn value_of(digits: &[u8], point: i32) -> Option<f32> {
    let mut numerator = Big::small(0);
    for &d in digits {
        numerator.mul_add(10, u32::from(d));
    }
    if numerator == Big::small(0) {
        return Some(0.0);
    }
    let mut denominator = Big::small(1);
    let shift = point - digits.len() as i32;
    for _ in 0..shift.unsigned_abs() {
        if shift > 0 {
            numerator.mul_add(10, 0);
        } else {
            denominator.mul_add(10, 0);
        }
    }
    round_quotient(numerator, denominator).map(f32::from_bits)
}

/// The most digits an `f32`'s exact decimal expansion has: `(2²⁴ - 1) · 5¹⁴⁹` has 112.
const EXACT_DIGITS: usize = 112;

/// Writes `v` as `f32`'s `Display` does: the shortest plain decimal that reads back to `v`
/// (the one nearer `v` if two of that length do, the upper one on a tie; `-0` for negative
/// zero; `inf`, `-inf` and `NaN` as they are). Module docs: how.
pub(crate) fn write_f32<W: core::fmt::Write>(out: &mut W, v: f32) -> core::fmt::Result {
    if v.is_nan() {
        return out.write_str("NaN");
    }
    if v.is_sign_negative() {
        out.write_char('-')?;
    }
    let a = v.abs();
    if a == f32::INFINITY {
        return out.write_str("inf");
    }
    if a == 0.0 {
        return out.write_char('0');
    }
    // a = m · 2^e exactly.
    let bits = a.to_bits();
    let (m, e) = match bits >> 23 {
        0 => (bits, -149),
        biased => (bits & 0x007f_ffff | 1 << 23, biased as i32 - 150),
    };
    // The exact expansion: the integer n, and a = n / 10^s.
    let mut n = Big::small(m);
    let s = if e >= 0 {
        n.shl(e as u32);
        0
    } else {
        for _ in 0..e.unsigned_abs() {
            n.mul_add(5, 0);
        }
        e.unsigned_abs() as i32
    };
    // Its digits, least significant first, without the trailing zeros: a = 0.d·10^point.
    let mut lsb_first = [0u8; EXACT_DIGITS];
    let (mut len, mut zeros) = (0usize, 0i32);
    while n != Big::small(0) {
        let d = n.div_rem_10() as u8;
        if len == 0 && d == 0 {
            zeros += 1;
        } else if let Some(slot) = lsb_first.get_mut(len) {
            *slot = d;
            len += 1;
        }
    }
    let point = len as i32 + zeros - s;
    let mut digits = [0u8; EXACT_DIGITS];
    for (slot, &d) in digits.iter_mut().zip(lsb_first.iter().take(len).rev()) {
        *slot = d;
    }
    let exact = digits.get(..len).unwrap_or(&[]);
    for p in 1..len.min(10) {
        let Some((head, tail)) = exact.split_at_checked(p) else {
            break;
        };
        let down_ok = value_of(head, point) == Some(a);
        // The cut plus one unit in its last place (a carry out of the top makes it 1).
        let mut up = [0u8; 9];
        let mut up_point = point;
        let mut up_len = p.min(up.len());
        for (slot, &d) in up.iter_mut().zip(head) {
            *slot = d;
        }
        let mut carry = true;
        for slot in up.iter_mut().take(up_len).rev() {
            if carry {
                *slot += 1;
                carry = *slot == 10;
                if carry {
                    *slot = 0;
                }
            }
        }
        if carry {
            up = [0; 9];
            up[0] = 1;
            up_len = 1;
            up_point += 1;
        }
        let up = up.get(..up_len).unwrap_or(&[]);
        let up_ok = value_of(up, up_point) == Some(a);
        if up_ok && down_ok {
            // Both read back: the nearer, and on a tie (a tail of exactly 5) the one above,
            // as `Display` does (2^-12 = 0.000244140625 writes as 0.00024414063).
            return if tail.first().is_some_and(|&d| d >= 5) {
                write_digits(out, up, up_point)
            } else {
                write_digits(out, head, point)
            };
        }
        if up_ok {
            return write_digits(out, up, up_point);
        }
        if down_ok {
            return write_digits(out, head, point);
        }
    }
    write_digits(out, exact, point)
}

/// An `f32` that displays through [`write_f32`]: as `f32`'s `Display`, without its panic
/// paths (for messages that name a float, such as [`crate::Error`]'s).
pub(crate) struct Shortest(pub(crate) f32);

impl core::fmt::Display for Shortest {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write_f32(f, self.0)
    }
}

/// Writes `0.d₁d₂…dₙ · 10^point` in plain notation (`d₁ != 0`, `dₙ != 0`).
fn write_digits<W: core::fmt::Write>(out: &mut W, digits: &[u8], point: i32) -> core::fmt::Result {
    let digit = |d: u8| char::from(b'0' + d % 10);
    if point <= 0 {
        out.write_str("0.")?;
        for _ in 0..point.unsigned_abs() {
            out.write_char('0')?;
        }
        for &d in digits {
            out.write_char(digit(d))?;
        }
        return Ok(());
    }
    let before = point.unsigned_abs() as usize;
    for i in 0..before.max(digits.len()) {
        if i == before {
            out.write_char('.')?;
        }
        out.write_char(digit(digits.get(i).copied().unwrap_or(0)))?;
    }
    Ok(())
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

    fn written(v: f32) -> String {
        let mut s = String::new();
        write_f32(&mut s, v).unwrap();
        s
    }

    #[test]
    fn floats_write_as_display() {
        let mut rng = Rng(0x5151_5151_a5a5_a5a5);
        let mut checked = 0;
        let edges = [
            0.0f32,
            -0.0,
            1.0,
            0.1,
            0.3,
            2.0 / 3.0,
            f32::MAX,
            f32::MIN,
            f32::MIN_POSITIVE,
            f32::EPSILON,
            f32::from_bits(1),
            f32::from_bits(0x007f_ffff),
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
            1e10,
            123_456_790.0,
        ];
        // Every power of two (the uneven rounding interval below them), their neighbours,
        // random bit patterns, and floats with two quarter bits in [2^21, 2^24), whose
        // shortest forms tie between two decimals of the same length.
        let powers = (0..255u32).flat_map(|b| {
            let v = b << 23;
            [v, v + 1, v.wrapping_sub(1)].map(f32::from_bits)
        });
        let quarters = (0..20_000).map(|_| {
            let x = (1u32 << 21) + (rng.next() as u32 % (3 << 21));
            x as f32 + [0.25, 0.75, 0.5][(rng.next() % 3) as usize]
        });
        let mut rng2 = Rng(0x0123_4567_89ab_cdef);
        let random = (0..300_000).map(|_| f32::from_bits(rng2.next() as u32));
        for v in edges
            .into_iter()
            .chain(powers)
            .chain(quarters)
            .chain(random)
        {
            assert_eq!(written(v), format!("{v}"), "{:#x}", v.to_bits());
            checked += 1;
        }
        assert!(checked > 300_000);
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

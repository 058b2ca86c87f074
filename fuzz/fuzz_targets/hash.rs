//! Olano's BBS hash for several moduli against a 64-bit integer reference: the integer path,
//! the f32 path (any f32 bit pattern), and the chained 1D–4D hashes; and the kernels' `exp_neg`
//! and `cos_turns` for any f32 and I16F16, in range and within their stated errors.
#![no_main]

use bandnoise::hash::Bbs;
use bandnoise::{I16F16, Real};
use libfuzzer_sys::fuzz_target;

fn reference(x: i64, m: i64) -> i64 {
    let r = x.rem_euclid(m);
    r * r % m
}

fn check<const M: u32>(x: i32, y: i32, z: i32, w: i32, f: f32) {
    let m = M as i64;
    let h = |v: i64| reference(v, m);
    let (x6, y6, z6, w6) = (x as i64, y as i64, z as i64, w as i64);
    assert_eq!(Bbs::<M>::hash(x) as i64, h(x6));
    assert_eq!(Bbs::<M>::hash2(x, y) as i64, h(x6 + h(y6)));
    assert_eq!(Bbs::<M>::hash3(x, y, z) as i64, h(x6 + h(y6 + h(z6))));
    assert_eq!(
        Bbs::<M>::hash4(x, y, z, w) as i64,
        h(x6 + h(y6 + h(z6 + h(w6))))
    );
    // The f32 path for any bit pattern: floor, then the reference (NaN and ±∞ give 0).
    let got = Bbs::<M>::hash_f32(f);
    if f.is_finite() {
        let fl = f.floor() as f64;
        let want = if fl.abs() < 9.0e18 {
            h(fl as i64)
        } else {
            h(fl.rem_euclid(m as f64) as i64)
        };
        assert_eq!(got, want as f32, "M={M} f={f:e}");
    } else {
        assert_eq!(got, 0.0);
    }
    // The integer and f32 paths agree wherever f32 holds the integer exactly.
    if x.unsigned_abs() <= 1 << 24 {
        assert_eq!(Bbs::<M>::hash_f32(x as f32), Bbs::<M>::hash(x) as f32);
    }
}

/// `e^{−x}` and `cos 2πx` in f32 (any bit pattern) and I16F16 (any bits) against `std`'s f64.
fn kernels(f: f32, bits: i32) {
    let (e, c) = (f.exp_neg(), f.cos_turns());
    assert!(
        (0.0..=1.0).contains(&e) && (-1.0..=1.0).contains(&c),
        "{f:e}: {e} {c}"
    );
    if f.is_nan() || f >= 16.0 {
        assert_eq!(e, 0.0);
    } else if f <= 0.0 {
        assert_eq!(e, 1.0);
    } else {
        assert!(
            (f64::from(e) - (-f64::from(f)).exp()).abs() < 2e-7,
            "exp {f:e}"
        );
    }
    // Against the cosine of the fraction `split` keeps (exact for every f32).
    let (_, t) = f.split();
    let want = (2.0 * std::f64::consts::PI * f64::from(t)).cos();
    assert!((f64::from(c) - want).abs() < 3e-7, "cos {f:e}");
    let q = I16F16::from_bits(bits);
    let (e, c) = (q.exp_neg(), q.cos_turns());
    assert!(e >= 0 && e <= 1 && c >= -1 && c <= 1, "{q}: {e} {c}");
    let x = q.to_num::<f64>();
    let want_e = if x <= 0.0 { 1.0 } else { (-x).exp() };
    assert!((e.to_num::<f64>() - want_e).abs() < 1e-4, "exp {q}");
    let want_c = (2.0 * std::f64::consts::PI * x.rem_euclid(1.0)).cos();
    assert!((c.to_num::<f64>() - want_c).abs() < 1e-4, "cos {q}");
}

fuzz_target!(|input: (i32, i32, i32, i32, f32)| {
    let (x, y, z, w, f) = input;
    kernels(f, x);
    check::<61>(x, y, z, w, f);
    check::<4093>(x, y, z, w, f);
    check::<2>(x, y, z, w, f);
    check::<1021>(x, y, z, w, f);
    check::<1031>(x, y, z, w, f);
});

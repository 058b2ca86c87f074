//! The Blum-Blum-Shub hash against a 64-bit integer reference, its integer and f32 paths against
//! each other (exhaustively over every integer f32 holds exactly), and the chained hashes.

use bandnoise::hash::{Bbs, PERLIN_2002, Permutation};
use bandnoise_tests::Rng;

/// `(x mod m)² mod m` in 64-bit integers, straight from the definition.
fn reference(x: i64, m: i64) -> i64 {
    let r = x.rem_euclid(m);
    (r * r) % m
}

fn exhaustive<const M: u32>() {
    let m = M as i64;
    // Every integer in [-2^24, 2^24]: all of them are exact in f32.
    let mut mismatches = 0u64;
    for i in -(1i32 << 24)..=(1 << 24) {
        let want = reference(i as i64, m);
        let int = Bbs::<M>::hash(i) as i64;
        let float = Bbs::<M>::hash_f32(i as f32);
        if int != want || float != want as f32 {
            mismatches += 1;
            assert!(
                mismatches < 10,
                "M={M} i={i}: int {int} f32 {float} want {want}"
            );
        }
    }
    assert_eq!(mismatches, 0);
    // Every i32 edge, and f32 integers beyond 2^24 (sparse, all exact).
    for i in [i32::MIN, i32::MIN + 1, -1, 0, 1, i32::MAX - 1, i32::MAX] {
        assert_eq!(
            Bbs::<M>::hash(i) as i64,
            reference(i as i64, m),
            "M={M} i={i}"
        );
    }
    let mut rng = Rng::from_env(61);
    for _ in 0..1_000_000 {
        let bits = rng.next_u64() as u32;
        let x = f32::from_bits(bits & 0x7FFF_FFFF | (bits & 0x8000_0000));
        if !x.is_finite() {
            assert_eq!(Bbs::<M>::hash_f32(x), 0.0);
            continue;
        }
        let fl = x.floor() as f64;
        // f32 integers up to 2^127 overflow i64; reduce the f64 value exactly instead.
        let want = if fl.abs() < 9.0e18 {
            reference(fl as i64, m)
        } else {
            let r = fl.rem_euclid(m as f64) as i64;
            (r * r) % m
        };
        assert_eq!(Bbs::<M>::hash_f32(x), want as f32, "M={M} x={x:e}");
        if (i32::MIN as f32..i32::MAX as f32).contains(&x) {
            assert_eq!(Bbs::<M>::hash(x.floor() as i32) as i64, want, "M={M} x={x}");
        }
    }
}

#[test]
fn bbs61_integer_and_f32_paths_agree_exhaustively() {
    exhaustive::<61>();
}

#[test]
fn bbs4093_integer_and_f32_paths_agree_exhaustively() {
    exhaustive::<4093>();
}

#[test]
fn bbs_small_modulus_and_reduction() {
    exhaustive_small::<2>();
    exhaustive_small::<3>();
    exhaustive_small::<7>();
    fn exhaustive_small<const M: u32>() {
        for i in -100_000..100_000 {
            assert_eq!(Bbs::<M>::hash(i) as i64, reference(i as i64, M as i64));
            assert_eq!(
                Bbs::<M>::hash_f32(i as f32),
                reference(i as i64, M as i64) as f32
            );
        }
    }
    // 4093 is the largest prime whose square is exact in f32 (below 2^24).
    let is_prime = |n: u64| {
        n > 1
            && (2..)
                .take_while(|d| d * d <= n)
                .all(|d| !n.is_multiple_of(d))
    };
    let largest = (2u64..1 << 12)
        .rev()
        .find(|&p| is_prime(p) && p * p < 1 << 24);
    assert_eq!(largest, Some(4093));
}

#[test]
fn the_reciprocal_reduction_is_exact_for_every_argument() {
    // The moduli the kernels use, both edges of the reciprocal's range (1024 uses it, 1031
    // falls back to %), powers of two (the tightest case) and small ones.
    assert!(Bbs::<61>::step_is_exact());
    assert!(Bbs::<2>::step_is_exact());
    assert!(Bbs::<3>::step_is_exact());
    assert!(Bbs::<64>::step_is_exact());
    assert!(Bbs::<257>::step_is_exact());
    assert!(Bbs::<1021>::step_is_exact());
    assert!(Bbs::<1024>::step_is_exact());
    assert!(Bbs::<1031>::step_is_exact());
    assert!(Bbs::<4093>::step_is_exact());
}

#[test]
fn chained_hashes_follow_olanos_formula() {
    type H = Bbs<61>;
    let h = |x: i64| reference(x, 61);
    let mut rng = Rng::from_env(7);
    for _ in 0..100_000 {
        let [x, y, z, w] = [0; 4].map(|_| rng.i32_in(i32::MIN, i32::MAX));
        let (x6, y6, z6, w6) = (x as i64, y as i64, z as i64, w as i64);
        assert_eq!(H::hash2(x, y) as i64, h(x6 + h(y6)));
        assert_eq!(H::hash3(x, y, z) as i64, h(x6 + h(y6 + h(z6))));
        assert_eq!(H::hash4(x, y, z, w) as i64, h(x6 + h(y6 + h(z6 + h(w6)))));
    }
}

#[test]
fn perlin_permutation_is_pbrts_noise_perm() {
    // pbrt's NoisePerm starts 151, 160, 137, 91, 90, 15 and ends 215, 61, 156, 180.
    assert_eq!(&PERLIN_2002[..6], &[151, 160, 137, 91, 90, 15]);
    assert_eq!(&PERLIN_2002[252..], &[215, 61, 156, 180]);
    let mut sorted = PERLIN_2002;
    sorted.sort_unstable();
    assert!(sorted.iter().enumerate().all(|(i, &v)| v as usize == i));
    assert_eq!(Permutation::new(0).get(256 + 3), 91);
}

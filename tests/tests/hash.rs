//! The Blum-Blum-Shub hash against a 64-bit integer reference, its integer and f32 paths against
//! each other (exhaustively over every integer f32 holds exactly), and the chained hashes. The
//! well-mixed cell hash's avalanche and neighbour correlation, and the cell generator's
//! uniformity, Poisson counts and independence, over 10⁶ cells each (figures printed).

use bandnoise::hash::{Bbs, CellHash, CellRng, PERLIN_2002, Permutation, Poisson};
use bandnoise::{I16F16, Real};
use bandnoise_tests::{Rng, correlation};

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
    // The moduli the kernels use, both edges of the direct reciprocal's range (131, 137) and
    // of the corrected one's (1024 uses it, 1031 falls back to %), powers of two (the
    // tightest case) and small ones.
    assert!(Bbs::<61>::step_is_exact());
    assert!(Bbs::<2>::step_is_exact());
    assert!(Bbs::<3>::step_is_exact());
    assert!(Bbs::<64>::step_is_exact());
    assert!(Bbs::<131>::step_is_exact()); // the largest with an exact direct reciprocal
    assert!(Bbs::<137>::step_is_exact()); // the smallest prime without one
    assert!(Bbs::<257>::step_is_exact());
    assert!(Bbs::<1021>::step_is_exact());
    assert!(Bbs::<1024>::step_is_exact());
    assert!(Bbs::<1031>::step_is_exact());
    assert!(Bbs::<4093>::step_is_exact());
}

#[test]
fn the_seeded_cell_reduction_is_exact() {
    // 61 (s = 21), a power of two, the largest direct modulus, and moduli without the small
    // reciprocal (7, 257), which reduce the cell first.
    assert!(Bbs::<61>::reduce_offset_is_exact());
    assert!(Bbs::<2>::reduce_offset_is_exact());
    assert!(Bbs::<7>::reduce_offset_is_exact());
    assert!(Bbs::<64>::reduce_offset_is_exact());
    assert!(Bbs::<131>::reduce_offset_is_exact());
    assert!(Bbs::<257>::reduce_offset_is_exact());
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

/// Strict avalanche: flipping any input bit (of the cell, or of the seed) flips each output bit
/// with probability 0.5 ± 0.02, over 10⁶ random cells.
#[test]
fn cell_hash_avalanches() {
    const CELLS: usize = 1_000_000;
    let mut rng = Rng::from_env(150);
    // flips[input bit][output bit]: 96 cell bits (3D), then 32 seed bits.
    let mut flips = vec![[0u32; 32]; 128];
    let count = |flips: &mut [u32; 32], diff: u32| {
        for (j, f) in flips.iter_mut().enumerate() {
            *f += diff >> j & 1;
        }
    };
    for _ in 0..CELLS {
        let seed = rng.next_u64() as u32;
        let cell: [i32; 3] = core::array::from_fn(|_| rng.next_u64() as i32);
        let h = CellHash::new(seed);
        let base = h.hash(cell);
        for bit in 0..96 {
            let mut c = cell;
            c[bit / 32] ^= 1 << (bit % 32);
            count(&mut flips[bit], base ^ h.hash(c));
        }
        for bit in 0..32 {
            count(
                &mut flips[96 + bit],
                base ^ CellHash::new(seed ^ 1 << bit).hash(cell),
            );
        }
    }
    let (mut worst, mut at) = (0.0f64, (0, 0));
    for (i, row) in flips.iter().enumerate() {
        for (j, &f) in row.iter().enumerate() {
            let d = (f as f64 / CELLS as f64 - 0.5).abs();
            if d > worst {
                (worst, at) = (d, (i, j));
            }
        }
    }
    println!(
        "cell hash avalanche over {CELLS} cells: worst |P(flip) − 0.5| = {worst:.4} (input bit {}, output bit {})",
        at.0, at.1
    );
    assert!(worst <= 0.02, "{worst} at {at:?}");
}

/// The hashes of neighbouring cells (and of neighbouring seeds) are uncorrelated.
#[test]
fn neighbouring_cells_hash_independently() {
    const CELLS: usize = 1_000_000;
    let mut rng = Rng::from_env(151);
    let h = CellHash::new(5);
    let unit = |x: u32| x as f64 / 4_294_967_296.0;
    let cells: Vec<[i32; 3]> = (0..CELLS)
        .map(|_| core::array::from_fn(|_| rng.i32_in(-100_000, 100_000)))
        .collect();
    let base: Vec<f64> = cells.iter().map(|&c| unit(h.hash(c))).collect();
    let mut worst = 0.0f64;
    for axis in 0..3 {
        let next: Vec<f64> = cells
            .iter()
            .map(|&c| {
                let mut n = c;
                n[axis] += 1;
                unit(h.hash(n))
            })
            .collect();
        worst = worst.max(correlation(&base, &next).abs());
    }
    let seeds: Vec<f64> = cells
        .iter()
        .map(|&c| unit(CellHash::new(6).hash(c)))
        .collect();
    worst = worst.max(correlation(&base, &seeds).abs());
    println!("cell hash: worst |correlation| of neighbouring cells and seeds {worst:.5}");
    // The standard error of a correlation over 10⁶ pairs is 0.001.
    assert!(worst < 0.005, "{worst}");
}

/// χ² of `n` values in `[0, 1)` over 64 bins.
fn chi_squared(values: impl Iterator<Item = f64>) -> f64 {
    let mut bins = [0u64; 64];
    let mut n = 0u64;
    for v in values {
        assert!((0.0..1.0).contains(&v), "{v}");
        bins[(v * 64.0) as usize] += 1;
        n += 1;
    }
    let expected = n as f64 / 64.0;
    bins.iter()
        .map(|&b| (b as f64 - expected) * (b as f64 - expected) / expected)
        .sum()
}

#[test]
fn cell_numbers_are_uniform_exact_and_independent() {
    const CELLS: usize = 1_000_000;
    let mut rng = Rng::from_env(152);
    let h = CellHash::new(9);
    let cells: Vec<[i32; 2]> = (0..CELLS)
        .map(|_| core::array::from_fn(|_| rng.i32_in(-1_000_000, 1_000_000)))
        .collect();
    // The first two draws of every cell, in f64.
    let draws: Vec<[f64; 2]> = cells
        .iter()
        .map(|&c| {
            let mut r = CellRng::new(&h, c);
            [r.uniform(), r.uniform()]
        })
        .collect();
    // χ² with 63 degrees of freedom: mean 63, standard deviation 11.2; 130 is 6 of them.
    let chi_first = chi_squared(draws.iter().map(|d| d[0]));
    let chi_second = chi_squared(draws.iter().map(|d| d[1]));
    let signed = chi_squared(cells.iter().map(|&c| {
        let v: f64 = CellRng::new(&h, c).signed_uniform();
        assert!((-1.0..1.0).contains(&v));
        (v + 1.0) / 2.0
    }));
    // Independence: successive draws of a cell, and the first draws of neighbouring cells.
    let first: Vec<f64> = draws.iter().map(|d| d[0]).collect();
    let second: Vec<f64> = draws.iter().map(|d| d[1]).collect();
    let next_cell: Vec<f64> = cells
        .iter()
        .map(|&[x, y]| CellRng::new(&h, [x + 1, y]).uniform())
        .collect();
    let r_draws = correlation(&first, &second);
    let r_cells = correlation(&first, &next_cell);
    println!(
        "cell generator over {CELLS} cells: χ²(63) first draw {chi_first:.1}, second {chi_second:.1}, signed {signed:.1}; correlation of successive draws {r_draws:+.5}, of neighbouring cells {r_cells:+.5}"
    );
    for chi in [chi_first, chi_second, signed] {
        assert!(chi < 130.0, "{chi}");
    }
    assert!(r_draws.abs() < 0.005 && r_cells.abs() < 0.005);

    // The same value in every number type, up to its precision.
    for &c in cells.iter().take(10_000) {
        let a: f32 = CellRng::new(&h, c).uniform();
        let b: f64 = CellRng::new(&h, c).uniform();
        let q: I16F16 = CellRng::new(&h, c).uniform();
        assert_eq!(a as f64, b);
        assert_eq!(q.to_f64(), (b * 65536.0).floor() / 65536.0);
        let s: f32 = CellRng::new(&h, c).signed_uniform();
        let t: f64 = CellRng::new(&h, c).signed_uniform();
        assert_eq!(s as f64, t);
    }
}

#[test]
fn poisson_counts_have_the_right_mean_and_variance() {
    const CELLS: usize = 1_000_000;
    let h = CellHash::new(10);
    for mean in [0.25f32, 1.0, 3.0, 8.0, 32.0] {
        let p = Poisson::new(mean).expect("valid mean");
        let (mut s1, mut s2, mut at_cap) = (0.0f64, 0.0f64, 0u32);
        for i in 0..CELLS as i32 {
            let k = CellRng::new(&h, [i, 17]).poisson(&p);
            assert!(k <= p.cap());
            at_cap += (k == p.cap()) as u32;
            s1 += k as f64;
            s2 += (k * k) as f64;
        }
        let m = s1 / CELLS as f64;
        let var = s2 / CELLS as f64 - m * m;
        let lambda = mean as f64;
        println!(
            "Poisson({mean}): mean {m:.4}, variance {var:.4} over {CELLS} cells; cap {} (reached {at_cap} times)",
            p.cap()
        );
        // Standard errors: sqrt(λ/n) for the mean, about λ·sqrt(2/n) for the variance.
        let n = CELLS as f64;
        assert!((m - lambda).abs() < 5.0 * (lambda / n).sqrt(), "mean {m}");
        let se_var = (lambda * (2.0 * lambda + 1.0) / n).sqrt();
        assert!((var - lambda).abs() < 5.0 * se_var, "variance {var}");
        assert!(p.cap() < 96);
    }
    for bad in [0.0f32, -1.0, 32.5, f32::NAN, f32::INFINITY] {
        assert!(Poisson::new(bad).is_err(), "{bad}");
    }
}

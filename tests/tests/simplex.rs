//! Simplex noise (Perlin 2001, Gustavson 2005) against an independent `f64` reference written
//! from the definition in the module docs, with the falloff radius as a parameter:
//!
//! * bandnoise's `f64` noise is the reference at `r² = ½` (1D: `r² = 1`);
//! * continuity: the largest jump across simplex faces, for `r² = ½` and for Gustavson's 0.6
//!   (3D, 4D), measured exactly on faces by evaluating both simplices that share one;
//! * the scale: the largest value over points and gradient choices, searched, is 1;
//! * fixed point follows `f32`; the gradient is the derivative; batches are `sample`;
//!   mean 0 and the range over random points.

use bandnoise::simplex::Simplex;
use bandnoise::{I16F16, Noise, NoiseGradient};
use bandnoise_tests::Rng;
use bandnoise_tests::agree;
use bandnoise_tests::spectral::mean_variance;

/// The skew `F` and the unskew `G` as the module docs define them (2⁻³¹ units).
const SKEW: [f64; 5] = [0.0, 0.0, 786_033_569.0, 715_827_883.0, 663_608_942.0];
const UNSKEW: [f64; 5] = [0.0, 0.0, 453_816_693.0, 357_913_941.0, 296_774_941.0];
const Q31: f64 = 2_147_483_648.0;

/// The corner hash (the module docs): a mix of the seed (Wellons' `lowbias32` of
/// `seed ^ 0x5BD1E995`), `xor` each axis's coordinate times its prime, times `0x27D4EB2D`,
/// all wrapping in 32 bits.
#[derive(Clone, Copy)]
struct Hash(u32);

impl Hash {
    const PRIMES: [u32; 4] = [501_125_321, 1_136_930_381, 1_720_413_743, 1_066_037_191];

    fn new(seed: u32) -> Self {
        let mut x = seed ^ 0x5BD1_E995;
        x ^= x >> 16;
        x = x.wrapping_mul(0x7FEB_352D);
        x ^= x >> 15;
        x = x.wrapping_mul(0x846C_A68B);
        x ^= x >> 16;
        Self(x)
    }

    fn of(self, cell: &[i64]) -> u32 {
        let mut h = self.0;
        for (a, &c) in cell.iter().enumerate() {
            h ^= (c as u32).wrapping_mul(Self::PRIMES[a]);
        }
        h.wrapping_mul(0x27D4_EB2D)
    }
}

/// Perlin's gradient for hash `h` in `d` dimensions (the module docs), chosen by its top 3
/// (1D), 4 (2D, 3D) or 5 (4D) bits: 1D slopes, the 12 cube edges (Perlin's `grad`, 2D their
/// x and y), the 32 tesseract edges.
fn gradient(d: usize, h: u32) -> [f64; 4] {
    let h = h >> (32 - [0, 3, 4, 4, 5][d]);
    let sign = |bit: u32| if h >> bit & 1 == 0 { 1.0 } else { -1.0 };
    match d {
        1 => [sign(2) * ((h & 3) as f64 + 1.0) / 4.0, 0.0, 0.0, 0.0],
        2 | 3 => {
            let h = h & 15;
            // Perlin's grad(h, x, y, z) = ±u ± v.
            let u = if h < 8 { 0 } else { 1 };
            let v = if h < 4 {
                1
            } else if h == 12 || h == 14 {
                0
            } else {
                2
            };
            let mut g = [0.0; 4];
            g[u] += sign(0);
            g[v] += sign(1);
            if d == 2 {
                g[2] = 0.0;
            }
            g
        }
        _ => {
            let zero = (h >> 3 & 3) as usize;
            let mut g = [0.0; 4];
            let mut bit = 0;
            for (a, c) in g.iter_mut().enumerate() {
                if a != zero {
                    *c = sign(bit);
                    bit += 1;
                }
            }
            g
        }
    }
}

/// The reference: simplex noise of the simplex that `order` names (the axes in the order the
/// walk from the cell's corner steps them), at the skewed fractions `u` of `cell`, with falloff
/// `r2`. Each corner's gradient is `choose(corner hash, offset)`: the hashed gradient's dot
/// product, or the largest over the gradient set (for the search of the maximum).
fn reference(
    d: usize,
    hash: Hash,
    cell: [i64; 4],
    u: [f64; 4],
    order: [usize; 4],
    r2: f64,
    choose: &dyn Fn(u32, &[f64; 4]) -> f64,
) -> f64 {
    let g1 = UNSKEW[d] / Q31;
    let sum: f64 = u[..d].iter().sum();
    let mut step = [0i64; 4];
    let mut total = 0.0;
    for j in 0..=d {
        if j > 0 {
            step[order[j - 1]] = 1;
        }
        let diagonal = j as f64 * UNSKEW[d] / Q31;
        let mut off = [0.0; 4];
        let mut q = 0.0;
        for a in 0..d {
            off[a] = u[a] - sum * g1 + diagonal - step[a] as f64;
            q += off[a] * off[a];
        }
        let tau = 1.0 - q / r2;
        if tau <= 0.0 {
            continue;
        }
        let corner: Vec<i64> = (0..d).map(|a| cell[a] + step[a]).collect();
        total += tau.powi(4) * choose(hash.of(&corner), &off);
    }
    total
}

fn hashed(d: usize) -> impl Fn(u32, &[f64; 4]) -> f64 {
    move |h, off| {
        let g = gradient(d, h);
        (0..d).map(|a| g[a] * off[a]).sum()
    }
}

/// The largest `g·d` over the gradient set: the sum of the largest `|d_a|`, one in 1D (times
/// the steepest slope, 1) and 2D's axes too, two in 2D and 3D, three in 4D.
fn steepest(d: usize) -> impl Fn(u32, &[f64; 4]) -> f64 {
    move |_, off| {
        let mut a: Vec<f64> = off[..d].iter().map(|x| x.abs()).collect();
        a.sort_by(|x, y| y.total_cmp(x));
        a[..[0, 1, 2, 2, 3][d]].iter().sum()
    }
}

/// The skewed cell and fractions of `p` in exact arithmetic (to f64's precision), and the
/// order of its fractions (largest first, ties to the later axis as Gustavson's ranks).
fn skewed(d: usize, p: &[f64]) -> ([i64; 4], [f64; 4], [usize; 4]) {
    let f = SKEW[d] / Q31;
    let s: f64 = p.iter().sum::<f64>() * f;
    let (mut cell, mut u) = ([0i64; 4], [0.0; 4]);
    for a in 0..d {
        let v = p[a] + s;
        cell[a] = v.floor() as i64;
        u[a] = v - v.floor();
    }
    let mut order = [0, 1, 2, 3];
    order[..d].sort_by(|&a, &b| u[b].total_cmp(&u[a]).then(b.cmp(&a)));
    (cell, u, order)
}

const SCALE: [f64; 5] = [0.0, 207_126.0, 287_326.0, 314_903.0, 257_137.0];

fn radius2(d: usize) -> f64 {
    if d == 1 { 1.0 } else { 0.5 }
}

fn reference_at<const D: usize>(hash: Hash, p: [f64; D]) -> f64 {
    let (cell, u, order) = skewed(D, &p);
    let v = reference(D, hash, cell, u, order, radius2(D), &hashed(D));
    v * SCALE[D] / 65536.0
}

fn matches_reference<const D: usize>(rng: &mut Rng)
where
    Simplex: Noise<f64, D>,
{
    for seed in [0u32, 1, 77] {
        let noise = Simplex::new(seed);
        let hash = Hash::new(seed);
        let mut worst = 0.0f64;
        for _ in 0..20_000 {
            let p: [f64; D] = core::array::from_fn(|_| rng.f64_in(-300.0, 300.0));
            let v: f64 = noise.sample(p);
            worst = worst.max((v - reference_at(hash, p)).abs());
        }
        println!("{D}D seed {seed}: largest |bandnoise − reference| {worst:.1e}");
        assert!(worst < 1e-12, "{D}D seed {seed}: {worst}");
    }
}

/// bandnoise's `f64` simplex noise is the reference (the definition in the module docs) within
/// rounding, for several seeds, 1D–4D.
#[test]
fn is_the_reference() {
    let mut rng = Rng::from_env(60);
    matches_reference::<1>(&mut rng);
    matches_reference::<2>(&mut rng);
    matches_reference::<3>(&mut rng);
    matches_reference::<4>(&mut rng);
}

/// The largest jump across simplex faces over `n` random points on faces, for falloff `r2`,
/// in units of the noise's scale at `r² = ½`. A point on the face between two simplices
/// belongs to both; the jump is the difference of the two simplices' sums there. Faces inside
/// a skewed cell are where two fractions are equal (the two orders of those axes); faces
/// between cells where a fraction is 0 (this cell with that axis stepped last, or the cell
/// below with fraction 1 and that axis stepped first).
fn largest_jump(d: usize, r2: f64, n: usize, rng: &mut Rng) -> f64 {
    let hash = Hash::new(3);
    let value =
        |cell, u, order| reference(d, hash, cell, u, order, r2, &hashed(d)) * SCALE[d] / 65536.0;
    let mut worst = 0.0f64;
    for i in 0..n {
        let cell: [i64; 4] = core::array::from_fn(|_| rng.i32_in(-50, 50) as i64);
        let mut u: [f64; 4] = core::array::from_fn(|_| rng.f64_in(0.0, 1.0));
        let a = (rng.next_u64() % d as u64) as usize;
        if i % 2 == 0 && d > 1 {
            // Two equal fractions: an inner face.
            let b = (a + 1 + (rng.next_u64() % (d as u64 - 1)) as usize) % d;
            u[b] = u[a];
            let mut order = [0, 1, 2, 3];
            order[..d].sort_by(|&x, &y| u[y].total_cmp(&u[x]).then(x.cmp(&y)));
            let first = value(cell, u, order);
            let (pa, pb) = (
                order.iter().position(|&x| x == a).unwrap(),
                order.iter().position(|&x| x == b).unwrap(),
            );
            order.swap(pa, pb);
            worst = worst.max((first - value(cell, u, order)).abs());
        } else {
            // A fraction 0: the face shared with the cell below along `a`.
            u[a] = 0.0;
            let mut order = [0, 1, 2, 3];
            order[..d].sort_by(|&x, &y| u[y].total_cmp(&u[x]).then(y.cmp(&x)));
            let here = value(cell, u, order);
            let mut below = cell;
            below[a] -= 1;
            let mut v = u;
            v[a] = 1.0;
            let mut order = [0, 1, 2, 3];
            order[..d].sort_by(|&x, &y| v[y].total_cmp(&v[x]).then(x.cmp(&y)));
            worst = worst.max((here - value(below, v, order)).abs());
        }
    }
    worst
}

/// bandnoise's falloff is continuous across every simplex face (jumps at rounding level);
/// Gustavson's `r² = 0.6` jumps in 3D and 4D. Printed for both.
#[test]
fn continuous_across_simplex_faces() {
    let mut rng = Rng::from_env(61);
    for d in 1..=4 {
        let ours = largest_jump(d, radius2(d), 200_000, &mut rng);
        print!(
            "{d}D: largest jump across simplex faces, r² = {}: {ours:.1e}",
            radius2(d)
        );
        assert!(ours < 1e-12, "{d}D: {ours}");
        if d >= 3 {
            let gustavson = largest_jump(d, 0.6, 200_000, &mut rng);
            print!("; Gustavson's r² = 0.6: {gustavson:.1e}");
            assert!(gustavson > 1e-4, "{d}D: 0.6 was expected to jump");
        }
        println!();
    }
}

/// The scale makes the largest value 1: a grid search over a skewed cell with the steepest
/// gradient at every corner, refined by coordinate ascent, finds a maximum in `[0.999, 1]`.
/// (1D: 81/256 at the middle, exactly.)
#[test]
fn the_largest_value_is_one() {
    let hash = Hash::new(0);
    for d in 1..=4usize {
        let peak = |u: [f64; 4]| {
            let mut order = [0, 1, 2, 3];
            order[..d].sort_by(|&x, &y| u[y].total_cmp(&u[x]).then(y.cmp(&x)));
            reference(d, hash, [0; 4], u, order, radius2(d), &steepest(d)) * SCALE[d] / 65536.0
        };
        let (best, at) = largest(d, [0, 4096, 256, 40, 16][d], peak);
        println!(
            "{d}D: largest value {best:.6} at skewed fractions {:?}",
            &at[..d]
        );
        assert!((0.999..=1.0).contains(&best), "{d}D: {best}");
    }
}

/// The largest `peak(u)` over skewed fractions `u ∈ [0, 1)^d`, and where: a grid of `n` per
/// axis, then coordinate ascent from its best point down to steps of 10⁻¹⁰.
fn largest(d: usize, n: usize, peak: impl Fn([f64; 4]) -> f64) -> (f64, [f64; 4]) {
    let (mut best, mut at) = (0.0f64, [0.0; 4]);
    for i in 0..n.pow(d as u32) {
        let mut rest = i;
        let mut u = [0.0; 4];
        for c in u.iter_mut().take(d) {
            *c = (rest % n) as f64 / n as f64;
            rest /= n;
        }
        let v = peak(u);
        if v > best {
            (best, at) = (v, u);
        }
    }
    let mut step = 1.0 / n as f64;
    while step > 1e-10 {
        let mut moved = false;
        for a in 0..d {
            for s in [-step, step] {
                let mut u = at;
                u[a] = (u[a] + s).clamp(0.0, 1.0 - 1e-12);
                let v = peak(u);
                if v > best {
                    (best, at, moved) = (v, u, true);
                }
            }
        }
        if !moved {
            step *= 0.5;
        }
    }
    (best, at)
}

fn statistics<const D: usize>(rng: &mut Rng)
where
    Simplex: Noise<f32, D>,
{
    let noise = Simplex::new(11);
    let values: Vec<f64> = (0..1_000_000)
        .map(|_| {
            let p: [f32; D] = core::array::from_fn(|_| rng.f64_in(-1000.0, 1000.0) as f32);
            noise.sample(p) as f64
        })
        .collect();
    let (mean, var) = mean_variance(&values);
    let max = values.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    println!("{D}D: mean {mean:+.4}, variance {var:.4}, largest |n| {max:.4} over 10⁶ points");
    assert!(mean.abs() < 0.01, "{D}D mean {mean}");
    assert!(max <= noise.amplitude_bound::<D>() as f64, "{D}D max {max}");
}

/// Mean 0 and values within the bound over 10⁶ random points (variance printed).
#[test]
fn mean_and_range() {
    let mut rng = Rng::from_env(62);
    statistics::<1>(&mut rng);
    statistics::<2>(&mut rng);
    statistics::<3>(&mut rng);
    statistics::<4>(&mut rng);
}

/// Fixed point follows `f32` (each point exact in both); the gradient is the derivative (and
/// its value `sample`'s, bit for bit); batches are `sample`'s bits.
#[test]
fn fixed_point_gradient_and_batches() {
    let mut rng = Rng::from_env(63);
    let noise = Simplex::new(5);
    let diffs = [
        agree::fixed_vs_f32::<_, 1>(&noise, 200_000, 256, &mut rng),
        agree::fixed_vs_f32::<_, 2>(&noise, 200_000, 256, &mut rng),
        agree::fixed_vs_f32::<_, 3>(&noise, 200_000, 256, &mut rng),
        agree::fixed_vs_f32::<_, 4>(&noise, 200_000, 256, &mut rng),
    ];
    println!("largest |I16F16 − f32|, 1D–4D: {diffs:?}");
    assert!(diffs.iter().all(|&d| d < 1e-3), "{diffs:?}");
    let errors = [
        agree::gradient_error::<_, 1>(&noise, 5000, 300.0, 1e-6, &mut rng),
        agree::gradient_error::<_, 2>(&noise, 5000, 300.0, 1e-6, &mut rng),
        agree::gradient_error::<_, 3>(&noise, 5000, 300.0, 1e-6, &mut rng),
        agree::gradient_error::<_, 4>(&noise, 5000, 300.0, 1e-6, &mut rng),
    ];
    println!("gradient against central differences (error, largest component): {errors:?}");
    assert!(errors.iter().all(|&(e, _)| e < 1e-6), "{errors:?}");
    let steps = [0.013, 0.37, 1.7];
    agree::batches_match::<_, 1>(&noise, &steps, &mut rng);
    agree::batches_match::<_, 2>(&noise, &steps, &mut rng);
    agree::batches_match::<_, 3>(&noise, &steps, &mut rng);
    agree::batches_match::<_, 4>(&noise, &steps, &mut rng);
}

/// Any coordinate gives a value within the bound, never a panic: non-finite, huge, and
/// fixed point's extremes (whose skewed coordinates leave its range).
#[test]
fn total_on_bad_input() {
    let noise = Simplex::new(0);
    let bound = noise.amplitude_bound::<4>();
    for x in [
        f32::NAN,
        f32::INFINITY,
        -f32::INFINITY,
        f32::MAX,
        -f32::MAX,
        1e30,
        -3e9,
    ] {
        for p in [[x, 0.5, 0.25, 0.1], [0.3, x, x, 0.7], [x; 4]] {
            let v: f32 = noise.sample(p);
            let (w, g): (f32, [f32; 4]) = noise.sample_with_gradient(p);
            assert!(v.abs() <= bound && v.to_bits() == w.to_bits(), "{p:?}: {v}");
            assert!(g.iter().all(|c| c.is_finite()), "{p:?}: {g:?}");
        }
    }
    for x in [I16F16::MAX, I16F16::MIN, I16F16::DELTA, -I16F16::DELTA] {
        let v: I16F16 = noise.sample([x, x, x, x]);
        let (w, _): (I16F16, [I16F16; 4]) = noise.sample_with_gradient([x, I16F16::MIN, x, x]);
        assert!(v.to_num::<f32>().abs() <= bound && w.to_num::<f32>().abs() <= bound);
        let v3: I16F16 = noise.sample([x, x, x]);
        let v2: I16F16 = noise.sample([x, x]);
        assert!(v3.to_num::<f32>().abs() <= bound && v2.to_num::<f32>().abs() <= bound);
    }
}

/// Flow noise's scale (`406340 · 2⁻¹⁶`): the largest value over points and every choice of
/// gradient directions, each corner's gradient along its offset (`|d|`), searched as for
/// simplex noise, is 1.
#[test]
fn flow_largest_value_is_one() {
    let hash = Hash::new(0);
    let length = |_: u32, off: &[f64; 4]| (off[0] * off[0] + off[1] * off[1]).sqrt();
    let peak = |u: [f64; 4]| {
        let order = if u[0] > u[1] {
            [0, 1, 2, 3]
        } else {
            [1, 0, 2, 3]
        };
        reference(2, hash, [0; 4], u, order, 0.5, &length) * FLOW_SCALE / 65536.0
    };
    let (best, at) = largest(2, 256, peak);
    println!(
        "flow: largest value {best:.6} at skewed fractions {:?}",
        &at[..2]
    );
    assert!((0.99999..=1.0).contains(&best), "{best}");
}

const FLOW_SCALE: f64 = 406_340.0;

/// Flow noise against the reference with gradients `(cos 2π(h/256 + α), sin 2π(h/256 + α))`
/// (bandnoise's directions are a table turned by the angle's f32 cosine and sine); a full turn is the same noise and half
/// a turn its negation (every gradient reversed); turning decorrelates the noise while keeping
/// its variance (Perlin and Neyret's point); the gradient, fixed point, batches, bad input.
#[test]
fn flow_noise() {
    use bandnoise::simplex::Flow;
    let mut rng = Rng::from_env(64);
    for (seed, angle) in [(0u32, 0.0f32), (1, 0.3), (77, -2.85)] {
        let flow = Flow::new(seed).with_angle(angle).unwrap();
        let alpha = f64::from(flow.angle());
        let hash = Hash::new(seed);
        let turned = move |h: u32, off: &[f64; 4]| {
            // The direction from the hash's top 8 bits.
            let t = core::f64::consts::TAU * ((h >> 24) as f64 / 256.0 + alpha);
            t.cos() * off[0] + t.sin() * off[1]
        };
        let mut worst = 0.0f64;
        for _ in 0..20_000 {
            let p = [rng.f64_in(-300.0, 300.0), rng.f64_in(-300.0, 300.0)];
            let (cell, u, order) = skewed(2, &p);
            let want = reference(2, hash, cell, u, order, 0.5, &turned) * FLOW_SCALE / 65536.0;
            let v: f64 = flow.sample(p);
            worst = worst.max((v - want).abs());
        }
        println!("flow seed {seed} angle {angle}: largest |bandnoise − reference| {worst:.1e}");
        // The angle's cosine and sine are f32 settings (within 3·10⁻⁸ each), so each gradient
        // is off by up to 10⁻⁷, times |d|·τ⁴ < 0.7 over three corners, times the scale 6.2.
        assert!(worst < 5e-7, "seed {seed}: {worst}");
        let full = flow.clone().with_angle(angle + 1.0).unwrap();
        let half = flow.clone().with_angle(angle + 0.5).unwrap();
        for _ in 0..2_000 {
            let p = [
                rng.f64_in(-300.0, 300.0) as f32,
                rng.f64_in(-300.0, 300.0) as f32,
            ];
            let v: f32 = flow.sample(p);
            let w: f32 = full.sample(p);
            assert!((v - w).abs() < 1e-6, "{p:?}: a full turn {v} {w}");
            let h: f32 = half.sample(p);
            assert!((v + h).abs() < 1e-5, "{p:?}: half a turn {v} {h}");
        }
    }
    // Turning keeps the variance and decorrelates: a quarter turn apart, the noises are
    // uncorrelated (each gradient orthogonal to its former self).
    let flow = Flow::new(5);
    let quarter = flow.clone().with_angle(0.25).unwrap();
    let tenth = flow.clone().with_angle(0.1).unwrap();
    let points: Vec<[f64; 2]> = (0..200_000)
        .map(|_| [rng.f64_in(-1000.0, 1000.0), rng.f64_in(-1000.0, 1000.0)])
        .collect();
    let values = |n: &Flow| -> Vec<f64> { points.iter().map(|&p| n.sample(p)).collect() };
    let (a, b, c) = (values(&flow), values(&quarter), values(&tenth));
    let (_, va) = mean_variance(&a);
    let (_, vb) = mean_variance(&b);
    let (_, vc) = mean_variance(&c);
    let r = bandnoise_tests::correlation(&a, &b);
    let r10 = bandnoise_tests::correlation(&a, &c);
    println!(
        "flow variance {va:.4} / {vb:.4} / {vc:.4}; correlation a quarter turn apart {r:.4}, a tenth {r10:.4}"
    );
    assert!((vb / va - 1.0).abs() < 0.03 && (vc / va - 1.0).abs() < 0.03);
    assert!(r.abs() < 0.01, "{r}");
    // cos 2π·0.1 = 0.81: the noises a tenth of a turn apart correlate as their gradients do.
    assert!(
        (r10 - (core::f64::consts::TAU * 0.1).cos()).abs() < 0.02,
        "{r10}"
    );
    let (err, largest) = agree::gradient_error::<_, 2>(&tenth, 5_000, 100.0, 1e-6, &mut rng);
    assert!(err < 1e-6 * largest.max(1.0), "{err} of {largest}");
    agree::batches_match::<_, 2>(&tenth, &[0.0737, 1.3], &mut rng);
    let worst = agree::fixed_vs_f32::<_, 2>(&tenth, 100_000, 256, &mut rng);
    println!("flow: fixed point within {worst:.1e} of f32");
    assert!(worst < 1e-3, "{worst}");
    for a in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
        let e = Flow::new(1).with_angle(a).unwrap_err();
        assert!(matches!(e, bandnoise::Error::FlowAngle(b) if b.to_bits() == a.to_bits()));
    }
    for x in bandnoise_tests::BAD_F32 {
        for p in [[x, 0.5], [0.5, x], [x, x]] {
            let v: f32 = tenth.sample(p);
            let (_, g) = tenth.sample_with_gradient(p);
            assert!(v.abs() <= tenth.amplitude_bound::<2>() && g.iter().all(|c| c.is_finite()));
        }
    }
    let q: I16F16 = tenth.sample([I16F16::MAX, I16F16::MIN]);
    assert!(q.to_num::<f32>().abs() <= tenth.amplitude_bound::<2>());
}

/// Flow fBm: without advection and turning, `Fractal::fbm` of `Flow`, bit for bit; with
/// turning, each octave is `Flow` at `α·spinⁱ` (summed here by hand); advection moves the
/// octaves (the sum changes, stays within its bound); settings checked; bad input.
#[test]
fn flow_fbm() {
    use bandnoise::fractal::{Fractal, Octaves};
    use bandnoise::simplex::{Flow, FlowSum};
    let mut rng = Rng::from_env(65);
    let octaves = Octaves::new(5, 2.0, 0.5).unwrap();
    let still = FlowSum::new(Flow::new(4), octaves).with_spin(1.0).unwrap();
    let fractal = Fractal::fbm(Flow::new(4), octaves);
    let spun = FlowSum::new(Flow::new(4).with_angle(0.3).unwrap(), octaves);
    let advected = spun.clone().with_advection(0.5).unwrap();
    let mut moved = 0.0f64;
    for _ in 0..20_000 {
        let p = [rng.f64_in(-200.0, 200.0), rng.f64_in(-200.0, 200.0)];
        let (a, b): (f64, f64) = (still.sample(p), fractal.sample(p));
        assert_eq!(a.to_bits(), b.to_bits(), "{p:?}");
        let q = p.map(|x| x as f32);
        let (a, b): (f32, f32) = (still.sample(q), fractal.sample(q));
        assert_eq!(a.to_bits(), b.to_bits(), "{q:?}");
        let x = p.map(I16F16::from_num);
        let (a, b): (I16F16, I16F16) = (still.sample(x), fractal.sample(x));
        assert_eq!(a, b, "{x:?}");
        // Spin 2: octave i turned by 0.3·2^i.
        let mut want = 0.0f64;
        let (mut f, mut amp) = (1.0, 1.0);
        for i in 0..5 {
            let octave = Flow::new(4).with_angle(0.3f32 * (1 << i) as f32).unwrap();
            want += amp * octave.sample([p[0] * f, p[1] * f]);
            f *= 2.0;
            amp *= 0.5;
        }
        let got: f64 = spun.sample(p);
        assert!((got - want).abs() < 1e-12, "{p:?}: {got} {want}");
        let v: f64 = advected.sample(p);
        assert!(v.abs() <= f64::from(advected.amplitude_bound::<2>()));
        moved = moved.max((v - got).abs());
    }
    assert!(moved > 0.1, "advection moves the octaves: {moved}");
    for bad in [f32::NAN, f32::INFINITY, -0.5, 16.5] {
        assert!(spun.clone().with_spin(bad).is_err(), "spin {bad}");
    }
    for bad in [f32::NAN, f32::NEG_INFINITY, -16.5] {
        assert!(spun.clone().with_advection(bad).is_err(), "advection {bad}");
    }
    assert!(spun.clone().with_angle(f32::NAN).is_err());
    let strong = spun.with_advection(16.0).unwrap();
    for x in bandnoise_tests::BAD_F32 {
        for p in [[x, 0.5], [0.5, x], [x, x]] {
            let v: f32 = strong.sample(p);
            assert!(
                v.is_finite() && v.abs() <= strong.amplitude_bound::<2>(),
                "{p:?}"
            );
        }
    }
    for x in [I16F16::MAX, I16F16::MIN] {
        let v: I16F16 = strong.sample([x, I16F16::MIN]);
        assert!(v.to_num::<f32>().abs() <= strong.amplitude_bound::<2>());
    }
}

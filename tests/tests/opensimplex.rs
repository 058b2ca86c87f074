//! OpenSimplex2 and OpenSimplex2S against the reference implementation (the `opensimplex2`
//! crate 1.1.0, KdotJPG's own Rust port): within 10⁻⁶ in `f64` at 10⁵ random points per
//! dimension, orientation and seed; `f32` and I16F16 against `f64`; the amplitude bounds; bad
//! input.

use bandnoise::prelude::*;
use bandnoise::simplex::{Improve, OpenSimplex2, OpenSimplex2S};
use bandnoise_tests::{BAD_F32, Rng};
use opensimplex2::{fast, smooth};

/// The reference implementation with `f64` in place of its internal `f32` (a copy of the
/// crate's source, `tests/reference/README.md`): the same algorithm without the published
/// crate's `f32` rounding.
#[allow(
    warnings,
    clippy::all,
    clippy::pedantic,
    non_snake_case,
    static_mut_refs
)]
#[path = "../reference/opensimplex2_f64/fast.rs"]
mod fast64;
#[allow(
    warnings,
    clippy::all,
    clippy::pedantic,
    non_snake_case,
    static_mut_refs
)]
#[path = "../reference/opensimplex2_f64/smooth.rs"]
mod smooth64;

/// Seed 0, the reference's examples' seed, a negative seed and a large one.
const SEEDS: [i64; 4] = [0, 1337, -42, 0x0123_4567_89AB_CDEF];

/// The reference's function for a variant, dimension and orientation: the published crate's
/// (`f32` inside) and the `f64` copy's.
type Reference<const D: usize> = (fn(i64, [f64; D]) -> f64, fn(i64, [f64; D]) -> f64);

/// The functions of one reference module: 2D standard, 2D `ImproveX`, 3D fallback, 3D
/// `ImproveXY`, 3D `ImproveXZ`, 4D fallback, 4D `ImproveXYZ_ImproveXY`, `_ImproveXZ`.
macro_rules! functions {
    ($m:ident) => {
        (
            [
                |s, p: [f64; 2]| f64::from($m::noise2(s, p[0], p[1])),
                |s, p: [f64; 2]| f64::from($m::noise2_ImproveX(s, p[0], p[1])),
            ],
            [
                |s, p: [f64; 3]| f64::from($m::noise3_Fallback(s, p[0], p[1], p[2])),
                |s, p: [f64; 3]| f64::from($m::noise3_ImproveXY(s, p[0], p[1], p[2])),
                |s, p: [f64; 3]| f64::from($m::noise3_ImproveXZ(s, p[0], p[1], p[2])),
            ],
            [
                |s, p: [f64; 4]| f64::from($m::noise4_Fallback(s, p[0], p[1], p[2], p[3])),
                |s, p: [f64; 4]| {
                    f64::from($m::noise4_ImproveXYZ_ImproveXY(s, p[0], p[1], p[2], p[3]))
                },
                |s, p: [f64; 4]| {
                    f64::from($m::noise4_ImproveXYZ_ImproveXZ(s, p[0], p[1], p[2], p[3]))
                },
            ],
        )
    };
}

type Functions = (
    [fn(i64, [f64; 2]) -> f64; 2],
    [fn(i64, [f64; 3]) -> f64; 3],
    [fn(i64, [f64; 4]) -> f64; 3],
);

fn functions(smooth_variant: bool, exact: bool) -> Functions {
    match (smooth_variant, exact) {
        (false, false) => functions!(fast),
        (false, true) => functions!(fast64),
        (true, false) => functions!(smooth),
        (true, true) => functions!(smooth64),
    }
}

fn reference_2d(smooth_variant: bool, improve: Improve) -> Reference<2> {
    let i = usize::from(improve == Improve::XZ);
    (
        functions(smooth_variant, false).0[i],
        functions(smooth_variant, true).0[i],
    )
}

fn reference_3d(smooth_variant: bool, improve: Improve) -> Reference<3> {
    let i = improve as usize;
    (
        functions(smooth_variant, false).1[i],
        functions(smooth_variant, true).1[i],
    )
}

fn reference_4d(smooth_variant: bool, improve: Improve) -> Reference<4> {
    let i = improve as usize;
    (
        functions(smooth_variant, false).2[i],
        functions(smooth_variant, true).2[i],
    )
}

const IMPROVES: [Improve; 3] = [Improve::Standard, Improve::XY, Improve::XZ];

/// What a comparison found over its points.
#[derive(Default)]
struct Found {
    /// The largest `|ours − f64 copy|`.
    exact: f64,
    /// The largest `|ours − published crate|`.
    published: f64,
    /// The largest `|f64 copy − published crate|`: the crate's own `f32` rounding.
    rounding: f64,
    /// How many points are within 10⁻⁶ of the published crate.
    within: usize,
    /// The largest `|value|`.
    largest: f64,
}

/// Compares `noise` with the reference at `n` random points of `|x| < range`: within 10⁻⁶ of
/// the reference's algorithm in `f64`, and never farther from the published crate than that
/// algorithm is (the difference is the crate's `f32` rounding, nothing of ours).
fn compare<N: Noise<f64, D>, const D: usize>(
    noise: &N,
    reference: Reference<D>,
    seed: i64,
    n: usize,
    range: f64,
    rng: &mut Rng,
) -> Found {
    let mut found = Found::default();
    for _ in 0..n {
        let p: [f64; D] = core::array::from_fn(|_| rng.f64_in(-range, range));
        let ours = noise.sample(p);
        let (published, exact) = (reference.0(seed, p), reference.1(seed, p));
        let error = (ours - exact).abs();
        let rounding = (exact - published).abs();
        let apart = (ours - published).abs();
        assert!(
            error < 1e-6 && apart <= rounding + 1e-8,
            "{D}D seed {seed} at {p:?}: ours {ours}, reference {published} (in f64 {exact})"
        );
        found.exact = found.exact.max(error);
        found.published = found.published.max(apart);
        found.rounding = found.rounding.max(rounding);
        found.within += usize::from(apart < 1e-6);
        found.largest = found.largest.max(ours.abs());
    }
    found
}

fn reproduce<N, const D: usize>(
    name: &str,
    make: impl Fn(i64, Improve) -> N,
    reference: impl Fn(Improve) -> Reference<D>,
) where
    N: Noise<f64, D>,
{
    let mut rng = Rng::from_env(19);
    for improve in IMPROVES {
        for seed in SEEDS {
            let noise = make(seed, improve);
            // 10⁵ points for seed 0, fewer for the others; coordinates as a user's: a few
            // hundred cells around the origin.
            let n = if seed == 0 { 100_000 } else { 20_000 };
            let found = compare(&noise, reference(improve), seed, n, 300.0, &mut rng);
            println!(
                "{name} {D}D {improve:?} seed {seed}: from the f64 reference {:.1e}, from the \
                 crate {:.1e} ({:.3}% within 1e-6; the crate's own f32 rounding {:.1e}), \
                 max |n| {:.4}",
                found.exact,
                found.published,
                100.0 * found.within as f64 / n as f64,
                found.rounding,
                found.largest,
            );
        }
    }
}

/// One test per variant and dimension, each over every orientation and seed.
macro_rules! reproduces {
    ($($test:ident: $noise:ident, $reference:ident, $smooth:expr;)*) => {$(
        #[test]
        fn $test() {
            reproduce(
                stringify!($noise),
                |s, i| $noise::new(s).improving(i),
                |i| $reference($smooth, i),
            );
        }
    )*};
}

reproduces! {
    fast_2d_reproduces_the_reference: OpenSimplex2, reference_2d, false;
    fast_3d_reproduces_the_reference: OpenSimplex2, reference_3d, false;
    fast_4d_reproduces_the_reference: OpenSimplex2, reference_4d, false;
    smooth_2d_reproduces_the_reference: OpenSimplex2S, reference_2d, true;
    smooth_3d_reproduces_the_reference: OpenSimplex2S, reference_3d, true;
    smooth_4d_reproduces_the_reference: OpenSimplex2S, reference_4d, true;
}

/// `f32` and I16F16 follow `f64` (the number types differ only in the offsets' rounding and
/// the arithmetic after it); the largest differences over random exact points are printed.
fn number_types<N, const D: usize>(name: &str, noise: &N, f32_limit: f64, fixed_limit: f64)
where
    N: Noise<f64, D> + Noise<f32, D> + Noise<I16F16, D>,
{
    let mut rng = Rng::from_env(20);
    let (mut single, mut fixed) = (0.0f64, 0.0f64);
    for _ in 0..50_000 {
        let p: [I16F16; D] = rng.exact_point(200);
        let exact: f64 = noise.sample(bandnoise_tests::to_f64(p));
        let s: f32 = noise.sample(bandnoise_tests::to_f32(p));
        let q: I16F16 = noise.sample(p);
        single = single.max((f64::from(s) - exact).abs());
        fixed = fixed.max((q.to_num::<f64>() - exact).abs());
    }
    println!("{name} {D}D: f32 within {single:.1e} of f64, I16F16 within {fixed:.1e}");
    assert!(single < f32_limit, "{name} {D}D f32: {single}");
    assert!(fixed < fixed_limit, "{name} {D}D I16F16: {fixed}");
}

#[test]
fn f32_and_fixed_point_follow_f64() {
    for improve in IMPROVES {
        let fast = OpenSimplex2::new(5).improving(improve);
        let smooth = OpenSimplex2S::new(5).improving(improve);
        number_types::<_, 2>("OpenSimplex2", &fast, 2e-5, 2e-3);
        number_types::<_, 3>("OpenSimplex2", &fast, 2e-5, 2e-3);
        number_types::<_, 4>("OpenSimplex2", &fast, 2e-5, 2e-3);
        number_types::<_, 2>("OpenSimplex2S", &smooth, 2e-5, 2e-3);
        number_types::<_, 3>("OpenSimplex2S", &smooth, 2e-5, 2e-3);
        number_types::<_, 4>("OpenSimplex2S", &smooth, 2e-5, 2e-3);
    }
}

/// The largest `|n|` over random points stays below the proved bound (printed beside it).
fn within_bound<N, const D: usize>(name: &str, noise: &N)
where
    N: Noise<f64, D>,
{
    let mut rng = Rng::from_env(21);
    let bound = f64::from(noise.amplitude_bound());
    let mut largest = 0.0f64;
    for _ in 0..200_000 {
        let p: [f64; D] = core::array::from_fn(|_| rng.f64_in(-100.0, 100.0));
        largest = largest.max(noise.sample(p).abs());
    }
    println!("{name} {D}D: largest |n| {largest:.4}, proved bound {bound:.3}");
    assert!(largest <= bound);
}

#[test]
fn values_stay_within_the_proved_bound() {
    within_bound::<_, 1>("OpenSimplex2", &OpenSimplex2::new(3));
    within_bound::<_, 2>("OpenSimplex2", &OpenSimplex2::new(3));
    within_bound::<_, 3>("OpenSimplex2", &OpenSimplex2::new(3));
    within_bound::<_, 4>("OpenSimplex2", &OpenSimplex2::new(3));
    within_bound::<_, 1>("OpenSimplex2S", &OpenSimplex2S::new(3));
    within_bound::<_, 2>("OpenSimplex2S", &OpenSimplex2S::new(3));
    within_bound::<_, 3>("OpenSimplex2S", &OpenSimplex2S::new(3));
    within_bound::<_, 4>("OpenSimplex2S", &OpenSimplex2S::new(3));
}

#[test]
fn one_dimension_is_the_line_y_0() {
    let (fast, smooth) = (OpenSimplex2::new(8), OpenSimplex2S::new(8));
    for i in -100..100 {
        let x = f64::from(i) * 0.137 + 0.01;
        let a: f64 = fast.sample([x]);
        let b: f64 = fast.sample([x, 0.0]);
        assert_eq!(a.to_bits(), b.to_bits());
        let a: f64 = smooth.sample([x]);
        let b: f64 = smooth.sample([x, 0.0]);
        assert_eq!(a.to_bits(), b.to_bits());
    }
}

/// A non-finite coordinate is 0 (not spread to the other turned axes); every bad input gives a
/// value within the bound in every number type.
#[test]
fn total_on_bad_input() {
    fn check<N, const D: usize>(noise: &N)
    where
        N: Noise<f32, D> + Noise<f64, D>,
    {
        let bound = Noise::<f32, D>::amplitude_bound(noise);
        for &bad in &BAD_F32 {
            for axis in 0..D {
                let mut p = [0.37f32; D];
                p[axis] = bad;
                let v: f32 = noise.sample(p);
                assert!(v.abs() <= bound, "{bad} on axis {axis}: {v}");
                if !bad.is_finite() {
                    let mut zero = p;
                    zero[axis] = 0.0;
                    let w: f32 = noise.sample(zero);
                    assert_eq!(v.to_bits(), w.to_bits(), "{bad} on axis {axis}");
                }
                let v: f64 = noise.sample(p.map(f64::from));
                assert!(v.abs() <= f64::from(bound), "{bad} on axis {axis}: {v}");
            }
        }
        // The largest f64 coordinates overflow the turn to ±∞: defined, within the bound.
        let v: f64 = noise.sample([f64::MAX; D]);
        assert!(v.abs() <= f64::from(bound));
    }
    for improve in IMPROVES {
        let fast = OpenSimplex2::new(1).improving(improve);
        let smooth = OpenSimplex2S::new(1).improving(improve);
        check::<_, 1>(&fast);
        check::<_, 2>(&fast);
        check::<_, 3>(&fast);
        check::<_, 4>(&fast);
        check::<_, 1>(&smooth);
        check::<_, 2>(&smooth);
        check::<_, 3>(&smooth);
        check::<_, 4>(&smooth);
    }
    // Fixed point: the extremes of its range.
    let p = [I16F16::MIN, I16F16::MAX, I16F16::DELTA, -I16F16::DELTA];
    let fast = OpenSimplex2::new(1);
    let v: I16F16 = fast.sample(p);
    assert!(v.abs().to_num::<f32>() <= fast.amplitude_bound::<4>());
}

/// The largest jump of `f` found along random segments of length up to 0.1: the step of 64 with
/// the largest change is bisected 40 times, keeping the half with the larger change; a
/// continuous noise's change then vanishes (below 10⁻⁸ even in `f32` arithmetic), a jump's
/// stays.
fn largest_jump<const D: usize>(f: impl Fn([f64; D]) -> f64, segments: usize, seed: u64) -> f64 {
    let mut rng = Rng::from_env(seed);
    let mut largest = 0.0f64;
    for _ in 0..segments {
        let a: [f64; D] = core::array::from_fn(|_| rng.f64_in(-50.0, 50.0));
        let dir: [f64; D] = core::array::from_fn(|_| rng.f64_in(-0.05, 0.05));
        let at = |t: f64| f(core::array::from_fn(|i| a[i] + t * dir[i]));
        let (mut lo, mut hi) = (0.0, 1.0 / 64.0);
        let mut change = 0.0f64;
        for k in 0..64 {
            let (s, t) = (f64::from(k) / 64.0, f64::from(k + 1) / 64.0);
            let c = (at(t) - at(s)).abs();
            if c > change {
                (change, lo, hi) = (c, s, t);
            }
        }
        for _ in 0..40 {
            let mid = 0.5 * (lo + hi);
            if (at(mid) - at(lo)).abs() >= (at(hi) - at(mid)).abs() {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        largest = largest.max((at(hi) - at(lo)).abs());
    }
    largest
}

/// Where the reference takes a fixed set of vertices rather than every one in reach, the noise
/// jumps where that set changes while a vertex it drops is still in reach: the same jumps in
/// the published crate and here (they are the same function within 10⁻⁶). Printed: the
/// largest jumps found along the same segments for both; asserted: they agree, and the noises
/// that take every vertex in reach are continuous.
#[test]
fn continuity_is_the_reference_s() {
    fn both<N: Noise<f64, D>, const D: usize>(
        name: &str,
        noise: &N,
        reference: fn(i64, [f64; D]) -> f64,
    ) -> f64 {
        let ours = largest_jump(|p| noise.sample(p), 3_000, 22);
        let theirs = largest_jump(|p| reference(0, p), 3_000, 22);
        println!("{name} {D}D: largest jump {ours:.2e}, the reference's {theirs:.2e}");
        if theirs > 1e-4 {
            assert!(
                (ours - theirs).abs() < 0.01 * theirs,
                "{name} {D}D: {ours} vs {theirs}"
            );
        } else {
            // The reference's `f32` rounding alone shows as steps of a few 10⁻⁷.
            assert!(ours < 1e-9, "{name} {D}D: jumps by {ours}");
        }
        ours
    }
    let (fast, smooth) = (OpenSimplex2::new(0), OpenSimplex2S::new(0));
    let standard = Improve::Standard;
    let jumps = [
        both("OpenSimplex2", &fast, reference_2d(false, standard).0),
        both("OpenSimplex2", &fast, reference_3d(false, standard).0),
        both("OpenSimplex2", &fast, reference_4d(false, standard).0),
        both("OpenSimplex2S", &smooth, reference_2d(true, standard).0),
        both("OpenSimplex2S", &smooth, reference_3d(true, standard).0),
        both("OpenSimplex2S", &smooth, reference_4d(true, standard).0),
    ];
    // The fixed vertex sets: 3D and 4D OpenSimplex2, 3D OpenSimplex2S; the others take
    // every vertex in reach.
    let jumping = jumps.map(|j| j > 1e-4);
    assert_eq!(jumping, [false, true, true, false, true, false]);
}

/// The analytic gradient is the value's: central differences (`h = 10⁻⁶`, `f64`) agree within
/// 10⁻⁵ at random points, in every orientation (the chain rule through the turn and unskew);
/// the value beside it is `sample`'s, bit for bit; `f32` and I16F16 follow.
#[test]
fn gradients_are_the_derivatives() {
    fn check<N, const D: usize>(name: &str, noise: &N, rng: &mut Rng) -> f64
    where
        N: NoiseGradient<f64, D> + NoiseGradient<f32, D> + NoiseGradient<I16F16, D>,
    {
        let h = 1e-6;
        let mut worst = 0.0f64;
        let mut fixed = 0.0f64;
        let mut skipped = 0;
        for _ in 0..20_000 {
            let p: [f64; D] = core::array::from_fn(|_| rng.f64_in(-100.0, 100.0));
            let (v, g) = noise.sample_with_gradient(p);
            let s: f64 = noise.sample(p);
            assert_eq!(v.to_bits(), s.to_bits());
            for a in 0..D {
                let mut hi = p;
                let mut lo = p;
                hi[a] += h;
                lo[a] -= h;
                let (fh, fl): (f64, f64) = (noise.sample(hi), noise.sample(lo));
                let numeric = (fh - fl) / (2.0 * h);
                let error = (numeric - g[a]).abs();
                // A difference across one of the reference's jumps is no derivative: there
                // the one-sided differences disagree (for a smooth function by O(h·f″)).
                if ((fh - v) - (v - fl)).abs() / h > 1e-3 {
                    skipped += 1;
                    continue;
                }
                worst = worst.max(error);
            }
            // The other types at their own rounding of the point, against f64 there.
            let ps = p.map(|x| x as f32);
            let (_, gs): (f32, [f32; D]) = noise.sample_with_gradient(ps);
            let (_, g) = noise.sample_with_gradient(ps.map(f64::from));
            for a in 0..D {
                let e = (f64::from(gs[a]) - g[a]).abs();
                assert!(e < 1e-4, "{name} f32 at {ps:?}: {gs:?} vs {g:?}");
            }
            let pq = p.map(I16F16::from_num);
            let (_, gq): (I16F16, [I16F16; D]) = noise.sample_with_gradient(pq);
            let pf = pq.map(|x| x.to_num::<f64>());
            let (_, g) = noise.sample_with_gradient(pf);
            let e = (0..D)
                .map(|a| (gq[a].to_num::<f64>() - g[a]).abs())
                .fold(0.0, f64::max);
            if e > 0.01 {
                // Where f64's own gradient changes within 10⁻⁴ of the point, the point lies
                // on one of the reference's jumps, and fixed point's rounding (offsets to
                // 2⁻¹⁶, 4D's lattice step 0.2 to 13107·2⁻¹⁶ four times) took the other side;
                // anywhere else it is a failure.
                let near_jump = (0..2 * D).any(|k| {
                    let mut q = pf;
                    q[k / 2] += if k % 2 == 0 { 1e-4 } else { -1e-4 };
                    let (_, h) = noise.sample_with_gradient(q);
                    (0..D).any(|b| (h[b] - g[b]).abs() > 0.01)
                });
                assert!(near_jump, "{name} I16F16 at {pq:?}: {gq:?} vs {g:?}");
                skipped += 1;
            } else {
                fixed = fixed.max(e);
            }
        }
        println!(
            "{name} {D}D: gradient within {worst:.1e} of central differences ({skipped} \
             skipped across jumps); I16F16's within {fixed:.1e} of f64's"
        );
        assert!(worst < 1e-5, "{name} {D}D: {worst}");
        assert!(skipped < 20, "{name} {D}D: {skipped}");
        worst
    }
    let mut rng = Rng::from_env(23);
    for improve in IMPROVES {
        let fast = OpenSimplex2::new(11).improving(improve);
        let smooth = OpenSimplex2S::new(11).improving(improve);
        check::<_, 1>("OpenSimplex2", &fast, &mut rng);
        check::<_, 2>("OpenSimplex2", &fast, &mut rng);
        check::<_, 3>("OpenSimplex2", &fast, &mut rng);
        check::<_, 4>("OpenSimplex2", &fast, &mut rng);
        check::<_, 1>("OpenSimplex2S", &smooth, &mut rng);
        check::<_, 2>("OpenSimplex2S", &smooth, &mut rng);
        check::<_, 3>("OpenSimplex2S", &smooth, &mut rng);
        check::<_, 4>("OpenSimplex2S", &smooth, &mut rng);
    }
}

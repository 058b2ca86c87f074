//! Measured figures: output range over 10⁶ seeded points, fixed point against f32 over 10⁵
//! points, and seed decorrelation over a 256² grid. Each test prints what it measured.

use bandnoise::prelude::*;
use bandnoise_tests::{AllTypes, Lattice, Rng, correlation, for_each_dim, to_f32};

/// Per noise, seed, dimension and number type.
const RANGE_POINTS: usize = 1_000_000;

fn max_abs<const D: usize>(noise: &Lattice, name: &str, rng: &mut Rng)
where
    Lattice: AllTypes<D>,
{
    let bound = Noise::<f32, D>::amplitude_bound(noise);
    let (mut m32, mut m64, mut mfx) = (0.0f64, 0.0f64, 0.0f64);
    for _ in 0..RANGE_POINTS {
        let p: [f64; D] = core::array::from_fn(|_| rng.f64_in(-1000.0, 1000.0));
        let v64: f64 = noise.sample(p);
        let v32: f32 = noise.sample(p.map(|x| x as f32));
        let fx: [I16F16; D] = core::array::from_fn(|_| I16F16::from_bits(rng.next_u64() as i32));
        let vfx: I16F16 = noise.sample(fx);
        assert!(!v64.is_nan() && !v32.is_nan());
        m64 = m64.max(v64.abs());
        m32 = m32.max(v32.abs() as f64);
        mfx = mfx.max(vfx.to_num::<f64>().abs());
    }
    println!("{name:>10} {D}D: max |n| f64 {m64:.4}, f32 {m32:.4}, I16F16 {mfx:.4}; bound {bound}");
    for (ty, m) in [("f64", m64), ("f32", m32), ("I16F16", mfx)] {
        assert!(
            m <= bound as f64,
            "{name} {D}D {ty}: {m} exceeds the documented bound {bound}"
        );
    }
}

#[test]
fn output_never_exceeds_the_documented_bound() {
    let mut rng = Rng::from_env(4);
    for seed in [0, 7919] {
        for (name, noise) in Lattice::all(seed) {
            for_each_dim!(max_abs(&noise, name, &mut rng));
        }
    }
}

fn fixed_vs_f32<const D: usize>(noise: &Lattice, name: &str, rng: &mut Rng) -> f64
where
    Lattice: AllTypes<D>,
{
    let mut worst = 0.0f64;
    for _ in 0..100_000 {
        // Points both types hold exactly, so only the arithmetic differs.
        let p: [I16F16; D] = rng.exact_point(256);
        let fx: I16F16 = noise.sample(p);
        let fl: f32 = noise.sample(to_f32(p));
        worst = worst.max((fx.to_num::<f64>() - fl as f64).abs());
    }
    println!(
        "{name:>10} {D}D: max |I16F16 − f32| = {worst:.3e} ({:.2} × 2⁻¹⁶)",
        worst * 65536.0
    );
    worst
}

#[test]
fn fixed_point_agrees_with_f32_within_2_pow_minus_11() {
    let mut rng = Rng::from_env(5);
    let mut overall = 0.0f64;
    for (name, noise) in Lattice::all(3) {
        let worst = [
            fixed_vs_f32::<1>(&noise, name, &mut rng),
            fixed_vs_f32::<2>(&noise, name, &mut rng),
            fixed_vs_f32::<3>(&noise, name, &mut rng),
            fixed_vs_f32::<4>(&noise, name, &mut rng),
        ]
        .into_iter()
        .fold(0.0, f64::max);
        overall = overall.max(worst);
        assert!(worst <= 1.0 / 2048.0, "{name}: {worst} > 2^-11");
    }
    println!("largest |I16F16 − f32| over every noise and dimension: {overall:.3e}");
}

#[test]
fn seeds_are_decorrelated() {
    // 256² samples 0.37 apart: about 95 cells per side.
    let grid = |noise: &Lattice| -> Vec<f64> {
        let mut v = Vec::with_capacity(256 * 256);
        for j in 0..256 {
            for i in 0..256 {
                let s: f64 = noise.sample([i as f64 * 0.37 + 0.1, j as f64 * 0.37 + 0.2]);
                v.push(s);
            }
        }
        v
    };
    for (a, b) in [(0u32, 1u32), (1, 2), (2, 3), (12345, 12346)] {
        for ((name, na), (_, nb)) in Lattice::all(a).into_iter().zip(Lattice::all(b)) {
            let r = correlation(&grid(&na), &grid(&nb));
            println!("{name:>10} seeds {a} and {b}: correlation {r:+.4}");
            assert!(r.abs() < 0.05, "{name}: seeds {a} and {b} correlate {r}");
        }
    }
}

/// The largest `|n|` of `MNoise<61>` over every cell centre of one period (`61^D` cells), for
/// `seed`: the figures its docs give. The bound `D/2` needs a cell whose gradients all point
/// outward; the BBS hash has one in 1D and 2D only.
#[test]
fn mnoise_maxima_over_cell_centres() {
    fn max_at_centres<const D: usize>(m: &MNoise<61>) -> f64 {
        let mut best = 0.0f64;
        for i in 0..61usize.pow(D as u32) {
            let mut rest = i;
            let p: [f64; D] = core::array::from_fn(|_| {
                let c = rest % 61;
                rest /= 61;
                c as f64 + 0.5
            });
            let v: f64 = m.sample(p);
            best = best.max(v.abs());
        }
        best
    }
    for seed in [0, 1, 77] {
        let m = MNoise::<61>::new(seed);
        let maxima = [
            max_at_centres::<1>(&m),
            max_at_centres::<2>(&m),
            max_at_centres::<3>(&m),
            if seed == 0 {
                max_at_centres::<4>(&m)
            } else {
                1.375
            },
        ];
        println!("mNoise<61> seed {seed}: max |n| over cell centres, 1D–4D: {maxima:?}");
        assert_eq!(maxima, [0.5, 1.0, 1.375, 1.375], "seed {seed}");
    }
}

/// Uniform multiband noise reaches the ends of `[-1, 1]`: `erf` rounds to ±1 in the tails.
#[test]
fn uniform_distribution_reaches_its_ends() {
    use bandnoise::wavelet::erf;
    // The first inputs whose erf is 1 (found by walking every value up from 3).
    let first = 3.875_808_2f32;
    assert_eq!(erf(first), 1.0);
    assert!(erf(f32::from_bits(first.to_bits() - 1)) < 1.0);
    assert_eq!(erf(-4.0f32), -1.0);
    let first = I16F16::from_num(3.09375);
    assert_eq!(erf(-first), -I16F16::ONE);
    assert!(erf(first - I16F16::DELTA) < I16F16::ONE);
}

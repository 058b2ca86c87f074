//! Olano's mixed mNoise (§3.4): the table evaluation gives the computed `MNoise<61>` bit for bit,
//! for every input.
//!
//! * I16F16: every cell of a period in 2D and 3D at an off-lattice point, and random points in
//!   1D–4D over the whole I16F16 range (every cell an I16F16 point can be in reduces to one of a
//!   period's, but the reduction itself is compared there too);
//! * `f32` and `f64`: 10⁵ random points per dimension, near the origin and far from it;
//! * gradients, the batch paths (grids off the lattice, scattered points) and bad input (NaN,
//!   ±∞, huge, I16F16's extremes), against the computed noise's;
//! * several seeds (0: Olano's noise; others translate the lattice and flip gradient axes).

use bandnoise::lattice::{MNoise, MixedMNoise};
use bandnoise::{I16F16, Noise, NoiseGradient, Real};
use bandnoise_tests::{BAD_F32, Rng, agree};

const SEEDS: [u32; 4] = [0, 1, 77, 0xDEAD_BEEF];

/// Value and gradient of both at `p`, bit for bit.
fn same<R: Real + core::fmt::Debug, const D: usize>(
    mixed: &MixedMNoise,
    computed: &MNoise<61>,
    p: [R; D],
) where
    MixedMNoise: NoiseGradient<R, D>,
    MNoise<61>: NoiseGradient<R, D>,
{
    // `to_f64` is exact for f32, f64 and I16F16, and keeps the sign of a zero.
    let bits = |v: R| v.to_f64().to_bits();
    let (a, b) = (mixed.sample(p), computed.sample(p));
    assert!(bits(a) == bits(b), "{p:?}: {a:?} != {b:?}");
    let (va, ga) = mixed.sample_with_gradient(p);
    let (vb, gb) = computed.sample_with_gradient(p);
    assert!(bits(va) == bits(vb), "{p:?}: value with gradient");
    for (x, y) in ga.iter().zip(&gb) {
        assert!(bits(*x) == bits(*y), "{p:?}: {ga:?} != {gb:?}");
    }
}

#[test]
fn every_cell_of_a_period_in_fixed_point() {
    let off = I16F16::from_bits(0x5A3C);
    for seed in SEEDS {
        let (mixed, computed) = (MixedMNoise::new(seed), MNoise::<61>::new(seed));
        for x in 0..61 {
            let px = I16F16::from_num(x) + off;
            for y in 0..61 {
                let py = I16F16::from_num(y) + off;
                same(&mixed, &computed, [px, py]);
                for z in 0..61 {
                    same(&mixed, &computed, [px, py, I16F16::from_num(z) + off]);
                }
            }
        }
    }
}

#[test]
fn random_points_in_every_number_type() {
    let mut rng = Rng::from_env(19);
    for seed in SEEDS {
        let (mixed, computed) = (MixedMNoise::new(seed), MNoise::<61>::new(seed));
        for i in 0..100_000 {
            // Near the origin, then across I16F16's range and f32's exact integers.
            let range = if i % 2 == 0 { 200.0 } else { 3e4 };
            let mut f = || rng.f64_in(-range, range);
            let p4 = [f(), f(), f(), f()];
            same(&mixed, &computed, [p4[0]]);
            same(&mixed, &computed, [p4[0], p4[1]]);
            same(&mixed, &computed, [p4[0], p4[1], p4[2]]);
            same(&mixed, &computed, p4);
            let q = p4.map(|x| x as f32);
            same(&mixed, &computed, [q[0], q[1]]);
            same(&mixed, &computed, [q[0], q[1], q[2]]);
            same(&mixed, &computed, q);
            let q = p4.map(I16F16::from_num);
            same(&mixed, &computed, [q[0]]);
            same(&mixed, &computed, [q[0], q[1], q[2]]);
            same(&mixed, &computed, q);
        }
        // Far from the origin in floats (cells beyond I16F16's range, reduced in 64 bits).
        for _ in 0..10_000 {
            let mut f = || rng.f64_in(-1e9, 1e9);
            same(&mixed, &computed, [f(), f(), f()]);
            same(
                &mixed,
                &computed,
                [f() as f32, f() as f32, f() as f32, f() as f32],
            );
        }
    }
}

#[test]
fn batches_and_bad_input() {
    let mut rng = Rng::from_env(20);
    let mixed = MixedMNoise::new(9);
    let computed = MNoise::<61>::new(9);
    agree::batches_match::<_, 2>(&mixed, &[0.0737, 1.3], &mut rng);
    agree::batches_match::<_, 3>(&mixed, &[0.0737, 0.61], &mut rng);
    agree::batches_match::<_, 4>(&mixed, &[0.0737], &mut rng);
    // The batches also equal the computed noise's (the same grid through both).
    let grid = bandnoise::batch::Grid::new([-3.17f32, 40.3, 7.9], [0.0737, 0.11, 0.29], [37, 5, 3]);
    let (mut a, mut b) = (vec![0.0f32; grid.len()], vec![0.0f32; grid.len()]);
    mixed.fill_grid(&grid, &mut a).unwrap();
    computed.fill_grid(&grid, &mut b).unwrap();
    assert_eq!(a, b);
    for x in BAD_F32 {
        for p in [[x, 0.5, 0.25], [0.5, x, 0.25], [0.5, 0.25, x], [x, x, x]] {
            same(&mixed, &computed, p);
            same(&mixed, &computed, [p[0], p[1], p[2], x]);
        }
    }
    for x in [I16F16::MAX, I16F16::MIN, I16F16::DELTA, -I16F16::DELTA] {
        same(&mixed, &computed, [x, I16F16::MIN, x]);
        same(&mixed, &computed, [x, x, I16F16::MAX, x]);
    }
}

/// Dimension reducibility carries over: a lower dimension is the slice at 0 of the higher.
#[test]
fn dimension_reducible() {
    let mut rng = Rng::from_env(21);
    for seed in SEEDS {
        let mixed = MixedMNoise::new(seed);
        for _ in 0..10_000 {
            let p: [I16F16; 2] = rng.exact_point(200);
            let z = I16F16::ZERO;
            let two: I16F16 = mixed.sample(p);
            assert_eq!(mixed.sample([p[0], p[1], z]), two);
            assert_eq!(mixed.sample([p[0], p[1], z, z]), two);
            assert_eq!(mixed.sample([p[0], z]), mixed.sample([p[0]]));
        }
    }
}

/// Olano's turbulence, octaves evaluated together, is the fractal sum of computed mNoise octave
/// by octave, bit for bit (value, and gradient), in every number type and dimension.
#[test]
fn turbulence_is_the_fractal_sum_of_computed_mnoise() {
    use bandnoise::fractal::{Fractal, Octaves};
    use bandnoise::lattice::MixedTurbulence;
    fn check<const N: usize>(seed: u32, rng: &mut Rng) {
        let t = MixedTurbulence::<N>::new(seed);
        let octaves = Octaves::new(N as u32, 2.0, 0.5).unwrap();
        let sum = Fractal::turbulence(MNoise::<61>::new(seed), octaves);
        let bits = |v: f64| v.to_bits();
        for i in 0..10_000 {
            let range = if i % 2 == 0 { 100.0 } else { 2e4 };
            let mut f = || rng.f64_in(-range, range);
            let p = [f(), f(), f(), f()];
            let q = p.map(|x| x as f32);
            let x = p.map(I16F16::from_num);
            let same = |a: f64, b: f64| assert_eq!(bits(a), bits(b), "{N} octaves at {p:?}");
            same(t.sample([p[0], p[1]]), sum.sample([p[0], p[1]]));
            same(t.sample([p[0], p[1], p[2]]), sum.sample([p[0], p[1], p[2]]));
            same(t.sample(p), sum.sample(p));
            let (a, b): (f32, f32) = (t.sample([q[0], q[1], q[2]]), sum.sample([q[0], q[1], q[2]]));
            same(a.into(), b.into());
            let (a, b): (I16F16, I16F16) =
                (t.sample([x[0], x[1], x[2]]), sum.sample([x[0], x[1], x[2]]));
            assert_eq!(a, b, "{N} octaves at {x:?}");
            let (a, b): (I16F16, I16F16) = (t.sample(x), sum.sample(x));
            assert_eq!(a, b, "{N} octaves at {x:?}");
            let (v, g) = t.sample_with_gradient([q[0], q[1]]);
            assert_eq!(v.to_bits(), t.sample([q[0], q[1]]).to_bits());
            assert_eq!(g, sum.sample_with_gradient([q[0], q[1]]).1);
        }
        assert_eq!(t.amplitude_bound::<3>(), sum.amplitude_bound::<3>());
        for x in [f32::NAN, f32::INFINITY, -3e38, 1e-40] {
            let v: f32 = t.sample([x, 0.5, x]);
            assert!(v.is_finite() && v <= t.amplitude_bound::<3>() && v >= 0.0);
        }
        let v: I16F16 = t.sample([I16F16::MAX, I16F16::MIN, I16F16::MAX]);
        assert!(v >= I16F16::ZERO && v.to_num::<f32>() <= t.amplitude_bound::<3>());
    }
    let mut rng = Rng::from_env(22);
    for seed in [0, 5] {
        check::<1>(seed, &mut rng);
        check::<4>(seed, &mut rng);
        check::<8>(seed, &mut rng);
    }
    // Deep enough that fixed-point frequencies saturate.
    check::<20>(1, &mut rng);
}

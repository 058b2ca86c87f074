//! Property tests (proptest): periodicity, dimension reducibility, output range, derivative
//! consistency, seed decorrelation and fixed-point agreement, over generated noises and points.
//! A failure prints the minimal input; `PROPTEST_CASES` raises the case count.

use bandnoise::prelude::*;
use bandnoise_tests::{Lattice, correlation};
use proptest::prelude::*;

/// A coordinate both I16F16 and f32 hold exactly: a multiple of 2⁻¹⁶ below 256 in magnitude.
fn exact() -> impl Strategy<Value = I16F16> {
    (-(256 << 16) + 1..(256 << 16)).prop_map(I16F16::from_bits)
}

fn lattice() -> impl Strategy<Value = (usize, u32)> {
    (0usize..6, any::<u32>())
}

fn noise(i: usize, seed: u32) -> Lattice {
    Lattice::all(seed).swap_remove(i).1
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    #[test]
    fn mnoise_is_periodic_in_every_axis(seed in any::<u32>(), x in exact(), y in exact(), z in exact(), axis in 0usize..3) {
        let m = MNoise::<61>::new(seed);
        let p = [x, y, z];
        let mut q = p;
        q[axis] += I16F16::from_num(61);
        let (a, b): (I16F16, I16F16) = (m.sample(p), m.sample(q));
        prop_assert_eq!(a, b);
    }

    #[test]
    fn olano_noises_are_dimension_reducible(seed in any::<u32>(), x in exact(), y in exact(), z in exact(), which in 0usize..3) {
        let n = vec![Lattice::M61(MNoise::new(seed)), Lattice::M4093(MNoise::seeded(seed)), Lattice::C(CNoise::new(seed))].swap_remove(which);
        let (a, b): (f32, f32) = (n.sample([x.to_num(), y.to_num(), z.to_num(), 0.0]), n.sample([x.to_num(), y.to_num(), z.to_num()]));
        prop_assert_eq!(a.to_bits(), b.to_bits());
        let (a, b): (I16F16, I16F16) = (n.sample([x, y, I16F16::ZERO]), n.sample([x, y]));
        prop_assert_eq!(a, b);
    }

    #[test]
    fn output_stays_within_the_documented_bound((i, seed) in lattice(), p in prop::array::uniform4(any::<f32>())) {
        let n = noise(i, seed);
        let v: f32 = n.sample(p);
        prop_assert!(!v.is_nan() && v.abs() <= Noise::<f32, 4>::amplitude_bound(&n));
        let v: f32 = n.sample([p[0], p[1]]);
        prop_assert!(v.abs() <= Noise::<f32, 2>::amplitude_bound(&n));
    }

    #[test]
    fn gradients_match_central_differences((i, seed) in lattice(), p in prop::array::uniform3(-100.0f32..100.0)) {
        let n = noise(i, seed);
        prop_assume!(!matches!(n, Lattice::Original(_))); // only C¹: central differences jump at faces
        let (_, g) = n.sample_with_gradient(p);
        let h = 1.0 / 512.0;
        for a in 0..3 {
            let (mut hi, mut lo) = (p, p);
            hi[a] += h;
            lo[a] -= h;
            let (nh, nl): (f32, f32) = (n.sample(hi), n.sample(lo));
            let central = (nh - nl) / (hi[a] - lo[a]);
            prop_assert!((g[a] - central).abs() <= 1e-3, "axis {}: {} vs {}", a, g[a], central);
        }
    }

    #[test]
    fn fixed_point_agrees_with_f32((i, seed) in lattice(), x in exact(), y in exact(), z in exact()) {
        let n = noise(i, seed);
        let a: I16F16 = n.sample([x, y, z]);
        let b: f32 = n.sample([x.to_num(), y.to_num(), z.to_num()]);
        prop_assert!((a.to_num::<f32>() - b).abs() <= 1.0 / 2048.0);
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    #[test]
    fn different_seeds_are_decorrelated(i in 0usize..6, s1 in any::<u32>(), s2 in any::<u32>()) {
        prop_assume!(s1 != s2);
        // mNoise with M = 61 has too few seeded noises for this to hold for every pair: see
        // `mnoise61_seeds_are_decorrelated_but_for_nearby_translations`.
        prop_assume!(Lattice::all(0)[i].0 != "mnoise");
        let r = correlation(&seed_grid(&noise(i, s1)), &seed_grid(&noise(i, s2)));
        // 128² samples over ~90² cells: the estimate's spread is about 0.02.
        prop_assert!(r.abs() < 0.1, "correlation {}", r);
    }
}

/// The 2D grid the seed tests sample: 128² points over about 90² cells.
fn seed_grid(n: &Lattice) -> Vec<f64> {
    (0..128 * 128)
        .map(|k| n.sample([(k % 128) as f64 * 0.71 + 0.1, (k / 128) as f64 * 0.71 + 0.2]))
        .collect()
}

#[test]
fn mnoise61_seeds_are_decorrelated_but_for_nearby_translations() {
    // A seed of MNoise<61> is a translation in [0, 61)^4 and a sign mask, so two seeds are
    // translated copies of one noise, and correlate when their translations lie within about
    // a cell of each other mod 61 (measured over 2000 pairs: rms 0.023, 0.85% of pairs at
    // |r| >= 0.1, the worst 0.27; 2229309011 and 3232270671 give 0.10). There are only 14884
    // distinct 2D noises, so now and then a pair is the same noise (r = 1). Asserted: the typical
    // pair is decorrelated (median), and correlated pairs stay rare (at most 2.5%).
    let index = Lattice::all(0)
        .iter()
        .position(|(name, _)| *name == "mnoise")
        .unwrap();
    let mut rng = bandnoise_tests::Rng::from_env(61);
    let pairs = 400;
    let r: Vec<f64> = (0..pairs)
        .map(|_| {
            let (s1, s2) = (rng.next_u64() as u32, rng.next_u64() as u32);
            correlation(&seed_grid(&noise(index, s1)), &seed_grid(&noise(index, s2)))
        })
        .collect();
    let mut abs: Vec<f64> = r.iter().map(|r| r.abs()).collect();
    abs.sort_by(f64::total_cmp);
    let (median, worst) = (abs[pairs / 2], abs[pairs - 1]);
    let high = abs.iter().filter(|&&r| r >= 0.1).count();
    println!(
        "MNoise<61>, {pairs} seed pairs: median |r| {median:.4}, worst {worst:.3}, {high} at |r| >= 0.1"
    );
    // A spread of 0.025 puts the median |r| of unrelated pairs near 0.017.
    assert!(median < 0.03, "median |correlation| {median}");
    assert!(
        high <= pairs / 40,
        "{high} of {pairs} pairs correlate at 0.1 or more"
    );
}

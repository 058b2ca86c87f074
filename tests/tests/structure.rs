//! Golden values and the structural properties the papers promise: Perlin's reference value,
//! zeros on the lattice, periodicity, and Olano's dimension reducibility, bit for bit.

use bandnoise::prelude::*;
use bandnoise_tests::{AllTypes, Lattice, Rng, for_each_dim, to_f32, to_f64};

#[test]
#[allow(
    clippy::approx_constant,
    reason = "Perlin's reference input is 3.14, not π"
)]
fn perlin_reference_value() {
    let p = Perlin::new(0);
    // Ken Perlin's reference implementation of improved noise gives this for (3.14, 42, 7).
    let want = 0.13691995878400012f64;
    let f64v: f64 = p.sample([3.14, 42.0, 7.0]);
    assert_eq!(f64v.to_bits(), want.to_bits());

    // f32: the inputs round (3.14f32 = 3.1400001) and so does every operation.
    let f32v: f32 = p.sample([3.14, 42.0, 7.0]);
    let at_rounded_input: f64 = p.sample([3.14f32 as f64, 42.0, 7.0]);
    println!(
        "f32 {f32v:.9}, |f32 − reference| = {:.2e}, |f32 − f64 at the f32 input| = {:.2e}",
        (f32v as f64 - want).abs(),
        (f32v as f64 - at_rounded_input).abs()
    );
    // Arithmetic rounding alone: a few f32 ulps of the intermediate values (all below 4).
    assert!((f32v as f64 - at_rounded_input).abs() <= 8.0 * f32::EPSILON as f64);
    assert!((f32v as f64 - want).abs() <= 1e-6);

    let fixed: I16F16 = p.sample([
        I16F16::from_num(3.14),
        I16F16::from_num(42),
        I16F16::from_num(7),
    ]);
    assert!((fixed.to_num::<f64>() - want).abs() <= 1.0 / 2048.0);
}

fn zero_on_lattice<const D: usize>(noise: &Lattice, name: &str, rng: &mut Rng)
where
    Lattice: AllTypes<D>,
{
    for _ in 0..2000 {
        let cell: [i32; D] = core::array::from_fn(|_| rng.i32_in(-30000, 30000));
        let f: f64 = noise.sample(cell.map(|c| c as f64));
        let s: f32 = noise.sample(cell.map(|c| c as f32));
        let x: I16F16 = noise.sample(cell.map(I16F16::from_num));
        assert_eq!(
            (f.to_bits(), s.to_bits(), x),
            (0, 0, I16F16::ZERO),
            "{name} {D}D at {cell:?}"
        );
    }
}

#[test]
fn gradient_noises_are_zero_on_the_lattice() {
    let mut rng = Rng::from_env(1);
    for (name, noise) in Lattice::gradient_noises(5) {
        for_each_dim!(zero_on_lattice(&noise, name, &mut rng));
    }
}

fn periodic<const D: usize>(noise: &Lattice, name: &str, period: i32, rng: &mut Rng)
where
    Lattice: AllTypes<D>,
{
    for _ in 0..5000 {
        let p: [I16F16; D] = rng.exact_point(256);
        let axis = rng.i32_in(0, D as i32) as usize;
        let mut q = p;
        q[axis] += I16F16::from_num(period);
        let (a, b): (I16F16, I16F16) = (noise.sample(p), noise.sample(q));
        assert_eq!(a, b, "{name} {D}D period {period} along {axis} at {p:?}");
        let (a, b): (f64, f64) = (noise.sample(to_f64(p)), noise.sample(to_f64(q)));
        assert_eq!(a.to_bits(), b.to_bits(), "{name} f64 {D}D");
    }
}

#[test]
fn mnoise_is_periodic_with_period_m_and_the_others_with_256() {
    let mut rng = Rng::from_env(2);
    for seed in [0, 1, 77] {
        for (name, noise) in Lattice::all(seed) {
            let period = match noise {
                Lattice::M61(_) => 61,
                Lattice::M4093(_) => 4093,
                _ => 256,
            };
            for_each_dim!(periodic(&noise, name, period, &mut rng));
        }
    }
}

/// `noise_{D+1}(p, 0) == noise_D(p)` in every number type, bit for bit.
fn reducible<const D: usize, const E: usize>(noise: &Lattice, name: &str, rng: &mut Rng)
where
    Lattice: AllTypes<D> + AllTypes<E>,
{
    assert_eq!(E, D + 1);
    for _ in 0..20_000 {
        let p: [I16F16; D] = rng.exact_point(256);
        let q: [I16F16; E] = core::array::from_fn(|a| if a < D { p[a] } else { I16F16::ZERO });
        let (lo, hi): (I16F16, I16F16) = (noise.sample(p), noise.sample(q));
        assert_eq!(lo, hi, "{name} fixed {E}D → {D}D at {p:?}");
        let (lo, hi): (f32, f32) = (noise.sample(to_f32(p)), noise.sample(to_f32(q)));
        assert_eq!(
            lo.to_bits(),
            hi.to_bits(),
            "{name} f32 {E}D → {D}D at {p:?}"
        );
        let (lo, hi): (f64, f64) = (noise.sample(to_f64(p)), noise.sample(to_f64(q)));
        assert_eq!(
            lo.to_bits(),
            hi.to_bits(),
            "{name} f64 {E}D → {D}D at {p:?}"
        );
    }
}

#[test]
fn mnoise_and_cnoise_are_dimension_reducible_bit_for_bit() {
    let mut rng = Rng::from_env(3);
    for seed in [0, 1, 2, 12345, u32::MAX] {
        for (name, noise) in Lattice::all(seed) {
            if !matches!(noise, Lattice::M61(_) | Lattice::M4093(_) | Lattice::C(_)) {
                continue;
            }
            reducible::<1, 2>(&noise, name, &mut rng);
            reducible::<2, 3>(&noise, name, &mut rng);
            reducible::<3, 4>(&noise, name, &mut rng);
        }
    }
}

#[test]
fn mnoise_seed_zero_is_olanos_hash_chain() {
    // At the centre of cell (x, y) the 2D value is ±½ ± ½ summed over corners; check the corner
    // gradient signs directly against hash(x + hash(y)).
    use bandnoise::hash::Bbs;
    let m = MNoise::<61>::new(0);
    for x in -70..70 {
        for y in -70..70 {
            // Just off the lower corner, the noise is the corner's gradient dot the offset.
            let e = 1.0 / 1024.0;
            let v: f64 = m.sample([x as f64 + e, y as f64 + 2.0 * e]);
            let h = Bbs::<61>::hash2(x, y);
            let sx = if h & 1 == 0 { 1.0 } else { -1.0 };
            let sy = if h & 2 == 0 { 1.0 } else { -1.0 };
            let want = sx * e + sy * 2.0 * e;
            assert!((v - want).abs() < 1e-6, "cell ({x}, {y}): {v} vs {want}");
        }
    }
}

/// `Perlin` is its doubled permutation on every target (the x86-64 point kernel's table is
/// static); `TabledPerlin` adds its per-seed table only where a kernel reads it, and gives
/// Perlin's values bit for bit on every path.
#[test]
fn perlin_has_one_size_and_the_tabled_perlin_its_values() {
    assert_eq!(size_of::<Perlin>(), 512);
    // Two 16 KiB tables: 2D/3D gradient pairs and 4D ones.
    let table = if cfg!(target_arch = "x86_64") {
        32 * 1024
    } else {
        0
    };
    assert!(size_of::<TabledPerlin>() >= 512 + table);
    assert!(size_of::<TabledPerlin>() <= 512 + table + 32);

    fn same<const D: usize>(perlin: &Perlin, tabled: &TabledPerlin, rng: &mut Rng)
    where
        Perlin: AllTypes<D> + NoiseGradient<f32, D>,
        TabledPerlin: AllTypes<D> + NoiseGradient<f32, D>,
    {
        for _ in 0..20_000 {
            let p: [f32; D] = core::array::from_fn(|_| rng.f64_in(-300.0, 300.0) as f32);
            let (a, b): (f32, f32) = (perlin.sample(p), tabled.sample(p));
            assert_eq!(a.to_bits(), b.to_bits(), "{D}D f32 at {p:?}");
            let (a, b) = (
                perlin.sample_with_gradient(p),
                tabled.sample_with_gradient(p),
            );
            assert_eq!(a, b, "{D}D gradient at {p:?}");
            let q: [I16F16; D] = p.map(I16F16::from_num);
            let (a, b): (I16F16, I16F16) = (perlin.sample(q), tabled.sample(q));
            assert_eq!(a, b, "{D}D I16F16 at {p:?}");
            let r = p.map(f64::from);
            let (a, b): (f64, f64) = (perlin.sample(r), tabled.sample(r));
            assert_eq!(a.to_bits(), b.to_bits(), "{D}D f64 at {p:?}");
        }
    }
    let mut rng = Rng::from_env(11);
    for seed in [0, 1, 0xdead_beef] {
        let (perlin, tabled) = (Perlin::new(seed), TabledPerlin::new(seed));
        assert_eq!(tabled.perlin(), &perlin);
        same::<1>(&perlin, &tabled, &mut rng);
        same::<2>(&perlin, &tabled, &mut rng);
        same::<3>(&perlin, &tabled, &mut rng);
        same::<4>(&perlin, &tabled, &mut rng);
    }
}

//! Every noise, dimension and number type gives the documented value for bad input: NaN, ±∞,
//! ±1e30, −0.0, subnormals and cells at the ends of `i32` (and of I16F16). Never a panic (these
//! tests run with overflow checks on), never a NaN.

use bandnoise::prelude::*;
use bandnoise_tests::{AllTypes, Lattice, Rng};

/// The specials of a float type, and what each is documented to sample.
fn float_specials() -> Vec<(f64, Option<f64>)> {
    let sub = f64::from_bits(1);
    vec![
        (f64::NAN, Some(0.0)),
        (f64::INFINITY, Some(0.0)),
        (f64::NEG_INFINITY, Some(0.0)),
        (-0.0, Some(0.0)),
        (1e30, None),
        (-1e30, None),
        (sub, None),
        (-sub, Some(0.0)), // x − floor(x) rounds to 1: the next cell, fraction 0
        (2_147_483_647.5, None), // cell i32::MAX
        (-2_147_483_648.0, None), // cell i32::MIN
        (-2_147_483_648.5, None), // cell below i32::MIN: wraps
        (4_294_967_296.25, Some(0.25)), // cell 2^32 wraps to 0
    ]
}

fn check<const D: usize>(noise: &Lattice, name: &str, rng: &mut Rng)
where
    Lattice: AllTypes<D>,
{
    let bound = Noise::<f64, D>::amplitude_bound(noise) as f64;
    for _ in 0..200 {
        let base: [f64; D] = core::array::from_fn(|_| rng.f64_in(-50.0, 50.0));
        for axis in 0..D {
            for (special, same_as) in float_specials() {
                let mut p = base;
                p[axis] = special;
                let v64: f64 = noise.sample(p);
                let v32: f32 = noise.sample(p.map(|x| x as f32));
                for v in [v64, v32 as f64] {
                    assert!(
                        !v.is_nan() && v.abs() <= bound,
                        "{name} {D}D {special:e}: {v}"
                    );
                    assert!(
                        v.to_bits() != (-0.0f64).to_bits(),
                        "{name} {D}D returned -0.0"
                    );
                }
                assert_ne!(v32.to_bits(), (-0.0f32).to_bits());
                if let Some(equiv) = same_as {
                    let mut q = base;
                    q[axis] = equiv;
                    let w64: f64 = noise.sample(q);
                    assert_eq!(
                        v64.to_bits(),
                        w64.to_bits(),
                        "{name} {D}D f64 {special:e} vs {equiv}"
                    );
                    // 2^32 + 0.25 is not an f32; the rest are.
                    if (special as f32) as f64 == special || special.is_nan() {
                        let w32: f32 = noise.sample(q.map(|x| x as f32));
                        assert_eq!(v32.to_bits(), w32.to_bits(), "{name} {D}D f32 {special:e}");
                    }
                }
            }
            // Fixed point: the ends of the range, whose cells are −32768 and 32767.
            let fx: [I16F16; D] = base.map(I16F16::from_num);
            for special in [
                I16F16::MIN,
                I16F16::MAX,
                I16F16::from_bits(-1),
                I16F16::DELTA,
            ] {
                let mut p = fx;
                p[axis] = special;
                let v: I16F16 = noise.sample(p);
                assert!(
                    v.to_num::<f64>().abs() <= bound,
                    "{name} {D}D fixed {special}: {v}"
                );
            }
        }
    }
}

#[test]
fn bad_coordinates_give_documented_values() {
    let mut rng = Rng::from_env(8);
    for (name, noise) in Lattice::all(21) {
        check::<1>(&noise, name, &mut rng);
        check::<2>(&noise, name, &mut rng);
        check::<3>(&noise, name, &mut rng);
        check::<4>(&noise, name, &mut rng);
    }
}

#[test]
fn huge_integer_coordinates_are_lattice_points() {
    // Every f32 beyond 2^24 is an integer: gradient noises are 0 there.
    for (name, noise) in Lattice::gradient_noises(2) {
        for x in [1e30f32, -1e30, 3e9, -3e9, f32::MAX, f32::MIN] {
            let v: f32 = noise.sample([x, 7.0, -2.0]);
            assert_eq!(v.to_bits(), 0, "{name} at {x:e}");
        }
    }
}

#[test]
fn gradients_of_bad_input_are_finite() {
    for (name, noise) in Lattice::gradient_noises(3) {
        for special in [
            f32::NAN,
            f32::INFINITY,
            -0.0,
            1e30,
            f32::from_bits(1),
            -2_147_483_648.0,
        ] {
            let (v, g) = noise.sample_with_gradient([special, 0.5, 0.25]).unwrap();
            assert!(
                v.is_finite() && g.iter().all(|d| d.is_finite()),
                "{name} {special:e}"
            );
            let (v, g) = noise
                .sample_with_gradient([I16F16::MAX, I16F16::MIN, I16F16::DELTA])
                .unwrap();
            assert!(
                v.abs() <= I16F16::from_num(2) && g.iter().all(|d| d.abs() < 64),
                "{name}"
            );
        }
    }
}

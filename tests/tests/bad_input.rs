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
            let (v, g) = noise.sample_with_gradient([special, 0.5, 0.25]);
            assert!(
                v.is_finite() && g.iter().all(|d| d.is_finite()),
                "{name} {special:e}"
            );
            let (v, g) = noise.sample_with_gradient([I16F16::MAX, I16F16::MIN, I16F16::DELTA]);
            assert!(
                v.abs() <= I16F16::from_num(2) && g.iter().all(|d| d.abs() < 64),
                "{name}"
            );
        }
    }
}

// Regressions: the holes a bad-input sweep from outside the crate found, with its reproducers.

use bandnoise::wavelet::{
    Bands, Distribution, Multiband, TILE2, TILE3, TileData, Wavelet, unit_normal,
};

#[test]
fn multiband_samples_the_origin_for_nan_and_infinite_coordinates() {
    let m = Multiband::new(0, &TILE2, Bands::default(), Distribution::Gaussian);
    let origin: f32 = m.sample([0.0, 0.0]);
    for bad in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
        assert_eq!(m.sample([bad, 0.0f32]).to_bits(), origin.to_bits(), "{bad}");
    }
    let m64: f64 = m.sample([f64::NAN, 5.25]);
    assert_eq!(m64.to_bits(), m.sample([0.0f64, 5.25]).to_bits());
    let u = Multiband::new(0, &TILE3, Bands::default(), Distribution::Uniform);
    let n = [0.0f32, 0.0, 1.0];
    assert_eq!(
        u.sample_projected([f32::NAN, 0.5, 0.5], n).to_bits(),
        u.sample_projected([0.0, 0.5, 0.5], n).to_bits()
    );
    // Through a fractal sum too.
    let f = Fractal::fbm(m, Octaves::default());
    assert_eq!(
        f.sample([f32::INFINITY, 1.5]).to_bits(),
        f.sample([0.0f32, 1.5]).to_bits()
    );
}

#[test]
fn large_normals_keep_their_direction() {
    let x = [I16F16::ONE, I16F16::ZERO, I16F16::ZERO];
    for len in [181, 200, 32767] {
        let n = [I16F16::from_num(len), I16F16::ZERO, I16F16::ZERO];
        assert_eq!(unit_normal(n), x, "length {len}");
    }
    assert_eq!(unit_normal([1e20f32, 0.0, 0.0]), [1.0, 0.0, 0.0]);
    assert_eq!(unit_normal([0.0, f64::MAX, 0.0]), [0.0, 1.0, 0.0]);
    let band = Wavelet::new(0, &TILE3);
    let p = [0.3f32, 0.6, 2.0];
    assert_eq!(
        band.sample_projected(p, [1e20, 0.0, 0.0]).to_bits(),
        band.sample_projected(p, [1.0, 0.0, 0.0]).to_bits()
    );
    // Tiny normals too (their squared length underflows).
    assert_eq!(unit_normal([0.0f32, 0.0, -1e-30]), [0.0, 0.0, -1.0]);
}

#[test]
fn filtered_sums_are_symmetric_in_their_footprints() {
    let f = Fractal::fbm(Perlin::new(0), Octaves::default());
    let p = [0.3f32, 0.7, 0.1];
    let (nan, quarter) = ([f32::NAN, 0.0, 0.0], [0.25f32, 0.0, 0.0]);
    let a = f.sample_filtered(p, nan, quarter);
    assert_eq!(a.to_bits(), f.sample_filtered(p, quarter, nan).to_bits());
    // The unknown footprint gives way to the known one.
    assert_eq!(
        a.to_bits(),
        f.sample_filtered(p, [0.0; 3], quarter).to_bits()
    );
}

#[test]
fn from_ratio_is_defined_for_every_shift() {
    assert_eq!(<f32 as Real>::from_ratio(1, 64), 2f32.powi(-64));
    assert_eq!(<f32 as Real>::from_ratio(1, 126), f32::MIN_POSITIVE);
    assert_eq!(<f32 as Real>::from_ratio(1, 149), f32::from_bits(1));
    assert_eq!(<f32 as Real>::from_ratio(-7, 70), -7.0 * 2f32.powi(-70));
    assert_eq!(<f64 as Real>::from_ratio(3, 1074), f64::from_bits(3));
    assert_eq!(<f32 as Real>::from_ratio(1, u32::MAX), 0.0);
    assert_eq!(<I16F16 as Real>::from_ratio(1, 80), I16F16::ZERO);
    assert_eq!(<I16F16 as Real>::from_ratio(-1, 80), -I16F16::DELTA);
    assert_eq!(
        <I16F16 as Real>::from_ratio(i32::MAX, u32::MAX),
        I16F16::ZERO
    );
    assert_eq!(<I16F16 as Real>::from_ratio(3, 17), I16F16::DELTA); // 1.5 ulp, toward −∞
}

/// A user's noise beyond the crate's ranges: a constant.
struct Constant(f32);

impl<R: Real, const D: usize> Noise<R, D> for Constant {
    fn sample(&self, _: [R; D]) -> R {
        R::from_f32(self.0)
    }
    fn amplitude_bound(&self) -> f32 {
        self.0.abs()
    }
}

/// A user's tile whose every coefficient is `self.0`.
struct Flat(f32);

impl<const D: usize> TileData<D> for Flat {
    const SIZE: usize = 4;
    fn get<R: Real>(&self, _: [usize; D]) -> R {
        R::from_f32(self.0)
    }
    fn flat<R: Real>(&self, _: usize) -> R {
        R::from_f32(self.0)
    }
    fn max_abs(&self) -> f32 {
        self.0.abs()
    }
}

#[test]
fn fixed_point_saturates_with_users_noises_and_tiles() {
    // Ridge terms are squares: (1 − 200)² = 39601 saturates, never wraps negative.
    let octaves = Octaves::default();
    let ridged = Fractal::ridged(Constant(200.0), octaves);
    let v: I16F16 = ridged.sample([I16F16::ONE, I16F16::ONE]);
    assert_eq!(v, I16F16::MAX);
    let f: f32 = Fractal::ridged(Constant(200.0), Octaves::default()).sample([1.0f32, 1.0]);
    assert!(f > 32768.0);

    // Projected weights sum to 2 along an axis: 2 · 17000 saturates.
    let tile = Flat(17000.0);
    let band = Wavelet::new(0, &tile);
    let z = [I16F16::ZERO, I16F16::ZERO, I16F16::ONE];
    let p = [
        I16F16::from_num(0.3),
        I16F16::from_num(0.6),
        I16F16::from_num(2),
    ];
    assert_eq!(band.sample_projected(p, z), I16F16::MAX);
    let f: f32 = band.sample_projected(p.map(|c| c.to_num()), [0.0, 0.0, 1.0]);
    assert!((f - 34000.0).abs() < 1.0, "{f}");

    // A plain band's weights sum to 1, but rounding overshoots a coefficient of I16F16::MAX by
    // an ulp at a fraction of ½ (the only such fraction, found exhaustively): it saturates.
    for c in [32768.0f32, -32768.0] {
        let tile = Flat(c);
        let band = Wavelet::new(0, &tile);
        for p in [[0.3f32, 0.6], [0.5, 0.5], [1.7, -3.2]] {
            let v: I16F16 = band.sample(p.map(I16F16::from_num));
            assert!((v.to_num::<f32>() - c).abs() < 0.01, "{c} at {p:?}: {v}");
        }
    }
}

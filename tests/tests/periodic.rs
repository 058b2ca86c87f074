//! Periodic lattice noise: `n(x + P·k) == n(x)` bit for bit along every axis, for every lattice
//! noise, dimension and period tried (1 to 2¹⁶), in fixed point always and in floats wherever
//! `x + P·k` is exact; for point, gradient and batch sampling, and fractal sums with an integer
//! lacunarity. A period equal to the hash's own gives the plain noise.

use bandnoise::batch::Grid;
use bandnoise::prelude::*;
use bandnoise::wavelet::Distribution;
use bandnoise::{Error, lattice::Periodic};
use bandnoise_tests::{Rng, Special};

/// A 2D noise as a function.
type Field<'a> = dyn Fn([f64; 2]) -> f64 + 'a;
/// A 2D noise with its gradient.
type FieldWithGradient<'a> = dyn Fn([f64; 2]) -> (f64, [f64; 2]) + 'a;

/// The periods tried: 1, small, the hashes' own, odd, beyond 256, the largest.
const PERIODS: [u32; 10] = [1, 2, 3, 16, 61, 255, 256, 257, 1000, 65536];

/// `x + shift` in `R`, if it is exact there.
fn shifted<R: Special>(x: R, shift: f64) -> Option<R> {
    let want = x.to_f64() + shift;
    let y = R::from_f64(want);
    (y.to_f64() == want).then_some(y)
}

/// Point `i` of a grid that runs along axis 0.
fn along_x<const D: usize>(i: usize) -> [usize; D] {
    core::array::from_fn(|a| if a == 0 { i } else { 0 })
}

/// `sample` (`value`) and its gradient (`gradient`) of a periodic noise repeat along every
/// axis; a grid over two periods equals point sampling and repeats.
fn check<R: Special, const D: usize, N: Noise<R, D>>(
    what: &str,
    n: &N,
    period: [u32; D],
    gradient: impl Fn([R; D]) -> Option<[R; D]>,
    rng: &mut Rng,
) {
    let p: [R; D] = core::array::from_fn(|_| R::from_f64(rng.exact_coord(200).to_f64()));
    let v = n.sample(p);
    let g = gradient(p);
    for axis in 0..D {
        for k in [-2i64, -1, 1, 3] {
            let Some(x) = shifted(p[axis], (period[axis] as i64 * k) as f64) else {
                continue;
            };
            let q = {
                let mut q = p;
                q[axis] = x;
                q
            };
            let at = || format!("{what} {D}D {} period {period:?} at {p:?} + {k}P", R::NAME);
            assert_eq!(n.sample(q).bits(), v.bits(), "{}", at());
            let h = gradient(q);
            assert_eq!(
                h.map(|h| h.map(R::bits)),
                g.map(|g| g.map(R::bits)),
                "{} gradient",
                at()
            );
        }
    }
    if period[0] <= 64 {
        // 8 samples per cell (1/8 is exact in every type), two periods along axis 0.
        let size: [usize; D] =
            core::array::from_fn(|a| if a == 0 { 16 * period[0] as usize } else { 1 });
        // An origin on 1/256 of a cell, so every grid point is exact in f32 too.
        let origin = p.map(|x| R::from_f64((x.to_f64() * 256.0).round() / 256.0));
        let grid = Grid::new(origin, [R::from_ratio(1, 3); D], size);
        let mut out = vec![R::ZERO; grid.len()];
        n.fill_grid(&grid, &mut out).expect("length matches");
        for (i, o) in out.iter().enumerate() {
            let q = grid.point(along_x::<D>(i));
            assert_eq!(o.bits(), n.sample(q).bits(), "{what} fill_grid at {q:?}");
        }
        let half = out.len() / 2;
        assert!(
            (0..half).all(|i| out[i].bits() == out[i + half].bits()),
            "{what} {D}D {}: the grid does not repeat after {period:?}",
            R::NAME
        );
    }
}

fn random_period<const D: usize>(rng: &mut Rng) -> [u32; D] {
    core::array::from_fn(|_| PERIODS[rng.i32_in(0, PERIODS.len() as i32) as usize])
}

/// A gradient noise, wrapped to random periods, in dimension `D` and type `R`.
fn gradient_noise<R: Special, const D: usize, N: Copy>(what: &str, noise: N, rng: &mut Rng)
where
    Periodic<N, D>: NoiseGradient<R, D>,
{
    for _ in 0..30 {
        let period = random_period::<D>(rng);
        let n = Periodic::new(noise, period).expect("valid periods");
        check::<R, D, _>(what, &n, period, |p| Some(n.sample_with_gradient(p).1), rng);
        // The gradient's value is the sample, bit for bit.
        let p: [R; D] = core::array::from_fn(|_| R::from_f64(rng.f64_in(-100.0, 100.0)));
        assert_eq!(n.sample_with_gradient(p).0.bits(), n.sample(p).bits());
    }
}

macro_rules! every_type_and_dim {
    ($run:ident, $name:expr, $noise:expr, $rng:expr) => {{
        $run::<f32, 1, _>($name, $noise, $rng);
        $run::<f32, 2, _>($name, $noise, $rng);
        $run::<f32, 3, _>($name, $noise, $rng);
        $run::<f32, 4, _>($name, $noise, $rng);
        $run::<f64, 2, _>($name, $noise, $rng);
        $run::<f64, 3, _>($name, $noise, $rng);
        $run::<I16F16, 1, _>($name, $noise, $rng);
        $run::<I16F16, 2, _>($name, $noise, $rng);
        $run::<I16F16, 3, _>($name, $noise, $rng);
        $run::<I16F16, 4, _>($name, $noise, $rng);
    }};
}

#[test]
fn every_lattice_noise_repeats_with_any_period() {
    let mut rng = Rng::from_env(160);
    // By reference, as a user shares one noise (`Periodic<&Perlin, D>`).
    let perlin = Perlin::new(4);
    every_type_and_dim!(gradient_noise, "perlin", &perlin, &mut rng);
    every_type_and_dim!(
        gradient_noise,
        "original",
        &OriginalPerlin::new(4),
        &mut rng
    );
    every_type_and_dim!(gradient_noise, "cnoise", &CNoise::new(4), &mut rng);
    every_type_and_dim!(
        gradient_noise,
        "mnoise61",
        MNoise::<61>::seeded(4),
        &mut rng
    );
    every_type_and_dim!(
        gradient_noise,
        "mnoise4093",
        MNoise::<4093>::seeded(4),
        &mut rng
    );
    every_type_and_dim!(value_noise, "value", (), &mut rng);
    // Lewis's lattice white noise and its Catmull-Rom interpolant (4ᴰ lattice points wrapped).
    let cubic = CubicValueNoise::new(4);
    every_type_and_dim!(gradient_noise, "value-cubic", &cubic, &mut rng);
    every_type_and_dim!(gradient_noise, "value-cubic owned", cubic, &mut rng);
    let white = WhiteNoise::new(4).with_distribution(Distribution::Gaussian);
    every_type_and_dim!(gradient_noise, "white", &white, &mut rng);
    every_type_and_dim!(gradient_noise, "white owned", white, &mut rng);
}

/// Wrapping white and cubic value noise changes only the lattice points outside the first
/// period: where every point a sample reads lies in `0..P`, the values are the unwrapped
/// noise's, bit for bit (and elsewhere they are not all).
#[test]
fn white_and_cubic_noise_wrap_only_outside_the_first_period() {
    let mut rng = Rng::from_env(161);
    let (white, cubic) = (WhiteNoise::new(9), CubicValueNoise::new(9));
    let period = [7u32, 300];
    let (pw, pc) = (
        Periodic::new(white, period).unwrap(),
        Periodic::new(cubic, period).unwrap(),
    );
    let mut differ = 0;
    for _ in 0..2000 {
        // Cubic value noise reads the points c − 1 … c + 2: c in 1..P − 2 stays inside.
        let p = [rng.f64_in(1.0, 5.0) as f32, rng.f64_in(1.0, 298.0) as f32];
        assert_eq!(pc.sample(p).to_bits(), cubic.sample(p).to_bits(), "{p:?}");
        assert_eq!(pw.sample(p).to_bits(), white.sample(p).to_bits(), "{p:?}");
        let outside = [rng.f64_in(-50.0, 0.0) as f32, rng.f64_in(-50.0, 0.0) as f32];
        differ += usize::from(pc.sample(outside) != cubic.sample(outside));
    }
    assert!(differ > 1900, "{differ}");
}

/// Value noise (no gradient), wrapped to random periods.
fn value_noise<R: Special, const D: usize, N>(what: &str, _: N, rng: &mut Rng)
where
    Periodic<ValueNoise, D>: Noise<R, D>,
{
    for _ in 0..30 {
        let period = random_period::<D>(rng);
        let n = Periodic::new(ValueNoise::new(4), period).expect("valid periods");
        check::<R, D, _>(what, &n, period, |_| None, rng);
    }
}

/// A period equal to the hash's own is the noise itself, bit for bit.
#[test]
fn the_natural_period_is_the_plain_noise() {
    let mut rng = Rng::from_env(161);
    let perlin = Perlin::new(9);
    let m = MNoise::<61>::seeded(9);
    for _ in 0..20_000 {
        let p: [f32; 3] = core::array::from_fn(|_| rng.f64_in(-600.0, 600.0) as f32);
        let same = |a: f32, b: f32| assert_eq!(a.to_bits(), b.to_bits(), "{p:?}");
        same(
            Periodic::new(&perlin, [256; 3]).unwrap().sample(p),
            perlin.sample(p),
        );
        let o = OriginalPerlin::new(9);
        same(Periodic::new(&o, [256; 3]).unwrap().sample(p), o.sample(p));
        let c = CNoise::new(9);
        same(Periodic::new(&c, [256; 3]).unwrap().sample(p), c.sample(p));
        let v = ValueNoise::new(9);
        same(
            Periodic::new(v.clone(), [256; 3]).unwrap().sample(p),
            v.sample(p),
        );
        same(Periodic::new(m, [61; 3]).unwrap().sample(p), m.sample(p));
    }
}

/// A period longer than the hash's own does not repeat with the hash's period: the noise 256
/// cells on (permutation noises) or `M` cells on (mNoise) is as unrelated as the noise 100 cells
/// on. Except for mNoise<61>, whose hash has only 61 states: its 61-cell blocks correlate, as
/// `Periodic`'s docs say (and the figure they give is checked here).
#[test]
fn long_periods_do_not_repeat_early() {
    let mut rng = Rng::from_env(163);
    let perlin = Perlin::new(2);
    let points: Vec<[f64; 2]> = (0..20_000)
        .map(|_| [rng.f64_in(0.0, 60_000.0), rng.f64_in(0.0, 700.0)])
        .collect();
    let correlation = |f: &Field<'_>, by: f64| -> f64 {
        let a: Vec<f64> = points.iter().map(|&p| f(p)).collect();
        let b: Vec<f64> = points.iter().map(|&p| f([p[0] + by, p[1]])).collect();
        bandnoise_tests::correlation(&a, &b)
    };
    let p = Periodic::new(&perlin, [1000, 1000]).unwrap();
    let c = Periodic::new(CNoise::new(2), [1000, 1000]).unwrap();
    let v = Periodic::new(ValueNoise::new(2), [1000, 1000]).unwrap();
    let m = Periodic::new(MNoise::<4093>::seeded(2), [65536, 65536]).unwrap();
    let m61 = Periodic::new(MNoise::<61>::seeded(2), [1000, 1000]).unwrap();
    let cases: [(&str, &Field<'_>, f64); 5] = [
        ("perlin, period 1000", &|q| p.sample(q), 256.0),
        ("cnoise, period 1000", &|q| c.sample(q), 256.0),
        ("value, period 1000", &|q| v.sample(q), 256.0),
        ("mnoise4093, period 65536", &|q| m.sample(q), 4093.0),
        ("mnoise61, period 1000", &|q| m61.sample(q), 61.0),
    ];
    for (name, f, natural) in cases {
        let (r, control) = (correlation(f, natural), correlation(f, 100.0));
        println!(
            "{name}: correlation with the noise {natural} cells on {r:+.4} (100 cells on: {control:+.4})"
        );
        // As related as an arbitrary shift: the standard error of each is 0.007.
        if name.starts_with("mnoise61") {
            assert!(
                (-0.2..-0.05).contains(&r),
                "{name}: {r} (see Periodic's docs)"
            );
        } else {
            assert!((r - control).abs() < 0.04, "{name}: {r} against {control}");
        }
    }
    // The plain noise does repeat there.
    let plain: f64 = perlin.sample([3.25, 4.5]);
    assert_eq!(plain, perlin.sample([3.25 + 256.0, 4.5]));
}

/// Fractal sums keep the period when the lacunarity is an integer.
#[test]
fn fractal_sums_with_integer_lacunarity_keep_the_period() {
    let mut rng = Rng::from_env(162);
    let tile = Periodic::new(Perlin::new(5), [8, 4]).unwrap();
    let fbm = Fractal::fbm(&tile, Octaves::new(5, 2.0, 0.5).unwrap());
    let pbrt = Fractal::fbm(&tile, Octaves::default());
    let mut pbrt_differs = 0;
    for _ in 0..1000 {
        let p: [I16F16; 2] = rng.exact_point(100);
        let q = [p[0] + I16F16::from_num(8), p[1] - I16F16::from_num(4)];
        assert_eq!(fbm.sample(p), fbm.sample(q), "{p:?}");
        pbrt_differs += (pbrt.sample(p) != pbrt.sample(q)) as u32;
    }
    // Lacunarity 1.99: octave i repeats every P/1.99^i, not a divisor of P.
    assert!(pbrt_differs > 900, "{pbrt_differs}");
}

#[test]
fn periods_outside_the_range_are_refused() {
    assert_eq!(
        Periodic::new(Perlin::new(0), [4, 0]).unwrap_err(),
        Error::Period { axis: 1, period: 0 }
    );
    assert!(Periodic::new(ValueNoise::new(0), [65537]).is_err());
    assert!(Periodic::new(ValueNoise::new(0), [65536]).is_ok());
    let e = Periodic::new(CNoise::new(0), [1, 2, 70000]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "period 70000 along axis 2 is outside 1..=65536 cells"
    );
}

/// Seamless: across the wrap the value and the gradient are continuous, as anywhere else
/// (the last cell's upper corner is the first cell's lower one).
#[test]
fn the_wrap_is_seamless() {
    let mut rng = Rng::from_env(164);
    let eps = 1.0 / 4096.0;
    for period in PERIODS {
        let perlin = Perlin::new(6);
        let gradient_noises: [(&str, &FieldWithGradient<'_>); 3] = [
            ("perlin", &|p| {
                Periodic::new(&perlin, [period, 7])
                    .unwrap()
                    .sample_with_gradient(p)
            }),
            ("cnoise", &|p| {
                Periodic::new(CNoise::new(6), [period, 7])
                    .unwrap()
                    .sample_with_gradient(p)
            }),
            ("mnoise61", &|p| {
                Periodic::new(MNoise::<61>::seeded(6), [period, 7])
                    .unwrap()
                    .sample_with_gradient(p)
            }),
        ];
        let value = Periodic::new(ValueNoise::new(6), [period, 7]).unwrap();
        for _ in 0..50 {
            let y = rng.f64_in(0.0, 7.0);
            let x = period as f64 * rng.i32_in(-3, 4) as f64;
            for (name, f) in &gradient_noises {
                let ((a, ga), (b, gb)) = (f([x - eps, y]), f([x + eps, y]));
                let jump = (ga[0] - gb[0]).abs().max((ga[1] - gb[1]).abs());
                assert!(
                    (a - b).abs() < 0.01 && jump < 0.1,
                    "{name} period {period} at x = {x}: {a} {b}, gradient jump {jump}"
                );
            }
            let (a, b): (f64, f64) = (value.sample([x - eps, y]), value.sample([x + eps, y]));
            assert!(
                (a - b).abs() < 0.01,
                "value period {period} at x = {x}: {a} {b}"
            );
        }
    }
}

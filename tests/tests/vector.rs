//! Curl noise (Bridson et al. 2007): divergence-free, measured by central differences of the
//! field in `f64`; the 2D field is the potential's gradient turned a quarter turn, bit for bit;
//! fixed point follows `f32`; a field worth the name (not vanishing); total on bad input.

use bandnoise::fractal::{Fractal, Octaves};
use bandnoise::lattice::Perlin;
use bandnoise::simplex::Simplex;
use bandnoise::vector::{Curl2, Curl3, VectorNoise};
use bandnoise::{I16F16, NoiseGradient};
use bandnoise_tests::Rng;

/// The largest |divergence| of `field` by central differences of step `h` over `n` random
/// points of `(−50, 50)^D`, and the root mean square of its components (the scale to judge the
/// divergence against).
fn divergence<const D: usize>(
    field: &impl VectorNoise<f64, D>,
    n: usize,
    h: f64,
    rng: &mut Rng,
) -> (f64, f64) {
    let (mut worst, mut square) = (0.0f64, 0.0f64);
    for _ in 0..n {
        let p: [f64; D] = core::array::from_fn(|_| rng.f64_in(-50.0, 50.0));
        let mut div = 0.0;
        for a in 0..D {
            let (mut hi, mut lo) = (p, p);
            hi[a] += h;
            lo[a] -= h;
            div += (field.sample_vector(hi)[a] - field.sample_vector(lo)[a]) / (2.0 * h);
        }
        worst = worst.max(div.abs());
        square += field.sample_vector(p).iter().map(|c| c * c).sum::<f64>() / D as f64;
    }
    (worst, (square / n as f64).sqrt())
}

/// Divergence below 1e-4 (central differences, step 1e-6: simplex noise's kernel has a kink
/// in its third derivative at its radius, which a central difference straddling it turns into
/// an error of order `h` times the jump, 8³ times larger in an fBm's fourth octave) for 2D and
/// 3D curl noise over Perlin noise, simplex noise and an fBm of simplex noise, with a field of
/// order 1.
#[test]
fn divergence_free() {
    let mut rng = Rng::from_env(70);
    let fbm = || Fractal::fbm(Simplex::new(4), Octaves::new(4, 1.99, 0.5).unwrap());
    let cases: [(&str, (f64, f64)); 6] = [
        (
            "2D Perlin",
            divergence(&Curl2::new(Perlin::new(1)), 20_000, 1e-6, &mut rng),
        ),
        (
            "2D simplex",
            divergence(&Curl2::new(Simplex::new(1)), 20_000, 1e-6, &mut rng),
        ),
        (
            "2D simplex fBm, 4 octaves",
            divergence(&Curl2::new(fbm()), 20_000, 1e-6, &mut rng),
        ),
        (
            "3D Perlin",
            divergence(
                &Curl3::new(Perlin::new(1), Perlin::new(2), Perlin::new(3)),
                20_000,
                1e-6,
                &mut rng,
            ),
        ),
        (
            "3D simplex",
            divergence(
                &Curl3::new(Simplex::new(1), Simplex::new(2), Simplex::new(3)),
                20_000,
                1e-6,
                &mut rng,
            ),
        ),
        (
            "3D simplex fBm, 4 octaves",
            divergence(
                &Curl3::new(
                    fbm(),
                    Fractal::fbm(Simplex::new(5), Octaves::new(4, 1.99, 0.5).unwrap()),
                    Fractal::fbm(Simplex::new(6), Octaves::new(4, 1.99, 0.5).unwrap()),
                ),
                20_000,
                1e-6,
                &mut rng,
            ),
        ),
    ];
    for (name, (worst, rms)) in cases {
        println!("curl of {name}: largest |divergence| {worst:.1e}, field rms {rms:.3}");
        assert!(worst < 1e-4, "{name}: divergence {worst}");
        assert!(rms > 0.1, "{name}: the field vanishes ({rms})");
    }
}

/// The 2D field is the gradient turned a quarter turn, bit for bit; the 3D field is the curl
/// of the three gradients; fixed point follows `f32` (each point exact in both).
#[test]
fn components_and_fixed_point() {
    let mut rng = Rng::from_env(71);
    let potential = Simplex::new(9);
    let flow = Curl2::new(potential.clone());
    let flow3 = Curl3::new(Perlin::new(1), Simplex::new(2), Perlin::new(3));
    let (mut worst2, mut worst3) = (0.0f32, 0.0f32);
    for _ in 0..20_000 {
        let q: [I16F16; 3] = rng.exact_point(200);
        let p = q.map(|x| x.to_num::<f32>());
        let (_, g): (f32, [f32; 2]) = potential.sample_with_gradient([p[0], p[1]]);
        let [u, v] = flow.sample_vector([p[0], p[1]]);
        assert_eq!(
            [u.to_bits(), v.to_bits()],
            [g[1].to_bits(), (-g[0] + 0.0).to_bits()]
        );
        let fixed: [I16F16; 2] = flow.sample_vector([q[0], q[1]]);
        for (a, b) in fixed.iter().zip([u, v]) {
            worst2 = worst2.max((a.to_num::<f32>() - b).abs());
        }
        let (_, g1) = Perlin::new(1).sample_with_gradient(p);
        let (_, g2) = Simplex::new(2).sample_with_gradient(p);
        let (_, g3) = Perlin::new(3).sample_with_gradient(p);
        let w: [f32; 3] = flow3.sample_vector(p);
        let expected = [g3[1] - g2[2], g1[2] - g3[0], g2[0] - g1[1]];
        assert_eq!(w.map(f32::to_bits), expected.map(|x| (x + 0.0).to_bits()));
        let fixed: [I16F16; 3] = flow3.sample_vector(q);
        for (a, b) in fixed.iter().zip(w) {
            worst3 = worst3.max((a.to_num::<f32>() - b).abs());
        }
    }
    println!("largest |I16F16 − f32|: 2D {worst2:.1e}, 3D {worst3:.1e}");
    assert!(worst2 < 1e-2 && worst3 < 1e-2, "{worst2} {worst3}");
}

/// Any coordinate gives finite components, never a panic.
#[test]
fn total_on_bad_input() {
    let flow = Curl2::new(Simplex::new(0));
    let flow3 = Curl3::new(Perlin::new(1), Perlin::new(2), Perlin::new(3));
    for x in [f32::NAN, f32::INFINITY, -f32::INFINITY, f32::MAX, 1e30] {
        let v: [f32; 2] = flow.sample_vector([x, 0.5]);
        let w: [f32; 3] = flow3.sample_vector([0.3, x, x]);
        assert!(
            v.iter().chain(&w).all(|c| c.is_finite()),
            "{x}: {v:?} {w:?}"
        );
    }
    for x in [I16F16::MAX, I16F16::MIN, I16F16::DELTA] {
        let _: [I16F16; 2] = flow.sample_vector([x, x]);
        let _: [I16F16; 3] = flow3.sample_vector([x, I16F16::MIN, x]);
    }
}

/// Domain warping (Lewis §5.3): the warped noise is the noise at the displaced point, which is
/// `p + amplitude · v(p)` (an independent f64 computation); amplitude 0 is the noise itself;
/// values stay within the noise's bound; the chain-rule gradient matches central differences;
/// fixed point follows `f32`; bad amplitudes are refused and bad coordinates give a value.
#[test]
fn warp() {
    use bandnoise::vector::{Components, Warp};
    use bandnoise::{Error, Noise};
    let mut rng = Rng::from_env(23);
    let field = Components::new([Simplex::new(11), Simplex::new(12), Simplex::new(13)]);
    let warp = Warp::new(Perlin::new(1), field.clone(), 0.8).unwrap();
    let still = Warp::new(Perlin::new(1), field.clone(), 0.0).unwrap();
    for _ in 0..20_000 {
        let p: [f64; 3] = core::array::from_fn(|_| rng.f64_in(-100.0, 100.0));
        let v = [11, 12, 13].map(|s| Simplex::new(s).sample(p));
        // The amplitude is the f32 setting, exactly.
        let q: [f64; 3] = core::array::from_fn(|a| p[a] + f64::from(0.8f32) * v[a]);
        assert_eq!(warp.displace(p), q);
        let w: f64 = warp.sample(p);
        assert_eq!(w.to_bits(), Perlin::new(1).sample(q).to_bits());
        assert!(w.abs() <= f64::from(warp.amplitude_bound::<3>()));
        let f = p.map(|x| x as f32);
        let s: f32 = still.sample(f);
        assert_eq!(s.to_bits(), Perlin::new(1).sample(f).to_bits());
    }
    // The warp moves the noise: decorrelated from the unwarped noise at amplitude 2.
    let strong = Warp::new(Perlin::new(1), field.clone(), 2.0).unwrap();
    let (a, b): (Vec<f64>, Vec<f64>) = (0..20_000)
        .map(|_| {
            let p: [f64; 3] = core::array::from_fn(|_| rng.f64_in(-100.0, 100.0));
            (strong.sample(p), Perlin::new(1).sample(p))
        })
        .unzip();
    let r = bandnoise_tests::correlation(&a, &b);
    println!("warp: correlation with the unwarped noise {r:.3} (amplitude 2)");
    assert!(r.abs() < 0.2, "correlation with the unwarped noise {r}");
    // Gradients: the chain rule through the field's Jacobian.
    let (err, largest) =
        bandnoise_tests::agree::gradient_error::<_, 3>(&warp, 2_000, 50.0, 1e-6, &mut rng);
    println!("warp: gradient within {err:.1e} of central differences (3D, largest {largest:.2})");
    assert!(err < 1e-6 * largest.max(1.0), "3D: {err} of {largest}");
    let flat = Warp::new(
        Simplex::new(3),
        Components::new([Perlin::new(4), Perlin::new(5)]),
        1.5,
    )
    .unwrap();
    let (err, largest) =
        bandnoise_tests::agree::gradient_error::<_, 2>(&flat, 2_000, 50.0, 1e-6, &mut rng);
    assert!(err < 1e-6 * largest.max(1.0), "2D: {err} of {largest}");
    // Fixed point follows f32: the displaced points differ by amplitude × the field's error
    // (simplex noise's, about 4·10⁻⁴), which the noise's slope turns into about 10⁻³.
    let mut worst = 0.0f32;
    for _ in 0..20_000 {
        let q: [I16F16; 3] = rng.exact_point(200);
        let x: I16F16 = warp.sample(q);
        let y: f32 = warp.sample(q.map(|c| c.to_num::<f32>()));
        worst = worst.max((x.to_num::<f32>() - y).abs());
    }
    println!("warp: fixed point within {worst:.1e} of f32");
    assert!(worst < 2e-3, "fixed point vs f32: {worst}");
    // Bad amplitudes are refused; bad coordinates sample somewhere, within the bound.
    for a in [f32::NAN, f32::INFINITY, -1024.5, 2048.0] {
        let e = Warp::new(Perlin::new(1), field.clone(), a).unwrap_err();
        assert!(matches!(e, Error::WarpAmplitude(_)), "{a}: {e}");
    }
    assert!(Warp::new(Perlin::new(1), field.clone(), -1024.0).is_ok());
    let far = Warp::new(Perlin::new(1), field, 1024.0).unwrap();
    for x in bandnoise_tests::BAD_F32 {
        for p in [[x, 0.5, 0.25], [0.5, x, x]] {
            let v: f32 = far.sample(p);
            assert!(
                v.is_finite() && v.abs() <= far.amplitude_bound::<3>(),
                "{p:?}"
            );
            let (_, g) = far.sample_with_gradient(p);
            assert!(g.iter().all(|c| c.is_finite()), "{p:?}");
        }
    }
    for x in [I16F16::MAX, I16F16::MIN] {
        let v: I16F16 = far.sample([x, x, I16F16::ZERO]);
        assert!(v.to_num::<f32>().abs() <= far.amplitude_bound::<3>());
        let _ = far.sample_with_gradient([x, I16F16::MIN, x]);
    }
}

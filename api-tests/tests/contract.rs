//! The contract of every public sampling entry point, over the inputs of a bad-input sweep run
//! from outside the crate: NaN, ±∞, ±1e30, ±`f32::MAX`, `MIN_POSITIVE`, a subnormal, −0.0 and
//! ±2³¹ in `f32` and `f64` (`f64` also ±`f64::MAX`), and I16F16's `MAX`, `MIN` and ±`DELTA`, at
//! each axis of random points and at every axis at once (`Special` in the test crate).
//!
//! For each entry point and number type it asserts what the docs promise:
//! * no panic (the test profile keeps overflow checks on), no NaN, no −0.0, and the documented
//!   bound (`amplitude_bound`, `projected_bound`, ±1 for `erf`);
//! * a NaN, ±∞ or −0.0 coordinate samples 0 along its axis, bit for bit;
//! * `sample_lanes`, `fill_points` and `fill_grid` (with a bad origin or step) equal `sample` at
//!   each point, bit for bit;
//! * `sample_with_gradient` (every lattice and periodic noise, fractal sums, wavelet bands,
//!   multiband noise) gives `sample`'s value and a finite gradient, the origin's for a NaN, ±∞
//!   or −0.0 coordinate;
//! * `Fractal::sample_filtered` is symmetric in its two footprints, whatever they hold;
//! * projection normalises any finite non-zero normal: a power-of-two multiple of a normal
//!   (2¹⁰⁰ or 2⁻¹⁰⁰ times, 2¹⁴ in fixed point) gives the same unit normal and sample, bit for bit.
//!
//! [`every_noise`] is the list of subjects: a noise added to the crate is added there.

use core::array::from_fn;

use bandnoise::batch::{Grid, LANES};
use bandnoise::fractal::{Fractal, Kind, Octaves};
use bandnoise::impulse::Orientation;
use bandnoise::lattice::Periodic;
use bandnoise::prelude::*;
use bandnoise::spec::{Base, Spec};
use bandnoise::wavelet::{
    Bands, Distribution, Multiband, TILE2, TILE2_I16, TILE3, TILE3_I16, Tiling, Wavelet, erf,
    unit_normal,
};
use bandnoise_tests::{Lattice, Rng, Special};

/// `v` is a value the contract allows: not NaN, not −0.0, within `bound`.
fn check_value<R: Special>(v: R, bound: f32, what: impl Fn() -> String) {
    assert!(
        !v.is_nan() && v.to_f64().abs() <= bound as f64,
        "{}: {v} (bound {bound})",
        what()
    );
    assert!(!v.is_negative_zero(), "{}: -0.0", what());
}

fn with<R: Copy, const D: usize>(mut p: [R; D], axis: usize, v: R) -> [R; D] {
    p[axis] = v;
    p
}

fn random_point<R: Special, const D: usize>(rng: &mut Rng) -> [R; D] {
    from_fn(|_| R::from_f64(rng.f64_in(-50.0, 50.0)))
}

/// Each special at each axis of `bases` random points and at every axis at once, with the point
/// it is documented to sample (if the contract says).
fn bad_points<R: Special, const D: usize>(
    rng: &mut Rng,
    bases: usize,
) -> Vec<([R; D], Option<[R; D]>)> {
    let mut out = Vec::new();
    for _ in 0..bases {
        let base = random_point::<R, D>(rng);
        for (s, same) in R::specials() {
            for axis in 0..D {
                out.push((with(base, axis, s), same.map(|z| with(base, axis, z))));
            }
            out.push(([s; D], same.map(|z| [z; D])));
        }
    }
    out
}

/// `sample`, `sample_lanes`, `fill_points` and `fill_grid`.
fn sweep_noise<R: Special, const D: usize, N: Noise<R, D>>(name: &str, noise: &N, rng: &mut Rng) {
    let bound = noise.amplitude_bound();
    let what = |p: &[R; D]| format!("{name} {D}D {} at {p:?}", R::NAME);
    let points = bad_points::<R, D>(rng, 3);
    let values: Vec<R> = points.iter().map(|(p, _)| noise.sample(*p)).collect();
    for ((p, same), v) in points.iter().zip(&values) {
        check_value(*v, bound, || what(p));
        if let Some(q) = same {
            let w = noise.sample(*q);
            assert_eq!(v.bits(), w.bits(), "{} vs {q:?}", what(p));
        }
    }

    let axes: [Vec<R>; D] = from_fn(|a| points.iter().map(|(p, _)| p[a]).collect());
    let mut out = vec![R::ZERO; points.len()];
    noise
        .fill_points(from_fn(|a| axes[a].as_slice()), &mut out)
        .expect("lengths match");
    for ((p, _), (o, v)) in points.iter().zip(out.iter().zip(&values)) {
        assert_eq!(o.bits(), v.bits(), "fill_points: {}", what(p));
    }
    // `sample_lanes` itself: a noise may fill points without it (a loop of `sample` where its
    // lanes are point samples).
    for (c, chunk) in points.chunks(LANES).enumerate() {
        let lanes: [[R; LANES]; D] = from_fn(|a| from_fn(|l| chunk[l.min(chunk.len() - 1)].0[a]));
        let mut out = [R::ZERO; LANES];
        noise.sample_lanes(&lanes, &mut out);
        for (l, (p, _)) in chunk.iter().enumerate() {
            let v = values[c * LANES + l];
            assert_eq!(out[l].bits(), v.bits(), "sample_lanes: {}", what(p));
        }
    }

    // Grids with a bad origin or step along one axis; a step that is no power-of-two fraction
    // of a cell, rows of more than two chunks.
    let size: [usize; D] = from_fn(|a| if a == 0 { 2 * LANES + 3 } else { 2 });
    for (s, _) in R::specials() {
        for axis in 0..D {
            let origin = random_point::<R, D>(rng);
            let step: [R; D] = from_fn(|a| R::from_f64(0.37 + 0.11 * a as f64));
            for grid in [
                Grid::new(with(origin, axis, s), step, size),
                Grid::new(origin, with(step, axis, s), size),
            ] {
                let mut out = vec![R::ZERO; grid.len()];
                noise.fill_grid(&grid, &mut out).expect("length matches");
                for (i, o) in out.iter().enumerate() {
                    let mut rest = i;
                    let index: [usize; D] = from_fn(|a| {
                        let k = rest % size[a];
                        rest /= size[a];
                        k
                    });
                    let p = grid.point(index);
                    check_value(*o, bound, || format!("fill_grid {}", what(&p)));
                    assert_eq!(o.bits(), noise.sample(p).bits(), "fill_grid {}", what(&p));
                }
            }
        }
    }
}

/// `sample_with_gradient` (given as `gradient`) against `sample`.
fn sweep_gradient<R: Special, const D: usize, N: Noise<R, D>>(
    name: &str,
    noise: &N,
    gradient: impl Fn([R; D]) -> (R, [R; D]),
    rng: &mut Rng,
) {
    for (p, same) in bad_points::<R, D>(rng, 3) {
        let what = || format!("{name} {D}D {} gradient at {p:?}", R::NAME);
        let (v, g) = gradient(p);
        assert_eq!(v.bits(), noise.sample(p).bits(), "{}", what());
        assert!(
            g.iter().all(|d| d.to_f64().is_finite()),
            "{}: {g:?}",
            what()
        );
        if let Some(q) = same {
            let (w, h) = gradient(q);
            assert_eq!(
                (v.bits(), g.map(R::bits)),
                (w.bits(), h.map(R::bits)),
                "{}",
                what()
            );
        }
    }
}

/// `sample_filtered` (of a fractal sum, Gabor noise) with bad points and bad footprints.
fn sweep_filtered<R: Special, const D: usize, F: FilteredNoise<R, D>>(
    name: &str,
    f: &F,
    rng: &mut Rng,
) {
    let bound = Noise::<R, D>::amplitude_bound(f);
    let mut footprints: Vec<[R; D]> = vec![
        [R::ZERO; D],
        from_fn(|_| R::from_f64(rng.f64_in(-0.3, 0.3))),
        with([R::ZERO; D], 0, R::from_f64(0.0625)),
    ];
    footprints.extend(
        R::specials()
            .into_iter()
            .map(|(s, _)| with([R::ZERO; D], 0, s)),
    );
    for (p, same) in bad_points::<R, D>(rng, 1) {
        for dx in &footprints {
            for dy in &footprints {
                let what = || format!("{name} {D}D {} filtered at {p:?}, {dx:?}, {dy:?}", R::NAME);
                let v = f.sample_filtered(p, *dx, *dy);
                check_value(v, bound, what);
                let swapped = f.sample_filtered(p, *dy, *dx);
                assert_eq!(v.bits(), swapped.bits(), "{} swapped", what());
                if let Some(q) = same {
                    assert_eq!(
                        v.bits(),
                        f.sample_filtered(q, *dx, *dy).bits(),
                        "{}",
                        what()
                    );
                }
            }
        }
    }
}

/// Normals with every component a multiple of 2⁻⁸ in `[-1, 1]`, not all 0, so that their
/// power-of-two multiples are exact in every type.
fn exact_normal<R: Special>(rng: &mut Rng) -> [R; 3] {
    loop {
        let n: [i32; 3] = from_fn(|_| rng.i32_in(-256, 257));
        if n != [0; 3] {
            return n.map(|c| R::from_ratio(c, 8));
        }
    }
}

/// Powers of two by which a normal of components at most 1 can be scaled exactly: beyond what
/// a squared length survives, in each type.
fn normal_scales<R: Special>() -> Vec<R> {
    if R::NAME == "I16F16" {
        // Squares overflow from 181 on.
        [1, 4, 8, 14].map(|k| R::from_i32(1 << k)).to_vec()
    } else {
        // 2^±100 overflows or underflows the squares in f32, 2^±600 in f64.
        let mut s = [-100, -60, 60, 100]
            .map(|k| R::from_f32(2f32.powi(k)))
            .to_vec();
        if R::NAME == "f64" {
            s.push(R::from_ratio(1, 600));
        }
        s
    }
}

/// Projected sampling (`project(p, normal)`) within `bound`.
fn sweep_projected<R: Special>(
    name: &str,
    project: impl Fn([R; 3], [R; 3]) -> R,
    bound: f32,
    rng: &mut Rng,
) {
    let mut normals: Vec<[R; 3]> = vec![
        [R::ZERO; 3],
        [R::ZERO, R::ZERO, R::ONE],
        [R::ONE, R::ZERO, R::ZERO],
        exact_normal(rng),
    ];
    let n = exact_normal::<R>(rng);
    for (s, _) in R::specials() {
        normals.extend((0..3).map(|a| with(n, a, s)));
        normals.push([s; 3]);
    }
    for (p, same) in bad_points::<R, 3>(rng, 1) {
        for n in &normals {
            let what = || format!("{name} {} projected at {p:?} normal {n:?}", R::NAME);
            let v = project(p, *n);
            check_value(v, bound, what);
            if let Some(q) = same {
                assert_eq!(v.bits(), project(q, *n).bits(), "{}", what());
            }
        }
    }
    // Any finite non-zero normal is normalised, huge and tiny ones included.
    for _ in 0..20 {
        let n = exact_normal::<R>(rng);
        let u = unit_normal(n);
        let len2: f64 = u.iter().map(|c| c.to_f64() * c.to_f64()).sum();
        assert!((len2 - 1.0).abs() < 1e-3, "{n:?} → {u:?}");
        let p = random_point::<R, 3>(rng);
        let v = project(p, n);
        for k in normal_scales::<R>() {
            let nk = n.map(|c| c * k);
            let what = || format!("{name} {} normal {n:?} × {k}", R::NAME);
            assert_eq!(unit_normal(nk).map(R::bits), u.map(R::bits), "{}", what());
            assert_eq!(project(p, nk).bits(), v.bits(), "{}", what());
        }
    }
}

/// Every sampling entry point of the crate in the number type `R`.
fn every_noise<R: Special>(rng: &mut Rng) {
    // Lattice noises, 1D–4D, and the gradients of the gradient noises.
    for (name, n) in Lattice::all(5) {
        sweep_noise::<R, 1, _>(name, &n, rng);
        sweep_noise::<R, 2, _>(name, &n, rng);
        sweep_noise::<R, 3, _>(name, &n, rng);
        sweep_noise::<R, 4, _>(name, &n, rng);
        sweep_gradient::<R, 1, _>(name, &n, |p| n.sample_with_gradient(p), rng);
        sweep_gradient::<R, 2, _>(name, &n, |p| n.sample_with_gradient(p), rng);
        sweep_gradient::<R, 3, _>(name, &n, |p| n.sample_with_gradient(p), rng);
        sweep_gradient::<R, 4, _>(name, &n, |p| n.sample_with_gradient(p), rng);
    }

    // Periodic lattice noise: periods short, odd, natural and beyond the hash's own.
    let perlin = Perlin::new(2);
    let name = "periodic perlin";
    sweep_noise::<R, 1, _>(name, &Periodic::new(&perlin, [3]).expect("valid"), rng);
    sweep_noise::<R, 2, _>(name, &Periodic::new(&perlin, [5, 256]).expect("valid"), rng);
    sweep_noise::<R, 3, _>(
        name,
        &Periodic::new(&perlin, [1, 7, 1000]).expect("valid"),
        rng,
    );
    let p4 = Periodic::new(&perlin, [65536, 2, 9, 300]).expect("valid");
    sweep_noise::<R, 4, _>(name, &p4, rng);
    sweep_gradient::<R, 4, _>(name, &p4, |p| p4.sample_with_gradient(p), rng);
    let m = Periodic::new(MNoise::<61>::new(3), [100, 13]).expect("valid");
    sweep_noise::<R, 2, _>("periodic mnoise", &m, rng);
    sweep_gradient::<R, 2, _>("periodic mnoise", &m, |p| m.sample_with_gradient(p), rng);
    let o = Periodic::new(OriginalPerlin::new(3), [17, 4, 3]).expect("valid");
    sweep_noise::<R, 3, _>("periodic original", &o, rng);
    let c = Periodic::new(CNoise::new(3), [17, 4, 3]).expect("valid");
    sweep_noise::<R, 3, _>("periodic cnoise", &c, rng);
    let v = Periodic::new(ValueNoise::new(3), [17, 4]).expect("valid");
    sweep_noise::<R, 2, _>("periodic value", &v, rng);
    sweep_gradient::<R, 2, _>("periodic value", &v, |p| v.sample_with_gradient(p), rng);

    // Fractal sums of every kind, plain and filtered.
    for kind in [Kind::Fbm, Kind::Turbulence, Kind::Ridged] {
        let f = Fractal::new(Perlin::new(3), Octaves::default(), kind);
        let name = &format!("{kind:?} of perlin");
        sweep_noise::<R, 1, _>(name, &f, rng);
        sweep_noise::<R, 2, _>(name, &f, rng);
        sweep_noise::<R, 3, _>(name, &f, rng);
        sweep_noise::<R, 4, _>(name, &f, rng);
        sweep_filtered::<R, 2, _>(name, &f, rng);
        sweep_filtered::<R, 3, _>(name, &f, rng);
        sweep_gradient::<R, 2, _>(name, &f, |p| f.sample_with_gradient(p), rng);
        sweep_gradient::<R, 3, _>(name, &f, |p| f.sample_with_gradient(p), rng);
    }

    // Wavelet bands over the default tiles, in every tiling, and the quantized tiles.
    for tiling in [Tiling::Varied, Tiling::Blended, Tiling::Periodic] {
        let name = &format!("wavelet {tiling:?}");
        let (b2, b3) = (
            Wavelet::new(6, &TILE2).with_tiling(tiling),
            Wavelet::new(6, &TILE3).with_tiling(tiling),
        );
        sweep_noise::<R, 2, _>(name, &b2, rng);
        sweep_noise::<R, 3, _>(name, &b3, rng);
        sweep_gradient::<R, 2, _>(name, &b2, |p| b2.sample_with_gradient(p), rng);
        sweep_gradient::<R, 3, _>(name, &b3, |p| b3.sample_with_gradient(p), rng);
    }
    sweep_noise::<R, 2, _>("wavelet i16", &Wavelet::new(6, &TILE2_I16), rng);
    sweep_noise::<R, 3, _>("wavelet i16", &Wavelet::new(6, &TILE3_I16), rng);
    // Projected: at most three times the tile's largest coefficient.
    let band = Wavelet::new(6, &TILE3);
    let b = 3.0 * Noise::<R, 3>::amplitude_bound(&band);
    sweep_projected::<R>("wavelet", |p, n| band.sample_projected(p, n), b, rng);
    let band = Wavelet::new(6, &TILE3_I16);
    let b = 3.0 * Noise::<R, 3>::amplitude_bound(&band);
    sweep_projected::<R>("wavelet i16", |p, n| band.sample_projected(p, n), b, rng);

    // Multiband noise: both distributions; default bands, bands below band 0 (scales that
    // fixed point cannot represent), 16 bands up to the highest.
    let band_lists = [
        Bands::default(),
        Bands::new(-20, &[1.0, 0.5, 0.25]).expect("valid"),
        Bands::new(8, &[1.0; 16]).expect("valid"),
    ];
    for distribution in [Distribution::Gaussian, Distribution::Uniform] {
        for bands in &band_lists {
            let name = &format!("multiband {distribution:?} from {}", bands.first());
            let m2 = Multiband::new(8, &TILE2, *bands, distribution);
            let m3 = Multiband::new(8, &TILE3, *bands, distribution);
            sweep_noise::<R, 2, _>(name, &m2, rng);
            sweep_noise::<R, 3, _>(name, &m3, rng);
            sweep_gradient::<R, 2, _>(name, &m2, |p| m2.sample_with_gradient(p), rng);
            sweep_gradient::<R, 3, _>(name, &m3, |p| m3.sample_with_gradient(p), rng);
            let b = m3.projected_bound();
            sweep_projected::<R>(name, |p, n| m3.sample_projected(p, n), b, rng);
        }
        // A fractal sum over multiband noise.
        let m = Multiband::new(8, &TILE2, Bands::default(), distribution);
        let f = Fractal::fbm(m, Octaves::new(3, 2.0, 0.5).expect("valid"));
        let name = &format!("fbm of multiband {distribution:?}");
        sweep_noise::<R, 2, _>(name, &f, rng);
        sweep_filtered::<R, 2, _>(name, &f, rng);
    }

    // Sparse convolution noise, 1D–4D: the default, Peachey's kernel with uniform weights at a
    // high density, a fixed count at the lowest density's scale; batches and gradients.
    let sparse = [
        ("sparse", Spec::new(Base::Sparse, 4)),
        (
            "sparse catmull-rom uniform 60",
            "sparse seed=4 kernel=catmull-rom weights=uniform density=60"
                .parse()
                .expect("valid"),
        ),
        (
            "sparse 1 per cell",
            "sparse seed=4 count=1".parse().expect("valid"),
        ),
        (
            "sparse 0.01",
            "sparse seed=4 density=0.01".parse().expect("valid"),
        ),
    ];
    for (name, spec) in sparse {
        let n1 = spec.build::<1>().expect("1D");
        let n2 = spec.build::<2>().expect("2D");
        let n3 = spec.build::<3>().expect("3D");
        let n4 = spec.build::<4>().expect("4D");
        sweep_noise::<R, 1, _>(name, &n1, rng);
        sweep_noise::<R, 2, _>(name, &n2, rng);
        sweep_noise::<R, 3, _>(name, &n3, rng);
        sweep_noise::<R, 4, _>(name, &n4, rng);
        sweep_gradient::<R, 2, _>(name, &n2, |p| n2.sample_with_gradient(p), rng);
        sweep_gradient::<R, 3, _>(name, &n3, |p| n3.sample_with_gradient(p), rng);
    }

    // Wiener noise, 1D–4D, both covariances; batches and gradients.
    for text in ["wiener seed=4", "wiener seed=4 covariance=band-pass"] {
        let spec: Spec = text.parse().expect("valid");
        let n1 = spec.build::<1>().expect("1D");
        let n2 = spec.build::<2>().expect("2D");
        let n3 = spec.build::<3>().expect("3D");
        let n4 = spec.build::<4>().expect("4D");
        sweep_noise::<R, 1, _>(text, &n1, rng);
        sweep_noise::<R, 2, _>(text, &n2, rng);
        sweep_noise::<R, 3, _>(text, &n3, rng);
        sweep_noise::<R, 4, _>(text, &n4, rng);
        sweep_gradient::<R, 2, _>(text, &n2, |p| n2.sample_with_gradient(p), rng);
        sweep_gradient::<R, 3, _>(text, &n3, |p| n3.sample_with_gradient(p), rng);
    }

    // Gabor noise, 1D–3D: the default, every variant and envelope, the extreme bandwidths
    // and frequency ratio, a fixed count; batches and gradients.
    for text in [
        "gabor seed=4",
        "gabor seed=4 orientation=isotropic envelope=truncated direction=1,1,1",
        "gabor seed=4 orientation=hybrid count=1 weights=uniform magnitude=-1024",
        "gabor seed=4 bandwidth=256 frequency=16384 density=64",
        "gabor seed=4 bandwidth=0.00390625 frequency=0 density=0.01",
    ] {
        let spec: Spec = text.parse().expect("valid");
        let n1 = spec.build::<1>().expect("1D");
        let n2 = spec.build::<2>().expect("2D");
        let n3 = spec.build::<3>().expect("3D");
        sweep_noise::<R, 1, _>(text, &n1, rng);
        sweep_noise::<R, 2, _>(text, &n2, rng);
        sweep_noise::<R, 3, _>(text, &n3, rng);
        sweep_gradient::<R, 2, _>(text, &n2, |p| n2.sample_with_gradient(p), rng);
        sweep_gradient::<R, 3, _>(text, &n3, |p| n3.sample_with_gradient(p), rng);
    }
    // Gabor surface noise: any normal, each variant.
    for orientation in [
        Orientation::Anisotropic,
        Orientation::Isotropic,
        Orientation::Hybrid,
    ] {
        let gabor = Gabor::<3>::new(4).with_orientation(orientation);
        let b = ProjectedNoise::<R>::projected_bound(&gabor);
        let name = &format!("gabor surface {orientation:?}");
        sweep_projected::<R>(name, |p, n| gabor.sample_projected(p, n), b, rng);
        let plane = Gabor::<2>::new(4).with_orientation(orientation);
        let name = &format!("gabor filtered {orientation:?}");
        sweep_filtered::<R, 2, _>(name, &plane, rng);
    }

    // The error function behind the uniform distribution.
    for (s, _) in R::specials() {
        let v = erf(s);
        check_value(v, 1.0, || format!("erf({s}) in {}", R::NAME));
    }
}

#[test]
fn every_entry_point_keeps_its_contract_in_f32() {
    every_noise::<f32>(&mut Rng::from_env(140));
}

#[test]
fn every_entry_point_keeps_its_contract_in_f64() {
    every_noise::<f64>(&mut Rng::from_env(141));
}

#[test]
fn every_entry_point_keeps_its_contract_in_fixed_point() {
    every_noise::<I16F16>(&mut Rng::from_env(142));
}

#[test]
fn erf_of_the_infinities_and_nan() {
    assert_eq!(erf(f32::INFINITY), 1.0);
    assert_eq!(erf(f64::NEG_INFINITY), -1.0);
    assert_eq!(erf(f32::NAN).to_bits(), 0);
}

/// The test profile must keep overflow checks on, or fixed point's overflows would wrap
/// silently in these tests instead of failing them.
#[test]
#[allow(arithmetic_overflow, clippy::no_effect)]
fn overflow_checks_are_on() {
    let r = std::panic::catch_unwind(|| I16F16::MAX + std::hint::black_box(I16F16::ONE));
    assert!(r.is_err(), "the test profile lost its overflow checks");
}

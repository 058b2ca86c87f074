//! Cellular noise (Worley 1996) against a brute-force search:
//!
//! * `F1`, `F2`, `F2 − F1` and the cell value equal those of a search over every cell within 4
//!   (2D, 3D) or 5 (4D) cells of the point, at 10⁵ random points per metric and jitter in 2D
//!   and 3D (fewer in 1D and 4D), for two seeds, with the feature points taken from
//!   [`Cellular::feature_point`] and the distances computed from the metrics' definitions;
//! * feature points lie in their cells, within the jitter's extent;
//! * every value within the documented bound; fixed point follows `f32`; batches are `sample`;
//!   bad coordinates and settings.

use bandnoise::cellular::{Cellular, Metric, Output};
use bandnoise::{Error, I16F16, Noise, NoiseGradient};
use bandnoise_tests::{BAD_F32, Rng, agree};

/// The distance from `p` to `q` in `metric`, from its definition.
fn distance<const D: usize>(metric: Metric, p: [f64; D], q: [f64; D]) -> f64 {
    let d = core::array::from_fn::<f64, D, _>(|a| (p[a] - q[a]).abs());
    match metric {
        Metric::Euclidean => d.iter().map(|x| x * x).sum::<f64>().sqrt(),
        Metric::EuclideanSquared => d.iter().map(|x| x * x).sum(),
        Metric::Manhattan => d.iter().sum(),
        _ => d.iter().copied().fold(0.0, f64::max),
    }
}

/// Every feature point of the cells `lo..lo + side` along each axis, for the brute force.
struct Points<const D: usize> {
    lo: i32,
    side: usize,
    points: Vec<[f64; D]>,
}

impl<const D: usize> Points<D> {
    fn new(noise: &Cellular, lo: i32, side: usize) -> Self {
        let points = (0..side.pow(D as u32))
            .map(|i| noise.feature_point(Self::cell(lo, side, i)))
            .collect();
        Self { lo, side, points }
    }

    fn cell(lo: i32, side: usize, mut i: usize) -> [i32; D] {
        core::array::from_fn(|_| {
            let k = (i % side) as i32 + lo;
            i /= side;
            k
        })
    }

    fn get(&self, cell: [i32; D]) -> [f64; D] {
        let mut i = 0;
        for a in (0..D).rev() {
            i = i * self.side + (cell[a] - self.lo) as usize;
        }
        self.points[i]
    }
}

/// `(F1, F2, the nearest point's cell)` over every cell within `radius` of `p`'s cell.
fn brute_force<const D: usize>(
    metric: Metric,
    points: &Points<D>,
    p: [f64; D],
    radius: i32,
) -> (f64, f64, [i32; D]) {
    let base = p.map(|x| x.floor() as i32);
    let side = (2 * radius + 1) as usize;
    let mut best = (f64::INFINITY, f64::INFINITY, base);
    for i in 0..side.pow(D as u32) {
        let k = Points::<D>::cell(-radius, side, i);
        let cell: [i32; D] = core::array::from_fn(|a| base[a] + k[a]);
        let d = distance(metric, p, points.get(cell));
        if d < best.0 {
            best = (d, best.0, cell);
        } else if d < best.1 {
            best.1 = d;
        }
    }
    best
}

/// Compares every output of `noise` (its metric and jitter) with the brute-force search at `n`
/// random points in `(−range, range)ᴰ` (far from the origin: around `centre` in each axis).
fn against_brute_force<const D: usize>(
    noise: Cellular,
    n: usize,
    (centre, range): (i32, i32),
    rng: &mut Rng,
) where
    Cellular: Noise<f64, D>,
{
    let radius = if D == 4 { 5 } else { 4 };
    let lo = centre - range - radius;
    let points = Points::<D>::new(&noise, lo, (2 * (range + radius) + 1) as usize);
    let outputs = Output::ALL.map(|o| noise.with_output(o));
    let mut ties = 0;
    for _ in 0..n {
        let p: [f64; D] =
            core::array::from_fn(|_| centre as f64 + rng.f64_in(-range as f64, range as f64));
        let (f1, f2, nearest) = brute_force(noise.metric(), &points, p, radius);
        let got = outputs.map(|o| Noise::<f64, D>::sample(&o, p));
        let what = (noise.metric(), noise.jitter(), p);
        assert!(
            (got[0] - f1).abs() <= 1e-12,
            "F1 {what:?}: {} vs {f1}",
            got[0]
        );
        assert!(
            (got[1] - f2).abs() <= 1e-12,
            "F2 {what:?}: {} vs {f2}",
            got[1]
        );
        assert!((got[2] - (f2 - f1)).abs() <= 1e-12, "F2 - F1 {what:?}");
        // Which cell is nearest is ambiguous only where F1 = F2 (common with Chebyshev
        // distances and a regular grid of points: equal offsets along the dominant axis).
        if f2 - f1 > 1e-9 {
            let value: f64 = noise.cell_value(nearest);
            assert_eq!(got[3], value, "cell value {what:?}");
        } else {
            ties += 1;
        }
    }
    assert!(ties < n / 4, "{ties} ties of {n} for {:?}", noise.metric());
}

#[test]
fn exact_against_brute_force() {
    let mut rng = Rng::from_env(70);
    for (seed, n) in [(0, 100_000), (9, 10_000)] {
        for metric in Metric::ALL {
            for jitter in [0.0, 0.5, 0.8, 1.0] {
                let noise = Cellular::new(seed)
                    .with_metric(metric)
                    .with_jitter(jitter)
                    .unwrap();
                against_brute_force::<1>(noise, n / 10, (0, 50), &mut rng);
                against_brute_force::<2>(noise, n, (0, 12), &mut rng);
                against_brute_force::<3>(noise, n, (0, 6), &mut rng);
                against_brute_force::<4>(noise, n / 100, (0, 3), &mut rng);
            }
        }
    }
    // Far from the origin, where the fraction keeps fewer bits, and across cell -1.
    let noise = Cellular::new(4);
    against_brute_force::<2>(noise, 10_000, (1_000_000, 5), &mut rng);
    against_brute_force::<3>(noise, 10_000, (-700_001, 3), &mut rng);
}

#[test]
fn feature_points_lie_in_their_cells_within_the_jitter() {
    let mut rng = Rng::from_env(71);
    for jitter in [0.0, 0.3, 1.0] {
        let noise = Cellular::new(3).with_jitter(jitter).unwrap();
        let margin = (1.0 - jitter as f64) / 2.0;
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for _ in 0..20_000 {
            let cell: [i32; 3] = core::array::from_fn(|_| rng.i32_in(-1000, 1000));
            let q = noise.feature_point(cell);
            for a in 0..3 {
                let o = q[a] - cell[a] as f64;
                assert!(
                    o >= margin - 1e-4 && o < 1.0 - margin + 1e-4,
                    "{o} {jitter}"
                );
                lo = lo.min(o);
                hi = hi.max(o);
            }
        }
        // The points fill the extent.
        assert!(
            lo < margin + 0.01 && hi > 1.0 - margin - 0.01,
            "{lo} {hi} {jitter}"
        );
    }
    // Jitter 0: every point at its cell's centre, F1 0 there.
    let grid = Cellular::new(3).with_jitter(0.0).unwrap();
    assert_eq!(Noise::<f32, 2>::sample(&grid, [-6.5, 2.5]), 0.0);
}

/// Every output in every metric within its bound, the distances at least 0; the mean of F1.
fn bounded<const D: usize>(rng: &mut Rng) -> f64
where
    Cellular: Noise<f32, D> + Noise<I16F16, D>,
{
    let mut mean_f1 = 0.0;
    for metric in Metric::ALL {
        for output in Output::ALL {
            let noise = Cellular::new(2).with_metric(metric).with_output(output);
            let bound = noise.amplitude_bound::<D>();
            let (mut lo, mut hi, mut sum) = (f32::INFINITY, f32::NEG_INFINITY, 0.0f64);
            let n = 100_000;
            for _ in 0..n {
                let p: [f32; D] = core::array::from_fn(|_| rng.f64_in(-100.0, 100.0) as f32);
                let v: f32 = noise.sample(p);
                lo = lo.min(v);
                hi = hi.max(v);
                sum += v as f64;
            }
            let floor = if output == Output::CellValue {
                -1.0
            } else {
                0.0
            };
            assert!(
                lo >= floor && hi <= bound,
                "{metric:?} {output:?} {D}D: {lo}..{hi}"
            );
            println!(
                "{D}D {metric:?} {output:?}: range {lo:.3}..{hi:.3} (bound {bound:.3}), mean {:.3}",
                sum / n as f64
            );
            if (metric, output) == (Metric::Euclidean, Output::F1) {
                mean_f1 = sum / n as f64;
            }
        }
    }
    mean_f1
}

#[test]
fn within_the_bound() {
    let mut rng = Rng::from_env(72);
    bounded::<1>(&mut rng);
    let m2 = bounded::<2>(&mut rng);
    let m3 = bounded::<3>(&mut rng);
    bounded::<4>(&mut rng);
    // The means the docs quote.
    assert!(
        (m2 - 0.43).abs() < 0.01 && (m3 - 0.52).abs() < 0.01,
        "{m2} {m3}"
    );
}

#[test]
fn fixed_point_follows_f32_and_batches_are_samples() {
    let mut rng = Rng::from_env(73);
    for metric in Metric::ALL {
        for output in Output::ALL {
            let noise = Cellular::new(5).with_metric(metric).with_output(output);
            let e2 = agree::fixed_vs_f32::<_, 2>(&noise, 20_000, 200, &mut rng);
            let e3 = agree::fixed_vs_f32::<_, 3>(&noise, 20_000, 200, &mut rng);
            println!("I16F16 vs f32, {metric:?} {output:?}: 2D {e2:.2e}, 3D {e3:.2e}");
            // Distances differ by the roundings of the fraction (2⁻¹⁶) and of the squares; the
            // cell value by the rounding of 2⁻²⁴ to 2⁻¹⁶, except where fixed point's rounded
            // offsets make another point the nearest (a near tie): counted below.
            let limit = if output == Output::CellValue {
                2.0
            } else {
                5e-5
            };
            assert!(
                e2 <= limit && e3 <= limit,
                "{metric:?} {output:?}: {e2} {e3}"
            );
            agree::batches_match::<_, 2>(&noise, &[0.37, 0.05], &mut rng);
            agree::batches_match::<_, 3>(&noise, &[0.37], &mut rng);
        }
    }
}

#[test]
fn fixed_point_cell_values_differ_only_at_near_ties() {
    let mut rng = Rng::from_env(74);
    let noise = Cellular::new(5).with_output(Output::CellValue);
    let n = 100_000;
    let differ = (0..n)
        .filter(|_| {
            let p: [I16F16; 3] = rng.exact_point(200);
            let q: I16F16 = noise.sample(p);
            let f: f32 = noise.sample(bandnoise_tests::to_f32(p));
            (q.to_num::<f32>() - f).abs() > 2e-5
        })
        .count();
    println!("I16F16 cell values differing from f32's: {differ} of {n}");
    assert!(differ <= n / 1000, "{differ}");
}

/// The analytic gradient against central differences, except within a step of a kink (where
/// the nearest point changes, or a Manhattan or Chebyshev distance switches axis): counted, and
/// rare. The gradient's value is `sample`'s bit for bit.
fn gradients<const D: usize>(rng: &mut Rng)
where
    Cellular: NoiseGradient<f64, D> + NoiseGradient<f32, D> + NoiseGradient<I16F16, D>,
{
    let h = 1e-7;
    for metric in Metric::ALL {
        for output in Output::ALL {
            let noise = Cellular::new(8).with_metric(metric).with_output(output);
            let (n, mut kinks) = (20_000, 0);
            for _ in 0..n {
                let p: [f64; D] = core::array::from_fn(|_| rng.f64_in(-50.0, 50.0));
                let (v, g) = noise.sample_with_gradient(p);
                assert_eq!(v.to_bits(), noise.sample(p).to_bits());
                let f = p.map(|x| x as f32);
                assert_eq!(noise.sample_with_gradient(f).0, noise.sample(f));
                let q = p.map(I16F16::from_num);
                assert_eq!(noise.sample_with_gradient(q).0, noise.sample(q));
                let off = (0..D).any(|a| {
                    let (mut hi, mut lo) = (p, p);
                    hi[a] += h;
                    lo[a] -= h;
                    let numeric = (noise.sample(hi) - noise.sample(lo)) / (2.0 * h);
                    (numeric - g[a]).abs() > 1e-5
                });
                kinks += off as usize;
            }
            println!("{D}D {metric:?} {output:?}: {kinks} of {n} points within 1e-7 of a kink");
            assert!(kinks <= n / 500, "{D}D {metric:?} {output:?}: {kinks}");
        }
    }
}

#[test]
fn gradients_are_the_derivatives() {
    let mut rng = Rng::from_env(75);
    gradients::<2>(&mut rng);
    gradients::<3>(&mut rng);
}

/// Different seeds give decorrelated noise: |correlation| < 0.05 over a 256² grid (step 0.137
/// cells, off the lattice) for every output, neighbouring seeds and distant ones.
#[test]
fn seeds_are_decorrelated() {
    let grid = |noise: &Cellular| -> Vec<f64> {
        (0..256 * 256)
            .map(|i| {
                let p = [
                    (i % 256) as f64 * 0.137 + 0.31,
                    (i / 256) as f64 * 0.137 - 5.2,
                ];
                Noise::<f64, 2>::sample(noise, p)
            })
            .collect()
    };
    for output in Output::ALL {
        for (s1, s2) in [(0, 1), (1, 2), (7, 1_000_003), (0, u32::MAX)] {
            let a = grid(&Cellular::new(s1).with_output(output));
            let b = grid(&Cellular::new(s2).with_output(output));
            let r = bandnoise_tests::correlation(&a, &b);
            assert!(r.abs() < 0.05, "{output:?} seeds {s1}, {s2}: {r}");
        }
    }
}

#[test]
fn total_on_bad_input_and_bad_settings() {
    for output in Output::ALL {
        let noise = Cellular::new(0).with_output(output);
        let bound = noise.amplitude_bound::<3>();
        for x in BAD_F32 {
            let v: f32 = noise.sample([x, 0.5, x]);
            assert!(
                v.abs() <= bound && v.to_bits() != (-0.0f32).to_bits(),
                "{x}: {v}"
            );
            let w: f64 = noise.sample([x as f64, 1e300, 0.5]);
            assert!(w.abs() <= bound as f64, "{x}: {w}");
        }
        for x in [I16F16::MAX, I16F16::MIN, I16F16::DELTA] {
            let v: I16F16 = noise.sample([x, x, I16F16::ZERO]);
            assert!(v.to_num::<f32>().abs() <= bound, "{x}: {v}");
        }
    }
    for j in [f32::NAN, -0.1, 1.0001, f32::INFINITY] {
        assert!(matches!(
            Cellular::new(0).with_jitter(j),
            Err(Error::Jitter(_))
        ));
    }
    assert_eq!(Cellular::new(0).with_jitter(0.25).unwrap().jitter(), 0.25);
}

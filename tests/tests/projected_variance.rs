//! The exact variance of a projected wavelet band as a function of the surface normal (issue 17
//! point 2), against the measured constants and against sampling.
//!
//! A band is `N(p) = Σ_c n_c W(p − c)`. Averaged over `p`, its variance is
//! `Σ_δ R(δ) ∫ W(u) W(u − δ) du`, with `R(δ)` the coefficients' autocovariance averaged over the
//! two phases (even, odd) of each axis. Cook & DeRose's coefficients are `n = (I − P³) r` (plus
//! a shifted copy, which doubles `R`) for white `r` and the 1D projection `P = up ∘ down` applied
//! along each axis, so `R(δ) = [δ = 0] − Π_a A(δ_a) − Π_a A(−δ_a) + Π_a C(δ_a)` with the 1D
//! phase averages `A(d)` of `P(φ, φ + d)` and `C(d)` of `(P Pᵀ)(φ, φ + d)`.
//!
//! * Sampled (no projection): `W = B³`, the overlap is `Π_a Q(δ_a)` with `Q = B ⋆ B`, the
//!   centred quintic B-spline.
//! * Projected along the unit normal `n`: `W(d) = B³(3/2 − M d)` with `M = I − ½ n nᵀ`
//!   (`projected.rs`), whose determinant is ½, so the overlap is `2 Π_a Q((M δ)_a)`.
//!
//! The ratio projected / sampled depends on the normal by a few per cent; multiband noise
//! divides by it through [`bandnoise::wavelet::projected_variance_ratio`].

use bandnoise::I16F16;
use bandnoise::prelude::*;
use bandnoise::wavelet::*;
use bandnoise_tests::Rng;

/// Cook & DeRose's analysis filter, `a_k` for `k = −16..−1` (symmetric: `a_{−1−k} = a_k`),
/// as in `tile.rs`.
const ANALYSIS: [f64; 16] = [
    0.000334, -0.001528, 0.000410, 0.0035455, -0.000938, -0.008233, 0.002172, 0.019120, -0.005040,
    -0.044412, 0.011655, 0.103311, -0.025936, -0.243780, 0.033979, 0.655340,
];

/// The period of the 1D rows the projection is computed on (long against the filter).
const L: usize = 128;

/// `up(down(row))` of a periodic row of length [`L`].
fn coarse(row: &[f64]) -> Vec<f64> {
    let tap = |k: i64| {
        if k < 0 {
            ANALYSIS[(k + 16) as usize]
        } else {
            ANALYSIS[(15 - k) as usize]
        }
    };
    let at = |i: i64| row[i.rem_euclid(L as i64) as usize];
    let c: Vec<f64> = (0..L as i64 / 2)
        .map(|i| (-16..16).map(|k| tap(k) * at(2 * i + k)).sum())
        .collect();
    let h = c.len();
    let mut out = vec![0.0; L];
    for m in 0..h {
        let (c0, c1) = (c[m], c[(m + 1) % h]);
        out[2 * m] = 0.75 * c0 + 0.25 * c1;
        out[2 * m + 1] = 0.25 * c0 + 0.75 * c1;
    }
    out
}

/// The coefficients' autocovariance, phase-averaged, up to a constant factor.
struct Covariance {
    /// `A(d)`, `A(−d)` and `C(d)` for `d = −REACH..=REACH` (index `d + REACH`).
    a: Vec<f64>,
    a_minus: Vec<f64>,
    c: Vec<f64>,
}

const REACH: i64 = 9;

impl Covariance {
    fn new() -> Self {
        // p[j] = P e_j, so P(i, j) = p[j][i].
        let p: Vec<Vec<f64>> = (0..L)
            .map(|j| {
                let mut e = vec![0.0; L];
                e[j] = 1.0;
                coarse(&e)
            })
            .collect();
        let pij =
            |i: i64, j: i64| p[j.rem_euclid(L as i64) as usize][i.rem_euclid(L as i64) as usize];
        let mut cov = Covariance {
            a: vec![],
            a_minus: vec![],
            c: vec![],
        };
        for d in -REACH..=REACH {
            let avg = |f: &dyn Fn(i64) -> f64| (f(0) + f(1)) / 2.0;
            cov.a.push(avg(&|phi| pij(phi, phi + d)));
            cov.a_minus.push(avg(&|phi| pij(phi + d, phi)));
            cov.c.push(avg(&|phi| {
                (0..L as i64).map(|j| pij(phi, j) * pij(phi + d, j)).sum()
            }));
        }
        cov
    }

    /// `R(δ)` (with `R(0) = 1 − …`), for `|δ_a| ≤ REACH`.
    fn at(&self, d: [i64; 3]) -> f64 {
        let i = d.map(|x| (x + REACH) as usize);
        let prod = |v: &[f64]| v[i[0]] * v[i[1]] * v[i[2]];
        let identity = if d == [0, 0, 0] { 1.0 } else { 0.0 };
        identity - prod(&self.a) - prod(&self.a_minus) + prod(&self.c)
    }
}

/// The centred quintic B-spline `Q(x) = ∫ B(s) B(s + x) ds` (support `(−3, 3)`).
fn quintic(x: f64) -> f64 {
    let t = x + 3.0;
    let binomial = [1.0, 6.0, 15.0, 20.0, 15.0, 6.0, 1.0];
    let mut sum = 0.0;
    for (k, b) in binomial.iter().enumerate() {
        let u = t - k as f64;
        if u > 0.0 {
            let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
            sum += sign * b * u.powi(5);
        }
    }
    sum / 120.0
}

/// `Σ_δ R(δ) · overlap(δ)` over every lag the overlap reaches.
fn variance(cov: &Covariance, overlap: impl Fn([f64; 3]) -> f64) -> f64 {
    let mut sum = 0.0;
    for z in -REACH..=REACH {
        for y in -REACH..=REACH {
            for x in -REACH..=REACH {
                let o = overlap([x as f64, y as f64, z as f64]);
                if o != 0.0 {
                    // The sum must take every lag the overlap reaches.
                    assert!(
                        x.abs().max(y.abs()).max(z.abs()) < REACH,
                        "overlap beyond REACH"
                    );
                    sum += cov.at([x, y, z]) * o;
                }
            }
        }
    }
    sum
}

/// The exact ratio of a projected band's variance to a sampled 3D band's, for a unit normal.
fn exact_ratio(cov: &Covariance, sampled: f64, n: [f64; 3]) -> f64 {
    let projected = variance(cov, |d| {
        let dot = n[0] * d[0] + n[1] * d[1] + n[2] * d[2];
        let m: [f64; 3] = core::array::from_fn(|a| d[a] - 0.5 * n[a] * dot);
        if m.iter().any(|x| x.abs() >= 3.0) {
            return 0.0;
        }
        2.0 * quintic(m[0]) * quintic(m[1]) * quintic(m[2])
    });
    projected / sampled
}

fn sampled_variance(cov: &Covariance) -> f64 {
    variance(cov, |d| d.iter().map(|&x| quintic(x)).product())
}

fn random_normal(rng: &mut Rng) -> [f64; 3] {
    loop {
        let v: [f64; 3] = core::array::from_fn(|_| rng.f64_in(-1.0, 1.0));
        let l2 = v.iter().map(|x| x * x).sum::<f64>();
        if l2 > 0.01 && l2 <= 1.0 {
            return v.map(|x| x / l2.sqrt());
        }
    }
}

#[test]
fn the_exact_projected_variance_matches_the_measured_constants() {
    let cov = Covariance::new();
    let sampled = sampled_variance(&cov);
    // The tile adds a shifted copy of itself: twice the variance.
    println!(
        "3D band variance from the filters: {:.4} (VARIANCE_3D, 24 tiles measured: {VARIANCE_3D})",
        2.0 * sampled
    );
    let mut rng = Rng::from_env(40);
    let count = 4000;
    let mean: f64 = (0..count)
        .map(|_| exact_ratio(&cov, sampled, random_normal(&mut rng)))
        .sum::<f64>()
        / count as f64;
    let along = |n| exact_ratio(&cov, sampled, n);
    let s = 1.0 / 3f64.sqrt();
    println!(
        "projected / sampled: mean over random normals {mean:.4} (VARIANCE_PROJECTED / \
         VARIANCE_3D = {:.4}); along an axis {:.4}, a face diagonal {:.4}, the cube diagonal {:.4}",
        VARIANCE_PROJECTED / VARIANCE_3D,
        along([0.0, 0.0, 1.0]),
        along([0.0, 0.5f64.sqrt(), 0.5f64.sqrt()]),
        along([s, s, s]),
    );
    assert!((2.0 * sampled / VARIANCE_3D as f64 - 1.0).abs() < 0.01);
    assert!((mean / (VARIANCE_PROJECTED / VARIANCE_3D) as f64 - 1.0).abs() < 0.01);
}

#[test]
fn the_projected_gain_is_the_exact_one_over_the_root_of_the_ratio() {
    let cov = Covariance::new();
    let sampled = sampled_variance(&cov);
    let mut rng = Rng::from_env(41);
    let (mut worst, mut worst_fixed, mut largest) = (0.0f64, 0.0f64, 0.0f64);
    for _ in 0..5000 {
        let n = random_normal(&mut rng);
        let exact = 1.0 / exact_ratio(&cov, sampled, n).sqrt();
        let g = projected_gain(n.map(|x| x as f32)) as f64;
        let fixed = projected_gain(n.map(I16F16::from_num)).to_num::<f64>();
        worst = worst.max((g / exact - 1.0).abs());
        worst_fixed = worst_fixed.max((fixed / exact - 1.0).abs());
        largest = largest.max(g).max(fixed);
    }
    println!(
        "projected_gain against 1/√ρ over 5000 normals: f32 within {worst:.1e}, I16F16 within \
         {worst_fixed:.1e} (relative); largest {largest:.4}"
    );
    assert!(worst < 5e-5 && worst_fixed < 2e-4);
    // The projected bounds use 0.822.
    assert!(largest <= 0.822);
}

/// A normal for each sample.
type NormalFn = dyn FnMut(&mut Rng) -> [f32; 3];

#[test]
fn projected_multiband_noise_has_variance_one_for_every_normal() {
    let mut rng = Rng::from_env(42);
    let bands = Bands::new(-1, &[1.0, 0.7, 0.5, 0.3]).unwrap();
    // The default tiling, the default tile.
    let m = Multiband::new(2, &TILE3, bands, Distribution::Gaussian);
    let count = 1_000_000;
    let mut variance = |normal: &mut NormalFn| {
        let (mut m1, mut m2) = (0.0f64, 0.0f64);
        for _ in 0..count {
            let p: [f32; 3] = core::array::from_fn(|_| rng.f64_in(-200.0, 200.0) as f32);
            let n = normal(&mut rng);
            let v = m.sample_projected(p, n) as f64;
            m1 += v;
            m2 += v * v;
        }
        (m2 / count as f64, m1 / count as f64)
    };
    let s = 1.0 / 3f32.sqrt();
    let cases: [(&str, Box<NormalFn>); 4] = [
        ("along z", Box::new(|_| [0.0, 0.0, 1.0])),
        ("along (0.6, 0, 0.8)", Box::new(|_| [0.6, 0.0, 0.8])),
        ("along the cube diagonal", Box::new(move |_| [s, s, s])),
        (
            "random normals",
            Box::new(|r| random_normal(r).map(|x| x as f32)),
        ),
    ];
    for (name, mut normal) in cases {
        let (v, mean) = variance(&mut *normal);
        println!(
            "projected multiband noise {name}: variance {v:.4}, mean {mean:+.4} ({count} samples)"
        );
        assert!((v - 1.0).abs() < 0.01, "{name}: variance {v}");
    }
}

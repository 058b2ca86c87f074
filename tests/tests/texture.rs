//! The textures (`bandnoise::texture`) against their papers' formulas written out here in
//! `f64` with `std`'s `sin` and `hypot`; their number types against `f64`; the ranges their
//! docs state (measured where not proved); colour maps (interpolation, continuity, the convex
//! hull, pbrt's marble spline's jumps); polka dots' coverage; settings and bad input.

use bandnoise::fractal::{Fractal, Octaves};
use bandnoise::lattice::{MixedTurbulence, Perlin};
use bandnoise::texture::{
    ColorMap, Interpolation, Marble, PolkaDots, Texture, Windy, Wood, Wrinkled, rgb,
};
use bandnoise::{Error, FilteredNoise, I16F16, Noise};
use bandnoise_tests::{BAD_F32, Rng, to_f32, to_f64};

/// pbrt's octaves (gain 0.5, lacunarity 1.99).
fn pbrt(count: u32) -> Octaves {
    Octaves::new(count, 1.99, 0.5).unwrap()
}

/// Points a user would sample: a grid of step 0.0731 (not a power-of-two fraction of a
/// cell) from an origin off the lattice, `n × n` of them.
fn user_grid(n: usize) -> impl Iterator<Item = [f64; 2]> {
    (0..n * n).map(move |k| {
        let (i, j) = (k % n, k / n);
        [-3.217 + 0.0731 * i as f64, 5.113 + 0.0731 * j as f64]
    })
}

/// The distance between two places in a ring (fractions of a turn): wood's pattern wraps.
fn ring_distance(a: f64, b: f64) -> f64 {
    let d = (a - b).abs();
    d.min(1.0 - d)
}

#[test]
fn windy_is_pbrts_formula() {
    let windy = Windy::new(5);
    let wind = Fractal::fbm(Perlin::new(5), pbrt(3));
    let waves = Fractal::fbm(Perlin::new(5), pbrt(6));
    let mut rng = Rng::from_env(11);
    for _ in 0..20_000 {
        let p = rng.exact_point::<3>(200);
        // f32: pbrt's `.1f * P` and its product, bit for bit.
        let q = to_f32(p);
        let expected = Noise::<f32, 3>::sample(&wind, q.map(|x| 0.1 * x)).abs()
            * Noise::<f32, 3>::sample(&waves, q);
        assert_eq!(windy.sample(q), expected + 0.0, "at {q:?}");
        // Filtered: both sums anti-aliased, the wind's footprint scaled.
        let w = [0.3f32, 0.0, 0.1];
        let v = [0.0f32, 0.2, 0.0];
        let tenth = |a: [f32; 3]| a.map(|x| 0.1 * x);
        let filtered = wind.sample_filtered(tenth(q), tenth(w), tenth(v)).abs()
            * waves.sample_filtered(q, w, v);
        assert_eq!(windy.sample_filtered(q, w, v), filtered + 0.0);
        // Fixed point within the sums' rounding of f64, near the origin (pbrt's lacunarity
        // 1.99 rounds to 2⁻¹⁶ in fixed point: far out, the finest octave lands elsewhere).
        let p = rng.exact_point::<3>(8);
        let exact: f64 = windy.sample(to_f64(p));
        let fixed: I16F16 = windy.sample(p);
        assert!(
            (fixed.to_num::<f64>() - exact).abs() < 2e-3,
            "{p:?}: {fixed} vs {exact}"
        );
    }
}

#[test]
fn windy_and_wrinkled_ranges() {
    let windy = Windy::new(0);
    let wrinkled = Wrinkled::new(0);
    let (mut windy_out, mut wrinkled_out, mut n) = (0usize, 0usize, 0usize);
    let (mut windy_max, mut wrinkled_max) = (0f64, 0f64);
    for [x, y] in user_grid(400) {
        let p = [x, y, 0.37];
        let h: f64 = windy.sample(p);
        let t: f64 = wrinkled.sample(p);
        assert!(h.abs() <= f64::from(Noise::<f64, 3>::amplitude_bound(&windy)));
        assert!((0.0..=f64::from(Noise::<f64, 3>::amplitude_bound(&wrinkled))).contains(&t));
        windy_out += usize::from(h.abs() > 1.0 / 3.0);
        wrinkled_out += usize::from(t > 1.5);
        windy_max = windy_max.max(h.abs());
        wrinkled_max = wrinkled_max.max(t);
        n += 1;
    }
    println!(
        "windy: |h| ≤ {windy_max:.3}, {windy_out} of {n} beyond 1/3; wrinkled ≤ \
         {wrinkled_max:.3}, {wrinkled_out} beyond 1.5"
    );
    // The docs' claims behind the patterns' clamps: under 1% of points clamped in windy
    // waves' (the crests), under 0.1% in wrinkled's.
    assert!(windy_out * 100 <= n && wrinkled_out * 1000 <= n);
    // And the patterns use their range: the heights are not all near 0.
    assert!(windy_max > 0.2 && wrinkled_max > 0.6);
}

#[test]
fn wrinkled_is_pbrts_turbulence() {
    let wrinkled = Wrinkled::new(9);
    let turbulence = Fractal::turbulence(Perlin::new(9), pbrt(8));
    for [x, y] in user_grid(60) {
        let p = [x as f32, y as f32];
        assert_eq!(wrinkled.sample(p), turbulence.sample(p));
        let w = [0.4f32, 0.0];
        assert_eq!(
            wrinkled.sample_filtered(p, w, [0.0, 0.4]),
            turbulence.sample_filtered(p, w, [0.0, 0.4])
        );
    }
}

#[test]
fn marble_is_pbrts_and_olanos_formula() {
    let pbrt_marble = Marble::new(3);
    let fbm = Fractal::fbm(Perlin::new(3), pbrt(8));
    let olano = Marble::olano(3);
    let turbulence = MixedTurbulence::<4>::new(3);
    let scaled = Marble::with_noise(Perlin::new(3), 2.5, -0.7).unwrap();
    let mut rng = Rng::from_env(12);
    let (mut worst_f32, mut worst_fixed) = (0f64, 0f64);
    for _ in 0..20_000 {
        let p = rng.exact_point::<3>(100);
        let q = to_f64(p);
        let expected = 0.5 + 0.5 * (q[1] + f64::from(0.2f32) * fbm.sample(q)).sin();
        let ours: f64 = pbrt_marble.sample(q);
        // The tabled sine's error (2e-8 in f64) and nothing else.
        assert!(
            (ours - expected).abs() < 1e-7,
            "{q:?}: {ours} vs {expected}"
        );
        let expected = 0.5 + 0.5 * (q[1] + 1.5 * turbulence.sample(q)).sin();
        assert!((olano.sample(q) - expected).abs() < 1e-7);
        let s = q.map(|x| 2.5 * x);
        let expected = 0.5 + 0.5 * (s[1] - f64::from(0.7f32) * Perlin::new(3).sample(s)).sin();
        assert!((scaled.sample(q) - expected).abs() < 1e-7);
        let single: f32 = pbrt_marble.sample(to_f32(p));
        let fixed: I16F16 = pbrt_marble.sample(p);
        worst_f32 = worst_f32.max((f64::from(single) - ours).abs());
        worst_fixed = worst_fixed.max((fixed.to_num::<f64>() - ours).abs());
    }
    println!("marble: f32 within {worst_f32:.2e} of f64, I16F16 within {worst_fixed:.2e}");
    assert!(worst_f32 < 1e-5 && worst_fixed < 1e-3);
}

#[test]
fn marble_filters_its_noise() {
    let marble = Marble::new(1);
    let fbm = Fractal::fbm(Perlin::new(1), pbrt(8));
    for [x, y] in user_grid(40) {
        let p = [x, y];
        let (w, v) = ([0.25, 0.0], [0.0, 0.25]);
        let expected = 0.5 + 0.5 * (y + f64::from(0.2f32) * fbm.sample_filtered(p, w, v)).sin();
        assert!((marble.sample_filtered(p, w, v) - expected).abs() < 1e-7);
    }
}

#[test]
fn wood_is_lewis_formula() {
    let lewis = Wood::new(4);
    let fbm = Fractal::fbm(Perlin::new(4), pbrt(4));
    let olano = Wood::olano(4);
    let turbulence = MixedTurbulence::<4>::new(4);
    let mut rng = Rng::from_env(13);
    let (mut worst_f32, mut worst_fixed) = (0f64, 0f64);
    for _ in 0..20_000 {
        let p = rng.exact_point::<3>(50);
        let q = to_f64(p);
        let r = q[0].hypot(q[1]);
        let ring = |n: f64| (2.0 * (r + f64::from(0.3f32) * n)).rem_euclid(1.0);
        let ours: f64 = lewis.sample(q);
        assert!((0.0..1.0).contains(&ours));
        assert!(ring_distance(ours, ring(fbm.sample(q))) < 1e-12, "{q:?}");
        assert!(ring_distance(olano.sample(q), ring(turbulence.sample(q))) < 1e-12);
        let single: f32 = lewis.sample(to_f32(p));
        let fixed: I16F16 = lewis.sample(p);
        worst_f32 = worst_f32.max(ring_distance(f64::from(single), ours));
        worst_fixed = worst_fixed.max(ring_distance(fixed.to_num::<f64>(), ours));
    }
    println!("wood: f32 within {worst_f32:.2e} of f64, I16F16 within {worst_fixed:.2e}");
    assert!(worst_f32 < 1e-4 && worst_fixed < 2e-3);
    // 1D: the distance is |x|.
    let one = Wood::with_noise(Perlin::new(4), 3.0, 0.0).unwrap();
    assert_eq!(one.sample([-1.25f64]), (3.0f64 * 1.25).fract());
}

#[test]
fn polka_dots_cover_what_pbrts_construction_does() {
    // 2D: a dot of radius r in a fraction `chance` of the cells covers chance · π r².
    let mut rng = Rng::from_env(14);
    for (radius, chance) in [(0.35f32, 0.5f32), (0.2, 0.9), (0.5, 0.25)] {
        let dots = PolkaDots::new(8)
            .with_radius(radius)
            .unwrap()
            .with_chance(chance)
            .unwrap();
        let n = 200_000;
        let mut inside = 0usize;
        let mut disagree = 0usize;
        for _ in 0..n {
            let p = rng.exact_point::<2>(250);
            let v: f64 = dots.sample(to_f64(p));
            assert!(v == 0.0 || v == 1.0);
            inside += usize::from(v == 1.0);
            let single: f32 = dots.sample(to_f32(p));
            let fixed: I16F16 = dots.sample(p);
            disagree +=
                usize::from(f64::from(single) != v) + usize::from(fixed.to_num::<f64>() != v);
        }
        let expected = f64::from(chance) * std::f64::consts::PI * f64::from(radius).powi(2);
        let measured = inside as f64 / n as f64;
        // The cells' presence is a binomial over about 62 500 · 4 cells sampled ~0.8 times:
        // a standard error near 0.2% of the coverage; 0.01 is several of them.
        println!("r {radius}, chance {chance}: coverage {measured:.4} vs {expected:.4}");
        assert!((measured - expected).abs() < 0.01);
        // f32 and I16F16 differ from f64 only at the dots' edges (a rounding's width).
        assert!(disagree * 1000 < n, "{disagree} disagreements");
    }
    // No dots: radius 0 or chance 0; every cell: chance 1, and its centre is always inside
    // (the shift is at most ½ − r < r for r > ¼).
    let none = PolkaDots::new(1).with_chance(0.0).unwrap();
    let empty = PolkaDots::new(1).with_radius(0.0).unwrap();
    let all = PolkaDots::new(1).with_chance(1.0).unwrap();
    for [x, y] in user_grid(50) {
        assert_eq!(none.sample([x, y]), 0.0);
        assert_eq!(empty.sample([x, y]), 0.0);
        assert_eq!(all.sample([x.round(), y.round()]), 1.0);
    }
    // Seeds differ.
    let (a, b) = (PolkaDots::new(1), PolkaDots::new(2));
    let differ = user_grid(100)
        .filter(|&p| a.sample(p) != b.sample(p))
        .count();
    assert!(differ > 500, "{differ}");
}

#[test]
fn linear_color_maps_pass_through_their_colors() {
    static STOPS: [[u16; 3]; 5] = [
        rgb(0.0, 0.1, 0.2),
        rgb(0.3, 0.9, 0.5),
        rgb(1.0, 0.0, 0.25),
        rgb(0.5, 0.5, 0.5),
        rgb(0.125, 0.75, 0.0625),
    ];
    let map = ColorMap::new(&STOPS, Interpolation::Linear).unwrap();
    for (k, stop) in STOPS.iter().enumerate() {
        let expected = stop.map(|c| f64::from(c) / 65536.0);
        let t = k as f64 / 4.0;
        assert_eq!(map.map(t), expected);
        assert_eq!(map.map(t as f32), expected.map(|c| c as f32));
        assert_eq!(map.map(I16F16::from_num(t)), expected.map(I16F16::from_num));
    }
    // Half way is the mean; outside [0, 1] the ends; NaN the start.
    let mid = map.map(0.125f64);
    for a in 0..3 {
        let mean = (f64::from(STOPS[0][a]) + f64::from(STOPS[1][a])) / 131_072.0;
        assert!((mid[a] - mean).abs() < 1e-15);
    }
    assert_eq!(map.map(-3.0f32), map.map(0.0f32));
    assert_eq!(map.map(7.0f32), map.map(1.0f32));
    assert_eq!(map.map(f32::NAN), map.map(0.0f32));
    assert_eq!(map.map(f32::INFINITY), map.map(0.0f32));
    assert_eq!(map.map(I16F16::MAX), map.map(I16F16::ONE));
    assert_eq!(map.map(I16F16::MIN), map.map(I16F16::ZERO));
}

/// pbrt's marble spline as printed (§10.6.6): de Casteljau over the window of four colours
/// starting at `⌊6t⌋`, times 1.5 (red component; the table index clamped at `t = 1`, where the
/// printed code reads past its table).
fn pbrt_spline_red(t: f64) -> f64 {
    const RED: [f64; 9] = [0.58, 0.58, 0.58, 0.5, 0.6, 0.58, 0.58, 0.2, 0.58];
    let first = ((t * 6.0).floor() as usize).min(5);
    let t = t * 6.0 - first as f64;
    let c = &RED[first..first + 4];
    let lerp = |a: f64, b: f64| (1.0 - t) * a + t * b;
    let (s0, s1, s2) = (lerp(c[0], c[1]), lerp(c[1], c[2]), lerp(c[2], c[3]));
    let (s0, s1) = (lerp(s0, s1), lerp(s1, s2));
    1.5 * lerp(s0, s1)
}

#[test]
fn bspline_maps_are_continuous_where_pbrts_spline_jumps() {
    let map = ColorMap::MARBLE;
    let (mut ours, mut theirs) = (0f64, 0f64);
    let steps = 60_000;
    for k in 0..steps {
        let (t0, t1) = (k as f64 / steps as f64, (k + 1) as f64 / steps as f64);
        ours = ours.max((map.map(t1)[0] - map.map(t0)[0]).abs());
        theirs = theirs.max((pbrt_spline_red(t1) - pbrt_spline_red(t0)).abs());
    }
    println!("largest step over 1/{steps}: ours {ours:.2e}, pbrt's printed spline {theirs:.2e}");
    assert!(ours < 1e-3, "{ours}");
    assert!(theirs > 0.1, "{theirs}");
    // Within the colours' convex hull, in every number type; a map of one colour is that
    // colour (the weights sum to 1).
    static SAME: [[u16; 3]; 4] = [rgb(0.3, 0.6, 0.9); 4];
    let same = ColorMap::new(&SAME, Interpolation::BSpline).unwrap();
    for k in 0..=1000 {
        let t = k as f64 / 1000.0;
        for (a, c) in map.map(t).iter().enumerate() {
            let (lo, hi) = ColorMap::MARBLE
                .colors()
                .iter()
                .fold((1f64, 0f64), |(lo, hi), s| {
                    let v = f64::from(s[a]) / 65536.0;
                    (lo.min(v), hi.max(v))
                });
            assert!(*c >= lo - 1e-12 && *c <= hi + 1e-12);
        }
        let fixed = map.map(I16F16::from_num(t));
        let single = map.map(t as f32);
        for a in 0..3 {
            assert!((fixed[a].to_num::<f64>() - map.map(t)[a]).abs() < 1e-4);
            assert!((f64::from(single[a]) - map.map(t)[a]).abs() < 1e-6);
            assert!((same.map(t)[a] - f64::from(SAME[0][a]) / 65536.0).abs() < 1e-15);
        }
    }
}

#[test]
fn settings_are_checked() {
    static ONE: [[u16; 3]; 1] = [rgb(0.0, 0.0, 0.0)];
    static THREE: [[u16; 3]; 3] = [rgb(0.0, 0.0, 0.0); 3];
    assert_eq!(
        ColorMap::new(&ONE, Interpolation::Linear),
        Err(Error::ColorCount {
            count: 1,
            min: 2,
            max: 1024
        })
    );
    assert!(ColorMap::new(&THREE, Interpolation::Linear).is_ok());
    assert!(ColorMap::new(&THREE, Interpolation::BSpline).is_err());
    let e = PolkaDots::new(0).with_radius(0.6).unwrap_err();
    assert_eq!(
        e.to_string(),
        "texture radius 0.6 must be finite and in [0, 0.5]"
    );
    assert!(PolkaDots::new(0).with_chance(f32::NAN).is_err());
    assert!(PolkaDots::new(0).with_chance(1.5).is_err());
    assert!(Marble::with_noise(Perlin::new(0), f32::INFINITY, 0.2).is_err());
    assert!(Marble::with_noise(Perlin::new(0), 1.0, 2000.0).is_err());
    assert!(Wood::with_noise(Perlin::new(0), 0.0, 0.2).is_err());
    assert!(Wood::with_noise(Perlin::new(0), 2.0, f32::NAN).is_err());
    let w = Wood::with_noise(Perlin::new(0), 2.0, -0.5).unwrap();
    assert_eq!((w.rings(), w.amount()), (2.0, -0.5));
    // The defaults the docs state.
    let (m, o) = (Marble::new(0), Marble::olano(0));
    assert_eq!(
        (m.scale(), m.variation(), o.scale(), o.variation()),
        (1.0, 0.2, 1.0, 1.5)
    );
    let (w, o) = (Wood::new(0), Wood::olano(0));
    assert_eq!(
        (w.rings(), w.amount(), o.rings(), o.amount()),
        (2.0, 0.3, 2.0, 0.3)
    );
    assert_eq!(
        (PolkaDots::new(0).radius(), PolkaDots::new(0).chance()),
        (0.35, 0.5)
    );
    let d = PolkaDots::new(0).with_chance(0.25).unwrap();
    assert_eq!((d.radius(), d.chance()), (0.35, 0.25));
}

/// Every texture at every bad coordinate, in `f32`, `f64` and I16F16's extremes: a value in
/// its range, never `-0.0`, a colour in `[0, 1]`.
#[test]
fn textures_are_total() {
    fn check<T: Texture<f32, 3> + Texture<f64, 3> + Texture<I16F16, 3>>(
        name: &str,
        t: &T,
        lo: f32,
    ) {
        let bound = Noise::<f32, 3>::amplitude_bound(t);
        for &a in &BAD_F32 {
            for &b in &BAD_F32 {
                let p = [a, b, 0.5];
                let v: f32 = t.sample(p);
                assert!(v >= lo * bound && v <= bound, "{name} at {p:?}: {v}");
                assert!(v.to_bits() != (-0.0f32).to_bits(), "{name} at {p:?}");
                assert!(t.color(p).iter().all(|c| (0.0..=1.0).contains(c)));
                let v: f64 = t.sample(p.map(f64::from));
                assert!(!v.is_nan() && v >= f64::from(lo * bound) && v <= f64::from(bound));
            }
        }
        for a in [I16F16::MIN, I16F16::MAX, I16F16::ZERO, I16F16::DELTA] {
            for b in [I16F16::MIN, I16F16::MAX, -I16F16::DELTA] {
                let v: I16F16 = t.sample([a, b, a]);
                assert!(
                    v.to_num::<f32>() >= lo * bound && v.to_num::<f32>() <= bound,
                    "{name}"
                );
                assert!(t.color([a, b, b]).iter().all(|c| *c >= 0 && *c <= 1));
            }
        }
    }
    check("windy", &Windy::new(1), -1.0);
    check("wrinkled", &Wrinkled::new(1), 0.0);
    check("marble", &Marble::new(1), 0.0);
    check("olano marble", &Marble::olano(1), 0.0);
    check("polka dots", &PolkaDots::new(1), 0.0);
    check("wood", &Wood::new(1), 0.0);
    check("olano wood", &Wood::olano(1), 0.0);
}

#[test]
fn filtered_textures_are_total() {
    let p = [f32::NAN, 3e38, -0.0];
    for w in [
        [f32::NAN; 3],
        [f32::INFINITY, 0.0, 0.0],
        [0.0; 3],
        [1e30, -1e30, 5.0],
    ] {
        let values = [
            Windy::new(0).sample_filtered(p, w, w),
            Wrinkled::new(0).sample_filtered(p, w, w),
            Marble::new(0).sample_filtered(p, w, w),
            Wood::new(0).sample_filtered(p, w, w),
            PolkaDots::new(0).sample_filtered(p, w, w),
        ];
        assert!(values.iter().all(|v| v.is_finite()), "{w:?}: {values:?}");
    }
}

#[test]
fn filtered_polka_dots_keep_their_coverage_and_fade_to_it() {
    let dots = PolkaDots::new(6);
    let zero = [0.0f64; 2];
    let mean = 0.5 * std::f64::consts::PI * f64::from(0.35f32).powi(2);
    let (mut plain, mut filtered, mut n) = (0.0, 0.0, 0.0);
    for [x, y] in user_grid(600) {
        let p = [x * 0.61, y * 0.61];
        let v: f64 = dots.sample(p);
        // No footprint, or an unknown one: the plain sample, bit for bit.
        assert_eq!(dots.sample_filtered(p, zero, zero), v);
        assert_eq!(dots.sample_filtered(p, [f64::NAN; 2], zero), v);
        // A footprint of a fifth of a cell: in [0, 1], and the same coverage on average
        // (the ramp is symmetric about the edge).
        let w: f64 = dots.sample_filtered(p, [0.2, 0.0], [0.0, 0.1]);
        assert!((0.0..=1.0).contains(&w));
        let single: f32 = dots.sample_filtered(p.map(|c| c as f32), [0.2, 0.0], [0.0, 0.1]);
        let fixed: I16F16 = dots.sample_filtered(
            p.map(I16F16::from_num),
            [I16F16::from_num(0.2), I16F16::ZERO],
            [I16F16::ZERO, I16F16::from_num(0.1)],
        );
        assert!((f64::from(single) - w).abs() < 1e-4, "{p:?}");
        assert!(
            (fixed.to_num::<f64>() - w).abs() < 2e-2,
            "{p:?}: {fixed} vs {w}"
        );
        plain += v;
        filtered += w;
        n += 1.0;
        // A cell or more: the mean coverage.
        let far: f64 = dots.sample_filtered(p, [1.5, 0.0], zero);
        assert!((far - mean).abs() < 1e-6);
        assert_eq!(dots.sample_filtered(p, [f64::INFINITY, 0.0], zero), far);
    }
    println!(
        "coverage: plain {:.4}, filtered {:.4}, expected {mean:.4}",
        plain / n,
        filtered / n
    );
    // The ramp across a round edge adds a little: π w²/12 per dot (0.0052 here).
    let added = filtered / n - plain / n;
    assert!((0.0..0.008).contains(&added), "{added}");
    // Between ½ and 1 cell the value moves to the mean: at 0.9 it is a fifth of the way from
    // the edge's ramp (somewhere in [0, 1]).
    for [x, y] in user_grid(50) {
        let v: f64 = dots.sample_filtered([x, y], [0.9, 0.0], zero);
        assert!((v - mean).abs() <= 0.2 * (1.0 - mean) + 1e-9, "{v}");
    }
}

//! Wavelet noise in every tiling with arbitrary coordinates, normals and band lists (weights zero, NaN, huge):
//! no panic; refused configurations are errors; accepted ones give finite values within their
//! documented bounds (uniform distributions within [-1, 1]); a NaN or ±∞ coordinate samples 0
//! there, bit for bit (bands, multiband, projected); gradients give the same values and finite
//! slopes; any finite non-zero normal, however large
//! or small, is normalised to its own direction, and its power-of-two multiples give the same
//! bits; filtered by any footprint, and as infinite noise at any footprint, values stay within
//! the bounds and a NaN footprint is none; projected grids along one normal are the points,
//! bit for bit.
#![no_main]

use arbitrary::Arbitrary;
use bandnoise::batch::Grid;
use bandnoise::wavelet::{
    Bands, Distribution, Multiband, TILE2_I16, TILE3_I16, Tiling, Wavelet, unit_normal,
};
use bandnoise::{
    FilteredNoise, I16F16, Noise, NoiseGradient, ProjectedNoise, ProjectedNoiseGradient,
};
use libfuzzer_sys::fuzz_target;

#[derive(Arbitrary, Debug)]
struct Input {
    seed: u32,
    coords: [u32; 3],
    footprint: [u32; 6],
    normal: [u32; 3],
    first: i32,
    weights: Vec<f32>,
    uniform: bool,
    tiling: u8,
}

fuzz_target!(|input: Input| {
    let p = input.coords.map(f32::from_bits);
    let n = input.normal.map(f32::from_bits);
    let q = input.coords.map(|b| I16F16::from_bits(b as i32));
    let nq = input.normal.map(|b| I16F16::from_bits(b as i32));
    let tiling = [Tiling::Varied, Tiling::Blended, Tiling::Periodic][input.tiling as usize % 3];
    let band3 = Wavelet::new(input.seed, &TILE3_I16).with_tiling(tiling);
    let band2 = Wavelet::new(input.seed, &TILE2_I16).with_tiling(tiling);
    let b3 = Noise::<f32, 3>::amplitude_bound(&band3);
    for v in [band3.sample(p), band2.sample([p[0], p[1]])] {
        assert!(v.is_finite() && v.abs() <= b3.max(Noise::<f32, 2>::amplitude_bound(&band2)));
    }
    let proj = band3.sample_projected(p, n);
    assert!(proj.is_finite() && proj.abs() <= 3.0 * b3, "{proj}");
    let _: I16F16 = band3.sample(q);
    let _: I16F16 = band3.sample_projected(q, nq);
    // Gradients: the same value as without, bit for bit, and a finite slope.
    let (v, g) = band3.sample_projected_with_gradient(p, n);
    assert!(
        v.to_bits() == proj.to_bits() && g.iter().all(|d| d.is_finite()),
        "{g:?}"
    );
    let (v, g) = band3.sample_with_gradient(p);
    assert!(v.to_bits() == band3.sample(p).to_bits() && g.iter().all(|d| d.is_finite()));
    let _: (I16F16, _) = band3.sample_projected_with_gradient(q, nq);
    // Filtered by any footprint: within the bound; a NaN footprint is no footprint.
    let dx = [0, 1, 2].map(|a| f32::from_bits(input.footprint[a]));
    let dy = [3, 4, 5].map(|a| f32::from_bits(input.footprint[a]));
    let v = band3.sample_filtered(p, dx, dy);
    assert!(v.is_finite() && v.abs() <= b3, "{v}");
    let nan = [f32::NAN; 3];
    assert_eq!(
        band3.sample_filtered(p, nan, nan).to_bits(),
        band3.sample(p).to_bits()
    );
    let dq = input.footprint.map(|b| I16F16::from_bits(b as i32));
    let _: I16F16 = band3.sample_filtered(q, [dq[0], dq[1], dq[2]], [dq[3], dq[4], dq[5]]);
    let u = unit_normal(n);
    let len2: f32 = u.iter().map(|x| x * x).sum();
    assert!((len2 - 1.0).abs() < 1e-4, "{n:?} → {u:?}");
    assert_direction(n.map(f64::from), u.map(f64::from), 1e-6);
    assert_direction(
        nq.map(|c| c.to_num::<f64>()),
        unit_normal(nq).map(|c| c.to_num::<f64>()),
        2e-4,
    );
    // Power-of-two multiples that stay exact give the same unit normal and projection.
    for k in [2f32.powi(64), 2f32.powi(-64)] {
        let nk = n.map(|c| c * k);
        if nk.iter().zip(&n).all(|(a, b)| a.is_finite() && a / k == *b) {
            assert_eq!(unit_normal(nk), u, "{n:?} × {k}");
            assert_eq!(
                band3.sample_projected(p, nk).to_bits(),
                proj.to_bits(),
                "{n:?} × {k}"
            );
        }
    }
    // NaN and ±∞ coordinates sample 0 along their axis.
    let p0 = p.map(|c| if c.is_finite() { c } else { 0.0 });
    let same = |a: f32, b: f32| assert_eq!(a.to_bits(), b.to_bits(), "{p:?} vs {p0:?}");
    same(band3.sample(p), band3.sample(p0));
    same(band2.sample([p[0], p[1]]), band2.sample([p0[0], p0[1]]));
    same(proj, band3.sample_projected(p0, n));
    // Grids along one normal (an axis-aligned one takes the rows' lanes) are the points.
    let grid = Grid::new(p, dx, [10, 3, 2]);
    let mut out = [0.0f32; 60];
    for normal in [[0.0, 0.0, n[2]], [n[0], 0.0, 0.0], n] {
        band3.fill_grid_projected(&grid, normal, &mut out).unwrap();
        for (i, &v) in out.iter().enumerate() {
            let at = grid.point([i % 10, i / 10 % 3, i / 30]);
            same(v, band3.sample_projected(at, normal));
        }
    }
    let gq = Grid::new(q, [dq[0], dq[1], dq[2]], [10, 3, 2]);
    let mut outq = [I16F16::ZERO; 60];
    band3
        .fill_grid_projected(&gq, [nq[0], I16F16::ZERO, I16F16::ZERO], &mut outq)
        .unwrap();
    for (i, &v) in outq.iter().enumerate() {
        let at = gq.point([i % 10, i / 10 % 3, i / 30]);
        assert_eq!(
            v,
            band3.sample_projected(at, [nq[0], I16F16::ZERO, I16F16::ZERO])
        );
    }

    let distribution = if input.uniform {
        Distribution::Uniform
    } else {
        Distribution::Gaussian
    };
    match Bands::new(input.first, &input.weights) {
        Err(_) => {
            // Refused: too many bands, a weight not finite or above 1e6, or a first band out of
            // range. Check it was one of those.
            let bad_weight = input
                .weights
                .iter()
                .any(|w| !w.is_finite() || w.abs() > 1e6);
            assert!(input.weights.len() > 16 || bad_weight || !(-24..=8).contains(&input.first));
        }
        Ok(bands) => {
            let m = Multiband::new(input.seed, &TILE3_I16, bands, distribution).with_tiling(tiling);
            let bound = Noise::<f32, 3>::amplitude_bound(&m);
            let v: f32 = m.sample(p);
            assert!(v.is_finite() && v.abs() <= bound, "{v} > {bound}");
            let w = m.sample_projected(p, n);
            assert!(w.is_finite() && w.abs() <= m.projected_bound(), "{w}");
            if input.uniform {
                assert!(v.abs() <= 1.0 && w.abs() <= 1.0);
            }
            same(v, m.sample(p0));
            same(w, m.sample_projected(p0, n));
            let _: I16F16 = m.sample(q);
            let _: I16F16 = m.sample_projected(q, nq);
            let (wg, g) = m.sample_projected_with_gradient(p, n);
            assert!(
                wg.to_bits() == w.to_bits() && g.iter().all(|d| d.is_finite()),
                "{g:?}"
            );
            let (vg, g) = m.sample_with_gradient(p);
            assert!(
                vg.to_bits() == v.to_bits() && g.iter().all(|d| d.is_finite()),
                "{g:?}"
            );
            let _: (I16F16, _) = m.sample_projected_with_gradient(q, nq);
            // Its grids along an axis are its points.
            let axis = [0.0, n[1], 0.0];
            m.fill_grid_projected(&grid, axis, &mut out).unwrap();
            for (i, &v) in out.iter().enumerate() {
                let at = grid.point([i % 10, i / 10 % 3, i / 30]);
                same(v, m.sample_projected(at, axis));
            }
            let f = m.sample_filtered(p, dx, dy);
            assert!(f.is_finite() && f.abs() <= bound, "{f} > {bound}");
            let z = m.sample_infinite(p, dx[0]);
            let zb = m.infinite_bound::<3>();
            assert!(z.is_finite() && z.abs() <= zb, "{z} > {zb}");
            let _: I16F16 = m.sample_infinite(q, dq[0]);
            let _: I16F16 = m.sample_filtered(q, [dq[0], dq[1], dq[2]], [dq[3], dq[4], dq[5]]);
        }
    }
});

/// `unit` is `normal`'s direction within `tolerance` per component, for every finite non-zero
/// normal (others project along z), checked against an f64 reference that scales first.
fn assert_direction(normal: [f64; 3], unit: [f64; 3], tolerance: f64) {
    let largest = normal.iter().fold(0.0f64, |m, c| m.max(c.abs()));
    let want = if largest > 0.0 && normal.iter().all(|c| c.is_finite()) {
        let scaled = normal.map(|c| c / largest);
        let len = scaled.iter().map(|c| c * c).sum::<f64>().sqrt();
        scaled.map(|c| c / len)
    } else {
        [0.0, 0.0, 1.0]
    };
    for (got, want) in unit.iter().zip(want) {
        assert!(
            (got - want).abs() <= tolerance,
            "{normal:?} → {unit:?}, want {want:?}"
        );
    }
}

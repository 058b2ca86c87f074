//! Every lattice noise, 1D–4D, in f32 and I16F16, with arbitrary bit patterns as coordinates and
//! seeds: no panic, never NaN or -0.0, within the documented bound; fixed point and f32 agree
//! within 2⁻¹¹ where the input is exact in both; gradients are finite; the batch path
//! (`sample_lanes`) equals `sample` bit for bit. Periodic noise with arbitrary periods: refused
//! outside 1..=65536, otherwise within the bound and periodic bit for bit in fixed point.
#![no_main]

use arbitrary::Arbitrary;
use bandnoise::batch::LANES;
use bandnoise::lattice::{
    CNoise, MNoise, OriginalPerlin, Periodic, Perlin, TabledPerlin, ValueNoise,
};
use bandnoise::{I16F16, Noise, NoiseGradient};
use libfuzzer_sys::fuzz_target;

#[derive(Arbitrary, Debug)]
struct Input {
    seed: u32,
    bits: [u32; 4],
    periods: [u32; 3],
}

fn check<N>(noise: &N, floats: [f32; 4], fixed: [I16F16; 4], exact: bool)
where
    N: Noise<f32, 1> + Noise<f32, 2> + Noise<f32, 3> + Noise<f32, 4>,
    N: Noise<I16F16, 1> + Noise<I16F16, 2> + Noise<I16F16, 3> + Noise<I16F16, 4>,
{
    macro_rules! dim {
        ($d:literal) => {{
            let p: [f32; $d] = core::array::from_fn(|a| floats[a]);
            let q: [I16F16; $d] = core::array::from_fn(|a| fixed[a]);
            let bound = Noise::<f32, $d>::amplitude_bound(noise);
            let v: f32 = noise.sample(p);
            assert!(
                !v.is_nan() && v.abs() <= bound,
                "{}D f32 {p:?}: {v} (bound {bound})",
                $d
            );
            assert_ne!(v.to_bits(), (-0.0f32).to_bits());
            let w: I16F16 = noise.sample(q);
            assert!(w.to_num::<f32>().abs() <= bound, "{}D fixed {q:?}: {w}", $d);
            // The batch path equals the point path bit for bit: the input in lane 0, its
            // neighbours a quarter cell apart in the other lanes (a mixed chunk for specials).
            let lanes: [[f32; LANES]; $d] =
                core::array::from_fn(|a| core::array::from_fn(|l| p[a] + l as f32 * 0.25));
            let mut out = [0.0f32; LANES];
            noise.sample_lanes(&lanes, &mut out);
            for (l, o) in out.iter().enumerate() {
                let x: [f32; $d] = core::array::from_fn(|a| lanes[a][l]);
                let s: f32 = noise.sample(x);
                assert_eq!(o.to_bits(), s.to_bits(), "{}D f32 batch {x:?}", $d);
            }
            let lanes: [[I16F16; LANES]; $d] = core::array::from_fn(|a| {
                core::array::from_fn(|l| q[a].wrapping_add(I16F16::from_bits((l as i32) << 14)))
            });
            let mut out = [I16F16::ZERO; LANES];
            noise.sample_lanes(&lanes, &mut out);
            for (l, o) in out.iter().enumerate() {
                let x: [I16F16; $d] = core::array::from_fn(|a| lanes[a][l]);
                let s: I16F16 = noise.sample(x);
                assert_eq!(*o, s, "{}D fixed batch {x:?}", $d);
            }
            if exact {
                let qf: [f32; $d] = core::array::from_fn(|a| fixed[a].to_num::<f32>());
                let vf: f32 = noise.sample(qf);
                assert!(
                    (w.to_num::<f32>() - vf).abs() <= 1.0 / 2048.0,
                    "{}D {q:?}: {w} vs {vf}",
                    $d
                );
            }
        }};
    }
    dim!(1);
    dim!(2);
    dim!(3);
    dim!(4);
}

fn gradients<N>(noise: &N, floats: [f32; 4], fixed: [I16F16; 4])
where
    N: NoiseGradient<f32, 3> + NoiseGradient<I16F16, 2>,
{
    let (v, g) = noise.sample_with_gradient([floats[0], floats[1], floats[2]]);
    assert!(
        v.is_finite() && g.iter().all(|d| d.is_finite()),
        "{floats:?}: {v} {g:?}"
    );
    let (_, g) = noise.sample_with_gradient([fixed[0], fixed[1]]);
    // Gradient components are bounded by a few units per lattice cell.
    assert!(g.iter().all(|d| d.abs() < I16F16::from_num(64)));
}

/// `noise` wrapped to `periods`: refused for a documented reason, or bounded and periodic.
fn periodic<N: Clone>(noise: &N, periods: [u32; 3], floats: [f32; 4], fixed: [I16F16; 4])
where
    Periodic<N, 3>: Noise<f32, 3> + Noise<I16F16, 3>,
{
    let Ok(n) = Periodic::new(noise.clone(), periods) else {
        assert!(
            periods.iter().any(|&p| p == 0 || p > 65536),
            "{periods:?} refused"
        );
        return;
    };
    let p = [floats[0], floats[1], floats[2]];
    let bound = Noise::<f32, 3>::amplitude_bound(&n);
    let v: f32 = n.sample(p);
    assert!(!v.is_nan() && v.abs() <= bound, "{periods:?} {p:?}: {v}");
    let q = [fixed[0], fixed[1], fixed[2]];
    let w: I16F16 = n.sample(q);
    assert!(w.to_num::<f32>().abs() <= bound);
    // n(q + P) == n(q) along each axis, where q + P fits I16F16.
    for a in 0..3 {
        let shift = I16F16::checked_from_num(periods[a]);
        if let Some(moved) = shift.and_then(|s| q[a].checked_add(s)) {
            let mut r = q;
            r[a] = moved;
            assert_eq!(
                Noise::<I16F16, 3>::sample(&n, r),
                w,
                "{periods:?} {q:?} axis {a}"
            );
        }
    }
}

/// Perlin with its per-seed table is Perlin, bit for bit, where the table's kernel runs (f32 2D
/// and 3D; on x86-64 a different kernel from `Perlin`'s).
fn tabled(seed: u32, floats: [f32; 4]) {
    let (perlin, tabled) = (Perlin::new(seed), TabledPerlin::new(seed));
    let [x, y, z, _] = floats;
    let (a, b): (f32, f32) = (perlin.sample([x, y]), tabled.sample([x, y]));
    assert_eq!(a.to_bits(), b.to_bits(), "2D {x} {y}");
    let (a, b): (f32, f32) = (perlin.sample([x, y, z]), tabled.sample([x, y, z]));
    assert_eq!(a.to_bits(), b.to_bits(), "3D {x} {y} {z}");
}

fuzz_target!(|input: Input| {
    let floats = input.bits.map(f32::from_bits);
    let fixed = input.bits.map(|b| I16F16::from_bits(b as i32));
    // Fixed-point inputs that f32 holds exactly: |x| < 256 (24 significant bits).
    let exact = fixed.iter().all(|x| x.to_bits().unsigned_abs() < 256 << 16);
    let s = input.seed;
    check(&Perlin::new(s), floats, fixed, exact);
    tabled(s, floats);
    check(&OriginalPerlin::new(s), floats, fixed, exact);
    check(&ValueNoise::new(s), floats, fixed, exact);
    check(&CNoise::new(s), floats, fixed, exact);
    check(&MNoise::<61>::seeded(s), floats, fixed, exact);
    check(&MNoise::<4093>::seeded(s), floats, fixed, exact);
    gradients(&Perlin::new(s), floats, fixed);
    gradients(&MNoise::<61>::seeded(s), floats, fixed);
    gradients(&OriginalPerlin::new(s), floats, fixed);
    periodic(&&Perlin::new(s), input.periods, floats, fixed);
    periodic(&ValueNoise::new(s), input.periods, floats, fixed);
    periodic(&MNoise::<61>::seeded(s), input.periods, floats, fixed);
    periodic(&CNoise::new(s), input.periods, floats, fixed);
});

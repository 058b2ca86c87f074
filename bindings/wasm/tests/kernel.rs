//! The WebAssembly SIMD point kernel of Perlin noise (`core/src/arch/wasm32.rs`, which this
//! crate's build selects: simd128, no `small`) gives the portable kernel's values bit for bit.
//! The native test of the shared kernel (`core/src/arch/vector.rs`) cannot run here, so the
//! point samples are compared with the batch kernels' (portable code, equal to the point
//! kernel's by the crate's contract) over random and edge-case points, for `Perlin` and
//! `TabledPerlin` in 2D, 3D and 4D. Run by
//! `cargo test -p bandnoise-js --target wasm32-unknown-unknown` (Node).
#![cfg(target_arch = "wasm32")]

use bandnoise::Noise;
use bandnoise::batch::LANES;
use bandnoise::lattice::{Perlin, TabledPerlin};
use wasm_bindgen_test::wasm_bindgen_test;

/// Edge cases of the split (signed zeros, tiny negatives, cell and range limits, non-finite
/// values) and random coordinates, half of them random bit patterns, half in (−128, 128).
fn coordinates(n: usize) -> Vec<f32> {
    let mut v = vec![
        0.0,
        -0.0,
        -1e-30,
        1e-30,
        -1e-8,
        0.999_999_94,
        -0.999_999_94,
        255.5,
        256.0,
        -256.0,
        4_194_303.5,
        -4_194_304.0,
        2_147_483_520.0,
        -2_147_483_520.0,
        2_147_483_648.0,
        -2_147_483_648.0,
        f32::NAN,
        f32::INFINITY,
        f32::NEG_INFINITY,
        f32::MAX,
        f32::MIN_POSITIVE,
    ];
    let mut state = 0x853c_49e6_748f_ea9b_u64;
    while v.len() < n {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        let bits = (state >> 32) as u32;
        v.push(if state & 1 == 0 {
            f32::from_bits(bits)
        } else {
            (bits >> 8) as f32 / 65_536.0 - 128.0
        });
    }
    v
}

/// `noise.sample` at each of `LANES` points against `sample_lanes` on them, bit for bit, for
/// every chunk of `LANES` consecutive points drawn from `xs` (axis `a` of point `k` is
/// `xs[(k · D + a · 7) % len]`).
fn point_equals_batch<N: Noise<f32, D>, const D: usize>(noise: &N, xs: &[f32]) -> usize {
    let mut compared = 0;
    for chunk in 0..xs.len() / LANES {
        let lanes: [[f32; LANES]; D] = core::array::from_fn(|a| {
            core::array::from_fn(|l| xs[((chunk * LANES + l) * D + a * 7) % xs.len()])
        });
        let mut batch = [0.0f32; LANES];
        noise.sample_lanes(&lanes, &mut batch);
        for (l, b) in batch.iter().enumerate() {
            let p: [f32; D] = core::array::from_fn(|a| lanes[a][l]);
            let v = noise.sample(p);
            assert_eq!(v.to_bits(), b.to_bits(), "{D}D {p:?}: point {v}, batch {b}");
            compared += 1;
        }
    }
    compared
}

#[wasm_bindgen_test]
fn simd_point_kernel_equals_the_portable_kernel() {
    let xs = coordinates(40_000);
    for seed in [0, 1, 0xdead_beef] {
        let perlin = Perlin::new(seed);
        let tabled = TabledPerlin::from_perlin(perlin.clone());
        assert!(point_equals_batch::<_, 2>(&perlin, &xs) >= 39_000);
        assert!(point_equals_batch::<_, 3>(&perlin, &xs) >= 39_000);
        assert!(point_equals_batch::<_, 4>(&perlin, &xs) >= 39_000);
        assert!(point_equals_batch::<_, 2>(&tabled, &xs) >= 39_000);
        assert!(point_equals_batch::<_, 3>(&tabled, &xs) >= 39_000);
        assert!(point_equals_batch::<_, 4>(&tabled, &xs) >= 39_000);
    }
}

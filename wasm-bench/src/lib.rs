//! The browser benchmark's wasm module (`web/bench.html`, `web/bench.js`): 2D Perlin, mNoise
//! and wavelet noise summed over a grid, point by point and through the batch API, for the page
//! to time against the npm `simplex-noise` package in the same Chromium.
//!
//! It is a module of its own so that the demo's (`bandnoise-wasm`) carries none of it: the batch
//! kernels and the three point loops are about 46 KB of wasm.

use bandnoise::Noise;
use bandnoise::batch::Grid;
use bandnoise::lattice::{MNoise, Perlin};
use bandnoise::wavelet::{TILE2_I16, Wavelet};
use wasm_bindgen::prelude::*;

/// The batch half of [`bench_sum`]: rows of 256 samples by `fill_grid`.
fn bench_rows<N: Noise<f32, 2>>(noise: &N, count: u32) -> f64 {
    let mut acc = 0.0f64;
    let mut row = [0.0f32; BENCH_SIDE as usize];
    for r in 0..count.div_ceil(BENCH_SIDE) {
        let y = (r % BENCH_SIDE) as f32 * BENCH_STEP;
        let grid = Grid::new([0.0, y], [BENCH_STEP, 0.0], [BENCH_SIDE as usize, 1]);
        if noise.fill_grid(&grid, &mut row).is_ok() {
            acc += row.iter().map(|&v| v as f64).sum::<f64>();
        }
    }
    acc
}

const BENCH_SIDE: u32 = 256;
const BENCH_STEP: f32 = 0.0625;

/// Sums `count` samples of a 2D noise over a 256² grid, 1/16 of a cell apart (for the browser
/// benchmark; the sum keeps the work from being optimised away). `kind`: `perlin`, `mnoise` or
/// `wavelet` (one band), sampled point by point, or `perlin-batch` and `mnoise-batch`, filled a
/// row of 256 at a time by `fill_grid`. Both give the same values.
///
/// # Errors
///
/// A message for an unknown kind.
#[wasm_bindgen]
pub fn bench_sum(kind: &str, count: u32) -> Result<f64, JsValue> {
    let points = |f: &dyn Fn([f32; 2]) -> f32| -> f64 {
        let mut acc = 0.0f64;
        for k in 0..count {
            let (i, j) = (k % BENCH_SIDE, k / BENCH_SIDE % BENCH_SIDE);
            acc += f([i as f32 * BENCH_STEP, j as f32 * BENCH_STEP]) as f64;
        }
        acc
    };
    let perlin = Perlin::new(0);
    let mnoise = MNoise::<61>::new(0);
    match kind {
        "perlin" => Ok(points(&|p| perlin.sample(p))),
        "mnoise" => Ok(points(&|p| mnoise.sample(p))),
        "wavelet" => {
            let wavelet = Wavelet::new(0, &TILE2_I16);
            Ok(points(&|p| wavelet.sample(p)))
        }
        "perlin-batch" => Ok(bench_rows(&perlin, count)),
        "mnoise-batch" => Ok(bench_rows(&mnoise, count)),
        _ => Err(JsValue::from_str(&format!(
            "unknown benchmark kind \"{kind}\""
        ))),
    }
}

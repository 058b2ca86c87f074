//! Target-specific code, in one place: each kernel here has a portable fallback, and `cfg`
//! picks one implementation per target at compile time (the pattern of libm's
//! `select_implementation`). The noise modules call these functions unconditionally; where a
//! target has no kernel the fallback declines and the portable code runs, so no other module
//! names a target.
//!
//! | kernel | targets | fallback |
//! |---|---|---|
//! | [`perlin2`], [`perlin3`], [`perlin4`]: Perlin's improved noise at one point in `f32` | x86-64 (SSE2, part of the architecture); wasm32 with `simd128` and without the `small` feature: one kernel ([`vector`]) over each target's 4-lane vector | `None`: the shared kernel of [`lattice`](crate::lattice) |
//! | [`sqrt_lanes`]: [`Real::sqrt`](crate::Real::sqrt) of 16 `f32` lanes (Wiener noise's batches) | x86-64 (SSE2 `sqrtps`), wasm32 as above (`f32x4.sqrt`), four lanes at a time | one lane at a time |
//! | [`simplex_corners`]: simplex noise's corners over a batch's 16 `f32` lanes, 2D and 3D | x86-64 (SSE2: the hashes' 32-bit products by `pmuludq`, the gradients' signed offsets by masks) | `false`: the portable body, which the compiler vectorises |
//! | [`cellular_near`]: cellular noise's point split and 3ᴰ near cells in `f32`, 2D and 3D, as lanes in near order | x86-64 (SSE2: the split by `split_lanes`' rounding, hashes and draws by `pmuludq`, the least key by `minps` and `movmskps`) | `None`: the portable body |
//! | [`OCTAVES_AS_LANES`]: whether [`MixedTurbulence`](crate::lattice::MixedTurbulence) interpolates its octaves as lanes of one lattice body | x86-64 (`true`: vectorised) | `false`: octave by octave |
//!
//! Every kernel computes the portable kernel's operations on the same numbers in the same order,
//! so the choice changes speed only, never a bit of a result (each kernel's tests compare them).
//! There is no run-time feature detection: the build's target features decide, so the kernels
//! stay within the crate's `forbid` lint (intrinsics come through `safe_arch` on x86-64 and
//! `core::arch::wasm32`'s safe functions in WebAssembly).

#[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
mod x86_64;
#[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
use x86_64 as selected;

// `bandnoise_vector` (build.rs): x86-64 with SSE2, or wasm32 with simd128 and without `small`.
#[cfg(all(target_arch = "wasm32", bandnoise_vector))]
mod wasm32;
#[cfg(all(target_arch = "wasm32", bandnoise_vector))]
use wasm32 as selected;

#[cfg(bandnoise_vector)]
mod vector;
#[cfg(bandnoise_vector)]
use vector as perlin_point;

#[cfg(not(bandnoise_vector))]
mod portable;
#[cfg(not(bandnoise_vector))]
use portable as perlin_point;
#[cfg(not(bandnoise_vector))]
use portable as selected;

// The kernels, each with the same signature in every implementation:
//
// * `PERLIN_POINT`: whether this target has the Perlin point kernels (a constant, so callers
//   skip the `f32` conversions where it has not).
// * `perlin2(p, x, y)`, `perlin3(p, x, y, z)`, `perlin4(p, x, y, z, w)`: Perlin's improved noise at one point over the
//   doubled permutation `p` (`p[i + 256] = p[i]`), bit-identical to the shared kernel; `None`
//   where the target has no kernel or leaves the point to the shared one (non-finite or beyond
//   ±2³¹).
// * `PerlinPairs`: a seed's table for the point kernels, built by `const fn` from the doubled
//   permutation (32 KiB where there is a kernel, empty where there is none), and
//   `perlin2_paired`, `perlin3_paired`, `perlin4_paired`: the kernels reading it, one
//   dependent lookup fewer (and in 4D no permutation lookup at the last level).
// * `OCTAVES_AS_LANES`: whether a sum of octaves is faster as one lattice body over the octaves
//   as lanes (vector units) than as one body per octave (scalar cores, where the lanes' values
//   spill to the stack). Either gives the same bits.
// * `sqrt_lanes(x)`: `Real::sqrt` of each lane (`√x` for `x > 0`, else 0), in place. IEEE
//   square roots are correctly rounded, so a vector instruction gives libm's bits.
pub(crate) use perlin_point::{
    PERLIN_POINT, PerlinPairs, perlin2, perlin2_paired, perlin3, perlin3_paired, perlin4,
    perlin4_paired,
};
// * `SIMPLEX_CORNERS`: whether this target has `simplex_corners` (so callers skip the
//   conversions where it has not).
// * `simplex_corners(k, value)`: simplex noise's corners (`simplex::corners` with Perlin's
//   gradients) over 16 `f32` lanes from their skewed cells and fractions, bit-identical to the
//   portable body; `false` where the target has no kernel or not for this dimension.
pub(crate) use selected::{OCTAVES_AS_LANES, SIMPLEX_CORNERS, simplex_corners, sqrt_lanes};
// * `SIMPLEX_POINT`: whether this target has `simplex_point`.
// * `simplex_point(cell, offset, k)`: simplex noise (Perlin's gradients) at one `f32` point in
//   3D from its skewed cell and fractions, its corners as lanes, bit-identical to the
//   portable body; `None` where the target has no kernel or not for this dimension.
pub(crate) use selected::{SIMPLEX_POINT, simplex_point};
// * `CELLULAR_NEAR`: whether this target has `cellular_near`.
// * `cellular_near(p, k, out)`: cellular noise's point split and its 3ᴰ near cells
//   (`Cellular::near_whole`) in `f32`, 2D and 3D, in near order as lanes, and the nearest and
//   second-nearest of them, bit-identical to the portable body; the point's cell and
//   fraction, or `None` where the target has no kernel or a coordinate is not within ±2²².
pub(crate) use selected::{CELLULAR_NEAR, cellular_near};
// * `split_point(p)` (tests only): the kernel's split as arrays, `None` where there is none.
#[cfg(test)]
pub(crate) use selected::split_point;

/// The lanes of [`cellular_near`]: the 3ᴰ cells around a point's in near order (the
/// cellular module's), padded to 28 (`unit`: each axis's offset times 1 in 16.16; `prime`:
/// times the axis's hash prime, wrapping).
pub(crate) struct NearLanes {
    /// `kₐ·2¹⁶` for each axis and lane.
    pub(crate) unit: [[i32; 28]; 3],
    /// `kₐ·Pₐ` (wrapping) for each axis and lane.
    pub(crate) prime: [[i32; 28]; 3],
}

/// What [`cellular_near`] takes besides the point: the hash's start, the jitter (16.16), the
/// metric, and the lanes' offsets.
#[cfg_attr(
    not(all(target_arch = "x86_64", target_feature = "sse2")),
    allow(
        dead_code,
        reason = "only the x86-64 kernel reads it; the others decline"
    )
)]
pub(crate) struct CellularCells<'a> {
    /// The cell hash's start (the mixed seed).
    pub(crate) start: u32,
    /// The jitter in 16.16 units.
    pub(crate) jitter: i32,
    /// Whether each axis's key is its square (the Euclidean metrics) rather than its magnitude.
    pub(crate) squares: bool,
    /// Whether the axes' keys combine by maximum (Chebyshev) rather than by sum.
    pub(crate) chebyshev: bool,
    /// Whether the second-nearest is sought too.
    pub(crate) second: bool,
    /// The cells' offsets as lanes.
    pub(crate) lanes: &'a NearLanes,
}

/// What [`cellular_near`] gives: the nearest cell's (and, where asked, the second
/// nearest's) key and point's offsets from the sample, and the nearest cell's hash.
pub(crate) struct NearPair {
    /// The keys, nearest first.
    pub(crate) key: [f32; 2],
    /// The offsets (the first `D` axes), nearest first.
    pub(crate) q: [[f32; 3]; 2],
    /// The nearest cell's hash.
    pub(crate) hash: u32,
}

/// What [`simplex_corners`] takes besides the output: the lanes' skewed cells and fractions,
/// and the body's constants in `f32` (computed by the portable code).
#[cfg_attr(
    not(all(target_arch = "x86_64", target_feature = "sse2")),
    allow(
        dead_code,
        reason = "only the x86-64 kernel reads the lanes; the others decline"
    )
)]
pub(crate) struct SimplexLanes<'a, const D: usize> {
    /// Each axis's skewed cell, lane by lane.
    pub(crate) cell: &'a [[i32; crate::batch::LANES]; D],
    /// Each axis's fraction in the skewed cell.
    pub(crate) offset: &'a [[f32; crate::batch::LANES]; D],
    /// The body's constants.
    pub(crate) constants: SimplexConstants,
}

/// The constants of [`simplex_corners`] and [`simplex_point`] for one dimension and seed, in
/// `f32` (computed by the portable code).
#[cfg_attr(
    not(all(target_arch = "x86_64", target_feature = "sse2")),
    allow(
        dead_code,
        reason = "only the x86-64 kernel reads the constants; the others decline"
    )
)]
pub(crate) struct SimplexConstants {
    /// The corner hash's start (the mixed seed).
    pub(crate) start: u32,
    /// The unskew `G`.
    pub(crate) unskew: f32,
    /// `j·G` for the corners `j = 0 … D` (0 beyond).
    pub(crate) diagonal: [f32; 5],
    /// The scale that makes the largest value 1.
    pub(crate) scale: f32,
}

#[cfg(test)]
mod tests {
    extern crate std;
    use crate::Real;
    use crate::batch::LANES;
    use std::vec;

    /// [`super::split_point`] is `Real::split` of each coordinate bit for bit where it
    /// answers, and answers (on x86-64) for every point within ±2²²: edge cases (zeros,
    /// integers, values just below integers whose fraction rounds to 1, the range's ends,
    /// NaN, infinities) and a million points of random bits and of random values in range.
    #[test]
    fn split_point_is_the_scalar_split() {
        let edges = [
            0.0f32,
            -0.0,
            1.0,
            -1.0,
            -1e-10,
            -1e-30,
            1e-45,
            0.999_999_94,
            -0.999_999_94,
            4_194_303.5,
            -4_194_303.5,
            4_194_304.0,
            -4_194_304.0,
            8_388_607.0,
            f32::NAN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            -2.5,
            7.25,
        ];
        let mut next = crate::testing::xorshift32(0x9E37_79B9);
        fn check<const D: usize>(p: [f32; D]) {
            let within = p.iter().all(|x| x.abs() < 4_194_304.0);
            match super::split_point(p) {
                Some((cell, frac)) => {
                    assert!(within, "{p:?}");
                    for a in 0..D {
                        let (c, f) = Real::split(p[a]);
                        assert_eq!((cell[a], frac[a].to_bits()), (c, f.to_bits()), "{p:?}");
                    }
                }
                None => assert!(
                    !within || cfg!(not(all(target_arch = "x86_64", target_feature = "sse2"))),
                    "{p:?}"
                ),
            }
        }
        for &x in &edges {
            for &y in &edges {
                check([x, y]);
                check([y, x, 0.5]);
                check([x]);
                check([0.25, x, y, -3.0]);
            }
        }
        for i in 0..1_000_000 {
            let bits = f32::from_bits(next());
            let value = (next() as i32) as f32 / (1u32 << (next() % 24)) as f32;
            let x = if i % 2 == 0 { bits } else { value };
            let y = (next() as i32 >> (next() % 31)) as f32 * 0.37;
            check([x, y]);
            check([y, x, value]);
        }
    }

    /// [`super::sqrt_lanes`] is `Real::sqrt` bit for bit: edge cases (zeros, negatives, NaN,
    /// infinities, subnormals, the largest value) and a million values spread over every
    /// binade.
    #[test]
    fn sqrt_lanes_is_the_scalar_sqrt() {
        let edges = [
            0.0f32,
            -0.0,
            -1.0,
            f32::NAN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::MIN_POSITIVE,
            1e-45,
            f32::MAX,
            1.0,
            0.25,
            2.0,
            3.0,
            0.999_999_9,
            1e-30,
            1e30,
        ];
        let mut next = crate::testing::xorshift32(0x2545_F491);
        let mut batches = vec![edges];
        for _ in 0..65_536 {
            batches.push(core::array::from_fn(|_| f32::from_bits(next())));
        }
        for x in batches {
            let mut lanes: [f32; LANES] = x;
            super::sqrt_lanes(&mut lanes);
            for (got, v) in lanes.iter().zip(x) {
                assert_eq!(got.to_bits(), Real::sqrt(v).to_bits(), "{v:e}");
            }
        }
    }
}

//! Target-specific code, in one place: each kernel here has a portable fallback, and `cfg`
//! picks one implementation per target at compile time (the pattern of libm's
//! `select_implementation`). The noise modules call these functions unconditionally; where a
//! target has no kernel the fallback declines and the portable code runs, so no other module
//! names a target.
//!
//! | kernel | targets | fallback |
//! |---|---|---|
//! | [`perlin2`], [`perlin3`], [`perlin4`]: Perlin's improved noise at one point in `f32` | x86-64 (SSE2, part of the architecture) | `None`: the shared kernel of [`lattice`](crate::lattice) |
//!
//! Every kernel computes the portable kernel's operations on the same numbers in the same order,
//! so the choice changes speed only, never a bit of a result (each kernel's tests compare them).
//! There is no run-time feature detection: the build's target features decide, so the kernels
//! stay within the crate's `forbid` lint (intrinsics come through `safe_arch`).

#[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
mod x86_64;
#[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
use x86_64 as selected;

#[cfg(not(all(target_arch = "x86_64", target_feature = "sse2")))]
mod portable;
#[cfg(not(all(target_arch = "x86_64", target_feature = "sse2")))]
use portable as selected;

// The kernels of the selected implementation, each with the same signature in every one:
//
// * `PERLIN_POINT`: whether this target has the Perlin point kernels (a constant, so callers
//   skip the `f32` conversions where it has not).
// * `perlin2(p, x, y)`, `perlin3(p, x, y, z)`, `perlin4(p, x, y, z, w)`: Perlin's improved noise at one point over the
//   doubled permutation `p` (`p[i + 256] = p[i]`), bit-identical to the shared kernel; `None`
//   where the target has no kernel or leaves the point to the shared one (non-finite or beyond
//   ±2³¹).
// * `PerlinPairs`: a seed's table for the point kernels, built by `const fn` from the doubled
//   permutation (16 KiB on x86-64, empty where no kernel uses it), and `perlin2_paired`,
//   `perlin3_paired`: the kernels reading it, one dependent lookup fewer.
pub(crate) use selected::{
    PERLIN_POINT, PerlinPairs, perlin2, perlin2_paired, perlin3, perlin3_paired, perlin4,
};

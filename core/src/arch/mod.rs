//! Target-specific code, in one place: each kernel here has a portable fallback, and `cfg`
//! picks one implementation per target at compile time (the pattern of libm's
//! `select_implementation`). The noise modules call these functions unconditionally; where a
//! target has no kernel the fallback declines and the portable code runs, so no other module
//! names a target.
//!
//! | kernel | targets | fallback |
//! |---|---|---|
//! | [`perlin2`], [`perlin3`]: Perlin's improved noise at one point in `f32` | x86-64 (SSE2, part of the architecture) | `None`: the shared kernel of [`lattice`](crate::lattice) |
//!
//! Every kernel computes the portable kernel's operations on the same numbers in the same order,
//! so the choice changes speed only, never a bit of a result (each kernel's tests compare them).
//! There is no run-time feature detection: the build's target features decide, so a kernel
//! needs no `unsafe`.

#[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
mod x86_64;
#[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
use x86_64 as selected;

#[cfg(not(all(target_arch = "x86_64", target_feature = "sse2")))]
mod portable;
#[cfg(not(all(target_arch = "x86_64", target_feature = "sse2")))]
use portable as selected;

/// Whether this target has the Perlin point kernels ([`perlin2`], [`perlin3`]): a constant, so
/// callers can skip the `f32` conversions where it has not.
pub(crate) const PERLIN_POINT: bool = selected::PERLIN_POINT;

/// Perlin's improved noise at `(x, y)` over the doubled permutation `p` (`p[i + 256] = p[i]`),
/// bit-identical to the shared kernel; `None` where this target has no kernel or the kernel
/// leaves the point to the shared one (non-finite or beyond ±2³¹).
#[inline]
pub(crate) fn perlin2(p: &[u8; 512], x: f32, y: f32) -> Option<f32> {
    selected::perlin2(p, x, y)
}

/// [`perlin2`] in 3D.
#[inline]
pub(crate) fn perlin3(p: &[u8; 512], x: f32, y: f32, z: f32) -> Option<f32> {
    selected::perlin3(p, x, y, z)
}

/// A seed's table for the Perlin point kernels ([`perlin2_paired`], [`perlin3_paired`]), built
/// by `const fn` from the doubled permutation: 16 KiB on x86-64, empty where no kernel uses it.
pub(crate) use selected::PerlinPairs;

/// [`perlin2`] with the seed's table of gradient pairs: one dependent lookup fewer.
#[inline]
pub(crate) fn perlin2_paired(p: &[u8; 512], pairs: &PerlinPairs, x: f32, y: f32) -> Option<f32> {
    selected::perlin2_paired(p, pairs, x, y)
}

/// [`perlin3`] with the seed's table of gradient pairs.
#[inline]
pub(crate) fn perlin3_paired(
    p: &[u8; 512],
    pairs: &PerlinPairs,
    x: f32,
    y: f32,
    z: f32,
) -> Option<f32> {
    selected::perlin3_paired(p, pairs, x, y, z)
}

//! The fallbacks of [`arch`](super) for targets without a kernel: each declines, so the portable
//! code runs.

pub(crate) const PERLIN_POINT: bool = false;

/// Scalar cores: a short lattice body per octave keeps its values in registers.
pub(crate) const OCTAVES_AS_LANES: bool = false;

#[inline]
pub(crate) fn perlin2(_: &[u8; 512], _: f32, _: f32) -> Option<f32> {
    None
}

#[inline]
pub(crate) fn perlin3(_: &[u8; 512], _: f32, _: f32, _: f32) -> Option<f32> {
    None
}

#[inline]
pub(crate) fn perlin4(_: &[u8; 512], _: f32, _: f32, _: f32, _: f32) -> Option<f32> {
    None
}

/// No kernel uses a seed's gradient pairs here: an empty table.
#[derive(Clone)]
pub(crate) struct PerlinPairs;

impl PerlinPairs {
    pub(crate) const fn new(_: &[u8; 512]) -> Self {
        Self
    }
}

#[inline]
pub(crate) fn perlin2_paired(_: &[u8; 512], _: &PerlinPairs, _: f32, _: f32) -> Option<f32> {
    None
}

#[inline]
pub(crate) fn perlin3_paired(
    _: &[u8; 512],
    _: &PerlinPairs,
    _: f32,
    _: f32,
    _: f32,
) -> Option<f32> {
    None
}

#[inline]
pub(crate) fn perlin4_paired(
    _: &[u8; 512],
    _: &PerlinPairs,
    _: f32,
    _: f32,
    _: f32,
    _: f32,
) -> Option<f32> {
    None
}

/// [`Real::sqrt`](crate::Real::sqrt) of each lane, one at a time.
#[inline]
pub(crate) fn sqrt_lanes(x: &mut [f32; crate::batch::LANES]) {
    for v in x.iter_mut() {
        *v = crate::Real::sqrt(*v);
    }
}

/// No simplex corner kernel: the portable body runs.
pub(crate) const SIMPLEX_CORNERS: bool = false;

#[inline]
pub(crate) fn simplex_corners<const D: usize>(
    _: &super::SimplexLanes<'_, D>,
    _: &mut [f32; crate::batch::LANES],
) -> bool {
    false
}

/// No simplex point kernel: the portable body runs.
pub(crate) const SIMPLEX_POINT: bool = false;

#[inline]
pub(crate) fn simplex_point<const D: usize>(
    _: [i32; D],
    _: [f32; D],
    _: &super::SimplexConstants,
) -> Option<f32> {
    None
}

/// No cellular near-cell kernel: the portable body runs.
pub(crate) const CELLULAR_NEAR: bool = false;

#[inline]
pub(crate) fn cellular_near<const D: usize>(
    _: [f32; D],
    _: &super::CellularCells<'_>,
    _: &mut super::NearPair,
) -> Option<([i32; D], [f32; D])> {
    None
}

/// No vector split (its test's entry point).
#[cfg(test)]
pub(crate) fn split_point<const D: usize>(_: [f32; D]) -> Option<([i32; D], [f32; D])> {
    None
}

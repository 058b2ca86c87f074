//! Wavelet noise (Cook & DeRose 2005, "Wavelet Noise"): noise bands that are almost perfectly
//! band-limited, built from tiles of B-spline coefficients generated at compile time.
//!
//! Perlin noise leaks energy below its band and, sliced from 3D, is not band-limited at all, so
//! a shader must choose between aliasing and missing detail. A wavelet band is the part of random
//! B-spline coefficients that the half-resolution space cannot represent (§3), so its bands are
//! orthogonal to coarser ones, and projecting 3D noise onto a surface keeps that (§3.7).
//!
//! | item | paper | file |
//! |---|---|---|
//! | [`Tile2`], [`Tile3`]: `const fn` tile generation | §3.4, §4.3, App. 1 | `tile.rs` |
//! | [`QuantizedTile2`], [`QuantizedTile3`]: `i16` tiles | | `quantized.rs` |
//! | [`TILE2`], [`TILE3`], [`TILE2_I16`], [`TILE3_I16`]: the default tiles | | `defaults.rs` |
//! | [`Wavelet`]: one band, 2D or 3D, tile orientations | §3.6, §4.3, App. 2 | `band.rs` |
//! | [`Wavelet`] as a [`ProjectedNoise`](crate::ProjectedNoise): 3D → 2D | §3.7, §4.1 eqs. 35–36, App. 2 | `projected.rs` |
//! | [`Multiband`], [`Bands`]: `Σ w_b N(2^b x)`, variance 1, Gaussian or uniform | eq. 1, §4.2 | `multiband.rs` |
//! | [`erf`] | §4.2 | `erf.rs` |
//!
//! # Measured (see `tests/tests/wavelet.rs` and `tests/benches/wavelet.rs`)
//!
//! * Band variance averaged over 24 tiles: 2D 0.270 (paper 0.265), projected 0.294 (paper
//!   0.296), 3D 0.1955 (paper 0.210, which is the figure of the odd 65³ tile that the printed
//!   Appendix 1 code builds for a requested 64³, erratum 1: a transcription of it gives 0.210,
//!   and 0.196 with an even tile). Means below 0.001.
//! * Power below half the band's lower edge (256² samples, FFT): one 2D band 0.002%, Perlin at
//!   the same scale 2.9%. A plane through 3D noise: sliced 4.1%, projected 0.6%, Perlin 15%.
//! * Varied tiling: no jump across block borders (≤ 4e-6 over 2e-6); the borders raise the
//!   variance by 2–3% and leak 1.2% of the power below the band with a 16² tile.
//! * Quantized tiles: shift 12, error ≤ 1.2e-4. I16F16 against f32: ≤ 3.3e-4.
//! * Cost: a 32³ tile adds 6.7 s of compile time (16³: 0.8 s; 64² 2D: 0.5 s;
//!   `scripts/measure-tiles.sh`). ns/sample on this machine (criterion, 2026-11-22):
//!   Perlin 3D 29; wavelet 2D 26; wavelet 3D 63 (81 where every sample straddles a tile-block
//!   border, 55 with periodic tiling); projected 990 (axis-aligned normal) and 2300 (oblique).
//!   Cook & DeRose measured one 3D band 30% faster than RenderMan's Perlin noise; here 2D is 10%
//!   faster than 3D Perlin and 3D is 2.2× slower: 27 coefficient loads from a 128 KiB tile and
//!   the orientation hash cost more than Perlin's 8 gradients from a 256-byte table.

mod band;
mod constmath;
mod defaults;
mod erf;
mod multiband;
mod projected;
mod quantized;
mod tile;

pub use band::{TileData, Tiling, Wavelet};
pub use defaults::{DEFAULT_TILE_SEED, TILE2, TILE2_I16, TILE3, TILE3_I16};
pub use erf::erf;
pub use multiband::{
    Bands, Distribution, MAX_BANDS, Multiband, TileVariance, VARIANCE_2D, VARIANCE_3D,
    VARIANCE_PROJECTED,
};
pub use projected::unit_normal;
pub use quantized::{QuantizedTile2, QuantizedTile3};
pub use tile::{MAX_TILE, Tile2, Tile3};

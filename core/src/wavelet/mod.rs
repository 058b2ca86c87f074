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
//! | [`Wavelet`] as a [`ProjectedNoise`](crate::ProjectedNoise) and [`ProjectedNoiseGradient`](crate::ProjectedNoiseGradient): 3D → 2D | §3.7, §4.1 eqs. 35–36, App. 2 | `projected.rs` |
//! | [`Multiband`], [`Bands`]: `Σ w_b N(2^b x)`, variance 1, Gaussian or uniform | eq. 1, §4.2 | `multiband.rs` |
//! | [`Wavelet`], [`Multiband`] as [`FilteredNoise`](crate::FilteredNoise): bands averaged over a footprint | §3.1, §4.1, §6 | `filtered.rs` |
//! | [`Multiband::sample_infinite`]: band weights relative to the footprint | §5.4 | `multiband.rs` |
//! | [`erf`] | §4.2 | `erf.rs` |
//!
//! # Properties (tested in `tests/tests/wavelet.rs`)
//!
//! * Band variance averaged over 24 tiles: 2D 0.270 (paper 0.265), projected 0.294 (paper
//!   0.296), 3D 0.1955 (paper 0.210, which is the figure of the odd 65³ tile that the printed
//!   Appendix 1 code builds for a requested 64³, erratum 1: a transcription of it gives 0.210,
//!   and 0.196 with an even tile). Means below 0.001.
//! * Power below half the band's lower edge (256² samples, FFT, [`Tiling::Periodic`]): one 2D
//!   band 0.002%, Perlin at the same scale 2.9%. A plane through 3D noise: sliced 4.1%,
//!   projected 0.6%, Perlin 15%.
//! * [`Tiling::Blended`], the default, against the others (`tests/tests/seams.rs`, the table
//!   in [`Tiling`]), for one 2D band: power below half the lower edge 0.005–0.006% (`Varied`
//!   0.27–0.47%), at the tile's harmonics 0.44–0.50% (0.39% if nothing repeats; `Varied`
//!   10–14%), variance near block borders within ±2.3% (`Varied` up to +63%). Band variance
//!   within 1% of the tile's.
//! * [`Tiling::Varied`]: no jump across block borders (≤ 4e-6 over 2e-6); the borders raise the
//!   variance by 2–3% and leak 1.2% of the power below the band with a 16² tile.
//! * Multiband noise with the default tiling, 10⁶ samples each: variance 2D and 3D within 1%
//!   of 1, projected within 1% of 1 along an axis, oblique and random normals (each normal's
//!   own [`projected_gain`]; `tests/tests/projected_variance.rs`).
//! * Filtered by the pixel's footprint, one sample per pixel of 10-band noise is 100–250×
//!   closer (mean squared error) to a 16×16-supersampled box-filtered image than a plain
//!   sample, for flat, 1/f and halving band weights (`tests/tests/filtering.rs`).
//! * Infinite noise along a zoom over 2¹⁰: variance within 3.1% of 1 at every level; at 60
//!   frames per octave, a point changes less between frames than neighbouring pixels differ.
//! * Quantized tiles: shift 12, error ≤ 1.2e-4. I16F16 against f32: ≤ 3.3e-4.
//!
//! # Cost
//!
//! A tile is computed when the crate that names it compiles: a few seconds for a 32³ tile,
//! well under one for 16³ or 64² (`scripts/measure-tiles.sh`). A 3D band reads 27
//! coefficients from a tile of up to 128 KiB and hashes its block's orientation, so it costs
//! more than Perlin's 8 gradients from a 256-byte table: Cook & DeRose measured one 3D band
//! 30% faster than RenderMan's Perlin noise. Here, with [`Tiling::Varied`] and the sample's
//! coefficients in one block, 2D is about as fast as 3D Perlin and 3D about twice as slow; the
//! default [`Tiling::Blended`] reads both blocks around a border in its blend zone (8 of
//! every 64 coefficients per axis in 2D, 8 of 32 in 3D), so a sample whose coefficients reach
//! a zone costs several times more. A band projected along an axis costs about twice a 3D
//! band, as Cook & DeRose found projection to ("approximately doubles the cost", §5.2); along
//! an oblique normal, whose basis is not a product of per-axis B-splines, about 7 times. In
//! fixed point on the quantized tiles a band is summed in 32-bit integer arithmetic (the
//! same bits as through I16F16's operations; `band/fixed.rs`): on a Cortex-M0, which has no
//! long multiply, a 2D band with the default tiling takes about 2.8 times the instructions of
//! fixed-point 2D Perlin noise. Figures per machine and tiling are in `bench/README.md`.

mod band;
#[cfg(test)]
mod compact;
pub(crate) mod constmath;
mod defaults;
mod erf;
mod filtered;
mod multiband;
pub(crate) use multiband::DEFAULT_BANDS;
mod projected;
mod quantized;
mod tile;
mod window;

pub use band::{TileData, Tiling, Wavelet};
pub use defaults::{DEFAULT_TILE_SEED, TILE2, TILE2_I16, TILE3, TILE3_I16};
pub use erf::erf;
pub use multiband::{
    Bands, Distribution, MAX_BANDS, Multiband, TileVariance, VARIANCE_2D, VARIANCE_3D,
    VARIANCE_PROJECTED,
};
pub use projected::{projected_gain, unit_normal};
pub use quantized::{QuantizedTile2, QuantizedTile3};
pub use tile::{MAX_TILE, Tile2, Tile3};

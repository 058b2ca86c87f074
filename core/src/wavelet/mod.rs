//! Wavelet noise (Cook & DeRose 2005, "Wavelet Noise"): noise bands that are almost perfectly
//! band-limited, built from tiles of B-spline coefficients generated at compile time.

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

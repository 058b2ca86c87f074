//! The tiles bandnoise ships, computed at compile time into `static`s (flash on firmware).
//!
//! | tile | coefficients | bytes | why this size |
//! |---|---|---|---|
//! | [`TILE2`] | 64 × 64 `f32` | 16 KiB | 2D tiles are cheap; 64² gives a stable variance (4096 coefficients) and, with hashed orientations, no visible repeat |
//! | [`TILE3`] | 32 × 32 × 32 `f32` | 128 KiB | the largest 3D tile whose compile time (a few seconds, `scripts/measure-tiles.sh`) and size suit a desktop or web build; the paper used 128³ (8 MiB) |
//! | [`TILE2_I16`] | 64 × 64 `i16` | 8 KiB | [`TILE2`] quantized, for firmware |
//! | [`TILE3_I16`] | 32 × 32 × 32 `i16` | 64 KiB | [`TILE3`] quantized, for firmware with the flash for it |
//!
//! A linker keeps only the tiles a program uses. Firmware short of flash can generate a smaller
//! tile itself: `static T: QuantizedTile3<16> = QuantizedTile3::quantize(&Tile3::generate(1));`
//! is 8 KiB.

use super::quantized::{QuantizedTile2, QuantizedTile3};
use super::tile::{Tile2, Tile3};

/// The seed of the default tiles.
pub const DEFAULT_TILE_SEED: u32 = 2005;

const T2: Tile2<64> = Tile2::generate(DEFAULT_TILE_SEED);
const T3: Tile3<32> = Tile3::generate(DEFAULT_TILE_SEED);

/// The default 2D tile: 64², `f32`.
pub static TILE2: Tile2<64> = T2;
/// The default 3D tile: 32³, `f32`.
pub static TILE3: Tile3<32> = T3;
/// [`TILE2`] quantized to `i16`.
pub static TILE2_I16: QuantizedTile2<64> = QuantizedTile2::quantize(&T2);
/// [`TILE3`] quantized to `i16`.
pub static TILE3_I16: QuantizedTile3<32> = QuantizedTile3::quantize(&T3);

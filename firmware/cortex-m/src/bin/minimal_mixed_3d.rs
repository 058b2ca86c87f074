//! `empty` plus one call of fixed-point 3D mNoise from Olano's table (`MixedMNoise`): what it
//! adds to a firmware, table included (beside `minimal-mnoise-3d`, the same noise computed).
#![no_std]
#![no_main]

type Noise3 = bandnoise::lattice::MixedMNoise;

include!("../minimal_3d_body.rs");

//! `empty` plus one call of fixed-point 3D mNoise from Olano's table (`MixedMNoise`): what it
//! adds to a firmware, table included (beside `minimal-mnoise-3d`, the same noise computed).
#![no_std]
#![no_main]

use bandnoise::lattice::MixedMNoise;
use bandnoise::{I16F16, Noise};

fn sample() -> I16F16 {
    MixedMNoise::new(core::hint::black_box(3)).sample(point::<3>())
}

include!("../minimal_body.rs");

//! `empty` plus one call of fixed-point 3D mNoise, computed: what it adds to a firmware (beside
//! `minimal-mixed-3d`, the same noise from Olano's table).
#![no_std]
#![no_main]

use bandnoise::lattice::MNoise;
use bandnoise::{I16F16, Noise};

fn sample() -> I16F16 {
    MNoise::<61>::new(core::hint::black_box(3)).sample(point::<3>())
}

include!("../minimal_body.rs");

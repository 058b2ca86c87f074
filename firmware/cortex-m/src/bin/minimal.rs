//! `empty` plus one call of fixed-point 2D mNoise: what the noise adds to a firmware.
#![no_std]
#![no_main]

use bandnoise::lattice::MNoise;
use bandnoise::{I16F16, Noise};

fn sample() -> I16F16 {
    MNoise::<61>::new(core::hint::black_box(3)).sample(point::<2>())
}

include!("../minimal_body.rs");

//! `empty` plus one call of fixed-point 2D Perlin noise (improved noise, its 256-byte
//! permutation included): what the noise adds to a firmware.
#![no_std]
#![no_main]

use bandnoise::lattice::Perlin;
use bandnoise::{I16F16, Noise};

fn sample() -> I16F16 {
    Perlin::new(core::hint::black_box(3)).sample(point::<2>())
}

include!("../minimal_body.rs");

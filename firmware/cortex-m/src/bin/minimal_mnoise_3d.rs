//! `empty` plus one call of fixed-point 3D mNoise, computed: what it adds to a firmware (beside
//! `minimal-mixed-3d`, the same noise from Olano's table).
#![no_std]
#![no_main]

type Noise3 = bandnoise::lattice::MNoise<61>;

include!("../minimal_3d_body.rs");

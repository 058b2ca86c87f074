//! Lattice hashes: integer cell coordinates to pseudo-random integers.
//!
//! * [`Bbs`]: Olano's Blum-Blum-Shub hash `x² mod M` (Olano 2005, §3.3), computable without
//!   tables, in integers or exactly in `f32`.
//! * [`Permutation`]: Ken Perlin's 2002 permutation of `0..256` (pbrt §10.6.1's `NoisePerm`),
//!   reshuffled for other seeds.
//! * [`CellHash`]: a well-mixed 32-bit hash of an integer cell, for noises that need more than
//!   8 bits per cell; [`CellRng`] and [`Poisson`]: a cell's own random numbers, exact dyadic
//!   uniforms and capped Poisson counts.
//!
//! Both are *chained* over the axes of a lattice point. The chain order is part of each noise's
//! definition and is documented there; the chains themselves (one cell, the corners of a cube,
//! periodic wraps) are one crate-internal seam, `chain.rs`, that every lattice noise uses.

mod bbs;
pub(crate) mod cell;
pub(crate) mod chain;
mod perm;
pub(crate) mod prime;
pub(crate) mod rng;
pub(crate) mod seed;

pub use bbs::Bbs;
pub use cell::CellHash;
pub(crate) use cell::mix;
pub use perm::{PERLIN_2002, Permutation};
pub use rng::{CellRng, Poisson};

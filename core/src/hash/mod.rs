//! Lattice hashes: integer cell coordinates to pseudo-random integers.
//!
//! * [`Bbs`]: Olano's Blum-Blum-Shub hash `x² mod M` (Olano 2005, §3.3), computable without
//!   tables, in integers or exactly in `f32`.
//! * [`Permutation`]: Ken Perlin's 2002 permutation of `0..256` (pbrt §10.6.1's `NoisePerm`),
//!   reshuffled for other seeds.
//!
//! Both are *chained* over the axes of a lattice point. The chain order is part of each noise's
//! definition and is documented there.

mod bbs;
mod perm;
pub(crate) mod seed;

pub use bbs::Bbs;
pub use perm::{PERLIN_2002, Permutation};

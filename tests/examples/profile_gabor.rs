//! Runs 2D Gabor noise (the defaults: anisotropic, 16 impulses per kernel) over the peer
//! benchmark's off-lattice grid for a profiler:
//! `valgrind --tool=callgrind --branch-sim=yes target/release/examples/profile_gabor [isotropic]`.
use bandnoise::Noise;
use bandnoise::impulse::{Gabor, Orientation};
fn main() {
    let isotropic = std::env::args().any(|a| a == "isotropic");
    let mut noise = Gabor::<2>::new(0);
    if isotropic {
        noise = noise.with_orientation(Orientation::Isotropic);
    }
    let mut acc = 0.0f32;
    let rows: usize = std::env::args()
        .nth(2)
        .and_then(|r| r.parse().ok())
        .unwrap_or(16);
    for j in 0..rows {
        for i in 0..1024 {
            acc += noise.sample(std::hint::black_box([
                3.217 + i as f32 * 0.0737,
                -5.683 + j as f32 * 0.0737,
            ]));
        }
    }
    println!("{acc}");
}

//! Runs 3D wavelet noise for a profiler: `valgrind --tool=callgrind target/release/examples/profile_wavelet`.
use bandnoise::Noise;
use bandnoise::wavelet::{TILE3, Wavelet};
fn main() {
    let w = Wavelet::new(0, &TILE3);
    let mut acc = 0.0f32;
    for j in 0..64 {
        for i in 0..1024 {
            acc += w.sample(std::hint::black_box([
                i as f32 / 16.0,
                j as f32 / 16.0,
                0.37,
            ]));
        }
    }
    println!("{acc}");
}

//! Runs 2D Gabor noise's batch path (`fill_grid`, the defaults) over the peer benchmark's
//! off-lattice grid for a profiler:
//! `valgrind --tool=callgrind --branch-sim=yes target/release/examples/profile_gabor_batch`.
use bandnoise::Noise;
use bandnoise::batch::Grid;
use bandnoise::impulse::Gabor;
fn main() {
    let noise = Gabor::<2>::new(0);
    let grid = Grid::new([3.217f32, -5.683], [0.0737, 0.0737], [1024, 16]);
    let mut out = vec![0.0f32; grid.len()];
    noise.fill_grid(&grid, &mut out).unwrap();
    println!("{}", out.iter().sum::<f32>());
}

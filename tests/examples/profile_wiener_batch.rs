//! Runs 3D Wiener noise's batch path (`fill_grid`, the low-pass default) over the peer
//! benchmark's off-lattice grid (the plane z = 0.37) for a profiler:
//! `valgrind --tool=callgrind target/release/examples/profile_wiener_batch`.
use bandnoise::Noise;
use bandnoise::batch::Grid;
use bandnoise::wiener::WienerNoise;
fn main() {
    let noise = WienerNoise::<3>::new(0);
    let grid = Grid::new(
        [3.217f32, -5.683, 0.37],
        [0.0737, 0.0737, 0.0],
        [1024, 16, 1],
    );
    let mut out = vec![0.0f32; grid.len()];
    if std::env::args().any(|a| a == "point") {
        for (i, o) in out.iter_mut().enumerate() {
            *o = noise.sample(grid.point([i % 1024, i / 1024, 0]));
        }
    } else {
        noise.fill_grid(&grid, &mut out).unwrap();
    }
    println!("{}", out.iter().sum::<f32>());
}

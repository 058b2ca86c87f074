//! What sparse convolution noise costs at each density, so a user can choose, what Wiener
//! noise costs with each covariance, and what Gabor noise costs in each variant and density
//! (Tavernier et al.'s fixed counts beside the Poisson form): ns per sample
//! (point, `f32`) on the off-lattice grid of the peer benchmark, and the ratio to bandnoise's
//! Perlin noise of the same dimension measured in the same rounds (each round times Perlin
//! and every configuration one after the other over the same rows, milliseconds apart; the
//! table gives medians over rounds, so a change of the machine's load moves both).
//!
//! `cargo bench -p bandnoise-bench --bench impulse`; under `cargo test` (or with `-- --test`)
//! each configuration runs once on one row and nothing is printed. Results in `bench/README.md`.

use bandnoise::Noise;
use bandnoise::impulse::{Envelope, Gabor, Kernel, Orientation, SparseConvolution, Weights};
use bandnoise::lattice::Perlin;
use bandnoise::wiener::{Covariance, WienerNoise};
use bandnoise_bench::{LAYOUTS, N, Run, measuring, quantile, seconds};

/// Rounds of the paired measurement.
const ROUNDS: usize = 21;
/// Grid rows each configuration fills in a round.
const ROWS: usize = 8;

/// The configurations of `D` dimensions: name and workload.
fn configurations<const D: usize>() -> Vec<(String, Run)>
where
    SparseConvolution<D>: Noise<f32, D>,
    WienerNoise<D>: Noise<f32, D>,
    Gabor<D>: Noise<f32, D>,
    Perlin: Noise<f32, D>,
{
    let layout = LAYOUTS[1];
    let mut all: Vec<(String, Run)> =
        vec![(format!("perlin-{D}d"), layout.point::<_, D>(Perlin::new(0)))];
    let base = || SparseConvolution::<D>::new(0);
    for density in [1.0, 3.0, 10.0, 30.0] {
        let noise = base().with_density(density).expect("a valid density");
        all.push((
            format!("sparse-{D}d cosine, {density} per kernel"),
            layout.point::<_, D>(noise),
        ));
    }
    let uniform = base().with_weights(Weights::Uniform);
    all.push((
        format!("sparse-{D}d cosine, 10 per kernel, uniform weights"),
        layout.point::<_, D>(uniform),
    ));
    let peachey = base().with_kernel(Kernel::CatmullRom);
    all.push((
        format!("sparse-{D}d Catmull-Rom, 10 per kernel"),
        layout.point::<_, D>(peachey),
    ));
    for per_cell in [1, 3] {
        let noise = base().with_fixed_count(per_cell).expect("a valid count");
        let density = noise.density();
        all.push((
            format!("sparse-{D}d cosine, {per_cell} per cell fixed ({density:.1} per kernel)"),
            layout.point::<_, D>(noise),
        ));
    }
    // The batch path (`fill_grid`): each chunk's cells' impulses generated once.
    all.push((
        format!("sparse-{D}d cosine, 10 per kernel, batch"),
        layout.batch::<_, D>(base()),
    ));
    let three = base().with_fixed_count(3).expect("a valid count");
    all.push((
        format!("sparse-{D}d cosine, 3 per cell fixed, batch"),
        layout.batch::<_, D>(three),
    ));
    for covariance in [Covariance::LowPass, Covariance::BandPass] {
        let noise = WienerNoise::<D>::new(0).with_covariance(covariance);
        all.push((
            format!("wiener-{D}d {covariance:?}"),
            layout.point::<_, D>(noise.clone()),
        ));
        all.push((
            format!("wiener-{D}d {covariance:?}, batch"),
            layout.batch::<_, D>(noise),
        ));
    }
    let gabor = || Gabor::<D>::new(0);
    for density in [4.0, 16.0, 64.0] {
        let noise = gabor().with_density(density).expect("a valid density");
        all.push((
            format!("gabor-{D}d anisotropic, {density} per kernel"),
            layout.point::<_, D>(noise),
        ));
    }
    for orientation in [Orientation::Isotropic, Orientation::Hybrid] {
        all.push((
            format!("gabor-{D}d {orientation:?}, 16 per kernel"),
            layout.point::<_, D>(gabor().with_orientation(orientation)),
        ));
    }
    all.push((
        format!("gabor-{D}d anisotropic, truncated, 16 per kernel"),
        layout.point::<_, D>(gabor().with_envelope(Envelope::Truncated)),
    ));
    // Tavernier et al. 2019's fast normalised process: the fixed count nearest 16 per kernel.
    let pi = core::f32::consts::PI;
    let per_cell = (16.0 / if D == 2 { pi } else { 4.0 / 3.0 * pi }) as u32 + 1;
    let fixed = gabor().with_fixed_count(per_cell).expect("a valid count");
    let density = fixed.density();
    all.push((
        format!("gabor-{D}d anisotropic, {per_cell} per cell fixed ({density:.1} per kernel)"),
        layout.point::<_, D>(fixed),
    ));
    all.push((
        format!("gabor-{D}d anisotropic, 16 per kernel, batch"),
        layout.batch::<_, D>(gabor()),
    ));
    all
}

fn measure(configs: &[(String, Run)], test: bool) {
    let mut out = vec![0.0f32; N * ROWS];
    if test {
        for (_, run) in configs {
            run(1, &mut out);
        }
        return;
    }
    let mut ns = vec![Vec::new(); configs.len()];
    let mut ratio = vec![Vec::new(); configs.len()];
    // One round unmeasured, to warm caches and branch predictors.
    for round in 0..=ROUNDS {
        let times: Vec<f64> = configs
            .iter()
            .map(|(_, run)| seconds(run, ROWS, &mut out))
            .collect();
        if round > 0 {
            for (i, t) in times.iter().enumerate() {
                ns[i].push(t * 1e9 / (N * ROWS) as f64);
                ratio[i].push(t / times[0]);
            }
        }
    }
    for (i, (name, _)) in configs.iter().enumerate() {
        let r = &mut ratio[i];
        let (q1, m, q3) = (quantile(r, 0.25), quantile(r, 0.5), quantile(r, 0.75));
        println!(
            "| {name} | {:.1} | {m:.1} [{q1:.1}–{q3:.1}] |",
            quantile(&mut ns[i], 0.5)
        );
    }
}

fn main() {
    let test = !measuring();
    if !test {
        println!(
            "point f32, off-lattice grid (step {}, origin {:?}); median [quartiles] of {ROUNDS} paired rounds of {ROWS} rows",
            LAYOUTS[1].step, LAYOUTS[1].origin
        );
        println!("| noise | ns/sample | × Perlin of the same dimension |");
        println!("|---|---|---|");
    }
    measure(&configurations::<2>(), test);
    measure(&configurations::<3>(), test);
}

//! Proof that sampling cannot panic: this program evaluates every noise (all lattice noises in
//! 1D–4D, mNoise from Olano's table and its turbulence, simplex, OpenSimplex2 and OpenSimplex2S, flow noise and its fBm, white and cubic value noise 1D–4D, curl noise, domain warping, the
//! textures and their colours, fractal sums, wavelet bands,
//! projected and multiband noise, sparse, Wiener and Gabor noise, batches, integer outputs
//! (`levels`), and the public helpers `from_ratio`, `unit_normal`, `erf`, `exp_neg` and
//! `cos_turns`) in I16F16 and f32 on inputs the optimiser cannot see (`nopanic-spec` proves the
//! runtime descriptions and `nopanic-text` their text form), and its panic handler calls a
//! function that does not exist. If any panic path survives optimisation, the link fails.
//! Built, not run (release, thumbv7em).
#![no_std]
#![no_main]

use core::hint::black_box;
use core::panic::PanicInfo;

use bandnoise::batch::Grid;
use bandnoise::cellular::{Cellular, Metric, Output};
use bandnoise::fractal::{Fractal, Kind, Octaves};
use bandnoise::hash::{CellHash, CellRng, Poisson};
use bandnoise::impulse::{Envelope, Gabor, Kernel, Orientation, SparseConvolution};
use bandnoise::lattice::{
    CNoise, CubicValueNoise, MNoise, MixedMNoise, MixedTurbulence, OriginalPerlin, Periodic,
    Perlin, TabledPerlin, ValueNoise, WhiteNoise,
};
use bandnoise::levels::Levels;
use bandnoise::simplex::{Flow, FlowSum, Improve, OpenSimplex2, OpenSimplex2S, Simplex};
use bandnoise::texture::{Marble, PolkaDots, Texture, Windy, Wood, Wrinkled};
use bandnoise::vector::{Components, Curl2, Curl3, VectorNoise, Warp};
use bandnoise::wavelet::{
    Bands, Distribution, Multiband, TILE2_I16, TILE3_I16, Tiling, Wavelet, erf, unit_normal,
};
use bandnoise::wiener::{Covariance, WienerNoise};
use bandnoise::{
    FilteredNoise, I16F16, Noise, NoiseGradient, ProjectedNoise, ProjectedNoiseGradient, Real,
};
use cortex_m as _;
use cortex_m_rt::entry;

unsafe extern "C" {
    /// Deliberately undefined: referenced only if a panic is reachable.
    fn bandnoise_sampling_can_panic() -> !;
}

fn lattice<R: Real>(acc: &mut u32, p: [R; 4]) {
    let mut add = |v: R| *acc = acc.wrapping_add(v.to_f32().to_bits());
    macro_rules! all_dims {
        ($n:expr) => {{
            let n = black_box($n);
            add(n.sample([p[0]]));
            add(n.sample([p[0], p[1]]));
            add(n.sample([p[0], p[1], p[2]]));
            add(n.sample(p));
        }};
    }
    all_dims!(Perlin::new(black_box(1)));
    all_dims!(TabledPerlin::new(black_box(1)));
    all_dims!(OriginalPerlin::new(black_box(1)));
    all_dims!(ValueNoise::new(black_box(1)));
    all_dims!(CNoise::new(black_box(1)));
    all_dims!(MNoise::<61>::new(black_box(1)));
    all_dims!(MixedMNoise::new(black_box(1)));
    all_dims!(MixedTurbulence::<4>::new(black_box(1)));
    add(MixedTurbulence::<3>::new(2).sample_with_gradient(p).1[3]);
    all_dims!(Simplex::new(black_box(1)));
    add(Simplex::new(2).sample_with_gradient(p).1[3]);
    // Any seed and orientation (the optimiser cannot tell which).
    let improve = [Improve::Standard, Improve::XY, Improve::XZ][black_box(2usize) % 3];
    all_dims!(OpenSimplex2::new(black_box(-1)).improving(improve));
    all_dims!(OpenSimplex2S::new(black_box(-1)).improving(improve));
    add(OpenSimplex2::new(2)
        .improving(improve)
        .sample_with_gradient(p)
        .1[3]);
    add(OpenSimplex2S::new(2)
        .improving(improve)
        .sample_with_gradient(p)
        .1[3]);
    if let Ok(flow) = Flow::new(black_box(1)).with_angle(black_box(0.3)) {
        add(flow.sample([p[0], p[1]]));
        add(flow.sample_with_gradient([p[0], p[1]]).1[1]);
        if let Ok(o) = Octaves::new(black_box(5), black_box(1.9), black_box(0.6)) {
            let sum = FlowSum::new(flow, o).with_advection(black_box(0.7));
            if let Ok(sum) = sum.and_then(|s| s.with_spin(black_box(1.5))) {
                add(sum.sample([p[0], p[1]]));
            }
        }
    }
    // Every output and metric (the optimiser cannot tell which), and any jitter.
    let cellular = Cellular::new(black_box(1))
        .with_output(black_box(Output::F2MinusF1))
        .with_metric(black_box(Metric::Chebyshev));
    if let Ok(c) = cellular.with_jitter(black_box(0.5)) {
        all_dims!(c);
        add(c.sample_with_gradient([p[0], p[1], p[2]]).1[2]);
    }
    // Either distribution (the optimiser cannot tell which).
    let distribution = black_box(Distribution::Gaussian);
    all_dims!(WhiteNoise::new(black_box(1)).with_distribution(distribution));
    let cubic = CubicValueNoise::new(black_box(1)).with_distribution(distribution);
    all_dims!(cubic);
    add(cubic.sample_with_gradient(p).1[3]);
    add(Curl2::new(Simplex::new(black_box(2))).sample_vector([p[0], p[1]])[1]);
    let flow = Curl3::new(Perlin::new(black_box(1)), Simplex::new(2), CNoise::new(3));
    add(flow.sample_vector([p[0], p[1], p[2]])[2]);
    let field = Components::new([Simplex::new(black_box(4)), Simplex::new(5), Simplex::new(6)]);
    if let Ok(warp) = Warp::new(Perlin::new(black_box(1)), field, black_box(3.5)) {
        add(warp.sample([p[0], p[1], p[2]]));
        add(warp.sample_with_gradient([p[0], p[1], p[2]]).1[1]);
        add(warp.displace([p[0], p[1], p[2]])[0]);
    }
    all_dims!(Windy::new(black_box(1)));
    all_dims!(Wrinkled::new(black_box(1)));
    all_dims!(Marble::new(black_box(1)));
    all_dims!(Marble::olano(black_box(1)));
    all_dims!(Wood::olano(black_box(1)));
    if let Ok(wood) = Wood::with_noise(Perlin::new(black_box(1)), black_box(3.0), black_box(0.2)) {
        all_dims!(wood.clone());
        wood.color([p[0], p[1], p[2]]).iter().for_each(|&c| add(c));
    }
    if let Ok(dots) = PolkaDots::new(black_box(1)).with_radius(black_box(0.3)) {
        all_dims!(dots.clone());
        add(R::from_i32(i32::from(dots.color_rgb8([p[0], p[1]])[2])));
        add(dots.sample_filtered([p[0], p[1]], [p[2], p[3]], [p[3], p[1]]));
    }
    add(Marble::new(2).color(p)[1]);
    add(Windy::new(2).sample_filtered([p[0], p[1]], [p[2], p[3]], [p[3], p[2]]));
    add(Perlin::new(2).sample_with_gradient([p[0], p[1], p[2]]).0);
    add(MNoise::<61>::new(2).sample_with_gradient([p[0], p[1]]).1[1]);
    let kind = black_box(Kind::Ridged);
    if let Ok(o) = Octaves::new(black_box(6), black_box(1.99), black_box(0.5)) {
        let f = Fractal::new(Perlin::new(3), o, kind);
        add(f.sample([p[0], p[1], p[2]]));
        add(f.sample_filtered([p[0], p[1]], [p[2], p[3]], [p[3], p[2]]));
        add(f.sample_with_gradient([p[0], p[1], p[2]]).1[2]);
    }
    // Every tiling: the optimiser cannot tell which.
    let tiling = black_box(Tiling::Blended);
    add(Wavelet::new(4, &TILE2_I16)
        .with_tiling(tiling)
        .sample([p[0], p[1]]));
    let w3 = Wavelet::new(4, &TILE3_I16).with_tiling(tiling);
    add(w3.sample([p[0], p[1], p[2]]));
    add(w3.sample_projected([p[0], p[1], p[2]], [p[3], p[2], p[1]]));
    add(w3.sample_with_gradient([p[0], p[1], p[2]]).1[1]);
    add(w3
        .sample_projected_with_gradient([p[0], p[1], p[2]], [p[2], p[3], p[0]])
        .1[2]);
    add(w3.sample_filtered([p[0], p[1], p[2]], [p[3], p[1], p[0]], [p[2], p[3], p[3]]));
    add(ValueNoise::new(2).sample_with_gradient([p[0], p[3]]).1[0]);
    if let Ok(b) = Bands::new(black_box(-2), black_box(&[0.5f32, 1.0, 0.25][..])) {
        let m =
            Multiband::new(5, &TILE3_I16, b, black_box(Distribution::Uniform)).with_tiling(tiling);
        add(m.sample([p[0], p[1], p[2]]));
        add(m.sample_projected([p[0], p[1], p[2]], [p[1], p[0], p[3]]));
        add(m.sample_with_gradient([p[0], p[1], p[2]]).1[0]);
        add(m
            .sample_projected_with_gradient([p[0], p[1], p[2]], [p[3], p[1], p[0]])
            .1[1]);
        add(m.sample_filtered([p[0], p[1], p[2]], [p[3], p[0], p[1]], [p[1], p[2], p[3]]));
        add(m.sample_infinite([p[0], p[1], p[2]], p[3]));
        // Grid rows of a band and of multiband noise (`band/row.rs`: the column cache).
        let grid3 = Grid::new(
            [p[0], p[1], p[2]],
            [p[3], p[2], p[1]],
            black_box([10, 3, 2]),
        );
        let mut out = [R::ZERO; 60];
        if w3.fill_grid(&grid3, &mut out).is_ok() {
            add(out.get(black_box(23)).copied().unwrap_or(R::ZERO));
        }
        if m.fill_grid(&grid3, &mut out).is_ok() {
            add(out.get(black_box(41)).copied().unwrap_or(R::ZERO));
        }
        // A projected grid along an axis (`projected/rows.rs`: lanes in groups) and not.
        for normal in [[R::ZERO, R::ZERO, p[3]], [p[3], p[2], p[1]]] {
            if w3.fill_grid_projected(&grid3, normal, &mut out).is_ok() {
                add(out.get(black_box(17)).copied().unwrap_or(R::ZERO));
            }
            if m.fill_grid_projected(&grid3, normal, &mut out).is_ok() {
                add(out.get(black_box(29)).copied().unwrap_or(R::ZERO));
            }
        }
    }
    // Periodic noise (a gradient lattice and value noise), the cell hash and generator.
    let period = black_box([7u32, 65536, 1]);
    if let Ok(n) = Periodic::new(Perlin::new(6), period) {
        add(n.sample([p[0], p[1], p[2]]));
        add(n.sample_with_gradient([p[0], p[1], p[2]]).1[0]);
    }
    if let Ok(n) = Periodic::new(ValueNoise::new(6), [period[0], period[1]]) {
        add(n.sample([p[3], p[2]]));
    }
    let hash = CellHash::new(black_box(9));
    let mut rng = CellRng::new(&hash, black_box([1, -5, 3]));
    add(rng.uniform::<R>());
    add(rng.signed_uniform::<R>());
    if let Ok(poisson) = Poisson::new(black_box(2.5)) {
        add(R::from_i32(rng.poisson(&poisson) as i32));
    }
    // Integer outputs of any value, through a range the optimiser cannot see.
    if let Ok(levels) = Levels::new(black_box(-0.7), black_box(0.9)) {
        add(R::from_i32(
            i32::from(levels.u16(p[0])) + i32::from(levels.i16(p[1])),
        ));
        add(R::from_i32(i32::from(levels.u8(p[2]))));
    }
    // The public helpers: every shift, any normal, any erf, exp and cos argument.
    add(R::from_ratio(black_box(-7), black_box(u32::MAX)));
    add(unit_normal([p[3], p[0], p[1]])[0]);
    add(erf(p[2]));
    add(p[1].exp_neg());
    add(p[0].cos_turns());
    // Batches: a grid and points, through every lane kernel of a lattice noise and a fractal.
    let grid = Grid::new([p[0], p[1]], [p[2], p[3]], black_box([20, 3]));
    let mut out = [R::ZERO; 60];
    if Perlin::new(5).fill_grid(&grid, &mut out).is_ok() {
        add(out.get(black_box(17)).copied().unwrap_or(R::ZERO));
    }
    let w2 = Wavelet::new(3, &TILE2_I16).with_tiling(black_box(Tiling::Blended));
    if w2.fill_grid(&grid, &mut out).is_ok() {
        add(out.get(black_box(19)).copied().unwrap_or(R::ZERO));
    }
    // Sparse convolution noise in batches (the shared walk of a chunk's cells), with any
    // density and fixed count.
    let sparse = SparseConvolution::<2>::new(black_box(4)).with_kernel(Kernel::CatmullRom);
    if let Ok(n) = sparse.clone().with_density(black_box(7.5)) {
        if n.fill_grid(&grid, &mut out).is_ok() {
            add(out.get(black_box(31)).copied().unwrap_or(R::ZERO));
        }
    }
    if let Ok(n) = sparse.with_fixed_count(black_box(3)) {
        add(n.sample_with_gradient([p[1], p[2]]).1[1]);
    }
    // Wiener noise with either covariance (the choice hidden from the optimiser): sample,
    // gradient and a grid.
    let covariance = if black_box(true) {
        Covariance::BandPass
    } else {
        Covariance::LowPass
    };
    let wiener = WienerNoise::<3>::new(black_box(6)).with_covariance(covariance);
    add(wiener.sample([p[0], p[1], p[2]]));
    add(wiener.sample_with_gradient([p[3], p[1], p[2]]).1[2]);
    if WienerNoise::<2>::new(black_box(6))
        .with_covariance(covariance)
        .fill_grid(&grid, &mut out)
        .is_ok()
    {
        add(out.get(black_box(9)).copied().unwrap_or(R::ZERO));
    }
    // Gabor noise with any variant and envelope (hidden from the optimiser), settings from
    // inputs it cannot see: sample, gradient and a grid (the shared walk's per-impulse draws).
    let orientation = black_box(Orientation::Isotropic);
    let envelope = black_box(Envelope::Truncated);
    let gabor = Gabor::<3>::new(black_box(8))
        .with_orientation(orientation)
        .with_envelope(envelope);
    if let Ok(g) = gabor.with_spectrum(black_box(3.0), black_box(0.7)) {
        add(g.sample([p[0], p[1], p[2]]));
        add(g.sample_with_gradient([p[3], p[1], p[2]]).1[2]);
        add(g.sample_projected([p[0], p[1], p[2]], [p[3], p[2], p[0]]));
    }
    let gabor = Gabor::<2>::new(black_box(8)).with_orientation(orientation);
    if let Ok(g) = gabor.with_direction([p[0].to_f32(), p[1].to_f32()]) {
        if g.fill_grid(&grid, &mut out).is_ok() {
            add(out.get(black_box(11)).copied().unwrap_or(R::ZERO));
        }
        add(g.sample_filtered([p[0], p[1]], [p[2], p[3]], [p[3], p[1]]));
    }
    if let Ok(g) = Gabor::<1>::new(black_box(2)).with_fixed_count(black_box(4)) {
        add(g.sample([p[2]]));
    }
    let xs = black_box([p[0]; 20]);
    let ys = black_box([p[3]; 20]);
    if let Ok(o) = Octaves::new(black_box(3), black_box(2.0), black_box(0.5)) {
        let f = Fractal::new(MNoise::<61>::new(3), o, black_box(Kind::Fbm));
        if f.fill_points([&xs[..], &ys[..]], &mut out[..20]).is_ok() {
            add(out.get(black_box(19)).copied().unwrap_or(R::ZERO));
        }
    }
}

#[entry]
fn main() -> ! {
    let mut acc = 0u32;
    let bits: [i32; 4] = black_box([1, -2, 3, i32::MIN]);
    lattice::<I16F16>(&mut acc, bits.map(I16F16::from_bits));
    lattice::<f32>(&mut acc, bits.map(|b| f32::from_bits(b as u32)));
    black_box(acc);
    loop {}
}

#[panic_handler]
fn panic(_: &PanicInfo) -> ! {
    // SAFETY: never called when the link succeeds: that is what this program proves.
    unsafe { bandnoise_sampling_can_panic() }
}

//! 4D Perlin noise by bandnoise (`Perlin` and `TabledPerlin`) and the 4D peers over the peer
//! benchmark's grids tilted out of the plane `(z, w) = (Z, W)` (`z = Z + 0.29·x + 0.53·y`,
//! `w = W + 0.41·x − 0.37·y`), so that every sample has its own `z` and `w`:
//! `tilted [ROUNDS]` prints, per layout, each implementation's median ns per sample and each
//! bandnoise type's paired ratio to the fastest peer (median and quartiles over `ROUNDS`
//! interleaved rounds of 32 rows, 101 if left out).
//!
//! On the benchmark's own plane a peer whose hash is a sum of per-axis terms (noise-functions)
//! has the constant `z` and `w` terms hoisted out of its loop, once the compiler has inlined its
//! sample into the loop; this grid shows each implementation's cost per sample without that.
//! A binary of its own: as a row of `workload` (the library), the peer's second call site made
//! the compiler stop inlining its plane row, which then took twice its time.

use bandnoise::Noise;
use bandnoise::lattice::{Perlin, TabledPerlin};
use bandnoise_bench::{LAYOUTS, Layout, N, Run, W, Z, quantile, seconds};
use noise::NoiseFn;
use noise_functions::Noise as _;

/// Grid rows each implementation fills in a round.
const ROWS: usize = 32;

/// How many of the runs are bandnoise's (the first ones); the rest are the peers.
const OURS: usize = 2;

/// The point `(x, y)` of a grid row, tilted out of the plane.
fn tilted(x: f32, y: f32) -> [f32; 4] {
    [x, y, Z + 0.29 * x + 0.53 * y, W + 0.41 * x - 0.37 * y]
}

/// `f` at every tilted point of `rows` rows of `layout`'s grid (instantiated in this binary,
/// so the library's own rows keep their call sites).
fn run(layout: Layout, f: impl Fn([f32; 4]) -> f32 + 'static) -> Run {
    Box::new(move |rows, out| layout.points(rows, out, |x, y| f(tilted(x, y))))
}

fn main() {
    let rounds = match std::env::args().nth(1).map(|a| a.parse::<usize>()) {
        None => 101,
        Some(Ok(n)) if n > 0 => n,
        Some(_) => {
            eprintln!("usage: tilted [ROUNDS]");
            std::process::exit(2);
        }
    };
    let mut out = vec![0.0f32; N * N];
    for layout in LAYOUTS {
        let perlin = Perlin::new(0);
        let tabled = Box::new(TabledPerlin::new(0));
        let noise = noise::Perlin::new(0);
        let libnoise = libnoise::Source::<4>::perlin(0);
        let runs: [(&str, Run); 3 + OURS] = [
            ("bandnoise", run(layout, move |p| perlin.sample(p))),
            ("bandnoise tabled", run(layout, move |p| tabled.sample(p))),
            (
                "noise",
                run(layout, move |p| noise.get(p.map(f64::from)) as f32),
            ),
            (
                "noise-functions",
                run(layout, |p| noise_functions::Perlin.sample4(p)),
            ),
            (
                "libnoise",
                run(layout, move |p| {
                    libnoise::Generator::sample(&libnoise, p.map(f64::from)) as f32
                }),
            ),
        ];
        let mut times = vec![Vec::new(); runs.len()];
        let mut ratios = [(); OURS].map(|()| Vec::new());
        // One round unmeasured, to warm caches and branch predictors.
        for round in 0..=rounds {
            let t: Vec<f64> = runs
                .iter()
                .map(|(_, run)| seconds(run, ROWS, &mut out))
                .collect();
            if round > 0 {
                let fastest_peer = t[OURS..].iter().copied().fold(f64::INFINITY, f64::min);
                for (ratios, t) in ratios.iter_mut().zip(&t) {
                    ratios.push(t / fastest_peer);
                }
                for (times, t) in times.iter_mut().zip(&t) {
                    times.push(t * 1e9 / (ROWS * N) as f64);
                }
            }
        }
        let ns: Vec<String> = runs
            .iter()
            .zip(&mut times)
            .map(|((name, _), t)| format!("{name} {:.2}", quantile(t, 0.5)))
            .collect();
        let ratios: Vec<String> = runs
            .iter()
            .zip(&mut ratios)
            .map(|((name, _), r)| {
                let (q1, m, q3) = (quantile(r, 0.25), quantile(r, 0.5), quantile(r, 0.75));
                format!("{name} {m:.2} [{q1:.2}–{q3:.2}]")
            })
            .collect();
        println!(
            "perlin-4d tilted, layout {}: ns/sample {}; ratio to the fastest peer: {}",
            layout.name,
            ns.join(", "),
            ratios.join(", ")
        );
    }
}

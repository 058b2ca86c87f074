//! Times one workload of the peer benchmark for A/B comparisons of two builds:
//! `timeit FUNCTION IMPLEMENTATION [LAYOUT] [ROWS]` fills `ROWS` rows (32 if left out) of the
//! 1024-wide grid (`LAYOUT` one of the names of `LAYOUTS`, `off-lattice` if left out) 41 times
//! into one buffer and prints the least and the median nanoseconds per sample of the last 40.
//!
//! The buffer is written once before timing: a process that fills a fresh buffer (the
//! `callgrind` binary) pays a page fault per 4 KiB of output, about a tenth of a Perlin
//! sample's time, which dilutes every before/after ratio. Run two builds' copies in
//! alternation (`bench/README.md`, "Measuring a change").

use bandnoise_bench::{LAYOUTS, N, layout, workload};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let usage = "usage: timeit FUNCTION IMPLEMENTATION [LAYOUT] [ROWS]";
    let (Some(function), Some(implementation)) = (args.get(1), args.get(2)) else {
        eprintln!("{usage}");
        std::process::exit(2);
    };
    let Some(layout) = layout(args.get(3).map_or("off-lattice", String::as_str)) else {
        let names: Vec<&str> = LAYOUTS.iter().map(|l| l.name).collect();
        eprintln!("{usage}: LAYOUT is one of {names:?}");
        std::process::exit(2);
    };
    let Ok(rows) = args.get(4).map_or(Ok(32), |r| r.parse::<usize>()) else {
        eprintln!("{usage}: ROWS must be a number");
        std::process::exit(2);
    };
    let Some(run) = workload(function, implementation, layout) else {
        eprintln!("no workload {function} for {implementation}");
        std::process::exit(2);
    };
    let rows = rows.clamp(1, N);
    let mut out = vec![1.0f32; N * N];
    run(rows, &mut out); // warm-up: caches, predictors, the buffer's pages
    let mut ns: Vec<f64> = (0..40)
        .map(|_| {
            let start = std::time::Instant::now();
            run(rows, &mut out);
            start.elapsed().as_secs_f64() * 1e9 / (rows * N) as f64
        })
        .collect();
    ns.sort_by(f64::total_cmp);
    // Use the result so nothing is optimised away.
    let sum: f64 = out[..rows * N].iter().map(|&v| f64::from(v)).sum();
    println!("{:.3} {:.3} {sum}", ns[0], ns[ns.len() / 2]);
}

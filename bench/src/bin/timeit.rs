//! Times one workload of the peer benchmark for A/B comparisons of two builds:
//! `timeit FUNCTION IMPLEMENTATION [ROWS] [LAYOUT]` (the `callgrind` binary's arguments) fills
//! `ROWS` rows (32 if left out) of the 1024-wide grid (`LAYOUT` one of the names of `LAYOUTS`,
//! `off-lattice` if left out) 41 times into one buffer and prints the least and the median
//! nanoseconds per sample of the last 40.
//!
//! The buffer is written once before timing: a process that fills a fresh buffer (the
//! `callgrind` binary) pays a page fault per 4 KiB of output, about a tenth of a Perlin
//! sample's time, which dilutes every before/after ratio. Run two builds' copies in
//! alternation (`bench/README.md`, "Measuring a change").

use bandnoise_bench::{N, command_line};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let usage = "usage: timeit FUNCTION IMPLEMENTATION [ROWS] [LAYOUT]";
    let (run, rows) =
        command_line(usage, &args, Some(32), "off-lattice").unwrap_or_else(|message| {
            eprintln!("{message}");
            std::process::exit(2);
        });
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

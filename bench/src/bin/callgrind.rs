//! Runs one workload of the peer benchmark for `callgrind` instruction counts:
//! `callgrind FUNCTION IMPLEMENTATION ROWS [LAYOUT]` fills `ROWS` rows of the 1024-wide grid
//! (`LAYOUT` one of the names of `LAYOUTS`, `sixteenth` if left out).
//! `scripts/bench-peers.sh` runs it at two row counts and divides the difference by the extra
//! samples, so start-up work cancels out.

use bandnoise_bench::{N, command_line};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let usage = "usage: callgrind FUNCTION IMPLEMENTATION ROWS [LAYOUT]";
    let (run, rows) = command_line(usage, &args, None, "sixteenth").unwrap_or_else(|message| {
        eprintln!("{message}");
        std::process::exit(2);
    });
    let mut out = vec![0.0f32; N * N];
    run(rows, &mut out);
    // Use the result so nothing is optimised away.
    let sum: f64 = out.iter().map(|&v| f64::from(v)).sum();
    println!("{sum}");
}

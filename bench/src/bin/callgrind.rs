//! Runs one workload of the peer benchmark for `callgrind` instruction counts:
//! `callgrind FUNCTION IMPLEMENTATION ROWS [LAYOUT]` fills `ROWS` rows of the 1024-wide grid
//! (`LAYOUT` one of the names of `LAYOUTS`, `sixteenth` if left out).
//! `scripts/bench-peers.sh` runs it at two row counts and divides the difference by the extra
//! samples, so start-up work cancels out.

use bandnoise_bench::{LAYOUTS, N, layout, workload};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let usage = "usage: callgrind FUNCTION IMPLEMENTATION ROWS [LAYOUT]";
    let (Some(function), Some(implementation), Some(rows)) =
        (args.get(1), args.get(2), args.get(3))
    else {
        eprintln!("{usage}");
        std::process::exit(2);
    };
    let Ok(rows) = rows.parse::<usize>() else {
        eprintln!("{usage}: ROWS must be a number");
        std::process::exit(2);
    };
    let Some(layout) = args.get(4).map_or(Some(LAYOUTS[0]), |name| layout(name)) else {
        let names: Vec<&str> = LAYOUTS.iter().map(|l| l.name).collect();
        eprintln!("{usage}: LAYOUT is one of {names:?}");
        std::process::exit(2);
    };
    let Some(run) = workload(function, implementation, layout) else {
        eprintln!("no workload {function} for {implementation}");
        std::process::exit(2);
    };
    let rows = rows.min(N);
    let mut out = vec![0.0f32; N * N];
    run(rows, &mut out);
    // Use the result so nothing is optimised away.
    let sum: f64 = out.iter().map(|&v| v as f64).sum();
    println!("{sum}");
}

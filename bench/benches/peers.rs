//! bandnoise against the peer crates, in one run: ns/sample over the same 1024² grid for every
//! workload of `bandnoise_bench`, then a table of each ratio to the fastest peer.
//!
//! `cargo bench -p bandnoise-bench --bench peers` (or `scripts/bench-peers.sh`, which also
//! counts instructions with callgrind). With `-- --test` each workload runs once, unmeasured,
//! and no table is printed.

use std::path::PathBuf;
use std::time::Duration;

use bandnoise_bench::{FUNCTIONS, IMPLEMENTATIONS, N, peer_function, workload};
use criterion::{Criterion, Throughput};

fn peers(c: &mut Criterion) {
    let mut out = vec![0.0f32; N * N];
    for function in FUNCTIONS {
        let mut g = c.benchmark_group(format!("peers-{function}"));
        g.throughput(Throughput::Elements((N * N) as u64));
        g.sample_size(10);
        g.warm_up_time(Duration::from_secs(1));
        g.measurement_time(Duration::from_secs(3));
        for implementation in IMPLEMENTATIONS {
            if let Some(run) = workload(function, implementation) {
                g.bench_function(implementation, |b| {
                    b.iter(|| {
                        run(N, &mut out);
                        std::hint::black_box(&out);
                    })
                });
            }
        }
        g.finish();
    }
}

/// Where criterion writes its estimates (its own rule: `CRITERION_HOME`, else
/// `$CARGO_TARGET_DIR/criterion`, else `target/criterion` beside this executable).
fn criterion_dir() -> PathBuf {
    if let Some(home) = std::env::var_os("CRITERION_HOME") {
        return home.into();
    }
    if let Some(target) = std::env::var_os("CARGO_TARGET_DIR") {
        return PathBuf::from(target).join("criterion");
    }
    let exe = std::env::current_exe().expect("the benchmark knows its path");
    // target/<profile>/deps/peers-<hash>
    exe.ancestors()
        .nth(3)
        .expect("inside target/")
        .join("criterion")
}

/// The mean time per grid from criterion's `estimates.json`, in ns per sample.
fn ns_per_sample(function: &str, implementation: &str) -> Option<f64> {
    let path = criterion_dir()
        .join(format!("peers-{function}"))
        .join(implementation)
        .join("new/estimates.json");
    let json = std::fs::read_to_string(path).ok()?;
    let mean = &json[json.find("\"mean\"")?..];
    let value = &mean[mean.find("\"point_estimate\":")? + "\"point_estimate\":".len()..];
    let end = value.find([',', '}'])?;
    Some(value[..end].trim().parse::<f64>().ok()? / (N * N) as f64)
}

fn table() {
    println!("\nns/sample over a {N}x{N} grid; ratio = bandnoise / fastest peer (lower is better)");
    println!(
        "| function | bandnoise | batch | noise | fastnoise-lite | noise-functions | libnoise | fastest peer | point ratio | batch ratio |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|");
    let cell = |v: Option<f64>| v.map_or("–".to_string(), |v| format!("{v:.2}"));
    for function in FUNCTIONS {
        let ns = IMPLEMENTATIONS.map(|i| ns_per_sample(function, i));
        let peer = peer_function(function);
        let fastest = IMPLEMENTATIONS[2..]
            .iter()
            .filter_map(|&i| ns_per_sample(peer, i).map(|v| (v, i)))
            .min_by(|a, b| a.0.total_cmp(&b.0));
        let ratio = |v: Option<f64>| match (v, fastest) {
            (Some(v), Some((f, _))) => format!("{:.2}", v / f),
            _ => "–".to_string(),
        };
        let fastest_name = fastest.map_or("–".to_string(), |(v, name)| {
            let of = if peer == function {
                String::new()
            } else {
                format!(" ({peer})")
            };
            format!("{name}{of} {v:.2}")
        });
        println!(
            "| {function} | {} | {} | {} | {} | {} | {} | {fastest_name} | {} | {} |",
            cell(ns[0]),
            cell(ns[1]),
            cell(ns[2]),
            cell(ns[3]),
            cell(ns[4]),
            cell(ns[5]),
            ratio(ns[0]),
            ratio(ns[1]),
        );
    }
}

fn main() {
    let mut c = Criterion::default().configure_from_args();
    peers(&mut c);
    c.final_summary();
    if !std::env::args().any(|a| a == "--test" || a == "--list") {
        table();
    }
}

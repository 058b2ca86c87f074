//! bandnoise against the peer crates, in one run: ns/sample over the same 1024² grid for every
//! workload of `bandnoise_bench` on each of its grid layouts, then a table of each ratio to the
//! fastest peer.
//!
//! Criterion measures each workload for seconds, one after the other, so on a shared machine
//! a change of load between two measurements moves their ratio (by ±20% here). A second pass
//! measures the ratios themselves: in each of [`ROUNDS`] rounds, every peer and bandnoise fill
//! the same [`PAIRED_ROWS`] rows one after the other (milliseconds apart), the round's ratio
//! is bandnoise's time over the fastest peer's of that round, and the table gives the median
//! and the quartiles over rounds; where FastNoise Lite has the function, also the point
//! samples' ratio to it (issue 19's measure for cellular noise).
//!
//! `cargo bench -p bandnoise-bench --bench peers` (or `scripts/bench-peers.sh`, which also
//! counts instructions with callgrind). With `-- --test` (and under `cargo test`) each workload
//! runs once on [`TEST_ROWS`] rows, unmeasured, and no table is printed.

use std::path::PathBuf;
use std::time::Duration;

use bandnoise_bench::{
    FUNCTIONS, IMPLEMENTATIONS, LAYOUTS, Layout, N, Run, measuring, peer_function, quantile,
    seconds, workload,
};
use criterion::{Criterion, Throughput};

/// Grid rows a workload fills when it runs once, unmeasured (the test command's smoke run):
/// enough to cross cells and fill whole and partial batch chunks; the whole grid for every
/// workload would take half a minute.
const TEST_ROWS: usize = 3;

fn peers(c: &mut Criterion) {
    let mut out = vec![0.0f32; N * N];
    let rows = if measuring() { N } else { TEST_ROWS };
    for layout in LAYOUTS {
        for function in FUNCTIONS {
            let mut g = c.benchmark_group(format!("peers-{}-{function}", layout.name));
            g.throughput(Throughput::Elements((N * N) as u64));
            g.sample_size(10);
            g.warm_up_time(Duration::from_secs(1));
            g.measurement_time(Duration::from_secs(2));
            for implementation in IMPLEMENTATIONS {
                if let Some(run) = workload(function, implementation, layout) {
                    g.bench_function(implementation, |b| {
                        b.iter(|| {
                            run(rows, &mut out);
                            std::hint::black_box(&out);
                        })
                    });
                }
            }
            g.finish();
        }
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
fn ns_per_sample(layout: Layout, function: &str, implementation: &str) -> Option<f64> {
    let path = criterion_dir()
        .join(format!("peers-{}-{function}", layout.name))
        .join(implementation)
        .join("new/estimates.json");
    let json = std::fs::read_to_string(path).ok()?;
    let mean = &json[json.find("\"mean\"")?..];
    let value = &mean[mean.find("\"point_estimate\":")? + "\"point_estimate\":".len()..];
    let end = value.find([',', '}'])?;
    Some(value[..end].trim().parse::<f64>().ok()? / (N * N) as f64)
}

fn table(layout: Layout) {
    println!(
        "\nns/sample over a {N}x{N} grid, layout {} (step {}, origin {:?}); ratio = bandnoise / fastest peer (lower is better)",
        layout.name, layout.step, layout.origin
    );
    println!(
        "| function | bandnoise | batch | noise | fastnoise-lite | noise-functions | libnoise | fastest peer | point ratio | batch ratio |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|");
    let cell = |v: Option<f64>| v.map_or("–".to_string(), |v| format!("{v:.2}"));
    for function in FUNCTIONS {
        let ns = IMPLEMENTATIONS.map(|i| ns_per_sample(layout, function, i));
        let peer = peer_function(function);
        let fastest = IMPLEMENTATIONS[2..]
            .iter()
            .filter_map(|&i| ns_per_sample(layout, peer, i).map(|v| (v, i)))
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

/// Rounds of the paired measurement.
const ROUNDS: usize = 101;

/// Grid rows every workload fills in a round (32·1024 samples).
const PAIRED_ROWS: usize = 32;

/// The paired pass (module docs): the median ratio to the fastest peer and its quartiles.
fn paired_table(layout: Layout) {
    let mut out = vec![0.0f32; N * N];
    println!(
        "\nratio to the fastest peer, layout {}, paired: median [quartiles] of {ROUNDS} interleaved rounds of {PAIRED_ROWS} rows",
        layout.name
    );
    println!("| function | point ratio | batch ratio | point × fastnoise-lite |");
    println!("|---|---|---|---|");
    for function in FUNCTIONS {
        let peer = peer_function(function);
        let peers: Vec<(&str, Run)> = IMPLEMENTATIONS[2..]
            .iter()
            .filter_map(|&i| Some((i, workload(peer, i, layout)?)))
            .collect();
        let ours = [IMPLEMENTATIONS[0], IMPLEMENTATIONS[1]].map(|i| workload(function, i, layout));
        if peers.is_empty() {
            continue;
        }
        // FastNoise Lite's same function (issue 19 compares cellular noise with it).
        let fastnoise = peers.iter().position(|(i, _)| *i == "fastnoise-lite");
        let mut ratios = [Vec::new(), Vec::new()];
        let mut to_fastnoise = Vec::new();
        // One round unmeasured, to warm caches and branch predictors.
        for round in 0..=ROUNDS {
            let times: Vec<f64> = peers
                .iter()
                .map(|(_, run)| seconds(run, PAIRED_ROWS, &mut out))
                .collect();
            let fastest = times.iter().copied().fold(f64::INFINITY, f64::min);
            let fastnoise_time = fastnoise.map(|i| times[i]);
            for (i, (ratios, run)) in ratios.iter_mut().zip(&ours).enumerate() {
                if let Some(run) = run {
                    let t = seconds(run, PAIRED_ROWS, &mut out);
                    if round > 0 {
                        ratios.push(t / fastest);
                        if let (0, Some(f)) = (i, fastnoise_time) {
                            to_fastnoise.push(t / f);
                        }
                    }
                }
            }
        }
        let cell = |v: &mut Vec<f64>| {
            if v.is_empty() {
                return "–".to_string();
            }
            let (q1, m, q3) = (quantile(v, 0.25), quantile(v, 0.5), quantile(v, 0.75));
            format!("{m:.2} [{q1:.2}–{q3:.2}]")
        };
        let [point, batch] = &mut ratios;
        println!(
            "| {function} | {} | {} | {} |",
            cell(point),
            cell(batch),
            cell(&mut to_fastnoise)
        );
    }
}

fn main() {
    let mut c = Criterion::default().configure_from_args();
    peers(&mut c);
    c.final_summary();
    if measuring() {
        for layout in LAYOUTS {
            table(layout);
        }
        for layout in LAYOUTS {
            paired_table(layout);
        }
    }
}
